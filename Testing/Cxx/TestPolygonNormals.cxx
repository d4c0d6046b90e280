// Specification of vtkPolygonNormals as a VTK filter. Expected values come from the independent
// exact reference (PhongVTKExactReference.h: GMP rationals, 1024-bit normals), from long double
// evaluations of the weighting formulas written here from their definitions, or from analytic
// facts; never from the filter's own output.
#include "PhongVTKExactReference.h"
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKOFFReader.h"
#include "vtkPolygonNormals.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using phongvtk_test::Cell;
using phongvtk_test::Cells;
using phongvtk_test::ExactAreaVector;
using phongvtk_test::MakeCellArray;
using phongvtk_test::MakePolyData;
using phongvtk_test::MessageObserver;
using phongvtk_test::Point;
using phongvtk_test::PointsOf;
using phongvtk_test::Transformed;
using Vec3L = std::array<long double, 3>;

constexpr int Modes[] = { vtkPolygonNormals::FAST, vtkPolygonNormals::DOUBLE,
  vtkPolygonNormals::COMPENSATED, vtkPolygonNormals::EXACT };
constexpr int Weightings[] = { vtkPolygonNormals::AREA, vtkPolygonNormals::ANGLE,
  vtkPolygonNormals::UNIFORM, vtkPolygonNormals::MAX };

const char* ModeName(int mode)
{
  static const char* names[] = { "FAST", "DOUBLE", "COMPENSATED", "EXACT" };
  return names[mode];
}

const char* WeightingName(int weighting)
{
  static const char* names[] = { "AREA", "ANGLE", "UNIFORM", "MAX" };
  return names[weighting];
}

//------------------------------------------------------------------------------
// Building inputs.

using phongvtk_test::JitteredSphere;

/**
 * A bumpy height field with small integer coordinates in [-8, 8]: triangles and non-planar quads.
 * Scaling by powers of two and offsets up to 2^49 keep every coordinate exact, and differences
 * of the points scaled by 2^1020 overflow.
 */
vtkSmartPointer<vtkPolyData> IntegerHeightField()
{
  std::vector<Point> points;
  Cells cells;
  const int n = 17;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int h = ((i * 7 + j * 3) % 5) - 2 + ((i + j) % 2 ? 1 : -1) * (i % 3 == 0 ? 2 : 0);
      points.push_back({ static_cast<double>(i - 8), static_cast<double>(j - 8),
        static_cast<double>(std::max(-8, std::min(8, h))) });
    }
  }
  auto id = [n](int i, int j)
  {
    return static_cast<vtkIdType>(j * n + i);
  };
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      if ((i + j) % 3 == 0)
      {
        cells.Polys.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
      }
      else
      {
        cells.Polys.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
        cells.Polys.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
      }
    }
  }
  // Two large cells across the whole field: at the scale 2^1020 their coordinate differences
  // (16 * 2^1020) overflow.
  cells.Polys.push_back({ id(0, 0), id(n - 1, 0), id(n - 1, n - 1) });
  cells.Polys.push_back({ id(0, 0), id(n - 1, n - 1), id(n / 2, n - 1), id(0, n - 1) });
  return MakePolyData(points, cells);
}

//------------------------------------------------------------------------------
// Running the filter and reading its output.

/// Runs the filter on `input`; warnings are swallowed (tests that expect them watch them
/// themselves), errors fail the test.
vtkSmartPointer<vtkPolyData> RunFilter(
  vtkPolyData* input, const std::function<void(vtkPolygonNormals*)>& configure = {})
{
  vtkNew<vtkPolygonNormals> filter;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(filter);
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  if (configure)
  {
    configure(filter);
  }
  filter->SetInputData(input);
  filter->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors.front();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}

/// Every cell output in double precision, in the given accuracy mode.
std::function<void(vtkPolygonNormals*)> AllCellOutputs(int mode)
{
  return [mode](vtkPolygonNormals* f)
  {
    f->SetAccuracy(mode);
    f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    f->ComputeAreaVectorsOn();
    f->ComputeAreasOn();
    f->ComputeNormalStatusOn();
  };
}

std::array<double, 3> Tuple3(vtkDataArray* array, vtkIdType i)
{
  std::array<double, 3> t;
  array->GetTuple(i, t.data());
  return t;
}

bool IsZero(const std::array<double, 3>& v)
{
  return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

bool IsFinite(const std::array<double, 3>& v)
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

int Status(vtkPolyData* output, vtkIdType cell)
{
  return static_cast<int>(output->GetCellData()->GetArray("NormalStatus")->GetTuple1(cell));
}

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

//------------------------------------------------------------------------------
// The independent reference.

/// The cell's points, in order (VTK cell id: verts, lines, polys, strips).
std::vector<Point> CellPoints(vtkPolyData* mesh, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  mesh->GetCellPoints(cell, ids);
  std::vector<Point> points(static_cast<std::size_t>(ids->GetNumberOfIds()));
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    mesh->GetPoint(ids->GetId(k), points[static_cast<std::size_t>(k)].data());
  }
  return points;
}

/// The triangles of a strip with the strip's alternating orientation (j odd: j+1, j, j+2).
std::vector<Cell> StripTriangles(const Cell& strip)
{
  std::vector<Cell> triangles;
  for (std::size_t j = 0; j + 2 < strip.size(); ++j)
  {
    if (j % 2 == 0)
    {
      triangles.push_back({ strip[j], strip[j + 1], strip[j + 2] });
    }
    else
    {
      triangles.push_back({ strip[j + 1], strip[j], strip[j + 2] });
    }
  }
  return triangles;
}

Cell CellIds(vtkPolyData* mesh, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  mesh->GetCellPoints(cell, ids);
  return Cell(ids->begin(), ids->end());
}

std::vector<Point> Gather(const std::vector<Point>& points, const Cell& ids)
{
  std::vector<Point> polygon;
  for (vtkIdType id : ids)
  {
    polygon.push_back(points[static_cast<std::size_t>(id)]);
  }
  return polygon;
}

/// Exact area vector of any cell: polygons directly, strips as the exact sum of their
/// triangles, vertices and lines zero.
ExactAreaVector ExactCellAreaVector(vtkPolyData* mesh, vtkIdType cell)
{
  const int type = mesh->GetCellType(cell);
  if (type == VTK_TRIANGLE_STRIP)
  {
    const std::vector<Point> points = PointsOf(mesh);
    ExactAreaVector sum;
    for (const Cell& triangle : StripTriangles(CellIds(mesh, cell)))
    {
      const ExactAreaVector w = phongvtk_test::ComputeExactAreaVector(Gather(points, triangle));
      for (int c = 0; c < 3; ++c)
      {
        sum.W[c] += w.W[c];
      }
    }
    return sum;
  }
  if (type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON)
  {
    return phongvtk_test::ComputeExactAreaVector(CellPoints(mesh, cell));
  }
  return ExactAreaVector{};
}

mpf_class Half(const mpq_class& x)
{
  return mpf_class(mpq_class(x / 2), phongvtk_test::ReferenceBits);
}

/// Angle between a computed unit vector and a long double reference direction.
long double AngleTo(const std::array<double, 3>& computed, const Vec3L& reference)
{
  const long double a[3] = { computed[0], computed[1], computed[2] };
  const long double x = a[1] * reference[2] - a[2] * reference[1];
  const long double y = a[2] * reference[0] - a[0] * reference[2];
  const long double z = a[0] * reference[1] - a[1] * reference[0];
  const long double dot = a[0] * reference[0] + a[1] * reference[1] + a[2] * reference[2];
  return std::atan2(std::sqrt(x * x + y * y + z * z), dot);
}

Vec3L Normalized(const Vec3L& v)
{
  const long double m = std::max({ std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2]) });
  if (m == 0.0L)
  {
    return { 0.0L, 0.0L, 0.0L };
  }
  const Vec3L s = { v[0] / m, v[1] / m, v[2] / m };
  const long double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  return { s[0] / length, s[1] / length, s[2] / length };
}

/**
 * Reference point normals, from the definitions: every polygon and every strip triangle is a
 * face; AREA sums the exact area vectors in rationals and normalises to 1024 bits; ANGLE,
 * UNIFORM and MAX are evaluated in long double (64-bit significand, 15-bit exponent: no overflow
 * or underflow for any double input) from the exact unit face normals.
 */
std::vector<Vec3L> ReferencePointNormals(vtkPolyData* mesh, int weighting)
{
  const std::vector<Point> points = PointsOf(mesh);
  std::vector<Cell> faces;
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    const int type = mesh->GetCellType(cell);
    if (type == VTK_TRIANGLE_STRIP)
    {
      for (const Cell& t : StripTriangles(CellIds(mesh, cell)))
      {
        faces.push_back(t);
      }
    }
    else if (type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON)
    {
      faces.push_back(CellIds(mesh, cell));
    }
  }
  const std::size_t numPoints = points.size();
  std::vector<Vec3L> result(numPoints, Vec3L{ 0.0L, 0.0L, 0.0L });
  if (weighting == vtkPolygonNormals::AREA)
  {
    std::vector<ExactAreaVector> sums(numPoints);
    for (const Cell& face : faces)
    {
      const ExactAreaVector w = phongvtk_test::ComputeExactAreaVector(Gather(points, face));
      for (vtkIdType id : face)
      {
        for (int c = 0; c < 3; ++c)
        {
          sums[static_cast<std::size_t>(id)].W[c] += w.W[c];
        }
      }
    }
    for (std::size_t p = 0; p < numPoints; ++p)
    {
      const auto n = phongvtk_test::ReferenceNormal(sums[p]);
      result[p] = { n[0].get_d(), n[1].get_d(), n[2].get_d() };
      // get_d truncates; the remainder keeps the long double reference accurate to ~2^-64.
      for (int c = 0; c < 3; ++c)
      {
        const mpf_class rest(n[c] - mpf_class(n[c].get_d()), phongvtk_test::ReferenceBits);
        result[p][c] += static_cast<long double>(rest.get_d());
      }
    }
    return result;
  }
  for (const Cell& face : faces)
  {
    const auto exact =
      phongvtk_test::ReferenceNormal(phongvtk_test::ComputeExactAreaVector(Gather(points, face)));
    const Vec3L unit = { exact[0].get_d(), exact[1].get_d(), exact[2].get_d() };
    if (unit[0] == 0.0L && unit[1] == 0.0L && unit[2] == 0.0L)
    {
      continue; // a degenerate face has no direction to give
    }
    const std::size_t n = face.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      const Point& v = points[static_cast<std::size_t>(face[i])];
      const Point& next = points[static_cast<std::size_t>(face[(i + 1) % n])];
      const Point& prev = points[static_cast<std::size_t>(face[(i + n - 1) % n])];
      Vec3L a, b; // a = next - v, b = prev - v
      for (int c = 0; c < 3; ++c)
      {
        a[c] = static_cast<long double>(next[c]) - static_cast<long double>(v[c]);
        b[c] = static_cast<long double>(prev[c]) - static_cast<long double>(v[c]);
      }
      const Vec3L cross = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0] };
      const long double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
      const long double bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
      Vec3L& s = result[static_cast<std::size_t>(face[i])];
      if (weighting == vtkPolygonNormals::UNIFORM)
      {
        for (int c = 0; c < 3; ++c)
        {
          s[c] += unit[c];
        }
      }
      else if (aa > 0.0L && bb > 0.0L)
      {
        if (weighting == vtkPolygonNormals::ANGLE)
        {
          const long double angle =
            std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]),
              a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
          for (int c = 0; c < 3; ++c)
          {
            s[c] += angle * unit[c];
          }
        }
        else
        {
          for (int c = 0; c < 3; ++c)
          {
            s[c] += cross[c] / (aa * bb);
          }
        }
      }
    }
  }
  for (Vec3L& n : result)
  {
    n = Normalized(n);
  }
  return result;
}

/// Worst angle between the filter's point normals and the reference; zero reference normals
/// must come out as exactly zero.
long double WorstPointNormalAngle(
  vtkPolyData* output, const std::vector<Vec3L>& reference, const std::string& what)
{
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  EXPECT_NE(normals, nullptr) << what;
  if (!normals)
  {
    return 0.0L;
  }
  long double worst = 0.0L;
  for (std::size_t p = 0; p < reference.size(); ++p)
  {
    const auto n = Tuple3(normals, static_cast<vtkIdType>(p));
    const Vec3L& r = reference[p];
    if (r[0] == 0.0L && r[1] == 0.0L && r[2] == 0.0L)
    {
      EXPECT_TRUE(IsZero(n)) << what << ": point " << p << " has no faces";
      continue;
    }
    const long double angle = AngleTo(n, r);
    EXPECT_TRUE(IsFinite(n)) << what << ": point " << p;
    if (angle > worst)
    {
      worst = angle;
    }
  }
  return worst;
}

