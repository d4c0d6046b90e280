// The two kernel sets (PhongVTKKernels.h): the baseline build and the AVX + FMA build give the
// same bits for every output of both filters, in every accuracy mode, on ordinary meshes and on
// polygons at the extremes of the double range (scaled paths, certified and exact EXACT
// decisions, non-finite and degenerate polygons). Each filter runs once with each set forced
// (PHONGVTK_KERNELS), and the test checks that the set asked for is the one selected.
//
// CTest runs this test twice: as it is, and with glibc's FMA and AVX2 switched off
// (GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA), where the baseline set's fma() is glibc's
// software emulation while the AVX + FMA set uses the instruction: both must still agree.
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKKernels.h"
#include "PhongVTKSkip.h"

#include "vtkCamera.h"
#include "vtkFieldData.h"
#include "vtkVariant.h"
#include "vtkVisibleArea.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>

namespace
{
using phongvtk_test::Cell;
using phongvtk_test::Cells;
using phongvtk_test::Point;

bool ProcessorHasAvxFma()
{
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx") && __builtin_cpu_supports("fma");
}

/// Runs `produce` with the kernel set `set` forced ("" for the default choice).
vtkSmartPointer<vtkPolyData> With(
  const char* set, const std::function<vtkSmartPointer<vtkPolyData>()>& produce)
{
  if (*set)
  {
    setenv("PHONGVTK_KERNELS", set, 1);
  }
  else
  {
    unsetenv("PHONGVTK_KERNELS");
  }
  auto out = produce();
  unsetenv("PHONGVTK_KERNELS");
  return out;
}

/// Every array of `a` and `b` (point, cell and field data, points, polygons) bit for bit.
void ExpectSameBits(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << what;
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells()) << what;
  auto same = [&](vtkDataArray* x, vtkDataArray* y, const std::string& name)
  {
    ASSERT_TRUE(x && y) << what << ": " << name;
    ASSERT_EQ(x->GetDataType(), y->GetDataType()) << what << ": " << name;
    ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues()) << what << ": " << name;
    const auto size = static_cast<std::size_t>(x->GetDataTypeSize());
    const auto* xb = static_cast<const unsigned char*>(x->GetVoidPointer(0));
    const auto* yb = static_cast<const unsigned char*>(y->GetVoidPointer(0));
    for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
    {
      if (std::memcmp(xb + i * size, yb + i * size, size) != 0)
      {
        ADD_FAILURE() << what << ": array " << name << " differs first at value " << i << " ("
                      << std::hexfloat << x->GetVariantValue(i).ToDouble() << " baseline, "
                      << y->GetVariantValue(i).ToDouble() << " avx_fma)";
        return;
      }
    }
  };
  if (a->GetPoints())
  {
    same(a->GetPoints()->GetData(), b->GetPoints()->GetData(), "points");
  }
  if (a->GetNumberOfPolys() > 0)
  {
    same(a->GetPolys()->GetConnectivityArray(), b->GetPolys()->GetConnectivityArray(), "polygons");
  }
  vtkFieldData* fields[2][3] = { { a->GetPointData(), a->GetCellData(), a->GetFieldData() },
    { b->GetPointData(), b->GetCellData(), b->GetFieldData() } };
  for (int k = 0; k < 3; ++k)
  {
    ASSERT_EQ(fields[0][k]->GetNumberOfArrays(), fields[1][k]->GetNumberOfArrays()) << what;
    for (int i = 0; i < fields[0][k]->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* x = fields[0][k]->GetArray(i);
      if (x)
      {
        same(x, fields[1][k]->GetArray(x->GetName()), x->GetName());
      }
    }
  }
}

/// `produce` with each set forced: the same bits, and the set asked for is the one selected.
void ExpectSetsAgree(
  const std::function<vtkSmartPointer<vtkPolyData>()>& produce, const std::string& what)
{
  std::string selected;
  auto base = With("baseline",
    [&]
    {
      selected = phongvtk::SelectedKernels();
      return produce();
    });
  EXPECT_EQ(selected, "baseline");
  auto avx = With("",
    [&]
    {
      selected = phongvtk::SelectedKernels();
      return produce();
    });
  EXPECT_EQ(selected, "avx_fma");
  ExpectSameBits(base, avx, what);
}

