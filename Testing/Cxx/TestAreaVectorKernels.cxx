/**
 * Specification of the area vector kernels of PhongVTKAreaVector.h: the summed cross-product rule
 * w = sum_i (p_i - p0) x (p_(i+1) - p0) and its unit normal in the accuracy modes FAST, DOUBLE,
 * COMPENSATED and EXACT. Every expected value comes from the independent exact reference
 * (PhongVTKExactReference.h) or from an analytic fact, never from the kernels' own output.
 *
 * The documented bounds (header comment of PhongVTKAreaVector.h), with u the unit roundoff of the
 * mode's arithmetic (2^-24 for FAST, 2^-53 otherwise), T = n - 2 fan triangles and P_c the sum of
 * |products| entering component c, which the tests compute exactly:
 *
 *   area vector  |w~_c - w_c| <= B_c = (T + 3) u P_c                   FAST, DOUBLE
 *                (+ 2^-52 P_c for FAST on double points: their differences rounded to float)
 *                                B_c = u |w_c| + (T + 65) u^2 P_c        COMPENSATED
 *   unit normal  the error of w~ carried through w / |w|, plus N u |n_c| for the normalisation
 *                (N = 4.5 for FAST, which multiplies by a rounded reciprocal, 3.5 otherwise):
 *                |n~_c - n_c| <= (B_c + |n_c| |B|) / (|w| - |B|) + N u |n_c|   when |B| < |w|
 *                (from n~_c - n_c = (w~_c - w_c) / |w~| + n_c (|w| - |w~|) / |w~|); when
 *                |B| >= |w| the bound allows any unit normal or the zero normal.
 *   length       |L~ - |w|| <= |B| + 3 u |w|
 *   EXACT        each normal component within 1 ulp of w_c / |w| (faithful); the zero normal
 *                and status Degenerate exactly when the exact w is zero; Vector and Length
 *                within 2 ulp of w * 2^-Exponent and |w| * 2^-Exponent.
 *
 * The header's bounds leave out gradual underflow. One exponent cannot resolve a component below
 * 2^-126 (float) or 2^-1022 (double) of the polygon's own scale, so the tests add the standard
 * underflow term to B_c, A = 16 (T + 3) eta max(D^2, min(1, 2^W (|w| + |B|))) (see
 * UnderflowTerm) with eta = 2^-150 (FAST) or 2^-1075 and D the largest coordinate difference
 * |p_ic - p0c|, and eta to each normal component. The error table counts the polygons that
 * needed A; only extremely flat polygons do.
 *
 * The worst measured errors of every family and mode are printed at the end of the run and
 * recorded as test properties (normal errors in ulps of the normal's format: float for FAST).
 */
#include "PhongVTKAreaVector.h"
#include "PhongVTKDocumentedBounds.h"
#include "PhongVTKExactReference.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using phongvtk::Accuracy;
using phongvtk::AreaVector;
using phongvtk_test::ComputeIntegerFan;
using phongvtk_test::Filler;
using phongvtk_test::IntegerFan;
using phongvtk_test::LaneCounts;
using phongvtk_test::LaneUse;
using phongvtk_test::MakeTruth;
using phongvtk_test::Measure;
using phongvtk_test::Measurement;
using phongvtk_test::ModeName;
using phongvtk_test::Point;
using phongvtk_test::Polygon;
using phongvtk_test::TimesPowerOfTwo;
using phongvtk_test::ToPoints;
using phongvtk_test::Truth;
using phongvtk_test::UnitRoundoff;

constexpr double Pi = 3.14159265358979323846;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Inf = std::numeric_limits<double>::infinity();

/**
 * The kernels under test (phongvtk_test::Compute): ComputeAreaVector for every polygon and, for
 * triangles, also the four-lane ComputeTriangles4 the filter uses for runs of triangles. A
 * triangle goes into a different lane at each call, beside ordinary triangles; when its lane is
 * done, the lane's result is the one checked, and it must equal the per-polygon result bit for
 * bit (the filter's grouping into lanes depends on the thread's range, and the output must not).
 */
template <class T>
AreaVector Compute(Accuracy mode, const Polygon<T>& polygon)
{
  static int lane = 0;
  lane = (lane + 1) % 4;
  std::string laneMismatch;
  const AreaVector r = phongvtk_test::Compute(mode, polygon, lane, laneMismatch);
  if (!laneMismatch.empty())
  {
    ADD_FAILURE() << laneMismatch;
  }
  return r;
}

/// The promises every mode makes for finite input: its documented bound (see the file comment).
::testing::AssertionResult MeetsDocumentedBound(Accuracy mode, const Measurement& m)
{
  const std::string why = phongvtk_test::BoundViolation(mode, m);
  if (why.empty())
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << why;
}

//------------------------------------------------------------------------------
// Worst measured errors, per family and mode, printed at the end of the run.
struct Worst
{
  long Polygons = 0;
  long Vacuous = 0;
  double NormalUlps = 0.0;
  double Angle = 0.0;
  double VectorRatio = 0.0;
  double NormalRatio = 0.0;
  double VectorUlps = 0.0;
  long NeedsUnderflowTerm = 0;
};

std::map<std::string, std::map<int, Worst>>& ErrorTable()
{
  static std::map<std::string, std::map<int, Worst>> table;
  return table;
}

void Record(const std::string& family, Accuracy mode, const Measurement& m)
{
  Worst& w = ErrorTable()[family][static_cast<int>(mode)];
  ++w.Polygons;
  w.Vacuous += m.Vacuous ? 1 : 0;
  w.NormalUlps = std::max(w.NormalUlps, m.NormalUlps);
  w.Angle = std::max(w.Angle, m.Angle);
  w.VectorRatio = std::max(w.VectorRatio, m.VectorRatio);
  w.NormalRatio = std::max(w.NormalRatio, m.NormalRatio);
  w.VectorUlps = std::max(w.VectorUlps, m.VectorUlps);
  w.NeedsUnderflowTerm += m.NeedsUnderflowTerm ? 1 : 0;
}

std::string FormatWorst(Accuracy mode, const Worst& w)
{
  char line[256];
  if (mode == Accuracy::Exact)
  {
    std::snprintf(line, sizeof(line),
      "%8ld polygons  normal %.3g ulp  angle %.3g rad  vector %.3g ulp", w.Polygons, w.NormalUlps,
      w.Angle, w.VectorUlps);
  }
  else
  {
    std::snprintf(line, sizeof(line),
      "%8ld polygons  normal %.3g %s  angle %.3g rad  error/bound: vector %.3g normal %.3g  "
      "(normal bound vacuous for %ld, underflow term needed for %ld)",
      w.Polygons, w.NormalUlps, mode == Accuracy::Fast ? "float ulp" : "ulp", w.Angle,
      w.VectorRatio, w.NormalRatio, w.Vacuous, w.NeedsUnderflowTerm);
  }
  return line;
}

