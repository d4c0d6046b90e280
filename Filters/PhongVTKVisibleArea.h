/**
 * @file PhongVTKVisibleArea.h
 * @brief Private kernels of vtkVisibleArea: the area a viewer sees of one polygon, v.w / 2 with
 * w the polygon's area vector and v the unit vector toward the viewer, in the accuracy modes of
 * PhongVTKAreaVector.h.
 *
 * The view is either a direction V (the same for every polygon) or an eye point E; then the
 * direction of a polygon is from the mean of its vertices to the eye, and the kernels use the
 * exactly equivalent S = sum_i (E - p_i) = n (E - mean): the visible area is S.w / (2 |S|).
 *
 * - FAST: the area vector in FAST, the dot product in float.
 * - DOUBLE: the area vector in DOUBLE, the dot product in double.
 * - COMPENSATED: the area vector in COMPENSATED, S as a compensated sum, the dot product by
 *   Ogita-Rump-Oishi's Dot2 (TwoProduct, TwoSum): as accurate as if computed in twice the
 *   working precision, then rounded.
 * - EXACT: faithful (within 1 ulp) of the exact S.w / (2 |S|) for the polygon's double
 *   coordinates and the given V or E. A double-double evaluation whose error bound is carried
 *   along (the area vector's bound from CompensatedArith, S's, the dot's) decides almost every
 *   polygon; exact GMP integers decide the rest (seen nearly edge-on, coordinates outside the
 *   safe exponent window). A polygon seen exactly edge-on gets exactly zero.
 */
#ifndef PhongVTKVisibleArea_h
#define PhongVTKVisibleArea_h

#include "PhongVTKAreaVector.h"
#include "PhongVTKKernelNamespace.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN

/// What the polygons are seen from.
struct View
{
  /// True: Vector is the eye point; false: Vector is the direction toward the viewer, scaled by
  /// a power of two so that its largest component lies in [1, 2) (the ratio v.w / |v| does not
  /// change).
  bool Eye = false;
  double Vector[3] = { 0.0, 0.0, 1.0 };
  /// 1 / |Vector| rounded (direction only).
  double InverseLength = 1.0;
  /// |Vector| in double-double and 1 / Norm.Hi rounded (direction only; EXACT), as
  /// detail::NormInWindow gives them: set by SetDirection.
  detail::DD Norm = { 1.0, 0.0 };
  double NormInverse = 1.0;
};

/// Visible area (v.w / 2) and the status of the area vector (NormalStatus values).
struct VisibleAreaResult
{
  double Area;
  std::uint8_t Status;
};

