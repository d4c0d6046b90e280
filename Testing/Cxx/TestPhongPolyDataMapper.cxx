// vtkPhongPolyDataMapper against an independent CPU evaluation of the Phong model (world
// coordinates, double precision, PhongVTKPhongReference.h): Phong shading of a finely
// tessellated sphere against the exact sphere, Gouraud and flat against their own per-vertex and
// per-face references; the model's seed facts; the shaders holding only what the scene uses.
#include "PhongVTKOFFReader.h"
#include "PhongVTKPhongScene.h"
#include "PhongVTKRenderingTestSupport.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPolygonNormals.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

using namespace phongvtk::testing;

namespace
{

using PhongScene = BasicPhongScene<vtkPhongPolyDataMapper>;

//------------------------------------------------------------------------------
// Phong shading of a finely tessellated sphere is the exact sphere's model within RMS 1 LSB
// and max 3 LSB away from the silhouette.
struct AnalyticCase
{
  const char* Name;
  SceneSpec (*Scene)();
  CameraSpec (*Camera)();
};

class PhongShadingMatchesTheExactSphere
  : public PhongMapper
  , public ::testing::WithParamInterface<AnalyticCase>
{
};

TEST_P(PhongShadingMatchesTheExactSphere, WithinOneLSBRMSAndThreeMax)
{
  const AnalyticCase& c = GetParam();
  const SceneSpec scene = c.Scene();
  const CameraSpec camera = c.Camera();
  PhongScene phong(SphereMesh(256, 128), scene, WarmMaterial(), camera, VTK_PHONG);
  const Image image = phong.Render();
  ExpectAgreement(image,
    AnalyticSphere(scene, WarmMaterial(), camera, { 0, 0, 0 }, 0.5, Size, Size), 1.0, 3.0, c.Name);
  EXPECT_NE(phong.Mapper->GetShaderConfiguration().find("phong"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PhongShadingMatchesTheExactSphere,
  ::testing::Values(AnalyticCase{ "OneLightPerspective", OneWhiteLight, Perspective },
    AnalyticCase{ "OneLightParallel", OneWhiteLight, Parallel },
    AnalyticCase{ "ThreeColouredLightsPerspective", ThreeColouredLights, Perspective },
    AnalyticCase{ "ThreeColouredLightsParallel", ThreeColouredLights, Parallel }),
  [](const ::testing::TestParamInfo<AnalyticCase>& info) { return std::string(info.param.Name); });

// VTK's headlight (created by the renderer when it has no light) follows the same formula: a
// white directional light from the camera.
TEST_F(PhongMapper, HeadlightFollowsTheSameFormula)
{
  SceneSpec none;
  none.RendererAmbient = { 0.2, 0.2, 0.2 };
  PhongScene phong(SphereMesh(256, 128), none, WarmMaterial(), Perspective(), VTK_PHONG);
  phong.Renderer->RemoveAllLights();
  const Image image = phong.Render();
  SceneSpec headlight = none;
  LightSpec light;
  light.Position = Perspective().Position;
  headlight.Lights.push_back(light);
  ExpectAgreement(image,
    AnalyticSphere(headlight, WarmMaterial(), Perspective(), { 0, 0, 0 }, 0.5, Size, Size), 1.0,
    3.0, "headlight");
}

// Camera lights are given in the camera's frame: (0, 0, 1) is the camera, (0, 0, 0) the focal
// point, x and y the view's right and up scaled by the distance d to the focal point, so a
// camera-frame point (x, y, z) is the world point P + d x right + d y up + d (1 - z) forward
// (vtkLight, vtkCamera::GetCameraLightTransformMatrix). The same formula holds for them once
// they are placed in the world: checked with a directional and an attenuated positional camera
// light, from an oblique camera.
TEST_F(PhongMapper, CameraLightsFollowTheSameFormula)
{
  CameraSpec camera;
  camera.Position = { 2.5, 1.5, 2.5 };
  camera.FocalPoint = { 0, 0, 0 };
  camera.ViewUp = { 0, 1, 0 };
  const Vec forward = Unit(camera.FocalPoint - camera.Position);
  const Vec right = Unit(Cross(forward, camera.ViewUp));
  const Vec up = Cross(right, forward);
  const Vec toFocal = camera.FocalPoint - camera.Position;
  const double d = std::sqrt(Dot(toFocal, toFocal));
  auto world = [&](const Vec& p)
  {
    return camera.Position + (d * p[0]) * right + (d * p[1]) * up + (d * (1 - p[2])) * forward;
  };

  SceneSpec scene;
  scene.RendererAmbient = { 0.1, 0.1, 0.1 };
  LightSpec key; // directional, from above right of the camera
  key.Position = world({ 0.6, 0.8, 1 });
  key.FocalPoint = world({ 0, 0, 0 });
  key.Diffuse = { 1, 0.8, 0.6 };
  LightSpec fill; // positional, attenuated, left of the view
  fill.Positional = true;
  fill.Position = world({ -0.4, 0.1, 0.7 });
  fill.FocalPoint = world({ 0, 0, 0 });
  fill.Diffuse = { 0.4, 0.6, 1 };
  fill.Specular = { 0.6, 0.8, 1 };
  fill.Attenuation = { 1, 0.1, 0.02 };
  fill.ConeAngle = 180;
  scene.Lights = { key, fill };

  SceneSpec none;
  none.RendererAmbient = scene.RendererAmbient;
  PhongScene phong(SphereMesh(256, 128), none, WarmMaterial(), camera, VTK_PHONG);
  phong.Renderer->RemoveAllLights();
  const Vec cameraFrame[2][2] = { { { 0.6, 0.8, 1 }, { 0, 0, 0 } },
    { { -0.4, 0.1, 0.7 }, { 0, 0, 0 } } };
  for (int j = 0; j < 2; ++j)
  {
    const LightSpec& spec = scene.Lights[j];
    vtkNew<vtkLight> light;
    light->SetLightTypeToCameraLight();
    light->SetPositional(spec.Positional);
    light->SetPosition(cameraFrame[j][0].data());
    light->SetFocalPoint(cameraFrame[j][1].data());
    light->SetDiffuseColor(spec.Diffuse.data());
    light->SetSpecularColor(spec.Specular.data());
    light->SetAttenuationValues(spec.Attenuation.data());
    light->SetConeAngle(spec.ConeAngle);
    phong.Renderer->AddLight(light);
  }
  const Image image = phong.Render();
  ExpectAgreement(image,
    AnalyticSphere(scene, WarmMaterial(), camera, { 0, 0, 0 }, 0.5, Size, Size), 1.0, 3.0,
    "camera lights");
}

//------------------------------------------------------------------------------
// Gouraud: the model evaluated at the vertices of a coarse sphere and the colours interpolated,
// against the same on the CPU; and visibly not Phong shading (unlike VTK's OpenGL2 mapper, whose
// Gouraud equals Phong).
TEST_F(PhongMapper, GouraudMatchesPerVertexEvaluationWithInterpolatedColours)
{
  auto coarse = SphereMesh(24, 16);
  for (const CameraSpec& camera : { Perspective(), Parallel() })
  {
    const SceneSpec scene = ThreeColouredLights();
    PhongScene gouraud(coarse, scene, WarmMaterial(), camera, VTK_GOURAUD);
    const Image image = gouraud.Render();
    EXPECT_NE(gouraud.Mapper->GetShaderConfiguration().find("gouraud"), std::string::npos);
    ExpectAgreement(image, RayCastMesh(scene, WarmMaterial(), camera, coarse, true, Size, Size),
      1.0, 3.0, camera.Parallel ? "gouraud, parallel" : "gouraud, perspective");
    const Agreement phong =
      Compare(image, AnalyticSphere(scene, WarmMaterial(), camera, { 0, 0, 0 }, 0.5, Size, Size));
    EXPECT_GT(phong.Max, 20) << "Gouraud on 24 x 16 facets should differ from the smooth sphere: "
                             << phong.Describe();
  }
}

// Flat: one normal per face (the derivatives of the position, or the cell normals of
// vtkPolygonNormals), the model evaluated per fragment.
TEST_F(PhongMapper, FlatMatchesPerFaceEvaluation)
{
  auto coarse = SphereMesh(24, 16);
  vtkNew<vtkPolygonNormals> normals;
  normals->SetInputData(coarse);
  normals->ComputeCellNormalsOn();
  normals->ComputePointNormalsOff();
  normals->Update();
  vtkNew<vtkPolyData> withCellNormals;
  withCellNormals->ShallowCopy(normals->GetOutput());
  withCellNormals->GetPointData()->SetNormals(nullptr);
  ASSERT_NE(withCellNormals->GetCellData()->GetNormals(), nullptr);

  const SceneSpec scene = ThreeColouredLights();
  for (vtkPolyData* mesh : { coarse.Get(), withCellNormals.Get() })
  {
    const bool cellNormals = mesh == withCellNormals.Get();
    PhongScene flat(mesh, scene, WarmMaterial(), Perspective(), VTK_FLAT);
    const Image image = flat.Render();
    const std::string configuration = flat.Mapper->GetShaderConfiguration();
    EXPECT_EQ(configuration.find("derivative-normals") != std::string::npos, !cellNormals)
      << configuration;
    ExpectAgreement(image,
      RayCastMesh(scene, WarmMaterial(), Perspective(), coarse, false, Size, Size), 1.0, 3.0,
      cellNormals ? "flat, cell normals" : "flat, derivatives");
  }
}

//------------------------------------------------------------------------------
// Seed facts of the model.

// The colour products are component-wise: a red surface under a blue light is black.
TEST_F(PhongMapper, RedSurfaceUnderBlueLightIsBlack)
{
  SceneSpec scene;
  LightSpec blue;
  blue.Position = { 0, 0, 1 };
  blue.Diffuse = blue.Specular = blue.Ambient = { 0, 0, 1 };
  scene.Lights.push_back(blue);
  scene.RendererAmbient = { 0, 0, 0.5 };
  MaterialSpec red;
  red.Ambient = 0.3;
  red.Diffuse = 1;
  red.Specular = 1;
  red.SpecularPower = 10;
  red.AmbientColor = red.DiffuseColor = red.SpecularColor = { 1, 0, 0 };
  PhongScene phong(SphereMesh(64, 32), scene, red, Perspective(), VTK_PHONG);
  const Image image = phong.Render();
  const Reference sphere = AnalyticSphere(scene, red, Perspective(), { 0, 0, 0 }, 0.5, Size, Size);
  int pixels = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      Vec expected;
      if (sphere(x, y, expected))
      {
        ++pixels;
        ASSERT_EQ(image.At(x, y, 0) + image.At(x, y, 1) + image.At(x, y, 2), 0)
          << "pixel " << x << ", " << y;
      }
    }
  }
  EXPECT_GT(pixels, 3000);
  EXPECT_EQ(image.At(0, 0, 0), 51) << "the background is drawn around the black sphere";
}

// The same product with non-trivial components: kd = (0.8, 0.4, 0.2), Id = (0.5, 1, 0.25)
// give (0.4, 0.4, 0.05) where n.l = 1 (the light behind the camera, parallel projection).
TEST_F(PhongMapper, ColourProductsAreComponentWise)
{
  SceneSpec scene;
  LightSpec light;
  light.Position = { 0, 0, 1 };
  light.Diffuse = { 0.5, 1, 0.25 };
  scene.Lights.push_back(light);
  MaterialSpec m;
  m.DiffuseColor = { 0.8, 0.4, 0.2 };
  PhongScene phong(SphereMesh(64, 32), scene, m, Parallel(), VTK_PHONG);
  const Image image = phong.Render();
  const double expected[3] = { 0.4, 0.4, 0.05 };
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(image.At(Size / 2, Size / 2, c), 255 * expected[c], 1.0) << "channel " << c;
  }
}

