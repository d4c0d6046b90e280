// Specification of vtkVisibleArea. Expected values come from exact rational arithmetic written
// here from the definition (the visible area of a polygon is v.w / 2 with w its exact area
// vector and v the unit vector toward the viewer), from exact 2-D convex hulls, or from
// identities of closed surfaces; never from the filter's own output.
#include "PhongVTKExactReference.h"
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKOFFReader.h"
#include "vtkPolygonNormals.h"
#include "vtkVisibleArea.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using phongvtk_test::Cell;
using phongvtk_test::Cells;
using phongvtk_test::ComputeExactAreaVector;
using phongvtk_test::ExactAreaVector;
using phongvtk_test::MakePolyData;
using phongvtk_test::MessageObserver;
using phongvtk_test::Point;
using phongvtk_test::PointsOf;
using phongvtk_test::Transformed;

constexpr int Modes[] = { vtkVisibleArea::FAST, vtkVisibleArea::DOUBLE, vtkVisibleArea::COMPENSATED,
  vtkVisibleArea::EXACT };
constexpr double U = 0x1p-53;

/// The spacing of doubles just above |x|.
double Ulp(double x)
{
  return std::nextafter(std::fabs(x), HUGE_VAL) - std::fabs(x);
}
constexpr double UF = 0x1p-24;

//------------------------------------------------------------------------------
// The exact reference.

/// The exact visible area X = N / (2 sqrt(Q)): N = v.w, Q = |v|^2, both rational.
struct ExactVisible
{
  mpq_class N;
  mpq_class Q;
  mpq_class W[3];

  /// Sign of X - a, exactly.
  int CompareWith(double a) const
  {
    const int sn = sgn(this->N);
    const int sa = a > 0.0 ? 1 : (a < 0.0 ? -1 : 0);
    if (sn != sa || sn == 0)
    {
      return sn > sa ? 1 : (sn < sa ? -1 : 0);
    }
    // Same sign s: X > a  <=>  N > 2 a sqrt(Q)  <=>  s (N^2 - 4 a^2 Q) > 0.
    const mpq_class aq(a);
    const int c = sgn(this->N * this->N - 4 * aq * aq * this->Q);
    return sn > 0 ? c : -c;
  }

  /// Whether r is a faithful rounding of X (one of the two doubles around it).
  bool IsFaithful(double r) const
  {
    if (r == 0.0)
    {
      return this->N == 0;
    }
    const double below = std::nextafter(r, -std::numeric_limits<double>::infinity());
    const double above = std::nextafter(r, std::numeric_limits<double>::infinity());
    return this->CompareWith(below) >= 0 && this->CompareWith(above) <= 0;
  }

  double Value() const
  {
    mpf_class n(this->N, 512), q(this->Q, 512);
    mpf_class x(0, 512);
    x = n / (2 * sqrt(q));
    return x.get_d();
  }

  /// |X - r|, in 512-bit arithmetic.
  double ErrorOf(double r) const
  {
    mpf_class n(this->N, 512), q(this->Q, 512), rr(r, 512);
    mpf_class d(0, 512);
    d = n / (2 * sqrt(q)) - rr;
    return std::fabs(d.get_d());
  }
};

/// Exact visible area of a polygon seen toward direction v, or from the eye point (the direction
/// from the vertex mean to the eye: S = sum_i (eye - p_i) has that direction).
ExactVisible ComputeExactVisible(const std::vector<Point>& polygon, const Point& v, bool eye)
{
  const ExactAreaVector w = ComputeExactAreaVector(polygon);
  mpq_class s[3];
  for (int c = 0; c < 3; ++c)
  {
    if (eye)
    {
      for (const Point& p : polygon)
      {
        s[c] += mpq_class(v[c]) - mpq_class(p[c]);
      }
    }
    else
    {
      s[c] = v[c];
    }
  }
  ExactVisible r;
  for (int c = 0; c < 3; ++c)
  {
    r.N += s[c] * w.W[c];
    r.Q += s[c] * s[c];
    r.W[c] = w.W[c];
  }
  return r;
}

/// The points of cell `cell` (strips: as their outline polygon 0, 1, 3, ..., 4, 2).
std::vector<Point> CellPolygon(vtkPolyData* mesh, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  mesh->GetCellPoints(cell, ids);
  const vtkIdType n = ids->GetNumberOfIds();
  std::vector<vtkIdType> order;
  if (mesh->GetCellType(cell) == VTK_TRIANGLE_STRIP)
  {
    for (vtkIdType i = 1; i < n; i += 2)
    {
      order.push_back(i);
    }
    for (vtkIdType i = (n - 1) / 2 * 2; i >= 0; i -= 2)
    {
      order.push_back(i);
    }
    std::rotate(order.begin(), order.end() - 1, order.end()); // start at point 0
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      order.push_back(i);
    }
  }
  std::vector<Point> polygon;
  for (vtkIdType i : order)
  {
    Point p;
    mesh->GetPoint(ids->GetId(i), p.data());
    polygon.push_back(p);
  }
  return polygon;
}

//------------------------------------------------------------------------------
// Running the filter.

struct FilterRun
{
  vtkSmartPointer<vtkPolyData> Output;
  double Total = 0.0;
  double MaxArea = 0.0;
  std::array<double, 3> MaxDirection = { { 0.0, 0.0, 0.0 } };
  std::vector<std::string> Errors, Warnings;
  bool Updated = false; // what the executive's Update() returned

  double Area(vtkIdType cell) const
  {
    return this->Output->GetCellData()->GetArray("VisibleArea")->GetComponent(cell, 0);
  }
};