/**
 * Bounds on the error of each area vector component in the inexact modes, as the kernel header
 * documents them (T fan triangles, P_c the sum of |products| entering component c):
 * FAST (T+3) u_f P_c, DOUBLE (T+3) u P_c, COMPENSATED u |w_c| + (T+65) u^2 P_c.
 */
std::array<long double, 3> ComponentBounds(
  const std::vector<Point>& polygon, const ExactAreaVector& exact, int mode)
{
  const std::size_t n = polygon.size();
  const long double u = 0x1p-53L;
  const long double uf = 0x1p-24L;
  long double p[3] = { 0.0L, 0.0L, 0.0L };
  for (std::size_t i = 1; i + 1 < n; ++i)
  {
    long double a[3], b[3];
    for (int c = 0; c < 3; ++c)
    {
      a[c] = static_cast<long double>(polygon[i][c]) - polygon[0][c];
      b[c] = static_cast<long double>(polygon[i + 1][c]) - polygon[0][c];
    }
    for (int c = 0; c < 3; ++c)
    {
      const int x = (c + 1) % 3;
      const int y = (c + 2) % 3;
      p[c] += std::fabs(a[x] * b[y]) + std::fabs(a[y] * b[x]);
    }
  }
  const long double triangles = static_cast<long double>(n) - 2.0L;
  std::array<long double, 3> bounds;
  for (int c = 0; c < 3; ++c)
  {
    switch (mode)
    {
      case vtkPolygonNormals::FAST:
        bounds[c] = (triangles + 3) * uf * p[c];
        break;
      case vtkPolygonNormals::DOUBLE:
        bounds[c] = (triangles + 3) * u * p[c];
        break;
      default:
        bounds[c] = u * std::fabs(static_cast<long double>(exact.W[c].get_d())) +
          (triangles + 65) * u * u * p[c];
        break;
    }
  }
  return bounds;
}

/**
 * Angle error bound of a cell normal in the inexact modes: the area vector's error bound
 * relative to |w|, plus the normalisation's few roundings. Pi when the bound says nothing.
 */
double AngleBound(const std::vector<Point>& polygon, const ExactAreaVector& exact, int mode)
{
  const auto bounds = ComponentBounds(polygon, exact, mode);
  long double error2 = 0.0L, length2 = 0.0L;
  for (int c = 0; c < 3; ++c)
  {
    const long double w = static_cast<long double>(exact.W[c].get_d());
    error2 += bounds[c] * bounds[c];
    length2 += w * w;
  }
  const long double relative = std::sqrt(error2 / length2);
  if (!(relative < 0.5L))
  {
    return M_PI;
  }
  const double unit = mode == vtkPolygonNormals::FAST ? 0x1p-24 : 0x1p-53;
  return static_cast<double>(relative) + 4.0 * unit;
}

//------------------------------------------------------------------------------
// The CGAL meshes and their exact references, computed once per test program.

struct MeshReference
{
  vtkSmartPointer<vtkPolyData> Mesh;
  std::vector<ExactAreaVector> W;
  std::vector<std::array<mpf_class, 3>> Normals;
};

const MeshReference* CGALMesh(const std::string& name)
{
  static std::map<std::string, MeshReference> cache;
  auto found = cache.find(name);
  if (found != cache.end())
  {
    return &found->second;
  }
  std::string error;
  MeshReference ref;
  ref.Mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name), &error);
  if (!ref.Mesh)
  {
    ADD_FAILURE() << error;
    return nullptr;
  }
  const std::vector<Point> points = PointsOf(ref.Mesh);
  const vtkIdType numCells = ref.Mesh->GetNumberOfCells();
  ref.W.resize(static_cast<std::size_t>(numCells));
  ref.Normals.reserve(static_cast<std::size_t>(numCells));
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    ref.W[cell] = phongvtk_test::ComputeExactAreaVector(Gather(points, CellIds(ref.Mesh, cell)));
    ref.Normals.push_back(phongvtk_test::ReferenceNormal(ref.W[cell]));
  }
  return &cache.emplace(name, std::move(ref)).first->second;
}
} // namespace

//==============================================================================
// API

TEST(PolygonNormalsApi, Defaults)
{
  vtkNew<vtkPolygonNormals> f;
  EXPECT_EQ(f->GetAccuracy(), vtkPolygonNormals::DOUBLE);
  EXPECT_EQ(f->GetPointWeighting(), vtkPolygonNormals::AREA);
  // vtkPolyDataNormals' options and defaults: TestDropIn compares them with that class.
  EXPECT_FALSE(f->GetComputeCellNormals());
  EXPECT_TRUE(f->GetComputePointNormals());
  EXPECT_TRUE(f->GetSplitting());
  EXPECT_TRUE(f->GetConsistency());
  EXPECT_TRUE(f->GetNonManifoldTraversal());
  EXPECT_TRUE(f->GetTriangulateStrips());
  EXPECT_EQ(f->GetOutputPointsPrecision(), vtkAlgorithm::DEFAULT_PRECISION);
  EXPECT_FALSE(f->GetComputeAreaVectors());
  EXPECT_FALSE(f->GetComputeAreas());
  EXPECT_FALSE(f->GetComputeNormalStatus());
  EXPECT_TRUE(f->GetPieceInvariant());
  EXPECT_EQ(f->GetOutputPrecision(), vtkAlgorithm::SINGLE_PRECISION);
}

TEST(PolygonNormalsApi, ConstantsAreNumberedFastestFirst)
{
  EXPECT_EQ(vtkPolygonNormals::FAST, 0);
  EXPECT_EQ(vtkPolygonNormals::DOUBLE, 1);
  EXPECT_EQ(vtkPolygonNormals::COMPENSATED, 2);
  EXPECT_EQ(vtkPolygonNormals::EXACT, 3);
  EXPECT_EQ(vtkPolygonNormals::AREA, 0);
  EXPECT_EQ(vtkPolygonNormals::ANGLE, 1);
  EXPECT_EQ(vtkPolygonNormals::UNIFORM, 2);
  EXPECT_EQ(vtkPolygonNormals::MAX, 3);
}

TEST(PolygonNormalsApi, AccuracySettersAndNames)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  f->SetAccuracyToFast();
  EXPECT_EQ(f->GetAccuracy(), vtkPolygonNormals::FAST);
  EXPECT_STREQ(f->GetAccuracyAsString(), "FAST");
  f->SetAccuracyToCompensated();
  EXPECT_EQ(f->GetAccuracy(), vtkPolygonNormals::COMPENSATED);
  EXPECT_STREQ(f->GetAccuracyAsString(), "COMPENSATED");
  f->SetAccuracyToExact();
  EXPECT_EQ(f->GetAccuracy(), vtkPolygonNormals::EXACT);
  EXPECT_STREQ(f->GetAccuracyAsString(), "EXACT");
  f->SetAccuracyToDouble();
  EXPECT_EQ(f->GetAccuracy(), vtkPolygonNormals::DOUBLE);
  EXPECT_STREQ(f->GetAccuracyAsString(), "DOUBLE");
}

TEST(PolygonNormalsApi, PointWeightingSettersAndNames)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  f->SetPointWeightingToAngle();
  EXPECT_EQ(f->GetPointWeighting(), vtkPolygonNormals::ANGLE);
  EXPECT_STREQ(f->GetPointWeightingAsString(), "ANGLE");
  f->SetPointWeightingToUniform();
  EXPECT_EQ(f->GetPointWeighting(), vtkPolygonNormals::UNIFORM);
  EXPECT_STREQ(f->GetPointWeightingAsString(), "UNIFORM");
  f->SetPointWeightingToMax();
  EXPECT_EQ(f->GetPointWeighting(), vtkPolygonNormals::MAX);
  EXPECT_STREQ(f->GetPointWeightingAsString(), "MAX");
  f->SetPointWeightingToArea();
  EXPECT_EQ(f->GetPointWeighting(), vtkPolygonNormals::AREA);
  EXPECT_STREQ(f->GetPointWeightingAsString(), "AREA");
}

TEST(PolygonNormalsApi, UnknownOptionValuesAreErrorsAndChangeNothing)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  vtkNew<phongvtk_test::MessageObserver> messages;
  messages->Watch(f);
  f->SetAccuracyToCompensated();
  f->SetPointWeightingToMax();
  f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  const vtkMTimeType before = f->GetMTime();
  f->SetAccuracy(-4);
  f->SetAccuracy(99);
  f->SetPointWeighting(-1);
  f->SetPointWeighting(4);
  f->SetOutputPrecision(-3);
  f->SetOutputPrecision(7);
  EXPECT_EQ(f->GetAccuracy(), vtkPolygonNormals::COMPENSATED);
  EXPECT_EQ(f->GetPointWeighting(), vtkPolygonNormals::MAX);
  EXPECT_EQ(f->GetOutputPrecision(), vtkAlgorithm::DOUBLE_PRECISION);
  EXPECT_EQ(f->GetMTime(), before);
  ASSERT_EQ(messages->Errors.size(), 6u);
  EXPECT_NE(messages->Errors[1].find("Unknown accuracy 99: expected FAST (0), DOUBLE (1), "
                                     "COMPENSATED (2) or EXACT (3); keeping COMPENSATED."),
    std::string::npos)
    << messages->Errors[1];
  EXPECT_NE(messages->Errors[2].find("Unknown point weighting -1"), std::string::npos);
  EXPECT_NE(messages->Errors[5].find("Unknown output precision 7"), std::string::npos);
}

TEST(PolygonNormalsApi, BooleanMacrosSwitchEachOutput)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  f->ComputeCellNormalsOff();
  f->ComputePointNormalsOn();
  f->ComputeAreaVectorsOn();
  f->ComputeAreasOn();
  f->ComputeNormalStatusOn();
  EXPECT_FALSE(f->GetComputeCellNormals());
  EXPECT_TRUE(f->GetComputePointNormals());
  EXPECT_TRUE(f->GetComputeAreaVectors());
  EXPECT_TRUE(f->GetComputeAreas());
  EXPECT_TRUE(f->GetComputeNormalStatus());
}

TEST(PolygonNormalsApi, SettersMarkTheFilterModified)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  vtkMTimeType t = f->GetMTime();
  f->SetAccuracyToExact();
  EXPECT_GT(f->GetMTime(), t);
  t = f->GetMTime();
  f->ComputePointNormalsOn();
  EXPECT_GT(f->GetMTime(), t);
}

TEST(PolygonNormalsApi, PrintSelfMentionsEveryMember)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  f->SetAccuracyToExact();
  f->SetPointWeightingToMax();
  f->ComputeAreasOn();
  f->AutoOrientNormalsOn();
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  std::ostringstream os;
  f->PrintSelf(os, vtkIndent());
  const std::string text = os.str();
  for (const char* member : { "Accuracy: EXACT", "PointWeighting: MAX", "ComputeCellNormals: On",
         "ComputePointNormals: Off", "ComputeAreaVectors: Off", "ComputeAreas: On",
         "ComputeNormalStatus: Off", "PieceInvariant: On", "Consistency: Off",
         "AutoOrientNormals: On", "NonManifoldTraversal: Off", "FlipNormals: Off", "Splitting: Off",
         "FeatureAngle: 30", "ComputeOriginalPointIds: On", "OutputPrecision: SINGLE_PRECISION",
         "TriangulateStrips: Off", "OutputPointsPrecision: DOUBLE_PRECISION" })
  {
    EXPECT_NE(text.find(member), std::string::npos) << "PrintSelf lacks '" << member << "'";
  }
}

//==============================================================================
// Compute only what was asked for; names and types of the outputs.

namespace
{
/// Two triangles and a quad, double points.
vtkSmartPointer<vtkPolyData> SmallMesh(int pointType = VTK_DOUBLE)
{
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 4, 5, 2 } };
  return MakePolyData(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.25 }, { 0, 1, 0 }, { 2, 0, 1 }, { 2, 1, 1 } }, cells,
    pointType);
}
} // namespace

TEST(PolygonNormalsOutputs, ByDefaultOnlyCellNormals)
{
  auto out = RunFilter(SmallMesh());
  vtkCellData* cd = out->GetCellData();
  ASSERT_EQ(cd->GetNumberOfArrays(), 1);
  EXPECT_STREQ(cd->GetArray(0)->GetName(), "Normals");
  EXPECT_EQ(cd->GetNormals(), cd->GetArray("Normals"));
  EXPECT_EQ(cd->GetArray("Normals")->GetNumberOfComponents(), 3);
  EXPECT_EQ(cd->GetArray("Normals")->GetNumberOfTuples(), 3);
  EXPECT_EQ(out->GetPointData()->GetNumberOfArrays(), 0);
  EXPECT_EQ(out->GetPointData()->GetNormals(), nullptr);
}

