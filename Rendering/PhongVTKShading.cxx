#include "PhongVTKShading.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTransform.h"

#include "PhongAttenuation.h"
#include "PhongDiffuse.h"
#include "PhongSpecular.h"
#include "PhongSpotlight.h"

#include "PhongVTKOpenGL.h" // GLenum, GL_VIEWPORT

#include <algorithm>
#include <cmath>
#include <sstream>

namespace phongvtk
{
namespace shading
{
namespace
{

template <typename T>
bool NonZero(const T c[3])
{
  return c[0] != 0 || c[1] != 0 || c[2] != 0;
}

void Store(const double in[3], float out[3])
{
  for (int i = 0; i < 3; ++i)
  {
    out[i] = static_cast<float>(in[i]);
  }
}

std::string Indexed(const char* name, std::size_t j)
{
  return name + std::to_string(j);
}

// The GLSL of light j's terms, accumulated into `diffuse` and `specular`, for the unit normal
// `n`, the eye vector `v`, the position `position` (view coordinates) and the exponent `alpha`.
void AppendLight(std::ostringstream& glsl, const Configuration::LightTerms& light, std::size_t j,
  const char* n, const char* position, const char* alpha)
{
  if (!light.Diffuse && !light.Specular)
  {
    return;
  }
  const char* kind = light.Headlight ? "headlight"
    : !light.Positional              ? "directional"
                                     : (light.Spot ? "spot" : "positional");
  glsl << "  {\n    // light " << j << ": " << kind << (light.Attenuated ? ", attenuated" : "")
       << "\n";
  std::string l;
  std::string a;
  if (light.Headlight)
  {
    // A headlight shines from the eye along the view direction: l is +z in view coordinates by
    // definition, a constant the compiler folds (n.l is n.z).
    l = "vec3(0.0, 0.0, 1.0)";
  }
  else if (!light.Positional)
  {
    l = Indexed("phongToLightVC", j);
  }
  else
  {
    l = "l";
    glsl << "    vec3 l = phongLightPositionVC" << j << " - " << position << ";\n";
    if (light.Attenuated)
    {
      glsl << "    float d = length(l);\n    l = l / d;\n";
    }
    else
    {
      glsl << "    l = normalize(l);\n";
    }
    std::ostringstream spot;
    spot << "phongSpotlight(l, phongLightAxisVC" << j << ", phongLightConeCos" << j
         << ", phongLightExponent" << j << ")";
    if (light.ConeFromUniform)
    {
      // A general shader meets lights without a cone too (cosine below -1).
      spot.str("(phongLightConeCos" + std::to_string(j) + " < -1.0 ? 1.0 : " + spot.str() + ")");
    }
    if (light.Attenuated && light.Spot)
    {
      glsl << "    float a = phongAttenuation(phongLightAttenuation" << j << ", d) * " << spot.str()
           << ";\n";
    }
    else if (light.Attenuated)
    {
      glsl << "    float a = phongAttenuation(phongLightAttenuation" << j << ", d);\n";
    }
    else if (light.Spot)
    {
      glsl << "    float a = " << spot.str() << ";\n";
    }
    if (light.Attenuated || light.Spot)
    {
      a = "a * ";
    }
  }
  if (light.Diffuse)
  {
    glsl << "    diffuse += " << a << "phongDiffuse(" << n << ", " << l << ", phongLightDiffuse"
         << j << ");\n";
  }
  if (light.Specular)
  {
    glsl << "    specular += " << a << "phongSpecular(" << n << ", " << l
         << ", v, phongLightSpecular" << j << ", " << alpha << ");\n";
  }
  glsl << "  }\n";
}

// The light terms of every light for the normal `n`.
void AppendLights(std::ostringstream& glsl, const Configuration& config, const char* n,
  const char* position, const char* alpha)
{
  for (std::size_t j = 0; j < config.Lights.size(); ++j)
  {
    AppendLight(glsl, config.Lights[j], j, n, position, alpha);
  }
}

// Functions and uniforms of the stage that evaluates the lights.
void AppendLightDeclarations(std::ostringstream& glsl, const Configuration& config)
{
  bool attenuated = false;
  bool spot = false;
  for (const auto& light : config.Lights)
  {
    attenuated = attenuated || ((light.Diffuse || light.Specular) && light.Attenuated);
    spot = spot || ((light.Diffuse || light.Specular) && light.Spot);
  }
  if (config.AnyDiffuse())
  {
    glsl << PhongDiffuse;
  }
  if (config.AnySpecular())
  {
    glsl << PhongSpecular;
  }
  if (attenuated)
  {
    glsl << PhongAttenuation;
  }
  if (spot)
  {
    glsl << PhongSpotlight;
  }
  for (std::size_t j = 0; j < config.Lights.size(); ++j)
  {
    const auto& light = config.Lights[j];
    if (!light.Diffuse && !light.Specular)
    {
      continue;
    }
    if (!light.Headlight)
    {
      glsl << "uniform vec3 " << (light.Positional ? "phongLightPositionVC" : "phongToLightVC") << j
           << ";\n";
    }
    if (light.Attenuated)
    {
      glsl << "uniform vec3 phongLightAttenuation" << j << ";\n";
    }
    if (light.Spot)
    {
      glsl << "uniform vec3 phongLightAxisVC" << j << ";\nuniform float phongLightConeCos" << j
           << ";\nuniform float phongLightExponent" << j << ";\n";
    }
    if (light.Diffuse)
    {
      glsl << "uniform vec3 phongLightDiffuse" << j << ";\n";
    }
    if (light.Specular)
    {
      glsl << "uniform vec3 phongLightSpecular" << j << ";\n";
    }
  }
}

// The eye vector v: from the surface to the eye, or the direction of projection reversed.
// `position` is null in the fragment shader when the position is not interpolated: then the
// reversed ray through the pixel centre, which passes through the surface point.
void AppendEyeVector(std::ostringstream& glsl, const Configuration& config, const char* position)
{
  if (!config.NeedsEyeVector())
  {
    return;
  }
  if (config.Parallel)
  {
    glsl << "  vec3 v = vec3(0.0, 0.0, 1.0);\n";
  }
  else if (!position)
  {
    glsl << "  vec3 v = normalize(vec3(gl_FragCoord.xy * phongEyeRay.xy + phongEyeRay.zw, 1.0));\n";
  }
  else
  {
    glsl << "  vec3 v = normalize(-" << position << ");\n";
  }
}

void AppendAccumulators(std::ostringstream& glsl, const Configuration& config)
{
  if (config.AnyDiffuse())
  {
    glsl << "  vec3 diffuse = vec3(0.0);\n";
  }
  if (config.AnySpecular())
  {
    glsl << "  vec3 specular = vec3(0.0);\n";
  }
}

// ka*Ia + kd*diffuse + ks*specular with the given names of ka, kd, ks.
std::string Sum(const Configuration& config, const char* ka, const char* kd, const char* ks)
{
  std::string sum;
  auto add = [&sum](const std::string& term)
  {
    sum += (sum.empty() ? "" : " + ") + term;
  };
  if (config.Ambient)
  {
    add(std::string(ka) + " * phongAmbientLight");
  }
  if (config.AnyDiffuse())
  {
    add(std::string(kd) + " * diffuse");
  }
  if (config.AnySpecular())
  {
    add(std::string(ks) + " * specular");
  }
  return sum.empty() ? "vec3(0.0)" : "clamp(" + sum + ", 0.0, 1.0)";
}

// Gouraud: the names of the per-vertex results the fragment shader interpolates.
bool GouraudWholeColour(const Configuration& config)
{
  return config.Colours != Material::FragmentOnly;
}

// The light terms present ("Diffuse", "Specular"), as the names of the Gouraud varyings carry.
std::vector<std::string> LightTermNames(const Configuration& config)
{
  std::vector<std::string> terms;
  if (config.AnyDiffuse())
  {
    terms.emplace_back("Diffuse");
  }
  if (config.AnySpecular())
  {
    terms.emplace_back("Specular");
  }
  return terms;
}

std::vector<std::string> GouraudVaryings(const Configuration& config)
{
  // The whole colour per side, or the light terms per side.
  const std::vector<std::string> quantities =
    GouraudWholeColour(config) ? std::vector<std::string>{ "Colour" } : LightTermNames(config);
  std::vector<std::string> names;
  for (const std::string& quantity : quantities)
  {
    names.push_back("phongFront" + quantity);
    if (config.TwoSided)
    {
      names.push_back("phongBack" + quantity);
    }
  }
  return names;
}

// The eye ray of a pixel centre (x, y) in window coordinates: the points of ndc depth -1 and +1
// on the pixel's ray are linear in (x, y, 1) (their w is constant across a plane of constant
// depth), and v points from the far one to the near one, i.e. toward the eye: v = normalize(M
// (x, y, 1)). For vtkCamera's frusta M is diagonal but for the offsets of the last column, and
// `ray` holds (M00, M11, M02, M12) / M22; false (use the position) for any other projection.
bool EyeRay(vtkRenderer* renderer, float ray[4])
{
  // The projection VTK's shaders use (vtkOpenGLCamera's VCDC matrix, transposed for GL).
  vtkMatrix4x4* wcvc;
  vtkMatrix3x3* normals;
  vtkMatrix4x4* vcdc;
  vtkMatrix4x4* wcdc;
  auto* camera = vtkOpenGLCamera::SafeDownCast(renderer->GetActiveCamera());
  vtkNew<vtkMatrix4x4> inverse;
  if (camera)
  {
    camera->GetKeyMatrices(renderer, wcvc, normals, vcdc, wcdc);
    vtkMatrix4x4::Transpose(vcdc, inverse);
  }
  else
  {
    inverse->DeepCopy(renderer->GetActiveCamera()->GetProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), -1, 1));
  }
  inverse->Invert();
  // The GL viewport the renderer set: window coordinates to ndc.
  int viewport[4] = { 0, 0, 1, 1 };
  if (auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()))
  {
    window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  }
  const double sx = 2.0 / std::max(viewport[2], 1);
  const double sy = 2.0 / std::max(viewport[3], 1);
  const double ox = -viewport[0] * sx - 1;
  const double oy = -viewport[1] * sy - 1;
  // Homogeneous point of ndc depth z on the ray of (x, y): columns for x, y and 1.
  auto column = [&](int row, int which, double z)
  {
    const double* m = inverse->GetData() + 4 * row;
    switch (which)
    {
      case 0:
        return m[0] * sx;
      case 1:
        return m[1] * sy;
      default:
        return m[0] * ox + m[1] * oy + m[2] * z + m[3];
    }
  };
  const double wNear = column(3, 2, -1.0);
  const double wFar = column(3, 2, 1.0);
  double m[3][3]; // m[row][which]
  double largest = 0;
  for (int which = 0; which < 3; ++which)
  {
    for (int row = 0; row < 3; ++row)
    {
      m[row][which] = column(row, which, -1.0) / wNear - column(row, which, 1.0) / wFar;
      largest = std::max(largest, std::abs(m[row][which]));
    }
  }
  const double tiny = 1e-12 * largest;
  if (!(m[2][2] > tiny) || std::abs(m[0][1]) > tiny || std::abs(m[1][0]) > tiny ||
    std::abs(m[2][0]) > tiny || std::abs(m[2][1]) > tiny || std::abs(column(3, 0, 0)) > tiny ||
    std::abs(column(3, 1, 0)) > tiny)
  {
    return false;
  }
  ray[0] = static_cast<float>(m[0][0] / m[2][2]);
  ray[1] = static_cast<float>(m[1][1] / m[2][2]);
  ray[2] = static_cast<float>(m[0][2] / m[2][2]);
  ray[3] = static_cast<float>(m[1][2] / m[2][2]);
  return true;
}

}

