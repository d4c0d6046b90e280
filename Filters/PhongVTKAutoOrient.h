/**
 * @file PhongVTKAutoOrient.h
 * @brief Private: vtkPolygonNormals' AutoOrientNormals. Every connected component, once its
 * polygons agree (PhongVTKOrientation.h), is turned to face outward, decided by an exact sign.
 *
 * The rule, one for closed and open components: a component faces outward when the flux of the
 * position field through it, taken from a point r,
 *
 *     F = sum over polygons f of (p0_f - r) . w_f     (w_f the summed cross products of f)
 *       = sum over fan triangles (p0, pi, pi+1) of det(p0 - r, pi - r, pi+1 - r),
 *
 * is positive. On a closed component F is six times the enclosed volume whatever r is (the area
 * vectors of a closed surface sum to exactly zero; r is its first point), so a closed component
 * is oriented by the sign of its volume; on an open one (a hemisphere, a surface with holes) r is
 * the centre of its bounding box and F says whether the faces on the whole turn away from the
 * middle of the component. The sign is exact: a double-precision
 * sum with a certified error bound (Shewchuk's orient3d bound per triangle, the summation's
 * bound on top), and exact integer arithmetic (GMP, PhongVTKExactAreaVector.cxx) when the bound
 * cannot decide. F exactly zero (a planar component, a surface as much inside out as not) keeps
 * the order of the component's first polygon. The sign, and so the result, is the same for any
 * thread count, and for any cell order (but for those ties).
 *
 * Nesting: a closed component inside an odd number of other closed components (the cavity of a
 * hollow solid) is turned inward, so that it faces out of the material like the outer shell.
 * Whether closed component A lies inside closed component B is B's winding number at a point of
 * A (the sum of the solid angles of B's triangles over 4 pi: +1 inside, 0 outside), tried only
 * when A's bounding box lies in B's. A point of A is passed over for A's next (up to 8) when it
 * is one of B's points, lies exactly in the plane of one of B's triangles and within it, or gets
 * a winding number further than 0.1 from an integer (a point on or next to B: on a face it
 * gets 1/2, on a right-angled edge 1/4); with none left A counts as outside. Closed components
 * are assumed not to cross each other.
 *
 * Non-orientable components, and components with a non-finite coordinate, are left as the
 * consistent ordering leaves them.
 */
#ifndef PhongVTKAutoOrient_h
#define PhongVTKAutoOrient_h

#include "PhongVTKKernelNamespace.h"
#include "PhongVTKOrientation.h"
#include "PhongVTKParallel.h"

#include "vtkSMPThreadLocal.h"

#include "vtkMath.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// What AutoOrient found and did, for the filter's report.
struct AutoOrientReport
{
  vtkIdType Components = 0; // components turned outward (orientable, finite)
  vtkIdType Closed = 0;     // of those, without a boundary or non-manifold edge
  vtkIdType Cavities = 0;   // closed components inside an odd number of others: turned inward
  vtkIdType Ties = 0;       // flux exactly zero: the first polygon's order kept
  vtkIdType Skipped = 0;    // non-orientable, or a non-finite coordinate
  vtkIdType ExactSums = 0;  // decided by the exact fallback
};

namespace detail
{
/**
 * The exact sign (-1, 0, 1) of sum over the polygons of signs[f] (p0_f - r) . w_f, polygon f
 * having sizes[f] points whose coordinates follow each other in `xyz`
 * (PhongVTKExactAreaVector.cxx).
 */
int ExactOrientedFluxSign(const double* xyz, const std::int64_t* sizes, const signed char* signs,
  std::int64_t numPolygons, const double r[3]);

/// The flux of one component in double with what its certified bound needs.
struct FluxSum
{
  double Sum = 0.0;       // the computed flux
  double Permanent = 0.0; // sum of the triangles' permanents (orient3d's bound)
  double Magnitude = 0.0; // sum of |triangle's term|, for the summation's bound
  double SmallestDifference = std::numeric_limits<double>::infinity(); // non-zero |p - r|
  std::int64_t Terms = 0;