// A light behind the surface gives no diffuse and no specular: only ka*Ia remains, on every
// visible point (parallel projection: the visible half is exactly the half facing away).
TEST_F(PhongMapper, LightBehindTheSurfaceLeavesOnlyTheAmbientTerm)
{
  SceneSpec scene;
  LightSpec behind;
  behind.Position = { 0, 0, -1 };
  behind.Ambient = { 0.1, 0.2, 0.3 };
  scene.Lights.push_back(behind);
  scene.RendererAmbient = { 0.3, 0.2, 0.1 };
  MaterialSpec m = WarmMaterial();
  m.Ambient = 0.5;
  PhongScene phong(SphereMesh(64, 32), scene, m, Parallel(), VTK_PHONG);
  const Image image = phong.Render();
  // ka*Ia = 0.5*(0.9, 0.6, 0.3)*(0.4, 0.4, 0.4)
  const double ambient[3] = { 0.18, 0.12, 0.06 };
  const Reference sphere = AnalyticSphere(scene, m, Parallel(), { 0, 0, 0 }, 0.5, Size, Size, 0.1);
  int pixels = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      Vec colour;
      if (!sphere(x, y, colour))
      {
        continue;
      }
      ++pixels;
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_NEAR(image.At(x, y, c), 255 * ambient[c], 0.51)
          << x << ", " << y << " channel " << c;
      }
    }
  }
  EXPECT_GT(pixels, 5000);
}