/// Records the family's worst errors as properties of the running test (XML attribute names).
void ReportFamily(const std::string& family, Accuracy mode)
{
  std::string key = family;
  for (char& ch : key)
  {
    ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  }
  const Worst& w = ErrorTable()[family][static_cast<int>(mode)];
  ::testing::Test::RecordProperty(key + "_worst_normal_ulp", std::to_string(w.NormalUlps));
  ::testing::Test::RecordProperty(key + "_worst_angle_rad", std::to_string(w.Angle));
  if (mode != Accuracy::Exact)
  {
    ::testing::Test::RecordProperty(
      key + "_worst_vector_error_over_bound", std::to_string(w.VectorRatio));
  }
}

class ErrorTablePrinter : public ::testing::Environment
{
public:
  void TearDown() override
  {
    std::printf("\nWorst measured errors (normal ulps in the normal's format; error/bound <= 1: "
                "within the documented bound plus the underflow term)\n");
    for (const auto& family : ErrorTable())
    {
      for (const auto& mode : family.second)
      {
        const Accuracy a = static_cast<Accuracy>(mode.first);
        std::printf("  %-44s %-11s %s\n", family.first.c_str(), ModeName(a),
          FormatWorst(a, mode.second).c_str());
      }
    }
  }
};

const ::testing::Environment* const errorTablePrinter =
  ::testing::AddGlobalTestEnvironment(new ErrorTablePrinter);

template <class T>
std::string Describe(const Polygon<T>& polygon)
{
  std::ostringstream s;
  s << "polygon with " << polygon.size() << " vertices:";
  for (std::size_t i = 0; i < std::min<std::size_t>(polygon.size(), 12); ++i)
  {
    char vertex[128];
    std::snprintf(vertex, sizeof(vertex), " (%a, %a, %a)", static_cast<double>(polygon[i][0]),
      static_cast<double>(polygon[i][1]), static_cast<double>(polygon[i][2]));
    s << vertex;
  }
  if (polygon.size() > 12)
  {
    s << " ...";
  }
  return s.str();
}

/**
 * Checks one polygon against the mode's documented bound and records its errors under `family`.
 * Stops reporting details after a few failures so that a broken family stays readable.
 */
template <class T>
void ExpectDocumentedBound(Accuracy mode, const Polygon<T>& polygon, const std::string& family)
{
  const Truth truth = MakeTruth(polygon);
  const Measurement m = Measure(mode, Compute(mode, polygon), truth);
  Record(family, mode, m);
  static const ::testing::TestInfo* test = nullptr;
  static int failures = 0;
  const ::testing::TestInfo* current = ::testing::UnitTest::GetInstance()->current_test_info();
  failures = current == test ? failures : 0;
  test = current;
  const ::testing::AssertionResult result = MeetsDocumentedBound(mode, m);
  if (!result && ++failures <= 10)
  {
    ADD_FAILURE() << family << " (" << ModeName(mode) << "): " << result.message() << "\n  "
                  << Describe(polygon);
  }
  else if (!result)
  {
    ADD_FAILURE() << family << " (" << ModeName(mode) << "): " << result.message();
  }
}

//------------------------------------------------------------------------------
// Polygon families.
using Rng = std::mt19937_64;

double Uniform(Rng& rng, double lo, double hi)
{
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Point RandomUnitVector(Rng& rng)
{
  std::normal_distribution<double> gauss;
  Point v = { gauss(rng), gauss(rng), gauss(rng) };
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& x : v)
  {
    x /= length;
  }
  return v;
}

/// Orthonormal (first two) directions of a random plane.
std::pair<Point, Point> RandomPlane(Rng& rng)
{
  const Point d = RandomUnitVector(rng);
  Point e = RandomUnitVector(rng);
  const double dot = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
  for (int c = 0; c < 3; ++c)
  {
    e[c] -= dot * d[c];
  }
  const double length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  for (double& x : e)
  {
    x /= length;
  }
  return { d, e };
}

/// n points uniform in the cube [-size, size]^3 around `offset` (a twisted polygon for n > 3).
Polygon<double> RandomPolygon(Rng& rng, std::size_t n, double size = 1.0, const Point& offset = {})
{
  Polygon<double> p(n);
  for (auto& v : p)
  {
    for (int c = 0; c < 3; ++c)
    {
      v[c] = offset[c] + Uniform(rng, -size, size);
    }
  }
  return p;
}

/**
 * A star-shaped polygon in a random plane: vertex i at angle 2 pi i / n and a radius from
 * radius(i); `lift(i)` moves it off the plane. Concave when the radii vary.
 */
template <class Radius, class Lift>
Polygon<double> PlanarLoop(Rng& rng, std::size_t n, const Point& offset, Radius radius, Lift lift)
{
  const auto plane = RandomPlane(rng);
  Point normal = { plane.first[1] * plane.second[2] - plane.first[2] * plane.second[1],
    plane.first[2] * plane.second[0] - plane.first[0] * plane.second[2],
    plane.first[0] * plane.second[1] - plane.first[1] * plane.second[0] };
  Polygon<double> p(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double angle = 2.0 * Pi * static_cast<double>(i) / static_cast<double>(n);
    const double r = radius(i);
    const double h = lift(i);
    for (int c = 0; c < 3; ++c)
    {
      p[i][c] = offset[c] +
        (r * std::cos(angle) * plane.first[c] + r * std::sin(angle) * plane.second[c] +
          h * normal[c]);
    }
  }
  return p;
}

template <class T>
Polygon<T> Rotated(const Polygon<T>& p, std::size_t first)
{
  Polygon<T> r(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    r[i] = p[(first + i) % p.size()];
  }
  return r;
}

Polygon<float> ToFloat(const Polygon<double>& p)
{
  Polygon<float> r(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      r[i][c] = static_cast<float>(p[i][c]);
    }
  }
  return r;
}

Polygon<double> Scaled(const Polygon<double>& p, int exponent)
{
  Polygon<double> r = p;
  for (auto& v : r)
  {
    for (double& x : v)
    {
      x = std::ldexp(x, exponent);
    }
  }
  return r;
}

std::string Decade(double x)
{
  char s[32];
  std::snprintf(s, sizeof(s), "1e%d", static_cast<int>(std::lround(std::log10(x))));
  return s;
}

class AreaVectorKernel : public ::testing::TestWithParam<Accuracy>
{
};

INSTANTIATE_TEST_SUITE_P(AllModes, AreaVectorKernel,
  ::testing::Values(Accuracy::Fast, Accuracy::Double, Accuracy::Compensated, Accuracy::Exact),
  [](const ::testing::TestParamInfo<Accuracy>& info) { return ModeName(info.param); });

//------------------------------------------------------------------------------
// 1. Random triangles and polygons.
TEST(ExactReference, IntegerFanEqualsTheRationalReference)
{
  // The fast integer reference (used for the condition P_c and for long polygons) against
  // phongvtk_test::ComputeExactAreaVector, including subnormal and huge coordinates.
  Rng rng(11);
  for (int k = 0; k < 300; ++k)
  {
    Polygon<double> p = RandomPolygon(rng, 3 + k % 10);
    const int exponent = std::uniform_int_distribution<int>(-1074, 1020)(rng);
    p = Scaled(p, k % 3 == 0 ? 0 : exponent);
    const std::vector<Point> points = ToPoints(p);
    const IntegerFan fan = ComputeIntegerFan(points);
    const phongvtk_test::ExactAreaVector w = phongvtk_test::ComputeExactAreaVector(points);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(TimesPowerOfTwo(fan.W[c], fan.Exponent), w.W[c]) << Describe(p);
    }
  }
}

TEST(ExactReference, FaithfulMeansANeighbouringDouble)
{
  using phongvtk_test::IsFaithful;
  const int bits = phongvtk_test::ReferenceBits;
  const double below1 = std::nextafter(1.0, 0.0); // 1 - 2^-53: half an ulp of 1's binade
  EXPECT_TRUE(IsFaithful(1.0, mpf_class(1, bits)));
  EXPECT_FALSE(IsFaithful(below1, mpf_class(1, bits)));
  EXPECT_FALSE(IsFaithful(-below1, mpf_class(-1, bits)));
  EXPECT_TRUE(IsFaithful(0.0, mpf_class(0, bits)));
  EXPECT_FALSE(IsFaithful(std::numeric_limits<double>::denorm_min(), mpf_class(0, bits)));
  mpf_class above1(1, bits); // 1 + 2^-60: between 1 and 1 + 2^-52
  mpf_class tiny(1, bits);
  mpf_div_2exp(tiny.get_mpf_t(), tiny.get_mpf_t(), 60);
  above1 += tiny;
  EXPECT_TRUE(IsFaithful(1.0, above1));
  EXPECT_TRUE(IsFaithful(std::nextafter(1.0, 2.0), above1));
  EXPECT_FALSE(IsFaithful(below1, above1));
  EXPECT_TRUE(IsFaithful(-1.0, mpf_class(-above1, bits)));
  EXPECT_TRUE(IsFaithful(-std::nextafter(1.0, 2.0), mpf_class(-above1, bits)));
  mpf_class deep(1, bits); // 2^-1100: below the smallest subnormal, 2^-1074
  mpf_div_2exp(deep.get_mpf_t(), deep.get_mpf_t(), 1100);
  EXPECT_TRUE(IsFaithful(0.0, deep));
  EXPECT_TRUE(IsFaithful(std::numeric_limits<double>::denorm_min(), deep));
  EXPECT_FALSE(IsFaithful(2 * std::numeric_limits<double>::denorm_min(), deep));
}

TEST_P(AreaVectorKernel, RandomTrianglesMeetTheDocumentedBound)
{
  Rng rng(1);
  for (int k = 0; k < 5000; ++k)
  {
    ExpectDocumentedBound(GetParam(), RandomPolygon(rng, 3), "random triangles");
  }
  ReportFamily("random triangles", GetParam());
}

TEST_P(AreaVectorKernel, OrdinaryTrianglesAreCompletedFourPerSimdRegister)
{
  // Triangles of ordinary size, scale and offset are all completed by the four-lane kernel (the
  // filter's fast path), within the documented bound and bitwise as the per-polygon kernel
  // (ComputeIn checks both).
  Rng rng(31);
  const LaneUse before = LaneCounts();
  for (int k = 0; k < 2000; ++k)
  {
    const Point offset = { Uniform(rng, -1e3, 1e3), Uniform(rng, -1e3, 1e3), 0.0 };
    const int exponent = std::uniform_int_distribution<int>(-20, 20)(rng);
    const Polygon<double> p = Scaled(RandomPolygon(rng, 3, 1.0, offset), exponent);
    ExpectDocumentedBound(GetParam(), p, "lanes: ordinary triangles");
    ExpectDocumentedBound(GetParam(), ToFloat(p), "lanes: ordinary float triangles");
  }
  EXPECT_EQ(LaneCounts().Done - before.Done, LaneCounts().Triangles - before.Triangles);
  ReportFamily("lanes: ordinary triangles", GetParam());
  ReportFamily("lanes: ordinary float triangles", GetParam());
}

template <class T>
int DoneLanes(Accuracy mode, const T* const corner[3][4])
{
  phongvtk::TriangleLanes lanes;
  switch (mode)
  {
    case Accuracy::Fast:
      phongvtk::ComputeTriangles4<Accuracy::Fast, T>(corner, lanes);
      break;
    case Accuracy::Double:
      phongvtk::ComputeTriangles4<Accuracy::Double, T>(corner, lanes);
      break;
    case Accuracy::Compensated:
      phongvtk::ComputeTriangles4<Accuracy::Compensated, T>(corner, lanes);
      break;
    case Accuracy::Exact:
      phongvtk::ComputeTriangles4<Accuracy::Exact, T>(corner, lanes);
      break;
  }
  return lanes.Done;
}

TEST_P(AreaVectorKernel, TrianglesOutsideTheCommonCaseLeaveTheirLaneToThePerPolygonKernel)
{
  // Degenerate, non-finite, tiny and huge triangles are not completed in their lane, whichever
  // it is, while the ordinary triangles beside them are.
  const Polygon<double> unit = { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } } };
  const std::vector<std::pair<std::string, Polygon<double>>> cases = {
    { "collinear", { { { 0, 0, 0 } }, { { 1, 1, 1 } }, { { 2, 2, 2 } } } },
    { "repeated vertex", { { { 1, 2, 3 } }, { { 1, 2, 3 } }, { { 0, 1, 0 } } } },
    { "NaN", { { { 0, 0, 0 } }, { { NaN, 0, 0 } }, { { 0, 1, 0 } } } },
    { "Inf", { { { 0, 0, Inf } }, { { 1, 0, 0 } }, { { 0, 1, 0 } } } },
    { "scale 2^-1000", Scaled(unit, -1000) },
    { "scale 2^1000", Scaled(unit, 1000) },
  };
  for (const auto& c : cases)
  {
    const Polygon<float> f = ToFloat(c.second);
    for (int lane = 0; lane < 4; ++lane)
    {
      const double* corner[3][4];
      const float* cornerF[3][4];
      for (int v = 0; v < 3; ++v)
      {
        for (int j = 0; j < 4; ++j)
        {
          corner[v][j] = j == lane ? c.second[v].data() : Filler<double>(v, j);
          cornerF[v][j] = j == lane ? f[v].data() : Filler<float>(v, j);
        }
      }
      EXPECT_EQ(DoneLanes(GetParam(), corner), 15 & ~(1 << lane)) << c.first << ", lane " << lane;
      EXPECT_EQ(DoneLanes(GetParam(), cornerF), 15 & ~(1 << lane))
        << c.first << " (float), lane " << lane;
    }
  }
}