TEST(PolygonNormalsOutputs, EveryOutputWhenAskedNamedAsDocumented)
{
  auto out = RunFilter(SmallMesh(),
    [](vtkPolygonNormals* f)
    {
      f->ComputePointNormalsOn();
      f->ComputeAreaVectorsOn();
      f->ComputeAreasOn();
      f->ComputeNormalStatusOn();
    });
  vtkCellData* cd = out->GetCellData();
  EXPECT_EQ(cd->GetNumberOfArrays(), 4);
  ASSERT_NE(cd->GetArray("Normals"), nullptr);
  EXPECT_EQ(cd->GetNormals(), cd->GetArray("Normals"));
  ASSERT_NE(cd->GetArray("AreaVectors"), nullptr);
  EXPECT_EQ(cd->GetArray("AreaVectors")->GetNumberOfComponents(), 3);
  ASSERT_NE(cd->GetArray("Areas"), nullptr);
  EXPECT_EQ(cd->GetArray("Areas")->GetNumberOfComponents(), 1);
  ASSERT_NE(cd->GetArray("NormalStatus"), nullptr);
  EXPECT_EQ(cd->GetArray("NormalStatus")->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(cd->GetArray("NormalStatus")->GetNumberOfComponents(), 1);
  for (const char* name : { "Normals", "AreaVectors", "Areas", "NormalStatus" })
  {
    EXPECT_EQ(cd->GetArray(name)->GetNumberOfTuples(), 3) << name;
  }
  vtkPointData* pd = out->GetPointData();
  EXPECT_EQ(pd->GetNumberOfArrays(), 1);
  ASSERT_NE(pd->GetNormals(), nullptr);
  EXPECT_STREQ(pd->GetNormals()->GetName(), "Normals");
  EXPECT_EQ(pd->GetNormals()->GetNumberOfTuples(), 6);
}

TEST(PolygonNormalsOutputs, EachOptionalArrayAlone)
{
  using Setter = void (vtkPolygonNormals::*)();
  const std::pair<Setter, const char*> options[] = {
    { &vtkPolygonNormals::ComputeAreaVectorsOn, "AreaVectors" },
    { &vtkPolygonNormals::ComputeAreasOn, "Areas" },
    { &vtkPolygonNormals::ComputeNormalStatusOn, "NormalStatus" },
  };
  for (const auto& option : options)
  {
    auto out = RunFilter(SmallMesh(),
      [&](vtkPolygonNormals* f)
      {
        f->ComputeCellNormalsOff();
        (f->*option.first)();
      });
    vtkCellData* cd = out->GetCellData();
    ASSERT_EQ(cd->GetNumberOfArrays(), 1) << option.second;
    EXPECT_STREQ(cd->GetArray(0)->GetName(), option.second);
    EXPECT_EQ(cd->GetNormals(), nullptr) << option.second;
    EXPECT_EQ(out->GetPointData()->GetNumberOfArrays(), 0) << option.second;
  }
}

TEST(PolygonNormalsOutputs, PointNormalsAloneAreTheActivePointNormals)
{
  auto out = RunFilter(SmallMesh(),
    [](vtkPolygonNormals* f)
    {
      f->ComputeCellNormalsOff();
      f->ComputePointNormalsOn();
    });
  EXPECT_EQ(out->GetCellData()->GetNumberOfArrays(), 0);
  ASSERT_EQ(out->GetPointData()->GetNumberOfArrays(), 1);
  EXPECT_EQ(out->GetPointData()->GetNormals(), out->GetPointData()->GetArray("Normals"));
}

TEST(PolygonNormalsOutputs, SinglePrecisionByDefault)
{
  auto out = RunFilter(SmallMesh(VTK_DOUBLE),
    [](vtkPolygonNormals* f)
    {
      f->ComputePointNormalsOn();
      f->ComputeAreaVectorsOn();
      f->ComputeAreasOn();
    });
  for (const char* name : { "Normals", "AreaVectors", "Areas" })
  {
    EXPECT_EQ(out->GetCellData()->GetArray(name)->GetDataType(), VTK_FLOAT) << name;
  }
  EXPECT_EQ(out->GetPointData()->GetNormals()->GetDataType(), VTK_FLOAT);
}

TEST(PolygonNormalsOutputs, DoublePrecisionOnRequest)
{
  auto out = RunFilter(SmallMesh(VTK_FLOAT),
    [](vtkPolygonNormals* f)
    {
      f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      f->ComputePointNormalsOn();
      f->ComputeAreaVectorsOn();
      f->ComputeAreasOn();
    });
  for (const char* name : { "Normals", "AreaVectors", "Areas" })
  {
    EXPECT_EQ(out->GetCellData()->GetArray(name)->GetDataType(), VTK_DOUBLE) << name;
  }
  EXPECT_EQ(out->GetPointData()->GetNormals()->GetDataType(), VTK_DOUBLE);
}

TEST(PolygonNormalsOutputs, DefaultPrecisionFollowsThePoints)
{
  for (int pointType : { VTK_FLOAT, VTK_DOUBLE })
  {
    auto out = RunFilter(SmallMesh(pointType),
      [](vtkPolygonNormals* f)
      {
        f->SetOutputPrecision(vtkAlgorithm::DEFAULT_PRECISION);
        f->ComputePointNormalsOn();
        f->ComputeAreaVectorsOn();
        f->ComputeAreasOn();
      });
    for (const char* name : { "Normals", "AreaVectors", "Areas" })
    {
      EXPECT_EQ(out->GetCellData()->GetArray(name)->GetDataType(), pointType) << name;
    }
    EXPECT_EQ(out->GetPointData()->GetNormals()->GetDataType(), pointType);
  }
}

TEST(PolygonNormalsOutputs, EmptyInputGivesEmptyOutputQuietly)
{
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  vtkNew<MessageObserver> messages;
  messages->Watch(f);
  f->SetInputData(empty);
  f->ComputePointNormalsOn();
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_TRUE(messages->Errors.empty());
  EXPECT_TRUE(messages->Warnings.empty());
}

//==============================================================================
// Pass-through

namespace
{
/// A mesh with every kind of cell and arrays of every association.
vtkSmartPointer<vtkPolyData> DecoratedMesh()
{
  Cells cells;
  cells.Verts = { { 0 }, { 1, 2 } };
  cells.Lines = { { 0, 1, 2 } };
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3, 4 } };
  cells.Strips = { { 0, 1, 3, 2, 4 } };
  auto mesh = MakePolyData(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0.5 }, { -1, 0.5, 0.25 } }, cells);
  const vtkIdType numCells = mesh->GetNumberOfCells();

  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("Temperature");
  for (vtkIdType i = 0; i < 5; ++i)
  {
    temperature->InsertNextValue(20.0 + static_cast<double>(i));
  }
  mesh->GetPointData()->SetScalars(temperature);
  vtkNew<vtkFloatArray> pointNormals;
  pointNormals->SetName("InputPointNormals");
  pointNormals->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < 5; ++i)
  {
    pointNormals->InsertNextTuple3(0, 0, 1);
  }
  mesh->GetPointData()->SetNormals(pointNormals);

  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  vtkNew<vtkDoubleArray> cellNormals;
  cellNormals->SetName("InputCellNormals");
  cellNormals->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < numCells; ++i)
  {
    material->InsertNextValue(static_cast<int>(100 + i));
    cellNormals->InsertNextTuple3(1, 0, 0);
  }
  mesh->GetCellData()->SetScalars(material);
  mesh->GetCellData()->SetNormals(cellNormals);

  vtkNew<vtkStringArray> author;
  author->SetName("Author");
  author->InsertNextValue("Stanford bunny's keeper");
  mesh->GetFieldData()->AddArray(author);
  return mesh;
}
} // namespace

TEST(PolygonNormalsPassThrough, PointsAndEveryCellUnchanged)
{
  auto input = DecoratedMesh();
  auto out = RunFilter(input, AllCellOutputs(vtkPolygonNormals::EXACT));
  ASSERT_EQ(out->GetNumberOfPoints(), input->GetNumberOfPoints());
  if (out->GetPoints() != input->GetPoints())
  {
    EXPECT_EQ(PointsOf(out), PointsOf(input));
  }
  EXPECT_EQ(out->GetNumberOfVerts(), input->GetNumberOfVerts());
  EXPECT_EQ(out->GetNumberOfLines(), input->GetNumberOfLines());
  EXPECT_EQ(out->GetNumberOfPolys(), input->GetNumberOfPolys());
  EXPECT_EQ(out->GetNumberOfStrips(), input->GetNumberOfStrips());
  ASSERT_EQ(out->GetNumberOfCells(), input->GetNumberOfCells());
  for (vtkIdType cell = 0; cell < input->GetNumberOfCells(); ++cell)
  {
    EXPECT_EQ(out->GetCellType(cell), input->GetCellType(cell)) << "cell " << cell;
    EXPECT_EQ(CellIds(out, cell), CellIds(input, cell)) << "cell " << cell;
  }
}

TEST(PolygonNormalsPassThrough, OtherArraysUnchangedWhenPointNormalsAreNotComputed)
{
  auto input = DecoratedMesh();
  auto out = RunFilter(input, AllCellOutputs(vtkPolygonNormals::DOUBLE));
  vtkPointData* pd = out->GetPointData();
  EXPECT_EQ(pd->GetScalars(), input->GetPointData()->GetScalars());
  EXPECT_EQ(pd->GetNormals(), input->GetPointData()->GetNormals())
    << "the input's point normals stay the active point normals";
  EXPECT_EQ(pd->GetNumberOfArrays(), 2);
  vtkCellData* cd = out->GetCellData();
  EXPECT_EQ(cd->GetScalars(), input->GetCellData()->GetScalars());
  EXPECT_EQ(cd->GetArray("Material"), input->GetCellData()->GetArray("Material"));
  EXPECT_EQ(cd->GetArray("InputCellNormals"), input->GetCellData()->GetArray("InputCellNormals"))
    << "a cell array of another name is not the filter's to remove";
  EXPECT_STREQ(cd->GetNormals()->GetName(), "Normals");
  EXPECT_EQ(cd->GetNumberOfArrays(), 6);
  ASSERT_NE(out->GetFieldData()->GetAbstractArray("Author"), nullptr);
  EXPECT_EQ(out->GetFieldData()->GetAbstractArray("Author"),
    input->GetFieldData()->GetAbstractArray("Author"));
  // The input itself is untouched.
  EXPECT_EQ(input->GetCellData()->GetNumberOfArrays(), 2);
  EXPECT_STREQ(input->GetCellData()->GetNormals()->GetName(), "InputCellNormals");
}

TEST(PolygonNormalsPassThrough, InputPointNormalsOfAnotherNameSurviveComputedPointNormals)
{
  auto input = DecoratedMesh();
  auto out = RunFilter(input, [](vtkPolygonNormals* f) { f->ComputePointNormalsOn(); });
  vtkPointData* pd = out->GetPointData();
  EXPECT_STREQ(pd->GetNormals()->GetName(), "Normals");
  EXPECT_EQ(pd->GetArray("InputPointNormals"), input->GetPointData()->GetNormals());
  EXPECT_EQ(pd->GetScalars(), input->GetPointData()->GetScalars());
}

TEST(PolygonNormalsPassThrough, InputCellNormalsPassWhenCellNormalsAreOff)
{
  auto input = DecoratedMesh();
  auto out = RunFilter(input,
    [](vtkPolygonNormals* f)
    {
      f->ComputeCellNormalsOff();
      f->ComputeAreasOn();
    });
  EXPECT_EQ(out->GetCellData()->GetNormals(), input->GetCellData()->GetNormals());
  EXPECT_EQ(out->GetCellData()->GetNumberOfArrays(), 3);
}

//==============================================================================
// Vertices, lines, polygons and strips together

TEST(PolygonNormalsCells, VerticesAndLinesAreNotSurfaces)
{
  Cells cells;
  cells.Verts = { { 0 }, { 0, 1, 2 } };          // a poly-vertex of three points
  cells.Lines = { { 0, 1 }, { 0, 1, 2, 3, 0 } }; // a closed polyline around a square
  auto input = MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, cells);
  auto out = RunFilter(input, AllCellOutputs(vtkPolygonNormals::DOUBLE));
  ASSERT_EQ(out->GetNumberOfCells(), 4);
  for (vtkIdType cell = 0; cell < 4; ++cell)
  {
    EXPECT_EQ(Status(out, cell), 3) << "cell " << cell;
    EXPECT_TRUE(IsZero(Tuple3(out->GetCellData()->GetNormals(), cell))) << "cell " << cell;
    EXPECT_TRUE(IsZero(Tuple3(out->GetCellData()->GetArray("AreaVectors"), cell)));
    EXPECT_EQ(out->GetCellData()->GetArray("Areas")->GetTuple1(cell), 0.0);
  }
}