// The highlight sits where v.r is largest: under parallel projection with a directional light,
// where the normal is the half vector h = (l + v)/|l + v|.
TEST_F(PhongMapper, HighlightSitsWhereVDotRIsLargest)
{
  SceneSpec scene;
  LightSpec light;
  light.Position = { 1, 0.5, 1 };
  scene.Lights.push_back(light);
  MaterialSpec shiny;
  shiny.Diffuse = 0;
  shiny.Specular = 1;
  shiny.SpecularPower = 200;
  PhongScene phong(SphereMesh(256, 128), scene, shiny, Parallel(), VTK_PHONG);
  const Image image = phong.Render();
  int bx = -1, by = -1, best = -1;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      if (image.At(x, y, 0) > best)
      {
        best = image.At(x, y, 0);
        bx = x;
        by = y;
      }
    }
  }
  const Vec h = Unit(Unit(light.Position) + Vec{ 0, 0, 1 });
  // The sphere point 0.5*h seen through the parallel camera (scale 0.6: 200 px = 1.2 units).
  const double px = (0.5 * h[0] / 0.6 + 1) * Size / 2 - 0.5;
  const double py = (0.5 * h[1] / 0.6 + 1) * Size / 2 - 0.5;
  EXPECT_GE(best, 250) << "ks*Is*(v.r)^alpha = 1 at the half vector";
  EXPECT_LE(std::hypot(bx - px, by - py), 1.5)
    << "brightest pixel " << bx << ", " << by << "; half vector at " << px << ", " << py;
}