TEST_P(AreaVectorKernel, RandomFloatTrianglesMeetTheDocumentedBound)
{
  Rng rng(2);
  for (int k = 0; k < 5000; ++k)
  {
    ExpectDocumentedBound(GetParam(), ToFloat(RandomPolygon(rng, 3)), "random triangles (float)");
  }
  ReportFamily("random triangles (float)", GetParam());
}

TEST_P(AreaVectorKernel, RandomTwistedPolygonsMeetTheDocumentedBound)
{
  Rng rng(3);
  for (int k = 0; k < 3000; ++k)
  {
    const std::size_t n = 4 + k % 9;
    ExpectDocumentedBound(GetParam(), RandomPolygon(rng, n), "random twisted polygons n=4..12");
  }
  ReportFamily("random twisted polygons n=4..12", GetParam());
}

TEST_P(AreaVectorKernel, RandomPlanarPolygonsMeetTheDocumentedBound)
{
  Rng rng(4);
  for (int k = 0; k < 1000; ++k)
  {
    const std::size_t n = 4 + k % 29;
    const Point offset = { Uniform(rng, -10, 10), Uniform(rng, -10, 10), Uniform(rng, -10, 10) };
    ExpectDocumentedBound(GetParam(),
      PlanarLoop(
        rng, n, offset, [](std::size_t) { return 1.0; }, [](std::size_t) { return 0.0; }),
      "random convex planar polygons n=4..32");
  }
  ReportFamily("random convex planar polygons n=4..32", GetParam());
}

//------------------------------------------------------------------------------
// 2. Offsets from the origin.
TEST_P(AreaVectorKernel, TrianglesAndQuadsFarFromTheOriginMeetTheDocumentedBound)
{
  Rng rng(5);
  for (double offset : { 1.0, 1e3, 1e6, 1e9, 1e12, 1e15 })
  {
    const std::string family = "offset " + Decade(offset) + ", size 1 (double)";
    for (int k = 0; k < 600; ++k)
    {
      const Point o = { offset, -0.75 * offset, 0.5 * offset };
      ExpectDocumentedBound(GetParam(), RandomPolygon(rng, 3 + k % 2, 0.5, o), family);
    }
    ReportFamily(family, GetParam());
  }
}

TEST_P(AreaVectorKernel, FloatTrianglesAndQuadsFarFromTheOriginMeetTheDocumentedBound)
{
  Rng rng(6);
  for (double offset : { 1.0, 1e3, 1e5, 1e7 })
  {
    const std::string family = "offset " + Decade(offset) + ", size 1 (float)";
    for (int k = 0; k < 600; ++k)
    {
      const Point o = { offset, -0.75 * offset, 0.5 * offset };
      ExpectDocumentedBound(GetParam(), ToFloat(RandomPolygon(rng, 3 + k % 2, 0.5, o)), family);
    }
    ReportFamily(family, GetParam());
  }
}

//------------------------------------------------------------------------------
// 3. Scales from the subnormal range to the overflow threshold.

/// A fixed non-planar pentagon with small integer coordinates: scaled by 2^k it stays exact
/// down to 2^-1074 (subnormal coordinates), so its normal is the same at every scale.
Polygon<double> IntegerPentagon()
{
  return { { 7, -3, 1 }, { 2, 6, -5 }, { -6, 4, 3 }, { -4, -7, 2 }, { 3, -5, -6 } };
}

TEST_P(AreaVectorKernel, PowerOfTwoScalesFromSubnormalToHugeKeepTheNormal)
{
  const Polygon<double> pentagon = IntegerPentagon();
  const Polygon<double> triangle = { { 1, 0, 0 }, { 0, 2, 1 }, { -3, 1, 5 } };
  const Truth unit = MakeTruth(pentagon);
  for (int k = -1071; k <= 1020; k += (k < -1060 || k > 1010) ? 1 : 7)
  {
    for (const Polygon<double>* shape :
      std::initializer_list<const Polygon<double>*>{ &pentagon, &triangle })
    {
      const Polygon<double> p = Scaled(*shape, k);
      ExpectDocumentedBound(GetParam(), p, "scales 2^-1071..2^1020 (integer shapes)");
      if (shape == &pentagon)
      {
        // The analytic fact: scaling by a power of two does not change the exact normal.
        const AreaVector r = Compute(GetParam(), p);
        ASSERT_EQ(r.Status, phongvtk::StatusOk) << "2^" << k;
        EXPECT_LT(phongvtk_test::AngleError(r.Normal, unit.Normal), 64 * UnitRoundoff(GetParam()))
          << "2^" << k;
      }
    }
  }
  ReportFamily("scales 2^-1071..2^1020 (integer shapes)", GetParam());
}

TEST_P(AreaVectorKernel, PowerOfTwoScalesOfFullPrecisionPolygonsMeetTheDocumentedBound)
{
  Rng rng(7);
  for (int k = 0; k < 600; ++k)
  {
    // Coordinates of magnitude in [2^-1, 2^0] with full 53-bit significands, scaled exactly.
    Polygon<double> p = RandomPolygon(rng, 3 + k % 4);
    for (auto& v : p)
    {
      for (double& x : v)
      {
        x = std::copysign(0.5 + 0.5 * std::fabs(x), x);
      }
    }
    const int exponent = std::uniform_int_distribution<int>(-1021, 1022)(rng);
    ExpectDocumentedBound(
      GetParam(), Scaled(p, exponent), "scales 2^-1021..2^1022 (full precision)");
  }
  ReportFamily("scales 2^-1021..2^1022 (full precision)", GetParam());
}

TEST_P(AreaVectorKernel, CoordinatesNearTheOverflowThresholdMeetTheDocumentedBound)
{
  // Differences such as 1e308 - (-1e308) overflow; the kernels must rescale, not fail.
  const std::string family = "coordinates +-1e308 (differences overflow)";
  ExpectDocumentedBound(GetParam(),
    Polygon<double>{
      { 1e308, -1e308, 5e307 }, { -1e308, 1e308, -3e307 }, { 1e308, 1e308, -1e308 } },
    family);
  const double max = std::numeric_limits<double>::max();
  ExpectDocumentedBound(GetParam(),
    Polygon<double>{ { max, -max, max }, { -max, max, 0 }, { -max, -max, -max }, { max, 0, -max } },
    family);
  Rng rng(8);
  for (int k = 0; k < 500; ++k)
  {
    Polygon<double> p = RandomPolygon(rng, 3 + k % 5);
    for (auto& v : p)
    {
      for (double& x : v)
      {
        x = std::copysign(0.5 + 0.5 * std::fabs(x), x) * max;
      }
    }
    if (k % 4 == 0)
    {
      p[k % p.size()][k % 3] = 1e-300; // a tiny coordinate among huge ones
    }
    ExpectDocumentedBound(GetParam(), p, family);
  }
  ReportFamily(family, GetParam());
}