TEST(PolygonNormalsCells, OutputFollowsVTKCellOrder)
{
  // Each surface cell faces a different axis, so a misplaced output is visible.
  Cells cells;
  cells.Strips = { { 4, 5, 6, 7 } };          // in the plane x = 2, facing +x
  cells.Polys = { { 0, 1, 2 }, { 0, 3, 1 } }; // facing +z, then +y
  cells.Lines = { { 0, 1 } };
  cells.Verts = { { 2 } };
  auto input = MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 2, 0, 0 },
                              { 2, 1, 0 }, { 2, 0, 1 }, { 2, 1, 1 } },
    cells);
  auto out = RunFilter(input, AllCellOutputs(vtkPolygonNormals::EXACT));
  ASSERT_EQ(out->GetNumberOfCells(), 5);
  const std::array<double, 3> expected[] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 },
    { 1, 0, 0 } };
  const int status[] = { 3, 3, 0, 0, 0 };
  for (vtkIdType cell = 0; cell < 5; ++cell)
  {
    EXPECT_EQ(Tuple3(out->GetCellData()->GetNormals(), cell), expected[cell]) << "cell " << cell;
    EXPECT_EQ(Status(out, cell), status[cell]) << "cell " << cell;
  }
  // The strip's triangles (4,5,6) and (6,5,7) have w = (1,0,0) each: area 1.
  EXPECT_EQ(out->GetCellData()->GetArray("Areas")->GetTuple1(4), 1.0);
}

TEST(PolygonNormalsCells, PolygonsBeforeARunOfTrianglesGetTheirNormals)
{
  // Triangles go four per SIMD register, other polygons one by one (EXACT completes those in
  // batches): a quad followed by a run of triangles that ends the input must get its normal.
  Cells cells;
  cells.Polys = { { 0, 1, 2, 3 }, { 0, 1, 2 }, { 0, 2, 3 }, { 1, 2, 3 }, { 0, 1, 3 } };
  auto input = MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.5 }, { 0, 1, 0.25 } }, cells);
  for (int mode : Modes)
  {
    for (bool onlyNormals : { true, false })
    {
      auto out = RunFilter(input,
        [mode, onlyNormals](vtkPolygonNormals* f)
        {
          f->SetAccuracy(mode);
          f->SetComputeAreas(!onlyNormals);
          f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        });
      vtkDataArray* normals = out->GetCellData()->GetNormals();
      ASSERT_NE(normals, nullptr);
      for (vtkIdType cell = 0; cell < 5; ++cell)
      {
        const auto exact = phongvtk_test::ReferenceNormal(ExactCellAreaVector(input, cell));
        const auto n = Tuple3(normals, cell);
        EXPECT_LE(phongvtk_test::AngleError(n.data(), exact),
          mode == vtkPolygonNormals::FAST ? 1e-6 : 1e-15)
          << ModeName(mode) << " cell " << cell << (onlyNormals ? " (normals only)" : "");
      }
    }
  }
}

TEST(PolygonNormalsCells, StripAreaVectorIsTheExactSumOfItsAlternatingTriangles)
{
  // A twisted, non-planar strip of 9 points with irregular coordinates.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Point> points;
  Cell strip;
  for (int k = 0; k < 9; ++k)
  {
    const double t = 0.4 * k;
    const double side = (k % 2 == 0) ? -1.0 : 1.0;
    points.push_back({ t + jitter(random), side * std::cos(t) + jitter(random),
      side * std::sin(t) + jitter(random) });
    strip.push_back(k);
  }
  Cells cells;
  cells.Strips = { strip };
  auto input = MakePolyData(points, cells);
  ExactAreaVector exact;
  for (const Cell& triangle : StripTriangles(strip))
  {
    const ExactAreaVector w = phongvtk_test::ComputeExactAreaVector(Gather(points, triangle));
    for (int c = 0; c < 3; ++c)
    {
      exact.W[c] += w.W[c];
    }
  }
  const auto normal = phongvtk_test::ReferenceNormal(exact);
  const mpf_class area(phongvtk_test::ReferenceLength(exact) / 2, phongvtk_test::ReferenceBits);
  for (int mode : Modes)
  {
    auto out = RunFilter(input, AllCellOutputs(mode));
    const auto n = Tuple3(out->GetCellData()->GetNormals(), 0);
    const auto av = Tuple3(out->GetCellData()->GetArray("AreaVectors"), 0);
    const double a = out->GetCellData()->GetArray("Areas")->GetTuple1(0);
    EXPECT_EQ(Status(out, 0), 0) << ModeName(mode);
    if (mode == vtkPolygonNormals::EXACT)
    {
      EXPECT_TRUE(phongvtk_test::NormalIsFaithful(n.data(), normal));
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_TRUE(phongvtk_test::IsFaithful(av[c], Half(exact.W[c]))) << c;
      }
      EXPECT_TRUE(phongvtk_test::IsFaithful(a, area));
    }
    else
    {
      const double tolerance = mode == vtkPolygonNormals::FAST ? 1e-5 : 1e-14;
      EXPECT_LE(phongvtk_test::AngleError(n.data(), normal), tolerance) << ModeName(mode);
      EXPECT_NEAR(a, area.get_d(), tolerance * area.get_d()) << ModeName(mode);
    }
  }
}

TEST(PolygonNormalsCells, StripWithRepeatedPointsKeepsTheSumOfItsTriangles)
{
  // Strips are often stitched with repeated points, i.e. zero-area triangles.
  Cells cells;
  cells.Strips = { { 0, 1, 2, 2, 3, 4 } };
  auto input =
    MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 2, 0, 0.5 } }, cells);
  auto out = RunFilter(input, AllCellOutputs(vtkPolygonNormals::EXACT));
  const ExactAreaVector exact = ExactCellAreaVector(input, 0);
  const auto normal = phongvtk_test::ReferenceNormal(exact);
  EXPECT_EQ(Status(out, 0), 0);
  EXPECT_TRUE(
    phongvtk_test::NormalIsFaithful(Tuple3(out->GetCellData()->GetNormals(), 0).data(), normal));
  EXPECT_TRUE(phongvtk_test::IsFaithful(out->GetCellData()->GetArray("Areas")->GetTuple1(0),
    mpf_class(phongvtk_test::ReferenceLength(exact) / 2, phongvtk_test::ReferenceBits)));
}

//==============================================================================
// Area vectors and areas against the exact reference

namespace
{
/// Polygons of every shape the issue lists: concave, star, twisted non-planar, needle,
/// far offset, repeated vertex, exactly zero area.
vtkSmartPointer<vtkPolyData> ShapeZoo()
{
  std::vector<Point> points;
  Cells cells;
  auto add = [&](const std::vector<Point>& polygon)
  {
    Cell cell;
    for (const Point& p : polygon)
    {
      cell.push_back(static_cast<vtkIdType>(points.size()));
      points.push_back(p);
    }
    cells.Polys.push_back(cell);
  };
  std::vector<Point> star, twisted;
  for (int k = 0; k < 10; ++k)
  {
    const double angle = 2.0 * M_PI * k / 10.0;
    const double radius = k % 2 == 0 ? 1.0 : 0.37;
    star.push_back({ radius * std::cos(angle), radius * std::sin(angle), 0.1 * radius });
    twisted.push_back({ std::cos(angle), std::sin(angle), k % 2 == 0 ? 0.3 : -0.3 });
  }
  add(star);
  add(twisted);
  add({ { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 1, 0.5, 0.1 }, { 0, 2, 0 } }); // concave
  add({ { 0, 0, 0 }, { 1, 1e-12, 0 }, { 2, 0, 1e-13 } });                       // needle
  add({ { 1e15, 1e15, 1e15 }, { 1e15 + 1, 1e15, 1e15 }, { 1e15, 1e15 + 2, 1e15 + 0.5 } });
  add({ { 0.1, 0.2, 0.3 }, { 0.4, 0.5, 0.6 }, { 0.4, 0.5, 0.6 }, { 0.7, 0.9, 0.8 } });
  add({ { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 } }); // collinear: exactly zero
  add({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0 } });
  add({ { 0.3, 0.1, 0.2 }, { 1.7, 0.2, 0.1 }, { 1.1, 1.9, 0.4 }, { 0.2, 1.3, 1.1 } });
  return MakePolyData(points, cells);
}
} // namespace

TEST(PolygonNormalsAreas, ExactAreaVectorsAndAreasAreFaithful)
{
  auto input = ShapeZoo();
  auto out = RunFilter(input, AllCellOutputs(vtkPolygonNormals::EXACT));
  vtkDataArray* areaVectors = out->GetCellData()->GetArray("AreaVectors");
  vtkDataArray* areas = out->GetCellData()->GetArray("Areas");
  for (vtkIdType cell = 0; cell < input->GetNumberOfCells(); ++cell)
  {
    const ExactAreaVector exact = ExactCellAreaVector(input, cell);
    const auto av = Tuple3(areaVectors, cell);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_TRUE(phongvtk_test::IsFaithful(av[c], Half(exact.W[c])))
        << "cell " << cell << " component " << c;
    }
    const mpf_class area(phongvtk_test::ReferenceLength(exact) / 2, phongvtk_test::ReferenceBits);
    EXPECT_TRUE(phongvtk_test::IsFaithful(areas->GetTuple1(cell), area)) << "cell " << cell;
    EXPECT_EQ(Status(out, cell), exact.IsZero() ? 1 : 0) << "cell " << cell;
  }
}

TEST(PolygonNormalsAreas, InexactModesMeetTheirDocumentedBounds)
{
  auto input = ShapeZoo();
  for (int mode :
    { vtkPolygonNormals::FAST, vtkPolygonNormals::DOUBLE, vtkPolygonNormals::COMPENSATED })
  {
    auto out = RunFilter(input, AllCellOutputs(mode));
    for (vtkIdType cell = 0; cell < input->GetNumberOfCells(); ++cell)
    {
      const ExactAreaVector exact = ExactCellAreaVector(input, cell);
      if (exact.IsZero())
      {
        EXPECT_EQ(Status(out, cell), 1) << ModeName(mode) << " cell " << cell;
        continue;
      }
      const auto n = Tuple3(out->GetCellData()->GetNormals(), cell);
      const double bound = AngleBound(CellPoints(input, cell), exact, mode);
      const double angle =
        phongvtk_test::AngleError(n.data(), phongvtk_test::ReferenceNormal(exact));
      EXPECT_LE(angle, bound) << ModeName(mode) << " cell " << cell;
      // AreaVectors = w/2 within half the documented bound on w.
      const auto av = Tuple3(out->GetCellData()->GetArray("AreaVectors"), cell);
      const auto bounds = ComponentBounds(CellPoints(input, cell), exact, mode);
      for (int c = 0; c < 3; ++c)
      {
        const mpf_class error(
          abs(mpf_class(av[c], phongvtk_test::ReferenceBits) - Half(exact.W[c])),
          phongvtk_test::ReferenceBits);
        EXPECT_LE(error.get_d(), static_cast<double>(bounds[c] / 2))
          << ModeName(mode) << " cell " << cell << " component " << c;
      }
      // |AreaVectors| is Areas up to the rounding of the output.
      const double a = out->GetCellData()->GetArray("Areas")->GetTuple1(cell);
      EXPECT_NEAR(std::sqrt(av[0] * av[0] + av[1] * av[1] + av[2] * av[2]), a, 1e-6 * a)
        << ModeName(mode) << " cell " << cell;
      EXPECT_GE(a, 0.0);
    }
  }
}

//==============================================================================
// Real meshes from CGAL's sample data

namespace
{
struct MeshMode
{
  const char* Mesh;
  int Mode;
};

/// Readable parameters in test logs and CTest names.
void PrintTo(const MeshMode& param, std::ostream* os)
{
  *os << param.Mesh << " " << ModeName(param.Mode);
}

std::string MeshModeName(const ::testing::TestParamInfo<MeshMode>& info)
{
  std::string name = info.param.Mesh;
  name = name.substr(0, name.find('.'));
  return name + "_" + ModeName(info.param.Mode);
}

std::vector<MeshMode> AllMeshModes()
{
  std::vector<MeshMode> all;
  for (const char* mesh : { "bunny00.off", "fandisk.off", "cube_poly.off", "degtri_sliding.off" })
  {
    for (int mode : Modes)
    {
      all.push_back({ mesh, mode });
    }
  }
  return all;
}
} // namespace

class PolygonNormalsRealMesh : public ::testing::TestWithParam<MeshMode>
{
};