namespace detail
{
// EXACT's certificate, written once for one polygon (R double) and for four triangles (R V4).

/// Error bound of S = sum of n exact differences E - p_i summed in double-double, from the sum of
/// their magnitudes.
template <class R>
PHONGVTK_INLINE R EyeSumBound(R magnitude, double n)
{
  return 1.01 * n * (0x1p-100 * magnitude + 0x1p-1070);
}

/// Error bound of D = v.w from the propagated input errors `err` and the magnitude of the
/// products: certified when it is within CertifiedRelativeError of |D|.
template <class R>
PHONGVTK_INLINE R DotBound(R err, R magnitude)
{
  return 1.01 * (err + 0x1p-100 * magnitude) + 0x1p-1060;
}

/// The smallest |S| the eye vector is scaled from (below it, the exact fallback decides).
constexpr double EyeSumBottom = 0x1p-900;
/// The view vector's certificate: its summed error bounds within this of its norm.
constexpr double ViewRelativeError = 0x1p-58;

/// Exact fallback of the EXACT mode in GMP integers (PhongVTKExactAreaVector.cxx).
VisibleAreaResult ExactVisibleArea(
  const double* xyz, std::int64_t n, const double vector[3], bool eye);

/// a * 2^k as a double, magnitudes beyond double's range saturated at its largest value.
inline double ScaleSaturated(double a, int k)
{
  constexpr double top = std::numeric_limits<double>::max();
  return std::max(-top, std::min(top, Scale2(a, k)));
}

/// Scales v[0..3) by the power of two that brings its largest component into [1, 2); false when
/// v is zero or not finite.
inline bool ScaleToUnitRange(double v[3])
{
  const double m = MaxAbs3(v);
  if (!(m > 0.0 && m <= std::numeric_limits<double>::max()))
  {
    return false;
  }
  const int k = Exponent2(m);
  for (int c = 0; c < 3; ++c)
  {
    v[c] = Scale2(v[c], -k);
  }
  return true;
}

/**
 * Makes `view` a direction view along d (finite, non-zero): scaled into [1, 2) by a power of two,
 * with its inverse length and norm. False when d is zero or not finite.
 */
inline bool SetDirection(View& view, const double d[3])
{
  view.Eye = false;
  std::copy(d, d + 3, view.Vector);
  if (!ScaleToUnitRange(view.Vector))
  {
    return false;
  }
  const double* v = view.Vector;
  view.InverseLength = 1.0 / std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const DD dd[3] = { { v[0], 0.0 }, { v[1], 0.0 }, { v[2], 0.0 } };
  view.Norm = NormInWindow(dd, view.NormInverse);
  return true;
}

/// sum += d in the arithmetic of mode A (COMPENSATED: TwoSum, its error into err), for doubles
/// and for four lanes alike.
template <Accuracy A, class Real>
PHONGVTK_INLINE void AddEyeDifference(Real& sum, Real& err, Real d)
{
  if constexpr (A == Accuracy::Compensated)
  {
    Real t, e;
    TwoSum(sum, d, t, e);
    sum = t;
    err += e;
  }
  else
  {
    sum += d;
  }
}

/**
 * S = sum_i (E - p_i) (toward the eye from the vertex mean, times n), scaled into [1, 2) by a
 * power of two; a compensated sum for COMPENSATED, a plain double sum otherwise. False when S is
 * zero (the eye is the vertex mean) or not finite.
 */
template <Accuracy A, class T, class VertexFn>
bool EyeVector(const VertexFn& vertex, std::int64_t n, const double eye[3], double s[3])
{
  for (double pre : { 1.0, 0x1p-4 })
  {
    for (int c = 0; c < 3; ++c)
    {
      double sum = 0.0, err = 0.0;
      for (std::int64_t i = 0; i < n; ++i)
      {
        AddEyeDifference<A>(sum, err, eye[c] * pre - static_cast<double>(vertex(i)[c]) * pre);
      }
      s[c] = sum + err;
    }
    if (ScaleToUnitRange(s))
    {
      return true;
    }
    if (MaxAbs3(s) == 0.0)
    {
      return false;
    }
    // Overflowed: once more on coordinates scaled down (finite ones: the area vector is ok).
  }
  return false;
}

/// Dot2 (Ogita, Rump and Oishi) of two 3-vectors: of doubles, or of four lanes (V4) with the
/// same operations lane by lane.
template <class R>
PHONGVTK_INLINE R Dot2(const R v[3], const R w[3])
{
  R s = {}, err = {};
  for (int c = 0; c < 3; ++c)
  {
    R p, e, t, f;
    TwoProduct(v[c], w[c], p, e);
    TwoSum(s, p, t, f);
    s = t;
    err += e + f;
  }
  return s + err;
}

/// v.w in the arithmetic of mode A (FAST: float; DOUBLE: double; COMPENSATED: Dot2).
template <Accuracy A>
PHONGVTK_INLINE double Dot(const double v[3], const double w[3])
{
  if constexpr (A == Accuracy::Fast)
  {
    float d = 0.0f;
    for (int c = 0; c < 3; ++c)
    {
      d += static_cast<float>(v[c]) * static_cast<float>(w[c]);
    }
    return d;
  }
  else if constexpr (A == Accuracy::Double)
  {
    return v[0] * w[0] + v[1] * w[1] + v[2] * w[2];
  }
  else
  {
    return Dot2(v, w);
  }
}

/**
 * EXACT, certified double-double stage: v.w / (2 |v|) from a double-double v with absolute error
 * bounds vErr and a double-double w with bounds wErr (wZero: certified exactly zero). False when
 * the bound does not certify a faithful result.
 */
inline bool CertifiedVisibleArea(const DD v[3], const double vErr[3], const DD w[3],
  const double wErr[3], const bool wZero[3], double& area, const View* direction = nullptr)
{
  bool exactZero = true;
  for (int c = 0; c < 3; ++c)
  {
    exactZero = exactZero && (wZero[c] || (v[c].Hi == 0.0 && v[c].Lo == 0.0 && vErr[c] == 0.0));
  }
  if (exactZero)
  {
    area = 0.0; // every product is exactly zero: seen exactly edge-on
    return true;
  }
  // D = v.w: the leading products exactly (TwoProduct) in a double-double sum, the cross terms
  // (first order) in double; bound = propagated input errors + the sum's rounding.
  DD d = { 0.0, 0.0 };
  double cross = 0.0, magnitude = 0.0, err = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    if (wZero[c])
    {
      continue;
    }
    double p, e;
    TwoProduct(v[c].Hi, w[c].Hi, p, e);
    d = Add(d, DD{ p, e });
    cross += v[c].Hi * w[c].Lo + v[c].Lo * w[c].Hi;
    const double av = std::fabs(v[c].Hi) + std::fabs(v[c].Lo);
    const double aw = std::fabs(w[c].Hi) + std::fabs(w[c].Lo);
    magnitude += av * aw;
    err += av * wErr[c] + aw * vErr[c] + vErr[c] * wErr[c];
  }
  d = Add(d, DD{ cross, 0.0 });
  err = DotBound(err, magnitude);
  if (!(err <= CertifiedRelativeError * std::fabs(d.Hi)))
  {
    return false;
  }
  // A direction's norm is the same for every polygon (and exact: vErr = 0).
  double inverse = direction ? direction->NormInverse : 0.0;
  const DD norm = direction ? direction->Norm : NormInWindow(v, inverse);
  if (!(1.01 * (vErr[0] + vErr[1] + vErr[2]) <= ViewRelativeError * norm.Hi))
  {
    return false;
  }
  area = 0.5 * DivideDD(d, norm, inverse);
  return true;
}