/// A soup of triangles (in runs, for the 4-lane path), quads and heptagons, each polygon at its
/// own scale between 2^-700 and 2^700, some offset far from the origin (cancellation), some
/// nearly flat or with repeated points, a few with a non-finite coordinate, and triangle strips.
vtkSmartPointer<vtkPolyData> ExtremeSoup(int pointType)
{
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> binade(-700, 700);
  std::vector<Point> points;
  Cells cells;
  auto polygon = [&](int n, std::vector<Cell>& into)
  {
    const int kind = static_cast<int>(random() % 8);
    const double scale =
      std::ldexp(1.0, pointType == VTK_FLOAT ? binade(random) / 6 : binade(random));
    const double offset = kind == 1 ? scale * std::ldexp(1.0, 40) : 0.0;
    Cell cell;
    for (int i = 0; i < n; ++i)
    {
      Point p = { offset + scale * unit(random), offset + scale * unit(random),
        offset + scale * unit(random) };
      if (kind == 2 && i == n - 1)
      {
        // Nearly collinear with the first two: a tiny, cancelling area vector.
        for (int c = 0; c < 3; ++c)
        {
          p[c] = points[cell[0]][c] + 0.5 * (points[cell[1]][c] - points[cell[0]][c]);
          p[c] = std::nextafter(p[c], 2.0 * p[c] + 1.0);
        }
      }
      if (kind == 3 && i == n - 1)
      {
        p = points[cell[0]]; // a repeated point
      }
      if (kind == 4 && i == 1 && random() % 4 == 0)
      {
        p[random() % 3] = random() % 2 ? std::nan("") : HUGE_VAL;
      }
      cell.push_back(static_cast<vtkIdType>(points.size()));
      points.push_back(p);
    }
    into.push_back(cell);
  };
  for (int i = 0; i < 2000; ++i)
  {
    const int r = static_cast<int>(random() % 10);
    polygon(r < 7 ? 3 : (r < 9 ? 4 : 7), cells.Polys);
  }
  for (int i = 0; i < 50; ++i)
  {
    polygon(3 + static_cast<int>(random() % 6), cells.Strips);
  }
  return phongvtk_test::MakePolyData(points, cells, pointType);
}

class KernelSets : public ::testing::Test
{
protected:
  void SetUp() override
  {
    if (!ProcessorHasAvxFma())
    {
      PHONGVTK_SKIP() << "this processor has no AVX + FMA: only the baseline set runs here";
    }
  }
};

TEST_F(KernelSets, DefaultIsAvxFmaWhereTheProcessorHasIt)
{
  unsetenv("PHONGVTK_KERNELS");
  EXPECT_STREQ(phongvtk::SelectedKernels(), "avx_fma");
  setenv("PHONGVTK_KERNELS", "baseline", 1);
  EXPECT_STREQ(phongvtk::SelectedKernels(), "baseline");
  unsetenv("PHONGVTK_KERNELS");
}

