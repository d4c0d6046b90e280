// Shared by the Phong mapper tests: one actor drawn by a Phong mapper (polygonal or composite) in
// a headless window, the scenes the tests light it with, and the comparison with a CPU reference.
#ifndef PhongVTKPhongScene_h
#define PhongVTKPhongScene_h

#include "PhongVTKImageRegression.h"
#include "PhongVTKPhongReference.h"

#include "vtkActor.h"
#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace phongvtk
{
namespace testing
{

/// The tests' window is Size x Size pixels.
constexpr int Size = 200;

/// One actor drawn by a mapper of type MapperT in a headless window.
template <class MapperT>
class BasicPhongScene
{
public:
  BasicPhongScene(vtkDataObject* mesh, const SceneSpec& scene, const MaterialSpec& material,
    const CameraSpec& camera, int interpolation)
  {
    this->Mapper->SetInputDataObject(mesh);
    this->Actor->SetMapper(this->Mapper);
    Apply(material, this->Actor->GetProperty());
    this->Actor->GetProperty()->SetInterpolation(interpolation);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.2, 0.2, 0.2);
    Apply(scene, camera, this->Renderer);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(Size, Size);
    // One sample per pixel, as the references evaluate at pixel centres (VTK 9.4 and later's
    // own OSMesa and EGL windows multisample by default; PhongVTK's headless windows do not).
    this->Window->SetMultiSamples(0);
  }
  Image Render()
  {
    this->Window->Render();
    return Capture(this->Window);
  }
  vtkNew<MapperT> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> Window = vtkSmartPointer<vtkRenderWindow>::New();
};

/// The tests run headless whatever the environment says.
class PhongMapper : public ::testing::Test
{
protected:
  void SetUp() override
  {
    unsetenv("DISPLAY");
    unsetenv("PHONGVTK_HEADLESS");
    // VTK 9.4 and later: VTK's own OSMesa window, without first trying X and warning that there
    // is no display (PhongVTK's headless window on earlier VTK, which ignores the variable).
    setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow", 0);
  }
};

inline SceneSpec OneWhiteLight()
{
  SceneSpec s;
  LightSpec light;
  light.Position = { 1, 1, 2 };
  s.Lights.push_back(light);
  s.RendererAmbient = { 0.2, 0.2, 0.2 };
  return s;
}

/// Three coloured lights with their own ambient and specular colours: directional, positional
/// with attenuation (no cone), and a spot (cone and exponent) covering the sphere.
inline SceneSpec ThreeColouredLights()
{
  SceneSpec s;
  LightSpec key;
  key.Position = { -1, 1, 2 };
  key.Diffuse = { 1, 0.9, 0.8 };
  key.Specular = { 0.9, 0.9, 1 };
  key.Ambient = { 0.1, 0.05, 0 };
  key.Intensity = 0.8;
  LightSpec fill;
  fill.Positional = true;
  fill.Position = { 1.5, 0.5, 2 };
  fill.Diffuse = { 0.3, 0.5, 1 };
  fill.Specular = { 0.5, 0.7, 1 };
  fill.Intensity = 1.2;
  fill.Attenuation = { 1, 0.2, 0.05 };
  fill.ConeAngle = 180;
  LightSpec spot;
  spot.Positional = true;
  spot.Position = { 0, 2.5, 2.5 };
  spot.Diffuse = { 0.4, 1, 0.4 };
  spot.Specular = { 0.2, 1, 0.2 };
  spot.Intensity = 0.9;
  spot.ConeAngle = 40;
  spot.Exponent = 4;
  s.Lights = { key, fill, spot };
  s.RendererAmbient = { 0.1, 0.1, 0.15 };
  return s;
}

inline CameraSpec Perspective()
{
  return CameraSpec();
}

inline CameraSpec Parallel()
{
  CameraSpec c;
  c.Parallel = true;
  c.ParallelScale = 0.6;
  return c;
}

/// The image agrees with the reference within `rms` and `max` LSB over more than 3000 pixels.
inline void ExpectAgreement(
  const Image& image, const Reference& reference, double rms, double max, const std::string& what)
{
  const Agreement agreement = Compare(image, reference);
  std::cout << "  " << what << ": " << agreement.Describe() << "\n";
  EXPECT_GT(agreement.Pixels, 3000) << what;
  EXPECT_LE(agreement.RMS, rms) << what << ": " << agreement.Describe();
  EXPECT_LE(agreement.Max, max) << what << ": " << agreement.Describe();
}

}
}

#endif