/// EXACT: S = sum_i (E - p_i) as double-double with error bounds, scaled into [1, 2) by a power
/// of two. False when S cannot be bounded (overflow) or is zero.
template <class T, class VertexFn>
bool EyeVectorDD(
  const VertexFn& vertex, std::int64_t n, const double eye[3], DD s[3], double sErr[3])
{
  for (int c = 0; c < 3; ++c)
  {
    DD sum = { 0.0, 0.0 };
    double magnitude = 0.0;
    for (std::int64_t i = 0; i < n; ++i)
    {
      DD d;
      TwoSum(eye[c], -static_cast<double>(vertex(i)[c]), d.Hi, d.Lo); // exact
      sum = Add(sum, d);
      magnitude += std::fabs(d.Hi);
    }
    if (!(magnitude <= PermanentLimit))
    {
      return false;
    }
    s[c] = sum;
    sErr[c] = EyeSumBound(magnitude, static_cast<double>(n));
  }
  double hi[3] = { s[0].Hi, s[1].Hi, s[2].Hi };
  const double m = MaxAbs3(hi);
  if (!(m > EyeSumBottom))
  {
    return false;
  }
  const int k = Exponent2(m);
  for (int c = 0; c < 3; ++c)
  {
    s[c] = { Scale2(s[c].Hi, -k), Scale2(s[c].Lo, -k) };
    sErr[c] = Scale2(sErr[c], -k);
  }
  return true;
}

