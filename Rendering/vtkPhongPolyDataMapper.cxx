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
PHONGVTK_MAPPER_CORE_FORWARDS(vtkPhongPolyDataMapper, this->PhongState())

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneAmbient: " << (this->SceneAmbient ? "On" : "Off") << "\n";
  os << indent << "SpecializeShaders: " << (this->SpecializeShaders ? "On" : "Off") << "\n";
  os << indent << "ShaderRebuilds: " << this->Internals->State.ShaderRebuilds << "\n";
  os << indent << "ShaderConfiguration: " << this->GetShaderConfiguration() << "\n";
}
