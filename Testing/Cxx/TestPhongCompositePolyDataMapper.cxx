// vtkPhongCompositePolyDataMapper: multiblock data lit by the same Phong model as
// vtkPhongPolyDataMapper, checked against the independent CPU reference per block (two spheres,
// one per block), with per-block colours (also overriding mapped scalars), the shader
// specialisation and rebuild counting across helpers, and block picking.
#include "PhongVTKPhongScene.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongPolyDataMapper.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkHardwareSelector.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace phongvtk::testing;

namespace
{

using CompositeScene = BasicPhongScene<vtkPhongCompositePolyDataMapper>;

// Two spheres side by side, one per block (left: block 0, right: block 1).
constexpr double Radius = 0.4;
const Vec LeftCentre = { -0.45, 0, 0 };
const Vec RightCentre = { 0.45, 0, 0 };

vtkSmartPointer<vtkMultiBlockDataSet> TwoSpheres(int theta, int phi)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, SphereMesh(theta, phi, Radius, LeftCentre));
  blocks->SetBlock(1, SphereMesh(theta, phi, Radius, RightCentre));
  return blocks;
}

// Both spheres fit the parallel view too.
CameraSpec WideParallel()
{
  CameraSpec c = Parallel();
  c.ParallelScale = 1.0;
  return c;
}

// The reference of the left sphere where it is seen, else the right one's (they do not overlap
// on the screen).
Reference Either(const Reference& left, const Reference& right)
{
  return [=](int px, int py, Vec& colour)
  {
    return left(px, py, colour) || right(px, py, colour);
  };
}

MaterialSpec WithColour(MaterialSpec material, const Vec& colour)
{
  material.AmbientColor = material.DiffuseColor = colour;
  return material;
}

//------------------------------------------------------------------------------
// Phong shading of each block matches the exact spheres within RMS 1 LSB and max 3 LSB.
TEST_F(PhongMapper, CompositePhongShadingMatchesTheExactSpheres)
{
  const SceneSpec scene = ThreeColouredLights();
  for (const CameraSpec& camera : { Perspective(), WideParallel() })
  {
    CompositeScene phong(TwoSpheres(256, 128), scene, WarmMaterial(), camera, VTK_PHONG);
    const Image image = phong.Render();
    EXPECT_NE(phong.Mapper->GetShaderConfiguration().find("phong"), std::string::npos);
    ExpectAgreement(image,
      Either(AnalyticSphere(scene, WarmMaterial(), camera, LeftCentre, Radius, Size, Size),
        AnalyticSphere(scene, WarmMaterial(), camera, RightCentre, Radius, Size, Size)),
      1.0, 3.0, camera.Parallel ? "composite phong, parallel" : "composite phong, perspective");
  }
}

// Gouraud and flat: per-vertex evaluation with interpolated colours, and per-face evaluation.
TEST_F(PhongMapper, CompositeGouraudAndFlatMatchTheirMeshReferences)
{
  const SceneSpec scene = ThreeColouredLights();
  auto blocks = TwoSpheres(24, 16);
  auto* left = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
  auto* right = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
  for (int interpolation : { VTK_GOURAUD, VTK_FLAT })
  {
    const bool gouraud = interpolation == VTK_GOURAUD;
    CompositeScene scene3(blocks, scene, WarmMaterial(), Perspective(), interpolation);
    const Image image = scene3.Render();
    EXPECT_NE(scene3.Mapper->GetShaderConfiguration().find(gouraud ? "gouraud" : "flat"),
      std::string::npos);
    ExpectAgreement(image,
      Either(RayCastMesh(scene, WarmMaterial(), Perspective(), left, gouraud, Size, Size),
        RayCastMesh(scene, WarmMaterial(), Perspective(), right, gouraud, Size, Size)),
      1.0, 3.0, gouraud ? "composite gouraud" : "composite flat");
  }
}