TEST_P(AreaVectorKernel, PolygonsWhoseProductsOverflowInOneComponentOnlyAreRescaled)
{
  // Flat in z, huge in x and y: the z component's products overflow (inf - inf = NaN in the
  // direct evaluation) while the x and y components stay inside the safe window.
  const std::string family = "flat polygons, products overflow in one component";
  Rng rng(9);
  for (int big : { 70, 140, 520, 700, 1000 })
  {
    for (int small : { -100, -30, 0 })
    {
      for (int k = 0; k < 20; ++k)
      {
        Polygon<double> p = RandomPolygon(rng, 3 + k % 3);
        for (auto& v : p)
        {
          v[0] = std::ldexp(v[0], big);
          v[1] = std::ldexp(v[1], big);
          v[2] = std::ldexp(v[2], small);
        }
        ExpectDocumentedBound(GetParam(), p, family);
      }
    }
  }
  ReportFamily(family, GetParam());
}

//------------------------------------------------------------------------------
// 4. Needles.

/// A needle triangle or quad of length 1 and width 1/aspect along random directions.
Polygon<double> Needle(Rng& rng, double aspect, const Point& offset, bool quad)
{
  const auto plane = RandomPlane(rng);
  const double width = 1.0 / aspect;
  auto at = [&](double along, double across)
  {
    return std::array<double, 3>{ offset[0] + along * plane.first[0] + across * plane.second[0],
      offset[1] + along * plane.first[1] + across * plane.second[1],
      offset[2] + along * plane.first[2] + across * plane.second[2] };
  };
  if (quad)
  {
    return { at(0, 0), at(1, 0), at(1, width), at(0, width) };
  }
  return { at(0, 0), at(1, 0), at(Uniform(rng, 0.1, 0.9), width) };
}

TEST_P(AreaVectorKernel, NeedlesMeetTheDocumentedBound)
{
  Rng rng(10);
  for (double aspect : { 1e12, 1e15, 1e16 })
  {
    for (double offset : { 0.0, 1.0, 1e3 })
    {
      const std::string family = "needles aspect " + Decade(aspect) + " at " +
        (offset == 0.0 ? std::string("origin") : "offset " + Decade(offset));
      for (int k = 0; k < 600; ++k)
      {
        const Point o = { offset, 0.5 * offset, -offset };
        const Polygon<double> p = Needle(rng, aspect, o, k % 2 == 1);
        ExpectDocumentedBound(GetParam(), Rotated(p, k % p.size()), family);
      }
      ReportFamily(family, GetParam());
    }
  }
}

//------------------------------------------------------------------------------
// 5. Concave, self-intersecting and twisted polygons.
TEST_P(AreaVectorKernel, ConcavePolygonsMeetTheDocumentedBound)
{
  const std::string family = "concave (stars, L-shapes, combs)";
  Rng rng(12);
  for (int k = 0; k < 400; ++k)
  {
    const std::size_t n = 5 + k % 20;
    const Point offset = { Uniform(rng, -1e3, 1e3), Uniform(rng, -1e3, 1e3),
      Uniform(rng, -1e3, 1e3) };
    std::vector<double> radii(n);
    for (double& r : radii)
    {
      r = Uniform(rng, 0.05, 1.0);
    }
    const Polygon<double> p = PlanarLoop(
      rng, n, offset, [&radii](std::size_t i) { return radii[i]; },
      [](std::size_t) { return 0.0; });
    ExpectDocumentedBound(GetParam(), Rotated(p, k % n), family);
  }
  // An L-shape and a comb, with the fan started at every vertex (including reflex ones, whose
  // fans mix triangles of both orientations).
  const Polygon<double> shape = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 1, 0 }, { 1, 2, 0 },
    { 0, 2, 0 } };
  Polygon<double> comb;
  for (int tooth = 0; tooth < 10; ++tooth)
  {
    comb.push_back({ 0.3 * tooth, 0.0, 0.01 * tooth });
    comb.push_back({ 0.3 * tooth + 0.1, 5.0, 0.0 });
    comb.push_back({ 0.3 * tooth + 0.2, 5.0, 0.0 });
  }
  comb.push_back({ 3.0, -1.0, 0.0 });
  comb.push_back({ 0.0, -1.0, 0.0 });
  for (const Polygon<double>* base : std::initializer_list<const Polygon<double>*>{ &shape, &comb })
  {
    for (std::size_t first = 0; first < base->size(); ++first)
    {
      Polygon<double> p = Rotated(*base, first);
      const auto plane = RandomPlane(rng);
      for (auto& v : p)
      {
        const double x = v[0], y = v[1], z = v[2];
        for (int c = 0; c < 3; ++c)
        {
          v[c] = 100.0 + x * plane.first[c] + y * plane.second[c] + z * (c == 0 ? 1.0 : 0.0);
        }
      }
      ExpectDocumentedBound(GetParam(), p, family);
    }
  }
  ReportFamily(family, GetParam());
}

TEST_P(AreaVectorKernel, PentagramsMeetTheDocumentedBound)
{
  // The self-intersecting star 0, 2, 4, 1, 3 of a regular pentagon: its inner pentagon is
  // covered twice, so w is the pentagon's plus the inner pentagon's (the summed rule counts
  // winding numbers).
  const std::string family = "pentagrams (self-intersecting)";
  Rng rng(13);
  for (int k = 0; k < 300; ++k)
  {
    const Point offset = { Uniform(rng, -10, 10), Uniform(rng, -10, 10), Uniform(rng, -10, 10) };
    const Polygon<double> pentagon = PlanarLoop(
      rng, 5, offset, [](std::size_t) { return 1.0; }, [](std::size_t) { return 0.0; });
    Polygon<double> star;
    for (std::size_t i : { 0, 2, 4, 1, 3 })
    {
      star.push_back(pentagon[(i + k) % 5]);
    }
    ExpectDocumentedBound(GetParam(), star, family);
  }
  ReportFamily(family, GetParam());
}

TEST(AreaVectorReference, PentagramAreaVectorCountsTheInnerPentagonTwice)
{
  // Analytic check of the reference on a star: the summed rule weighs each region by its
  // winding number, so a regular pentagram of circumradius 1 in the plane z = 0 has
  // |w| = 2 (5 A_tip + 2 A_inner), with the inner pentagon's circumradius r = cos 72 / cos 36,
  // A_inner = (5/2) r^2 sin 72 and each tip a triangle of base 2 r sin 36 and height
  // 1 - r cos 36.
  Polygon<double> star;
  for (int i : { 0, 2, 4, 1, 3 })
  {
    star.push_back({ std::cos(2 * Pi * i / 5), std::sin(2 * Pi * i / 5), 0.0 });
  }
  const Truth t = MakeTruth(star);
  const double r = std::cos(2 * Pi / 5) / std::cos(Pi / 5);
  const double inner = 2.5 * r * r * std::sin(2 * Pi / 5);
  const double tip = 0.5 * (2 * r * std::sin(Pi / 5)) * (1 - r * std::cos(Pi / 5));
  EXPECT_NEAR(t.Length.get_d(), 2 * (5 * tip + 2 * inner), 1e-14);
  EXPECT_EQ(t.W.W[0], 0);
  EXPECT_EQ(t.W.W[1], 0);
}

TEST_P(AreaVectorKernel, TwistedPolygonsMeetTheDocumentedBound)
{
  // Non-planar polygons: w is the summed rule (the area seen by the viewer who sees most).
  const std::string family = "twisted (saddles, waves)";
  Rng rng(14);
  ExpectDocumentedBound(
    GetParam(), Polygon<double>{ { 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 } }, family);
  for (int k = 0; k < 400; ++k)
  {
    const std::size_t n = 4 + k % 40;
    const double amplitude = std::ldexp(1.0, -(k % 30));
    const double waves = 1 + k % 5;
    const Point offset = { Uniform(rng, -1e4, 1e4), Uniform(rng, -1e4, 1e4),
      Uniform(rng, -1e4, 1e4) };
    const Polygon<double> p = PlanarLoop(
      rng, n, offset, [](std::size_t) { return 1.0; },
      [&](std::size_t i) { return amplitude * std::sin(waves * 2 * Pi * i / n); });
    ExpectDocumentedBound(GetParam(), p, family);
  }
  ReportFamily(family, GetParam());
}

//------------------------------------------------------------------------------
// 6. Degenerate and nearly degenerate polygons.

/// Expects status Degenerate and an exactly zero result.
template <class T>
void ExpectExactlyDegenerate(Accuracy mode, const Polygon<T>& p)
{
  const AreaVector r = Compute(mode, p);
  EXPECT_EQ(r.Status, phongvtk::StatusDegenerate) << Describe(p);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(r.Normal[c], 0.0) << Describe(p);
    EXPECT_EQ(r.Vector[c], 0.0) << Describe(p);
  }
  EXPECT_EQ(r.Length, 0.0) << Describe(p);
  EXPECT_EQ(r.Exponent, 0) << Describe(p);
}

TEST_P(AreaVectorKernel, FewerThanThreeVerticesAreDegenerate)
{
  const Polygon<double> points = { { 1, 2, 3 }, { 4, -5, 6 } };
  for (std::size_t n = 0; n < 3; ++n)
  {
    ExpectExactlyDegenerate(GetParam(), Polygon<double>(points.begin(), points.begin() + n));
  }
}

TEST_P(AreaVectorKernel, CoincidentAndRepeatedVerticesAreDegenerate)
{
  Rng rng(15);
  for (int k = 0; k < 100; ++k)
  {
    const Polygon<double> two = RandomPolygon(rng, 2, std::ldexp(1.0, k % 40 - 20));
    const auto& p = two[0];
    const auto& q = two[1];
    ExpectExactlyDegenerate(GetParam(), Polygon<double>(3 + k % 5, p));
    ExpectExactlyDegenerate(GetParam(), Polygon<double>{ p, p, q });
    ExpectExactlyDegenerate(GetParam(), Polygon<double>{ p, q, p });
    ExpectExactlyDegenerate(GetParam(), Polygon<double>{ q, p, p });
    ExpectExactlyDegenerate(GetParam(), ToFloat(Polygon<double>{ q, p, p }));
  }
}

TEST_P(AreaVectorKernel, ExactlyCollinearPointsAreDegenerate)
{
  // Points t d on a line through the origin with d of short significands, so that every point
  // and every difference is exact in float and double: each fan cross product is exactly zero
  // and so is every computed product difference.
  ExpectExactlyDegenerate(GetParam(), Polygon<double>{ { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 } });
  // Rounding commutes with scaling by 2: the doubles nearest to 0.2, 0.4, 0.8 are exactly 2, 4, 8
  // times the double nearest to 0.1 (and so on), so these points are exactly collinear.
  const Polygon<double> tenths = { { 0, 0, 0 }, { 0.1, 0.2, 0.3 }, { 0.2, 0.4, 0.6 },
    { 0.4, 0.8, 1.2 } };
  ASSERT_TRUE(MakeTruth(tenths).W.IsZero());
  ExpectExactlyDegenerate(GetParam(), tenths);
  Rng rng(16);
  for (int k = 0; k < 300; ++k)
  {
    Point d;
    for (double& x : d)
    {
      x = std::ldexp(std::round(Uniform(rng, -1, 1) * 0x1p16), -16 + k % 20);
    }
    Polygon<double> p(3 + k % 6);
    for (auto& v : p)
    {
      const double t = std::uniform_int_distribution<int>(-7, 7)(rng);
      for (int c = 0; c < 3; ++c)
      {
        v[c] = t * d[c];
      }
    }
    ExpectExactlyDegenerate(GetParam(), p);
    ExpectExactlyDegenerate(GetParam(), ToFloat(p));
  }
}

TEST_P(AreaVectorKernel, OutAndBackQuadIsDegenerate)
{
  // p0 p1 p2 p1: the two fan triangles are exact opposites in every arithmetic.
  Rng rng(17);
  for (int k = 0; k < 300; ++k)
  {
    const Polygon<double> t = RandomPolygon(rng, 3, 1.0, { 1e3, 0, -1e3 });
    ExpectExactlyDegenerate(GetParam(), Polygon<double>{ t[0], t[1], t[2], t[1] });
  }
}

TEST(AreaVectorExact, ZeroNormalExactlyWhenTheExactAreaVectorIsZero)
{
  // Zero-area polygons whose zero only exact arithmetic sees: collinear points at arbitrary
  // (rounded) positions on a line through two double points, and longer out-and-back paths.
  Rng rng(18);
  for (int k = 0; k < 300; ++k)
  {
    // Out and back: p0 p1 ... pm ... p1, every triangle cancelled by its mirror.
    const Polygon<double> path = RandomPolygon(rng, 3 + k % 6, 1.0, { 10.0, 20.0, -5.0 });
    Polygon<double> p = path;
    for (std::size_t i = path.size() - 2; i >= 1; --i)
    {
      p.push_back(path[i]);
    }
    ASSERT_TRUE(MakeTruth(p).W.IsZero());
    ExpectExactlyDegenerate(Accuracy::Exact, p);
    ExpectDocumentedBound(Accuracy::Exact, p, "zero area (out and back, collinear)");
    // Collinear: a + t (b - a) for binary fractions t whose products are exact.
    const Polygon<double> ab = RandomPolygon(rng, 2, 1.0);
    Polygon<double> line;
    for (double t : { 0.0, 1.0, 0.5, -2.0, 0.25, 3.0 })
    {
      Point v;
      for (int c = 0; c < 3; ++c)
      {
        v[c] = std::ldexp(std::round(std::ldexp(ab[0][c], 20)), -20) +
          t * std::ldexp(std::round(std::ldexp(ab[1][c] - ab[0][c], 20)), -20);
      }
      line.push_back(v);
    }
    ASSERT_TRUE(MakeTruth(line).W.IsZero()) << Describe(line);
    ExpectExactlyDegenerate(Accuracy::Exact, line);
  }
  ReportFamily("zero area (out and back, collinear)", Accuracy::Exact);
}

