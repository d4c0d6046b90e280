/**
 * @file PhongVTKDocumentedBounds.h
 * @brief The area-vector kernels' promises as a checkable oracle: each accuracy mode's documented
 * error bound (header comment of PhongVTKAreaVector.h), measured against the exact truth of
 * PhongVTKExactReference.h and GMP integer fans. Shared by TestAreaVectorKernels.cxx (whose file
 * comment states the bounds in full) and the kernels' fuzz target (Testing/Fuzz).
 *
 * Nothing here depends on a test framework: a violated promise is a description
 * (BoundViolation), empty when every promise holds.
 */
#ifndef PhongVTKDocumentedBounds_h
#define PhongVTKDocumentedBounds_h

#include "PhongVTKAreaVector.h"
#include "PhongVTKExactReference.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace phongvtk_test
{
using phongvtk::Accuracy;
using phongvtk::AreaVector;

template <class T>
using Polygon = std::vector<std::array<T, 3>>;

inline const char* ModeName(Accuracy mode)
{
  switch (mode)
  {
    case Accuracy::Fast:
      return "Fast";
    case Accuracy::Double:
      return "Double";
    case Accuracy::Compensated:
      return "Compensated";
    default:
      return "Exact";
  }
}

/// Unit roundoff of the mode's arithmetic.
inline double UnitRoundoff(Accuracy mode)
{
  return mode == Accuracy::Fast ? 0x1p-24 : 0x1p-53;
}

/// The normalisation's share of a unit-normal component's error, in units of u |n_c|: |w| from
/// a rounded sum of squares and a square root (2.5 u), then a division (1 u), or for FAST a
/// rounded reciprocal and a product (2 u).
inline double NormalisationUlps(Accuracy mode)
{
  return mode == Accuracy::Fast ? 4.5 : 3.5;
}

//------------------------------------------------------------------------------
// The kernels under test: ComputeAreaVector for every polygon and, for triangles, also the
// four-lane ComputeTriangles4 the filter uses for runs of triangles, whose result must equal the
// per-polygon one bit for bit (the filter's grouping into lanes depends on the thread's range,
// and the output must not).

/// Ordinary triangles that fill the other three lanes.
template <class T>
const T* Filler(int vertex, int lane)
{
  static const T corners[4][3][3] = { { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } },
    { { 1, 2, 3 }, { -2, 1, 0.5 }, { 0.25, -1, 2 } }, { { 5, 5, 5 }, { 6, 5, 5 }, { 5, 5, 7 } },
    { { -1, -1, -1 }, { 3, 1, 2 }, { 1, 3, -2 } } };
  return corners[lane][vertex];
}

/// Which lanes came out done, over all calls (the fast path must really be taken).
struct LaneUse
{
  long Triangles = 0;
  long Done = 0;
};

inline LaneUse& LaneCounts()
{
  static LaneUse use;
  return use;
}

/**
 * The per-polygon kernel into `out`; for a triangle also the four-lane kernel with the triangle in
 * lane `lane` beside Filler triangles. When that lane comes out done, its result must equal the
 * per-polygon one bit for bit: the description of a difference is returned (empty when equal) and
 * the lane's result is left in `out`.
 */
template <Accuracy A, class T>
std::string ComputeIn(const Polygon<T>& polygon, int lane, AreaVector& out)
{
  phongvtk::ComputeAreaVector<A, T>([&polygon](std::int64_t i)
    { return polygon[static_cast<std::size_t>(i)].data(); },
    static_cast<std::int64_t>(polygon.size()), out);
  if (polygon.size() != 3)
  {
    return std::string();
  }
  const T* corner[3][4];
  for (int v = 0; v < 3; ++v)
  {
    for (int j = 0; j < 4; ++j)
    {
      corner[v][j] = j == lane ? polygon[static_cast<std::size_t>(v)].data() : Filler<T>(v, j);
    }
  }
  phongvtk::TriangleLanes lanes;
  phongvtk::ComputeTriangles4<A, T>(corner, lanes);
  ++LaneCounts().Triangles;
  if (!(lanes.Done & (1 << lane)))
  {
    return std::string();
  }
  ++LaneCounts().Done;
  const AreaVector r = lanes.Result(lane);
  const bool same = std::memcmp(r.Normal, out.Normal, sizeof(r.Normal)) == 0 &&
    std::memcmp(r.Vector, out.Vector, sizeof(r.Vector)) == 0 &&
    std::memcmp(&r.Length, &out.Length, sizeof(r.Length)) == 0 && out.Exponent == 0 &&
    out.Status == phongvtk::StatusOk;
  std::ostringstream mismatch;
  if (!same)
  {
    mismatch << "lane " << lane << " differs from the per-polygon kernel: normal (" << r.Normal[0]
             << ", " << r.Normal[1] << ", " << r.Normal[2] << ") vs (" << out.Normal[0] << ", "
             << out.Normal[1] << ", " << out.Normal[2] << "), status " << int(out.Status);
  }
  out = r;
  return mismatch.str();
}