/// EXACT: the certified stage, then the GMP fallback.
template <class T, class VertexFn>
VisibleAreaResult ExactVisibleAreaOf(const VertexFn& vertex, std::int64_t n, const View& view)
{
  if (n < 3)
  {
    return { 0.0, StatusDegenerate };
  }
  const Scaling identity;
  CompensatedArith<T, true> acc;
  AccumulateFan<false>(acc, vertex, n, identity);
  V4 hi, lo;
  TwoSum(acc.S, acc.Err, hi, lo);
  const V4 bound = acc.Bound(n);
  DD w[3];
  double wErr[3];
  bool wZero[3];
  bool ok = true, anyZero = false, allZero = true;
  for (int c = 0; c < 3; ++c)
  {
    ok = ok && acc.Permanent[c] <= PermanentLimit; // no overflow risk, no NaN
    w[c] = { hi[c], lo[c] };
    wZero[c] = acc.Permanent[c] == 0.0; // every product exactly zero (unless one underflowed)
    wErr[c] = wZero[c] ? 0.0 : bound[c];
    anyZero = anyZero || wZero[c];
    allZero = allZero && wZero[c];
  }
  // A product that underflowed to zero would pass for an exact zero.
  ok = ok && !(anyZero && HasTinyDifference<false, T>(vertex, n, identity));
  if (ok && allZero)
  {
    return { 0.0, StatusDegenerate };
  }
  if (ok)
  {
    DD v[3];
    double vErr[3] = { 0.0, 0.0, 0.0 };
    if (view.Eye)
    {
      ok = EyeVectorDD<T>(vertex, n, view.Vector, v, vErr);
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        v[c] = { view.Vector[c], 0.0 };
      }
    }
    double area;
    if (ok && CertifiedVisibleArea(v, vErr, w, wErr, wZero, area, view.Eye ? nullptr : &view))
    {
      return { area, StatusOk };
    }
  }
  thread_local std::vector<double> xyz;
  xyz.resize(static_cast<std::size_t>(3 * n));
  for (std::int64_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      xyz[3 * i + c] = static_cast<double>(vertex(i)[c]);
    }
  }
  return ExactVisibleArea(xyz.data(), n, view.Vector, view.Eye);
}
} // namespace detail

/**
 * Visible area of one polygon from a known area vector w * 2^exponent (FAST, DOUBLE and
 * COMPENSATED; the vertices are read only for an eye point).
 */
template <Accuracy A, class T, class VertexFn>
double VisibleAreaOfVector(
  const VertexFn& vertex, std::int64_t n, const View& view, const double w[3], int exponent)
{
  double dot, inverseLength;
  if (view.Eye)
  {
    double s[3];
    if (!detail::EyeVector<A, T>(vertex, n, view.Vector, s))
    {
      return 0.0; // the eye is the vertex mean: no direction
    }
    dot = detail::Dot<A>(s, w);
    inverseLength = 1.0 / std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  }
  else
  {
    dot = detail::Dot<A>(view.Vector, w);
    inverseLength = view.InverseLength;
  }
  if constexpr (A == Accuracy::Fast)
  {
    return detail::ScaleSaturated(
      static_cast<float>(dot) * static_cast<float>(inverseLength), exponent - 1);
  }
  return detail::ScaleSaturated(dot * inverseLength, exponent - 1);
}

