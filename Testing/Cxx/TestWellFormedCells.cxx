// Cell arrays whose offsets do not describe their cells (what VTK's legacy reader builds from a
// corrupt binary file): FirstMalformedCell finds the first such cell, and both filters refuse
// the input with an error naming it instead of reading outside the connectivity.
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKWellFormedCells.h"
#include "vtkPolygonNormals.h"
#include "vtkVisibleArea.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <functional>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace
{
using phongvtk::FirstMalformedCell;
using phongvtk_test::Cells;
using phongvtk_test::MakePolyData;
using phongvtk_test::MessageObserver;
using phongvtk_test::RunFilter;

vtkIdType FirstOf(const std::vector<vtkIdType>& offsets, std::int64_t size)
{
  return FirstMalformedCell(offsets.data(), static_cast<vtkIdType>(offsets.size()) - 1, size);
}

TEST(WellFormedCells, OffsetsThatDescribeTheCellsPass)
{
  EXPECT_EQ(FirstOf({ 0, 3, 6, 10 }, 10), -1);
  EXPECT_EQ(FirstOf({ 0, 0, 3, 3 }, 3), -1); // empty cells are cells
  EXPECT_EQ(FirstOf({ 0 }, 0), -1);          // no cells
  EXPECT_EQ(FirstOf({ 7 }, 0), -1);          // no cells: nothing is read
}

TEST(WellFormedCells, TheFirstCellWithoutAnExtentIsNamed)
{
  EXPECT_EQ(FirstOf({ 1, 3, 6 }, 6), 0);          // starts late
  EXPECT_EQ(FirstOf({ -3, 3, 6 }, 6), 0);         // starts before the connectivity
  EXPECT_EQ(FirstOf({ 0, 3, 2, 6 }, 6), 1);       // cell 1 ends before it starts
  EXPECT_EQ(FirstOf({ 0, 3, 2, 1, 6 }, 6), 1);    // the first of two
  EXPECT_EQ(FirstOf({ 0, 3, 6, 9 }, 8), 2);       // the last runs past the connectivity
  EXPECT_EQ(FirstOf({ 0, 10, 10, 10 }, 5), 0);    // the first already does
  EXPECT_EQ(FirstOf({ 0, 3, 6, 7 }, 9), 2);       // or stops short of its end
  EXPECT_EQ(FirstOf({ 0, 3, 1 << 30, 9 }, 9), 2); // a huge offset, then back
}

TEST(WellFormedCells, SameAnswerForEveryBackendAndThreadCount)
{
  // 3M triangles: far above the size where passes run on threads. Defects at cells 2,000,001
  // and 2,900,000 (different ranges on any thread count): the first is always the answer.
  const vtkIdType n = 3000000;
  std::vector<vtkIdType> offsets(n + 1);
  std::iota(offsets.begin(), offsets.end(), 0);
  for (auto& o : offsets)
  {
    o *= 3;
  }
  const std::int64_t size = 3 * n;
  offsets[2000002] = offsets[2000001] - 1;
  offsets[2900001] = 5;
  const std::string original = vtkSMPTools::GetBackend();
  for (const auto& config : std::vector<std::pair<const char*, int>>{
         { "Sequential", 1 }, { "STDThread", 1 }, { "STDThread", 2 }, { "STDThread", 5 } })
  {
    ASSERT_TRUE(vtkSMPTools::SetBackend(config.first));
    vtkSMPTools::Initialize(config.second);
    EXPECT_EQ(FirstMalformedCell(offsets.data(), n, size), 2000001)
      << config.first << " x" << config.second;
    std::vector<vtkIdType> late = offsets;
    late[2000002] = 3 * 2000002;
    EXPECT_EQ(FirstMalformedCell(late.data(), n, size), 2900000);
  }
  vtkSMPTools::SetBackend(original.c_str());
}

/// A vertex cell, then two triangles and a strip on four points; `corrupt` replaces the offsets
/// of the polygons (or of the strips) with `offsets`.
vtkSmartPointer<vtkPolyData> MeshWithOffsets(const std::vector<vtkIdType>& offsets, bool strips)
{
  Cells cells;
  cells.Verts = { { 3 } };
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 } };
  cells.Strips = { { 0, 1, 3, 2 } };
  auto mesh = MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, cells);
  vtkCellArray* target = strips ? mesh->GetStrips() : mesh->GetPolys();
  vtkNew<vtkIdTypeArray> newOffsets;
  for (vtkIdType o : offsets)
  {
    newOffsets->InsertNextValue(o);
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->DeepCopy(target->GetConnectivityArray());
  target->SetData(newOffsets, connectivity);
  return mesh;
}

TEST(WellFormedCells, BothFiltersRefuseTheInputNamingTheCell)
{
  // Cell ids count the vertex cell first: polygon 1 is cell 2, the strip cell 3.
  const std::vector<std::pair<vtkSmartPointer<vtkPolyData>, std::string>> inputs = {
    { MeshWithOffsets({ 0, 3, 2 }, false), "Cell 2 " },   // the polygon runs backwards
    { MeshWithOffsets({ 0, 3, 9 }, false), "Cell 2 " },   // past the connectivity
    { MeshWithOffsets({ 4, 3, 6 }, false), "Cell 1 " },   // polygon 0 starts late
    { MeshWithOffsets({ 0, 1 << 20 }, true), "Cell 3 " }, // the strip runs far past
  };
  const std::vector<std::function<void(vtkPolygonNormals*)>> options = {
    [](vtkPolygonNormals*) {},
    [](vtkPolygonNormals* f) { f->ComputePointNormalsOn(); },
    [](vtkPolygonNormals* f)
    {
      f->ComputePointNormalsOn();
      f->SplittingOn();
    },
    [](vtkPolygonNormals* f) { f->ConsistencyOn(); },
    [](vtkPolygonNormals* f)
    {
      f->AutoOrientNormalsOn();
      f->SetAccuracy(vtkPolygonNormals::EXACT);
    },
  };
  for (const auto& input : inputs)
  {
    for (std::size_t k = 0; k < options.size(); ++k)
    {
      vtkNew<MessageObserver> messages;
      auto out = RunFilter(input.first, options[k], messages);
      ASSERT_EQ(messages->Errors.size(), 1u) << input.second << k;
      EXPECT_NE(messages->Errors[0].find(input.second + "has no extent"), std::string::npos)
        << messages->Errors[0];
      EXPECT_EQ(out->GetNumberOfCells(), 0);
      EXPECT_EQ(out->GetNumberOfPoints(), 0);
    }
    vtkNew<vtkVisibleArea> area;
    vtkNew<MessageObserver> messages;
    messages->Watch(area);
    area->SetInputData(input.first);
    area->Update();
    ASSERT_EQ(messages->Errors.size(), 1u) << input.second;
    EXPECT_NE(messages->Errors[0].find(input.second + "has no extent"), std::string::npos)
      << messages->Errors[0];
    EXPECT_EQ(area->GetOutput()->GetNumberOfCells(), 0);
  }
}

TEST(WellFormedCells, AWellFormedInputIsNotTouched)
{
  vtkNew<MessageObserver> messages;
  auto out = RunFilter(
    MeshWithOffsets({ 0, 3, 6 }, false), [](vtkPolygonNormals*) {}, messages);
  EXPECT_TRUE(messages->Errors.empty());
  EXPECT_EQ(out->GetNumberOfCells(), 4);
}
} // namespace
