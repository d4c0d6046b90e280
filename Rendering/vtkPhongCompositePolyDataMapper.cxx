#include "vtkPhongCompositePolyDataMapper.h"

#include "PhongVTKMapperCore.h"

// VTK 9.1's vtkCompositeMapperHelper2.h uses GLenum without declaring it (fixed in 9.2).
#include "PhongVTKOpenGL.h"

#include "vtkCompositeMapperHelper2.h"
#include "vtkObjectFactory.h"

//------------------------------------------------------------------------------
// The helper drawing one kind of block: vtkCompositeMapperHelper2 (per-block uniforms,
// selection) with the Phong model's shader code.
class vtkPhongCompositeMapperHelper : public vtkCompositeMapperHelper2
{
public:
  static vtkPhongCompositeMapperHelper* New();
  vtkTypeMacro(vtkPhongCompositeMapperHelper, vtkCompositeMapperHelper2);

  phongvtk::MapperState State;

  const phongvtk::MapperState::Primitive& Triangles()
  {
    return this->State.Get(&this->Primitives[PrimitiveTris]);
  }

protected:
  vtkPhongCompositeMapperHelper()
  {
    // A block's colour may replace the material's (and mapped scalars).
    this->State.BlockColours = true;
  }
  ~vtkPhongCompositeMapperHelper() override = default;

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
  vtkPhongCompositeMapperHelper(const vtkPhongCompositeMapperHelper&) = delete;
  void operator=(const vtkPhongCompositeMapperHelper&) = delete;
  friend struct phongvtk::MapperCore<vtkPhongCompositeMapperHelper>;
};

vtkStandardNewMacro(vtkPhongCompositeMapperHelper);

PHONGVTK_MAPPER_CORE_FORWARDS(vtkPhongCompositeMapperHelper, this->State)

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkPhongCompositePolyDataMapper);

vtkPhongCompositePolyDataMapper::vtkPhongCompositePolyDataMapper() = default;

vtkPhongCompositePolyDataMapper::~vtkPhongCompositePolyDataMapper() = default;

vtkCompositeMapperHelper2* vtkPhongCompositePolyDataMapper::CreateHelper()
{
  auto* helper = vtkPhongCompositeMapperHelper::New();
  helper->State.SharedRebuilds = &this->ShaderRebuilds;
  return helper;
}

void vtkPhongCompositePolyDataMapper::CopyMapperValuesToHelper(vtkCompositeMapperHelper2* helper)
{
  this->Superclass::CopyMapperValuesToHelper(helper);
  if (auto* phong = vtkPhongCompositeMapperHelper::SafeDownCast(helper))
  {
    phong->State.SceneAmbient = this->SceneAmbient;
    phong->State.SpecializeShaders = this->SpecializeShaders;
  }
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::Render(ren, act);
  // Remember the shaders of the first helper the Phong model drew with.
  for (const auto& entry : this->Helpers)
  {
    auto* phong = vtkPhongCompositeMapperHelper::SafeDownCast(entry.second);
    if (phong && phong->Triangles().Active)
    {
      this->VertexSource = phong->Triangles().VertexSource;
      this->FragmentSource = phong->Triangles().FragmentSource;
      this->Configuration = phong->Triangles().Configuration.Describe();
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