// Two-sided lighting follows the renderer: a back face is lit with its normal reversed, or gets
// only the ambient term.
TEST_F(PhongMapper, BackFacesFollowTheRenderersTwoSidedLighting)
{
  vtkNew<vtkPlaneSource> plane; // normal +z, seen from -z below
  plane->SetResolution(4, 4);
  plane->Update();
  CameraSpec below;
  below.Position = { 0, 0, -4 };
  SceneSpec scene;
  LightSpec light;
  light.Position = { 0, 0, -1 };
  scene.Lights.push_back(light);
  scene.RendererAmbient = { 1, 1, 1 };
  MaterialSpec m;
  m.Ambient = 0.2;
  m.Diffuse = 0.5;
  m.AmbientColor = m.DiffuseColor = { 1, 1, 1 };
  for (bool twoSided : { true, false })
  {
    scene.TwoSided = twoSided;
    PhongScene phong(plane->GetOutput(), scene, m, below, VTK_PHONG);
    const Image image = phong.Render();
    const double expected = twoSided ? 0.7 : 0.2; // 0.2 ambient + 0.5 diffuse when lit
    EXPECT_NEAR(image.At(Size / 2, Size / 2, 1), 255 * expected, 1.0)
      << (twoSided ? "two-sided" : "one-sided");
  }
}

//------------------------------------------------------------------------------
// The shaders hold only what the scene uses.
TEST_F(PhongMapper, DiffuseOnlySceneHasNoSpecularCode)
{
  MaterialSpec matte = WarmMaterial();
  matte.Specular = 0;
  PhongScene phong(SphereMesh(32, 16), OneWhiteLight(), matte, Perspective(), VTK_PHONG);
  phong.Render();
  const std::string fs = phong.Mapper->GetFragmentShaderSource();
  ASSERT_FALSE(fs.empty());
  EXPECT_EQ(fs.find("pecular"), std::string::npos) << fs; // no specular term, uniform or function
  EXPECT_NE(fs.find("phongDiffuse("), std::string::npos);
  // Directional light, no eye vector needed, point normals: no interpolated position.
  EXPECT_EQ(fs.find("vertexVC"), std::string::npos) << fs;
  EXPECT_EQ(phong.Mapper->GetVertexShaderSource().find("vertexVCVSOutput"), std::string::npos);
}

TEST_F(PhongMapper, ShadersHoldExactlyTheScenesLightsAndKinds)
{
  PhongScene phong(
    SphereMesh(32, 16), ThreeColouredLights(), WarmMaterial(), Perspective(), VTK_PHONG);
  phong.Render();
  const std::string fs = phong.Mapper->GetFragmentShaderSource();
  EXPECT_NE(fs.find("// light 0: directional"), std::string::npos) << fs;
  EXPECT_NE(fs.find("// light 1: positional, attenuated"), std::string::npos) << fs;
  EXPECT_NE(fs.find("// light 2: spot"), std::string::npos) << fs;
  EXPECT_EQ(fs.find("light 3"), std::string::npos);
  EXPECT_EQ(fs.find("for ("), std::string::npos) << "no loop over lights";
  EXPECT_EQ(fs.find("lightColor"), std::string::npos) << "none of VTK's own light code";

  // One directional light: no attenuation or cone code at all.
  PhongScene one(SphereMesh(32, 16), OneWhiteLight(), WarmMaterial(), Perspective(), VTK_PHONG);
  one.Render();
  const std::string single = one.Mapper->GetFragmentShaderSource();
  EXPECT_EQ(single.find("phongAttenuation"), std::string::npos);
  EXPECT_EQ(single.find("phongSpotlight"), std::string::npos);
  EXPECT_EQ(single.find("light 1"), std::string::npos);
  // The specular eye vector varies under perspective: on large triangles (fragment-bound) it is
  // interpolated from the position...
  EXPECT_NE(single.find("vec3 v = normalize(-vertexVC.xyz)"), std::string::npos) << single;
  // ...on triangles of a few pixels (vertex-bound: 65,024 triangles in 200 x 200 pixels) it is
  // the reversed ray through the pixel, with directional lights only: no interpolated position.
  PhongScene fine(SphereMesh(256, 128), OneWhiteLight(), WarmMaterial(), Perspective(), VTK_PHONG);
  fine.Render();
  const std::string small = fine.Mapper->GetFragmentShaderSource();
  EXPECT_NE(small.find("gl_FragCoord"), std::string::npos) << small;
  EXPECT_EQ(small.find("vertexVC"), std::string::npos) << small;
  EXPECT_EQ(fine.Mapper->GetVertexShaderSource().find("vertexVCVSOutput"), std::string::npos);
}

