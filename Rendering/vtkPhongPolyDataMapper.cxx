#include "vtkPhongPolyDataMapper.h"

#include "PhongVTKShading.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkLightingMapPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"

#include <cstring>

namespace shading = phongvtk::shading;

//------------------------------------------------------------------------------
class vtkPhongPolyDataMapper::vtkInternals
{
public:
  struct Primitive
  {
    bool Active = false; ///< the Phong model (not VTK's lighting) draws this primitive
    shading::Configuration Configuration;
    std::string VertexSource;
    std::string FragmentSource;
  };
  std::map<const vtkOpenGLHelper*, Primitive> Primitives;
  shading::Scene Scene;
  bool WarnedNoPointNormals = false;
};

vtkStandardNewMacro(vtkPhongPolyDataMapper);

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::vtkPhongPolyDataMapper()
  : Internals(new vtkInternals)
{
}

vtkPhongPolyDataMapper::~vtkPhongPolyDataMapper() = default;

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ApplyPreset(vtkProperty* property, int preset)
{
  if (!property)
  {
    return;
  }
  double colour[3];
  property->GetDiffuseColor(colour);
  // ka = kd: the ambient reflectance is the diffuse one.
  if (preset == METAL)
  {
    property->SetDiffuse(0.4);
  }
  property->SetAmbientColor(colour);
  property->SetAmbient(property->GetDiffuse());
  switch (preset)
  {
    case PLASTIC:
      property->SetSpecularColor(1.0, 1.0, 1.0);
      property->SetSpecular(0.5);
      property->SetSpecularPower(30.0);
      break;
    case METAL:
      property->SetSpecularColor(colour);
      property->SetSpecular(1.0);
      property->SetSpecularPower(100.0);
      break;
    case MATTE:
      property->SetSpecular(0.0);
      break;
    default:
      vtkGenericWarningMacro("Unknown material preset " << preset << ": use PLASTIC (0), METAL (1) "
                                                        << "or MATTE (2).");
  }
}

