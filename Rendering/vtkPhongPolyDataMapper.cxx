#include "vtkPhongPolyDataMapper.h"

#include "PhongVTKMapperCore.h"

#include "vtkObjectFactory.h"
#include "vtkProperty.h"

#include <cstring>

//------------------------------------------------------------------------------
class vtkPhongPolyDataMapper::vtkInternals
{
public:
  phongvtk::MapperState State;
};

vtkStandardNewMacro(vtkPhongPolyDataMapper);

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::vtkPhongPolyDataMapper()
  : Internals(new vtkInternals)
{
  this->Internals->State.Triangles = &this->Primitives[PrimitiveTris];
}

vtkPhongPolyDataMapper::~vtkPhongPolyDataMapper() = default;

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ApplyPreset(vtkProperty* property, int preset)
{
  if (!property)
  {
    return;
  }
  if (!GetPresetName(preset))
  {
    vtkGenericWarningMacro("Unknown material preset "
      << preset << ": use CUSTOM (0), PLASTIC (1), METAL (2) or MATTE (3).");
    return;
  }
  if (preset == CUSTOM)
  {
    return;
  }
  // Coefficients chosen so that ambient + diffuse stay at most 1 under one white light of
  // intensity 1 (VTK's headlight) and under ParaView's light kit, whose lights add up to about
  // that on a surface facing the viewer; only the core of a highlight saturates.
  struct Coefficients
  {
    double Diffuse, Specular, SpecularPower;
  };
  constexpr Coefficients presets[] = { { 0.8, 0.3, 30.0 }, { 0.45, 0.6, 60.0 }, { 0.9, 0.0, 1.0 } };
  const Coefficients& c = presets[preset - PLASTIC];
  double colour[3];
  property->GetDiffuseColor(colour);
  // ka = kd as colours; the ambient coefficient is the strength of the ambient light's share.
  property->SetAmbientColor(colour);
  property->SetAmbient(0.1);
  property->SetDiffuse(c.Diffuse);
  property->SetSpecular(c.Specular);
  property->SetSpecularPower(c.SpecularPower);
  if (preset == METAL)
  {
    property->SetSpecularColor(colour); // a metal's highlight takes the surface's colour
  }
  else
  {
    property->SetSpecularColor(1.0, 1.0, 1.0);
  }
}

bool vtkPhongPolyDataMapper::ApplyPreset(vtkProperty* property, const char* name)
{
  for (int preset = CUSTOM; preset <= MATTE; ++preset)
  {
    if (name && std::strcmp(name, GetPresetName(preset)) == 0)
    {
      ApplyPreset(property, preset);
      return true;
    }
  }
  return false;
}

const char* vtkPhongPolyDataMapper::GetPresetName(int preset)
{
  constexpr const char* names[] = { "custom", "plastic", "metal", "matte" };
  static_assert(CUSTOM == 0 && MATTE == 3, "names follow MaterialPreset's values");
  return preset >= CUSTOM && preset <= MATTE ? names[preset] : nullptr;
}

//------------------------------------------------------------------------------
phongvtk::MapperState& vtkPhongPolyDataMapper::PhongState()
{
  phongvtk::MapperState& state = this->Internals->State;
  state.SceneAmbient = this->SceneAmbient;
  state.SpecializeShaders = this->SpecializeShaders;
  return state;
}

int vtkPhongPolyDataMapper::GetShaderRebuilds()
{
  return this->Internals->State.ShaderRebuilds;
}

std::string vtkPhongPolyDataMapper::GetVertexShaderSource()
{
  return this->Internals->State.Get(this->Internals->State.Triangles).VertexSource;
}

std::string vtkPhongPolyDataMapper::GetFragmentShaderSource()
{
  return this->Internals->State.Get(this->Internals->State.Triangles).FragmentSource;
}

std::string vtkPhongPolyDataMapper::GetShaderConfiguration()
{
  const auto& primitive = this->Internals->State.Get(this->Internals->State.Triangles);
  return primitive.Active ? primitive.Configuration.Describe() : std::string();
}

//------------------------------------------------------------------------------
// The Phong model's overrides (PhongVTKMapperCore.h).
bool vtkPhongPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  return phongvtk::MapperCore<vtkPhongPolyDataMapper>::GetNeedToRebuildShaders(
    *this, this->PhongState(), cellBO, ren, act);
}

void vtkPhongPolyDataMapper::UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::UpdateShaders(
    *this, this->PhongState(), cellBO, ren, act);
}

void vtkPhongPolyDataMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::BuildShaders(
    *this, this->PhongState(), shaders, ren, act);
}

void vtkPhongPolyDataMapper::ReplaceShaderColor(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::ReplaceShaderColor(
    *this, this->PhongState(), shaders, ren, act);
}

void vtkPhongPolyDataMapper::ReplaceShaderNormal(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::ReplaceShaderNormal(
    *this, this->PhongState(), shaders, ren, act);
}

void vtkPhongPolyDataMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::ReplaceShaderLight(
    *this, this->PhongState(), shaders, ren, act);
}

void vtkPhongPolyDataMapper::ReplaceShaderPositionVC(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::ReplaceShaderPositionVC(
    *this, this->PhongState(), shaders, ren, act);
}

void vtkPhongPolyDataMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongPolyDataMapper>::SetLightingShaderParameters(
    *this, this->PhongState(), cellBO, ren, act);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneAmbient: " << (this->SceneAmbient ? "On" : "Off") << "\n";
  os << indent << "SpecializeShaders: " << (this->SpecializeShaders ? "On" : "Off") << "\n";
  os << indent << "ShaderRebuilds: " << this->Internals->State.ShaderRebuilds << "\n";
  os << indent << "ShaderConfiguration: " << this->GetShaderConfiguration() << "\n";
}
