/**
 * @file PhongVTKAreaVector.h
 * @brief Private arithmetic kernels of vtkPolygonNormals and vtkVisibleArea: the summed
 * cross-product rule w = sum_i (p_i - p0) x (p_(i+1) - p0) in four accuracy modes.
 *
 * The kernels know nothing about VTK data structures: a polygon is a point coordinate array and a
 * function mapping the polygon's vertex index to a point id. One loop skeleton (`AccumulateFan`)
 * serves every mode; the modes differ only in the arithmetic type plugged into it.
 *
 * Error bounds (u = 2^-53 for double, u_f = 2^-24 for float; T = number of fan triangles =
 * n - 2; P_c = sum of |products| entering component c of w, the condition of that component):
 *
 *   FAST         |error of w_c| <= (T + 3) u_f P_c;  unit normal: + 4.5 u_f |n_c| per component.
 *                Differences of double points are rounded to float: add 2 u P_c.
 *   DOUBLE       |error of w_c| <= (T + 3) u P_c;  unit normal: + 3.5 u |n_c| per component.
 *   COMPENSATED  |error of w_c| <= u |w_c| + (T + 65) u^2 P_c to first order (the rounding of
 *                the error accumulator can reach T (T + 4) u^2 P_c when partial sums grow
 *                coherently; not observed); unit normal: + 3.5 u |n_c|. A few ulp unless
 *                P_c > |w_c| / u.
 *   EXACT        exact area vector (certified double-double, else GMP integers); every component
 *                of the unit normal within 1 ulp of w_c / |w| (faithful), zero exactly when the
 *                exact w is zero.
 *
 * The unit normal's term is the normalisation: |w| from a rounded sum of squares and a square
 * root (2.5 u), then a division (1 u), or for FAST a rounded reciprocal and a product (2 u_f),
 * added to the error of w carried through w / |w| (TestAreaVectorKernels.cxx states it whole).
 *
 * Underflow adds an absolute term to the inexact modes: a component below 2^-126 (float) or
 * 2^-1022 (double) of the polygon's own size cannot be resolved by one exponent; such components
 * carry up to 16 (T + 3) eta D^2 (eta = 2^-150 or 2^-1075, D the largest coordinate difference)
 * while the direction stays exact to that level.
 *
 * Every mode is protected against overflow and underflow: when the direct evaluation leaves the
 * safe exponent window, the polygon is re-evaluated on differences scaled by exact powers of two
 * (per axis for FAST, DOUBLE and COMPENSATED, so that extents spanning more binades than the
 * arithmetic holds lose nothing; uniformly for EXACT, whose fallback is exact integer arithmetic).
 * Non-finite coordinates give status NonFinite and a zero normal; a zero area vector gives status
 * Degenerate and a zero normal (for EXACT: exactly when the exact area vector is zero).
 */
#ifndef PhongVTKAreaVector_h
#define PhongVTKAreaVector_h

#include "PhongVTKKernelNamespace.h"
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

// Clang keeps this header's arithmetic uncontracted even where the includer contracts (its
// decision is made per expression, before inlining); GCC's is the flag (PhongVTKKernelNamespace.h).
#if defined(__clang__)
#pragma float_control(push)
#pragma clang fp contract(off)
#endif

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN

/// Accuracy modes, numbered as vtkPolygonNormals::FAST ... EXACT.
enum class Accuracy : int
{
  Fast = 0,
  Double = 1,
  Compensated = 2,
  Exact = 3
};

/// Values of the NormalStatus cell array.
enum NormalStatus : std::uint8_t
{
  StatusOk = 0,
  StatusDegenerate = 1,
  StatusNonFinite = 2,
  StatusNotSurface = 3,
  /// Consistency: a polygon along an edge where a non-orientable surface still disagrees (its
  /// normal is computed as usual).
  StatusInconsistent = 4,
  /// Internal: Vector (+ VectorLo) holds w, the normal is still to be computed (see
  /// ComputeAreaVectorDeferred); never stored in an output.
  StatusPending = 255
};

/**
 * Result for one polygon. The true area vector (twice the area, as a vector) is
 * `Vector * 2^Exponent`; Exponent is zero except for polygons that needed rescaling.
 */
struct AreaVector
{
  double Normal[3];
  double Vector[3];
  double VectorLo[3]; // low parts of Vector while Status is StatusPending (EXACT only)
  double Length;      // |Vector|
  int Exponent;
  std::uint8_t Status;

  void SetZero(std::uint8_t status)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Normal[c] = 0.0;
      this->Vector[c] = 0.0;
      this->VectorLo[c] = 0.0;
    }
    this->Length = 0.0;
    this->Exponent = 0;
    this->Status = status;
  }
};

namespace detail
{
#if defined(__GNUC__)
#define PHONGVTK_INLINE inline __attribute__((always_inline))
#else
#define PHONGVTK_INLINE inline
#endif

//------------------------------------------------------------------------------
// Error-free transformations (Knuth's TwoSum, FMA-based TwoProduct).
PHONGVTK_INLINE void TwoSum(double a, double b, double& s, double& e)
{
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

PHONGVTK_INLINE void FastTwoSum(double a, double b, double& s, double& e)
{
  s = a + b;
  e = b - (s - a);
}

PHONGVTK_INLINE double Fma(double a, double b, double c)
{
#if defined(PHONGVTK_HAVE_AVX_FMA)
  return __builtin_fma(a, b, c);
#else
  return std::fma(a, b, c);
#endif
}

PHONGVTK_INLINE void TwoProduct(double a, double b, double& p, double& e)
{
  p = a * b;
  e = Fma(a, b, -p);
}

/// A double-double number hi + lo with |lo| <= ulp(hi)/2.
struct DD
{
  double Hi;
  double Lo;
};

PHONGVTK_INLINE DD Add(DD a, DD b)
{
  double s, e, t, f;
  TwoSum(a.Hi, b.Hi, s, e);
  TwoSum(a.Lo, b.Lo, t, f);
  e += t;
  FastTwoSum(s, e, s, e);
  e += f;
  FastTwoSum(s, e, s, e);
  return { s, e };
}

/// Three coordinates (x, y, z, 0) in one SIMD register (GCC/Clang vector extension). The
/// alignment is explicit: GCC aligns a 32-byte vector to 32 bytes only where AVX is enabled and
/// to 16 elsewhere, and the two kernel sets (PhongVTKKernelNamespace.h) share the standard
/// library's allocators, which must agree with the kernels on the alignment of what holds them.
typedef double V4 __attribute__((vector_size(32), aligned(32)));
typedef long long V4i __attribute__((vector_size(32), aligned(32)));

template <class T>
PHONGVTK_INLINE V4 Load(const T* p)
{
  return V4{ static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]), 0.0 };
}

// Lane permutations: GCC's __builtin_shuffle, Clang's __builtin_shufflevector.
#if defined(__clang__)
#define PHONGVTK_SHUFFLE4(v, a, b, c, d) __builtin_shufflevector(v, v, a, b, c, d)
#else
#define PHONGVTK_SHUFFLE4(v, a, b, c, d) __builtin_shuffle(v, V4i{ a, b, c, d })
#endif

PHONGVTK_INLINE V4 RotateYZX(V4 v)
{
  return PHONGVTK_SHUFFLE4(v, 1, 2, 0, 3);
}

PHONGVTK_INLINE V4 RotateZXY(V4 v)
{
  return PHONGVTK_SHUFFLE4(v, 2, 0, 1, 3);
}

PHONGVTK_INLINE V4 Abs(V4 v)
{
  constexpr long long magnitude = 0x7fffffffffffffffLL; // clears the sign bit
  return reinterpret_cast<V4>(reinterpret_cast<V4i>(v) & magnitude);
}

PHONGVTK_INLINE V4 Fma(V4 a, V4 b, V4 c)
{
#if defined(PHONGVTK_HAVE_AVX_FMA)
  return reinterpret_cast<V4>(_mm256_fmadd_pd(
    reinterpret_cast<__m256d>(a), reinterpret_cast<__m256d>(b), reinterpret_cast<__m256d>(c)));
#else
  return V4{ Fma(a[0], b[0], c[0]), Fma(a[1], b[1], c[1]), Fma(a[2], b[2], c[2]),
    Fma(a[3], b[3], c[3]) };
#endif
}

PHONGVTK_INLINE void TwoSum(V4 a, V4 b, V4& s, V4& e)
{
  s = a + b;
  const V4 bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

PHONGVTK_INLINE void TwoProduct(V4 a, V4 b, V4& p, V4& e)
{
  p = a * b;
  e = Fma(a, b, -p);
}

//------------------------------------------------------------------------------
// What the accuracy modes decide by, written once for the per-polygon kernel and the four-lane
// triangle kernel (and the point and visible-area kernels that share them).

/// A safe exponent window: a vector whose largest |component| lies in [Bottom, Top] is squared,
/// summed and divided without overflow or harmful underflow.
struct SafeWindow
{
  double Bottom, Top;
};
/// Double arithmetic (DOUBLE, COMPENSATED, EXACT, and the normalisations).
constexpr SafeWindow DoubleWindow = { 0x1p-500, 0x1p500 };
/// FAST's float arithmetic.
constexpr SafeWindow FloatWindow = { 0x1p-60, 0x1p60 };

/// EXACT: a non-zero coordinate difference below this (once scaled) may have products that
/// underflowed to zero and would pass for an exact zero; such polygons go to the exact fallback.
constexpr double TinyDifference = 0x1p-480;
/// EXACT's certificate: every component's error bound below this relative error (so that
/// NormalizeFaithful returns a faithful normal) ...
constexpr double CertifiedRelativeError = 0x1p-56;
/// ... and no sum of product magnitudes above this (no overflow risk; NaN fails the test).
constexpr double PermanentLimit = 0x1p900;

/**
 * One step of the compensated cross product (COMPENSATED and EXACT) for the components held in
 * the lanes: a1 b2 - a2 b1 with a = ah + al, b = bh + bl (al bl is second order and dropped).
 * The leading part is added to `sum` by TwoSum and every first-order error term to `err`; with
 * TrackBound, |p1| + |p2| to `permanent` and |error term| to `errMagnitude` (CompensatedBound).
 * The per-polygon kernel calls it with the three components of one polygon in the lanes, the
 * four-lane kernel with one component of four triangles.
 */
template <bool TrackBound>
PHONGVTK_INLINE void CompensatedCrossStep(V4 a1h, V4 a1l, V4 a2h, V4 a2l, V4 b1h, V4 b1l, V4 b2h,
  V4 b2l, V4& sum, V4& err, V4& permanent, V4& errMagnitude)
{
  V4 p1, e1, p2, e2, s, e, t, f;
  TwoProduct(a1h, b2h, p1, e1);
  TwoProduct(a2h, b1h, p2, e2);
  TwoSum(p1, -p2, s, e);
  TwoSum(sum, s, t, f);
  sum = t;
  const V4 first = Fma(a1h, b2l, Fma(a1l, b2h, Fma(-a2h, b1l, -(a2l * b1h))));
  const V4 term = (e + f) + ((e1 - e2) + first);
  err += term;
  if (TrackBound)
  {
    permanent += Abs(p1) + Abs(p2);
    errMagnitude += Abs(term);
  }
}

/**
 * Bound on |(hi + lo) - w_c| per lane, where hi + lo = TwoSum(sum, err) of CompensatedCrossStep
 * over `triangles` - 1 fan triangles and w the exact area vector: the neglected second-order
 * products, the rounding of the error accumulator, and an absolute slack for error terms lost to
 * underflow (at most 2^-1074 per operation).
 */
PHONGVTK_INLINE V4 CompensatedBound(V4 permanent, V4 errMagnitude, V4 err, double triangles)
{
  const double underflow = 32.0 * triangles * 0x1p-1074;
  return 64.0 * 0x1p-106 * permanent + (1.01 * triangles * 0x1p-53) * errMagnitude +
    0x1p-53 * Abs(err) + underflow;
}

/// Lanes certified by EXACT's filter: no overflow risk and no non-finite input, and either every
/// product exactly zero (permanent == 0) or the bound within CertifiedRelativeError of |hi|.
PHONGVTK_INLINE V4i Certified(V4 permanent, V4 bound, V4 hi)
{
  return (permanent <= PermanentLimit) &
    ((permanent == 0.0) | (bound <= CertifiedRelativeError * Abs(hi)));
}

/// w += a x b, component c being a_(c+1) b_(c+2) - a_(c+2) b_(c+1): the fan's step of FAST and
/// DOUBLE (R float or double, one polygon) and of their four-lane kernel (R a lane type, one
/// component of four triangles per lane, from w = 0).
template <class R>
PHONGVTK_INLINE void AddCross(const R a[3], const R b[3], R w[3])
{
  for (int c = 0; c < 3; ++c)
  {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    w[c] += a[c1] * b[c2] - a[c2] * b[c1];
  }
}

/// Largest |component|; NaN when a component is NaN, which std::max alone may drop (a NaN area
/// vector would then pass the safe-window tests).
template <class Real>
PHONGVTK_INLINE Real MaxAbs3(const Real v[3])
{
  const Real a = std::fabs(v[0]), b = std::fabs(v[1]), c = std::fabs(v[2]);
  const Real sum = a + b + c; // NaN exactly when a component is NaN: no term is negative
  return sum == sum ? std::max(a, std::max(b, c)) : sum;
}

/// 2^k for k in [-1022, 1023], built from its bits (std::ldexp is a slow library call).
PHONGVTK_INLINE double Pow2(int k)
{
  const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof(x));
  return x;
}

/// x * 2^k, exact unless the result leaves the normal range (then rounded once, like ldexp).
PHONGVTK_INLINE double Scale2(double x, int k)
{
  if (k >= -1022 && k <= 1023)
  {
    return x * Pow2(k);
  }
  return std::ldexp(x, k);
}

/// floor(log2|m|) for finite non-zero m.
PHONGVTK_INLINE int Exponent2(double m)
{
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof(bits));
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  return biased != 0 ? biased - 1023 : std::ilogb(m);
}

/**
 * x rounded to float (and back to double). Out of line on purpose: GCC 12 at -O3 vectorises a
 * pair of such roundings written in place (`n[c] = static_cast<float>(n[c])` after n was
 * stored) and drops them, leaving FAST's scaled-path normals unrounded for two of three
 * components, and then only in some of the places it inlines them (found by TestKernelSets;
 * reproduced with g++ 12.2 -O3 on FinishScaled alone, not at -O2 nor with Clang). The slow paths
 * that use it are rare; a call costs nothing there.
 */
__attribute__((noinline)) inline double RoundToFloat(double x)
{
  return static_cast<float>(x);
}

/**
 * Unit vector and length of a double vector, safe for every finite input: when the largest
 * component leaves [2^-500, 2^500] the vector is first scaled by an exact power of two.
 * Returns false (and leaves n untouched) for the zero vector.
 */
inline bool NormalizeDouble(const double w[3], double n[3], double& length, int& exponent)
{
  double m = MaxAbs3(w);
  exponent = 0;
  double v[3] = { w[0], w[1], w[2] };
  if (!(m >= DoubleWindow.Bottom && m <= DoubleWindow.Top))
  {
    if (m == 0.0)
    {
      return false;
    }
    const int k = Exponent2(m);
    for (int c = 0; c < 3; ++c)
    {
      v[c] = Scale2(v[c], -k);
    }
    exponent = k;
  }
  const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int c = 0; c < 3; ++c)
  {
    n[c] = v[c] / len;
  }
  length = len;
  return true;
}

/**
 * |v| of a double-double vector whose largest component lies in [2^-500, 2^500], in
 * double-double (relative error ~2^-100); `inverse` receives 1 / norm.Hi rounded.
 */
PHONGVTK_INLINE DD NormInWindow(const DD v[3], double& inverse)
{
  // |v|^2 in double-double: the three leading squares are summed exactly (TwoSum); the error
  // terms (square errors, cross terms 2 hi lo, sum errors) are O(u |v|^2) and summed in double.
  double p[3], e[3];
  for (int c = 0; c < 3; ++c)
  {
    TwoProduct(v[c].Hi, v[c].Hi, p[c], e[c]);
    e[c] += 2.0 * v[c].Hi * v[c].Lo;
  }
  double s1, t1, s2, t2;
  TwoSum(p[0], p[1], s1, t1);
  TwoSum(s1, p[2], s2, t2);
  DD s;
  FastTwoSum(s2, (t1 + t2) + (e[0] + e[1] + e[2]), s.Hi, s.Lo);
  // sqrt in double-double: one Newton correction of the double square root.
  const double r = std::sqrt(s.Hi);
  inverse = 1.0 / r;
  const double residual = Fma(-r, r, s.Hi) + s.Lo;
  DD norm;
  FastTwoSum(r, 0.5 * residual * inverse, norm.Hi, norm.Lo);
  return norm;
}

/// (a.Hi + a.Lo) / (b.Hi + b.Lo) rounded to double, relative error ~2^-100 before the final
/// rounding; `inverse` is 1 / b.Hi rounded.
PHONGVTK_INLINE double DivideDD(DD a, DD b, double inverse)
{
  const double q1 = a.Hi * inverse;
  const double rem = Fma(-q1, b.Hi, a.Hi) + (a.Lo - q1 * b.Lo);
  return q1 + rem * inverse;
}

/**
 * Faithful unit vector of a double-double vector: each returned component is within 1 ulp of the
 * exact w_c/|w| when every component of w carries a relative error below 2^-56. The norm,
 * square root and quotients are evaluated in double-double (error ~2^-100), so the only
 * rounding that matters is the final one to double. Returns false for the zero vector.
 */
inline bool NormalizeFaithful(const DD w[3], double n[3], double& length, int& exponent)
{
  const double m = std::max(std::fabs(w[0].Hi), std::max(std::fabs(w[1].Hi), std::fabs(w[2].Hi)));
  if (m == 0.0)
  {
    return false;
  }
  // Squares of components in [2^-500, 2^500] neither overflow nor lose the low parts to
  // underflow; outside that window the vector is first scaled by an exact power of two, to the
  // top of the window: components down to 2^-1522 of the largest stay normal numbers. (Scaled
  // to [1, 2), a component under 2^-1022 of the largest had its high and low parts rounded to
  // subnormals separately and the quotient was off by more than 1 ulp.)
  const int k = (m >= DoubleWindow.Bottom && m <= DoubleWindow.Top) ? 0 : Exponent2(m) - 499;
  DD v[3];
  for (int c = 0; c < 3; ++c)
  {
    v[c] = k == 0 ? w[c] : DD{ Scale2(w[c].Hi, -k), Scale2(w[c].Lo, -k) };
  }
  // One reciprocal serves every quotient: q1 = v.Hi / norm is only a first approximation, the
  // remainder v - q1 * norm is evaluated (nearly) exactly, so the correction rem / norm needs
  // only a few correct bits and the reciprocal's rounding error vanishes at second order.
  double inverse;
  const DD norm = NormInWindow(v, inverse);
  for (int c = 0; c < 3; ++c)
  {
    n[c] = DivideDD(v[c], norm, inverse);
  }
  length = norm.Hi;
  exponent = k;
  return true;
}

//------------------------------------------------------------------------------
/// Scaling applied to the differences on the slow path: component c of a difference is
/// ((p_c * Pre) - (p0_c * Pre)) * 2^Shift[c].
struct Scaling
{
  double Pre = 1.0;
  int Shift[3] = { 0, 0, 0 };

  /// log2 of the factor that turns scaled differences of component c back into true ones.
  int Unscale(int c) const { return -this->Shift[c] + (this->Pre != 1.0 ? 2 : 0); }
};

/**
 * The loop skeleton shared by every accuracy mode: w = sum over the fan from p0.
 * `vertex(i)` returns a pointer to the coordinates of the polygon's i-th vertex.
 */
template <bool Scaled, class Arith, class VertexFn>
PHONGVTK_INLINE void AccumulateFan(
  Arith& acc, const VertexFn& vertex, std::int64_t n, const Scaling& scaling)
{
  using Diff = typename Arith::Diff;
  const auto* p0 = vertex(0);
  Diff prev = Arith::template Difference<Scaled>(vertex(1), p0, scaling);
  if (n == 3)
  {
    // Triangles, the common case, without a loop: the accumulator then stays in registers.
    acc.Add(prev, Arith::template Difference<Scaled>(vertex(2), p0, scaling));
    return;
  }
  for (std::int64_t i = 2; i < n; ++i)
  {
    const Diff next = Arith::template Difference<Scaled>(vertex(i), p0, scaling);
    acc.Add(prev, next);
    prev = next;
  }
}

template <bool Scaled, class T>
PHONGVTK_INLINE double ScaledDifference(T a, T b, const Scaling& s, int c)
{
  if (!Scaled)
  {
    return static_cast<double>(a) - static_cast<double>(b);
  }
  const double d = static_cast<double>(a) * s.Pre - static_cast<double>(b) * s.Pre;
  return Scale2(d, s.Shift[c]);
}

//------------------------------------------------------------------------------
/// FAST: float32 arithmetic. Differences of nearby points are taken in the points' own
/// precision (exact by Sterbenz's lemma for double points too), then everything is float.
template <class T>
struct FastArith
{
  struct Diff
  {
    float V[3];
  };
  float W[3] = { 0.0f, 0.0f, 0.0f };

  template <bool Scaled>
  static PHONGVTK_INLINE Diff Difference(const T* p, const T* p0, const Scaling& s)
  {
    Diff d;
    for (int c = 0; c < 3; ++c)
    {
      d.V[c] = Scaled ? static_cast<float>(ScaledDifference<true>(p[c], p0[c], s, c))
                      : static_cast<float>(p[c] - p0[c]);
    }
    return d;
  }

  PHONGVTK_INLINE void Add(const Diff& a, const Diff& b) { AddCross(a.V, b.V, this->W); }

  void Raw(double w[3]) const
  {
    for (int c = 0; c < 3; ++c)
    {
      w[c] = this->W[c];
    }
  }