TEST_P(AreaVectorKernel, ZeroAreaPolygonsMeetTheDocumentedBound)
{
  // The other modes may see rounding noise instead of zero, but no more than their bound.
  Rng rng(18);
  for (int k = 0; k < 300; ++k)
  {
    const Polygon<double> path = RandomPolygon(rng, 3 + k % 6, 1.0, { 10.0, 20.0, -5.0 });
    Polygon<double> p = path;
    for (std::size_t i = path.size() - 2; i >= 1; --i)
    {
      p.push_back(path[i]);
    }
    ExpectDocumentedBound(GetParam(), p, "zero area (out and back)");
  }
  ReportFamily("zero area (out and back)", GetParam());
}

TEST(AreaVectorExact, NearlyDegenerateTrianglesHaveFaithfulNormals)
{
  // (p, q, m) with m the exact midpoint of p and q moved by one ulp in one coordinate: the exact
  // w is tiny but not zero, so the status is Ok and the normal faithful.
  const std::string family = "nearly degenerate (midpoint +-1 ulp)";
  Rng rng(19);
  for (int k = 0; k < 3000; ++k)
  {
    const double offset = std::ldexp(1.0, 3 * (k % 12));
    Polygon<double> t(3);
    for (int c = 0; c < 3; ++c)
    {
      // p, q in [offset, 2 offset) on a grid of ulp(offset) * 2: the midpoint is exact.
      const double grid = std::ldexp(offset, -51);
      t[0][c] = offset + grid * std::floor(Uniform(rng, 0, 0x1p51));
      t[1][c] = offset + grid * std::floor(Uniform(rng, 0, 0x1p51));
      t[2][c] = 0.5 * (t[0][c] + t[1][c]);
    }
    const int c = k % 3;
    t[2][c] = std::nextafter(t[2][c], k % 2 ? Inf : -Inf);
    const Polygon<double> p = Rotated(t, k % 3);
    ASSERT_FALSE(MakeTruth(p).W.IsZero()) << Describe(p);
    ExpectDocumentedBound(Accuracy::Exact, p, family);
    ExpectDocumentedBound(Accuracy::Exact, ToFloat(p), family);
  }
  ReportFamily(family, Accuracy::Exact);
}

TEST(AreaVectorExact, NormalComponentsInTheSubnormalRangeAreFaithful)
{
  // Polygons flat in z to within 2^-1020 .. 2^-1070 of their size: the normal's x and y
  // components are subnormal numbers with many significant bits, and faithful means within one
  // subnormal ulp (2^-1074) of the exact value.
  const std::string family = "normal components in the subnormal range";
  Rng rng(20);
  for (int k = 0; k < 1500; ++k)
  {
    Polygon<double> p = RandomPolygon(rng, 3 + k % 3);
    const int flatness = std::uniform_int_distribution<int>(-1070, -1020)(rng);
    for (auto& v : p)
    {
      v[2] = std::ldexp(v[2], flatness);
    }
    const int scale = std::uniform_int_distribution<int>(-1, 1)(rng) * 500;
    ExpectDocumentedBound(Accuracy::Exact, Scaled(p, scale), family);
  }
  ReportFamily(family, Accuracy::Exact);
}

TEST(AreaVectorExact, HugeAreaVectorsWithSubnormalNormalComponentsAreFaithful)
{
  // Certified area vectors beyond 2^500 whose x component is 2^-1022 .. 2^-1074 of the largest:
  // the normalisation rescales them, and the x component of the normal is a subnormal number
  // that must stay within one subnormal ulp (2^-1074) of the exact value.
  const std::string family = "huge area vectors, subnormal normal components";
  ExpectDocumentedBound(Accuracy::Exact,
    Polygon<double>{ { -0x1.0248255611828p+905, 0x1.d621634cd70ep-118, 0x1.a23bc5797853cp-119 },
      { -0x1.d3c5ab193bb43p+905, 0x1.1e4f4638c413p-108, -0x1.16ae47a6c854p-123 },
      { 0x1.9573af15bd6ecp+905, 0x1.bc59b19b72784p-176, -0x1.4397f111191acp-244 },
      { -0x1.59d263cdf0b3ep+905, -0x1.021d20971df6p-197, -0x1.2ecf900032c64p-204 },
      { 0x1.f781d635bb8dcp+905, -0x1.d85f07c14cfa8p-127, 0x1.1c033a219bde4p-269 },
      { 0x1.d3e69a8bc61e8p+905, 0x1.81214220483e8p-141, 0x1.c72493ea6b65p-168 } },
    family);
  Rng rng(22);
  for (int k = 0; k < 3000; ++k)
  {
    Polygon<double> p = RandomPolygon(rng, 3 + k % 3);
    const int x = std::uniform_int_distribution<int>(700, 1000)(rng);
    const int y = std::uniform_int_distribution<int>(510 - x, 890 - x)(rng);
    const int z = x - std::uniform_int_distribution<int>(1020, 1076)(rng);
    for (auto& v : p)
    {
      v[0] = std::ldexp(v[0], x);
      v[1] = std::ldexp(v[1], y);
      v[2] = std::ldexp(v[2], z);
    }
    ExpectDocumentedBound(Accuracy::Exact, p, family);
  }
  ReportFamily(family, Accuracy::Exact);
}

TEST(AreaVectorExact, DifferencesThatTheSlowPathScalesToZeroAreNotLost)
{
  // Huge in x, tiny in y and z: the direct evaluation overflows its window, and the slow path's
  // scaling (largest difference to [1, 2)) rounds the tiny differences to zero. Certifying the
  // scaled sum would then call (0, 0, 2^920) degenerate, or drop the -2^-597 of the second
  // triangle's normal.
  const std::string family = "differences scaled below 2^-1075";
  const Polygon<double> flat = { { 0, 0, 0 }, { 0x1p1000, 0, 0 }, { 0, 0x1p-80, 0 } };
  ASSERT_FALSE(MakeTruth(flat).W.IsZero());
  const AreaVector r = Compute(Accuracy::Exact, flat);
  EXPECT_EQ(r.Status, phongvtk::StatusOk);
  EXPECT_EQ(r.Normal[2], 1.0);
  ExpectDocumentedBound(Accuracy::Exact, flat, family);
  ExpectDocumentedBound(Accuracy::Exact,
    Polygon<double>{ { 0, 0, 0 }, { 0x1p1000, 0x1p-76, 0 }, { 0x1p1000, 0, 0x1p521 } }, family);
  Rng rng(21);
  for (int k = 0; k < 1000; ++k)
  {
    Polygon<double> p = RandomPolygon(rng, 3 + k % 4);
    const int big = std::uniform_int_distribution<int>(900, 1020)(rng);
    for (auto& v : p)
    {
      v[0] = std::ldexp(v[0], big);
      for (int c = 1; c < 3; ++c)
      {
        const int below = std::uniform_int_distribution<int>(1000, 1200)(rng);
        v[c] = std::ldexp(v[c], big - below);
      }
    }
    if (k % 5 == 0)
    {
      p[1][1] = p[0][1]; // the only differences in y are lost
    }
    ExpectDocumentedBound(Accuracy::Exact, p, family);
  }
  ReportFamily(family, Accuracy::Exact);
}