template <class T>
/// The kernels of `mode` on `polygon` (ComputeIn), every output field poisoned beforehand so that
/// a field the kernel forgets to write shows up as a NaN.
AreaVector Compute(Accuracy mode, const Polygon<T>& polygon, int lane, std::string& laneMismatch)
{
  AreaVector out;
  for (int c = 0; c < 3; ++c)
  {
    out.Normal[c] = std::numeric_limits<double>::quiet_NaN();
    out.Vector[c] = std::numeric_limits<double>::quiet_NaN();
  }
  out.Length = std::numeric_limits<double>::quiet_NaN();
  out.Exponent = INT_MIN;
  out.Status = 255;
  switch (mode)
  {
    case Accuracy::Fast:
      laneMismatch = ComputeIn<Accuracy::Fast>(polygon, lane, out);
      break;
    case Accuracy::Double:
      laneMismatch = ComputeIn<Accuracy::Double>(polygon, lane, out);
      break;
    case Accuracy::Compensated:
      laneMismatch = ComputeIn<Accuracy::Compensated>(polygon, lane, out);
      break;
    case Accuracy::Exact:
      laneMismatch = ComputeIn<Accuracy::Exact>(polygon, lane, out);
      break;
  }
  return out;
}

//------------------------------------------------------------------------------
// Exact truth. Every finite double is an integer times a power of two, so with one common power
// of two the differences, the products and their sums are exact integers (GMP's mpz), much
// faster than rationals for long polygons. ExactReference.IntegerFanEqualsTheRationalReference
// checks it against phongvtk_test::ComputeExactAreaVector.
struct IntegerFan
{
  mpz_class W[3]; // w = W * 2^Exponent
  mpz_class P[3]; // P_c = P[c] * 2^Exponent
  long Exponent = 0;
};

/// Exponent of the last bit of x's 53-bit significand (x finite, non-zero).
inline long LastBitExponent(double x)
{
  int e;
  std::frexp(x, &e);
  return e - 53;
}

/// z = x * 2^-shift, exact when shift <= LastBitExponent(x).
inline void SetInteger(mpz_class& z, double x, long shift)
{
  if (x == 0.0)
  {
    z = 0;
    return;
  }
  int e;
  const double f = std::frexp(x, &e);
  z = std::ldexp(f, 53); // an integer of at most 53 bits
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(e - 53 - shift));
}

inline IntegerFan ComputeIntegerFan(const std::vector<Point>& polygon)
{
  IntegerFan fan;
  if (polygon.size() < 3)
  {
    return fan;
  }
  long shift = LONG_MAX;
  for (const Point& p : polygon)
  {
    for (double x : p)
    {
      if (x != 0.0)
      {
        shift = std::min(shift, LastBitExponent(x));
      }
    }
  }
  if (shift == LONG_MAX)
  {
    return fan; // every coordinate is zero
  }
  fan.Exponent = 2 * shift;
  mpz_class p0[3], a[3], b[3], product;
  for (int c = 0; c < 3; ++c)
  {
    SetInteger(p0[c], polygon[0][c], shift);
    SetInteger(a[c], polygon[1][c], shift);
    a[c] -= p0[c];
  }
  for (std::size_t i = 2; i < polygon.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      SetInteger(b[c], polygon[i][c], shift);
      b[c] -= p0[c];
    }
    for (int c = 0; c < 3; ++c)
    {
      const int c1 = (c + 1) % 3;
      const int c2 = (c + 2) % 3;
      mpz_mul(product.get_mpz_t(), a[c1].get_mpz_t(), b[c2].get_mpz_t());
      fan.W[c] += product;
      mpz_abs(product.get_mpz_t(), product.get_mpz_t());
      fan.P[c] += product;
      mpz_mul(product.get_mpz_t(), a[c2].get_mpz_t(), b[c1].get_mpz_t());
      fan.W[c] -= product;
      mpz_abs(product.get_mpz_t(), product.get_mpz_t());
      fan.P[c] += product;
    }
    for (int c = 0; c < 3; ++c)
    {
      mpz_swap(a[c].get_mpz_t(), b[c].get_mpz_t());
    }
  }
  return fan;
}