FilterRun RunFilter(vtkPolyData* input, int mode, const Point& direction,
  vtkCamera* camera = nullptr, bool expectQuiet = true)
{
  vtkNew<vtkVisibleArea> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  filter->SetAccuracy(mode);
  filter->SetViewDirection(direction[0], direction[1], direction[2]);
  filter->SetCamera(camera);
  filter->SetInputData(input);
  FilterRun r;
  r.Updated = filter->GetExecutive()->Update() != 0;
  r.Output = vtkSmartPointer<vtkPolyData>::New();
  r.Output->ShallowCopy(filter->GetOutput());
  r.Total = filter->GetTotalVisibleArea();
  r.MaxArea = filter->GetMaxVisibleArea();
  filter->GetMaxVisibleAreaDirection(r.MaxDirection.data());
  r.Errors = messages->Errors;
  r.Warnings = messages->Warnings;
  if (expectQuiet)
  {
    EXPECT_TRUE(r.Errors.empty()) << r.Errors.front();
    EXPECT_TRUE(r.Updated);
  }
  return r;
}

/// Sum over components of |v_c| * (sum of |products| entering w_c): the condition of v.w.
double DotCondition(const std::vector<Point>& polygon, const Point& unit)
{
  long double p[3] = { 0, 0, 0 };
  const Point& p0 = polygon[0];
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
  {
    long double a[3], b[3];
    for (int c = 0; c < 3; ++c)
    {
      a[c] = static_cast<long double>(polygon[i][c]) - p0[c];
      b[c] = static_cast<long double>(polygon[i + 1][c]) - p0[c];
    }
    for (int c = 0; c < 3; ++c)
    {
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      p[c] += std::fabs(a[c1] * b[c2]) + std::fabs(a[c2] * b[c1]);
    }
  }
  return static_cast<double>(
    std::fabs(unit[0]) * p[0] + std::fabs(unit[1]) * p[1] + std::fabs(unit[2]) * p[2]);
}

double Norm(const Point& v)
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/**
 * Error bound of the inexact modes for one polygon (from the bounds of PhongVTKAreaVector.h and
 * of the dot product), times two: `condition` is DotCondition, `length` |w|, `eye` whether v is
 * per cell.
 */
double Bound(int mode, std::size_t n, double condition, double length, double exact, bool eye)
{
  const double t = static_cast<double>(n) - 2.0;
  switch (mode)
  {
    case vtkVisibleArea::FAST:
      return 2.0 *
        (0.5 * (t + 5) * UF * condition + 4 * UF * length + 2 * UF * std::fabs(exact) +
          (eye ? (static_cast<double>(n) + 4) * UF * length : 0.0));
    case vtkVisibleArea::DOUBLE:
      return 2.0 *
        (0.5 * (t + 3) * U * condition + 4 * U * length + 2 * U * std::fabs(exact) +
          (eye ? (static_cast<double>(n) + 4) * U * length : 0.0));
    default: // COMPENSATED
      return 2.0 *
        (2 * U * length + 0.5 * (t + 65) * U * U * condition + 3 * U * std::fabs(exact) +
          (eye ? 2 * U * length : 0.0));
  }
}

/// The error of a non-EXACT mode's value `r` for `polygon` seen along v (or from the eye point v)
/// over its documented bound (at most 1 when the bound holds).
double ErrorOverBound(int mode, const std::vector<Point>& polygon, const Point& v, bool eye,
  const ExactVisible& exact, double r)
{
  Point unit = v;
  if (eye)
  {
    for (int c = 0; c < 3; ++c)
    {
      unit[c] = 0.0;
      for (const Point& p : polygon)
      {
        unit[c] += v[c] - p[c];
      }
    }
  }
  const double scale = 1.0 / Norm(unit);
  for (double& x : unit)
  {
    x *= scale;
  }
  mpf_class length(0, 512);
  length = sqrt(
    mpf_class(exact.W[0] * exact.W[0] + exact.W[1] * exact.W[1] + exact.W[2] * exact.W[2], 512));
  const double bound =
    Bound(mode, polygon.size(), DotCondition(polygon, unit), length.get_d(), exact.Value(), eye);
  const double err = exact.ErrorOf(r);
  return err == 0.0 ? 0.0 : err / bound;
}

//------------------------------------------------------------------------------
// Inputs.

/// Random polygons (triangles ... heptagons, planar and not, needles), scaled and offset.
vtkSmartPointer<vtkPolyData> RandomPolygons(double scale, double offset, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Point> points;
  Cells cells;
  auto add = [&](const Point& p)
  {
    points.push_back({ { p[0] * scale + offset, p[1] * scale + offset, p[2] * scale + offset } });
    return static_cast<vtkIdType>(points.size() - 1);
  };
  for (int k = 0; k < 120; ++k)
  {
    const int n = 3 + k % 5;
    Cell cell;
    if (k % 6 == 5)
    {
      // A needle: long and thin.
      const Point a = { { unit(rng), unit(rng), unit(rng) } };
      const Point d = { { unit(rng), unit(rng), unit(rng) } };
      cell = { add(a), add({ { a[0] + d[0], a[1] + d[1], a[2] + d[2] } }),
        add({ { a[0] + 0.5 * d[0] + 1e-9 * unit(rng), a[1] + 0.5 * d[1] + 1e-9 * unit(rng),
          a[2] + 0.5 * d[2] } }) };
    }
    else
    {
      // Around a centre, angles increasing; non-planar by a random height.
      const Point centre = { { unit(rng), unit(rng), unit(rng) } };
      const double height = (k % 2) ? 0.3 : 0.0;
      for (int i = 0; i < n; ++i)
      {
        const double angle = 2.0 * M_PI * (i + 0.3 * unit(rng)) / n;
        cell.push_back(add({ { centre[0] + 0.5 * std::cos(angle), centre[1] + 0.5 * std::sin(angle),
          centre[2] + height * unit(rng) } }));
      }
    }
    cells.Polys.push_back(cell);
  }
  return MakePolyData(points, cells);
}