// The eye vector from gl_FragCoord follows the renderer's viewport: a renderer in the right half
// of a window, a perspective camera, a specular highlight, against the exact sphere.
TEST_F(PhongMapper, EyeVectorFollowsTheViewport)
{
  const SceneSpec scene = OneWhiteLight();
  PhongScene phong(SphereMesh(256, 128), scene, WarmMaterial(), Perspective(), VTK_PHONG);
  phong.Renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
  phong.Window->SetSize(2 * Size, Size);
  const Image image = phong.Render();
  ASSERT_NE(phong.Mapper->GetFragmentShaderSource().find("gl_FragCoord"), std::string::npos);
  const Reference sphere =
    AnalyticSphere(scene, WarmMaterial(), Perspective(), { 0, 0, 0 }, 0.5, Size, Size);
  ExpectAgreement(
    image, [&](int px, int py, Vec& colour) { return px >= Size && sphere(px - Size, py, colour); },
    1.0, 3.0, "right half of the window");
}

TEST_F(PhongMapper, GouraudEvaluatesInTheVertexShaderOnly)
{
  PhongScene gouraud(
    SphereMesh(32, 16), OneWhiteLight(), WarmMaterial(), Perspective(), VTK_GOURAUD);
  gouraud.Render();
  const std::string vs = gouraud.Mapper->GetVertexShaderSource();
  const std::string fs = gouraud.Mapper->GetFragmentShaderSource();
  EXPECT_NE(vs.find("phongDiffuse("), std::string::npos) << vs;
  EXPECT_NE(vs.find("phongSpecular("), std::string::npos) << vs;
  EXPECT_EQ(fs.find("phongDiffuse("), std::string::npos) << fs;
  EXPECT_EQ(fs.find("normalVCVSOutput"), std::string::npos) << fs;
  EXPECT_EQ(fs.find("vertexVC"), std::string::npos) << fs;
}

TEST_F(PhongMapper, ShadersAreRebuiltOnlyWhenTheConfigurationChanges)
{
  PhongScene phong(SphereMesh(32, 16), OneWhiteLight(), WarmMaterial(), Perspective(), VTK_PHONG);
  phong.Render();
  const int first = phong.Mapper->GetShaderRebuilds();
  EXPECT_GE(first, 1);
  phong.Render();
  EXPECT_EQ(phong.Mapper->GetShaderRebuilds(), first) << "redrawing an unchanged scene";
  phong.Actor->GetProperty()->SetSpecular(0.6);
  phong.Actor->GetProperty()->SetSpecularPower(10);
  phong.Render();
  EXPECT_EQ(phong.Mapper->GetShaderRebuilds(), first) << "a coefficient, every term still present";
  phong.Actor->GetProperty()->SetSpecular(0);
  phong.Render();
  EXPECT_EQ(phong.Mapper->GetShaderRebuilds(), first + 1) << "the specular term dropped";
  EXPECT_EQ(phong.Mapper->GetFragmentShaderSource().find("pecular"), std::string::npos);
  vtkLight* light = vtkLight::SafeDownCast(phong.Renderer->GetLights()->GetItemAsObject(0));
  light->SetPositional(true);
  light->SetConeAngle(90);
  phong.Render();
  EXPECT_EQ(phong.Mapper->GetShaderRebuilds(), first + 2) << "a light changed kind";
  EXPECT_NE(phong.Mapper->GetFragmentShaderSource().find("light 0: positional"), std::string::npos);
}

// Smooth shading without point normals falls back to flat with one warning.
TEST_F(PhongMapper, SmoothShadingWithoutPointNormalsFallsBackToFlatWithOneWarning)
{
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(SphereMesh(24, 16));
  bare->GetPointData()->SetNormals(nullptr);
  MessageCatcher messages;
  PhongScene phong(bare, ThreeColouredLights(), WarmMaterial(), Perspective(), VTK_PHONG);
  const Image image = phong.Render();
  phong.Render();
  ASSERT_EQ(messages.Warnings().size(), 1u);
  EXPECT_NE(messages.Warnings()[0].find("point normals"), std::string::npos);
  EXPECT_NE(phong.Mapper->GetShaderConfiguration().find("flat"), std::string::npos);
  ExpectAgreement(image,
    RayCastMesh(ThreeColouredLights(), WarmMaterial(), Perspective(), bare, false, Size, Size), 1.0,
    3.0, "fallback to flat");
}

