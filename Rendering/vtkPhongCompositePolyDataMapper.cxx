// vtkPhongCompositePolyDataMapper: what does not depend on VTK's composite mapper. The block
// mappers are in vtkPhongCompositePolyDataMapperHelpers.cxx (VTK up to 9.2) and
// vtkPhongCompositePolyDataMapperDelegators.cxx (9.3 and later).
#include "vtkPhongCompositePolyDataMapper.h"

#include "PhongVTKMapperCore.h"

#include "vtkObjectFactory.h"

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkPhongCompositePolyDataMapper);

vtkPhongCompositePolyDataMapper::vtkPhongCompositePolyDataMapper() = default;

vtkPhongCompositePolyDataMapper::~vtkPhongCompositePolyDataMapper() = default;

void vtkPhongCompositePolyDataMapper::Configure(phongvtk::MapperState& state)
{
  // A block's colour may replace the material's (and mapped scalars).
  state.BlockColours = true;
  state.SharedRebuilds = &this->ShaderRebuilds;
  state.SceneAmbient = this->SceneAmbient;
  state.SpecializeShaders = this->SpecializeShaders;
}

void vtkPhongCompositePolyDataMapper::RememberShaders(
  const std::vector<phongvtk::MapperState*>& states)
{
  for (phongvtk::MapperState* state : states)
  {
    const auto triangles = state->Primitives.find(state->Triangles);
    if (triangles != state->Primitives.end() && triangles->second.Active)
    {
      this->VertexSource = triangles->second.VertexSource;
      this->FragmentSource = triangles->second.FragmentSource;
      this->Configuration = triangles->second.Configuration.Describe();
      return;
    }
  }
  this->VertexSource.clear();
  this->FragmentSource.clear();
  this->Configuration.clear();
}

std::string vtkPhongCompositePolyDataMapper::GetVertexShaderSource()
{
  return this->VertexSource;
}

std::string vtkPhongCompositePolyDataMapper::GetFragmentShaderSource()
{
  return this->FragmentSource;
}

std::string vtkPhongCompositePolyDataMapper::GetShaderConfiguration()
{
  return this->Configuration;
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SceneAmbient: " << (this->SceneAmbient ? "On" : "Off") << "\n";
  os << indent << "SpecializeShaders: " << (this->SpecializeShaders ? "On" : "Off") << "\n";
  os << indent << "ShaderRebuilds: " << this->ShaderRebuilds << "\n";
  os << indent << "ShaderConfiguration: " << this->Configuration << "\n";
}