Point RandomDirection(std::mt19937_64& rng)
{
  std::normal_distribution<double> normal;
  return { { normal(rng), normal(rng), normal(rng) } };
}

vtkSmartPointer<vtkPolyData> Sphere(int theta, int phi, double radius, double offset)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(theta);
  source->SetPhiResolution(phi);
  source->SetRadius(radius);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  return Transformed(source->GetOutput(), 1.0, offset);
}

/// The unit cube [0, 1]^3 with outward quads.
vtkSmartPointer<vtkPolyData> Cube()
{
  std::vector<Point> points;
  for (int i = 0; i < 8; ++i)
  {
    points.push_back({ { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) } });
  }
  Cells cells;
  cells.Polys = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 },
    { 1, 3, 7, 5 } };
  return MakePolyData(points, cells);
}

/// Area of the 2-D convex hull of the points, exactly (Andrew's monotone chain on rationals).
mpq_class ConvexHullArea(std::vector<std::array<mpq_class, 2>> p)
{
  std::sort(p.begin(), p.end(),
    [](const auto& a, const auto& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  auto cross = [](const auto& o, const auto& a, const auto& b)
  {
    return mpq_class((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]));
  };
  std::vector<std::array<mpq_class, 2>> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
    {
      --k;
    }
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i)
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0)
    {
      --k;
    }
    hull[k++] = p[i - 1];
  }
  mpq_class area;
  for (std::size_t i = 0; i + 1 < k; ++i)
  {
    area += hull[i][0] * hull[i + 1][1] - hull[i + 1][0] * hull[i][1];
  }
  return area / 2;
}

bool ExactlyZero(const std::array<double, 3>& v)
{
  return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

//------------------------------------------------------------------------------
TEST(VisibleAreaApi, DefaultsAndNames)
{
  vtkNew<vtkVisibleArea> f;
  EXPECT_EQ(f->GetAccuracy(), vtkVisibleArea::DOUBLE);
  EXPECT_STREQ(f->GetAccuracyAsString(), "DOUBLE");
  double v[3];
  f->GetViewDirection(v);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[1], 0.0);
  EXPECT_EQ(v[2], 1.0);
  EXPECT_EQ(f->GetCamera(), nullptr);
  EXPECT_TRUE(f->GetUseInputAreaVectors());
  EXPECT_TRUE(f->GetComputeMaxVisibleArea());
  const char* names[] = { "FAST", "DOUBLE", "COMPENSATED", "EXACT" };
  for (int mode : Modes)
  {
    f->SetAccuracy(mode);
    EXPECT_STREQ(f->GetAccuracyAsString(), names[mode]);
    EXPECT_EQ(mode, vtkPolygonNormals::FAST + mode); // numbered as vtkPolygonNormals'
  }
  vtkNew<phongvtk_test::MessageObserver> messages;
  messages->Watch(f);
  f->SetAccuracy(9);
  EXPECT_EQ(f->GetAccuracy(), vtkVisibleArea::EXACT); // the last mode set, kept
  ASSERT_EQ(messages->Errors.size(), 1u);
  EXPECT_NE(messages->Errors[0].find("Unknown accuracy 9"), std::string::npos);
}

TEST(VisibleAreaApi, CameraChangesReexecute)
{
  vtkSmartPointer<vtkPolyData> cube = Cube();
  vtkNew<vtkCamera> camera;
  camera->ParallelProjectionOn();
  camera->SetPosition(0.5, 0.5, 10.0);
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  vtkNew<vtkVisibleArea> f;
  f->SetInputData(cube);
  f->SetCamera(camera);
  f->Update();
  EXPECT_EQ(f->GetTotalVisibleArea(), 1.0);
  camera->SetPosition(10.5, 10.5, 10.5); // along (1, 1, 1): the silhouette is a hexagon
  f->Update();
  EXPECT_NEAR(f->GetTotalVisibleArea(), std::sqrt(3.0), 4 * U);
}

//------------------------------------------------------------------------------
// Each polygon against exact arithmetic.

struct Extreme
{
  const char* Name;
  double Scale;
  double Offset;
};

/// Areas of the last three are outside double's range: only finite values of the right sign
/// (saturated, or flushed to zero) are expected there.
constexpr Extreme Extremes[] = { { "unit", 1.0, 0.0 }, { "offset 1e8", 1.0, 1e8 },
  { "offset 1e8, size 1e-6", 1e-6, 1e8 }, { "tiny 1e-150", 1e-150, 0.0 },
  { "huge 1e150", 1e150, 0.0 }, { "tiny 1e-300", 1e-300, 0.0 }, { "huge 1e300", 1e300, 0.0 },
  { "subnormal 1e-310", 1e-310, 0.0 } };

