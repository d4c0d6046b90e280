// vtkPolygonNormals in place of vtkPolyDataNormals: the same options with the same defaults, and
// a pipeline with only the class name swapped gives VTK's points and cells. The truth is
// vtkPolyDataNormals itself, run on the same meshes.
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKOFFReader.h"
#include "PhongVTKSkip.h"
#include "vtkPolygonNormals.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
TEST(DropIn, EveryOptionOfVTKsFilterHasItsNameAndDefault)
{
  vtkNew<vtkPolyDataNormals> vtk;
  vtkNew<vtkPolygonNormals> ours;
  EXPECT_EQ(ours->GetFeatureAngle(), vtk->GetFeatureAngle());
  EXPECT_EQ(ours->GetSplitting(), vtk->GetSplitting() != 0);
  EXPECT_EQ(ours->GetConsistency(), vtk->GetConsistency() != 0);
  EXPECT_EQ(ours->GetAutoOrientNormals(), vtk->GetAutoOrientNormals() != 0);
  EXPECT_EQ(ours->GetComputePointNormals(), vtk->GetComputePointNormals() != 0);
  EXPECT_EQ(ours->GetComputeCellNormals(), vtk->GetComputeCellNormals() != 0);
  EXPECT_EQ(ours->GetFlipNormals(), vtk->GetFlipNormals() != 0);
  EXPECT_EQ(ours->GetNonManifoldTraversal(), vtk->GetNonManifoldTraversal() != 0);
  EXPECT_EQ(ours->GetOutputPointsPrecision(), vtk->GetOutputPointsPrecision());
  EXPECT_TRUE(ours->GetTriangulateStrips()); // what vtkPolyDataNormals always does
}

/// Each output point as (x, y, z, nx, ny, nz), sorted: the split copies of a point share its
/// coordinates, and the two filters may number them differently.
std::vector<std::array<double, 6>> PointsWithNormals(vtkPolyData* mesh)
{
  std::vector<std::array<double, 6>> rows(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    auto& row = rows[static_cast<std::size_t>(i)];
    mesh->GetPoint(i, row.data());
    normals->GetTuple(i, row.data() + 3);
  }
  // Normals rounded for the order only: copies at one place differ by far more than 1e-3.
  auto key = [](const std::array<double, 6>& r)
  {
    return std::array<double, 6>{ r[0], r[1], r[2], std::round(r[3] * 1e3), std::round(r[4] * 1e3),
      std::round(r[5] * 1e3) };
  };
  std::sort(rows.begin(), rows.end(),
    [&](const std::array<double, 6>& a, const std::array<double, 6>& b)
    { return key(a) < key(b); });
  return rows;
}

class SwappedClass : public ::testing::TestWithParam<std::string>
{
};

TEST_P(SwappedClass, GivesVTKsPointsCellsAndNormals)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh =
    phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(GetParam()), &error);
  ASSERT_NE(mesh, nullptr) << error;

  vtkNew<vtkPolyDataNormals> vtk;
  vtk->SetInputData(mesh);
  vtk->Update();
  vtkNew<vtkPolygonNormals> ours;
  ours->SetInputData(mesh);
  ours->SetPointWeightingToUniform(); // VTK's weighting, so that the normals compare too
  ASSERT_TRUE(ours->GetExecutive()->Update());

  vtkPolyData* expected = vtk->GetOutput();
  vtkPolyData* got = ours->GetOutput();
  EXPECT_EQ(got->GetNumberOfPoints(), expected->GetNumberOfPoints());
  EXPECT_EQ(got->GetNumberOfCells(), expected->GetNumberOfCells());
  ASSERT_NE(got->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(got->GetCellData()->GetNormals(), nullptr); // ComputeCellNormals off, as VTK's
  if (got->GetNumberOfPoints() != expected->GetNumberOfPoints())
  {
    return;
  }
  const auto a = PointsWithNormals(expected);
  const auto b = PointsWithNormals(got);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(a[i][c], b[i][c]) << "point " << i;
      worst = std::max(worst, std::abs(a[i][c + 3] - b[i][c + 3]));
    }
  }
  // Both float normals of the same sums; VTK adds the float cell normals in its own order.
  EXPECT_LT(worst, 1e-5) << GetParam();
}

// fandisk: 6,475 points and no point normals before the defaults were VTK's, 7,207 in VTK;
// cube_poly: 8 and 24.
INSTANTIATE_TEST_SUITE_P(CGAL, SwappedClass,
  ::testing::Values("fandisk.off", "cube_poly.off", "bunny00.off", "elephant.off", "cross.off"),
  [](const ::testing::TestParamInfo<std::string>& info)
  { return info.param.substr(0, info.param.find('.')); });