TEST_P(PolygonNormalsRealMesh, CellNormalsAgainstTheExactReference)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  const MeshMode param = GetParam();
  const MeshReference* ref = CGALMesh(param.Mesh);
  ASSERT_NE(ref, nullptr);
  auto out = RunFilter(ref->Mesh, AllCellOutputs(param.Mode));
  vtkDataArray* normals = out->GetCellData()->GetNormals();
  const std::vector<Point> points = PointsOf(ref->Mesh);
  double worstUlp = 0.0, worstAngle = 0.0, worstRatio = 0.0;
  std::vector<double> angles;
  int failures = 0;
  for (vtkIdType cell = 0; cell < ref->Mesh->GetNumberOfCells() && failures < 10; ++cell)
  {
    const auto n = Tuple3(normals, cell);
    const auto& exact = ref->Normals[cell];
    ASSERT_TRUE(IsFinite(n)) << "cell " << cell;
    if (ref->W[cell].IsZero())
    {
      failures += !IsZero(n) || Status(out, cell) != 1;
      EXPECT_TRUE(IsZero(n)) << "cell " << cell << " has zero area";
      EXPECT_EQ(Status(out, cell), 1) << "cell " << cell << " has zero area";
      continue;
    }
    // ulps of double, except for FAST, whose float arithmetic is measured in float ulps.
    const double ulp = param.Mode == vtkPolygonNormals::FAST
      ? phongvtk_test::NormalUlpError<float>(n.data(), exact)
      : phongvtk_test::NormalUlpError<double>(n.data(), exact);
    const double angle = phongvtk_test::AngleError(n.data(), exact);
    worstUlp = std::max(worstUlp, ulp);
    worstAngle = std::max(worstAngle, angle);
    angles.push_back(angle);
    if (param.Mode == vtkPolygonNormals::EXACT)
    {
      failures += ulp > 1.0 || Status(out, cell) != 0;
      EXPECT_LE(ulp, 1.0) << "cell " << cell;
      EXPECT_EQ(Status(out, cell), 0) << "cell " << cell;
    }
    else
    {
      const double bound =
        AngleBound(Gather(points, CellIds(ref->Mesh, cell)), ref->W[cell], param.Mode);
      worstRatio = std::max(worstRatio, angle / bound);
      failures += angle > bound;
      EXPECT_LE(angle, bound) << "cell " << cell;
    }
  }
  std::sort(angles.begin(), angles.end());
  const double median = angles.empty() ? 0.0 : angles[angles.size() / 2];
  std::cout << "[ measured ] " << param.Mesh << " " << ModeName(param.Mode) << ": worst ulp "
            << worstUlp << ", worst angle " << worstAngle << " rad, median angle " << median
            << " rad, worst angle/bound " << worstRatio << "\n";
  RecordProperty("worst_ulp", std::to_string(worstUlp));
  RecordProperty("worst_angle_rad", std::to_string(worstAngle));
  // Sanity of the whole ladder on well-shaped meshes, beyond the per-cell bounds.
  const double sane = param.Mode == vtkPolygonNormals::FAST ? 1e-5 : 1e-12;
  EXPECT_LE(worstAngle, sane);
}

INSTANTIATE_TEST_SUITE_P(
  CGAL, PolygonNormalsRealMesh, ::testing::ValuesIn(AllMeshModes()), MeshModeName);

namespace
{
/// Status 1, zero normal and zero area exactly for the cells whose exact area vector is zero.
int ExpectZeroExactlyWhenExactlyZero(const char* name, int mode)
{
  const MeshReference* ref = CGALMesh(name);
  EXPECT_NE(ref, nullptr);
  if (!ref)
  {
    return 0;
  }
  auto out = RunFilter(ref->Mesh, AllCellOutputs(mode));
  int degenerate = 0;
  int wrong = 0;
  for (vtkIdType cell = 0; cell < ref->Mesh->GetNumberOfCells() && wrong < 10; ++cell)
  {
    const bool zero = ref->W[cell].IsZero();
    degenerate += zero;
    const bool ok = Status(out, cell) == (zero ? 1 : 0) &&
      IsZero(Tuple3(out->GetCellData()->GetNormals(), cell)) == zero &&
      (out->GetCellData()->GetArray("Areas")->GetTuple1(cell) == 0.0) == zero;
    wrong += !ok;
    EXPECT_TRUE(ok) << name << " " << ModeName(mode) << " cell " << cell << ": exact area vector "
                    << (zero ? "zero" : "non-zero") << ", status " << Status(out, cell);
  }
  return degenerate;
}
} // namespace

TEST(PolygonNormalsRealMeshes, ExactModeGivesZeroExactlyForZeroArea)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  for (const char* mesh : { "bunny00.off", "fandisk.off", "cube_poly.off", "degtri_sliding.off" })
  {
    ExpectZeroExactlyWhenExactlyZero(mesh, vtkPolygonNormals::EXACT);
  }
}

TEST(PolygonNormalsRealMeshes, DegenerateTrianglesOfDegtriSlidingInEveryMode)
{
  // Small integer coordinates: every mode computes these area vectors exactly.
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  for (int mode : Modes)
  {
    EXPECT_EQ(ExpectZeroExactlyWhenExactlyZero("degtri_sliding.off", mode), 4)
      << "degtri_sliding has four flat triangles";
  }
}

TEST(PolygonNormalsRealMeshes, ExactFloatOutputIsWithinOneFloatUlp)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  const MeshReference* ref = CGALMesh("fandisk.off");
  ASSERT_NE(ref, nullptr);
  auto out = RunFilter(ref->Mesh, [](vtkPolygonNormals* f) { f->SetAccuracyToExact(); });
  vtkDataArray* normals = out->GetCellData()->GetNormals();
  ASSERT_EQ(normals->GetDataType(), VTK_FLOAT);
  double worst = 0.0;
  for (vtkIdType cell = 0; cell < ref->Mesh->GetNumberOfCells(); ++cell)
  {
    worst = std::max(worst,
      phongvtk_test::NormalUlpError<float>(Tuple3(normals, cell).data(), ref->Normals[cell]));
  }
  EXPECT_LE(worst, 1.0);
}

TEST(PolygonNormalsRealMeshes, AreaPointNormalsOfTheBunny)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  const MeshReference* ref = CGALMesh("bunny00.off");
  ASSERT_NE(ref, nullptr);
  const auto reference = ReferencePointNormals(ref->Mesh, vtkPolygonNormals::AREA);
  for (int mode : { vtkPolygonNormals::DOUBLE, vtkPolygonNormals::EXACT })
  {
    auto out = RunFilter(ref->Mesh,
      [mode](vtkPolygonNormals* f)
      {
        f->SetAccuracy(mode);
        f->ComputePointNormalsOn();
        f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      });
    const long double worst = WorstPointNormalAngle(out, reference, ModeName(mode));
    std::cout << "[ measured ] bunny00 AREA point normals " << ModeName(mode) << ": worst angle "
              << static_cast<double>(worst) << " rad\n";
    EXPECT_LE(worst, 1e-14L) << ModeName(mode);
  }
}

//==============================================================================
// Bad input

namespace
{
struct BadRun
{
  vtkSmartPointer<vtkPolyData> Output;
  std::vector<std::string> Errors, Warnings;
  bool Updated = false; // what the executive's Update() returned
};

BadRun RunWatched(vtkPolyData* input, const std::function<void(vtkPolygonNormals*)>& configure)
{
  vtkNew<vtkPolygonNormals> f;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  vtkNew<MessageObserver> messages;
  messages->Watch(f);
  configure(f);
  f->SetInputData(input);
  BadRun run;
  run.Updated = f->GetExecutive()->Update() != 0;
  run.Output = vtkSmartPointer<vtkPolyData>::New();
  run.Output->ShallowCopy(f->GetOutput());
  run.Errors = messages->Errors;
  run.Warnings = messages->Warnings;
  return run;
}

void ExpectRejected(vtkPolyData* input, vtkIdType firstBadCell, const std::string& what)
{
  // Cell outputs, cell and point outputs, point normals alone (no cell pass to find it).
  for (int outputs : { 0, 1, 2 })
  {
    BadRun run = RunWatched(input,
      [outputs](vtkPolygonNormals* f)
      {
        f->SetComputePointNormals(outputs > 0);
        f->SetComputeCellNormals(outputs < 2);
        f->SetComputeNormalStatus(outputs < 2);
      });
    ASSERT_EQ(run.Errors.size(), 1u) << what;
    const std::string message = Lower(run.Errors[0]);
    EXPECT_NE(message.find("cell " + std::to_string(firstBadCell) + " "), std::string::npos)
      << what << ": the error should name cell " << firstBadCell << ": " << run.Errors[0];
    EXPECT_FALSE(run.Updated) << what << ": the update should fail";
    EXPECT_EQ(run.Output->GetNumberOfPoints(), 0) << what;
    EXPECT_EQ(run.Output->GetNumberOfCells(), 0) << what;
    EXPECT_EQ(run.Output->GetCellData()->GetNumberOfArrays(), 0) << what;
    EXPECT_EQ(run.Output->GetPointData()->GetNumberOfArrays(), 0) << what;
  }
}

const std::vector<Point> FourPoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
} // namespace

TEST(PolygonNormalsBadInput, PolygonIdBeyondThePointsIsAnErrorNamingTheCell)
{
  Cells cells;
  cells.Verts = { { 0 } };
  cells.Lines = { { 0, 1 } };
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 4 } }; // cell 3
  ExpectRejected(MakePolyData(FourPoints, cells), 3, "polygon");
}

TEST(PolygonNormalsBadInput, NegativeIdInAStripIsAnError)
{
  Cells cells;
  cells.Polys = { { 0, 1, 2 } };
  cells.Strips = { { 0, 1, 2, 3 }, { 0, 1, -1, 3 } }; // cell 2
  ExpectRejected(MakePolyData(FourPoints, cells), 2, "strip");
}

TEST(PolygonNormalsBadInput, BadIdInALineOrVertexIsAnError)
{
  Cells cells;
  cells.Verts = { { 0 }, { 1 } };
  cells.Lines = { { 0, 1 }, { 2, 9 } }; // cell 3
  cells.Polys = { { 0, 1, 2 } };
  ExpectRejected(MakePolyData(FourPoints, cells), 3, "line");
  cells.Verts = { { 0 }, { 4 } }; // now cell 1 comes first
  ExpectRejected(MakePolyData(FourPoints, cells), 1, "vertex");
}

TEST(PolygonNormalsBadInput, TheFirstBadCellIsNamedWhateverTheThreads)
{
  // 200,000 triangles with bad ids at 150,001 and 100,003 (and a later strip).
  std::vector<Point> points;
  Cells cells;
  for (int k = 0; k < 200000; ++k)
  {
    points.push_back({ static_cast<double>(k), 0.0, 0.0 });
  }
  for (vtkIdType k = 0; k < 200000; ++k)
  {
    cells.Polys.push_back({ k, (k + 1) % 200000, (k + 7) % 200000 });
  }
  cells.Polys[150001][1] = 200000;
  cells.Polys[100003][2] = -5;
  cells.Strips = { { 0, 1, 2, 300000 } };
  auto input = MakePolyData(points, cells);
  const std::string backend = vtkSMPTools::GetBackend();
  if (vtkSMPTools::SetBackend("STDThread"))
  {
    vtkSMPTools::Initialize(2);
  }
  ExpectRejected(input, 100003, "large mesh");
  vtkSMPTools::SetBackend(backend.c_str());
}

TEST(PolygonNormalsBadInput, NonFiniteCoordinatesFlagTheirCellsWithOneWarning)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Point> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { nan, 0, 0 },
    { 2, -inf, 0 }, { 2, 2, 0.5 }, { 3, 3, inf } };
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 4, 2 }, { 2, 5, 6 }, { 1, 6, 2 },
    { 0, 1, 6, 2, 3 } };
  cells.Strips = { { 0, 1, 3, 2 }, { 2, 6, 3, 7 } };
  auto input = MakePolyData(points, cells);
  const bool flagged[] = { false, false, true, true, false, false, false, true };
  for (int mode : Modes)
  {
    BadRun run = RunWatched(input,
      [mode](vtkPolygonNormals* f)
      {
        AllCellOutputs(mode)(f);
        f->ComputePointNormalsOn();
      });
    EXPECT_TRUE(run.Errors.empty()) << ModeName(mode);
    ASSERT_EQ(run.Warnings.size(), 1u) << ModeName(mode);
    EXPECT_TRUE(std::regex_search(run.Warnings[0], std::regex("(^|[^0-9])3([^0-9]|$)")))
      << "the warning should give the count 3: " << run.Warnings[0];
    vtkDataArray* normals = run.Output->GetCellData()->GetNormals();
    ASSERT_NE(normals, nullptr);
    for (vtkIdType cell = 0; cell < 8; ++cell)
    {
      const auto n = Tuple3(normals, cell);
      EXPECT_TRUE(IsFinite(n)) << ModeName(mode) << " cell " << cell;
      EXPECT_TRUE(IsFinite(Tuple3(run.Output->GetCellData()->GetArray("AreaVectors"), cell)));
      EXPECT_TRUE(std::isfinite(run.Output->GetCellData()->GetArray("Areas")->GetTuple1(cell)));
      if (flagged[cell])
      {
        EXPECT_EQ(Status(run.Output, cell), 2) << ModeName(mode) << " cell " << cell;
        EXPECT_TRUE(IsZero(n)) << ModeName(mode) << " cell " << cell;
        continue;
      }
      EXPECT_EQ(Status(run.Output, cell), 0) << ModeName(mode) << " cell " << cell;
      const auto exact = phongvtk_test::ReferenceNormal(ExactCellAreaVector(input, cell));
      const double tolerance = mode == vtkPolygonNormals::FAST ? 1e-6 : 1e-15;
      EXPECT_LE(phongvtk_test::AngleError(n.data(), exact), tolerance)
        << ModeName(mode) << " cell " << cell;
      if (mode == vtkPolygonNormals::EXACT)
      {
        EXPECT_TRUE(phongvtk_test::NormalIsFaithful(n.data(), exact)) << cell;
      }
    }
    // Point normals: finite everywhere, zero where every face is flagged (points 4, 5, 7).
    vtkDataArray* pointNormals = run.Output->GetPointData()->GetNormals();
    ASSERT_NE(pointNormals, nullptr);
    for (vtkIdType p = 0; p < 8; ++p)
    {
      const auto n = Tuple3(pointNormals, p);
      EXPECT_TRUE(IsFinite(n)) << ModeName(mode) << " point " << p;
      EXPECT_EQ(IsZero(n), p == 4 || p == 5 || p == 7) << ModeName(mode) << " point " << p;
    }
  }
}