/// Every mode on random polygons seen from random directions and from eye points: EXACT is
/// faithful, the others within their bounds; prints the largest errors (units of u of the area).
TEST(VisibleAreaAccuracy, EveryPolygonAgainstExactArithmetic)
{
  std::mt19937_64 rng(11);
  for (const Extreme& extreme : Extremes)
  {
    vtkSmartPointer<vtkPolyData> mesh = RandomPolygons(extreme.Scale, extreme.Offset, 3);
    for (int view = 0; view < 4; ++view)
    {
      const bool eye = view >= 2;
      Point v = RandomDirection(rng);
      vtkNew<vtkCamera> camera;
      if (eye)
      {
        for (double& x : v)
        {
          x = x * 3.0 * extreme.Scale + extreme.Offset;
        }
        camera->SetPosition(v.data());
        camera->SetFocalPoint(extreme.Offset, extreme.Offset, extreme.Offset);
      }
      for (int mode : Modes)
      {
        FilterRun run = RunFilter(mesh, mode, v, eye ? camera.Get() : nullptr);
        double worst = 0.0;
        for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
        {
          const std::vector<Point> polygon = CellPolygon(mesh, cell);
          const ExactVisible exact = ComputeExactVisible(polygon, v, eye);
          const double r = run.Area(cell);
          ASSERT_TRUE(std::isfinite(r));
          mpf_class len(0, 512);
          len =
            sqrt(mpf_class(
              exact.W[0] * exact.W[0] + exact.W[1] * exact.W[1] + exact.W[2] * exact.W[2], 512)) /
            2;
          const bool representable = len > std::numeric_limits<double>::min() &&
            len < 0.5 * std::numeric_limits<double>::max();
          if (!representable)
          {
            // Outside double's range: EXACT gives a finite value of the exact sign (zero only
            // when tiny); the others a finite value (checked above).
            const int sign = sgn(exact.N);
            EXPECT_TRUE(
              mode != vtkVisibleArea::EXACT || (r == 0.0 ? len < 1.0 : (r > 0.0 ? 1 : -1) == sign))
              << extreme.Name << " cell " << cell << ": " << r;
            continue;
          }
          if (mode == vtkVisibleArea::EXACT)
          {
            EXPECT_TRUE(exact.IsFaithful(r))
              << extreme.Name << " cell " << cell << " computed " << r << " exact " << exact.Value()
              << (eye ? " (eye)" : "");
            continue;
          }
          const double relative = ErrorOverBound(mode, polygon, v, eye, exact, r);
          EXPECT_LE(relative, 1.0) << extreme.Name << " mode " << mode << " cell " << cell;
          worst = std::max(worst, relative);
        }
        if (mode != vtkVisibleArea::EXACT && view == 0)
        {
          std::cout << "[ measured ] " << extreme.Name << ", mode " << mode
                    << ": largest error / bound " << worst << "\n";
        }
      }
    }
  }
}

TEST(VisibleAreaAccuracy, FloatPointsAndStripsAgainstExactArithmetic)
{
  // Float coordinates (read in place) and a strip (its outline polygon).
  std::vector<Point> points;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 12; ++i)
  {
    points.push_back({ { static_cast<float>(i * 0.5 + 1000.0),
      static_cast<float>((i % 2) + 0.1 * unit(rng) + 1000.0),
      static_cast<float>(0.2 * unit(rng) + 1000.0) } });
  }
  Cells cells;
  cells.Strips = { { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 }, { 0, 1, 2, 3, 4 } };
  cells.Polys = { { 0, 3, 5, 8 } };
  vtkSmartPointer<vtkPolyData> mesh = MakePolyData(points, cells, VTK_FLOAT);
  for (int view = 0; view < 8; ++view)
  {
    const Point v = RandomDirection(rng);
    for (int mode : Modes)
    {
      FilterRun run = RunFilter(mesh, mode, v);
      for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
      {
        const std::vector<Point> polygon = CellPolygon(mesh, cell);
        const ExactVisible exact = ComputeExactVisible(polygon, v, false);
        if (mode == vtkVisibleArea::EXACT)
        {
          EXPECT_TRUE(exact.IsFaithful(run.Area(cell))) << "cell " << cell;
        }
        else
        {
          EXPECT_LE(ErrorOverBound(mode, polygon, v, false, exact, run.Area(cell)), 1.0)
            << "mode " << mode << " cell " << cell;
        }
      }
    }
  }
}

TEST(VisibleAreaAccuracy, EdgeOnIsExactlyZeroAndNearlyEdgeOnKeepsItsSign)
{
  // A unit square in the plane z = 1e8 seen along x (exactly edge-on), and a triangle tilted by
  // 2^-60 seen along a direction where DOUBLE's dot product has no correct digit.
  Cells cells;
  cells.Polys = { { 0, 1, 2, 3 }, { 4, 5, 6 } };
  const double t = 0x1p-60;
  vtkSmartPointer<vtkPolyData> mesh =
    MakePolyData({ { { 0, 0, 1e8 } }, { { 1, 0, 1e8 } }, { { 1, 1, 1e8 } }, { { 0, 1, 1e8 } },
                   { { 0, 0, 0 } }, { { 1, 0, t } }, { { 0, 1, 0 } } },
      cells);
  const Point edgeOn = { { 1.0, 0.0, 0.0 } };
  FilterRun run = RunFilter(mesh, vtkVisibleArea::EXACT, edgeOn);
  EXPECT_EQ(run.Area(0), 0.0);
  // w = (-t, 0, 1) and v = (1, 0, t / 2): v.w = -t / 2, its back is seen.
  const Point v = { { 1.0, 0.0, 0.5 * t } };
  for (int mode : Modes)
  {
    run = RunFilter(mesh, mode, v);
    const ExactVisible exact = ComputeExactVisible(CellPolygon(mesh, 1), v, false);
    if (mode == vtkVisibleArea::EXACT)
    {
      EXPECT_TRUE(exact.IsFaithful(run.Area(1))) << run.Area(1) << " vs " << exact.Value();
      EXPECT_LT(run.Area(1), 0.0);
      continue;
    }
    // The other modes within their bounds, which here exceed the value itself: the sign is
    // not promised.
    EXPECT_LE(ErrorOverBound(mode, CellPolygon(mesh, 1), v, false, exact, run.Area(1)), 1.0)
      << "mode " << mode << ": " << run.Area(1) << " vs " << exact.Value();
    // The square seen exactly edge-on: zero within the bound.
    run = RunFilter(mesh, mode, edgeOn);
    const std::vector<Point> square = CellPolygon(mesh, 0);
    EXPECT_LE(ErrorOverBound(mode, square, edgeOn, false,
                ComputeExactVisible(square, edgeOn, false), run.Area(0)),
      1.0)
      << "mode " << mode << ": " << run.Area(0);
  }
}

//------------------------------------------------------------------------------
// Identities.

/// The signed visible areas of a closed surface sum to zero from any direction;
/// the max visible area direction is exactly zero.
TEST(VisibleAreaIdentities, ClosedSurfacesSumToZero)
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes = {
    { "sphere", Sphere(40, 25, 2.0, 0.0) }, { "sphere offset 1e6", Sphere(40, 25, 1.0, 1e6) },
    { "cube", Cube() }
  };
  for (const char* name : { "elephant.off", "eight.off" })
  {
    if (phongvtk_test::HaveCGALMeshes())
    {
      meshes.emplace_back(name, phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name)));
    }
  }
  std::mt19937_64 rng(2);
  for (const auto& [name, mesh] : meshes)
  {
    ASSERT_GT(mesh->GetNumberOfCells(), 0) << name;
    double bounds[6];
    mesh->GetBounds(bounds);
    for (int view = 0; view < 4; ++view)
    {
      // Three directions and a parallel camera (under perspective v changes from polygon to
      // polygon and the identity does not hold).
      const bool parallel = view == 3;
      Point v = RandomDirection(rng);
      vtkNew<vtkCamera> camera;
      camera->ParallelProjectionOn();
      camera->SetPosition(bounds[1] + 3 * (bounds[1] - bounds[0]), bounds[3], bounds[5]);
      camera->SetFocalPoint(bounds[0], bounds[2], bounds[4]);
      for (int mode : Modes)
      {
        FilterRun run = RunFilter(mesh, mode, v, parallel ? camera.Get() : nullptr);
        EXPECT_TRUE(ExactlyZero(run.MaxDirection)) << name;
        EXPECT_EQ(run.MaxArea, 0.0) << name;
        // The exact sum of the computed values, against the sum of their error allowances.
        mpq_class sum;
        double allowance = 0.0, total = 0.0;
        for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
        {
          const double a = run.Area(cell);
          sum += mpq_class(a);
          total += std::fabs(a);
          allowance += mode == vtkVisibleArea::EXACT ? std::fabs(std::nextafter(a, 2 * a + 1) - a) +
              std::numeric_limits<double>::denorm_min()
                                                     : 0.0;
        }
        if (mode != vtkVisibleArea::EXACT)
        {
          // Per polygon the bound is ~ (n + 5) u_mode (area); the meshes' polygons are small.
          allowance = (mode == vtkVisibleArea::FAST ? 40 * UF : 40 * U) * total;
          if (name.find("offset") != std::string::npos && mode == vtkVisibleArea::FAST)
          {
            allowance = 1e-2 * total; // float differences of 1e6-offset points
          }
        }
        EXPECT_LE(std::fabs(sum.get_d()), allowance) << name << " mode " << mode;
      }
    }
  }
}

/// Seen along v, the front faces of a convex closed surface add up to its silhouette's area:
/// the exact convex hull of the points projected on two rational axes orthogonal to v.
TEST(VisibleAreaIdentities, ConvexFrontFacesAddUpToTheSilhouette)
{
  // v = (1, 2, 2) / 3 with e1 = (2, 1, -2) / 3, e2 = (2, -2, 1) / 3 is an orthonormal frame of
  // rational vectors; and the axis frame.
  struct Frame
  {
    Point V, E1, E2;
    double Length;
  };
  const Frame frames[] = { { { { 1, 2, 2 } }, { { 2, 1, -2 } }, { { 2, -2, 1 } }, 3.0 },
    { { { 0, 0, 1 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } }, 1.0 } };
  for (double offset : { 0.0, 1e5 })
  {
    vtkSmartPointer<vtkPolyData> sphere = Sphere(30, 17, 1.5, offset);
    const std::vector<Point> points = PointsOf(sphere);
    for (const Frame& f : frames)
    {
      std::vector<std::array<mpq_class, 2>> projected;
      for (const Point& p : points)
      {
        std::array<mpq_class, 2> q;
        for (int c = 0; c < 3; ++c)
        {
          q[0] += mpq_class(p[c]) * f.E1[c] / f.Length;
          q[1] += mpq_class(p[c]) * f.E2[c] / f.Length;
        }
        projected.push_back(q);
      }
      const double silhouette = mpq_class(ConvexHullArea(projected)).get_d();
      for (int mode : Modes)
      {
        FilterRun run = RunFilter(sphere, mode, f.V);
        // EXACT promises each face's visible area faithful and their sum faithful: the total
        // lies within one ulp of every front face's area and one of its own.
        vtkDataArray* areas = run.Output->GetCellData()->GetArray("VisibleArea");
        double faceUlps = Ulp(run.Total);
        for (vtkIdType cell = 0; cell < areas->GetNumberOfTuples(); ++cell)
        {
          faceUlps += areas->GetTuple1(cell) > 0 ? Ulp(areas->GetTuple1(cell)) : 0.0;
        }
        const double tolerance = mode == vtkVisibleArea::EXACT ? faceUlps
          : mode == vtkVisibleArea::FAST ? (offset > 0 ? 2e-2 : 64 * UF) * silhouette
                                         : 256 * U * silhouette;
        EXPECT_NEAR(run.Total, silhouette, tolerance) << "mode " << mode << " offset " << offset;
        if (mode == vtkVisibleArea::EXACT)
        {
          std::cout << "[ measured ] silhouette offset " << offset << ": EXACT total off by "
                    << std::fabs(run.Total - silhouette) / (U * silhouette) << " u (bound "
                    << tolerance / (U * silhouette) << " u)\n";
        }
      }
    }
  }
}

TEST(VisibleAreaIdentities, CubeSeenAlongAnAxis)
{
  for (int mode : Modes)
  {
    FilterRun run = RunFilter(Cube(), mode, { { 0.0, 0.0, 1.0 } });
    EXPECT_EQ(run.Total, 1.0);
    EXPECT_EQ(run.Area(0), -1.0); // bottom: its back
    EXPECT_EQ(run.Area(1), 1.0);  // top
    for (vtkIdType side = 2; side < 6; ++side)
    {
      EXPECT_EQ(run.Area(side), 0.0) << "mode " << mode;
    }
  }
}

TEST(VisibleAreaIdentities, OpenSurfacesLookLargestAlongTheirSummedAreaVector)
{
  // A unit square in the plane z = 0 (two triangles), offset far away: sum w = (0, 0, 2).
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 } };
  const double o = 1e9;
  vtkSmartPointer<vtkPolyData> square = MakePolyData(
    { { { o, o, o } }, { { o + 1, o, o } }, { { o + 1, o + 1, o } }, { { o, o + 1, o } } }, cells);
  FilterRun run = RunFilter(square, vtkVisibleArea::DOUBLE, { { 1.0, 1.0, 1.0 } });
  EXPECT_EQ(run.MaxDirection[0], 0.0);
  EXPECT_EQ(run.MaxDirection[1], 0.0);
  EXPECT_EQ(run.MaxDirection[2], 1.0);
  EXPECT_EQ(run.MaxArea, 1.0);

  // A hemisphere (sphere source cut at the equator): open at the bottom, the sum is the disc
  // that closes it: exactly the polygon of the rim, seen from +z.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(24);
  source->SetPhiResolution(12);
  source->SetEndPhi(90.0);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  vtkPolyData* hemisphere = source->GetOutput();
  // The rim: the points with z == 0 (the last ring), in angle order.
  std::vector<Point> rim;
  for (const Point& p : PointsOf(hemisphere))
  {
    if (std::fabs(p[2]) < 1e-12)
    {
      rim.push_back(p);
    }
  }
  std::sort(rim.begin(), rim.end(),
    [](const Point& a, const Point& b) { return std::atan2(a[1], a[0]) < std::atan2(b[1], b[0]); });
  ASSERT_EQ(rim.size(), 24u);
  const ExactVisible disc = ComputeExactVisible(rim, { { 0.0, 0.0, 1.0 } }, false);
  run = RunFilter(hemisphere, vtkVisibleArea::EXACT, { { 0.0, 0.0, 1.0 } });
  EXPECT_TRUE(disc.IsFaithful(run.MaxArea)) << run.MaxArea << " vs " << disc.Value();
  EXPECT_EQ(run.MaxDirection[2], 1.0);
  EXPECT_NEAR(run.MaxDirection[0], 0.0, 1e-15);
}

TEST(VisibleAreaIdentities, ATrianglesAreaDoesNotDependOnItsNeighbours)
{
  // Runs of triangles go four at a time; a triangle next to a quad goes alone. Either way (and so
  // for any order of the cells or split into pieces) a triangle's visible area is the same bits:
  // random triangles over 80 binades, nearly and exactly edge-on, with zero components, tiny and
  // huge coordinates, each once in a run of triangles and once between two quads.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> binade(-40, 40);
  std::vector<Point> points;
  std::vector<Cell> triangles;
  for (int k = 0; k < 4000; ++k)
  {
    const double scale = std::ldexp(1.0, binade(rng)) * (k % 97 == 0 ? 1e280 : 1.0);
    const double offset = k % 5 == 0 ? 1e6 * scale : 0.0;
    const vtkIdType first = static_cast<vtkIdType>(points.size());
    for (int v = 0; v < 3; ++v)
    {
      Point p = { { offset + scale * unit(rng), offset + scale * unit(rng),
        offset + scale * unit(rng) } };
      if (k % 7 == 0)
      {
        p[2] = offset; // in the plane z = offset: edge-on along x or y, zero x and y components
      }
      if (k % 11 == 0 && v == 2)
      {
        p = points[first]; // degenerate
      }
      points.push_back(p);
    }
    triangles.push_back({ first, first + 1, first + 2 });
  }
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  Cells runs, alone;
  runs.Polys = triangles;
  for (const Cell& t : triangles)
  {
    alone.Polys.push_back({ quad[0], quad[1], quad[2], quad[3] });
    alone.Polys.push_back(t);
  }
  auto inRuns = MakePolyData(points, runs);
  auto betweenQuads = MakePolyData(points, alone);
  vtkNew<vtkCamera> camera; // perspective: the direction to the eye from every triangle
  camera->SetPosition(3.0, -2.0, 5.0);
  const std::vector<Point> views = { { { 1.0, 0.0, 0.0 } }, { { 0.0, 0.0, 1.0 } },
    RandomDirection(rng), { { 0.0, 0.0, 0.0 } } };
  for (std::size_t view = 0; view < views.size(); ++view)
  {
    vtkCamera* eye = view + 1 == views.size() ? camera.Get() : nullptr;
    for (int mode : Modes)
    {
      FilterRun a = RunFilter(inRuns, mode, views[view], eye);
      FilterRun b = RunFilter(betweenQuads, mode, views[view], eye);
      int mismatches = 0;
      for (vtkIdType t = 0; t < static_cast<vtkIdType>(triangles.size()); ++t)
      {
        const double x = a.Area(t), y = b.Area(2 * t + 1);
        if (std::memcmp(&x, &y, sizeof(x)) != 0 && ++mismatches <= 5)
        {
          ADD_FAILURE() << "view " << view << " mode " << mode << " triangle " << t << ": " << x
                        << " in a run, " << y << " alone";
        }
      }
      EXPECT_EQ(mismatches, 0) << "view " << view << " mode " << mode;
    }
  }
}

