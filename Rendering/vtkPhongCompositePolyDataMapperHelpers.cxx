// vtkPhongCompositePolyDataMapper's block mappers on VTK up to 9.2: vtkCompositePolyDataMapper2
// draws each kind of block with a vtkCompositeMapperHelper2 (per-block uniforms, selection);
// here one with the Phong model's shader code.
#include "vtkPhongCompositePolyDataMapper.h"

#include "PhongVTKBlockMapper.h"
#include "PhongVTKOpenGL.h" // VTK 9.1's vtkCompositeMapperHelper2.h uses GLenum undeclared

#include "vtkCompositeMapperHelper2.h"
#include "vtkObjectFactory.h"

//------------------------------------------------------------------------------
class vtkPhongCompositeBlockMapper : public phongvtk::BlockMapper<vtkCompositeMapperHelper2>
{
public:
  static vtkPhongCompositeBlockMapper* New();
  vtkTypeMacro(vtkPhongCompositeBlockMapper, phongvtk::BlockMapper<vtkCompositeMapperHelper2>);

protected:
  vtkPhongCompositeBlockMapper() = default;
  ~vtkPhongCompositeBlockMapper() override = default;

private:
  vtkPhongCompositeBlockMapper(const vtkPhongCompositeBlockMapper&) = delete;
  void operator=(const vtkPhongCompositeBlockMapper&) = delete;
};

vtkStandardNewMacro(vtkPhongCompositeBlockMapper);

//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkPhongCompositePolyDataMapper::CreateHelper()
{
  auto* helper = vtkPhongCompositeBlockMapper::New();
  this->Configure(helper->State);
  return helper;
}

void vtkPhongCompositePolyDataMapper::CopyMapperValuesToHelper(vtkCompositeMapperHelper2* helper)
{
  this->Superclass::CopyMapperValuesToHelper(helper);
  if (auto* phong = vtkPhongCompositeBlockMapper::SafeDownCast(helper))
  {
    this->Configure(phong->State);
  }
}

void vtkPhongCompositePolyDataMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::Render(ren, act);
  std::vector<phongvtk::MapperState*> states;
  for (const auto& entry : this->Helpers)
  {
    if (auto* phong = vtkPhongCompositeBlockMapper::SafeDownCast(entry.second))
    {
      states.push_back(&phong->State);
    }
  }
  this->RememberShaders(states);
}