TEST(PolygonNormalsBadInput, NonFiniteCoordinatesAreCountedWhenOnlyPointNormalsAreAsked)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Point> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { nan, 0, 0 } };
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 4, 2 }, { 4, 3, 2 } };
  auto input = MakePolyData(points, cells);
  for (int mode : Modes)
  {
    BadRun run = RunWatched(input,
      [mode](vtkPolygonNormals* f)
      {
        f->SetAccuracy(mode);
        f->ComputeCellNormalsOff();
        f->ComputePointNormalsOn();
      });
    EXPECT_TRUE(run.Errors.empty()) << ModeName(mode);
    ASSERT_EQ(run.Warnings.size(), 1u) << ModeName(mode);
    EXPECT_TRUE(std::regex_search(run.Warnings[0], std::regex("(^|[^0-9])2([^0-9]|$)")))
      << "the warning should give the count 2: " << run.Warnings[0];
    vtkDataArray* normals = run.Output->GetPointData()->GetNormals();
    ASSERT_NE(normals, nullptr);
    for (vtkIdType p = 0; p < 5; ++p)
    {
      const auto n = Tuple3(normals, p);
      EXPECT_TRUE(IsFinite(n)) << ModeName(mode) << " point " << p;
      EXPECT_EQ(IsZero(n), p == 4) << ModeName(mode) << " point " << p;
      if (p != 4)
      {
        EXPECT_NEAR(n[2], 1.0, 1e-7) << ModeName(mode) << " point " << p;
      }
    }
  }
}

TEST(PolygonNormalsBadInput, CellsWithoutPointsAreAnError)
{
  vtkNew<vtkPolyData> input;
  input->SetPolys(MakeCellArray({ { 0, 1, 2 } }));
  BadRun run = RunWatched(input, [](vtkPolygonNormals*) {});
  EXPECT_EQ(run.Errors.size(), 1u);
  EXPECT_EQ(run.Output->GetNumberOfCells(), 0);
}

//==============================================================================
// Point normals

namespace
{
/**
 * A corner of four triangles at the origin O, chosen so that the four weightings disagree:
 * F1 (O,B,A) in x = 0, w = (-6,0,0), corner angle pi/2;  F2 (O,C,B) in y = 0, w = (0,-2,0), pi/2;
 * F3 (O,A,D) and F4 (O,D,C) in z = 0, w = (0,0,-6) and (0,0,-2), pi/4 each;
 * A = (0,3,0), B = (0,0,2), C = (1,0,0), D = (2,2,0). Point 5 belongs to no face.
 */
vtkSmartPointer<vtkPolyData> Corner()
{
  Cells cells;
  cells.Polys = { { 0, 2, 1 }, { 0, 3, 2 }, { 0, 1, 4 }, { 0, 4, 3 } };
  cells.Verts = { { 5 } };
  return MakePolyData(
    { { 0, 0, 0 }, { 0, 3, 0 }, { 0, 0, 2 }, { 1, 0, 0 }, { 2, 2, 0 }, { 5, 5, 5 } }, cells);
}

std::array<double, 3> PointNormal(
  vtkPolyData* input, int weighting, vtkIdType point, int mode = vtkPolygonNormals::DOUBLE)
{
  auto out = RunFilter(input,
    [weighting, mode](vtkPolygonNormals* f)
    {
      f->SetAccuracy(mode);
      f->ComputePointNormalsOn();
      f->SetPointWeighting(weighting);
      f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    });
  return Tuple3(out->GetPointData()->GetNormals(), point);
}

void ExpectDirection(const std::array<double, 3>& n, Vec3L expected, const std::string& what)
{
  expected = Normalized(expected);
  EXPECT_LE(AngleTo(n, expected), 1e-15L) << what;
  EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 4e-16) << what;
}
} // namespace

TEST(PolygonNormalsPointNormals, AreaWeightingSumsTheAreaVectors)
{
  // (-6,0,0) + (0,-2,0) + (0,0,-6) + (0,0,-2)
  ExpectDirection(PointNormal(Corner(), vtkPolygonNormals::AREA, 0), { -3, -1, -4 }, "AREA");
}

TEST(PolygonNormalsPointNormals, UniformWeightingSumsUnitNormals)
{
  ExpectDirection(PointNormal(Corner(), vtkPolygonNormals::UNIFORM, 0), { -1, -1, -2 }, "UNIFORM");
}

TEST(PolygonNormalsPointNormals, AngleWeightingIsThuermerWuethrich)
{
  // pi/2 (-1,0,0) + pi/2 (0,-1,0) + pi/4 (0,0,-1) + pi/4 (0,0,-1)
  ExpectDirection(PointNormal(Corner(), vtkPolygonNormals::ANGLE, 0), { -1, -1, -1 }, "ANGLE");
}

TEST(PolygonNormalsPointNormals, MaxWeightingIsNelsonMax1999)
{
  // F1: B x A / (|B|^2 |A|^2) = (-6,0,0)/36; F2: C x B / (1 * 4) = (0,-2,0)/4;
  // F3: A x D / (9 * 8) = (0,0,-6)/72; F4: D x C / (8 * 1) = (0,0,-2)/8. Sum = -(1,3,2)/6.
  ExpectDirection(PointNormal(Corner(), vtkPolygonNormals::MAX, 0), { -1, -3, -2 }, "MAX");
}

TEST(PolygonNormalsPointNormals, PointsWithoutFacesGetZero)
{
  for (int weighting : Weightings)
  {
    EXPECT_TRUE(IsZero(PointNormal(Corner(), weighting, 5))) << WeightingName(weighting);
  }
}

TEST(PolygonNormalsPointNormals, TinyFeaturesBesideLargeOnesKeepTheirDirection)
{
  // The corner shrunk by 2^-300 and 2^-600 next to an ordinary triangle at x = 10: every
  // weighting is invariant under a uniform scaling of the corner, so point 0 must keep the
  // corner's direction, whatever the scale of the rest of the mesh.
  const std::pair<int, Vec3L> expected[] = { { vtkPolygonNormals::AREA, { -3, -1, -4 } },
    { vtkPolygonNormals::UNIFORM, { -1, -1, -2 } }, { vtkPolygonNormals::ANGLE, { -1, -1, -1 } },
    { vtkPolygonNormals::MAX, { -1, -3, -2 } } };
  for (int exponent : { -300, -600, -1000 })
  {
    std::vector<Point> points = { { 0, 0, 0 }, { 0, 3, 0 }, { 0, 0, 2 }, { 1, 0, 0 }, { 2, 2, 0 } };
    for (Point& p : points)
    {
      for (double& x : p)
      {
        x = std::ldexp(x, exponent);
      }
    }
    points.push_back({ 10, 0, 0 });
    points.push_back({ 11, 0, 0 });
    points.push_back({ 10, 1, 0 });
    Cells cells;
    cells.Polys = { { 0, 2, 1 }, { 0, 3, 2 }, { 0, 1, 4 }, { 0, 4, 3 }, { 5, 6, 7 } };
    auto mesh = MakePolyData(points, cells);
    for (const auto& e : expected)
    {
      for (int mode : Modes)
      {
        if (mode == vtkPolygonNormals::FAST && exponent < -120)
        {
          continue; // float differences of 2^-600 coordinates are beyond FAST's promise
        }
        ExpectDirection(PointNormal(mesh, e.first, 0, mode), e.second,
          std::string(WeightingName(e.first)) + " " + ModeName(mode) + " at 2^" +
            std::to_string(exponent));
      }
    }
  }
}

TEST(PolygonNormalsPointNormals, EveryWeightingAgreesWhereSymmetryDecides)
{
  // Regular octahedron: at every vertex the four faces are congruent, so the normal is the
  // vertex's direction whatever the weighting.
  const std::vector<Point> points = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };
  Cells cells;
  cells.Polys = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 },
    { 3, 1, 5 }, { 0, 3, 5 } };
  auto input = MakePolyData(points, cells);
  for (int weighting : Weightings)
  {
    for (vtkIdType p = 0; p < 6; ++p)
    {
      const Point& q = points[static_cast<std::size_t>(p)];
      EXPECT_EQ(PointNormal(input, weighting, p), (std::array<double, 3>{ q[0], q[1], q[2] }))
        << WeightingName(weighting) << " point " << p;
    }
  }
}

TEST(PolygonNormalsPointNormals, MaxWeightingIsExactOnAnInscribedPolyhedron)
{
  // Max (1999): for a vertex whose neighbours lie on a sphere through it, his weights give the
  // sphere's normal exactly. Points on the unit sphere (radial jitter removed), irregular; the
  // jitter stays below the spacing near the poles, so that no triangle folds over.
  auto mesh = JitteredSphere(24, 0.003);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double& x : p)
    {
      x /= r;
    }
    mesh->GetPoints()->SetPoint(i, p);
  }
  long double worst[4] = { 0, 0, 0, 0 };
  for (int weighting : Weightings)
  {
    auto out = RunFilter(mesh,
      [weighting](vtkPolygonNormals* f)
      {
        f->ComputePointNormalsOn();
        f->SetPointWeighting(weighting);
        f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      });
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double p[3];
      mesh->GetPoint(i, p);
      worst[weighting] = std::max(worst[weighting],
        AngleTo(Tuple3(out->GetPointData()->GetNormals(), i), Vec3L{ p[0], p[1], p[2] }));
    }
  }
  // The points carry double rounding (~1e-16), the sphere is only approximately through them.
  EXPECT_LE(worst[vtkPolygonNormals::MAX], 1e-12L);
  // The others are only first or second order accurate here: the weightings really differ.
  EXPECT_GT(worst[vtkPolygonNormals::AREA], 1e-6L);
  EXPECT_GT(worst[vtkPolygonNormals::ANGLE], 1e-6L);
  EXPECT_GT(worst[vtkPolygonNormals::UNIFORM], 1e-6L);
}

TEST(PolygonNormalsPointNormals, EveryWeightingMatchesItsDefinitionOnAnIrregularMesh)
{
  auto mesh = JitteredSphere(30, 0.01);
  for (int weighting : Weightings)
  {
    const auto reference = ReferencePointNormals(mesh, weighting);
    for (int mode : { vtkPolygonNormals::DOUBLE, vtkPolygonNormals::EXACT })
    {
      auto out = RunFilter(mesh,
        [weighting, mode](vtkPolygonNormals* f)
        {
          f->SetAccuracy(mode);
          f->ComputePointNormalsOn();
          f->SetPointWeighting(weighting);
          f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        });
      const std::string what = std::string(WeightingName(weighting)) + " " + ModeName(mode);
      EXPECT_LE(WorstPointNormalAngle(out, reference, what), 1e-14L) << what;
    }
  }
}

TEST(PolygonNormalsPointNormals, StripsContributeTriangleByTriangle)
{
  // A folded strip: its point normals are those of its triangles taken one by one (a vertex in
  // the middle sees three triangles), not of the strip as one polygon.
  Cells cells;
  cells.Strips = { { 0, 1, 2, 3, 4, 5, 6 } };
  cells.Polys = { { 6, 5, 7 } };
  auto input = MakePolyData({ { 0, 0, 0 }, { 0, 1, 0.2 }, { 1, 0, 0.5 }, { 1, 1.3, 0 },
                              { 2, 0.1, 0.7 }, { 2.2, 1, 0.1 }, { 3, 0.2, 1 }, { 3, 1.5, 0.3 } },
    cells);
  for (int weighting : Weightings)
  {
    const auto reference = ReferencePointNormals(input, weighting);
    for (int mode : Modes)
    {
      auto out = RunFilter(input,
        [weighting, mode](vtkPolygonNormals* f)
        {
          f->SetAccuracy(mode);
          f->ComputePointNormalsOn();
          f->SetPointWeighting(weighting);
          f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        });
      const std::string what = std::string(WeightingName(weighting)) + " " + ModeName(mode);
      const long double tolerance = mode == vtkPolygonNormals::FAST ? 1e-6L : 1e-14L;
      EXPECT_LE(WorstPointNormalAngle(out, reference, what), tolerance) << what;
    }
  }
}