//------------------------------------------------------------------------------
// Views.

TEST(VisibleAreaViews, PerspectiveUsesTheDirectionToTheEyeFromEachPolygon)
{
  // Two unit squares side by side in z = 0 (triangulated), eye above the first: its triangles
  // are seen straight on, the second square's obliquely.
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 5, 6 }, { 4, 6, 7 } };
  vtkSmartPointer<vtkPolyData> mesh =
    MakePolyData({ { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 1, 1, 0 } }, { { 0, 1, 0 } },
                   { { 10, 0, 0 } }, { { 11, 0, 0 } }, { { 11, 1, 0 } }, { { 10, 1, 0 } } },
      cells);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.5, 0.5, 4.0);
  camera->SetFocalPoint(0.5, 0.5, 0.0);
  for (int mode : Modes)
  {
    FilterRun run = RunFilter(mesh, mode, { { 0, 0, 1 } }, camera);
    for (vtkIdType cell = 0; cell < 4; ++cell)
    {
      // Expected: 1/2 * cos of the angle between z and (eye - vertex mean).
      const ExactVisible exact =
        ComputeExactVisible(CellPolygon(mesh, cell), { { 0.5, 0.5, 4.0 } }, true);
      const double tolerance = mode == vtkVisibleArea::FAST ? 8 * UF : 8 * U;
      EXPECT_NEAR(run.Area(cell), exact.Value(), tolerance) << "mode " << mode;
      if (mode == vtkVisibleArea::EXACT)
      {
        EXPECT_TRUE(exact.IsFaithful(run.Area(cell)));
      }
    }
    EXPECT_LT(run.Area(2), 0.5 * 4.0 / std::sqrt(16.0 + 100.0)); // oblique: much smaller
  }
  // Parallel: the reverse of the direction of projection, the same for every polygon.
  camera->ParallelProjectionOn();
  camera->SetPosition(0.5, 0.5 - 4.0, 4.0);
  FilterRun run = RunFilter(mesh, vtkVisibleArea::EXACT, { { 0, 0, 1 } }, camera);
  for (vtkIdType cell = 0; cell < 4; ++cell)
  {
    EXPECT_NEAR(run.Area(cell), 0.5 / std::sqrt(2.0), 2 * U);
  }
}

//------------------------------------------------------------------------------
// Outputs, reuse, bad input.

TEST(VisibleAreaOutputs, ArraysFieldDataAndPassThrough)
{
  vtkSmartPointer<vtkPolyData> cube = Cube();
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("Ids");
  for (int i = 0; i < 6; ++i)
  {
    cellIds->InsertNextValue(i);
  }
  cube->GetCellData()->AddArray(cellIds);
  FilterRun run = RunFilter(cube, vtkVisibleArea::DOUBLE, { { 0, 0, 2 } });
  vtkPolyData* out = run.Output;
  EXPECT_EQ(out->GetPoints()->GetData(), cube->GetPoints()->GetData());
  EXPECT_EQ(out->GetCellData()->GetArray("Ids"), cellIds.Get());
  vtkDataArray* areas = out->GetCellData()->GetArray("VisibleArea");
  ASSERT_NE(areas, nullptr);
  EXPECT_EQ(areas->GetDataType(), VTK_DOUBLE);
  vtkFieldData* fd = out->GetFieldData();
  ASSERT_NE(fd->GetArray("TotalVisibleArea"), nullptr);
  EXPECT_EQ(fd->GetArray("TotalVisibleArea")->GetComponent(0, 0), 1.0);
  ASSERT_NE(fd->GetArray("MaxVisibleAreaDirection"), nullptr);
  EXPECT_EQ(fd->GetArray("MaxVisibleAreaDirection")->GetNumberOfComponents(), 3);
  ASSERT_NE(fd->GetArray("MaxVisibleArea"), nullptr);

  vtkNew<vtkVisibleArea> f;
  f->ComputeMaxVisibleAreaOff();
  f->SetInputData(cube);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetFieldData()->GetArray("MaxVisibleAreaDirection"), nullptr);
}

TEST(VisibleAreaOutputs, VerticesAndLinesAreNotSurfaces)
{
  Cells cells;
  cells.Verts = { { 0 } };
  cells.Lines = { { 0, 1, 2 } };
  cells.Polys = { { 0, 1, 2 } };
  vtkSmartPointer<vtkPolyData> mesh =
    MakePolyData({ { { 0, 0, 0 } }, { { 2, 0, 0 } }, { { 0, 3, 0 } } }, cells);
  FilterRun run = RunFilter(mesh, vtkVisibleArea::EXACT, { { 0, 0, 1 } });
  EXPECT_EQ(run.Area(0), 0.0);
  EXPECT_EQ(run.Area(1), 0.0);
  EXPECT_EQ(run.Area(2), 3.0);
  EXPECT_EQ(run.Total, 3.0);
}

