// Cell arrays in every storage a VTK gives them: 64- and 32-bit arrays, and from VTK 9.6 on
// fixed-size cells (implicit offsets, what vtkFlyingEdges3D and vtkSurfaceNets3D make) and
// arrays of any type (generic storage). VTK 9.6's vtkCellArray::Visit skips those two with a
// warning; the filters must read them all and give the same bits as from plain 64-bit arrays,
// without changing the input's arrays, and pass them through where they compute nothing.
#include "PhongVTKCells.h"
#include "PhongVTKFilterTestSupport.h"
#include "vtkPolygonNormals.h"
#include "vtkVisibleArea.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedShortArray.h"
#include "vtkVersionMacros.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#define PHONGVTK_TEST_VTK_96                                                                       \
  (VTK_MAJOR_VERSION > 9 || (VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION >= 6))

namespace
{
using phongvtk_test::JitteredSphere;
using phongvtk_test::MessageObserver;
using phongvtk_test::RunFilter;

struct Stored
{
  std::string Name;
  vtkSmartPointer<vtkCellArray> Cells;
};

template <class Array>
vtkSmartPointer<Array> CopyAs(vtkDataArray* values)
{
  auto copy = vtkSmartPointer<Array>::New();
  copy->DeepCopy(values);
  return copy;
}

/// The triangles `plain` (one cell array of triangles) in each storage VTK offers.
std::vector<Stored> Storages(vtkCellArray* plain)
{
  std::vector<Stored> stored;
  auto add = [&](const std::string& name) -> vtkCellArray*
  {
    stored.push_back({ name, vtkSmartPointer<vtkCellArray>::New() });
    return stored.back().Cells;
  };
  add("64-bit")->DeepCopy(plain);
  stored.back().Cells->ConvertTo64BitStorage();
  add("32-bit")->DeepCopy(plain);
  stored.back().Cells->ConvertTo32BitStorage();
  add("fixed size, 64-bit")->SetData(3, CopyAs<vtkTypeInt64Array>(plain->GetConnectivityArray()));
  add("fixed size, 32-bit")->SetData(3, CopyAs<vtkTypeInt32Array>(plain->GetConnectivityArray()));
#if PHONGVTK_TEST_VTK_96
  // Before 9.6 VTK refuses arrays of other types.
  add("unsigned short arrays")
    ->SetData(CopyAs<vtkUnsignedShortArray>(plain->GetOffsetsArray()),
      CopyAs<vtkUnsignedShortArray>(plain->GetConnectivityArray()));
#endif
  return stored;
}

std::vector<vtkIdType> IdsOf(vtkCellArray* cells)
{
  std::vector<vtkIdType> ids;
  vtkNew<vtkIdList> cell;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    cells->GetCellAtId(c, cell);
    ids.push_back(cell->GetNumberOfIds());
    for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
    {
      ids.push_back(cell->GetId(k));
    }
  }
  return ids;
}

/// The bytes of `array` (double or float values), to compare bit for bit.
std::vector<unsigned char> BytesOf(vtkDataArray* array)
{
  if (!array)
  {
    return {};
  }
  const auto* begin = static_cast<const unsigned char*>(array->GetVoidPointer(0));
  return std::vector<unsigned char>(
    begin, begin + array->GetNumberOfValues() * array->GetDataTypeSize());
}

vtkSmartPointer<vtkPolyData> WithPolys(vtkPolyData* mesh, vtkCellArray* polys)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(mesh);
  copy->SetPolys(polys);
  return copy;
}

TEST(CellStorage, VTK96HasStorageTheFiltersCannotReadInPlace)
{
  auto sphere = JitteredSphere(24, 1e-3);
  int notPlain = 0;
  for (const Stored& s : Storages(sphere->GetPolys()))
  {
    EXPECT_EQ(IdsOf(s.Cells), IdsOf(sphere->GetPolys())) << s.Name;
    EXPECT_EQ(IdsOf(phongvtk::PlainCells(s.Cells)), IdsOf(sphere->GetPolys())) << s.Name;
    EXPECT_TRUE(phongvtk::IsPlainStorage(phongvtk::PlainCells(s.Cells))) << s.Name;
    notPlain += phongvtk::IsPlainStorage(s.Cells) ? 0 : 1;
  }
#if PHONGVTK_TEST_VTK_96
  EXPECT_EQ(notPlain, 3); // the two fixed-size storages and the generic one
#else
  EXPECT_EQ(notPlain, 0); // VTK converts the arrays it is given to 32 or 64 bits
#endif
}