inline mpf_class Mpf(double x)
{
  return mpf_class(x, phongvtk_test::ReferenceBits);
}

/// x * 2^e, exact.
inline mpf_class TimesPowerOfTwo(const mpf_class& x, long e)
{
  mpf_class r(0, phongvtk_test::ReferenceBits);
  if (e >= 0)
  {
    mpf_mul_2exp(r.get_mpf_t(), x.get_mpf_t(), static_cast<mp_bitcnt_t>(e));
  }
  else
  {
    mpf_div_2exp(r.get_mpf_t(), x.get_mpf_t(), static_cast<mp_bitcnt_t>(-e));
  }
  return r;
}

inline mpq_class TimesPowerOfTwo(const mpz_class& x, long e)
{
  mpq_class r(x);
  if (e >= 0)
  {
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  }
  else
  {
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  }
  return r;
}

/// Everything the checks need to know about one polygon, exactly.
struct Truth
{
  phongvtk_test::ExactAreaVector W;
  std::array<mpf_class, 3> Normal;
  mpf_class Length;
  std::array<mpf_class, 3> Condition; // P_c
  mpf_class Extent;                   // D, the largest |p_ic - p0c|
  std::int64_t Triangles = 0;         // T = n - 2
  bool DoublePoints = false;          // FAST rounds the differences of double points to float
};

template <class T>
std::vector<Point> ToPoints(const Polygon<T>& polygon)
{
  std::vector<Point> points(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      points[i][c] = static_cast<double>(polygon[i][c]);
    }
  }
  return points;
}

/// The rational reference is used up to this size; longer polygons use the integer fan alone.
constexpr std::size_t RationalReferenceLimit = 4096;

