/**
 * @file PhongVTKFeatureAngle.h
 * @brief Private: whether the edge between two faces is sharp, i.e. whether the angle between
 * their area vectors w1, w2 is at least the feature angle: `w1.w2 <= c |w1| |w2|` with c the
 * double value of cos(FeatureAngle). An edge exactly at the feature angle is sharp (VTK crosses
 * an edge only when n1.n2 > cos(FeatureAngle)).
 *
 * FAST, DOUBLE and COMPENSATED decide from their own unit normals, `fl(n1.n2) <= c`: their error
 * is that of their normals (docs/normals.md) plus the rounding of the dot product, and a face far
 * from the origin can be misjudged. EXACT decides the sign of `w1.w2 - c |w1| |w2|` for the exact
 * area vectors of the double coordinates: from its faithful normals when the dot product is
 * certified to lie on one side of c, in exact integer arithmetic otherwise.
 */
#ifndef PhongVTKFeatureAngle_h
#define PhongVTKFeatureAngle_h

#include "PhongVTKKernelNamespace.h"
#include <cstdint>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/**
 * The error of fl(n1.n2) against the exact n1e.n2e when every component of n1 and n2 is within
 * 1 ulp of the exact unit normals' (EXACT's faithful normals): each component is off by at most
 * 2^-52 of itself, so the products by at most 2^-51 |n1e_i n2e_i| (plus 2^-104), which sums to
 * 2^-51 |n1e| |n2e| = 2^-51 by Cauchy-Schwarz; the three products and two additions round by at
 * most 3 u = 1.5 2^-52 of the same sum. Together below 1.8 2^-51 (and the subnormal components'
 * absolute error, below 2^-1070): 2^-49 leaves a factor of two, also for rounding c +- bound.
 */
constexpr double FaithfulDotBound = 0x1p-49;

/// Sharp or smooth, or (EXACT's certified stage only) too close to call from the normals.
enum class FeatureEdge : signed char
{
  Smooth = 0,
  Sharp = 1,
  Undecided = 2
};

/// fl(n1.n2), the three products and the two additions in this order for every mode (so that
/// the decision is symmetric: the same products for (n1, n2) and (n2, n1)).
inline double UnitDot(const double n1[3], const double n2[3])
{
  return n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
}

/// FAST, DOUBLE, COMPENSATED: sharp when fl(n1.n2) <= c.
inline FeatureEdge FeatureEdgeFromNormals(const double n1[3], const double n2[3], double c)
{
  return UnitDot(n1, n2) <= c ? FeatureEdge::Sharp : FeatureEdge::Smooth;
}

/**
 * EXACT's certified stage: from faithful unit normals, Sharp or Smooth when the dot product is
 * further than FaithfulDotBound from c, Undecided otherwise (the exact test decides).
 */
inline FeatureEdge CertifiedFeatureEdge(const double n1[3], const double n2[3], double c)
{
  const double d = UnitDot(n1, n2);
  if (d > c + FaithfulDotBound)
  {
    return FeatureEdge::Smooth;
  }
  if (d < c - FaithfulDotBound)
  {
    return FeatureEdge::Sharp;
  }
  return FeatureEdge::Undecided;
}

namespace detail
{
/**
 * The exact decision (PhongVTKExactAreaVector.cxx): whether `w1.w2 <= c |w1| |w2|` for the exact
 * area vectors w1, w2 of the polygons xyz1 (n1 vertices) and xyz2 (n2 vertices), coordinates
 * finite doubles, |c| <= 1. A polygon whose exact area vector is zero makes the edge sharp.
 */
bool ExactFeatureEdgeIsSharp(
  const double* xyz1, std::int64_t n1, const double* xyz2, std::int64_t n2, double c);
}
PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKFeatureAngle.h
