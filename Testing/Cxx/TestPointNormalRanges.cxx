/**
 * The point pass of vtkPolygonNormals (Filters/PhongVTKPointNormals.h) gives the same bits
 * whatever the split of the points into ranges: on a machine with few cores the ranges the
 * filter picks barely move with the thread count, so this test forces them, from one point a
 * range (every boundary between two ranges) to one range for the whole mesh, on a coherent and
 * on a shuffled (incoherent) mesh, in every accuracy mode and weighting, cell-order and
 * piece-invariant sums, with every SMP backend this VTK has (Sequential, STDThread, and OpenMP
 * and TBB where built), and on a mesh large enough that threads share the ranges.
 */
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKPointNormals.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace
{
using phongvtk::Accuracy;

// A jittered sphere, and the same surface with its cells and points shuffled.
vtkSmartPointer<vtkPolyData> Sphere(int resolution, bool shuffled)
{
  auto mesh = phongvtk_test::JitteredSphere(resolution, 1e-3, 29);
  std::mt19937_64 random(31);
  if (!shuffled)
  {
    return mesh;
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> newId(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    newId[static_cast<size_t>(i)] = i;
  }
  std::shuffle(newId.begin(), newId.end(), random);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(newId[static_cast<size_t>(i)], mesh->GetPoint(i));
  }
  std::vector<std::vector<vtkIdType>> cells;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    std::vector<vtkIdType> cell;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      cell.push_back(newId[static_cast<size_t>(ids->GetId(k))]);
    }
    cells.push_back(cell);
  }
  std::shuffle(cells.begin(), cells.end(), random);
  vtkNew<vtkCellArray> polys;
  for (const auto& cell : cells)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

std::vector<double> PointNormals(
  vtkPolyData* mesh, Accuracy mode, int weighting, bool invariant, vtkIdType rangeSize)
{
  vtkNew<vtkPolygonNormals> filter; // progress and abort only
  auto* points = vtkDoubleArray::SafeDownCast(mesh->GetPoints()->GetData());
  phongvtk::PointNormalPass<double, double> pass{ filter, mesh->GetPolys(), mesh->GetStrips(),
    points->GetPointer(0), mesh->GetNumberOfPoints(), weighting, invariant };
  pass.ForcedRangeSize = rangeSize;
  std::vector<double> normals(static_cast<size_t>(3 * mesh->GetNumberOfPoints()), -7.0);
  switch (mode)
  {
    case Accuracy::Fast:
      pass.Run<Accuracy::Fast>(normals.data());
      break;
    case Accuracy::Double:
      pass.Run<Accuracy::Double>(normals.data());
      break;
    case Accuracy::Compensated:
      pass.Run<Accuracy::Compensated>(normals.data());
      break;
    case Accuracy::Exact:
      pass.Run<Accuracy::Exact>(normals.data());
      break;
  }
  return normals;
}

// Every forced range size gives the bits of one range for the whole mesh (run sequentially), for
// every backend this VTK has.
void ExpectSameBits(vtkPolyData* mesh, const std::string& name, const std::vector<vtkIdType>& sizes,
  const std::vector<Accuracy>& modes, const std::vector<int>& weightings, int& backendsRun)
{
  const std::string original = vtkSMPTools::GetBackend();
  const char* backends[] = { "Sequential", "STDThread", "OpenMP", "TBB" };
  for (Accuracy mode : modes)
  {
    for (int weighting : weightings)
    {
      for (bool invariant : { false, true })
      {
        vtkSMPTools::SetBackend("Sequential");
        const std::vector<double> reference =
          PointNormals(mesh, mode, weighting, invariant, mesh->GetNumberOfPoints());
        ASSERT_EQ(std::count(reference.begin(), reference.end(), -7.0), 0);
        backendsRun = 0;
        for (const char* backend : backends)
        {
          if (!vtkSMPTools::SetBackend(backend))
          {
            continue; // not built into this VTK
          }
          ++backendsRun;
          for (vtkIdType size : sizes)
          {
            const std::vector<double> normals =
              PointNormals(mesh, mode, weighting, invariant, size);
            EXPECT_EQ(
              std::memcmp(normals.data(), reference.data(), reference.size() * sizeof(double)), 0)
              << name << ", mode " << int(mode) << ", weighting " << weighting
              << (invariant ? ", invariant" : ", cell order") << ", " << backend << ", " << size
              << " points a range";
          }
        }
      }
    }
  }
  vtkSMPTools::SetBackend(original.c_str());
}

// A small mesh: every range boundary (one point a range) up to one range, every mode and
// weighting (the passes run on one thread: the mesh is below the threading threshold).
TEST(PointNormalRanges, EveryRangeSizeGivesTheSameBits)
{
  int backends = 0;
  for (bool shuffled : { false, true })
  {
    auto mesh = Sphere(30, shuffled);
    const vtkIdType n = mesh->GetNumberOfPoints();
    ExpectSameBits(mesh, shuffled ? "shuffled" : "coherent", { 1, 7, 61, 256, n - 1, n, 0 },
      { Accuracy::Fast, Accuracy::Double, Accuracy::Compensated, Accuracy::Exact },
      { vtkPolygonNormals::AREA, vtkPolygonNormals::ANGLE, vtkPolygonNormals::UNIFORM,
        vtkPolygonNormals::MAX },
      backends);
  }
  EXPECT_GE(backends, 2); // Sequential and STDThread at least
}

// A mesh large enough for the passes to run on several threads: ranges of several sizes, shared
// among the threads.
TEST(PointNormalRanges, ThreadsSharingForcedRangesGiveTheSameBits)
{
  auto mesh = Sphere(260, true);
  ASSERT_GE(mesh->GetNumberOfPolys(), phongvtk::SerialWork);
  const vtkIdType n = mesh->GetNumberOfPoints();
  int backends = 0;
  ExpectSameBits(mesh, "shuffled, large", { 997, 4099, 16384, n / 2 + 1, 0 },
    { Accuracy::Double, Accuracy::Exact }, { vtkPolygonNormals::AREA, vtkPolygonNormals::ANGLE },
    backends);
  EXPECT_GE(backends, 2);
}
}
