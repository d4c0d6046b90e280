/**
 * @class   vtkPhongPolyDataMapper
 * @brief   polygonal mapper whose shaders evaluate the Phong reflectance model term by term
 *
 * For each switched-on vtkLight j and the actor's vtkProperty the colour is
 *
 *   ka∘Ia + Σ_j [ kd∘Id_j·max(n·l_j, 0) + ks∘Is_j·max(v·r_j, 0)^α ],   r_j = 2(l_j·n)n − l_j
 *
 * with no diffuse or specular from a light when n·l_j ≤ 0, ∘ the component-wise product and the
 * sum clamped to [0, 1]. Id_j, Is_j, Ia_j are the light's diffuse, specular and ambient colours
 * times its intensity; Ia = vtkRenderer::GetAmbient() + Σ_j Ia_j (or, with SceneAmbient, the
 * lights' Σ_j Id_j times the mean kd of the renderer's visible actors). kd = Diffuse·DiffuseColor
 * (or Diffuse times the mapped scalar colour), ka = Ambient·AmbientColor (or Ambient times the
 * scalar colour), ks = Specular·SpecularColor, α = SpecularPower. l_j points from the surface to
 * the light (directional lights: from the focal point to the position; positional lights per
 * fragment, with vtkLight's attenuation and cone); v points from the surface to the eye, and is
 * the direction of projection reversed under parallel projection. Headlights and camera lights
 * follow the same formula. With vtkRenderer::GetTwoSidedLighting() a back face is lit with its
 * normal reversed; without, it gets only the ambient term.
 *
 * Shading follows vtkProperty::GetInterpolation(): VTK_FLAT uses one normal per cell (the cell
 * array of normals when the input has one, e.g. from vtkPolygonNormals, else the derivatives of
 * the position); VTK_GOURAUD evaluates the model per vertex and interpolates the colours;
 * VTK_PHONG interpolates normal and position and evaluates per fragment. Smooth shading of an
 * input without point normals falls back to flat with one warning. VTK_PBR, lighting off,
 * points rendered as spheres and lines as tubes are left to vtkOpenGLPolyDataMapper.
 *
 * The generated GLSL holds exactly the terms, lights and light kinds the scene uses (no specular
 * code when ks or every light's Is is zero, no code for absent lights, no interpolated position
 * when nothing needs it). Shader programs are cached per configuration by VTK's shader cache;
 * sources are rebuilt only when the configuration changes.
 *
 * Render passes that rewrite VTK's own lighting code (shadow maps, vtkLightingMapPass) are not
 * supported by this mapper.
 *
 * @sa vtkOpenGLPolyDataMapper vtkPolygonNormals vtkProperty vtkLight
 */
#ifndef vtkPhongPolyDataMapper_h
#define vtkPhongPolyDataMapper_h

#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPhongVTKRenderingModule.h" // for export macro

#include <map>    // for the per-primitive state
#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkProperty;
namespace phongvtk
{
template <class M>
struct MapperCore;
struct MapperState;
}

class VTKPHONGVTKRENDERING_EXPORT vtkPhongPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkPhongPolyDataMapper* New();
  vtkTypeMacro(vtkPhongPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Derive the ambient light from the scene: Ia = (Σ_j Id_j)∘(mean kd over the renderer's
   * visible actors), replacing the renderer's and the lights' ambient colours. Default: off.
   */
  vtkSetMacro(SceneAmbient, bool);
  vtkGetMacro(SceneAmbient, bool);
  vtkBooleanMacro(SceneAmbient, bool);
  ///@}

  ///@{
  /**
   * Generate shaders holding only the terms, lights and light kinds the scene uses. Off: every
   * term of every light is evaluated and the position interpolated (a general shader, for
   * measuring what specialisation saves; the image is the same). Default: on.
   */
  vtkSetMacro(SpecializeShaders, bool);
  vtkGetMacro(SpecializeShaders, bool);
  vtkBooleanMacro(SpecializeShaders, bool);
  ///@}

  /**
   * Material presets of the model, applied to a property keeping its diffuse colour C. All set
   * ka = kd as colours (AmbientColor = DiffuseColor = C) with the ambient coefficient 0.1: the
   * ambient light's strength, whether it is the renderer's (VTK's and
   * ParaView's default (1, 1, 1)) or derived from the scene (SceneAmbient). Ambient + diffuse
   * stay at most 1 under VTK's headlight and ParaView's light kit; only highlights saturate.
   * - PLASTIC: Diffuse 0.8, white highlight (SpecularColor white, Specular 0.3, SpecularPower 30);
   * - METAL: Diffuse 0.45, highlight tinted by the surface (SpecularColor C, Specular 0.6,
   *   SpecularPower 60);
   * - MATTE: Diffuse 0.9, no highlight (Specular 0).
   * CUSTOM leaves the property as it is: its own coefficients and colours. An unknown preset
   * changes nothing (and warns). These values are also the Phong Surface representation's
   * MaterialPreset property in ParaView.
   */
  enum MaterialPreset
  {
    CUSTOM = 0,
    PLASTIC = 1,
    METAL = 2,
    MATTE = 3
  };
  static void ApplyPreset(vtkProperty* property, int preset);
  /**
   * The same by name ("custom", "plastic", "metal", "matte"); false (property unchanged) for
   * another name.
   */
  static bool ApplyPreset(vtkProperty* property, const char* name);
  /**
   * The name of a MaterialPreset value ("custom", "plastic", "metal", "matte"), or nullptr for
   * another value.
   */
  static const char* GetPresetName(int preset);

  /**
   * The GLSL of the program that last drew this mapper's polygons (vertex, fragment): for
   * inspection and tests. Empty before the first render or when VTK's own lighting drew them.
   */
  std::string GetVertexShaderSource();
  std::string GetFragmentShaderSource();

  /**
   * A one-line description of the configuration of the polygons' shaders (shading, projection,
   * sidedness, terms, lights), e.g. "phong perspective two-sided uniform ambient | L0
   * directional diffuse specular". Empty when VTK's own lighting drew them.
   */
  std::string GetShaderConfiguration();

  /**
   * How many times the shader sources of this mapper changed (a new configuration): redrawing
   * an unchanged scene or changing a coefficient that leaves every term present does not count.
   */
  int GetShaderRebuilds();

protected:
  vtkPhongPolyDataMapper();
  ~vtkPhongPolyDataMapper() override;

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderColor(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderPositionVC(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetLightingShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  bool SceneAmbient = false;
  bool SpecializeShaders = true;

private:
  vtkPhongPolyDataMapper(const vtkPhongPolyDataMapper&) = delete;
  void operator=(const vtkPhongPolyDataMapper&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
  // The shared overrides' state, with this mapper's options.
  phongvtk::MapperState& PhongState();
  template <class M>
  friend struct phongvtk::MapperCore;
};

#endif