namespace detail
{
/// v.w of four lanes, component by component, in the arithmetic of Dot<A> (FAST, DOUBLE,
/// COMPENSATED): the same operations in the same order, so the same bits as lane by lane.
template <Accuracy A>
PHONGVTK_INLINE V4 Dot4(const V4 v[3], const V4 w[3])
{
  if constexpr (A == Accuracy::Fast)
  {
    V4f d = {};
    for (int c = 0; c < 3; ++c)
    {
      d += __builtin_convertvector(v[c], V4f) * __builtin_convertvector(w[c], V4f);
    }
    return __builtin_convertvector(d, V4);
  }
  else if constexpr (A == Accuracy::Double)
  {
    return v[0] * w[0] + v[1] * w[1] + v[2] * w[2];
  }
  else
  {
    return Dot2(v, w);
  }
}

/**
 * EyeVector for four triangles (n = 3): S = sum_i (E - p_i) in the arithmetic of mode A, scaled
 * into [1, 2) by a power of two, and 1 / |S|. Returns the lanes whose S lies within 2^+-1000
 * before scaling: there EyeVector's first (unscaled) try succeeds, with the same bits.
 */
template <Accuracy A, class T>
PHONGVTK_INLINE int EyeVectors4(
  const T* const corner[3][4], const double eye[3], V4 s[3], V4& inverseLength)
{
  for (int c = 0; c < 3; ++c)
  {
    V4 sum = {}, err = {};
    for (int v = 0; v < 3; ++v)
    {
      AddEyeDifference<A, V4>(sum, err, eye[c] * 1.0 - GatherAxis<V4>(corner[v], c) * 1.0);
    }
    s[c] = sum + err;
  }
  const V4 m = MaxAbs4(s);
  const V4i inRange = (m >= 0x1p-1000) & (m <= 0x1p1000);
  const V4 scale = InverseBinade(m); // ScaleToUnitRange's Scale2(s_c, -k)
  for (int c = 0; c < 3; ++c)
  {
    s[c] = inRange ? s[c] * scale : s[c];
  }
  inverseLength = 1.0 / Sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  return LaneBits(inRange);
}

/// Add(DD, DD) lane by lane: the same operations.
PHONGVTK_INLINE void Add4(V4& hi, V4& lo, V4 bHi, V4 bLo)
{
  V4 s, e, t, f;
  TwoSum(hi, bHi, s, e);
  TwoSum(lo, bLo, t, f);
  e += t;
  V4 s2 = s + e;
  e = e - (s2 - s);
  e += f;
  hi = s2 + e;
  lo = e - (hi - s2);
}

/**
 * EyeVectorDD for four triangles (n = 3): S = sum_i (E - p_i) in double-double with its bound,
 * scaled into [1, 2) by a power of two. Returns the lanes where EyeVectorDD succeeds (the same
 * operations, so the same bits there).
 */
template <class T>
PHONGVTK_INLINE V4i EyeVectorsDD4(
  const T* const corner[3][4], const double eye[3], V4 hi[3], V4 lo[3], V4 err[3])
{
  V4i ok = ~V4i{};
  for (int c = 0; c < 3; ++c)
  {
    V4 sumHi = {}, sumLo = {}, magnitude = {};
    for (int v = 0; v < 3; ++v)
    {
      V4 dHi, dLo;
      TwoSum(V4{} + eye[c], -GatherAxis<V4>(corner[v], c), dHi, dLo); // exact
      Add4(sumHi, sumLo, dHi, dLo);
      magnitude += Abs(dHi);
    }
    ok &= magnitude <= PermanentLimit;
    hi[c] = sumHi;
    lo[c] = sumLo;
    err[c] = EyeSumBound(magnitude, 3.0);
  }
  const V4 m = MaxAbs4(hi);
  ok &= m > EyeSumBottom;
  const V4 scale = InverseBinade(m); // EyeVectorDD's Scale2(x, -k)
  for (int c = 0; c < 3; ++c)
  {
    hi[c] = ok ? hi[c] * scale : hi[c];
    lo[c] = ok ? lo[c] * scale : lo[c];
    err[c] = ok ? err[c] * scale : err[c];
  }
  return ok;
}

/**
 * ExactVisibleAreaOf's certified stage, four triangles at once: the conditions for entering it
 * (no tiny difference, no overflow risk, not every component zero), then CertifiedVisibleArea
 * with v = vHi + vLo (bounds vErr) and its norm, the `continue` for zero components as a lane
 * mask. Returns the lanes that certify; their areas are bit for bit the per-polygon kernel's.
 */
PHONGVTK_INLINE int CertifiedVisibleAreas4(const V4 vHi[3], const V4 vLo[3], const V4 vErr[3],
  V4 normHi, V4 normLo, V4 normInverse, const CertifiedLanes& w, double area[4])
{
  V4i ok = ~w.Tiny, allZero = ~V4i{}, exactZero = ~V4i{};
  V4i wZero[3];
  V4 wErr[3];
  for (int c = 0; c < 3; ++c)
  {
    ok &= w.Permanent[c] <= PermanentLimit;
    wZero[c] = w.Permanent[c] == 0.0;
    wErr[c] = wZero[c] ? V4{} : w.Bound[c];
    allZero &= wZero[c];
    exactZero &= wZero[c] | ((vHi[c] == 0.0) & (vLo[c] == 0.0) & (vErr[c] == 0.0));
  }
  V4 dHi = {}, dLo = {}, cross = {}, magnitude = {}, err = {};
  for (int c = 0; c < 3; ++c)
  {
    V4 p, e, hi = dHi, lo = dLo;
    TwoProduct(vHi[c], w.Hi[c], p, e);
    Add4(hi, lo, p, e);
    dHi = wZero[c] ? dHi : hi;
    dLo = wZero[c] ? dLo : lo;
    const V4 crossNext = cross + (vHi[c] * w.Lo[c] + vLo[c] * w.Hi[c]);
    cross = wZero[c] ? cross : crossNext;
    const V4 av = Abs(vHi[c]) + Abs(vLo[c]);
    const V4 aw = Abs(w.Hi[c]) + Abs(w.Lo[c]);
    const V4 magnitudeNext = magnitude + av * aw;
    magnitude = wZero[c] ? magnitude : magnitudeNext;
    const V4 errNext = err + (av * wErr[c] + aw * vErr[c] + vErr[c] * wErr[c]);
    err = wZero[c] ? err : errNext;
  }
  Add4(dHi, dLo, cross, V4{});
  err = DotBound(err, magnitude);
  V4i certified = err <= CertifiedRelativeError * Abs(dHi);
  certified &= 1.01 * (vErr[0] + vErr[1] + vErr[2]) <= ViewRelativeError * normHi;
  // DivideDD by the norm.
  const V4 q1 = dHi * normInverse;
  const V4 rem = Fma(-q1, normHi, dHi) + (dLo - q1 * normLo);
  const V4 quotient = 0.5 * (q1 + rem * normInverse);
  for (int j = 0; j < 4; ++j)
  {
    area[j] = exactZero[j] ? 0.0 : quotient[j];
  }
  return LaneBits(ok & ~allZero & (exactZero | certified));
}
} // namespace detail

/**
 * Visible areas of four triangles, one per lane, in mode A;
 * `corner[v][j]` points at vertex v of triangle j. Returns the lanes (bit j: triangle j) whose
 * `area[j]` is bit for bit what ComputeVisibleArea gives with status Ok: FAST, DOUBLE and
 * COMPENSATED where the per-polygon kernel leaves the area vector in its safe window at exponent
 * 0; EXACT where the area vector and then the visible area certify (the same certified stage on
 * the same double-doubles and bounds). The other lanes are left to the per-polygon kernel.
 */
template <Accuracy A, class T>
PHONGVTK_INLINE int VisibleAreas4(const T* const corner[3][4], const View& view, double area[4])
{
  using namespace detail;
  V4 w[3];
  int done;
  if constexpr (A == Accuracy::Exact)
  {
    CertifiedLanes c;
    CertifiedAreaVectors4<T>(corner, c);
    V4 vHi[3], vLo[3], vErr[3], normHi, normLo, normInverse;
    int eyeOk = 15;
    if (view.Eye)
    {
      eyeOk = LaneBits(EyeVectorsDD4<T>(corner, view.Vector, vHi, vLo, vErr));
      normHi = NormInWindow4(vHi, vLo, normLo, normInverse);
    }
    else
    {
      for (int k = 0; k < 3; ++k)
      {
        vHi[k] = V4{} + view.Vector[k];
        vLo[k] = vErr[k] = V4{};
      }
      // A direction's norm, computed once (SetDirection).
      normHi = V4{} + view.Norm.Hi;
      normLo = V4{} + view.Norm.Lo;
      normInverse = V4{} + view.NormInverse;
    }
    return eyeOk & CertifiedVisibleAreas4(vHi, vLo, vErr, normHi, normLo, normInverse, c, area);
  }
  else if constexpr (A == Accuracy::Double)
  {
    DoubleAreaVectors4<T>(corner, w);
    done = InWindow(w, DoubleWindow);
  }
  else
  {
    TriangleLanes lanes;
    ComputeTriangles4<A, T>(corner, lanes);
    for (int c = 0; c < 3; ++c)
    {
      w[c] = lanes.Vector[c];
    }
    done = lanes.Done;
  }
  V4 v[3], inverseLength;
  if (view.Eye)
  {
    done &= EyeVectors4<A, T>(corner, view.Vector, v, inverseLength);
  }
  else
  {
    for (int c = 0; c < 3; ++c)
    {
      v[c] = V4{} + view.Vector[c];
    }
    inverseLength = V4{} + view.InverseLength;
  }
  const V4 dot = Dot4<A>(v, w);
  for (int j = 0; j < 4; ++j)
  {
    // VisibleAreaOfVector at exponent 0; in the window the product cannot overflow.
    if constexpr (A == Accuracy::Fast)
    {
      area[j] = 0.5 *
        static_cast<double>(static_cast<float>(dot[j]) * static_cast<float>(inverseLength[j]));
    }
    else
    {
      area[j] = 0.5 * (dot[j] * inverseLength[j]);
    }
  }
  return done;
}