//==============================================================================
// Threads: bitwise identical output for every backend and thread count

TEST(PolygonNormalsThreads, OutputIsBitwiseIdenticalForEveryBackendAndThreadCount)
{
  auto mesh = JitteredSphere(400, 1e-4);
  // A few non-finite cells too, so that the counting is exercised.
  mesh->GetPoints()->SetPoint(12345, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  ASSERT_GT(mesh->GetNumberOfCells(), 300000);
  const std::string original = vtkSMPTools::GetBackend();
  struct Config
  {
    const char* Backend;
    int Threads;
  };
  // TBB is Debian's VTK 9.1 default backend (ParaView's VTK has none): used where available.
  const Config configs[] = { { "Sequential", 1 }, { "STDThread", 1 }, { "STDThread", 2 },
    { "STDThread", 4 }, { "TBB", 1 }, { "TBB", 2 } };
  for (int mode : Modes)
  {
    for (int weighting : { vtkPolygonNormals::AREA, vtkPolygonNormals::ANGLE })
    {
      std::vector<vtkSmartPointer<vtkPolyData>> outputs;
      for (const Config& config : configs)
      {
        if (!vtkSMPTools::SetBackend(config.Backend))
        {
          continue;
        }
        vtkSMPTools::Initialize(config.Threads);
        // STDThread caps the count at the hardware's threads.
        const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        EXPECT_EQ(vtkSMPTools::GetEstimatedNumberOfThreads(), std::min(config.Threads, cores))
          << config.Backend;
        outputs.push_back(RunFilter(mesh,
          [mode, weighting](vtkPolygonNormals* f)
          {
            AllCellOutputs(mode)(f);
            f->ComputePointNormalsOn();
            f->SetPointWeighting(weighting);
          }));
      }
      ASSERT_GE(outputs.size(), 2u) << "the STDThread backend is not available";
      for (std::size_t k = 1; k < outputs.size(); ++k)
      {
        const std::string what = std::string(ModeName(mode)) + " " + WeightingName(weighting) +
          " run " + std::to_string(k);
        auto same = [&](vtkDataArray* a, vtkDataArray* b, const char* name)
        {
          ASSERT_NE(a, nullptr) << name;
          ASSERT_NE(b, nullptr) << name;
          ASSERT_EQ(a->GetDataSize(), b->GetDataSize()) << name;
          const auto bytes = static_cast<std::size_t>(a->GetDataSize() * a->GetDataTypeSize());
          EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes), 0)
            << what << ": " << name;
        };
        vtkCellData* a = outputs[0]->GetCellData();
        vtkCellData* b = outputs[k]->GetCellData();
        for (const char* name : { "Normals", "AreaVectors", "Areas", "NormalStatus" })
        {
          same(a->GetArray(name), b->GetArray(name), name);
        }
        same(outputs[0]->GetPointData()->GetNormals(), outputs[k]->GetPointData()->GetNormals(),
          "point Normals");
      }
    }
  }
  vtkSMPTools::SetBackend(original.c_str());
}

TEST(PolygonNormalsThreads, PointNormalsDoNotDependOnThePointOrder)
{
  // The point pass splits the points into ranges and visits the blocks of cells whose point ids
  // reach into a range. Numbering the points at random (every block then spans every range)
  // must give each point the same normal bit for bit: its faces are the same, in the same cell
  // order. The same holds with and without the cell outputs (the cell pass is skipped without
  // them) and for any number of threads.
  auto mesh = JitteredSphere(300, 1e-4);
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> newId(static_cast<std::size_t>(numPoints));
  std::iota(newId.begin(), newId.end(), 0);
  std::shuffle(newId.begin(), newId.end(), std::mt19937_64(5));
  auto shuffled = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    points->SetPoint(newId[p], mesh->GetPoint(p));
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType* ids;
  vtkIdType n;
  for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(n, ids);)
  {
    std::vector<vtkIdType> renumbered(ids, ids + n);
    for (vtkIdType& id : renumbered)
    {
      id = newId[id];
    }
    polys->InsertNextCell(n, renumbered.data());
  }
  shuffled->SetPoints(points);
  shuffled->SetPolys(polys);

  const std::string original = vtkSMPTools::GetBackend();
  ASSERT_TRUE(vtkSMPTools::SetBackend("STDThread"));
  for (int mode : Modes)
  {
    for (int weighting : { vtkPolygonNormals::AREA, vtkPolygonNormals::ANGLE })
    {
      auto pointsOnly = [mode, weighting](vtkPolygonNormals* f)
      {
        f->SetAccuracy(mode);
        f->SetPointWeighting(weighting);
        f->ComputeCellNormalsOff();
        f->ComputePointNormalsOn();
      };
      vtkSMPTools::Initialize(1);
      auto reference = RunFilter(mesh,
        [&](vtkPolygonNormals* f)
        {
          pointsOnly(f);
          f->ComputeCellNormalsOn();
          f->ComputeNormalStatusOn();
        });
      vtkSMPTools::Initialize(2);
      auto renumbered = RunFilter(shuffled, pointsOnly);
      vtkDataArray* expected = reference->GetPointData()->GetNormals();
      vtkDataArray* actual = renumbered->GetPointData()->GetNormals();
      ASSERT_NE(expected, nullptr);
      ASSERT_NE(actual, nullptr);
      int mismatches = 0;
      for (vtkIdType p = 0; p < numPoints; ++p)
      {
        const auto a = Tuple3(expected, p);
        const auto b = Tuple3(actual, newId[p]);
        if (std::memcmp(a.data(), b.data(), sizeof(a)) != 0 && ++mismatches <= 5)
        {
          ADD_FAILURE() << ModeName(mode) << " " << WeightingName(weighting) << ": point " << p
                        << " (" << a[0] << ", " << a[1] << ", " << a[2] << ") renumbered (" << b[0]
                        << ", " << b[1] << ", " << b[2] << ")";
        }
      }
      EXPECT_EQ(mismatches, 0) << ModeName(mode) << " " << WeightingName(weighting);
    }
  }
  vtkSMPTools::SetBackend(original.c_str());
  vtkSMPTools::Initialize(0);
}

namespace
{
/// The mesh made of `cells` (ids into `mesh`'s polygons, in that order), points numbered in
/// order of first use; `oldPointId` receives each new point's id in `mesh`.
vtkSmartPointer<vtkPolyData> CellSubset(
  vtkPolyData* mesh, const std::vector<vtkIdType>& cells, std::vector<vtkIdType>& oldPointId)
{
  std::vector<vtkIdType> newId(static_cast<std::size_t>(mesh->GetNumberOfPoints()), -1);
  oldPointId.clear();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell : cells)
  {
    mesh->GetPolys()->GetCellAtId(cell, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      vtkIdType& id = newId[static_cast<std::size_t>(ids->GetId(k))];
      if (id < 0)
      {
        id = points->InsertNextPoint(mesh->GetPoint(ids->GetId(k)));
        oldPointId.push_back(ids->GetId(k));
      }
      ids->SetId(k, id);
    }
    polys->InsertNextCell(ids);
  }
  auto subset = vtkSmartPointer<vtkPolyData>::New();
  subset->SetPoints(points);
  subset->SetPolys(polys);
  return subset;
}

/// Point normals of one mode and weighting, output in double: float would hide the last bits.
std::function<void(vtkPolygonNormals*)> PointNormalsInDouble(int mode, int weighting)
{
  return [mode, weighting](vtkPolygonNormals* f)
  {
    f->SetAccuracy(mode);
    f->SetPointWeighting(weighting);
    f->ComputePointNormalsOn();
    f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  };
}

/// Counts the points of `part` whose normal differs in any bit from that of `oldPointId[p]` in
/// `whole`; `owned(p)` selects the points compared.
template <class Owned>
int CountDifferentNormals(vtkPolyData* whole, vtkPolyData* part,
  const std::vector<vtkIdType>& oldPointId, const Owned& owned, const std::string& what)
{
  vtkDataArray* expected = whole->GetPointData()->GetNormals();
  vtkDataArray* actual = part->GetPointData()->GetNormals();
  int mismatches = 0;
  for (vtkIdType p = 0; p < part->GetNumberOfPoints(); ++p)
  {
    if (!owned(p))
    {
      continue;
    }
    const auto a = Tuple3(expected, oldPointId[static_cast<std::size_t>(p)]);
    const auto b = Tuple3(actual, p);
    if (std::memcmp(a.data(), b.data(), sizeof(a)) != 0 && ++mismatches <= 3)
    {
      ADD_FAILURE() << what << ": point " << oldPointId[static_cast<std::size_t>(p)] << " (" << a[0]
                    << ", " << a[1] << ", " << a[2] << ") became (" << b[0] << ", " << b[1] << ", "
                    << b[2] << ")";
    }
  }
  return mismatches;
}
} // namespace

TEST(PolygonNormalsPointNormals, DoNotDependOnTheCellOrder)
{
  // A point adds its faces' contributions in an order set by their values: shuffling the cells
  // changes no bit of any point normal, in any mode and weighting. (Rounding makes a sum in
  // another order differ in the last bits on such a mesh: the test would see it.)
  auto mesh = JitteredSphere(120, 1e-3);
  std::vector<vtkIdType> order(static_cast<std::size_t>(mesh->GetNumberOfPolys()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(11));
  std::vector<vtkIdType> oldPointId;
  auto shuffled = CellSubset(mesh, order, oldPointId);
  for (int mode : Modes)
  {
    for (int weighting : Weightings)
    {
      auto configure = PointNormalsInDouble(mode, weighting);
      auto whole = RunFilter(mesh, configure);
      auto reordered = RunFilter(shuffled, configure);
      const std::string what = std::string(ModeName(mode)) + " " + WeightingName(weighting);
      EXPECT_EQ(CountDifferentNormals(
                  whole, reordered, oldPointId, [](vtkIdType) { return true; }, what),
        0)
        << what;
    }
  }
}

TEST(PolygonNormalsPointNormals, PiecesWithOneGhostLayerGiveTheWholeMeshNormals)
{
  // A distributed pipeline hands each process a piece: its own cells, then the ghost cells
  // around them (every cell sharing a point with the piece). The points of the piece's own
  // cells, boundary points included, get the whole mesh's normals bit for bit.
  auto mesh = JitteredSphere(90, 1e-3, 3);
  const vtkIdType numCells = mesh->GetNumberOfPolys();
  vtkNew<vtkIdList> ids;
  for (int pieces : { 2, 3 })
  {
    for (int piece = 0; piece < pieces; ++piece)
    {
      // Pieces by the sign pattern of the centre's coordinates, so that their boundaries wind
      // through the mesh rather than follow the cell order.
      std::vector<char> own(static_cast<std::size_t>(numCells), 0);
      std::vector<char> ownPoint(static_cast<std::size_t>(mesh->GetNumberOfPoints()), 0);
      std::vector<vtkIdType> cells;
      for (vtkIdType c = 0; c < numCells; ++c)
      {
        mesh->GetPolys()->GetCellAtId(c, ids);
        double centre[3] = { 0.0, 0.0, 0.0 };
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        {
          const double* x = mesh->GetPoint(ids->GetId(k));
          for (int j = 0; j < 3; ++j)
          {
            centre[j] += x[j];
          }
        }
        const double angle = std::atan2(centre[1], centre[0]) + std::sin(7.0 * centre[2]);
        const int owner = static_cast<int>(std::floor(
                            (angle + 2.0 * vtkMath::Pi()) / (2.0 * vtkMath::Pi() / pieces))) %
          pieces;
        if (owner == piece)
        {
          own[static_cast<std::size_t>(c)] = 1;
          cells.push_back(c);
          for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
          {
            ownPoint[static_cast<std::size_t>(ids->GetId(k))] = 1;
          }
        }
      }
      for (vtkIdType c = numCells - 1; c >= 0; --c) // ghosts, in another order than the mesh's
      {
        mesh->GetPolys()->GetCellAtId(c, ids);
        bool touches = false;
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        {
          touches = touches || ownPoint[static_cast<std::size_t>(ids->GetId(k))];
        }
        if (touches && !own[static_cast<std::size_t>(c)])
        {
          cells.push_back(c);
        }
      }
      std::vector<vtkIdType> oldPointId;
      auto part = CellSubset(mesh, cells, oldPointId);
      for (int mode : Modes)
      {
        for (int weighting : Weightings)
        {
          auto configure = PointNormalsInDouble(mode, weighting);
          auto whole = RunFilter(mesh, configure);
          auto computed = RunFilter(part, configure);
          const std::string what = std::to_string(pieces) + " pieces, piece " +
            std::to_string(piece) + ", " + ModeName(mode) + " " + WeightingName(weighting);
          EXPECT_EQ(
            CountDifferentNormals(
              whole, computed, oldPointId,
              [&](vtkIdType p) { return ownPoint[static_cast<std::size_t>(oldPointId[p])] != 0; },
              what),
            0)
            << what;
        }
      }
    }
  }
}

//==============================================================================
// Progress and abort

namespace
{
class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    const double progress = *static_cast<double*>(data);
    this->Values.push_back(progress);
    if (this->AbortAbove >= 0.0 && progress > this->AbortAbove && this->AbortedAt < 0)
    {
      this->AbortedAt = static_cast<int>(this->Values.size()) - 1;
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  }
  std::vector<double> Values;
  double AbortAbove = -1.0; // abort at the first progress above this value (if >= 0)
  int AbortedAt = -1;
};
} // namespace