bool vtkPhongPolyDataMapper::ApplyPreset(vtkProperty* property, const char* name)
{
  const char* names[] = { "plastic", "metal", "matte" };
  for (int preset = PLASTIC; preset <= MATTE; ++preset)
  {
    if (name && std::strcmp(name, names[preset]) == 0)
    {
      ApplyPreset(property, preset);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::string vtkPhongPolyDataMapper::GetVertexShaderSource()
{
  return this->Internals->Primitives[&this->Primitives[PrimitiveTris]].VertexSource;
}

std::string vtkPhongPolyDataMapper::GetFragmentShaderSource()
{
  return this->Internals->Primitives[&this->Primitives[PrimitiveTris]].FragmentSource;
}

std::string vtkPhongPolyDataMapper::GetShaderConfiguration()
{
  const auto& primitive = this->Internals->Primitives[&this->Primitives[PrimitiveTris]];
  return primitive.Active ? primitive.Configuration.Describe() : std::string();
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The superclass decides whether VTK would light this primitive at all (and remembers it).
  bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  vtkInternals::Primitive& primitive = this->Internals->Primitives[&cellBO];

  vtkProperty* property = act->GetProperty();
  vtkInformation* keys = act->GetPropertyKeys();
  const auto& info = this->PrimitiveInfo[&cellBO];
  const bool active = info.LastLightComplexity > 0 && info.LastLightCount > 0 &&
    property->GetInterpolation() != VTK_PBR && !this->DrawingTubesOrSpheres(cellBO, act) &&
    !(keys &&
      (keys->Has(vtkLightingMapPass::RENDER_NORMALS()) ||
        keys->Has(vtkLightingMapPass::RENDER_LUMINANCE())));

  shading::Configuration config;
  if (active)
  {
    this->Internals->Scene = shading::GatherScene(ren, this->SceneAmbient);

    shading::Mode mode = property->GetInterpolation() == VTK_FLAT ? shading::Mode::Flat
      : property->GetInterpolation() == VTK_GOURAUD               ? shading::Mode::Gouraud
                                                                  : shading::Mode::Phong;
    if (mode != shading::Mode::Flat && this->VBOs->GetNumberOfComponents("normalMC") != 3)
    {
      if (!this->Internals->WarnedNoPointNormals)
      {
        vtkWarningMacro("Smooth shading needs point normals and the input has none: shading "
                        "flat (cell normals or the derivatives of the position). Compute them "
                        "with vtkPolygonNormals (ComputePointNormals on) or set the "
                        "interpolation to flat.");
        this->Internals->WarnedNoPointNormals = true;
      }
      mode = shading::Mode::Flat;
    }

    // Where kd and ka come from: the same cases as VTK's colour code.
    shading::Material colours = shading::Material::Uniform;
    if (this->VBOs->GetNumberOfComponents("scalarColor") != 0 && !this->DrawingVertices)
    {
      colours = shading::Material::PointColours;
    }
    else if ((this->InterpolateScalarsBeforeMapping && this->ColorCoordinates &&
               !this->DrawingVertices) ||
      (this->HaveCellScalars && !this->DrawingVertices && !this->PointPicking) ||
      act->GetBackfaceProperty())
    {
      colours = shading::Material::FragmentOnly;
    }

    // Code that is not ours may read the interpolated position: keep it then.
    vtkShaderProperty* sp = act->GetShaderProperty();
    const bool keepPosition = sp->HasVertexShaderCode() || sp->HasFragmentShaderCode() ||
      sp->HasGeometryShaderCode() || sp->GetNumberOfShaderReplacements() > 0 ||
      (keys && keys->Has(vtkOpenGLRenderPass::RenderPasses())) || this->DrawingEdges(ren, act);

    config = shading::Configure(this->Internals->Scene, property, act->GetBackfaceProperty(), mode,
      colours, mode == shading::Mode::Flat && !this->HaveCellNormals, keepPosition,
      this->SpecializeShaders);
  }

  if (active != primitive.Active || (active && config != primitive.Configuration))
  {
    rebuild = true;
  }
  primitive.Active = active;
  primitive.Configuration = config;
  return rebuild;
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildShaders(shaders, ren, act);
  vtkInternals::Primitive& primitive = this->Internals->Primitives[this->LastBoundBO];
  const std::string vertex = shaders[vtkShader::Vertex]->GetSource();
  const std::string fragment = shaders[vtkShader::Fragment]->GetSource();
  if (vertex != primitive.VertexSource || fragment != primitive.FragmentSource)
  {
    ++this->ShaderRebuilds;
  }
  primitive.VertexSource = primitive.Active ? vertex : std::string();
  primitive.FragmentSource = primitive.Active ? fragment : std::string();
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReplaceShaderColor(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  const vtkInternals::Primitive& primitive = this->Internals->Primitives[this->LastBoundBO];
  if (!primitive.Active || primitive.Configuration.FragmentUsesSpecular())
  {
    this->Superclass::ReplaceShaderColor(shaders, ren, act);
    return;
  }
  // VTK's colour code declares the specular material whenever the primitive is lit; it does so
  // only when the light complexity is non-zero, so hide it for that call.
  int& complexity = this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity;
  const int lit = complexity;
  complexity = 0;
  this->Superclass::ReplaceShaderColor(shaders, ren, act);
  complexity = lit;
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReplaceShaderNormal(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  const vtkInternals::Primitive& primitive = this->Internals->Primitives[this->LastBoundBO];
  if (!primitive.Active || primitive.Configuration.Shading != shading::Mode::Gouraud ||
    primitive.Configuration.KeepPosition)
  {
    // Flat and Phong read VTK's normal (turned toward the viewer on back faces); so does code
    // that is not ours.
    this->Superclass::ReplaceShaderNormal(shaders, ren, act);
    return;
  }
  // Gouraud: the normal is used in the vertex shader only (declared with the light code).
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReplaceShaderPositionVC(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  const vtkInternals::Primitive& primitive = this->Internals->Primitives[this->LastBoundBO];
  const shading::Configuration& config = primitive.Configuration;
  if (!primitive.Active || config.FragmentNeedsPosition())
  {
    this->Superclass::ReplaceShaderPositionVC(shaders, ren, act);
    return;
  }
  // Nothing reads the interpolated position: the vertex shader only projects (and a Gouraud
  // vertex shader computes the position for its own use).
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  const bool vertexPosition = config.Shading == shading::Mode::Gouraud && config.NeedsPosition();
  vtkShaderProgram::Substitute(vs, "//VTK::Camera::Dec",
    vertexPosition ? "uniform mat4 MCDCMatrix;\nuniform mat4 MCVCMatrix;"
                   : "uniform mat4 MCDCMatrix;");
  vtkShaderProgram::Substitute(
    vs, "//VTK::PositionVC::Impl", "  gl_Position = MCDCMatrix * vertexMC;\n");
  vtkShaderProgram::Substitute(fs, "//VTK::Camera::Dec", "uniform int cameraParallel;\n", false);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  const vtkInternals::Primitive& primitive = this->Internals->Primitives[this->LastBoundBO];
  if (!primitive.Active)
  {
    this->Superclass::ReplaceShaderLight(shaders, ren, act);
    return;
  }
  const shading::Configuration& config = primitive.Configuration;
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(fs, "//VTK::Light::Dec", shading::FragmentDeclarations(config));
  vtkShaderProgram::Substitute(
    fs, "//VTK::Light::Impl", shading::FragmentImplementation(config), false);
  shaders[vtkShader::Fragment]->SetSource(fs);

  if (config.Shading == shading::Mode::Gouraud)
  {
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    // VTK's normal code declared normalMC and normalMatrix when it ran.
    vtkShaderProgram::Substitute(
      vs, "//VTK::Light::Dec", shading::VertexDeclarations(config, !config.KeepPosition));
    vtkShaderProgram::Substitute(vs, "//VTK::Light::Impl", shading::VertexImplementation(config));
    shaders[vtkShader::Vertex]->SetSource(vs);
    std::string gs = shaders[vtkShader::Geometry]->GetSource();
    if (!gs.empty())
    {
      vtkShaderProgram::Substitute(gs, "//VTK::Light::Dec", shading::GeometryDeclarations(config));
      vtkShaderProgram::Substitute(
        gs, "//VTK::Light::Impl", shading::GeometryImplementation(config));
      shaders[vtkShader::Geometry]->SetSource(gs);
    }
  }
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const vtkInternals::Primitive& primitive = this->Internals->Primitives[&cellBO];
  if (!primitive.Active)
  {
    this->Superclass::SetLightingShaderParameters(cellBO, ren, act);
    return;
  }
  shading::SetUniforms(cellBO.Program, primitive.Configuration, this->Internals->Scene);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneAmbient: " << (this->SceneAmbient ? "On" : "Off") << "\n";
  os << indent << "SpecializeShaders: " << (this->SpecializeShaders ? "On" : "Off") << "\n";
  os << indent << "ShaderRebuilds: " << this->ShaderRebuilds << "\n";
  os << indent << "ShaderConfiguration: " << this->GetShaderConfiguration() << "\n";
}