/**
 * The sum of the positive values of a[0, n) as a double-double: four interleaved compensated
 * sums (TwoSum, the errors added in double; every term has the same sign, so nothing cancels
 * and the error is about n u^2 of the sum), added in double-double in lane order.
 */
inline detail::DD PositiveSum(const double* a, std::int64_t n)
{
  using namespace detail;
  V4 s = {}, err = {};
  std::int64_t i = 0;
  for (; i + 4 <= n; i += 4)
  {
    V4 x;
    std::memcpy(&x, a + i, sizeof(x));
    x = x > 0.0 ? x : V4{};
    V4 t, e;
    TwoSum(s, x, t, e);
    s = t;
    err += e;
  }
  DD sum = { 0.0, 0.0 };
  for (int j = 0; j < 4; ++j)
  {
    sum = Add(sum, DD{ s[j], err[j] });
  }
  for (; i < n; ++i)
  {
    if (a[i] > 0.0)
    {
      sum = Add(sum, DD{ a[i], 0.0 });
    }
  }
  return sum;
}

/**
 * Visible area v.w / 2 of one polygon with n vertices in accuracy mode A, and the status of its
 * area vector (zero area for any status but StatusOk). `vertex(i)` returns a `const T*` to the
 * coordinates of vertex i.
 */
template <Accuracy A, class T, class VertexFn>
VisibleAreaResult ComputeVisibleArea(const VertexFn& vertex, std::int64_t n, const View& view)
{
  if constexpr (A == Accuracy::Exact)
  {
    return detail::ExactVisibleAreaOf<T>(vertex, n, view);
  }
  else
  {
    // The area vector is all that is needed: a pending result (w inside the safe window) is not
    // normalised.
    AreaVector w;
    ComputeAreaVectorDeferred<A, T>(vertex, n, w);
    if (w.Status != StatusOk && w.Status != StatusPending)
    {
      return { 0.0, w.Status };
    }
    return { VisibleAreaOfVector<A, T>(vertex, n, view, w.Vector, w.Exponent), StatusOk };
  }
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKVisibleArea.h
