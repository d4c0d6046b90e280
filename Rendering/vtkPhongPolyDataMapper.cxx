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
void vtkPhongPolyDataMapper::SetSceneAmbient(bool value)
{
  if (this->Internals->State.SceneAmbient != value)
  {
    this->Internals->State.SceneAmbient = value;
    this->Modified();
  }
}

bool vtkPhongPolyDataMapper::GetSceneAmbient()
{
  return this->Internals->State.SceneAmbient;
}

void vtkPhongPolyDataMapper::SetSpecializeShaders(bool value)
{
  if (this->Internals->State.SpecializeShaders != value)
  {
    this->Internals->State.SpecializeShaders = value;
    this->Modified();
  }
}

bool vtkPhongPolyDataMapper::GetSpecializeShaders()
{
  return this->Internals->State.SpecializeShaders;
}

int vtkPhongPolyDataMapper::GetShaderRebuilds()
{
  return this->Internals->State.ShaderRebuilds;
}

std::string vtkPhongPolyDataMapper::GetVertexShaderSource()
{
  return this->Internals->State.Get(&this->Primitives[PrimitiveTris]).VertexSource;
}

std::string vtkPhongPolyDataMapper::GetFragmentShaderSource()
{
  return this->Internals->State.Get(&this->Primitives[PrimitiveTris]).FragmentSource;
}

std::string vtkPhongPolyDataMapper::GetShaderConfiguration()
{
  const auto& primitive = this->Internals->State.Get(&this->Primitives[PrimitiveTris]);
  return primitive.Active ? primitive.Configuration.Describe() : std::string();
}

//------------------------------------------------------------------------------
PHONGVTK_MAPPER_CORE_FORWARDS(vtkPhongPolyDataMapper, this->Internals->State)

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const phongvtk::MapperState& state = this->Internals->State;
  os << indent << "SceneAmbient: " << (state.SceneAmbient ? "On" : "Off") << "\n";
  os << indent << "SpecializeShaders: " << (state.SpecializeShaders ? "On" : "Off") << "\n";
  os << indent << "ShaderRebuilds: " << state.ShaderRebuilds << "\n";
  os << indent << "ShaderConfiguration: " << this->GetShaderConfiguration() << "\n";
}