// Presets set the material as documented (vtkPhongPolyDataMapper.h), keeping the diffuse colour:
// ka = kd as colours with ambient strength 0.1, and the documented coefficients.
TEST_F(PhongMapper, PresetsSetTheMaterial)
{
  vtkNew<vtkProperty> p;
  p->SetDiffuseColor(0.8, 0.2, 0.1);
  p->SetDiffuse(0.9);
  p->SetAmbient(0.7);
  struct Expected
  {
    const char* Name;
    double Diffuse, Specular, SpecularPower;
    bool Tinted;
  };
  for (const Expected& e : { Expected{ "plastic", 0.8, 0.3, 30.0, false },
         Expected{ "metal", 0.45, 0.6, 60.0, true }, Expected{ "matte", 0.9, 0.0, 1.0, false } })
  {
    ASSERT_TRUE(vtkPhongPolyDataMapper::ApplyPreset(p, e.Name)) << e.Name;
    EXPECT_EQ(p->GetAmbient(), 0.1) << e.Name;
    EXPECT_EQ(p->GetDiffuse(), e.Diffuse) << e.Name;
    EXPECT_EQ(p->GetSpecular(), e.Specular) << e.Name;
    if (e.Specular > 0)
    {
      EXPECT_EQ(p->GetSpecularPower(), e.SpecularPower) << e.Name;
      EXPECT_EQ(p->GetSpecularColor()[1], e.Tinted ? 0.2 : 1.0) << e.Name;
    }
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(p->GetAmbientColor()[c], p->GetDiffuseColor()[c]) << e.Name;
    }
    EXPECT_EQ(p->GetDiffuseColor()[0], 0.8) << e.Name;
  }
  p->SetDiffuse(0.55);
  EXPECT_FALSE(vtkPhongPolyDataMapper::ApplyPreset(p, "velvet"));
  EXPECT_EQ(p->GetDiffuse(), 0.55) << "an unknown preset changes nothing";
}

// One enumeration of presets (the mapper's, also the ParaView representation's MaterialPreset):
// CUSTOM (0) keeps the property, each other value is its named preset, other values warn and
// change nothing.
TEST_F(PhongMapper, PresetValuesAreCustomThenTheNamedPresets)
{
  EXPECT_STREQ(vtkPhongPolyDataMapper::GetPresetName(0), "custom");
  EXPECT_STREQ(vtkPhongPolyDataMapper::GetPresetName(vtkPhongPolyDataMapper::PLASTIC), "plastic");
  EXPECT_STREQ(vtkPhongPolyDataMapper::GetPresetName(vtkPhongPolyDataMapper::METAL), "metal");
  EXPECT_STREQ(vtkPhongPolyDataMapper::GetPresetName(vtkPhongPolyDataMapper::MATTE), "matte");
  EXPECT_EQ(vtkPhongPolyDataMapper::GetPresetName(-1), nullptr);
  EXPECT_EQ(vtkPhongPolyDataMapper::GetPresetName(4), nullptr);
  auto material = [](vtkProperty* p)
  {
    return std::vector<double>{ p->GetAmbient(), p->GetDiffuse(), p->GetSpecular(),
      p->GetSpecularPower(), p->GetAmbientColor()[0], p->GetSpecularColor()[1] };
  };
  vtkNew<vtkProperty> own;
  own->SetDiffuseColor(0.8, 0.2, 0.1);
  own->SetAmbient(0.7);
  own->SetDiffuse(0.55);
  own->SetSpecular(0.25);
  own->SetSpecularPower(12.0);
  own->SetSpecularColor(0.3, 0.4, 0.5);
  const std::vector<double> before = material(own);
  vtkPhongPolyDataMapper::ApplyPreset(own, vtkPhongPolyDataMapper::CUSTOM);
  EXPECT_EQ(material(own), before) << "CUSTOM keeps the property's own material";
  EXPECT_TRUE(vtkPhongPolyDataMapper::ApplyPreset(own, "custom"));
  EXPECT_EQ(material(own), before);
  for (int preset = vtkPhongPolyDataMapper::PLASTIC; preset <= vtkPhongPolyDataMapper::MATTE;
       ++preset)
  {
    vtkNew<vtkProperty> byValue, byName;
    byValue->DeepCopy(own);
    byName->DeepCopy(own);
    vtkPhongPolyDataMapper::ApplyPreset(byValue, preset);
    ASSERT_TRUE(
      vtkPhongPolyDataMapper::ApplyPreset(byName, vtkPhongPolyDataMapper::GetPresetName(preset)));
    EXPECT_EQ(material(byValue), material(byName)) << preset;
    EXPECT_NE(material(byValue), before) << preset;
  }
  MessageCatcher messages;
  vtkPhongPolyDataMapper::ApplyPreset(own, 4);
  vtkPhongPolyDataMapper::ApplyPreset(own, -1);
  EXPECT_EQ(material(own), before) << "an unknown value changes nothing";
  ASSERT_EQ(messages.Warnings().size(), 2u);
  EXPECT_NE(messages.Warnings()[0].find("CUSTOM (0)"), std::string::npos);
}