  /// Adds sign * det(a - r, b - r, c - r).
  void Add(const double* a, const double* b, const double* c, const double* r, double sign)
  {
    double d[9];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = a[k] - r[k];
      d[3 + k] = b[k] - r[k];
      d[6 + k] = c[k] - r[k];
    }
    for (const double x : d)
    {
      const double m = std::fabs(x);
      this->SmallestDifference =
        m != 0.0 && m < this->SmallestDifference ? m : this->SmallestDifference;
    }
    const double bycz = d[4] * d[8], bzcy = d[5] * d[7];
    const double bzcx = d[5] * d[6], bxcz = d[3] * d[8];
    const double bxcy = d[3] * d[7], bycx = d[4] * d[6];
    const double t = d[0] * (bycz - bzcy) + d[1] * (bzcx - bxcz) + d[2] * (bxcy - bycx);
    this->Permanent += std::fabs(d[0]) * (std::fabs(bycz) + std::fabs(bzcy)) +
      std::fabs(d[1]) * (std::fabs(bzcx) + std::fabs(bxcz)) +
      std::fabs(d[2]) * (std::fabs(bxcy) + std::fabs(bycx));
    this->Magnitude += std::fabs(t);
    this->Sum += sign * t;
    ++this->Terms;
  }

  /**
   * The exact sign when the double sum certifies it, else 2. Each term is off by at most
   * (7 + 56u) u times its permanent (Shewchuk's orient3d, u = 2^-53), the sum of N terms (in any
   * order) by (N - 1) u (1 + ...) times the sum of their magnitudes; 8u and 1.01 N u cover both
   * and the rounding of the bound itself for N below 2^40. Differences of at least 2^-300 keep
   * every product of up to three of them, and of the cross products' differences, clear of
   * underflow; smaller ones are left to the exact sum. A zero bound means every term was exactly
   * zero.
   */
  int CertifiedSign() const
  {
    constexpr double u = 1.0 / 9007199254740992.0; // 2^-53
    if (!std::isfinite(this->Sum) || !std::isfinite(this->Permanent) ||
      !std::isfinite(this->Magnitude) || this->SmallestDifference < 0x1p-300 ||
      this->Terms > (std::int64_t(1) << 40))
    {
      return 2;
    }
    const double bound =
      8.0 * u * this->Permanent + 1.01 * static_cast<double>(this->Terms) * u * this->Magnitude;
    if (bound == 0.0)
    {
      return 0;
    }
    if (std::fabs(this->Sum) > bound)
    {
      return this->Sum > 0.0 ? 1 : -1;
    }
    return 2;
  }
};

/**
 * The solid angle of triangle (a, b, c) seen from q (van Oosterom and Strackee); NaN when q lies
 * in the triangle's plane (the determinant exactly zero) within or on it (the denominator not
 * positive): a point on the surface has no winding number.
 */
inline double SolidAngle(const double* a, const double* b, const double* c, const double* q)
{
  double x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k)
  {
    x[k] = a[k] - q[k];
    y[k] = b[k] - q[k];
    z[k] = c[k] - q[k];
  }
  const double lx = vtkMath::Norm(x), ly = vtkMath::Norm(y), lz = vtkMath::Norm(z);
  double yz[3];
  vtkMath::Cross(y, z, yz);
  const double det = vtkMath::Dot(x, yz);
  const double denominator =
    lx * ly * lz + vtkMath::Dot(x, y) * lz + vtkMath::Dot(y, z) * lx + vtkMath::Dot(z, x) * ly;
  if (det == 0.0 && denominator <= 0.0)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return 2.0 * std::atan2(det, denominator);
}
} // namespace detail

namespace detail
{
/// What one pass gathers of one component: its bounding box, whether its coordinates are
/// finite, and its flux.
struct PartSum
{
  double Lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double Hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  bool Finite = true;
  FluxSum Flux;

  void Merge(const PartSum& other)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Lo[k] = std::min(this->Lo[k], other.Lo[k]);
      this->Hi[k] = std::max(this->Hi[k], other.Hi[k]);
    }
    this->Finite = this->Finite && other.Finite;
    this->Flux.Sum += other.Flux.Sum;
    this->Flux.Permanent += other.Flux.Permanent;
    this->Flux.Magnitude += other.Flux.Magnitude;
    this->Flux.SmallestDifference =
      std::min(this->Flux.SmallestDifference, other.Flux.SmallestDifference);
    this->Flux.Terms += other.Flux.Terms;
  }
};