TEST(VisibleAreaOutputs, InputAreaVectorsAreReusedExceptInExact)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere(16, 9, 1.0, 0.0);
  vtkNew<vtkPolygonNormals> normals;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(normals);
  normals->SetInputData(sphere);
  normals->ComputeAreaVectorsOn();
  normals->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  normals->Update();
  auto withVectors = vtkSmartPointer<vtkPolyData>::New();
  withVectors->DeepCopy(normals->GetOutput());
  // Doubled area vectors: a filter that reuses them reports doubled areas.
  vtkDataArray* vectors = withVectors->GetCellData()->GetArray("AreaVectors");
  for (vtkIdType i = 0; i < vectors->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      vectors->SetComponent(i, c, 2.0 * vectors->GetComponent(i, c));
    }
  }
  const Point v = { { 0.3, -0.4, 0.5 } };
  const double plain = RunFilter(sphere, vtkVisibleArea::DOUBLE, v).Total;
  EXPECT_NEAR(RunFilter(withVectors, vtkVisibleArea::DOUBLE, v).Total, 2.0 * plain, 1e-13);
  EXPECT_NEAR(RunFilter(withVectors, vtkVisibleArea::EXACT, v).Total, plain, 1e-13);
  vtkNew<vtkVisibleArea> f;
  f->UseInputAreaVectorsOff();
  f->SetViewDirection(v[0], v[1], v[2]);
  f->SetInputData(withVectors);
  f->Update();
  EXPECT_NEAR(f->GetTotalVisibleArea(), plain, 1e-13);
}

TEST(VisibleAreaBadInput, ZeroOrNonFiniteViewIsAnError)
{
  for (const Point& v : { Point{ { 0, 0, 0 } }, Point{ { NAN, 0, 1 } } })
  {
    FilterRun run = RunFilter(Cube(), vtkVisibleArea::DOUBLE, v, nullptr, false);
    ASSERT_EQ(run.Errors.size(), 1u);
    EXPECT_NE(run.Errors[0].find("view direction"), std::string::npos) << run.Errors[0];
    EXPECT_FALSE(run.Updated);
    EXPECT_EQ(run.Output->GetNumberOfCells(), 0);
  }
}

TEST(VisibleAreaBadInput, BadPointIdNamesTheCell)
{
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 1, 7 } };
  vtkSmartPointer<vtkPolyData> mesh =
    MakePolyData({ { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } } }, cells);
  FilterRun run = RunFilter(mesh, vtkVisibleArea::EXACT, { { 0, 0, 1 } }, nullptr, false);
  ASSERT_EQ(run.Errors.size(), 1u);
  EXPECT_NE(run.Errors[0].find("Cell 1"), std::string::npos) << run.Errors[0];
  EXPECT_FALSE(run.Updated);
  EXPECT_EQ(run.Output->GetNumberOfCells(), 0);
}

TEST(VisibleAreaBadInput, NonFiniteCoordinatesGiveZeroAndOneWarning)
{
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 1, 3 }, { 4, 1, 2 } };
  const double inf = std::numeric_limits<double>::infinity();
  vtkSmartPointer<vtkPolyData> mesh = MakePolyData(
    { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } }, { { NAN, 0, 0 } }, { { 0, inf, 0 } } },
    cells);
  for (int mode : Modes)
  {
    for (bool eye : { false, true })
    {
      vtkNew<vtkCamera> camera;
      camera->SetPosition(1.0 / 3.0, 1.0 / 3.0, 5.0); // above the first triangle's mean
      FilterRun run = RunFilter(mesh, mode, { { 0, 0, 1 } }, eye ? camera.Get() : nullptr);
      EXPECT_NEAR(run.Area(0), 0.5, 1e-7);
      EXPECT_EQ(run.Area(1), 0.0);
      EXPECT_EQ(run.Area(2), 0.0);
      ASSERT_EQ(run.Warnings.size(), 1u) << "mode " << mode;
      EXPECT_NE(run.Warnings[0].find("2 cell(s)"), std::string::npos) << run.Warnings[0];
      EXPECT_TRUE(std::isfinite(run.MaxArea));
    }
  }
}

TEST(VisibleAreaBadInput, DegenerateCellsAreZero)
{
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 0, 1 }, { 0, 1 } };
  vtkSmartPointer<vtkPolyData> mesh =
    MakePolyData({ { { 0, 0, 0 } }, { { 1, 1, 1 } }, { { 2, 2, 2 } } }, cells);
  for (int mode : Modes)
  {
    FilterRun run = RunFilter(mesh, mode, { { 0, 0, 1 } });
    for (vtkIdType cell = 0; cell < 3; ++cell)
    {
      EXPECT_EQ(run.Area(cell), 0.0);
    }
    EXPECT_EQ(run.Total, 0.0);
  }
}

TEST(VisibleAreaBadInput, ATotalBeyondTheDoubleRangeSaturates)
{
  // Found by FuzzPolyDataFilters: front faces whose areas are finite but whose sum exceeds the
  // double range gave a NaN total (the compensated sum's error term is infinity minus infinity).
  // Eight triangles of area 2^1022 each: the exact total, 2^1025, is beyond the largest double.
  const double a = std::ldexp(1.0, 512), b = std::ldexp(1.0, 511);
  Cells cells;
  for (int k = 0; k < 8; ++k)
  {
    cells.Polys.push_back({ 0, 1, 2 });
  }
  vtkSmartPointer<vtkPolyData> mesh =
    MakePolyData({ { { 0, 0, 0 } }, { { a, 0, 0 } }, { { 0, b, 0 } } }, cells);
  for (int mode : Modes)
  {
    FilterRun run = RunFilter(mesh, mode, { { 0, 0, 1 } });
    EXPECT_EQ(run.Area(0), std::ldexp(1.0, 1022)) << "mode " << mode;
    EXPECT_EQ(run.Total, std::numeric_limits<double>::max()) << "mode " << mode;
  }
}

TEST(VisibleAreaBadInput, EmptyInputIsQuiet)
{
  auto empty = vtkSmartPointer<vtkPolyData>::New();
  FilterRun run = RunFilter(empty, vtkVisibleArea::EXACT, { { 0, 0, 1 } });
  EXPECT_TRUE(run.Warnings.empty());
  EXPECT_EQ(run.Total, 0.0);
}
} // namespace