  /// Direct result if it is inside float's safe window, else false (caller rescales).
  PHONGVTK_INLINE bool Finish(AreaVector& out, bool mustSucceed) const
  {
    const float m = MaxAbs3(this->W);
    if (m >= FloatWindow.Bottom && m <= FloatWindow.Top)
    {
      for (int c = 0; c < 3; ++c)
      {
        out.Vector[c] = this->W[c];
      }
      out.Exponent = 0;
      out.Status = StatusPending;
      return true;
    }
    // Large but finite: nothing underflowed that matters, the direct result only needs a scaled
    // normalisation. Tiny, zero or non-finite: the caller re-evaluates on scaled differences.
    if (!mustSucceed && !(m > FloatWindow.Top && m <= std::numeric_limits<float>::max()))
    {
      return false;
    }
    const double w[3] = { this->W[0], this->W[1], this->W[2] };
    return FinishDouble(w, out);
  }

  /// The normal of a pending result, in float arithmetic (Vector holds float values exactly).
  static PHONGVTK_INLINE void Complete(AreaVector& out)
  {
    const float w[3] = { static_cast<float>(out.Vector[0]), static_cast<float>(out.Vector[1]),
      static_cast<float>(out.Vector[2]) };
    const float len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const float inv = 1.0f / len;
    for (int c = 0; c < 3; ++c)
    {
      out.Normal[c] = w[c] * inv;
    }
    out.Length = len;
    out.Status = StatusOk;
  }

  static bool FinishDouble(const double w[3], AreaVector& out)
  {
    int k;
    if (!(std::isfinite(w[0]) && std::isfinite(w[1]) && std::isfinite(w[2])) ||
      !NormalizeDouble(w, out.Normal, out.Length, k))
    {
      out.SetZero(StatusDegenerate);
      return true;
    }
    for (int c = 0; c < 3; ++c)
    {
      out.Vector[c] = Scale2(w[c], -k);
      out.Normal[c] = RoundToFloat(out.Normal[c]);
    }
    out.Exponent = k;
    out.Status = StatusOk;
    return true;
  }
};

//------------------------------------------------------------------------------
/// DOUBLE: double arithmetic, fan from p0 (what VTK does).
template <class T>
struct DoubleArith
{
  struct Diff
  {
    double V[3];
  };
  double W[3] = { 0.0, 0.0, 0.0 };

  template <bool Scaled>
  static PHONGVTK_INLINE Diff Difference(const T* p, const T* p0, const Scaling& s)
  {
    Diff d;
    for (int c = 0; c < 3; ++c)
    {
      d.V[c] = ScaledDifference<Scaled>(p[c], p0[c], s, c);
    }
    return d;
  }

  PHONGVTK_INLINE void Add(const Diff& a, const Diff& b) { AddCross(a.V, b.V, this->W); }

  PHONGVTK_INLINE bool Finish(AreaVector& out, bool mustSucceed) const
  {
    return FinishVector(this->W, out, mustSucceed);
  }

  void Raw(double w[3]) const { std::copy(this->W, this->W + 3, w); }

  /// The normal of a pending result (Vector inside the safe window).
  static PHONGVTK_INLINE void Complete(AreaVector& out)
  {
    const double* w = out.Vector;
    const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    // The three quotients in one SIMD division (the same correctly rounded IEEE quotients as
    // three scalar divisions, at a third of their throughput cost).
    const V4 n = V4{ w[0], w[1], w[2], 1.0 } / len;
    for (int c = 0; c < 3; ++c)
    {
      out.Normal[c] = n[c];
    }
    out.Length = len;
    out.Status = StatusOk;
  }

  static PHONGVTK_INLINE bool FinishVector(const double w[3], AreaVector& out, bool mustSucceed)
  {
    const double m = MaxAbs3(w);
    if (m >= DoubleWindow.Bottom && m <= DoubleWindow.Top)
    {
      for (int c = 0; c < 3; ++c)
      {
        out.Vector[c] = w[c];
      }
      out.Exponent = 0;
      out.Status = StatusPending;
      return true;
    }
    // Large but finite: the direct result only needs a scaled normalisation (re-evaluating on
    // differences scaled down could flush small ones to zero). Tiny, zero or non-finite: the
    // caller re-evaluates on scaled differences.
    if (!mustSucceed && !(m > DoubleWindow.Top && m <= std::numeric_limits<double>::max()))
    {
      return false;
    }
    int k;
    if (!std::isfinite(m) || !NormalizeDouble(w, out.Normal, out.Length, k))
    {
      out.SetZero(StatusDegenerate);
      return true;
    }
    for (int c = 0; c < 3; ++c)
    {
      out.Vector[c] = Scale2(w[c], -k);
    }
    out.Exponent = k;
    out.Status = StatusOk;
    return true;
  }
};

//------------------------------------------------------------------------------
/**
 * COMPENSATED (and the filter stage of EXACT): the differences are split into exact
 * double-double values (TwoDiff), every product is split by an FMA TwoProduct, the leading parts
 * are summed with TwoSum and every first-order error term is kept in a second accumulator. The
 * neglected terms are the second-order products of the differences' low parts and the rounding
 * of the error accumulator: |error of w_c| <= 64 u^2 P_c + 1.01 (T + 1) u M_c + u |Err_c| where
 * M_c is the sum of the magnitudes added to the error accumulator Err_c.
 * With `TrackBound`, P_c and M_c are accumulated so that EXACT can certify the result.
 */
template <class T, bool TrackBound>
struct CompensatedArith
{
  /// A difference p - p0 as the exact double-double Hi + Lo, with the lane rotations the cross
  /// product needs (yzx, zxy), computed once per vertex.
  struct Diff
  {
    V4 Hi, Lo, HiYZX, HiZXY, LoYZX, LoZXY;
  };
  V4 S = {};            // leading sum
  V4 Err = {};          // every error term of the leading sum and of the products
  V4 Permanent = {};    // P_c, sum of |products| (only with TrackBound)
  V4 ErrMagnitude = {}; // M_c, sum of |terms added to Err| (only with TrackBound)

  template <bool Scaled>
  static PHONGVTK_INLINE Diff Difference(const T* p, const T* p0, const Scaling& s)
  {
    V4 a = Load(p);
    V4 b = Load(p0);
    if (Scaled)
    {
      a *= s.Pre;
      b *= s.Pre;
    }
    Diff d;
    TwoSum(a, -b, d.Hi, d.Lo);
    if (Scaled)
    {
      for (int c = 0; c < 3; ++c)
      {
        d.Hi[c] = Scale2(d.Hi[c], s.Shift[c]);
        d.Lo[c] = Scale2(d.Lo[c], s.Shift[c]);
      }
    }
    d.HiYZX = RotateYZX(d.Hi);
    d.HiZXY = RotateZXY(d.Hi);
    d.LoYZX = RotateYZX(d.Lo);
    d.LoZXY = RotateZXY(d.Lo);
    return d;
  }

  PHONGVTK_INLINE void Add(const Diff& a, const Diff& b)
  {
    // Component c of a x b is a_(c+1) b_(c+2) - a_(c+2) b_(c+1), all three lanes at once.
    CompensatedCrossStep<TrackBound>(a.HiYZX, a.LoYZX, a.HiZXY, a.LoZXY, b.HiYZX, b.LoYZX, b.HiZXY,
      b.LoZXY, this->S, this->Err, this->Permanent, this->ErrMagnitude);
  }

  void Raw(double w[3]) const
  {
    const V4 sum = this->S + this->Err;
    for (int c = 0; c < 3; ++c)
    {
      w[c] = sum[c];
    }
  }

  /// COMPENSATED finish: double area vector, double normalisation.
  PHONGVTK_INLINE bool Finish(AreaVector& out, bool mustSucceed) const
  {
    const V4 sum = this->S + this->Err;
    const double w[3] = { sum[0], sum[1], sum[2] };
    return DoubleArith<T>::FinishVector(w, out, mustSucceed);
  }