// Scene ambient: Ia = (sum of Id) * mean kd of the visible actors.
TEST_F(PhongMapper, SceneAmbientIsTheLightTimesTheMeanDiffuseReflectance)
{
  SceneSpec scene;
  LightSpec light;
  light.Position = { 0, 0, -1 }; // behind: only the ambient term shows
  light.Diffuse = { 1, 0.5, 0.5 };
  scene.Lights.push_back(light);
  scene.RendererAmbient = { 1, 1, 1 }; // replaced by the scene-derived ambient
  MaterialSpec m;
  m.Ambient = 1;
  m.AmbientColor = { 1, 1, 1 };
  m.Diffuse = 0.5;
  m.DiffuseColor = { 0.2, 0.4, 0.8 };
  PhongScene phong(SphereMesh(64, 32), scene, m, Parallel(), VTK_PHONG);
  phong.Mapper->SceneAmbientOn();
  const Image image = phong.Render();
  // Ia = (1, 0.5, 0.5) * 0.5 * (0.2, 0.4, 0.8) = (0.1, 0.1, 0.2); ka = 1.
  EXPECT_NEAR(image.At(Size / 2, Size / 2, 0), 25.5, 1.0);
  EXPECT_NEAR(image.At(Size / 2, Size / 2, 1), 25.5, 1.0);
  EXPECT_NEAR(image.At(Size / 2, Size / 2, 2), 51.0, 1.0);
}

}

namespace
{
// The general shader (every term of every light) draws the same image as the specialised one,
// with and without a specular term, in the three modes.
TEST_F(PhongMapper, GeneralShaderDrawsTheSameImage)
{
  MaterialSpec matte = WarmMaterial();
  matte.Specular = 0;
  for (const MaterialSpec& material : { matte, WarmMaterial() })
  {
    const bool specular = material.Specular > 0;
    for (int interpolation : { VTK_FLAT, VTK_GOURAUD, VTK_PHONG })
    {
      PhongScene phong(
        SphereMesh(48, 24), ThreeColouredLights(), material, Perspective(), interpolation);
      const Image specialised = phong.Render();
      const std::string lean =
        phong.Mapper->GetFragmentShaderSource() + phong.Mapper->GetVertexShaderSource();
      phong.Mapper->SpecializeShadersOff();
      const Image general = phong.Render();
      const std::string full =
        phong.Mapper->GetFragmentShaderSource() + phong.Mapper->GetVertexShaderSource();
      EXPECT_LE(MaxAbsDifference(specialised, general), 1)
        << "interpolation " << interpolation << (specular ? " with" : " without") << " specular";
      EXPECT_EQ(lean.find("phongSpecular(") != std::string::npos, specular);
      EXPECT_NE(full.find("phongSpecular("), std::string::npos);
    }
  }
}

// The general shader's specular path against the exact sphere (as the specialised shader is in
// PhongShadingMatchesTheExactSphere): the highlights of three coloured lights, both projections.
TEST_F(PhongMapper, GeneralShaderWithSpecularMatchesTheExactSphere)
{
  const SceneSpec scene = ThreeColouredLights();
  ASSERT_GT(WarmMaterial().Specular, 0);
  for (const CameraSpec& camera : { Perspective(), Parallel() })
  {
    PhongScene phong(SphereMesh(256, 128), scene, WarmMaterial(), camera, VTK_PHONG);
    phong.Mapper->SpecializeShadersOff();
    const Image image = phong.Render();
    ASSERT_EQ(phong.Mapper->GetShaderConfiguration().find("phong"), 0u);
    ExpectAgreement(image,
      AnalyticSphere(scene, WarmMaterial(), camera, { 0, 0, 0 }, 0.5, Size, Size), 1.0, 3.0,
      camera.Parallel ? "general shader, parallel" : "general shader, perspective");
  }
}
}

//------------------------------------------------------------------------------
// Image baselines for real meshes: CGAL's bunny (bunny00.off) and fandisk (fandisk.off, a CAD
// part with creases) with vtkPolygonNormals' cell and point normals under three coloured lights,
// in the three shading modes. The modes must differ visibly from each other (flat facets,
// Gouraud's interpolated highlights, Phong's).
namespace
{
/// CGAL's mesh `name` centred at the origin, diagonal of the bounds 2 (where the scenes' lights
/// expect it), with the cell and point normals of vtkPolygonNormals set up by `configure`; with
/// `turn`, rotated 35 degrees about x, then -40 about y (to show fandisk's top and creases).
vtkSmartPointer<vtkPolyData> UnitMesh(const char* name,
  const std::function<void(vtkPolygonNormals*)>& configure = {}, bool turn = false)
{
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name), &error);
  if (!mesh)
  {
    ADD_FAILURE() << error;
    return nullptr;
  }
  double bounds[6];
  mesh->GetBounds(bounds);
  const double centre[3] = { (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
    (bounds[4] + bounds[5]) / 2 };
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  vtkPoints* points = mesh->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      p[c] = (p[c] - centre[c]) * 2 / diagonal;
    }
    if (turn)
    {
      const double a = vtkMath::RadiansFromDegrees(35.0), b = vtkMath::RadiansFromDegrees(-40.0);
      const double y = std::cos(a) * p[1] - std::sin(a) * p[2];
      const double z = std::sin(a) * p[1] + std::cos(a) * p[2];
      const double x = std::cos(b) * p[0] + std::sin(b) * z;
      p[2] = -std::sin(b) * p[0] + std::cos(b) * z;
      p[0] = x;
      p[1] = y;
    }
    points->SetPoint(i, p);
  }
  vtkNew<vtkPolygonNormals> normals;
  normals->SetInputData(mesh);
  normals->ComputeCellNormalsOn();
  normals->ComputePointNormalsOn();
  normals->SplittingOff(); // smooth across every edge, the polygons as given, unless configured
  normals->ConsistencyOff();
  if (configure)
  {
    configure(normals);
  }
  normals->Update();
  return normals->GetOutput();
}