//------------------------------------------------------------------------------
Scene GatherScene(vtkRenderer* renderer, bool sceneAmbient)
{
  Scene scene;
  vtkCamera* camera = renderer->GetActiveCamera();
  scene.Parallel = camera->GetParallelProjection() != 0;
  scene.TwoSided = renderer->GetTwoSidedLighting() != 0;
  vtkTransform* view = camera->GetModelViewTransformObject();
  if (!scene.Parallel)
  {
    scene.EyeRayValid = EyeRay(renderer, scene.EyeRay);
  }

  double ambient[3];
  renderer->GetAmbient(ambient);
  double sumDiffuse[3] = { 0, 0, 0 };
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* vtklight = lights->GetNextLight(it))
  {
    if (!vtklight->GetSwitch())
    {
      continue;
    }
    Light light;
    const double intensity = vtklight->GetIntensity();
    double diffuse[3], specular[3], lightAmbient[3];
    vtklight->GetDiffuseColor(diffuse);
    vtklight->GetSpecularColor(specular);
    vtklight->GetAmbientColor(lightAmbient);
    for (int i = 0; i < 3; ++i)
    {
      diffuse[i] *= intensity;
      specular[i] *= intensity;
      ambient[i] += lightAmbient[i] * intensity;
      sumDiffuse[i] += diffuse[i];
    }
    Store(diffuse, light.Diffuse);
    Store(specular, light.Specular);

    // World coordinates (camera lights and headlights carry their transform), then view.
    double position[3], focalPoint[3];
    vtklight->GetTransformedPosition(position);
    vtklight->GetTransformedFocalPoint(focalPoint);
    double axis[3];
    vtkMath::Subtract(focalPoint, position, axis);
    double axisVC[3];
    view->TransformVector(axis, axisVC);
    vtkMath::Normalize(axisVC);
    light.Positional = vtklight->GetPositional() != 0;
    light.Headlight = !light.Positional && vtklight->LightTypeIsHeadlight();
    if (!light.Positional)
    {
      const double toLight[3] = { -axisVC[0], -axisVC[1], -axisVC[2] };
      Store(toLight, light.ToLight);
    }
    else
    {
      double positionVC[3];
      view->TransformPoint(position, positionVC);
      Store(positionVC, light.Position);
      double attenuation[3];
      vtklight->GetAttenuationValues(attenuation);
      Store(attenuation, light.Attenuation);
      light.Attenuated = attenuation[0] != 1 || attenuation[1] != 0 || attenuation[2] != 0;
      // VTK's rule: a cone angle of 90 degrees or more is no cone.
      light.Spot = vtklight->GetConeAngle() < 90;
      Store(axisVC, light.Axis);
      if (light.Spot)
      {
        light.CosCone =
          static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(vtklight->GetConeAngle())));
      }
      light.Exponent = static_cast<float>(vtklight->GetExponent());
    }
    scene.Lights.push_back(light);
  }

  if (sceneAmbient)
  {
    // The light's colour times the average kd of everything in the room.
    double meanKd[3] = { 0, 0, 0 };
    int count = 0;
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal(it);
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      if (!actor->GetVisibility() || !actor->GetProperty())
      {
        continue;
      }
      vtkProperty* property = actor->GetProperty();
      for (int i = 0; i < 3; ++i)
      {
        meanKd[i] += property->GetDiffuse() * property->GetDiffuseColor()[i];
      }
      ++count;
    }
    for (int i = 0; i < 3; ++i)
    {
      ambient[i] = count ? sumDiffuse[i] * meanKd[i] / count : 0.0;
    }
  }
  Store(ambient, scene.Ambient);
  return scene;
}