  /**
   * Bound on |(hi + lo) - w_c| per component, where hi + lo = TwoSum(S, Err) and w is the exact
   * area vector of the n-gon (TrackBound only): the neglected second-order products, the rounding
   * of the error accumulator, and an absolute slack for error terms lost to underflow (at most
   * 2^-1074 per operation).
   */
  PHONGVTK_INLINE V4 Bound(std::int64_t n) const
  {
    // n - 1: the fan's triangles + 1.
    return CompensatedBound(
      this->Permanent, this->ErrMagnitude, this->Err, static_cast<double>(n - 1));
  }

  /**
   * EXACT filter: true when every component is certified to carry a relative error below 2^-56
   * (or is certified exactly zero), so that NormalizeFaithful returns a faithful normal.
   * `hasTinyDifference()` is asked only when a component's products were all zero: a product
   * that underflowed to zero would pass for an exact zero, so a non-zero difference below
   * 2^-480 leaves the polygon to the exact fallback.
   */
  template <class TinyFn>
  PHONGVTK_INLINE bool FinishCertified(
    AreaVector& out, std::int64_t n, const TinyFn& hasTinyDifference) const
  {
    V4 hi, lo;
    TwoSum(this->S, this->Err, hi, lo);
    const V4i certified = Certified(this->Permanent, this->Bound(n), hi);
    if (!(certified[0] & certified[1] & certified[2]))
    {
      return false;
    }
    if ((this->Permanent[0] == 0.0 || this->Permanent[1] == 0.0 || this->Permanent[2] == 0.0) &&
      hasTinyDifference())
    {
      return false;
    }
    if (hi[0] == 0.0 && hi[1] == 0.0 && hi[2] == 0.0)
    {
      out.SetZero(StatusDegenerate); // certified: every product was exactly zero
      return true;
    }
    for (int c = 0; c < 3; ++c)
    {
      out.Vector[c] = hi[c];
      out.VectorLo[c] = lo[c];
    }
    out.Exponent = 0;
    out.Status = StatusPending;
    return true;
  }

  /// COMPENSATED: the normal of a pending result, in double.
  static PHONGVTK_INLINE void Complete(AreaVector& out) { DoubleArith<T>::Complete(out); }

  /// EXACT: the faithful normal of a pending certified double-double area vector.
  static PHONGVTK_INLINE void CompleteFaithful(AreaVector& out)
  {
    const DD w[3] = { { out.Vector[0], out.VectorLo[0] }, { out.Vector[1], out.VectorLo[1] },
      { out.Vector[2], out.VectorLo[2] } };
    int k;
    double len;
    NormalizeFaithful(w, out.Normal, len, k);
    for (int c = 0; c < 3; ++c)
    {
      out.Vector[c] = k == 0 ? w[c].Hi + w[c].Lo : Scale2(w[c].Hi, -k) + Scale2(w[c].Lo, -k);
      out.VectorLo[c] = 0.0;
    }
    out.Length = len;
    out.Exponent += k;
    out.Status = StatusOk;
  }
};

template <Accuracy A, class T>
struct ArithFor;
template <class T>
struct ArithFor<Accuracy::Fast, T>
{
  using Type = FastArith<T>;
};
template <class T>
struct ArithFor<Accuracy::Double, T>
{
  using Type = DoubleArith<T>;
};
template <class T>
struct ArithFor<Accuracy::Compensated, T>
{
  using Type = CompensatedArith<T, false>;
};
template <class T>
struct ArithFor<Accuracy::Exact, T>
{
  using Type = CompensatedArith<T, true>;
};

/**
 * Result of the slow path of the inexact modes: component c of the true area vector is
 * w[c] * 2^unscale[c]. The components are brought to a common exponent (the largest lands in
 * [1, 2); components below 2^-1074 of it vanish, as they would in the unit normal) and
 * normalised.
 */
inline void FinishScaled(const double w[3], const int unscale[3], AreaVector& out, bool single)
{
  int top = INT_MIN;
  for (int c = 0; c < 3; ++c)
  {
    if (!std::isfinite(w[c]))
    {
      out.SetZero(StatusDegenerate);
      return;
    }
    if (w[c] != 0.0)
    {
      top = std::max(top, Exponent2(w[c]) + unscale[c]);
    }
  }
  if (top == INT_MIN)
  {
    out.SetZero(StatusDegenerate);
    return;
  }
  double v[3];
  for (int c = 0; c < 3; ++c)
  {
    v[c] = w[c] == 0.0 ? 0.0 : std::ldexp(w[c], unscale[c] - top);
  }
  int k;
  double n[3];
  NormalizeDouble(v, n, out.Length, k);
  for (int c = 0; c < 3; ++c)
  {
    out.Vector[c] = v[c];
    out.VectorLo[c] = 0.0;
    out.Normal[c] = single ? RoundToFloat(n[c]) : n[c];
  }
  out.Exponent = top + k;
  out.Status = StatusOk;
}

/**
 * Scale of the slow path: the largest coordinate difference and whether differences overflow.
 * Returns false when a coordinate is not finite.
 */
template <class T, class VertexFn>
bool MeasureDifferences(
  const VertexFn& vertex, std::int64_t n, Scaling& scaling, double& largest, bool perAxis)
{
  const T* p0 = vertex(0);
  for (int c = 0; c < 3; ++c)
  {
    if (!std::isfinite(static_cast<double>(p0[c])))
    {
      return false;
    }
  }
  double m[3] = { 0.0, 0.0, 0.0 };
  bool overflow = false;
  for (std::int64_t i = 1; i < n; ++i)
  {
    const T* p = vertex(i);
    for (int c = 0; c < 3; ++c)
    {
      const double x = static_cast<double>(p[c]);
      if (!std::isfinite(x))
      {
        return false;
      }
      const double d = std::fabs(x - static_cast<double>(p0[c]));
      overflow = overflow || std::isinf(d);
      m[c] = std::max(m[c], d);
    }
  }
  scaling.Pre = overflow ? 0.25 : 1.0;
  if (overflow)
  {
    m[0] = m[1] = m[2] = 0.0;
    for (std::int64_t i = 1; i < n; ++i)
    {
      const T* p = vertex(i);
      for (int c = 0; c < 3; ++c)
      {
        m[c] = std::max(
          m[c], std::fabs(static_cast<double>(p[c]) * 0.25 - static_cast<double>(p0[c]) * 0.25));
      }
    }
  }
  largest = std::max(m[0], std::max(m[1], m[2]));
  for (int c = 0; c < 3; ++c)
  {
    const double scale = perAxis ? m[c] : largest;
    scaling.Shift[c] = scale > 0.0 ? -std::ilogb(scale) : 0;
  }
  return true;
}

/// Whether a non-zero coordinate difference to p0 lies below 2^-480 once scaled. Scaling down can
/// round a non-zero difference to zero, so non-zero means the coordinates differ.
template <bool Scaled, class T, class VertexFn>
bool HasTinyDifference(const VertexFn& vertex, std::int64_t n, const Scaling& scaling)
{
  const T* p0 = vertex(0);
  for (std::int64_t i = 1; i < n; ++i)
  {
    const T* p = vertex(i);
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::fabs(ScaledDifference<Scaled>(p[c], p0[c], scaling, c));
      if (p[c] != p0[c] && d < TinyDifference)
      {
        return true;
      }
    }
  }
  return false;
}

/// Exact area vector in GMP integer arithmetic and its faithful normal
/// (PhongVTKExactAreaVector.cxx).
void ExactAreaVector(const double* xyz, std::int64_t n, AreaVector& out);