// The shading baselines' tolerance tells the modes apart: each mode's image is outside it
// against the other two modes' baselines.
void ExpectEachModeFailsTheOtherBaselines(const Image images[3], const char* const names[3])
{
  const Tolerance tolerance = ShadingTolerance();
  for (int mode = 0; mode < 3; ++mode)
  {
    for (int other = 0; other < 3; ++other)
    {
      Image baseline;
      if (other == mode ||
        !ReadPNG(std::string(PHONGVTK_BASELINE_DIR) + "/" + names[other] + ".png", baseline))
      {
        continue;
      }
      const int largest = MaxAbsDifference(images[mode], baseline);
      const double rms = RMSDifference(images[mode], baseline);
      EXPECT_TRUE(largest > tolerance.MaxLSB || rms > tolerance.RMSLSB)
        << names[mode] << "'s image is within the tolerance of " << names[other]
        << "'s baseline: " << largest << " LSB at most, RMS " << rms;
    }
  }
}

vtkSmartPointer<vtkPolyData> UnitBunny()
{
  return UnitMesh("bunny00.off");
}
}

TEST_F(PhongMapper, BunnyMatchesItsBaselinesInTheThreeModes)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  auto bunny = UnitBunny();
  ASSERT_NE(bunny, nullptr);
  ASSERT_NE(bunny->GetPointData()->GetNormals(), nullptr);
  ASSERT_NE(bunny->GetCellData()->GetNormals(), nullptr);
  const char* names[] = { "PhongBunnyFlat", "PhongBunnyGouraud", "PhongBunnyPhong" };
  const char* modes[] = { "flat ", "gouraud ", "phong " };
  Image images[3];
  for (int interpolation : { VTK_FLAT, VTK_GOURAUD, VTK_PHONG })
  {
    PhongScene scene(bunny, ThreeColouredLights(), WarmMaterial(), Perspective(), interpolation);
    scene.Window->SetSize(320, 320);
    images[interpolation] = scene.Render();
    const std::string configuration = scene.Mapper->GetShaderConfiguration();
    EXPECT_EQ(configuration.find(modes[interpolation]), 0u) << configuration;
    EXPECT_TRUE(MatchesBaseline(images[interpolation], names[interpolation], ShadingTolerance()));
  }
  ExpectEachModeFailsTheOtherBaselines(images, names);
  EXPECT_GT(MaxAbsDifference(images[VTK_FLAT], images[VTK_PHONG]), 20);
  EXPECT_GT(MaxAbsDifference(images[VTK_GOURAUD], images[VTK_PHONG]), 10);
}

TEST_F(PhongMapper, FandiskMatchesItsBaselinesInTheThreeModesWithCrispCreases)
{
  // Split at 30 degrees and oriented outward, as `phongvtk render` draws it: Gouraud and Phong
  // shade the curved patches smoothly and keep every crease as sharp as flat shading does.
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  auto split = [](vtkPolygonNormals* f)
  {
    f->SplittingOn();
    f->AutoOrientNormalsOn();
  };
  auto fandisk = UnitMesh("fandisk.off", split, true);
  auto rounded = UnitMesh("fandisk.off", {}, true);
  ASSERT_NE(fandisk, nullptr);
  ASSERT_NE(rounded, nullptr);
  ASSERT_GT(fandisk->GetNumberOfPoints(), rounded->GetNumberOfPoints()) << "nothing was split";
  const char* names[] = { "PhongFandiskFlat", "PhongFandiskGouraud", "PhongFandiskPhong" };
  Image images[3];
  for (int interpolation : { VTK_FLAT, VTK_GOURAUD, VTK_PHONG })
  {
    PhongScene scene(fandisk, ThreeColouredLights(), WarmMaterial(), Perspective(), interpolation);
    scene.Window->SetSize(320, 320);
    images[interpolation] = scene.Render();
    EXPECT_TRUE(MatchesBaseline(images[interpolation], names[interpolation], ShadingTolerance()));
  }
  ExpectEachModeFailsTheOtherBaselines(images, names);
  EXPECT_GT(MaxAbsDifference(images[VTK_FLAT], images[VTK_PHONG]), 10);
  // Without splitting the normals average across the creases: a visibly different picture.
  PhongScene soft(rounded, ThreeColouredLights(), WarmMaterial(), Perspective(), VTK_PHONG);
  soft.Window->SetSize(320, 320);
  EXPECT_GT(MaxAbsDifference(soft.Render(), images[VTK_PHONG]), 40);
}