//------------------------------------------------------------------------------
bool Configuration::AnyDiffuse() const
{
  for (const auto& light : this->Lights)
  {
    if (light.Diffuse)
    {
      return true;
    }
  }
  return false;
}

bool Configuration::AnySpecular() const
{
  for (const auto& light : this->Lights)
  {
    if (light.Specular)
    {
      return true;
    }
  }
  return false;
}

bool Configuration::AnyPositional() const
{
  for (const auto& light : this->Lights)
  {
    if (light.Positional && (light.Diffuse || light.Specular))
    {
      return true;
    }
  }
  return false;
}

bool Configuration::operator==(const Configuration& o) const
{
  return this->Shading == o.Shading && this->Colours == o.Colours && this->Ambient == o.Ambient &&
    this->Parallel == o.Parallel && this->TwoSided == o.TwoSided &&
    this->DerivativeNormals == o.DerivativeNormals && this->KeepPosition == o.KeepPosition &&
    this->BlockColours == o.BlockColours && this->EyeFromFragCoord == o.EyeFromFragCoord &&
    this->Lights == o.Lights;
}

std::string Configuration::Describe() const
{
  std::ostringstream text;
  const char* modes[] = { "flat", "gouraud", "phong" };
  const char* colours[] = { "uniform", "point-colours", "fragment-colours" };
  text << modes[static_cast<int>(this->Shading)] << (this->Parallel ? " parallel" : " perspective")
       << (this->TwoSided ? " two-sided " : " one-sided ")
       << colours[static_cast<int>(this->Colours)] << (this->Ambient ? " ambient" : "")
       << (this->DerivativeNormals ? " derivative-normals" : "")
       << (this->BlockColours ? " block-colours" : "")
       << (this->EyeFromFragCoord ? " eye-from-fragcoord" : "");
  for (std::size_t j = 0; j < this->Lights.size(); ++j)
  {
    const auto& light = this->Lights[j];
    text << " | L" << j
         << (light.Positional ? (light.Spot ? " spot" : " positional") : " directional")
         << (light.Attenuated ? " attenuated" : "") << (light.Diffuse ? " diffuse" : "")
         << (light.Specular ? " specular" : "");
  }
  return text.str();
}