template <class T, class VertexFn>
void ExactFallback(const VertexFn& vertex, std::int64_t n, AreaVector& out)
{
  // Only polygons the double-double filter could not certify get here; gather them as doubles.
  thread_local std::vector<double> xyz;
  xyz.resize(static_cast<std::size_t>(3 * n));
  for (std::int64_t i = 0; i < n; ++i)
  {
    const T* p = vertex(i);
    for (int c = 0; c < 3; ++c)
    {
      xyz[3 * i + c] = static_cast<double>(p[c]);
    }
  }
  ExactAreaVector(xyz.data(), n, out);
}
} // namespace detail

/**
 * Second half of ComputeAreaVector for a result left pending by ComputeAreaVectorDeferred: the
 * unit normal and length (sqrt and division, whose latency dominates when done polygon by polygon;
 * batching them lets the processor overlap many).
 */
template <Accuracy A, class T>
PHONGVTK_INLINE void CompleteAreaVector(AreaVector& out)
{
  if constexpr (A == Accuracy::Exact)
  {
    detail::CompensatedArith<T, true>::CompleteFaithful(out);
  }
  else
  {
    detail::ArithFor<A, T>::Type::Complete(out);
  }
}

namespace detail
{
/// Correctly rounded square root of each lane.
PHONGVTK_INLINE V4 Sqrt(V4 v)
{
#if defined(PHONGVTK_HAVE_AVX_FMA)
  return reinterpret_cast<V4>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(v)));
#else
  return V4{ std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3]) };
#endif
}

/// The largest |v_c| of each lane (lanes free of NaN).
PHONGVTK_INLINE V4 MaxAbs4(const V4 v[3])
{
  const V4 a0 = Abs(v[0]), a1 = Abs(v[1]), a2 = Abs(v[2]);
  const V4 m = a0 > a1 ? a0 : a1;
  return m > a2 ? m : a2;
}

/// Exponent2(m) of each lane, for normal m.
PHONGVTK_INLINE V4i Exponent2(V4 m)
{
  return ((reinterpret_cast<V4i>(m) >> 52) & 0x7ff) - 1023;
}

/// 2^-Exponent2(m) of each lane, for normal m whose inverse binade is normal too: Scale2(x, -k)
/// is then x times it, and m times it lies in [1, 2).
PHONGVTK_INLINE V4 InverseBinade(V4 m)
{
  return reinterpret_cast<V4>((2046 - ((reinterpret_cast<V4i>(m) >> 52) & 0x7ff)) << 52);
}

/// NormInWindow of four double-double vectors hi + lo, lane by lane: the same operations, so the
/// same bits; returns the norm's high part.
PHONGVTK_INLINE V4 NormInWindow4(const V4 hi[3], const V4 lo[3], V4& normLo, V4& inverse)
{
  V4 p[3], e[3];
  for (int c = 0; c < 3; ++c)
  {
    TwoProduct(hi[c], hi[c], p[c], e[c]);
    e[c] += 2.0 * hi[c] * lo[c];
  }
  V4 s1, t1, s2, t2;
  TwoSum(p[0], p[1], s1, t1);
  TwoSum(s1, p[2], s2, t2);
  const V4 b = (t1 + t2) + (e[0] + e[1] + e[2]);
  const V4 sHi = s2 + b;
  const V4 sLo = b - (sHi - s2);
  const V4 r = Sqrt(sHi);
  inverse = 1.0 / r;
  const V4 residual = Fma(-r, r, sHi) + sLo;
  const V4 correction = 0.5 * residual * inverse;
  const V4 normHi = r + correction;
  normLo = correction - (normHi - r);
  return normHi;
}

/**
 * NormalizeFaithful of four double-double vectors h + l inside its unscaled window, one per SIMD
 * lane: the same operations, so the results are bitwise the same; the square roots and divisions
 * of four vectors then cost what one costs.
 */
PHONGVTK_INLINE void NormalizeFaithful4(const V4 h[3], const V4 l[3], V4 n[3], V4& length)
{
  V4 normLo, inverse;
  const V4 normHi = NormInWindow4(h, l, normLo, inverse);
  for (int c = 0; c < 3; ++c)
  {
    const V4 q1 = h[c] * inverse;
    const V4 rem = Fma(-q1, normHi, h[c]) + (l[c] - q1 * normLo);
    n[c] = q1 + rem * inverse;
  }
  length = normHi;
}

/// CompleteFaithful for four pending EXACT results inside NormalizeFaithful's unscaled window.
inline void CompleteFaithful4(AreaVector* r[4])
{
  V4 h[3], l[3], n[3], length;
  for (int c = 0; c < 3; ++c)
  {
    h[c] = V4{ r[0]->Vector[c], r[1]->Vector[c], r[2]->Vector[c], r[3]->Vector[c] };
    l[c] = V4{ r[0]->VectorLo[c], r[1]->VectorLo[c], r[2]->VectorLo[c], r[3]->VectorLo[c] };
  }
  NormalizeFaithful4(h, l, n, length);
  for (int j = 0; j < 4; ++j)
  {
    for (int c = 0; c < 3; ++c)
    {
      r[j]->Normal[c] = n[c][j];
      r[j]->Vector[c] = h[c][j] + l[c][j];
      r[j]->VectorLo[c] = 0.0;
    }
    r[j]->Length = length[j];
    r[j]->Status = StatusOk;
  }
}

/// Whether a pending EXACT result lies inside NormalizeFaithful's unscaled window.
inline bool InFaithfulWindow(const AreaVector& r)
{
  const double m = MaxAbs3(r.Vector);
  return m >= DoubleWindow.Bottom && m <= DoubleWindow.Top;
}
} // namespace detail

/**
 * Completes every pending result of a batch (see ComputeAreaVectorDeferred): EXACT four cells
 * at a time, the other modes cell by cell.
 */
template <Accuracy A, class T>
void CompleteAreaVectors(AreaVector* results, std::int64_t count)
{
  if constexpr (A == Accuracy::Exact)
  {
    AreaVector* group[4];
    int size = 0;
    for (std::int64_t j = 0; j < count; ++j)
    {
      if (results[j].Status != StatusPending)
      {
        continue;
      }
      if (!detail::InFaithfulWindow(results[j]))
      {
        CompleteAreaVector<A, T>(results[j]);
        continue;
      }
      group[size++] = results + j;
      if (size == 4)
      {
        detail::CompleteFaithful4(group);
        size = 0;
      }
    }
    for (int j = 0; j < size; ++j)
    {
      CompleteAreaVector<A, T>(*group[j]);
    }
  }
  else
  {
    for (std::int64_t j = 0; j < count; ++j)
    {
      if (results[j].Status == StatusPending)
      {
        CompleteAreaVector<A, T>(results[j]);
      }
    }
  }
}

/**
 * Four triangles at once, one per SIMD lane (structure of arrays): the direct evaluation of
 * ComputeAreaVector for n = 3 with the same operations in the same order, hence bitwise the same
 * results, for the runs of triangles most meshes consist of. The square roots and divisions of
 * four triangles then cost what one costs. A lane whose triangle leaves the common case (outside
 * the safe exponent window, non-finite, degenerate or, for EXACT, not certified) is not done: the
 * caller gives that triangle to ComputeAreaVector.
 */
struct TriangleLanes
{
  detail::V4 Normal[3]; // unit normal, one component per register
  detail::V4 Vector[3]; // area vector w (exponent 0)
  detail::V4 Length;    // |w|
  int Done;             // bit j set: lane j is complete with status Ok