// A block's colour (vtkCompositeDataDisplayAttributes) replaces the material colour (ka and kd
// of that block), in every shading mode; the other block keeps the material.
TEST_F(PhongMapper, CompositeBlockColourReplacesTheMaterialColour)
{
  const SceneSpec scene = ThreeColouredLights();
  const Vec blue = { 0.2, 0.4, 1.0 };
  for (int interpolation : { VTK_FLAT, VTK_GOURAUD, VTK_PHONG })
  {
    // Phong on fine facets against the exact spheres, the others on coarse ones against the
    // ray-cast facets.
    auto blocks = interpolation == VTK_PHONG ? TwoSpheres(256, 128) : TwoSpheres(24, 16);
    CompositeScene phong(blocks, scene, WarmMaterial(), Perspective(), interpolation);
    vtkNew<vtkCompositeDataDisplayAttributes> attributes;
    attributes->SetBlockColor(blocks->GetBlock(1), blue.data());
    phong.Mapper->SetCompositeDataDisplayAttributes(attributes);
    const Image image = phong.Render();
    auto* left = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
    auto* right = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
    const bool smooth = interpolation != VTK_FLAT;
    const Reference reference = interpolation == VTK_PHONG
      ? Either(AnalyticSphere(scene, WarmMaterial(), Perspective(), LeftCentre, Radius, Size, Size),
          AnalyticSphere(scene, WithColour(WarmMaterial(), blue), Perspective(), RightCentre,
            Radius, Size, Size))
      : Either(RayCastMesh(scene, WarmMaterial(), Perspective(), left, smooth, Size, Size),
          RayCastMesh(
            scene, WithColour(WarmMaterial(), blue), Perspective(), right, smooth, Size, Size));
    ExpectAgreement(
      image, reference, 1.0, 3.0, "block colour, interpolation " + std::to_string(interpolation));
  }
}

// With mapped scalars the block colour overrides the scalars of its block: in Gouraud shading
// the vertex shader, which evaluates the whole colour, must pick the block colour.
TEST_F(PhongMapper, CompositeBlockColourOverridesPointScalarsInGouraud)
{
  const SceneSpec scene = ThreeColouredLights();
  const Vec blue = { 0.2, 0.4, 1.0 };
  const unsigned char green[3] = { 51, 204, 102 };
  auto blocks = TwoSpheres(24, 16);
  for (unsigned int b = 0; b < 2; ++b)
  {
    auto* mesh = vtkPolyData::SafeDownCast(blocks->GetBlock(b));
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("colours");
    colours->SetNumberOfComponents(3);
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      colours->InsertNextTypedTuple(green);
    }
    mesh->GetPointData()->SetScalars(colours);
  }
  CompositeScene gouraud(blocks, scene, WarmMaterial(), Perspective(), VTK_GOURAUD);
  gouraud.Mapper->SetColorModeToDirectScalars();
  gouraud.Mapper->ScalarVisibilityOn();
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockColor(blocks->GetBlock(1), blue.data());
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  // From VTK 9.3 a block colour replaces visible scalars only where the block's own scalar
  // visibility is off (vtkCompositePolyDataMapper sets OverridesColor so); up to 9.2 it always
  // did. The mapper follows VTK's rule: the block is set up so that both VTKs override. (The
  // block is then drawn by its own delegator, with uniform colours.)
  attributes->SetBlockScalarVisibility(blocks->GetBlock(1), false);
  const char* expected = "gouraud perspective two-sided";
#else
  // The block colour replaces the point colours in the vertex shader (OverridesColor).
  const char* expected = "gouraud perspective two-sided point-colours";
#endif
  gouraud.Mapper->SetCompositeDataDisplayAttributes(attributes);
  const Image image = gouraud.Render();
  EXPECT_NE(gouraud.Mapper->GetShaderConfiguration().find(expected), std::string::npos)
    << gouraud.Mapper->GetShaderConfiguration();
  EXPECT_NE(gouraud.Mapper->GetShaderConfiguration().find("block-colours"), std::string::npos)
    << gouraud.Mapper->GetShaderConfiguration();
  const Vec scalar = { green[0] / 255.0, green[1] / 255.0, green[2] / 255.0 };
  ExpectAgreement(image,
    Either(RayCastMesh(scene, WithColour(WarmMaterial(), scalar), Perspective(),
             vtkPolyData::SafeDownCast(blocks->GetBlock(0)), true, Size, Size),
      RayCastMesh(scene, WithColour(WarmMaterial(), blue), Perspective(),
        vtkPolyData::SafeDownCast(blocks->GetBlock(1)), true, Size, Size)),
    1.0, 3.0, "gouraud, scalars with a block colour");
}

