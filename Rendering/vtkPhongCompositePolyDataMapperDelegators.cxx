// vtkPhongCompositePolyDataMapper's block mappers on VTK 9.3 and later: vtkCompositePolyDataMapper
// hands each kind of block to a delegator, whose OpenGL delegate, a vtkOpenGLBatchedPolyDataMapper,
// draws the blocks (per-block uniforms, selection); here a delegator whose delegate has the
// Phong model's shader code.
#include "vtkPhongCompositePolyDataMapper.h"

#include "PhongVTKBlockMapper.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBatchedPolyDataMapper.h"
#include "vtkOpenGLCompositePolyDataMapperDelegator.h"

//------------------------------------------------------------------------------
class vtkPhongCompositeBlockMapper : public phongvtk::BlockMapper<vtkOpenGLBatchedPolyDataMapper>
{
public:
  static vtkPhongCompositeBlockMapper* New();
  vtkTypeMacro(vtkPhongCompositeBlockMapper, phongvtk::BlockMapper<vtkOpenGLBatchedPolyDataMapper>);

protected:
  vtkPhongCompositeBlockMapper() = default;
  ~vtkPhongCompositeBlockMapper() override = default;

private:
  vtkPhongCompositeBlockMapper(const vtkPhongCompositeBlockMapper&) = delete;
  void operator=(const vtkPhongCompositeBlockMapper&) = delete;
};

vtkStandardNewMacro(vtkPhongCompositeBlockMapper);

//------------------------------------------------------------------------------
// VTK's OpenGL delegator with a Phong block mapper as its delegate.
class vtkPhongCompositeDelegator : public vtkOpenGLCompositePolyDataMapperDelegator
{
public:
  static vtkPhongCompositeDelegator* New();
  vtkTypeMacro(vtkPhongCompositeDelegator, vtkOpenGLCompositePolyDataMapperDelegator);

  phongvtk::MapperState& State() { return this->Phong->State; }

  // Called before every render with the composite mapper: its options to the block mapper.
  void ShallowCopy(vtkCompositePolyDataMapper* mapper) override
  {
    this->Superclass::ShallowCopy(mapper);
    if (auto* phong = vtkPhongCompositePolyDataMapper::SafeDownCast(mapper))
    {
      phong->Configure(this->Phong->State);
    }
  }

protected:
  vtkPhongCompositeDelegator()
  {
    // The superclass's constructor made a vtkOpenGLBatchedPolyDataMapper; replaced (and
    // released) before anything saw it.
    this->Phong = vtkPhongCompositeBlockMapper::New();
    this->GLDelegate = this->Phong;
    this->Delegate = vtk::TakeSmartPointer(static_cast<vtkPolyDataMapper*>(this->Phong));
  }
  ~vtkPhongCompositeDelegator() override = default;

private:
  vtkPhongCompositeDelegator(const vtkPhongCompositeDelegator&) = delete;
  void operator=(const vtkPhongCompositeDelegator&) = delete;

  vtkPhongCompositeBlockMapper* Phong = nullptr; // owned through Delegate
};

vtkStandardNewMacro(vtkPhongCompositeDelegator);

//------------------------------------------------------------------------------
vtkCompositePolyDataMapperDelegator* vtkPhongCompositePolyDataMapper::CreateADelegator()
{
  return vtkPhongCompositeDelegator::New();
}

void vtkPhongCompositePolyDataMapper::PostRender(
  const std::vector<vtkSmartPointer<vtkCompositePolyDataMapperDelegator>>& delegators,
  vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::PostRender(delegators, ren, act);
  std::vector<phongvtk::MapperState*> states;
  for (const auto& delegator : delegators)
  {
    if (auto* phong = vtkPhongCompositeDelegator::SafeDownCast(delegator))
    {
      states.push_back(&phong->State());
    }
  }
  this->RememberShaders(states);
}