// VTK's own test of strips (Filters/Core/Testing/Python/testPDNormals.py) with the class
// swapped: a sphere's 96 polygons with cell value 2, then a plane's strip with value 1; the
// strip's triangles come after the polygons, each with its strip's value.
TEST(DropIn, StripsAreBrokenIntoTrianglesWithTheirCellData)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetYResolution(10);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkStripper> stripper;
  stripper->SetInputConnection(triangles->GetOutputPort());
  stripper->Update();
  vtkPolyData* strips = stripper->GetOutput();
  vtkNew<vtkFloatArray> one;
  one->InsertNextTuple1(1);
  one->SetName("foo");
  strips->GetCellData()->AddArray(one);
  vtkNew<vtkSphereSource> source;
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  vtkNew<vtkFloatArray> two;
  two->SetNumberOfTuples(96);
  two->FillComponent(0, 2);
  two->SetName("foo");
  sphere->GetCellData()->AddArray(two);
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(strips);
  append->AddInputData(sphere);

  vtkNew<vtkPolygonNormals> normals;
  normals->SetInputConnection(append->GetOutputPort());
  normals->ComputeCellNormalsOn();
  ASSERT_TRUE(normals->GetExecutive()->Update());
  vtkPolyData* output = normals->GetOutput();
  ASSERT_EQ(output->GetNumberOfCells(), 116);
  EXPECT_EQ(output->GetNumberOfStrips(), 0);
  vtkDataArray* foo = output->GetCellData()->GetArray("foo");
  ASSERT_NE(foo, nullptr);
  for (vtkIdType i = 0; i < 96; ++i)
  {
    EXPECT_EQ(foo->GetComponent(i, 0), 2.0) << i;
  }
  vtkDataArray* cellNormals = output->GetCellData()->GetNormals();
  for (vtkIdType i = 96; i < 116; ++i)
  {
    EXPECT_EQ(foo->GetComponent(i, 0), 1.0) << i;
    // Every triangle of the strip faces the plane's way, +z.
    EXPECT_EQ(cellNormals->GetComponent(i, 2), 1.0) << i;
  }

  // Off: the strip stays one cell, as before.
  normals->TriangulateStripsOff();
  ASSERT_TRUE(normals->GetExecutive()->Update());
  EXPECT_EQ(normals->GetOutput()->GetNumberOfStrips(), 1);
  EXPECT_EQ(normals->GetOutput()->GetNumberOfCells(), 97);
}

TEST(DropIn, AStripWithABadPointIdNamesTheStrip)
{
  phongvtk_test::Cells cells;
  cells.Strips = { { 0, 1, 2, 3 }, { 0, 1, 9 } };
  vtkSmartPointer<vtkPolyData> mesh =
    phongvtk_test::MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } }, cells);
  vtkNew<vtkPolygonNormals> normals;
  vtkNew<phongvtk_test::MessageObserver> messages;
  messages->Watch(normals);
  normals->SetInputData(mesh);
  EXPECT_FALSE(normals->GetExecutive()->Update());
  ASSERT_EQ(messages->Errors.size(), 1u);
  EXPECT_NE(messages->Errors[0].find("Cell 1 refers to a point id"), std::string::npos)
    << messages->Errors[0];
  EXPECT_EQ(normals->GetOutput()->GetNumberOfCells(), 0);
}

TEST(DropIn, OutputPointsPrecisionAppliesToSplitPoints)
{
  vtkNew<vtkSphereSource> source; // float points; a sphere of 8 x 6 facets splits at 30 degrees
  source->SetThetaResolution(8);
  source->SetPhiResolution(6);
  for (int precision : { vtkAlgorithm::DEFAULT_PRECISION, vtkAlgorithm::SINGLE_PRECISION,
         vtkAlgorithm::DOUBLE_PRECISION })
  {
    vtkNew<vtkPolygonNormals> ours;
    ours->SetInputConnection(source->GetOutputPort());
    ours->SetOutputPointsPrecision(precision);
    vtkNew<vtkPolyDataNormals> vtk;
    vtk->SetInputConnection(source->GetOutputPort());
    vtk->SetOutputPointsPrecision(precision);
    ours->Update();
    vtk->Update();
    EXPECT_EQ(
      ours->GetOutput()->GetPoints()->GetDataType(), vtk->GetOutput()->GetPoints()->GetDataType())
      << precision;
    EXPECT_EQ(ours->GetOutput()->GetNumberOfPoints(), vtk->GetOutput()->GetNumberOfPoints());
  }
  vtkNew<vtkPolygonNormals> ours;
  vtkNew<phongvtk_test::MessageObserver> messages;
  messages->Watch(ours);
  ours->SetOutputPointsPrecision(7);
  EXPECT_EQ(ours->GetOutputPointsPrecision(), vtkAlgorithm::DEFAULT_PRECISION);
  EXPECT_EQ(messages->Errors.size(), 1u);
}
}