template <class T>
Truth MakeTruth(const Polygon<T>& polygon)
{
  const std::vector<Point> points = ToPoints(polygon);
  const IntegerFan fan = ComputeIntegerFan(points);
  Truth t;
  if (points.size() <= RationalReferenceLimit)
  {
    t.W = phongvtk_test::ComputeExactAreaVector(points);
  }
  else
  {
    for (int c = 0; c < 3; ++c)
    {
      t.W.W[c] = TimesPowerOfTwo(fan.W[c], fan.Exponent);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    t.Condition[c] =
      TimesPowerOfTwo(mpf_class(fan.P[c], phongvtk_test::ReferenceBits), fan.Exponent);
  }
  t.Extent = mpf_class(0, phongvtk_test::ReferenceBits);
  for (const Point& p : points)
  {
    for (int c = 0; c < 3; ++c)
    {
      const mpf_class d(abs(Mpf(p[c]) - Mpf(points[0][c])), phongvtk_test::ReferenceBits);
      t.Extent = d > t.Extent ? d : t.Extent;
    }
  }
  t.Normal = phongvtk_test::ReferenceNormal(t.W);
  t.Length = phongvtk_test::ReferenceLength(t.W);
  t.Triangles = std::max<std::int64_t>(static_cast<std::int64_t>(polygon.size()) - 2, 0);
  t.DoublePoints = sizeof(T) == sizeof(double);
  return t;
}

//------------------------------------------------------------------------------
// Measurement of one result against the truth.
struct Measurement
{
  bool Finite = true;     // no NaN or infinity in Normal, Vector, Length
  bool ZeroResult = true; // Normal, Vector and Length exactly zero
  bool UnitNormal = true; // | |n~| - 1 | <= 8 u
  bool ExactZero = false; // the exact w is zero
  bool Vacuous = false;   // |B| >= |w|: the documented bound allows any normal
  std::uint8_t Status = 255;
  double NormalUlps = 0.0; // in ulps of float for FAST, of double otherwise
  double Angle = 0.0;      // radians
  double VectorRatio = 0.0;
  double NormalRatio = 0.0;
  double LengthRatio = 0.0;
  bool NeedsUnderflowTerm = false; // within the bound only thanks to the underflow term
  double VectorUlps = 0.0;         // EXACT: Vector against w * 2^-Exponent
  double LengthUlps = 0.0;         // EXACT: Length against |w| * 2^-Exponent
  bool NormalFaithful = true;      // EXACT: each component a neighbouring double of the exact one
};

inline double Ratio(const mpf_class& error, const mpf_class& bound)
{
  if (bound == 0)
  {
    return error == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  return mpf_class(error / bound, phongvtk_test::ReferenceBits).get_d();
}

/// Half the smallest subnormal number of the mode's format: the absolute error of gradual
/// underflow.
inline mpf_class UnderflowUnit(Accuracy mode)
{
  return TimesPowerOfTwo(Mpf(1.0), mode == Accuracy::Fast ? -150 : -1075); // 2^-1075: no double
}

/**
 * The error term of gradual underflow that the header's bounds leave out (see the file comment),
 * A = 16 (T + 3) eta max(D^2, min(1, 2^W (|w| + |B|))), given the documented bound's norm |B|.
 * The kernels evaluate on differences scaled to the largest one, D, where every product is below
 * 4 and gradual underflow adds a few eta (times D^2 in true units) per product; or directly,
 * where it adds a few eta (absolute) per product, but only when the computed |w~| <= |w| + |B|
 * lies in the safe window [2^-W, 2^W] named in the header (W = 60 for float, 500 for double).
 */
inline mpf_class UnderflowTerm(Accuracy mode, const Truth& t, const mpf_class& documentedNorm)
{
  constexpr mp_bitcnt_t bits = phongvtk_test::ReferenceBits;
  const mpf_class scale2(t.Extent * t.Extent, bits);
  const mpf_class direct(
    TimesPowerOfTwo(mpf_class(t.Length + documentedNorm, bits), mode == Accuracy::Fast ? 60 : 500),
    bits);
  const mpf_class largest(std::max(scale2, std::min(direct, Mpf(1.0))), bits);
  return mpf_class(
    Mpf(16.0 * static_cast<double>(t.Triangles + 3)) * UnderflowUnit(mode) * largest, bits);
}

/// The documented bound B_c on the error of the area vector's component c (not for EXACT).
inline mpf_class VectorBound(Accuracy mode, const Truth& t, int c)
{
  const mpf_class u = Mpf(UnitRoundoff(mode));
  const mpf_class triangles = Mpf(static_cast<double>(t.Triangles));
  if (mode == Accuracy::Compensated)
  {
    const mpf_class w(t.W.W[c], phongvtk_test::ReferenceBits);
    return mpf_class(
      u * abs(w) + (triangles + 65) * u * u * t.Condition[c], phongvtk_test::ReferenceBits);
  }
  // FAST on double points: + 2 u P_c for the differences rounded to float (u of double).
  const mpf_class rounding =
    mode == Accuracy::Fast && t.DoublePoints ? Mpf(0x1p-52) : mpf_class(0, ReferenceBits);
  return mpf_class(((triangles + 3) * u + rounding) * t.Condition[c], phongvtk_test::ReferenceBits);
}

inline Measurement Measure(Accuracy mode, const AreaVector& r, const Truth& t)
{
  constexpr mp_bitcnt_t bits = phongvtk_test::ReferenceBits;
  Measurement m;
  m.Status = r.Status;
  m.ExactZero = t.W.IsZero();
  for (int c = 0; c < 3; ++c)
  {
    m.Finite = m.Finite && std::isfinite(r.Normal[c]) && std::isfinite(r.Vector[c]);
    m.ZeroResult = m.ZeroResult && r.Normal[c] == 0.0 && r.Vector[c] == 0.0;
  }
  m.Finite = m.Finite && std::isfinite(r.Length);
  m.ZeroResult = m.ZeroResult && r.Length == 0.0;
  if (!m.Finite || r.Status > phongvtk::StatusDegenerate)
  {
    return m;
  }
  const double u = UnitRoundoff(mode);
  if (r.Status == phongvtk::StatusOk)
  {
    mpf_class norm2(0, bits);
    for (int c = 0; c < 3; ++c)
    {
      norm2 += Mpf(r.Normal[c]) * Mpf(r.Normal[c]);
    }
    m.UnitNormal = abs(mpf_class(sqrt(norm2), bits) - 1) <= 8 * u;
    if (!m.ExactZero)
    {
      m.NormalUlps = mode == Accuracy::Fast
        ? phongvtk_test::NormalUlpError<float>(r.Normal, t.Normal)
        : phongvtk_test::NormalUlpError<double>(r.Normal, t.Normal);
      m.NormalFaithful = phongvtk_test::NormalIsFaithful(r.Normal, t.Normal);
      m.Angle = phongvtk_test::AngleError(r.Normal, t.Normal);
    }
  }
  if (mode == Accuracy::Exact)
  {
    for (int c = 0; c < 3; ++c)
    {
      const mpf_class w(t.W.W[c], bits);
      m.VectorUlps = std::max(m.VectorUlps,
        phongvtk_test::UlpError<double>(r.Vector[c], TimesPowerOfTwo(w, -r.Exponent)));
    }
    m.LengthUlps =
      phongvtk_test::UlpError<double>(r.Length, TimesPowerOfTwo(t.Length, -r.Exponent));
    return m;
  }
  mpf_class documented[3];
  mpf_class documentedNorm2(0, bits);
  for (int c = 0; c < 3; ++c)
  {
    documented[c] = VectorBound(mode, t, c);
    documentedNorm2 += documented[c] * documented[c];
  }
  const mpf_class underflow = UnderflowTerm(mode, t, mpf_class(sqrt(documentedNorm2), bits));
  mpf_class bound[3];
  mpf_class boundNorm2(0, bits);
  for (int c = 0; c < 3; ++c)
  {
    bound[c] = documented[c] + underflow;
    boundNorm2 += bound[c] * bound[c];
    const mpf_class w(t.W.W[c], bits);
    const mpf_class error(abs(TimesPowerOfTwo(Mpf(r.Vector[c]), r.Exponent) - w), bits);
    m.VectorRatio = std::max(m.VectorRatio, Ratio(error, bound[c]));
    m.NeedsUnderflowTerm = m.NeedsUnderflowTerm || Ratio(error, documented[c]) > 1.0;
  }
  const mpf_class boundNorm(sqrt(boundNorm2), bits);
  const mpf_class lengthError(abs(TimesPowerOfTwo(Mpf(r.Length), r.Exponent) - t.Length), bits);
  m.LengthRatio = Ratio(lengthError, mpf_class(boundNorm + 3 * u * t.Length, bits));
  m.Vacuous = !(boundNorm < t.Length);
  if (!m.Vacuous && r.Status == phongvtk::StatusOk)
  {
    const mpf_class denominator(t.Length - boundNorm, bits);
    for (int c = 0; c < 3; ++c)
    {
      const mpf_class n(abs(t.Normal[c]), bits);
      const mpf_class normalBound((bound[c] + n * boundNorm) / denominator +
          NormalisationUlps(mode) * u * n + UnderflowUnit(mode),
        bits);
      const mpf_class error(abs(Mpf(r.Normal[c]) - t.Normal[c]), bits);
      m.NormalRatio = std::max(m.NormalRatio, Ratio(error, normalBound));
    }
  }
  return m;
}

/// The promises every mode makes for finite input, its documented bound (see the file comment):
/// empty when they hold, otherwise which one failed.
inline std::string BoundViolation(Accuracy mode, const Measurement& m)
{
  std::ostringstream why;
  if (!m.Finite)
  {
    why << "non-finite value in the result";
    return why.str();
  }
  if (m.Status == phongvtk::StatusDegenerate && !m.ZeroResult)
  {
    why << "status Degenerate with a non-zero result";
    return why.str();
  }
  if (m.Status == phongvtk::StatusOk && !m.UnitNormal)
  {
    why << "status Ok with a normal that is not a unit vector";
    return why.str();
  }
  if (mode == Accuracy::Exact)
  {
    const std::uint8_t expected = m.ExactZero ? phongvtk::StatusDegenerate : phongvtk::StatusOk;
    if (m.Status != expected)
    {
      why << "status " << int(m.Status) << ", expected " << int(expected)
          << (m.ExactZero ? " (exact area vector is zero)" : " (exact area vector is non-zero)");
      return why.str();
    }
    if (!m.NormalFaithful || m.VectorUlps > 2.0 || m.LengthUlps > 2.0)
    {
      why << "not faithful: normal " << m.NormalUlps << " ulp"
          << (m.NormalFaithful ? "" : " (a component is not a neighbouring double)") << ", vector "
          << m.VectorUlps << " ulp, length " << m.LengthUlps << " ulp";
      return why.str();
    }
    return std::string();
  }
  if (m.Status != phongvtk::StatusOk && m.Status != phongvtk::StatusDegenerate)
  {
    why << "status " << int(m.Status) << " for finite input";
    return why.str();
  }
  if (m.VectorRatio > 1.0 || m.LengthRatio > 1.0 || m.NormalRatio > 1.0)
  {
    why << "error / bound: vector " << m.VectorRatio << ", length " << m.LengthRatio << ", normal "
        << m.NormalRatio << " (normal " << m.NormalUlps << " ulp, angle " << m.Angle << " rad)";
    return why.str();
  }
  return std::string();
}
} // namespace phongvtk_test

#endif