TEST(CellStorage, NormalsAndAreasAreTheSameBitsFromEveryStorage)
{
  auto sphere = JitteredSphere(24, 1e-3);
  const std::vector<Stored> stored = Storages(sphere->GetPolys());
  for (int accuracy : { vtkPolygonNormals::FAST, vtkPolygonNormals::EXACT })
  {
    for (bool reorder : { false, true })
    {
      auto configure = [&](vtkPolygonNormals* filter)
      {
        filter->SetAccuracy(accuracy);
        filter->SetComputePointNormals(true);
        filter->SetComputeAreaVectors(true);
        filter->SetSplitting(reorder);
        filter->SetConsistency(reorder);
        filter->SetFeatureAngle(20.0);
      };
      vtkSmartPointer<vtkPolyData> referenceOutput;
      double referenceArea = 0.0;
      for (const Stored& s : stored)
      {
        SCOPED_TRACE(s.Name + (reorder ? ", split and oriented" : "") + ", accuracy " +
          std::to_string(accuracy));
        auto input = WithPolys(sphere, s.Cells);
        vtkDataArray* offsets = s.Cells->GetOffsetsArray();
        vtkDataArray* connectivity = s.Cells->GetConnectivityArray();
        const std::vector<vtkIdType> before = IdsOf(s.Cells);
        const bool plainBefore = phongvtk::IsPlainStorage(s.Cells);

        vtkNew<MessageObserver> messages;
        auto output = RunFilter(input, configure, messages);
        EXPECT_TRUE(messages->Errors.empty() && messages->Warnings.empty());
        ASSERT_EQ(output->GetNumberOfPolys(), sphere->GetNumberOfPolys());
        vtkNew<vtkVisibleArea> area;
        area->SetInputData(input);
        area->SetViewDirection(0.3, -0.5, 0.8);
        area->SetAccuracy(accuracy);
        messages->Watch(area);
        area->Update();
        EXPECT_TRUE(messages->Errors.empty() && messages->Warnings.empty());

        // The input as it was.
        EXPECT_EQ(s.Cells->GetOffsetsArray(), offsets);
        EXPECT_EQ(s.Cells->GetConnectivityArray(), connectivity);
        EXPECT_EQ(phongvtk::IsPlainStorage(s.Cells), plainBefore);
        EXPECT_EQ(IdsOf(s.Cells), before);
        if (!reorder)
        {
          // Nothing computed about the cells: the given arrays pass through.
          EXPECT_EQ(output->GetPolys()->GetConnectivityArray(), connectivity);
        }

        const double total = area->GetTotalVisibleArea();
        if (!referenceOutput)
        {
          referenceOutput = output;
          referenceArea = total;
          EXPECT_GT(referenceArea, 0.0);
          continue;
        }
        EXPECT_EQ(IdsOf(output->GetPolys()), IdsOf(referenceOutput->GetPolys()));
        for (const char* name : { "Normals", "AreaVectors" })
        {
          EXPECT_EQ(BytesOf(output->GetCellData()->GetArray(name)),
            BytesOf(referenceOutput->GetCellData()->GetArray(name)))
            << name;
          EXPECT_FALSE(BytesOf(output->GetCellData()->GetArray(name)).empty()) << name;
        }
        EXPECT_EQ(BytesOf(output->GetPointData()->GetNormals()),
          BytesOf(referenceOutput->GetPointData()->GetNormals()));
        EXPECT_EQ(output->GetNumberOfPoints(), referenceOutput->GetNumberOfPoints());
        EXPECT_EQ(std::memcmp(&referenceArea, &total, sizeof(double)), 0);
      }
    }
  }
}
} // namespace
