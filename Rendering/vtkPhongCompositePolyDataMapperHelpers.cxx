// vtkPhongCompositePolyDataMapper's block mappers on VTK up to 9.2: vtkCompositePolyDataMapper2
// draws each kind of block with a vtkCompositeMapperHelper2 (per-block uniforms, selection);
// here one with the Phong model's shader code.
#include "vtkPhongCompositePolyDataMapper.h"

#include "PhongVTKMapperCore.h"
#include "PhongVTKOpenGL.h" // VTK 9.1's vtkCompositeMapperHelper2.h uses GLenum undeclared

#include "vtkCompositeMapperHelper2.h"
#include "vtkObjectFactory.h"

//------------------------------------------------------------------------------
class vtkPhongCompositeBlockMapper : public vtkCompositeMapperHelper2
{
public:
  static vtkPhongCompositeBlockMapper* New();
  vtkTypeMacro(vtkPhongCompositeBlockMapper, vtkCompositeMapperHelper2);

  phongvtk::MapperState State;

protected:
  vtkPhongCompositeBlockMapper() { this->State.Triangles = &this->Primitives[PrimitiveTris]; }
  ~vtkPhongCompositeBlockMapper() override = default;

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

private:
  vtkPhongCompositeBlockMapper(const vtkPhongCompositeBlockMapper&) = delete;
  void operator=(const vtkPhongCompositeBlockMapper&) = delete;
  friend struct phongvtk::MapperCore<vtkPhongCompositeBlockMapper>;
  friend class vtkPhongCompositePolyDataMapper;
};

vtkStandardNewMacro(vtkPhongCompositeBlockMapper);

//------------------------------------------------------------------------------
// The Phong model's overrides (PhongVTKMapperCore.h).
bool vtkPhongCompositeBlockMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  return phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::GetNeedToRebuildShaders(
    *this, this->State, cellBO, ren, act);
}

void vtkPhongCompositeBlockMapper::UpdateShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::UpdateShaders(
    *this, this->State, cellBO, ren, act);
}

void vtkPhongCompositeBlockMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::BuildShaders(
    *this, this->State, shaders, ren, act);
}

void vtkPhongCompositeBlockMapper::ReplaceShaderColor(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::ReplaceShaderColor(
    *this, this->State, shaders, ren, act);
}

void vtkPhongCompositeBlockMapper::ReplaceShaderNormal(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::ReplaceShaderNormal(
    *this, this->State, shaders, ren, act);
}

void vtkPhongCompositeBlockMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::ReplaceShaderLight(
    *this, this->State, shaders, ren, act);
}

void vtkPhongCompositeBlockMapper::ReplaceShaderPositionVC(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::ReplaceShaderPositionVC(
    *this, this->State, shaders, ren, act);
}

void vtkPhongCompositeBlockMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  phongvtk::MapperCore<vtkPhongCompositeBlockMapper>::SetLightingShaderParameters(
    *this, this->State, cellBO, ren, act);
}

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
