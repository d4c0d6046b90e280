// Exact fallbacks of the EXACT accuracy mode: the area vector, the visible area, the
// feature-angle decision and AutoOrientNormals' flux in GMP integer arithmetic.
//
// Every finite double is m * 2^e with an integer m of at most 53 bits. Scaling the whole polygon
// by 2^-emin (emin the smallest such e) turns every coordinate into an integer, so differences,
// cross products and their sum are exact integers; the area vector is W * 2^(2 emin). Only the
// polygons the double-double filter cannot certify come here (exact cancellation, coordinates
// outside the safe exponent window), so clarity wins over speed.
#include "PhongVTKAreaVector.h"
#include "PhongVTKAutoOrient.h"
#include "PhongVTKFeatureAngle.h"
#include "PhongVTKVisibleArea.h"

#include <gmp.h>

#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
namespace detail
{
namespace
{
/// RAII holder of an mpz_t.
class Integer
{
public:
  Integer() { mpz_init(this->Value); }
  ~Integer() { mpz_clear(this->Value); }
  Integer(const Integer&) = delete;
  Integer& operator=(const Integer&) = delete;
  mpz_ptr get() { return this->Value; }
  mpz_srcptr get() const { return this->Value; }

private:
  mpz_t Value;
};

/// x = c * 2^-emin exactly (c a finite double whose exponent is >= emin).
void SetScaled(mpz_ptr x, double c, int emin)
{
  if (c == 0.0)
  {
    mpz_set_ui(x, 0);
    return;
  }
  int e;
  const double f = std::frexp(c, &e);                  // c = f * 2^e, 0.5 <= |f| < 1
  const auto m = static_cast<long>(std::ldexp(f, 53)); // exact: 53-bit integer
  mpz_set_si(x, m);
  mpz_mul_2exp(x, x, static_cast<mp_bitcnt_t>(e - 53 - emin));
}

/// The integer z as a double-double hi + lo times 2^shift, with |hi + lo - z 2^-shift| tiny.
DD ToScaledDD(mpz_srcptr z, long shift)
{
  if (mpz_sgn(z) == 0)
  {
    return { 0.0, 0.0 };
  }
  const long bits = static_cast<long>(mpz_sizeinbase(z, 2));
  if (bits <= 53)
  {
    return { Scale2(mpz_get_d(z), static_cast<int>(-shift)), 0.0 };
  }
  // hi: the leading 53 bits (truncated); lo: the rest, rounded by mpz_get_d_2exp's truncation
  // to 53 bits, so hi + lo carries ~106 correct bits.
  Integer top, rest;
  const auto drop = static_cast<mp_bitcnt_t>(bits - 53);
  mpz_tdiv_q_2exp(top.get(), z, drop);
  mpz_mul_2exp(rest.get(), top.get(), drop);
  mpz_sub(rest.get(), z, rest.get());
  const double hi = Scale2(mpz_get_d(top.get()), static_cast<int>(static_cast<long>(drop) - shift));
  long e2 = 0;
  double lo = 0.0;
  if (mpz_sgn(rest.get()) != 0)
  {
    lo = mpz_get_d_2exp(&e2, rest.get());
    lo = Scale2(lo, static_cast<int>(e2 - shift));
  }
  double s, t;
  FastTwoSum(hi, lo, s, t);
  return { s, t };
}
/// floor(log2) of the lowest bit of the non-zero values among x[0 .. count): every one of them is
/// an integer times 2^emin. INT_MAX when all are zero.
int LowestExponent(const double* x, std::int64_t count, int emin = INT_MAX)
{
  for (std::int64_t k = 0; k < count; ++k)
  {
    if (x[k] != 0.0)
    {
      int e;
      std::frexp(x[k], &e);
      emin = std::min(emin, e - 53);
    }
  }
  return emin;
}

/// W = the exact area vector of the polygon in units of 2^(2 emin) (coordinates scaled to
/// integers by 2^-emin).
void ExactIntegerAreaVector(const double* xyz, std::int64_t n, int emin, std::array<Integer, 3>& w)
{
  std::array<Integer, 3> p0, prev, next;
  for (int c = 0; c < 3; ++c)
  {
    SetScaled(p0[c].get(), xyz[c], emin);
  }
  auto difference = [&](std::int64_t i, std::array<Integer, 3>& d)
  {
    for (int c = 0; c < 3; ++c)
    {
      SetScaled(d[c].get(), xyz[3 * i + c], emin);
      mpz_sub(d[c].get(), d[c].get(), p0[c].get());
    }
  };
  difference(1, prev);
  for (std::int64_t i = 2; i < n; ++i)
  {
    difference(i, next);
    for (int c = 0; c < 3; ++c)
    {
      const int a = (c + 1) % 3;
      const int b = (c + 2) % 3;
      mpz_addmul(w[c].get(), prev[a].get(), next[b].get());
      mpz_submul(w[c].get(), prev[b].get(), next[a].get());
    }
    for (int c = 0; c < 3; ++c)
    {
      mpz_swap(prev[c].get(), next[c].get());
    }
  }
}

/// Number of bits of the largest of the integers (0 when all are zero).
long MaxBits(const std::array<Integer, 3>& v)
{
  long bits = 0;
  for (int c = 0; c < 3; ++c)
  {
    if (mpz_sgn(v[c].get()) != 0)
    {
      bits = std::max(bits, static_cast<long>(mpz_sizeinbase(v[c].get(), 2)));
    }
  }
  return bits;
}
} // namespace

void ExactAreaVector(const double* xyz, std::int64_t n, AreaVector& out)
{
  const int emin = LowestExponent(xyz, 3 * n);
  if (emin == INT_MAX)
  {
    out.SetZero(StatusDegenerate); // every coordinate is zero
    return;
  }
  std::array<Integer, 3> w;
  ExactIntegerAreaVector(xyz, n, emin, w);

  const long bits = MaxBits(w);
  if (bits == 0)
  {
    out.SetZero(StatusDegenerate); // the exact area vector is zero
    return;
  }
  // W * 2^(500 - bits) has components below 2^500, the top of NormalizeFaithful's window: no
  // overflow, and components down to 2^-1522 of the largest one stay normal numbers. (Scaled
  // below 1, a component under 2^-1022 of the largest was first rounded to a subnormal, then
  // the division by a norm below 1 doubled that error: normal components off by 1.15 ulp.)
  const long shift = bits - 500;
  DD v[3];
  for (int c = 0; c < 3; ++c)
  {
    v[c] = ToScaledDD(w[c].get(), shift);
  }
  int k;
  double len;
  NormalizeFaithful(v, out.Normal, len, k);
  for (int c = 0; c < 3; ++c)
  {
    out.Vector[c] = Scale2(v[c].Hi, -k) + Scale2(v[c].Lo, -k);
    out.VectorLo[c] = 0.0;
  }
  out.Length = len;
  out.Exponent = static_cast<int>(shift) + k + 2 * emin;
  out.Status = StatusOk;
}

VisibleAreaResult ExactVisibleArea(
  const double* xyz, std::int64_t n, const double vector[3], bool eye)
{
  for (std::int64_t k = 0; k < 3 * n; ++k)
  {
    if (!std::isfinite(xyz[k]))
    {
      return { 0.0, StatusNonFinite };
    }
  }
  const int emin = LowestExponent(vector, 3, LowestExponent(xyz, 3 * n));
  if (n < 3 || emin == INT_MAX)
  {
    return { 0.0, StatusDegenerate };
  }
  std::array<Integer, 3> w;
  ExactIntegerAreaVector(xyz, n, emin, w);
  if (MaxBits(w) == 0)
  {
    return { 0.0, StatusDegenerate };
  }
  // S: the view vector in units of 2^emin; with an eye point, sum_i (eye - p_i) = n (eye - mean).
  std::array<Integer, 3> s;
  Integer t;
  for (int c = 0; c < 3; ++c)
  {
    SetScaled(t.get(), vector[c], emin);
    if (!eye)
    {
      mpz_set(s[c].get(), t.get());
      continue;
    }
    mpz_mul_si(s[c].get(), t.get(), static_cast<long>(n));
    for (std::int64_t i = 0; i < n; ++i)
    {
      SetScaled(t.get(), xyz[3 * i + c], emin);
      mpz_sub(s[c].get(), s[c].get(), t.get());
    }
  }
  // D = S . W in units of 2^(3 emin): the visible area is D / (2 |S|) in units of 2^(2 emin).
  Integer d;
  for (int c = 0; c < 3; ++c)
  {
    mpz_addmul(d.get(), s[c].get(), w[c].get());
  }
  if (mpz_sgn(d.get()) == 0)
  {
    return { 0.0, StatusOk }; // seen exactly edge-on (or from a point of its own plane)
  }
  // Both brought near 1 before the double-double division.
  const long shiftS = MaxBits(s) - 1;
  const long shiftD = static_cast<long>(mpz_sizeinbase(d.get(), 2)) - 1;
  DD sv[3];
  for (int c = 0; c < 3; ++c)
  {
    sv[c] = ToScaledDD(s[c].get(), shiftS);
  }
  double inverse;
  const DD norm = NormInWindow(sv, inverse);
  const double q = DivideDD(ToScaledDD(d.get(), shiftD), norm, inverse);
  const long exponent = shiftD - shiftS + 2L * emin - 1;
  const double area = std::ldexp(q, static_cast<int>(std::max(-4000L, std::min(4000L, exponent))));
  constexpr double top = std::numeric_limits<double>::max();
  return { std::max(-top, std::min(top, area)), StatusOk };
}

bool ExactFeatureEdgeIsSharp(
  const double* xyz1, std::int64_t n1, const double* xyz2, std::int64_t n2, double c)
{
  // One scale for both polygons: W1 in units of 2^(2 emin), A = W1.W2 in units of 2^(4 emin)
  // and B = |W1|^2 |W2|^2 in units of 2^(8 emin), so A and sqrt(B) compare as integers.
  const int emin = LowestExponent(xyz1, 3 * n1, LowestExponent(xyz2, 3 * n2));
  if (emin == INT_MAX)
  {
    return true; // every coordinate zero: no direction
  }
  std::array<Integer, 3> w1, w2;
  ExactIntegerAreaVector(xyz1, n1, emin, w1);
  ExactIntegerAreaVector(xyz2, n2, emin, w2);
  Integer a, b1, b2;
  for (int k = 0; k < 3; ++k)
  {
    mpz_addmul(a.get(), w1[k].get(), w2[k].get());
    mpz_addmul(b1.get(), w1[k].get(), w1[k].get());
    mpz_addmul(b2.get(), w2[k].get(), w2[k].get());
  }
  if (mpz_sgn(b1.get()) == 0 || mpz_sgn(b2.get()) == 0)
  {
    return true;
  }
  const int sa = mpz_sgn(a.get());
  // A <= c sqrt(B): with c > 0 true for A <= 0, else A^2 <= c^2 B; with c < 0 false for A >= 0,
  // else A^2 >= c^2 B; with c = 0 exactly A <= 0.
  if (c == 0.0 || (c > 0.0 && sa <= 0) || (c < 0.0 && sa >= 0))
  {
    return c == 0.0 ? sa <= 0 : c > 0.0;
  }
  // c = m 2^e with an integer m of 53 bits; |c| <= 1 makes e <= -52, so
  // A^2 <=> c^2 B is A^2 2^(-2e) <=> m^2 B.
  int e;
  const double f = std::frexp(std::fabs(c), &e);
  e -= 53;
  Integer lhs, rhs, m;
  mpz_set_d(m.get(), std::ldexp(f, 53));
  mpz_mul(lhs.get(), a.get(), a.get());
  mpz_mul_2exp(lhs.get(), lhs.get(), static_cast<mp_bitcnt_t>(-2 * e));
  mpz_mul(rhs.get(), b1.get(), b2.get());
  mpz_mul(rhs.get(), rhs.get(), m.get());
  mpz_mul(rhs.get(), rhs.get(), m.get());
  const int order = mpz_cmp(lhs.get(), rhs.get());
  return c > 0.0 ? order <= 0 : order >= 0;
}

int ExactOrientedFluxSign(const double* xyz, const std::int64_t* sizes, const signed char* signs,
  std::int64_t numPolygons, const double r[3])
{
  // One scale for every point and r: W_f in units of 2^(2 emin), (P0 - R) . W_f in 2^(3 emin).
  std::int64_t numPoints = 0;
  for (std::int64_t f = 0; f < numPolygons; ++f)
  {
    numPoints += sizes[f];
  }
  const int emin = LowestExponent(r, 3, LowestExponent(xyz, 3 * numPoints));
  if (emin == INT_MAX)
  {
    return 0; // every coordinate zero
  }
  std::array<Integer, 3> rs, w;
  for (int c = 0; c < 3; ++c)
  {
    SetScaled(rs[c].get(), r[c], emin);
  }
  Integer total, d;
  const double* p = xyz;
  for (std::int64_t f = 0; f < numPolygons; p += 3 * sizes[f], ++f)
  {
    if (sizes[f] < 3)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      mpz_set_ui(w[c].get(), 0);
    }
    ExactIntegerAreaVector(p, sizes[f], emin, w);
    for (int c = 0; c < 3; ++c)
    {
      SetScaled(d.get(), p[c], emin);
      mpz_sub(d.get(), d.get(), rs[c].get());
      if (signs[f] < 0)
      {
        mpz_neg(d.get(), d.get());
      }
      mpz_addmul(total.get(), d.get(), w[c].get());
    }
  }
  return mpz_sgn(total.get());
}

} // namespace detail
PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk
