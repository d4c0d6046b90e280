/**
 * @file PhongVTKExactReference.h
 * @brief Independent truth for the tests: the area vector in exact rational arithmetic (GMP) and
 * its unit normal in 1024-bit floating point, written directly from the definition
 * w = sum_i (p_i - p0) x (p_(i+1) - p0) and sharing no code with the filter.
 */
#ifndef PhongVTKExactReference_h
#define PhongVTKExactReference_h

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace phongvtk_test
{
using Point = std::array<double, 3>;

/// Exact area vector (twice the area, as a vector) of the polygon p0 ... p(n-1).
struct ExactAreaVector
{
  mpq_class W[3];

  bool IsZero() const { return W[0] == 0 && W[1] == 0 && W[2] == 0; }
};

inline ExactAreaVector ComputeExactAreaVector(const std::vector<Point>& polygon)
{
  ExactAreaVector r;
  const std::size_t n = polygon.size();
  if (n < 3)
  {
    return r;
  }
  // Coordinates are dyadic rationals; mpq_class(double) is exact.
  const mpq_class p0[3] = { polygon[0][0], polygon[0][1], polygon[0][2] };
  mpq_class a[3], b[3];
  for (int c = 0; c < 3; ++c)
  {
    a[c] = mpq_class(polygon[1][c]) - p0[c];
  }
  for (std::size_t i = 2; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      b[c] = mpq_class(polygon[i][c]) - p0[c];
    }
    r.W[0] += a[1] * b[2] - a[2] * b[1];
    r.W[1] += a[2] * b[0] - a[0] * b[2];
    r.W[2] += a[0] * b[1] - a[1] * b[0];
    for (int c = 0; c < 3; ++c)
    {
      a[c] = b[c];
    }
  }
  return r;
}

constexpr mp_bitcnt_t ReferenceBits = 1024;

/// The exact unit normal to 1024 bits (zero vector when w is zero).
inline std::array<mpf_class, 3> ReferenceNormal(const ExactAreaVector& w)
{
  std::array<mpf_class, 3> n = { mpf_class(0, ReferenceBits), mpf_class(0, ReferenceBits),
    mpf_class(0, ReferenceBits) };
  mpf_class sum(0, ReferenceBits);
  mpf_class x[3] = { mpf_class(0, ReferenceBits), mpf_class(0, ReferenceBits),
    mpf_class(0, ReferenceBits) };
  for (int c = 0; c < 3; ++c)
  {
    x[c] = w.W[c];
    sum += x[c] * x[c];
  }
  if (sum == 0)
  {
    return n;
  }
  mpf_class norm(sqrt(sum), ReferenceBits);
  for (int c = 0; c < 3; ++c)
  {
    n[c] = x[c] / norm;
  }
  return n;
}

/// Twice the exact area |w| to 1024 bits.
inline mpf_class ReferenceLength(const ExactAreaVector& w)
{
  mpf_class sum(0, ReferenceBits);
  for (int c = 0; c < 3; ++c)
  {
    mpf_class x(w.W[c], ReferenceBits);
    sum += x * x;
  }
  return mpf_class(sqrt(sum), ReferenceBits);
}

/**
 * Distance between a computed value and the exact one, in units in the last place of the exact
 * value in the format Real (float or double): the spacing of Real numbers in the binade of the
 * exact value (the smallest subnormal below the normal range). Faithful rounding gives < 1.
 */
template <class Real>
double UlpError(double computed, const mpf_class& exact)
{
  mpf_class e(exact, ReferenceBits);
  const mpf_class diff(abs(mpf_class(computed, ReferenceBits) - e), ReferenceBits);
  if (e == 0)
  {
    return computed == 0.0
      ? 0.0
      : diff.get_d() / static_cast<double>(std::numeric_limits<Real>::denorm_min());
  }
  long exponent; // |exact| = m * 2^exponent with 0.5 <= m < 1
  mpf_get_d_2exp(&exponent, e.get_mpf_t());
  const int digits = std::numeric_limits<Real>::digits;
  const long minExponent = std::numeric_limits<Real>::min_exponent; // 2^(min_exponent - 1) = min
  const long ulpExponent = std::max(exponent, minExponent) - digits;
  mpf_class ulp(1, ReferenceBits);
  if (ulpExponent >= 0)
  {
    mpf_mul_2exp(ulp.get_mpf_t(), ulp.get_mpf_t(), static_cast<mp_bitcnt_t>(ulpExponent));
  }
  else
  {
    mpf_div_2exp(ulp.get_mpf_t(), ulp.get_mpf_t(), static_cast<mp_bitcnt_t>(-ulpExponent));
  }
  return mpf_class(diff / ulp, ReferenceBits).get_d();
}

/**
 * Whether `computed` is a faithful rounding of `exact` to double: one of the two doubles next to
 * it, and the exact value itself when that is a double (so 0 for an exact 0, and 1 - 2^-53 is
 * not faithful for an exact 1, although it lies half an ulp of 1's binade away).
 */
inline bool IsFaithful(double computed, const mpf_class& exact)
{
  const mpf_class e(exact, ReferenceBits);
  const double towardZero = e.get_d(); // GMP truncates
  if (mpf_class(towardZero, ReferenceBits) == e)
  {
    return computed == towardZero;
  }
  const double away = std::nextafter(towardZero, e > 0 ? HUGE_VAL : -HUGE_VAL);
  return computed == towardZero || computed == away;
}

/// Whether every component of a computed unit normal is a faithful rounding (IsFaithful).
inline bool NormalIsFaithful(const double computed[3], const std::array<mpf_class, 3>& exact)
{
  return IsFaithful(computed[0], exact[0]) && IsFaithful(computed[1], exact[1]) &&
    IsFaithful(computed[2], exact[2]);
}

/// Largest UlpError over the three components of a unit normal.
template <class Real>
double NormalUlpError(const double computed[3], const std::array<mpf_class, 3>& exact)
{
  double worst = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    worst = std::max(worst, UlpError<Real>(computed[c], exact[c]));
  }
  return worst;
}

/// Angle in radians between a computed unit normal and the exact one (pi/2 for a zero vector).
inline double AngleError(const double computed[3], const std::array<mpf_class, 3>& exact)
{
  mpf_class cross2(0, ReferenceBits), dot(0, ReferenceBits);
  mpf_class n[3] = { mpf_class(computed[0], ReferenceBits), mpf_class(computed[1], ReferenceBits),
    mpf_class(computed[2], ReferenceBits) };
  for (int c = 0; c < 3; ++c)
  {
    const int a = (c + 1) % 3;
    const int b = (c + 2) % 3;
    mpf_class x(n[a] * exact[b] - n[b] * exact[a], ReferenceBits);
    cross2 += x * x;
    dot += n[c] * exact[c];
  }
  return std::atan2(std::sqrt(cross2.get_d()), dot.get_d());
}
} // namespace phongvtk_test

#endif