//------------------------------------------------------------------------------
Configuration Configure(
  const Scene& scene, vtkProperty* front, vtkProperty* back, const Request& request)
{
  Configuration config;
  config.Shading = request.Shading;
  config.Colours = request.Colours;
  config.Parallel = scene.Parallel;
  config.TwoSided = scene.TwoSided;
  config.DerivativeNormals = request.DerivativeNormals;
  config.KeepPosition = request.KeepPosition;
  config.BlockColours = request.BlockColours;
  const bool specialize = request.Specialize;

  // A material colour only counts when it is the material's (not mapped scalars).
  const bool uniform = request.Colours == Material::Uniform && !back && !request.BlockColours;
  bool ka = false;
  bool kd = false;
  bool ks = false;
  for (vtkProperty* property : { front, back })
  {
    if (!property)
    {
      continue;
    }
    ka = ka || (property->GetAmbient() != 0 && (!uniform || NonZero(property->GetAmbientColor())));
    kd = kd || (property->GetDiffuse() != 0 && (!uniform || NonZero(property->GetDiffuseColor())));
    ks = ks || (property->GetSpecular() != 0 && NonZero(property->GetSpecularColor()));
  }
  config.Ambient = ka && NonZero(scene.Ambient);
  for (const Light& light : scene.Lights)
  {
    Configuration::LightTerms terms;
    terms.Positional = light.Positional;
    terms.Attenuated = light.Attenuated;
    terms.Spot = light.Spot;
    terms.Headlight = light.Headlight;
    terms.Diffuse = kd && NonZero(light.Diffuse);
    terms.Specular = ks && NonZero(light.Specular);
    if (!specialize)
    {
      terms.Diffuse = terms.Specular = true;
      terms.Attenuated = terms.Spot = terms.ConeFromUniform = terms.Positional;
    }
    config.Lights.push_back(terms);
  }
  if (!specialize)
  {
    config.Ambient = true;
    config.KeepPosition = true;
  }
  // EyeRayValid implies perspective.
  config.EyeFromFragCoord = request.SmallTriangles && scene.EyeRayValid &&
    config.Shading != Mode::Gouraud && config.NeedsEyeVector() && !config.AnyPositional() &&
    !config.KeepPosition && !config.DerivativeNormals;
  return config;
}