  /// Lane j of a done lane as a per-polygon result.
  AreaVector Result(int j) const
  {
    AreaVector r;
    for (int c = 0; c < 3; ++c)
    {
      r.Normal[c] = this->Normal[c][j];
      r.Vector[c] = this->Vector[c][j];
      r.VectorLo[c] = 0.0;
    }
    r.Length = this->Length[j];
    r.Exponent = 0;
    r.Status = StatusOk;
    return r;
  }
};

namespace detail
{
typedef float V4f __attribute__((vector_size(16)));
typedef int V4fi __attribute__((vector_size(16)));

/// The four-lane type of element type E (V4f for float, V4 for double). A trait rather than
/// std::conditional_t, which would drop V4's alignment attribute.
template <class E>
struct LanesOf
{
  using Type = V4;
};
template <>
struct LanesOf<float>
{
  using Type = V4f;
};

PHONGVTK_INLINE V4f Abs(V4f v)
{
  return reinterpret_cast<V4f>(reinterpret_cast<V4fi>(v) & 0x7fffffff); // clears the sign bit
}

/// Coordinate c of four points, one per lane, converted to the lane's element type.
template <class Lane, class T>
PHONGVTK_INLINE Lane GatherAxis(const T* const point[4], int c)
{
  using E = std::remove_cv_t<std::remove_reference_t<decltype(Lane{}[0])>>;
  return Lane{ static_cast<E>(point[0][c]), static_cast<E>(point[1][c]),
    static_cast<E>(point[2][c]), static_cast<E>(point[3][c]) };
}

/// Bit j set when lane j of a comparison result is true.
template <class Mask>
PHONGVTK_INLINE int LaneBits(Mask m)
{
  return static_cast<int>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
}

/// Lanes whose three components w_c are all at most `top` in magnitude (NaN is not) and not all
/// below `bottom`: the safe window of the per-polygon kernel's MaxAbs3 test.
template <class Lane>
PHONGVTK_INLINE int InWindow(const Lane w[3], SafeWindow window)
{
  using E = std::remove_cv_t<std::remove_reference_t<decltype(Lane{}[0])>>;
  const Lane a0 = Abs(w[0]), a1 = Abs(w[1]), a2 = Abs(w[2]);
  const E lo = static_cast<E>(window.Bottom), hi = static_cast<E>(window.Top);
  return LaneBits((a0 <= hi) & (a1 <= hi) & (a2 <= hi) & ((a0 >= lo) | (a1 >= lo) | (a2 >= lo)));
}

/**
 * DOUBLE's area vectors of four triangles, without their normals; a lane is complete (as the
 * per-polygon kernel would leave it, exponent 0) where InWindow(w, DoubleWindow) holds.
 */
template <class T>
PHONGVTK_INLINE void DoubleAreaVectors4(const T* const corner[3][4], V4 w[3])
{
  V4 a[3], b[3];
  for (int c = 0; c < 3; ++c)
  {
    const V4 p0 = GatherAxis<V4>(corner[0], c);
    a[c] = GatherAxis<V4>(corner[1], c) - p0;
    b[c] = GatherAxis<V4>(corner[2], c) - p0;
    w[c] = V4{};
  }
  AddCross(a, b, w);
}

/// DOUBLE's (and COMPENSATED's) completion of in-window area vectors: w / |w|.
PHONGVTK_INLINE void NormalizeDouble4(const V4 w[3], TriangleLanes& out)
{
  out.Length = Sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  for (int c = 0; c < 3; ++c)
  {
    out.Vector[c] = w[c];
    out.Normal[c] = w[c] / out.Length;
  }
  out.Done = InWindow(w, DoubleWindow);
}

template <class T>
PHONGVTK_INLINE void FastTriangles4(const T* const corner[3][4], TriangleLanes& out)
{
  // Differences in the points' own precision, then float (FastArith::Difference).
  using Point = typename LanesOf<T>::Type;
  V4f a[3], b[3], w[3];
  for (int c = 0; c < 3; ++c)
  {
    const Point p0 = GatherAxis<Point>(corner[0], c);
    a[c] = __builtin_convertvector(GatherAxis<Point>(corner[1], c) - p0, V4f);
    b[c] = __builtin_convertvector(GatherAxis<Point>(corner[2], c) - p0, V4f);
    w[c] = V4f{};
  }
  AddCross(a, b, w);
  const V4f squares = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
#if defined(__SSE__)
  const V4f length = reinterpret_cast<V4f>(_mm_sqrt_ps(reinterpret_cast<__m128>(squares)));
#else
  const V4f length = { std::sqrt(squares[0]), std::sqrt(squares[1]), std::sqrt(squares[2]),
    std::sqrt(squares[3]) };
#endif
  const V4f inverse = 1.0f / length;
  for (int c = 0; c < 3; ++c)
  {
    out.Vector[c] = __builtin_convertvector(w[c], V4);
    out.Normal[c] = __builtin_convertvector(w[c] * inverse, V4);
  }
  out.Length = __builtin_convertvector(length, V4);
  out.Done = InWindow(w, FloatWindow);
}

template <class T>
PHONGVTK_INLINE void DoubleTriangles4(const T* const corner[3][4], TriangleLanes& out)
{
  V4 w[3];
  DoubleAreaVectors4<T>(corner, w);
  NormalizeDouble4(w, out);
}

/// EXACT's area vectors of four triangles: hi + lo with CompensatedArith's bound per component.
struct CertifiedLanes
{
  V4 Hi[3], Lo[3];
  V4 Bound[3];     // |(hi + lo) - w_c| (CompensatedArith::Bound for n = 3)
  V4 Permanent[3]; // sum of |products|: zero when w_c is exactly zero
  V4i Tiny;        // a non-zero difference below 2^-480: a product may have underflowed
  V4i Certified;   // FinishCertified: every component certified to 2^-56 (or exactly zero)
};

/// CompensatedArith::Bound and FinishCertified for n = 3, lane by lane.
PHONGVTK_INLINE void FinishCertified4(const V4 sum[3], const V4 err[3], const V4 permanent[3],
  const V4 errMagnitude[3], V4i tiny, CertifiedLanes& w)
{
  w.Tiny = tiny;
  w.Certified = ~tiny;
  for (int c = 0; c < 3; ++c)
  {
    TwoSum(sum[c], err[c], w.Hi[c], w.Lo[c]);
    w.Bound[c] = CompensatedBound(permanent[c], errMagnitude[c], err[c], 2.0); // n - 1, n = 3
    w.Permanent[c] = permanent[c];
    w.Certified &= Certified(permanent[c], w.Bound[c], w.Hi[c]);
  }
}

/// COMPENSATED and EXACT: CompensatedArith's Difference, Add and finish, lane by lane; EXACT's
/// certified area vectors also in `certified` when given.
template <class T, bool Exact>
PHONGVTK_INLINE void CompensatedTriangles4(
  const T* const corner[3][4], TriangleLanes& out, CertifiedLanes* certifiedOut = nullptr)
{
  V4 aHi[3], aLo[3], bHi[3], bLo[3];
  // Lanes with a non-zero difference below 2^-480 (HasTinyDifference): a product that underflowed
  // to zero would pass for an exact zero. The per-polygon path decides them.
  V4i tiny = {};
  for (int c = 0; c < 3; ++c)
  {
    const V4 p0 = GatherAxis<V4>(corner[0], c);
    const V4 p1 = GatherAxis<V4>(corner[1], c);
    const V4 p2 = GatherAxis<V4>(corner[2], c);
    TwoSum(p1, -p0, aHi[c], aLo[c]);
    TwoSum(p2, -p0, bHi[c], bLo[c]);
    if (Exact)
    {
      tiny |= ((p1 != p0) & (Abs(aHi[c]) < TinyDifference)) |
        ((p2 != p0) & (Abs(bHi[c]) < TinyDifference));
    }
  }
  // The per-polygon kernel's one fan step from zero accumulators, a component at a time.
  V4 sum[3] = {}, err[3] = {}, permanent[3] = {}, errMagnitude[3] = {};
  for (int c = 0; c < 3; ++c)
  {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    CompensatedCrossStep<Exact>(aHi[c1], aLo[c1], aHi[c2], aLo[c2], bHi[c1], bLo[c1], bHi[c2],
      bLo[c2], sum[c], err[c], permanent[c], errMagnitude[c]);
  }
  if (!Exact)
  {
    V4 w[3];
    for (int c = 0; c < 3; ++c)
    {
      w[c] = sum[c] + err[c];
    }
    NormalizeDouble4(w, out);
    return;
  }
  // CompensatedArith::FinishCertified for n = 3, then NormalizeFaithful.
  CertifiedLanes w;
  FinishCertified4(sum, err, permanent, errMagnitude, tiny, w);
  V4i certified = w.Certified;
  V4* hi = w.Hi;
  V4* lo = w.Lo;
  if (certifiedOut)
  {
    *certifiedOut = w;
    return;
  }
  NormalizeFaithful4(hi, lo, out.Normal, out.Length);
  for (int c = 0; c < 3; ++c)
  {
    out.Vector[c] = hi[c] + lo[c];
  }
  out.Done = LaneBits(certified) & InWindow(hi, DoubleWindow);
}
} // namespace detail

