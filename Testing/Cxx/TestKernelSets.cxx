// The two kernel sets (PhongVTKKernels.h): the baseline build and the AVX + FMA build give the
// same bits for every output of both filters, in every accuracy mode, on ordinary meshes and on
// polygons at the extremes of the double range (scaled paths, certified and exact EXACT
// decisions, non-finite and degenerate polygons). Each filter runs once with each set forced
// (PHONGVTK_KERNELS), and the test checks that the set asked for is the one selected.
//
// CTest runs this test twice: as it is, and with glibc's FMA and AVX2 switched off
// (GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA), where the baseline set's fma() is glibc's
// software emulation while the AVX + FMA set uses the instruction: both must still agree (and
// GlibcTunable.TookEffect checks that glibc did switch its FMA off).
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
#if defined(__x86_64__) && __has_include(<sys/platform/x86.h>)
#include <sys/platform/x86.h> // glibc 2.33+: CPU_FEATURE_ACTIVE
#define PHONGVTK_TEST_GLIBC_CPU_FEATURES 1
#endif
#include <random>
#include <string>

namespace
{
using phongvtk_test::Cell;
using phongvtk_test::Cells;
using phongvtk_test::Point;

bool ProcessorHasAvxFma()
{
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

/// Runs `produce` with the kernel set `set` forced ("" for the default choice).
template <typename Produce>
auto With(const char* set, const Produce& produce)
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

/// One filter run: its output and the errors it reported.
struct FilterRun
{
  vtkSmartPointer<vtkPolyData> Output;
  std::vector<std::string> Errors;
};

/// `produce` with each set forced: the same bits, and the set asked for is the one selected.
/// Each run must report no error, keep every cell of `input` and hold the cell arrays
/// `cellArrays` and the point arrays `pointArrays` (a run that failed as a whole would
/// otherwise agree with the other on nothing).
void ExpectSetsAgree(const std::function<FilterRun()>& produce, vtkPolyData* input,
  const std::vector<std::string>& cellArrays, const std::vector<std::string>& pointArrays,
  const std::string& what)
{
  std::string selected;
  const FilterRun runs[2] = { With("baseline",
                                [&]
                                {
                                  selected = phongvtk::SelectedKernels();
                                  return produce();
                                }),
    With("",
      [&]
      {
        EXPECT_EQ(selected, "baseline") << what;
        selected = phongvtk::SelectedKernels();
        return produce();
      }) };
  EXPECT_EQ(selected, "avx_fma") << what;
  for (const FilterRun& run : runs)
  {
    EXPECT_TRUE(run.Errors.empty()) << what << ": " << run.Errors.front();
    ASSERT_EQ(run.Output->GetNumberOfCells(), input->GetNumberOfCells()) << what;
    for (const std::string& name : cellArrays)
    {
      ASSERT_NE(run.Output->GetCellData()->GetArray(name.c_str()), nullptr)
        << what << ": cell array " << name;
    }
    for (const std::string& name : pointArrays)
    {
      ASSERT_NE(run.Output->GetPointData()->GetArray(name.c_str()), nullptr)
        << what << ": point array " << name;
    }
  }
  ExpectSameBits(runs[0].Output, runs[1].Output, what);
}

/// vtkPolygonNormals on `input` with `configure`.
FilterRun RunNormals(vtkPolyData* input, const std::function<void(vtkPolygonNormals*)>& configure)
{
  vtkNew<phongvtk_test::MessageObserver> messages;
  FilterRun run;
  run.Output = phongvtk_test::RunFilter(input, configure, messages);
  run.Errors = messages->Errors;
  return run;
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
    if (!phongvtk::AvxFmaKernelsBuilt())
    {
      PHONGVTK_SKIP() << "this build has no AVX + FMA set (PHONGVTK_AVX_FMA_KERNELS off, or not "
                         "x86-64 with GCC or Clang)";
    }
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
                return RunNormals(mesh,
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
              mesh, { "Normals", "AreaVectors", "Areas", "NormalStatus" }, { "Normals" },
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
            return RunNormals(mesh,
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
          mesh, { "Normals" }, { "Normals", "OriginalPointIds" },
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
              FilterRun run;
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
              run.Output = vtkSmartPointer<vtkPolyData>::New();
              run.Output->ShallowCopy(filter->GetOutput());
              run.Errors = messages->Errors;
              return run;
            },
            mesh, { "VisibleArea" }, {},
            "visible area accuracy " + std::to_string(accuracy) + (eye ? " eye" : ""));
        }
      }
    }
  }
}

TEST(KernelChoice, DefaultFollowsTheBuildAndTheProcessor)
{
  unsetenv("PHONGVTK_KERNELS");
  EXPECT_STREQ(phongvtk::SelectedKernels(),
    phongvtk::AvxFmaKernelsBuilt() && ProcessorHasAvxFma() ? "avx_fma" : "baseline");
}

TEST(KernelChoice, AnUnknownValueIsIgnored)
{
  const std::string expected =
    phongvtk::AvxFmaKernelsBuilt() && ProcessorHasAvxFma() ? "avx_fma" : "baseline";
  setenv("PHONGVTK_KERNELS", "Baseline ", 1); // not the exact name: warned about, not taken
  EXPECT_EQ(phongvtk::SelectedKernels(), expected);
  unsetenv("PHONGVTK_KERNELS");
}

// Under ctest's TestKernelSets.GlibcWithoutFma, glibc must really have switched its FMA off
// (otherwise that run compares the same two paths as the plain one); in the plain run glibc uses
// FMA exactly where the processor has it.
TEST(GlibcTunable, MatchesTheEnvironment)
{
#if defined(PHONGVTK_TEST_GLIBC_CPU_FEATURES)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "-FMA"))
  {
    EXPECT_FALSE(CPU_FEATURE_ACTIVE(FMA))
      << "GLIBC_TUNABLES=" << tunables << " left glibc's FMA on";
    EXPECT_FALSE(CPU_FEATURE_ACTIVE(AVX2))
      << "GLIBC_TUNABLES=" << tunables << " left glibc's AVX2 on";
  }
  else
  {
    __builtin_cpu_init();
    EXPECT_EQ(
      static_cast<bool>(CPU_FEATURE_ACTIVE(FMA)), static_cast<bool>(__builtin_cpu_supports("fma")));
  }
#else
  PHONGVTK_SKIP() << "no <sys/platform/x86.h> to ask glibc";
#endif
}
} // namespace
