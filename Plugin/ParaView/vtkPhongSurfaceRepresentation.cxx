#include "vtkPhongSurfaceRepresentation.h"

#include "PhongVTKOptions.h" // PhongVTK::Filters' checked setter of enumerated options
#include "vtkAutoInit.h"
#include "vtkObjectFactory.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkProperty.h"

#include <cmath>

// ParaView 5.11's VTK is GLX-only: the plugin brings PhongVTK's headless windows, which take
// vtkRenderWindow's place in pvbatch and pvpython without an X display
// (PhongVTK::RenderingHeadless; the reference keeps the library linked).
VTK_MODULE_INIT(vtkPhongVTKRenderingHeadless);

vtkStandardNewMacro(vtkPhongSurfaceRepresentation);

namespace
{
constexpr const char* const ShadingNames[] = { "Flat", "Gouraud", "Phong" };
// The names of vtkPhongPolyDataMapper::MaterialPreset's values, as the panel shows them.
constexpr const char* const PresetNames[] = { "Custom", "Plastic", "Metal", "Matte" };
static_assert(vtkPhongPolyDataMapper::CUSTOM == 0 && vtkPhongPolyDataMapper::PLASTIC == 1 &&
    vtkPhongPolyDataMapper::METAL == 2 && vtkPhongPolyDataMapper::MATTE == 3,
  "PresetNames follow vtkPhongPolyDataMapper::MaterialPreset");
constexpr int Interpolations[] = { VTK_FLAT, VTK_GOURAUD, VTK_PHONG };
}

//------------------------------------------------------------------------------
vtkPhongSurfaceRepresentation::vtkPhongSurfaceRepresentation()
{
  // As ParaView's own representations with their own mappers do: replace both mappers, then set
  // up the pipeline around them again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkPhongCompositePolyDataMapper::New();
  this->LODMapper = vtkPhongCompositePolyDataMapper::New();
  this->SetupDefaults();
  this->Property->SetInterpolation(Interpolations[this->Shading]);
}

//------------------------------------------------------------------------------
vtkPhongSurfaceRepresentation::~vtkPhongSurfaceRepresentation() = default;

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetShading(int shading)
{
  if (phongvtk::SetEnumeratedOption(this, "shading", this->Shading, shading, ShadingNames))
  {
    this->Property->SetInterpolation(Interpolations[this->Shading]);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetMaterialPreset(int preset)
{
  if (phongvtk::SetEnumeratedOption(
        this, "material preset", this->MaterialPreset, preset, PresetNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetSceneAmbient(bool sceneAmbient)
{
  if (sceneAmbient != this->SceneAmbient)
  {
    this->SceneAmbient = sceneAmbient;
    for (vtkMapper* mapper : { this->Mapper, this->LODMapper })
    {
      if (auto* phong = vtkPhongCompositePolyDataMapper::SafeDownCast(mapper))
      {
        phong->SetSceneAmbient(sceneAmbient);
      }
    }
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkPhongSurfaceRepresentation::CheckCoefficient(const char* name, double value)
{
  if (!(value >= 0.0) || std::isinf(value))
  {
    vtkErrorMacro("Invalid " << name << " " << value
                             << ": the Phong model needs a finite value >= 0; keeping the "
                                "previous one.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetAmbient(double ka)
{
  if (this->CheckCoefficient("ambient coefficient", ka))
  {
    this->Superclass::SetAmbient(ka);
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDiffuse(double kd)
{
  if (this->CheckCoefficient("diffuse coefficient", kd))
  {
    this->Superclass::SetDiffuse(kd);
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetSpecular(double ks)
{
  if (this->CheckCoefficient("specular coefficient", ks))
  {
    this->Superclass::SetSpecular(ks);
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetSpecularPower(double alpha)
{
  if (this->CheckCoefficient("specular power", alpha))
  {
    this->Superclass::SetSpecularPower(alpha);
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::UpdateColoringParameters()
{
  // The superclass copies Ambient, Diffuse and Specular into the property; the shading and a
  // preset are applied after it so that they win whatever order ParaView pushed properties in.
  this->Superclass::UpdateColoringParameters();
  this->Property->SetInterpolation(Interpolations[this->Shading]);
  vtkPhongPolyDataMapper::ApplyPreset(this->Property, this->MaterialPreset); // CUSTOM: as it is
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shading: " << ShadingNames[this->Shading] << "\n";
  os << indent << "MaterialPreset: " << PresetNames[this->MaterialPreset] << "\n";
  os << indent << "SceneAmbient: " << (this->SceneAmbient ? "On" : "Off") << "\n";
}