//------------------------------------------------------------------------------
std::string FragmentDeclarations(const Configuration& config)
{
  std::ostringstream glsl;
  const bool gouraud = config.Shading == Mode::Gouraud;
  if (config.Ambient && (!gouraud || !GouraudWholeColour(config) || !config.TwoSided))
  {
    glsl << "uniform vec3 phongAmbientLight;\n";
  }
  if (gouraud)
  {
    for (const std::string& name : GouraudVaryings(config))
    {
      glsl << "in vec3 " << name << "VSOutput;\n";
    }
  }
  else
  {
    AppendLightDeclarations(glsl, config);
    if (config.EyeFromFragCoord)
    {
      glsl << "uniform vec4 phongEyeRay;\n";
    }
  }
  return glsl.str();
}

std::string FragmentImplementation(const Configuration& config)
{
  std::ostringstream glsl;
  const bool lit = config.AnyDiffuse() || config.AnySpecular();
  if (config.Shading != Mode::Gouraud)
  {
    if (lit)
    {
      glsl << "  vec3 n = normalVCVSOutput;\n";
    }
    AppendEyeVector(glsl, config, config.EyeFromFragCoord ? nullptr : "vertexVC.xyz");
    AppendAccumulators(glsl, config);
    if (lit && !config.TwoSided)
    {
      // One-sided lighting: a back face gets only the ambient term.
      glsl << "  if (gl_FrontFacing == true)\n  {\n";
    }
    AppendLights(glsl, config, "n", "vertexVC.xyz", "specularPower");
    if (lit && !config.TwoSided)
    {
      glsl << "  }\n";
    }
    glsl << "  gl_FragData[0] = vec4("
         << Sum(config, "ambientColor", "diffuseColor", "specularColor") << ", opacity);\n";
  }
  else if (GouraudWholeColour(config))
  {
    glsl << "  vec3 colour = phongFrontColourVSOutput;\n"
            "  if (gl_FrontFacing == false)\n  {\n";
    if (config.TwoSided)
    {
      glsl << "    colour = phongBackColourVSOutput;\n";
    }
    else
    {
      Configuration ambientOnly = config;
      ambientOnly.Lights.clear();
      glsl << "    colour = " << Sum(ambientOnly, "ambientColor", "", "") << ";\n";
    }
    glsl << "  }\n  gl_FragData[0] = vec4(colour, opacity);\n";
  }
  else
  {
    for (const std::string& term : LightTermNames(config))
    {
      const std::string local = term == "Diffuse" ? "diffuse" : "specular";
      glsl << "  vec3 " << local << " = phongFront" << term << "VSOutput;\n"
           << "  if (gl_FrontFacing == false) { " << local << " = "
           << (config.TwoSided ? "phongBack" + term + "VSOutput" : "vec3(0.0)") << "; }\n";
    }
    glsl << "  gl_FragData[0] = vec4("
         << Sum(config, "ambientColor", "diffuseColor", "specularColor") << ", opacity);\n";
  }
  glsl << "  //VTK::Light::Impl\n";
  return glsl.str();
}

