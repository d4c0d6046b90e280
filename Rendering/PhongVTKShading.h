// The Phong reflectance model as GLSL: what a scene's lights and material need (the
// configuration), the lights in view coordinates (the uniforms), and the shader code generated
// for exactly that configuration. Shared by vtkPhongPolyDataMapper and its composite variant:
// the one place where the model becomes GLSL. Private to PhongVTK::Rendering.
//
// The model, for each switched-on light j (vtkLight) and the material (vtkProperty):
//   colour = ka*Ia + sum_j [ kd*Id_j*max(n.l_j, 0) + ks*Is_j*max(v.r_j, 0)^alpha ]
//   r_j = 2(l_j.n)n - l_j, nothing from light j when n.l_j <= 0, products component-wise,
//   clamped to [0, 1] at the end;
//   Id_j = DiffuseColor_j*Intensity_j, Is_j = SpecularColor_j*Intensity_j,
//   Ia = vtkRenderer::GetAmbient() + sum_j AmbientColor_j*Intensity_j (or, with scene ambient,
//        (sum_j Id_j) * the mean kd of the renderer's visible actors);
//   kd = Diffuse*DiffuseColor (or Diffuse*the mapped scalar colour), ka = Ambient*AmbientColor
//   (or Ambient*the scalar colour), ks = Specular*SpecularColor, alpha = SpecularPower.
#ifndef PhongVTKShading_h
#define PhongVTKShading_h

#include <string>
#include <vector>

class vtkProperty;
class vtkRenderer;
class vtkShaderProgram;

namespace phongvtk
{
namespace shading
{

/// How the model is sampled: per face (cell normals, else the derivatives of the position),
/// per vertex with colours interpolated (Gouraud), or per fragment with the normal and position
/// interpolated (Phong).
enum class Mode
{
  Flat,
  Gouraud,
  Phong
};

/// Where the material colours come from, which decides whether Gouraud can evaluate the whole
/// colour per vertex: a uniform material or per-point colours are known to the vertex shader;
/// cell colours, colour textures and a back-face material only to the fragment shader (then
/// the vertex shader evaluates the light terms and the fragment shader multiplies by ka, kd, ks).
enum class Material
{
  Uniform,
  PointColours,
  FragmentOnly
};

/// One switched-on light in view coordinates, with the numbers its uniforms carry.
struct Light
{
  bool Positional = false;
  bool Attenuated = false; ///< positional with attenuation other than (1, 0, 0)
  bool Spot = false;       ///< positional with a cone angle below 90 degrees
  bool Headlight = false;  ///< directional from the camera: l = +z in view coordinates, always
  float ToLight[3] = { 0, 0, 1 }; ///< directional: unit vector from the surface to the light
  float Position[3] = { 0, 0, 0 };
  float Axis[3] = { 0, 0, -1 }; ///< spot: unit direction the light shines in
  float Attenuation[3] = { 1, 0, 0 };
  float CosCone = -2; ///< cosine of the cone angle; below -1: no cone
  float Exponent = 1;
  float Diffuse[3] = { 0, 0, 0 };  ///< Id
  float Specular[3] = { 0, 0, 0 }; ///< Is
};

/// The renderer's side of the model: its switched-on lights and the ambient light Ia.
struct Scene
{
  std::vector<Light> Lights;
  float Ambient[3] = { 0, 0, 0 };
  bool Parallel = false;
  bool TwoSided = true;
  /// Perspective: the eye vector of a fragment at window coordinates (x, y) is
  /// normalize((x EyeRay[0] + EyeRay[2], y EyeRay[1] + EyeRay[3], 1)), the reversed ray through
  /// the pixel (from the GL viewport and the projection VTK's shaders use); valid when the
  /// projection has the form of vtkCamera's frusta.
  float EyeRay[4] = { 0, 0, 0, 0 };
  bool EyeRayValid = false;
};

/// Lights of `renderer` in the view coordinates of its active camera, and Ia (the renderer's
/// ambient plus the lights' ambient colours, or the scene-derived ambient).
Scene GatherScene(vtkRenderer* renderer, bool sceneAmbient);

/// What the generated GLSL contains: the terms, lights and light kinds the scene has.
struct Configuration
{
  struct LightTerms
  {
    bool Positional = false;
    bool Attenuated = false;
    bool Spot = false;
    bool Headlight = false;
    bool Diffuse = false;
    bool Specular = false;
    bool ConeFromUniform = false; ///< general shader: the cone uniform says whether there is one
    bool operator==(const LightTerms& o) const
    {
      return this->Positional == o.Positional && this->Attenuated == o.Attenuated &&
        this->Spot == o.Spot && this->Headlight == o.Headlight && this->Diffuse == o.Diffuse &&
        this->Specular == o.Specular && this->ConeFromUniform == o.ConeFromUniform;
    }
  };
  Mode Shading = Mode::Phong;
  Material Colours = Material::Uniform;
  bool Ambient = false;
  bool Parallel = false;
  bool TwoSided = true;
  bool DerivativeNormals = false; ///< flat without cell normals
  bool KeepPosition = false;      ///< something else in the shaders reads the position
  bool BlockColours = false;      ///< composite: a block's colours may replace the material's
  bool EyeFromFragCoord = false;  ///< perspective eye vector from gl_FragCoord, not the position
  std::vector<LightTerms> Lights;