TEST(PolygonNormalsProgress, ReachesOneMonotonically)
{
  auto mesh = JitteredSphere(400, 1e-4);
  // Cells only, point normals, point normals after splitting.
  for (int pass : { 0, 1, 2 })
  {
    vtkNew<vtkPolygonNormals> f;
    phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
    vtkNew<ProgressRecorder> progress;
    f->AddObserver(vtkCommand::ProgressEvent, progress);
    f->SetComputePointNormals(pass > 0);
    f->SetSplitting(pass == 2);
    f->SetInputData(mesh);
    f->Update();
    const std::vector<double>& v = progress->Values;
    ASSERT_FALSE(v.empty());
    EXPECT_EQ(v.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(v.begin(), v.end())) << "progress must never go back";
    const auto intermediate =
      std::count_if(v.begin(), v.end(), [](double p) { return p > 0.0 && p < 1.0; });
    EXPECT_GE(intermediate, 3) << "a 300,000-cell mesh reports progress along the way";
  }
}

TEST(PolygonNormalsProgress, AbortFromAProgressObserverStopsEarly)
{
  auto mesh = JitteredSphere(400, 1e-4);
  for (int pass : { 0, 1, 2 })
  {
    vtkNew<vtkPolygonNormals> f;
    phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
    vtkNew<ProgressRecorder> progress;
    progress->AbortAbove = 0.0;
    f->AddObserver(vtkCommand::ProgressEvent, progress);
    f->SetComputePointNormals(pass > 0);
    f->SetSplitting(pass == 2);
    f->SetInputData(mesh);
    f->Update();
    ASSERT_GE(progress->AbortedAt, 0);
    const double abortedAt = progress->Values[static_cast<std::size_t>(progress->AbortedAt)];
    EXPECT_LT(abortedAt, 0.5);
    for (std::size_t k = static_cast<std::size_t>(progress->AbortedAt) + 1;
         k < progress->Values.size(); ++k)
    {
      EXPECT_FALSE(progress->Values[k] > abortedAt && progress->Values[k] < 1.0)
        << "work went on after the abort: progress " << progress->Values[k];
    }
    // Nothing half-computed is delivered: an aborted run leaves an empty output.
    EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(f->GetOutput()->GetCellData()->GetNumberOfArrays(), 0);
    // Once the flag is cleared (ParaView 5.11's VTK leaves that to the caller), the next update
    // runs to completion.
    progress->AbortAbove = -1.0;
    progress->Values.clear();
    f->SetAbortExecute(0);
    f->Modified();
    f->Update();
    const std::vector<double>& v = progress->Values;
    ASSERT_FALSE(v.empty());
    EXPECT_EQ(v.back(), 1.0);
    EXPECT_GE(std::count_if(v.begin(), v.end(), [](double p) { return p > 0.0 && p < 1.0; }), 3);
  }
}

//==============================================================================
// Numerical extremes through the filter

namespace
{
struct Extreme
{
  const char* Name;
  double Scale;
  double Offset;
  int PointType;
};

class PolygonNormalsExtremes : public ::testing::TestWithParam<Extreme>
{
};

void PrintTo(const Extreme& param, std::ostream* os)
{
  *os << param.Name;
}

std::string ExtremeName(const ::testing::TestParamInfo<Extreme>& info)
{
  return info.param.Name;
}
} // namespace

TEST(PolygonNormalsAnisotropic, ExtentsSpanningMoreBinadesThanTheArithmeticKeepTheirNormal)
{
  // Triangles whose axes differ by more binades than float (and, for some, double) can hold:
  // each mode must still find the normal (every axis is scaled on its own on the slow path).
  struct Case
  {
    std::vector<Point> Points;
    Vec3L Normal;
  };
  const Case cases[] = {
    { { { 0, 0, 0 }, { std::ldexp(1.0, 1000), 0, 0 }, { 0, std::ldexp(1.0, -80), 0 } },
      { 0, 0, 1 } },
    { { { 0, 0, 0 }, { std::ldexp(1.0, -1000), 0, 0 }, { 0, std::ldexp(1.0, -60), 0 } },
      { 0, 0, 1 } },
    { { { 0, 0, 0 }, { 1e300, 0, 0 }, { 0, 1e-300, 0 } }, { 0, 0, 1 } },
    { { { 0, 0, 0 }, { 0, 0, 1e-300 }, { 0, 1e300, 0 } }, { -1, 0, 0 } },
  };
  for (const Case& c : cases)
  {
    Cells cells;
    cells.Polys = { { 0, 1, 2 } };
    auto mesh = MakePolyData(c.Points, cells);
    for (int mode : Modes)
    {
      auto out = RunFilter(mesh,
        [mode](vtkPolygonNormals* f)
        {
          f->SetAccuracy(mode);
          f->ComputeNormalStatusOn();
          f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        });
      vtkCellData* cd = out->GetCellData();
      EXPECT_EQ(cd->GetArray("NormalStatus")->GetTuple1(0), 0.0) << ModeName(mode);
      EXPECT_LE(AngleTo(Tuple3(cd->GetNormals(), 0), c.Normal), 1e-15L) << ModeName(mode);
    }
  }
}

TEST_P(PolygonNormalsExtremes, CellNormalsAreCorrectInEveryMode)
{
  const Extreme param = GetParam();
  auto base = IntegerHeightField();
  auto input = Transformed(base, param.Scale, param.Offset, param.PointType);
  // The transform is exact: the reference is that of the transformed points themselves.
  std::vector<std::array<mpf_class, 3>> reference;
  for (vtkIdType cell = 0; cell < input->GetNumberOfCells(); ++cell)
  {
    const ExactAreaVector w = ExactCellAreaVector(input, cell);
    ASSERT_FALSE(w.IsZero()) << "cell " << cell;
    reference.push_back(phongvtk_test::ReferenceNormal(w));
  }
  for (int mode : Modes)
  {
    auto out = RunFilter(input, AllCellOutputs(mode));
    vtkDataArray* normals = out->GetCellData()->GetNormals();
    double worstAngle = 0.0, worstUlp = 0.0;
    int wrong = 0;
    for (vtkIdType cell = 0; cell < input->GetNumberOfCells(); ++cell)
    {
      const auto n = Tuple3(normals, cell);
      wrong += !IsFinite(n) || Status(out, cell) != 0 ||
        !IsFinite(Tuple3(out->GetCellData()->GetArray("AreaVectors"), cell));
      if (IsFinite(n))
      {
        worstAngle = std::max(worstAngle, phongvtk_test::AngleError(n.data(), reference[cell]));
        worstUlp =
          std::max(worstUlp, phongvtk_test::NormalUlpError<double>(n.data(), reference[cell]));
      }
    }
    EXPECT_EQ(wrong, 0) << ModeName(mode) << ": cells with a NaN or a status other than 0";
    if (mode == vtkPolygonNormals::EXACT)
    {
      EXPECT_LE(worstUlp, 1.0) << ModeName(mode);
    }
    else
    {
      // Small integers times a power of two: every inexact mode is exact up to normalisation.
      const double tolerance = mode == vtkPolygonNormals::FAST ? 1e-6 : 1e-15;
      EXPECT_LE(worstAngle, tolerance) << ModeName(mode);
    }
  }
}

TEST_P(PolygonNormalsExtremes, PointNormalsAreCorrectForEveryWeighting)
{
  const Extreme param = GetParam();
  auto input = Transformed(IntegerHeightField(), param.Scale, param.Offset, param.PointType);
  for (int weighting : Weightings)
  {
    const auto reference = ReferencePointNormals(input, weighting);
    for (int mode : { vtkPolygonNormals::DOUBLE, vtkPolygonNormals::EXACT })
    {
      auto out = RunFilter(input,
        [weighting, mode](vtkPolygonNormals* f)
        {
          f->SetAccuracy(mode);
          f->ComputePointNormalsOn();
          f->SetPointWeighting(weighting);
          f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
        });
      const std::string what = std::string(WeightingName(weighting)) + " " + ModeName(mode);
      EXPECT_LE(WorstPointNormalAngle(out, reference, what), 1e-14L) << what;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, PolygonNormalsExtremes,
  ::testing::Values(Extreme{ "unit", 1.0, 0.0, VTK_DOUBLE },
    Extreme{ "scale_2m1070", 0x1p-1070, 0.0, VTK_DOUBLE },
    Extreme{ "scale_2m600", 0x1p-600, 0.0, VTK_DOUBLE },
    Extreme{ "scale_2p600", 0x1p600, 0.0, VTK_DOUBLE },
    Extreme{ "scale_2p1020", 0x1p1020, 0.0, VTK_DOUBLE },
    Extreme{ "offset_1e15", 1.0, 1e15, VTK_DOUBLE },
    Extreme{ "float_offset_1e7", 1.0, 1e7, VTK_FLOAT },
    Extreme{ "float_scale_2m140", 0x1p-140, 0.0, VTK_FLOAT },
    Extreme{ "float_scale_2p120", 0x1p120, 0.0, VTK_FLOAT }),
  ExtremeName);

namespace
{
// FAST normals are float values whichever path a polygon takes. A heptagon at 2^529, whose float
// differences overflow (the scaled path), and the same heptagon scaled to 2^-529 and to 1: GCC
// 12.2 at -O3 once dropped the rounding of two components on the scaled path (see RoundToFloat
// in PhongVTKAreaVector.h), in the cell pass and in the point pass alike.
TEST(PolygonNormals, FastNormalsAreFloatsOnEveryPath)
{
  const char* const hex[7][3] = {
    { "-0x1.48e0621f84714p+529", "0x1.b71caf989ce7p+526", "0x1.b8efadae91848p+529" },
    { "-0x1.75d4faf9d85e4p+529", "-0x1.2651a692bee86p+529", "-0x1.349ddf579829cp+528" },
    { "0x1.80c75d5325a2p+529", "0x1.a6f0db9e136bp+529", "0x1.fd5e80828668cp+528" },
    { "-0x1.b4c2e84b5849fp+529", "-0x1.6a144a43eabbep+529", "0x1.0ed9b6761afp+524" },
    { "0x1.a99c838170c0cp+528", "0x1.335ad810e76fep+529", "0x1.3c40aab77e72p+529" },
    { "-0x1.ae1dc36588af8p+526", "0x1.aa5da84356aap+528", "-0x1.5ac4e22f6d99p+526" },
    { "-0x1.75d31ec760b44p+528", "0x1.57d12c44e7e2cp+528", "0x1.64058264e609ap+529" },
  };
  for (int shift : { 0, -529, -1058 })
  {
    std::vector<Point> points;
    for (const auto& p : hex)
    {
      points.push_back({ std::ldexp(std::strtod(p[0], nullptr), shift),
        std::ldexp(std::strtod(p[1], nullptr), shift),
        std::ldexp(std::strtod(p[2], nullptr), shift) });
    }
    Cells cells;
    cells.Polys = { { 0, 1, 2, 3, 4, 5, 6 } };
    auto out = phongvtk_test::RunFilter(MakePolyData(points, cells),
      [](vtkPolygonNormals* f)
      {
        f->SetAccuracy(vtkPolygonNormals::FAST);
        f->SetComputePointNormals(true);
        f->SetPointWeighting(vtkPolygonNormals::UNIFORM);
        f->SetOutputPrecision(vtkPolygonNormals::DOUBLE_PRECISION);
      });
    double n[3];
    out->GetCellData()->GetNormals()->GetTuple(0, n);
    for (double x : n)
    {
      EXPECT_EQ(x, static_cast<double>(static_cast<float>(x)))
        << "shift " << shift << ": " << std::hexfloat << x << " is not a float";
    }
    // UNIFORM: every point's normal is the one face's float normal, normalised in double.
    double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (vtkIdType p = 0; p < 7; ++p)
    {
      double m[3];
      out->GetPointData()->GetNormals()->GetTuple(p, m);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(m[c], n[c] / length)
          << "shift " << shift << ", point " << p << ", component " << c;
      }
    }
  }
}
} // namespace