/// Components up to which the passes run on several threads, each with its own sums of all.
constexpr std::size_t ThreadedComponents = 1024;
} // namespace detail

/**
 * Turns every orientable component of the `numPolys` polygons (cell array `offsets`, `conn`;
 * coordinates `points`, every id valid) outward, as the file comment says: `orientation` (from
 * ConsistentOrientation, which made each component agree) gets the Reverse flags of the
 * components to turn inverted.
 *
 * One pass over the polygons gathers every component's box and, for a closed component, its
 * flux from its first point (any point gives the volume); a second pass, only over open
 * components, their flux from their box's centre. Both run on several threads when there are
 * few components; the sums' order then varies, their certified or exact sign does not.
 */
template <class T, class Offsets, class Connectivity>
AutoOrientReport AutoOrient(const T* points, vtkIdType numPolys, const Offsets* offsets,
  const Connectivity* conn, Orientation& orientation)
{
  AutoOrientReport report;
  const std::vector<vtkIdType>& component = orientation.Component;
  const std::size_t numComponents = orientation.ComponentClashes.size();
  auto point = [&](vtkIdType id, double* x)
  {
    for (int k = 0; k < 3; ++k)
    {
      x[k] = static_cast<double>(points[3 * static_cast<std::int64_t>(id) + k]);
    }
  };
  struct Part
  {
    detail::PartSum Sum;
    double Reference[3] = { 0.0, 0.0, 0.0 }; // the flux is taken from here
    bool Closed = true;
    int Sign = 0; // of the flux in the consistent ordering: +1 outward, -1 inward, 0 a tie
  };
  std::vector<Part> parts(numComponents);
  // Closed: no slot without a neighbour but edges from a point to itself.
  for (const auto& slot : orientation.OpenSlots)
  {
    const vtkIdType f = slot.first;
    const auto k = slot.second;
    const auto next = k + 1 == static_cast<vtkIdType>(offsets[f + 1]) ? offsets[f] : k + 1;
    if (conn[k] != conn[next])
    {
      parts[static_cast<std::size_t>(component[static_cast<std::size_t>(f)])].Closed = false;
    }
  }
  for (std::size_t c = 0; c < numComponents; ++c)
  {
    const vtkIdType f = orientation.ComponentFirst[c];
    // A polygon without vertices is a component of its own, without a volume or a point.
    if (parts[c].Closed && offsets[f + 1] > offsets[f])
    {
      point(static_cast<vtkIdType>(conn[offsets[f]]), parts[c].Reference);
    }
  }
  // A pass over the polygons of the components `wanted(c)`: box and finiteness always, the
  // flux from the reference when `flux(c)`.
  auto pass = [&](auto&& wanted, auto&& flux)
  {
    auto run = [&](vtkIdType begin, vtkIdType end, std::vector<detail::PartSum>& sums)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const auto c = static_cast<std::size_t>(component[static_cast<std::size_t>(f)]);
        if (!wanted(c))
        {
          continue;
        }
        detail::PartSum& sum = sums[c];
        const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
        double x[3];
        for (vtkIdType k = 0; k < m; ++k)
        {
          point(static_cast<vtkIdType>(conn[offsets[f] + k]), x);
          for (int j = 0; j < 3; ++j)
          {
            sum.Finite = sum.Finite && std::isfinite(x[j]);
            sum.Lo[j] = std::min(sum.Lo[j], x[j]);
            sum.Hi[j] = std::max(sum.Hi[j], x[j]);
          }
        }
        if (m < 3 || !flux(c))
        {
          continue;
        }
        const double sign = orientation.Reverse[static_cast<std::size_t>(f)] ? -1.0 : 1.0;
        double p0[3], a[3], b[3];
        point(static_cast<vtkIdType>(conn[offsets[f]]), p0);
        point(static_cast<vtkIdType>(conn[offsets[f] + 1]), a);
        for (vtkIdType k = 2; k < m; ++k)
        {
          point(static_cast<vtkIdType>(conn[offsets[f] + k]), b);
          sum.Flux.Add(p0, a, b, parts[c].Reference, sign);
          std::copy(b, b + 3, a);
        }
      }
    };
    if (numComponents > detail::ThreadedComponents)
    {
      std::vector<detail::PartSum> sums(numComponents);
      run(0, numPolys, sums);
      for (std::size_t c = 0; c < numComponents; ++c)
      {
        parts[c].Sum.Merge(sums[c]);
      }
      return;
    }
    vtkSMPThreadLocal<std::vector<detail::PartSum>> local;
    phongvtk::For(0, numPolys, FluxWork * numPolys,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<detail::PartSum>& sums = local.Local();
        sums.resize(numComponents);
        run(begin, end, sums);
      });
    for (const std::vector<detail::PartSum>& sums : local)
    {
      for (std::size_t c = 0; c < sums.size(); ++c)
      {
        parts[c].Sum.Merge(sums[c]);
      }
    }
  };
  pass([](std::size_t) { return true; }, [&](std::size_t c) { return parts[c].Closed; });
  bool anyOpen = false;
  for (std::size_t c = 0; c < numComponents; ++c)
  {
    Part& part = parts[c];
    if (!part.Closed && part.Sum.Finite && !orientation.ComponentClashes[c])
    {
      anyOpen = true;
      for (int k = 0; k < 3; ++k)
      {
        part.Reference[k] = 0.5 * part.Sum.Lo[k] + 0.5 * part.Sum.Hi[k];
      }
    }
  }
  auto open = [&](std::size_t c)
  {
    return !parts[c].Closed && parts[c].Sum.Finite && !orientation.ComponentClashes[c];
  };
  if (anyOpen)
  {
    pass(open, open);
  }
  // The polygons of every component, in polygon order (a counting sort), made only when the
  // exact sums or the nesting need them.
  std::vector<vtkIdType> first, members;
  auto listMembers = [&]()
  {
    if (!first.empty())
    {
      return;
    }
    first.assign(numComponents + 1, 0);
    members.resize(static_cast<std::size_t>(numPolys));
    for (vtkIdType f = 0; f < numPolys; ++f)
    {
      ++first[static_cast<std::size_t>(component[static_cast<std::size_t>(f)]) + 1];
    }
    for (std::size_t c = 0; c < numComponents; ++c)
    {
      first[c + 1] += first[c];
    }
    std::vector<vtkIdType> next(first.begin(), first.end() - 1);
    for (vtkIdType f = 0; f < numPolys; ++f)
    {
      members[static_cast<std::size_t>(
        next[static_cast<std::size_t>(component[static_cast<std::size_t>(f)])]++)] = f;
    }
  };
  // The sign of every orientable, finite component's flux.
  std::vector<unsigned char> oriented(numComponents, 0);
  for (std::size_t c = 0; c < numComponents; ++c)
  {
    Part& part = parts[c];
    if (orientation.ComponentClashes[c] || !part.Sum.Finite)
    {
      ++report.Skipped;
      continue;
    }
    oriented[c] = 1;
    ++report.Components;
    report.Closed += part.Closed;
    part.Sign = part.Sum.Flux.CertifiedSign();
    if (part.Sign == 2)
    {
      ++report.ExactSums;
      listMembers();
      std::vector<double> xyz;
      std::vector<std::int64_t> sizes;
      std::vector<signed char> signs;
      for (vtkIdType i = first[c]; i < first[c + 1]; ++i)
      {
        const vtkIdType f = members[static_cast<std::size_t>(i)];
        const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
        for (vtkIdType k = 0; k < m; ++k)
        {
          double x[3];
          point(static_cast<vtkIdType>(conn[offsets[f] + k]), x);
          xyz.insert(xyz.end(), x, x + 3);
        }
        sizes.push_back(m);
        signs.push_back(orientation.Reverse[static_cast<std::size_t>(f)] ? -1 : 1);
      }
      part.Sign = detail::ExactOrientedFluxSign(xyz.data(), sizes.data(), signs.data(),
        static_cast<std::int64_t>(sizes.size()), part.Reference);
    }
    report.Ties += part.Sign == 0;
  }
  // Nesting of the closed components with a volume: how many others hold each.
  std::vector<std::size_t> closed;
  for (std::size_t c = 0; c < numComponents; ++c)
  {
    if (oriented[c] && parts[c].Closed && parts[c].Sign != 0)
    {
      closed.push_back(c);
    }
  }
  std::vector<vtkIdType> depth(numComponents, 0);
  if (closed.size() > 1)
  {
    listMembers();
    std::sort(closed.begin(), closed.end(),
      [&](std::size_t a, std::size_t b)
      {
        return parts[a].Sum.Lo[0] < parts[b].Sum.Lo[0] ||
          (parts[a].Sum.Lo[0] == parts[b].Sum.Lo[0] && a < b);
      });
    auto inBox = [](const detail::PartSum& inner, const detail::PartSum& outer)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (inner.Lo[k] < outer.Lo[k] || inner.Hi[k] > outer.Hi[k])
        {
          return false;
        }
      }
      return true;
    };
    // B's winding number at q, B turned outward; NaN when q is on B.
    auto winding = [&](std::size_t b, const double* q)
    {
      double total = 0.0;
      for (vtkIdType i = first[b]; i < first[b + 1]; ++i)
      {
        const vtkIdType f = members[static_cast<std::size_t>(i)];
        const double sign = (orientation.Reverse[static_cast<std::size_t>(f)] ? -1.0 : 1.0) *
          static_cast<double>(parts[b].Sign);
        const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
        double p0[3], a[3], c[3];
        point(static_cast<vtkIdType>(conn[offsets[f]]), p0);
        point(static_cast<vtkIdType>(conn[offsets[f] + 1]), a);
        for (vtkIdType k = 2; k < m; ++k)
        {
          point(static_cast<vtkIdType>(conn[offsets[f] + k]), c);
          const bool corner =
            std::equal(p0, p0 + 3, q) || std::equal(a, a + 3, q) || std::equal(c, c + 3, q);
          const double angle =
            corner ? std::numeric_limits<double>::quiet_NaN() : detail::SolidAngle(p0, a, c, q);
          if (std::isnan(angle))
          {
            return angle;
          }
          total += sign * angle;
          std::copy(c, c + 3, a);
        }
      }
      return total / (4.0 * vtkMath::Pi());
    };
    auto inside = [&](std::size_t a, std::size_t b)
    {
      constexpr int tries = 8;
      int tried = 0;
      for (vtkIdType i = first[a]; i < first[a + 1] && tried < tries; ++i)
      {
        const vtkIdType f = members[static_cast<std::size_t>(i)];
        for (auto k = offsets[f]; k < offsets[f + 1] && tried < tries; ++k, ++tried)
        {
          double q[3];
          point(static_cast<vtkIdType>(conn[k]), q);
          const double w = winding(b, q);
          if (std::isfinite(w) && std::fabs(w - std::round(w)) < 0.1)
          {
            return std::round(w) != 0.0;
          }
        }
      }
      return false;
    };
    // Components sorted by the left side of their box join the active list; one whose box ends
    // left of the current one's start can hold none of the rest and leaves it.
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < closed.size();)
    {
      const double lo = parts[closed[i]].Sum.Lo[0];
      std::size_t end = i;
      while (end < closed.size() && parts[closed[end]].Sum.Lo[0] == lo)
      {
        ++end;
      }
      active.erase(std::remove_if(active.begin(), active.end(),
                     [&](std::size_t b) { return parts[b].Sum.Hi[0] < lo; }),
        active.end());
      active.insert(active.end(), closed.begin() + i, closed.begin() + end);
      for (std::size_t k = i; k < end; ++k)
      {
        const std::size_t a = closed[k];
        for (const std::size_t b : active)
        {
          if (b != a && inBox(parts[a].Sum, parts[b].Sum) && inside(a, b))
          {
            ++depth[a];
          }
        }
      }
      i = end;
    }
  }
  // Turn the components whose flux is negative, and the cavities.
  std::vector<unsigned char> turn(numComponents, 0);
  for (std::size_t c = 0; c < numComponents; ++c)
  {
    if (!oriented[c])
    {
      continue;
    }
    int sign = parts[c].Sign;
    if (depth[c] % 2 == 1)
    {
      sign = -sign;
      ++report.Cavities;
    }
    turn[c] = sign < 0;
  }
  if (std::find(turn.begin(), turn.end(), 1) != turn.end())
  {
    for (vtkIdType f = 0; f < numPolys; ++f)
    {
      orientation.Reverse[static_cast<std::size_t>(f)] ^=
        turn[static_cast<std::size_t>(component[static_cast<std::size_t>(f)])];
    }
  }
  return report;
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKAutoOrient.h