  bool AnyDiffuse() const;
  bool AnySpecular() const;
  bool AnyPositional() const;
  /// The eye vector varies over the surface (perspective) and something uses it.
  bool NeedsEyeVector() const { return this->AnySpecular(); }
  /// Whether the stage evaluating the model needs the view-coordinate position.
  bool NeedsPosition() const
  {
    return this->AnyPositional() || (this->AnySpecular() && !this->Parallel);
  }
  /// Whether the fragment shader reads ks and alpha (Gouraud with the whole colour per vertex
  /// does not).
  bool FragmentUsesSpecular() const
  {
    return this->AnySpecular() &&
      !(this->Shading == Mode::Gouraud && this->Colours != Material::FragmentOnly);
  }
  /// Whether the fragment shader needs the interpolated position.
  bool FragmentNeedsPosition() const
  {
    return this->KeepPosition || this->DerivativeNormals ||
      (this->Shading != Mode::Gouraud && !this->EyeFromFragCoord && this->NeedsPosition());
  }
  bool operator==(const Configuration& o) const;
  bool operator!=(const Configuration& o) const { return !(*this == o); }
  /// One line naming the configuration, e.g. "phong perspective two-sided ambient L0:dir+d+s".
  std::string Describe() const;
};

/// What a mapper asks of the model for one primitive.
struct Request
{
  Mode Shading = Mode::Phong;
  Material Colours = Material::Uniform;
  bool DerivativeNormals = false; ///< flat without cell normals
  bool KeepPosition = false;      ///< code that is not ours may read the position
  bool BlockColours = false;      ///< composite data: per-block colours replace the material's
  /// Triangles small next to the viewport (vertex-bound): a perspective eye vector is cheaper
  /// from gl_FragCoord than interpolated (llvmpipe: interpolation costs per triangle, the
  /// reconstruction per fragment).
  bool SmallTriangles = false;
  bool Specialize = true; ///< off: a general shader
};

/// The configuration for a scene and a material (`back` is the actor's back-face property or
/// null): a term is present only when its coefficient, its material colour (for a uniform
/// material without block colours) and some light's colour are all non-zero. Without
/// `Specialize` every term of every light is present and positional lights carry attenuation
/// and cone code (a general shader, for measuring what specialisation saves).
Configuration Configure(
  const Scene& scene, vtkProperty* front, vtkProperty* back, const Request& request);

/// GLSL for the configuration. Declarations go to //VTK::Light::Dec of the stage that evaluates
/// the model (and the varyings of the other stage); implementations replace //VTK::Light::Impl.
/// The fragment shader relies on VTK's colour code (ambientColor, diffuseColor, specularColor,
/// specularPower, opacity) and, for flat and Phong, on its normal code (normalVCVSOutput, the
/// unit normal turned toward the viewer on back faces) and position (vertexVC).
std::string FragmentDeclarations(const Configuration& config);
std::string FragmentImplementation(const Configuration& config);
/// Gouraud only: the vertex shader evaluates the model from normalMC, normalMatrix, vertexMC and
/// MCVCMatrix (declared here when `declareInputs`).
std::string VertexDeclarations(const Configuration& config, bool declareInputs);
std::string VertexImplementation(const Configuration& config);
/// Gouraud only: the geometry shader (edges, wide lines) passes the per-vertex results on.
std::string GeometryDeclarations(const Configuration& config);
std::string GeometryImplementation(const Configuration& config);

/// Sets the uniforms the generated code uses.
void SetUniforms(vtkShaderProgram* program, const Configuration& config, const Scene& scene);

}
}

#endif