//------------------------------------------------------------------------------
// 7. Non-finite coordinates.
template <class T>
void ExpectNonFiniteFlagged(Accuracy mode, const Polygon<T>& p)
{
  const AreaVector r = Compute(mode, p);
  EXPECT_EQ(r.Status, phongvtk::StatusNonFinite) << Describe(p);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(r.Normal[c], 0.0) << Describe(p);
    EXPECT_EQ(r.Vector[c], 0.0) << Describe(p);
  }
  EXPECT_EQ(r.Length, 0.0) << Describe(p);
}

TEST_P(AreaVectorKernel, NonFiniteCoordinatesAreFlaggedWithAZeroNormal)
{
  Rng rng(21);
  for (std::size_t n : { 3, 4, 5, 9 })
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        for (double bad : { NaN, Inf, -Inf })
        {
          Polygon<double> p = RandomPolygon(rng, n);
          p[i][c] = bad;
          ExpectNonFiniteFlagged(GetParam(), p);
          ExpectNonFiniteFlagged(GetParam(), ToFloat(p));
          // Also among huge and tiny coordinates (the rescaled paths).
          Polygon<double> huge = Scaled(RandomPolygon(rng, n), 1000);
          huge[i][c] = bad;
          ExpectNonFiniteFlagged(GetParam(), huge);
          Polygon<double> tiny = Scaled(RandomPolygon(rng, n), -1000);
          tiny[i][c] = bad;
          ExpectNonFiniteFlagged(GetParam(), tiny);
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// 8. A polygon with a million vertices.
TEST_P(AreaVectorKernel, MillionVertexPolygonMeetsTheDocumentedBound)
{
  // A circle of radius 1 sampled at 10^6 points far from the origin, slightly non-planar. The
  // coordinates lie on the grid 2^-30 (exact doubles), so the integer reference is fast.
  static const Polygon<double> circle = []()
  {
    constexpr std::size_t n = 1000000;
    Polygon<double> p(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double angle = 2 * Pi * static_cast<double>(i) / n;
      const double local[3] = { std::cos(angle), std::sin(angle), 1e-3 * std::sin(3 * angle) };
      const double offset[3] = { 1e6, -2e6, 5e5 };
      for (int c = 0; c < 3; ++c)
      {
        p[i][c] = offset[c] + std::ldexp(std::round(std::ldexp(local[c], 30)), -30);
      }
    }
    return p;
  }();
  static const Truth truth = MakeTruth(circle);
  const std::string family = "circle, 10^6 vertices, offset 1e6";
  const Measurement m = Measure(GetParam(), Compute(GetParam(), circle), truth);
  Record(family, GetParam(), m);
  EXPECT_TRUE(MeetsDocumentedBound(GetParam(), m));
  ReportFamily(family, GetParam());
}

//------------------------------------------------------------------------------
// 9. Triangle strips.

/// The outline of a strip of k points, as the kernels' callers build it.
Polygon<double> StripOutline(const Polygon<double>& strip)
{
  const auto k = static_cast<std::int64_t>(strip.size());
  Polygon<double> outline;
  for (std::int64_t i = 0; i < k; ++i)
  {
    outline.push_back(strip[static_cast<std::size_t>(phongvtk::StripOutlineIndex(i, k))]);
  }
  return outline;
}

Polygon<double> RandomStrip(Rng& rng, std::size_t k)
{
  Polygon<double> strip(k);
  for (std::size_t j = 0; j < k; ++j)
  {
    strip[j] = { 0.5 * j + Uniform(rng, -0.2, 0.2), (j % 2) + Uniform(rng, -0.2, 0.2),
      Uniform(rng, -0.3, 0.3) };
  }
  return strip;
}

TEST(TriangleStrip, OutlineAreaVectorEqualsTheSumOfTheAlternatingTriangles)
{
  Rng rng(22);
  for (std::size_t k = 3; k <= 12; ++k)
  {
    for (int trial = 0; trial < 50; ++trial)
    {
      const Polygon<double> strip = RandomStrip(rng, k);
      const std::vector<Point> points = ToPoints(strip);
      mpq_class sum[3];
      for (std::size_t j = 0; j + 2 < k; ++j)
      {
        const std::vector<Point> triangle = j % 2 == 0
          ? std::vector<Point>{ points[j], points[j + 1], points[j + 2] }
          : std::vector<Point>{ points[j + 1], points[j], points[j + 2] };
        const phongvtk_test::ExactAreaVector w = phongvtk_test::ComputeExactAreaVector(triangle);
        for (int c = 0; c < 3; ++c)
        {
          sum[c] += w.W[c];
        }
      }
      const phongvtk_test::ExactAreaVector outline =
        phongvtk_test::ComputeExactAreaVector(ToPoints(StripOutline(strip)));
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(outline.W[c], sum[c]) << "k = " << k << ", " << Describe(strip);
      }
    }
  }
}

TEST_P(AreaVectorKernel, StripOutlinesMeetTheDocumentedBound)
{
  const std::string family = "strip outlines k=3..12";
  Rng rng(23);
  for (std::size_t k = 3; k <= 12; ++k)
  {
    for (int trial = 0; trial < 50; ++trial)
    {
      ExpectDocumentedBound(GetParam(), StripOutline(RandomStrip(rng, k)), family);
    }
  }
  ReportFamily(family, GetParam());
}

//------------------------------------------------------------------------------
// 10. The scaled representation Vector * 2^Exponent.
TEST_P(AreaVectorKernel, VectorTimesTwoToTheExponentIsTheAreaVector)
{
  // Vector * 2^Exponent = w and Length * 2^Exponent = |w| within the mode's bound (EXACT: 2 ulp
  // of the stored Vector and Length), at scales where w itself is not representable.
  Rng rng(24);
  const Accuracy mode = GetParam();
  for (int k = 0; k < 400; ++k)
  {
    const int exponent = std::uniform_int_distribution<int>(-1070, 1020)(rng);
    const Polygon<double> p = Scaled(IntegerPentagon(), exponent);
    const Truth truth = MakeTruth(p);
    const AreaVector r = Compute(mode, p);
    const Measurement m = Measure(mode, r, truth);
    ASSERT_TRUE(m.Finite);
    ASSERT_EQ(r.Status, phongvtk::StatusOk);
    if (mode == Accuracy::Exact)
    {
      EXPECT_LE(m.VectorUlps, 2.0) << "2^" << exponent;
      EXPECT_LE(m.LengthUlps, 2.0) << "2^" << exponent;
    }
    else
    {
      EXPECT_LE(m.VectorRatio, 1.0) << "2^" << exponent;
      EXPECT_LE(m.LengthRatio, 1.0) << "2^" << exponent;
    }
  }
}

} // namespace