TEST_F(KernelSets, PolygonNormalsAgreeInEveryModeAndWeighting)
{
  for (int pointType : { VTK_DOUBLE, VTK_FLOAT })
  {
    const vtkSmartPointer<vtkPolyData> meshes[] = { ExtremeSoup(pointType),
      phongvtk_test::Transformed(phongvtk_test::JitteredSphere(40, 1e-3), 1.0, 0.0, pointType) };
    for (vtkPolyData* mesh : meshes)
    {
      for (int accuracy = vtkPolygonNormals::FAST; accuracy <= vtkPolygonNormals::EXACT; ++accuracy)
      {
        for (int weighting = vtkPolygonNormals::AREA; weighting <= vtkPolygonNormals::MAX;
             ++weighting)
        {
          for (int precision :
            { vtkPolygonNormals::DEFAULT_PRECISION, vtkPolygonNormals::SINGLE_PRECISION })
          {
            ExpectSetsAgree(
              [&]
              {
                return phongvtk_test::RunFilter(mesh,
                  [&](vtkPolygonNormals* f)
                  {
                    f->SetAccuracy(accuracy);
                    f->SetPointWeighting(weighting);
                    f->SetOutputPrecision(precision);
                    f->SetComputePointNormals(true);
                    f->SetComputeAreaVectors(true);
                    f->SetComputeAreas(true);
                    f->SetComputeNormalStatus(true);
                  });
              },
              "points " + std::to_string(pointType) + " accuracy " + std::to_string(accuracy) +
                " weighting " + std::to_string(weighting) + " precision " +
                std::to_string(precision));
          }
        }
      }
    }
  }
}

TEST_F(KernelSets, SplittingAndOrientationAgree)
{
  auto rough = phongvtk_test::RoughSphere(48, 0.08);
  // Half the polygons reversed: Consistency and AutoOrientNormals have work to do.
  auto polys = phongvtk_test::PolygonsOf(rough);
  for (std::size_t f = 0; f < polys.size(); f += 2)
  {
    std::reverse(polys[f].begin(), polys[f].end());
  }
  Cells cells;
  cells.Polys = polys;
  for (int pointType : { VTK_DOUBLE, VTK_FLOAT })
  {
    auto mesh = phongvtk_test::MakePolyData(phongvtk_test::PointsOf(rough), cells, pointType);
    for (int accuracy = vtkPolygonNormals::FAST; accuracy <= vtkPolygonNormals::EXACT; ++accuracy)
    {
      for (bool autoOrient : { false, true })
      {
        ExpectSetsAgree(
          [&]
          {
            return phongvtk_test::RunFilter(mesh,
              [&](vtkPolygonNormals* f)
              {
                f->SetAccuracy(accuracy);
                f->SetComputePointNormals(true);
                f->SetComputeCellNormals(true);
                f->SetSplitting(true);
                f->SetConsistency(true);
                f->SetAutoOrientNormals(autoOrient);
                f->SetComputeOriginalPointIds(true);
              });
          },
          "split accuracy " + std::to_string(accuracy) + (autoOrient ? " auto-orient" : ""));
      }
    }
  }
}

TEST_F(KernelSets, VisibleAreaAgreesInEveryMode)
{
  for (int pointType : { VTK_DOUBLE, VTK_FLOAT })
  {
    const vtkSmartPointer<vtkPolyData> meshes[] = { ExtremeSoup(pointType),
      phongvtk_test::Transformed(phongvtk_test::RoughSphere(40, 0.05), 1.0, 0.0, pointType) };
    for (vtkPolyData* mesh : meshes)
    {
      for (int accuracy = vtkVisibleArea::FAST; accuracy <= vtkVisibleArea::EXACT; ++accuracy)
      {
        for (bool eye : { false, true })
        {
          ExpectSetsAgree(
            [&]
            {
              vtkNew<vtkVisibleArea> filter;
              vtkNew<phongvtk_test::MessageObserver> messages; // the non-finite polygons' warning
              messages->Watch(filter);
              vtkNew<vtkCamera> camera;
              camera->SetPosition(3.0, -2.0, 5.0);
              if (eye)
              {
                filter->SetCamera(camera);
              }
              filter->SetViewDirection(1.0, 2.0, 2.0);
              filter->SetAccuracy(accuracy);
              filter->SetComputeMaxVisibleArea(true);
              filter->SetInputData(mesh);
              filter->Update();
              auto out = vtkSmartPointer<vtkPolyData>::New();
              out->ShallowCopy(filter->GetOutput());
              return out;
            },
            "visible area accuracy " + std::to_string(accuracy) + (eye ? " eye" : ""));
        }
      }
    }
  }
}
} // namespace
