// The block mapper of vtkPhongCompositePolyDataMapper: the block mapper of VTK's composite mapper
// (Base: vtkCompositeMapperHelper2 up to VTK 9.2, vtkOpenGLBatchedPolyDataMapper from 9.3) with
// the Phong model's overrides (PhongVTKMapperCore.h), written once for both. Private to
// PhongVTK::Rendering.
#ifndef PhongVTKBlockMapper_h
#define PhongVTKBlockMapper_h

#include "PhongVTKMapperCore.h"

namespace phongvtk
{
template <class Base>
class BlockMapper : public Base
{
public:
  using Superclass = Base;

  /// The model's state of this kind of block (its options set by the composite mapper).
  MapperState State;

protected:
  BlockMapper() { this->State.Triangles = &this->Primitives[Base::PrimitiveTris]; }
  ~BlockMapper() override = default;

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    return MapperCore<BlockMapper>::GetNeedToRebuildShaders(*this, this->State, cellBO, ren, act);
  }

  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::UpdateShaders(*this, this->State, cellBO, ren, act);
  }

  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::BuildShaders(*this, this->State, shaders, ren, act);
  }

  void ReplaceShaderColor(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::ReplaceShaderColor(*this, this->State, shaders, ren, act);
  }

  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::ReplaceShaderNormal(*this, this->State, shaders, ren, act);
  }

  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::ReplaceShaderLight(*this, this->State, shaders, ren, act);
  }

  void ReplaceShaderPositionVC(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::ReplaceShaderPositionVC(*this, this->State, shaders, ren, act);
  }

  void SetLightingShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    MapperCore<BlockMapper>::SetLightingShaderParameters(*this, this->State, cellBO, ren, act);
  }

private:
  BlockMapper(const BlockMapper&) = delete;
  void operator=(const BlockMapper&) = delete;
  friend struct MapperCore<BlockMapper>;
};
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKBlockMapper.h