//------------------------------------------------------------------------------
// The composite mapper draws what the polygonal one draws for the same polygons.
TEST_F(PhongMapper, CompositeDrawsWhatThePolygonalMapperDraws)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, SphereMesh(48, 24));
  for (int interpolation : { VTK_FLAT, VTK_GOURAUD, VTK_PHONG })
  {
    CompositeScene composite(
      blocks, ThreeColouredLights(), WarmMaterial(), Perspective(), interpolation);
    BasicPhongScene<vtkPhongPolyDataMapper> single(
      blocks->GetBlock(0), ThreeColouredLights(), WarmMaterial(), Perspective(), interpolation);
    EXPECT_LE(MaxAbsDifference(composite.Render(), single.Render()), 1)
      << "interpolation " << interpolation;
    // The same terms and lights; the composite one knows blocks may bring their colours.
    std::string configuration = composite.Mapper->GetShaderConfiguration();
    const std::string blockColours = " block-colours";
    ASSERT_NE(configuration.find(blockColours), std::string::npos) << configuration;
    configuration.erase(configuration.find(blockColours), blockColours.size());
    EXPECT_EQ(configuration, single.Mapper->GetShaderConfiguration());
  }
}

// Specialisation and rebuilds, summed over the helpers: a diffuse-only scene has no specular
// code; redrawing does not rebuild; switching the specular term on does; a general shader draws
// the same image.
TEST_F(PhongMapper, CompositeShadersHoldOnlyWhatTheSceneUses)
{
  MaterialSpec matte = WarmMaterial();
  matte.Specular = 0;
  CompositeScene phong(TwoSpheres(48, 24), ThreeColouredLights(), matte, Perspective(), VTK_PHONG);
  const Image specialised = phong.Render();
  EXPECT_EQ(phong.Mapper->GetFragmentShaderSource().find("phongSpecular("), std::string::npos);
  EXPECT_NE(phong.Mapper->GetFragmentShaderSource().find("phongDiffuse("), std::string::npos);
  const int rebuilds = phong.Mapper->GetShaderRebuilds();
  EXPECT_GE(rebuilds, 1);
  phong.Render();
  phong.Render();
  EXPECT_EQ(phong.Mapper->GetShaderRebuilds(), rebuilds) << "redrawing rebuilt the shaders";

  phong.Actor->GetProperty()->SetSpecular(0.5);
  phong.Render();
  EXPECT_GT(phong.Mapper->GetShaderRebuilds(), rebuilds);
  EXPECT_NE(phong.Mapper->GetFragmentShaderSource().find("phongSpecular("), std::string::npos);

  phong.Actor->GetProperty()->SetSpecular(0);
  phong.Mapper->SpecializeShadersOff();
  const Image general = phong.Render();
  EXPECT_NE(phong.Mapper->GetFragmentShaderSource().find("phongSpecular("), std::string::npos);
  EXPECT_LE(MaxAbsDifference(specialised, general), 1);
}

// Hardware selection still identifies the block under a pixel.
TEST_F(PhongMapper, CompositeBlocksCanBePicked)
{
  auto blocks = TwoSpheres(32, 16);
  CompositeScene phong(blocks, OneWhiteLight(), WarmMaterial(), Perspective(), VTK_PHONG);
  phong.Render();
  for (int b = 0; b < 2; ++b)
  {
    // The centre of sphere b on the screen (camera on +z at distance 4, view angle 30).
    const double halfHeight = 4 * std::tan(vtkMath::RadiansFromDegrees(15.0));
    const double x = (b == 0 ? LeftCentre : RightCentre)[0];
    const unsigned int px = static_cast<unsigned int>((x / halfHeight + 1) * Size / 2);
    vtkNew<vtkHardwareSelector> selector;
    selector->SetRenderer(phong.Renderer);
    selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
    selector->SetArea(px, Size / 2, px, Size / 2);
    vtkSmartPointer<vtkSelection> selection;
    selection.TakeReference(selector->Select());
    ASSERT_EQ(selection->GetNumberOfNodes(), 1u) << "block " << b;
    vtkInformation* properties = selection->GetNode(0)->GetProperties();
    ASSERT_TRUE(properties->Has(vtkSelectionNode::COMPOSITE_INDEX()));
    // Flat indices: 0 is the multiblock, 1 and 2 its leaves.
    EXPECT_EQ(properties->Get(vtkSelectionNode::COMPOSITE_INDEX()), b + 1);
  }
  // The Phong shaders draw again after the selection passes.
  EXPECT_NE(phong.Mapper->GetShaderConfiguration().find("phong"), std::string::npos);
}

}