namespace detail
{
/// EXACT's certified area vectors of four triangles, without their normals.
template <class T>
PHONGVTK_INLINE void CertifiedAreaVectors4(const T* const corner[3][4], CertifiedLanes& w)
{
  TriangleLanes unused;
  CompensatedTriangles4<T, true>(corner, unused, &w);
}
} // namespace detail

/// Four unit normals (component by component, one per lane) as 12 consecutive values
/// x0 y0 z0 x1 ... z3 of type O.
template <class O>
PHONGVTK_INLINE void StoreNormals4(O* out, const detail::V4 n[3])
{
  using Vec = typename detail::LanesOf<O>::Type;
  const Vec x = __builtin_convertvector(n[0], Vec);
  const Vec y = __builtin_convertvector(n[1], Vec);
  const Vec z = __builtin_convertvector(n[2], Vec);
  const Vec v[3] = { { x[0], y[0], z[0], x[1] }, { y[1], z[1], x[2], y[2] },
    { z[2], x[3], y[3], z[3] } };
  std::memcpy(out, v, sizeof(v));
}

/**
 * Four triangles in accuracy mode A; `corner[v][j]` points at the coordinates of vertex v of
 * triangle j.
 */
template <Accuracy A, class T>
PHONGVTK_INLINE void ComputeTriangles4(const T* const corner[3][4], TriangleLanes& out)
{
  if constexpr (A == Accuracy::Fast)
  {
    detail::FastTriangles4<T>(corner, out);
  }
  else if constexpr (A == Accuracy::Double)
  {
    detail::DoubleTriangles4<T>(corner, out);
  }
  else
  {
    detail::CompensatedTriangles4<T, A == Accuracy::Exact>(corner, out);
  }
}

/**
 * Area vector and status of one polygon with n vertices in accuracy mode A, possibly without its
 * normal yet: when out.Status is StatusPending, CompleteAreaVector<A, T>(out) finishes it.
 * `vertex(i)` returns a `const T*` to the coordinates of vertex i (i in [0, n)).
 */
template <Accuracy A, class T, class VertexFn>
PHONGVTK_INLINE void ComputeAreaVectorDeferred(
  const VertexFn& vertex, std::int64_t n, AreaVector& out)
{
  using Arith = typename detail::ArithFor<A, T>::Type;
  if (n < 3)
  {
    out.SetZero(StatusDegenerate);
    return;
  }
  const detail::Scaling identity;
  {
    Arith acc;
    detail::AccumulateFan<false>(acc, vertex, n, identity);
    if constexpr (A == Accuracy::Exact)
    {
      if (acc.FinishCertified(
            out, n, [&] { return detail::HasTinyDifference<false, T>(vertex, n, identity); }))
      {
        return;
      }
    }
    else if (acc.Finish(out, false))
    {
      return;
    }
  }
  // Slow path: outside the safe exponent window, non-finite input, or (EXACT) not certified.
  // EXACT scales every axis alike (its certificate and the exact fallback need the differences
  // exact); the other modes scale each axis on its own, so that a polygon whose extent spans
  // more binades than the arithmetic's exponent range (float's especially) loses nothing.
  detail::Scaling scaling;
  double largest;
  if (!detail::MeasureDifferences<T>(vertex, n, scaling, largest, A != Accuracy::Exact))
  {
    out.SetZero(StatusNonFinite);
    return;
  }
  if (largest == 0.0)
  {
    out.SetZero(StatusDegenerate);
    return;
  }
  Arith acc;
  detail::AccumulateFan<true>(acc, vertex, n, scaling);
  if constexpr (A == Accuracy::Exact)
  {
    // Scaling the exact differences by a power of two keeps them exact, unless they overflowed
    // and the coordinates themselves had to be scaled down (Pre != 1): certify the scaled
    // polygon, or decide it in exact integer arithmetic.
    if (!(scaling.Pre == 1.0 &&
          acc.FinishCertified(
            out, n, [&] { return detail::HasTinyDifference<true, T>(vertex, n, scaling); })))
    {
      detail::ExactFallback<T>(vertex, n, out);
      return;
    }
    if (out.Status == StatusPending)
    {
      CompleteAreaVector<A, T>(out);
    }
    if (out.Status == StatusOk)
    {
      // w scales with the square of the (uniformly scaled) differences.
      out.Exponent += 2 * scaling.Unscale(0);
    }
  }
  else
  {
    // Component c of w is a sum of products of the other two axes' differences.
    double w[3];
    acc.Raw(w);
    const int unscale[3] = { scaling.Unscale(1) + scaling.Unscale(2),
      scaling.Unscale(2) + scaling.Unscale(0), scaling.Unscale(0) + scaling.Unscale(1) };
    detail::FinishScaled(w, unscale, out, A == Accuracy::Fast);
  }
}

/**
 * Area vector, unit normal and status of one polygon with n vertices in accuracy mode A.
 * `vertex(i)` returns a `const T*` to the coordinates of vertex i (i in [0, n)).
 */
template <Accuracy A, class T, class VertexFn>
PHONGVTK_INLINE void ComputeAreaVector(const VertexFn& vertex, std::int64_t n, AreaVector& out)
{
  ComputeAreaVectorDeferred<A, T>(vertex, n, out);
  if (out.Status == StatusPending)
  {
    CompleteAreaVector<A, T>(out);
  }
}

/**
 * The boundary of a triangle strip with k points, as a polygon: 0, 1, 3, 5, ... (odd indices
 * ascending), then the even indices descending to 2. The sum of the strip's triangles, each with
 * the strip's alternating orientation, equals the area vector of this outline exactly (the area
 * vector is additive over a triangulation), so strips share the polygon kernel.
 */
inline std::int64_t StripOutlineIndex(std::int64_t i, std::int64_t k)
{
  const std::int64_t odd = k / 2;
  if (i <= odd)
  {
    return i == 0 ? 0 : 2 * i - 1;
  }
  const std::int64_t even = (k - 1) / 2;
  return 2 * (even - (i - odd - 1));
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#if defined(__clang__)
#pragma float_control(pop)
#endif

#endif
// VTK-HeaderTest-Exclude: PhongVTKAreaVector.h