//------------------------------------------------------------------------------
std::string VertexDeclarations(const Configuration& config, bool declareInputs)
{
  std::ostringstream glsl;
  if (declareInputs)
  {
    glsl << "in vec3 normalMC;\nuniform mat3 normalMatrix;\n";
  }
  AppendLightDeclarations(glsl, config);
  if (GouraudWholeColour(config))
  {
    // Point colours of a composite block may be replaced by the block's colour.
    const bool uniforms = config.Colours == Material::Uniform || config.BlockColours;
    if (config.Ambient)
    {
      glsl << "uniform vec3 phongAmbientLight;\nuniform float ambientIntensity;\n";
      if (uniforms)
      {
        glsl << "uniform vec3 ambientColorUniform;\n";
      }
    }
    if (config.AnyDiffuse())
    {
      glsl << "uniform float diffuseIntensity;\n";
      if (uniforms)
      {
        glsl << "uniform vec3 diffuseColorUniform;\n";
      }
    }
    if (config.Colours == Material::PointColours && config.BlockColours &&
      (config.Ambient || config.AnyDiffuse()))
    {
      glsl << "uniform bool OverridesColor;\n";
    }
  }
  if (config.AnySpecular())
  {
    glsl << "uniform float specularPowerUniform;\n";
    if (GouraudWholeColour(config))
    {
      glsl << "uniform float specularIntensity;\nuniform vec3 specularColorUniform;\n";
    }
  }
  for (const std::string& name : GouraudVaryings(config))
  {
    glsl << "out vec3 " << name << "VSOutput;\n";
  }
  return glsl.str();
}

std::string VertexImplementation(const Configuration& config)
{
  std::ostringstream glsl;
  const bool lit = config.AnyDiffuse() || config.AnySpecular();
  if (lit)
  {
    glsl << "  vec3 phongNormalVC = normalize(normalMatrix * normalMC);\n";
  }
  if (lit && config.NeedsPosition())
  {
    glsl << "  vec3 phongVertexVC = (MCVCMatrix * vertexMC).xyz;\n";
  }
  AppendEyeVector(glsl, config, "phongVertexVC");
  const bool whole = GouraudWholeColour(config);
  if (whole)
  {
    // The material colour: the property's (or the block's), the point's, or the block's where
    // it overrides the point colours.
    auto material = [&config](const std::string& uniform) -> std::string
    {
      if (config.Colours != Material::PointColours)
      {
        return uniform;
      }
      return config.BlockColours ? "(OverridesColor ? " + uniform + " : scalarColor.rgb)"
                                 : "scalarColor.rgb";
    };
    if (config.Ambient)
    {
      glsl << "  vec3 ka = ambientIntensity * " << material("ambientColorUniform") << ";\n";
    }
    if (config.AnyDiffuse())
    {
      glsl << "  vec3 kd = diffuseIntensity * " << material("diffuseColorUniform") << ";\n";
    }
    if (config.AnySpecular())
    {
      glsl << "  vec3 ks = specularIntensity * specularColorUniform;\n";
    }
  }
  const int sides = config.TwoSided ? 2 : 1;
  for (int side = 0; side < sides; ++side)
  {
    const char* n = side == 0 ? "phongNormalVC" : "-phongNormalVC";
    const char* name = side == 0 ? "Front" : "Back";
    glsl << "  {\n";
    AppendAccumulators(glsl, config);
    AppendLights(glsl, config, n, "phongVertexVC", "specularPowerUniform");
    if (whole)
    {
      glsl << "  phong" << name << "ColourVSOutput = " << Sum(config, "ka", "kd", "ks") << ";\n";
    }
    else
    {
      if (config.AnyDiffuse())
      {
        glsl << "  phong" << name << "DiffuseVSOutput = diffuse;\n";
      }
      if (config.AnySpecular())
      {
        glsl << "  phong" << name << "SpecularVSOutput = specular;\n";
      }
    }
    glsl << "  }\n";
  }
  return glsl.str();
}

std::string GeometryDeclarations(const Configuration& config)
{
  std::ostringstream glsl;
  for (const std::string& name : GouraudVaryings(config))
  {
    glsl << "in vec3 " << name << "VSOutput[];\nout vec3 " << name << "GSOutput;\n";
  }
  return glsl.str();
}

std::string GeometryImplementation(const Configuration& config)
{
  std::ostringstream glsl;
  for (const std::string& name : GouraudVaryings(config))
  {
    glsl << name << "GSOutput = " << name << "VSOutput[i];\n";
  }
  return glsl.str();
}

//------------------------------------------------------------------------------
void SetUniforms(vtkShaderProgram* program, const Configuration& config, const Scene& scene)
{
  auto set3 = [program](const std::string& name, const float value[3])
  {
    if (program->IsUniformUsed(name.c_str()))
    {
      program->SetUniform3f(name.c_str(), value);
    }
  };
  auto set4 = [program](const std::string& name, const float value[4])
  {
    if (program->IsUniformUsed(name.c_str()))
    {
      program->SetUniform4f(name.c_str(), value);
    }
  };
  auto set1 = [program](const std::string& name, float value)
  {
    if (program->IsUniformUsed(name.c_str()))
    {
      program->SetUniformf(name.c_str(), value);
    }
  };
  if (config.Ambient)
  {
    set3("phongAmbientLight", scene.Ambient);
  }
  if (config.EyeFromFragCoord)
  {
    set4("phongEyeRay", scene.EyeRay);
  }
  for (std::size_t j = 0; j < config.Lights.size() && j < scene.Lights.size(); ++j)
  {
    const Light& light = scene.Lights[j];
    if (!light.Positional)
    {
      set3(Indexed("phongToLightVC", j), light.ToLight);
    }
    else
    {
      set3(Indexed("phongLightPositionVC", j), light.Position);
      set3(Indexed("phongLightAttenuation", j), light.Attenuation);
      set3(Indexed("phongLightAxisVC", j), light.Axis);
      set1(Indexed("phongLightConeCos", j), light.CosCone);
      set1(Indexed("phongLightExponent", j), light.Exponent);
    }
    set3(Indexed("phongLightDiffuse", j), light.Diffuse);
    set3(Indexed("phongLightSpecular", j), light.Specular);
  }
}

}
}
