/**
 * @file PhongVTKPointSums.h
 * @brief Private: the sums of the faces' contributions that make a point normal, in cell order
 * (ScaledSum) or independent of the order by construction (InvariantSums).
 *
 * A contribution is `V * 2^E`: a double vector with an exponent of its own, so that faces of any
 * size (2^-1000 beside 2^1000) add without overflow or underflow.
 *
 * InvariantSums makes each point's sum a function of the *set* of its contributions: every
 * contribution is rounded, by itself, onto two grids fixed by that set alone (the largest
 * contribution's exponent and the number of contributions), and the rounded parts are added in
 * double where every partial sum is exact. No addition rounds, so the order cannot matter; the
 * two grids keep 2 (52 - h) bits below the largest contribution (h = bit width of the count, + 1),
 * so the result is the exact sum rounded once, to within Count 2^(2h - 106) of the largest
 * contribution (2^-95 relative for up to seven faces at a point). This replaces sorting each
 * point's contributions by value (the same guarantee, twice the cost of the cell-order fold).
 */
#ifndef PhongVTKPointSums_h
#define PhongVTKPointSums_h

#include "PhongVTKAreaVector.h"
#include "PhongVTKKernelNamespace.h"

#include "vtkType.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN

/**
 * A point normal sum in cell order with a binary exponent of its own: the value is S * 2^E.
 * Contributions of any scale add without overflow or underflow; when every exponent is zero
 * (faces of ordinary size) the additions are exactly those of a plain double sum.
 */
struct ScaledSum
{
  double S[3] = { 0.0, 0.0, 0.0 };
  double Exponent = 0.0; // E, an integer held as a double: the four doubles add as one register

  int E() const { return static_cast<int>(this->Exponent); }

  PHONGVTK_INLINE void Add(const double v[3], int e)
  {
    if (static_cast<double>(e) != this->Exponent)
    {
      this->AddScaled(v, e);
      return;
    }
    this->AddInPlace(detail::V4{ v[0], v[1], v[2], 0.0 });
  }

  /// Add() of (v0, v1, v2, 0) with exponent 0.
  PHONGVTK_INLINE void Add(const detail::V4& v)
  {
    if (this->Exponent != 0.0)
    {
      const double w[3] = { v[0], v[1], v[2] };
      this->AddScaled(w, 0);
      return;
    }
    this->AddInPlace(v);
  }

  /// Contributions lie below 2^500 and the sum is renormalised below 2^500 whenever exponents
  /// differ, so plain additions (the common case) cannot overflow. Lane 3 adds zero to the
  /// exponent, which an integer-valued double keeps exactly.
  PHONGVTK_INLINE void AddInPlace(const detail::V4& v)
  {
    detail::V4 sum;
    std::memcpy(&sum, this, sizeof sum);
    sum += v;
    std::memcpy(this, &sum, sizeof sum);
  }

  /// Adds v * 2^e when e differs from the sum's exponent: the smaller of the two is scaled to
  /// the larger one's exponent (and may vanish: it is then negligible).
  void AddScaled(const double v[3], int e)
  {
    using detail::Scale2;
    const int own = this->E();
    if (this->S[0] == 0.0 && this->S[1] == 0.0 && this->S[2] == 0.0)
    {
      std::copy(v, v + 3, this->S);
      this->Exponent = e;
    }
    else if (e > own)
    {
      const int d = std::max(own - e, -2200);
      for (int c = 0; c < 3; ++c)
      {
        this->S[c] = Scale2(Scale2(this->S[c], d / 2), d - d / 2) + v[c];
      }
      this->Exponent = e;
    }
    else
    {
      const int d = std::max(e - own, -2200);
      for (int c = 0; c < 3; ++c)
      {
        this->S[c] += Scale2(Scale2(v[c], d / 2), d - d / 2);
      }
    }
    this->Renormalize();
  }

  void Renormalize()
  {
    const double m = detail::MaxAbs3(this->S);
    if (!(m <= detail::DoubleWindow.Top) || (m < detail::DoubleWindow.Bottom && m != 0.0))
    {
      if (!std::isfinite(m))
      {
        return;
      }
      const int k = detail::Exponent2(m);
      for (double& x : this->S)
      {
        x = detail::Scale2(x, -k);
      }
      this->Exponent = this->E() + k;
    }
  }
};
static_assert(sizeof(ScaledSum) == sizeof(detail::V4), "ScaledSum adds as one register");

/**
 * Order-independent sums of the contributions to a block of points [0, Size), in two passes over
 * the same contributions (in any order each): Count() (after Reset) finds every point's largest
 * exponent and number of contributions; StartDeposits() fixes each point's grids, and Deposit()
 * adds every contribution, rounded onto them, into exact sums. Finish() hands out the sums. A
 * point's result depends only on the multiset of (V, E) given to it, bit for bit. Two passes
 * instead of keeping the contributions: recomputing a face costs less than storing and reloading
 * its contributions (measured: 32 bytes a corner written and read again was most of the cost).
 */
class InvariantSums
{
public:
  /// Forgets every contribution and starts the first pass; the points are [0, points).
  void Reset(std::size_t points) { this->Points.assign(points, PointState{}); }

  std::size_t Size() const { return this->Points.size(); }

  /// The exponent Count() needs: that of V's largest component plus E (INT_MIN for a zero V).
  static PHONGVTK_INLINE int TopOf(const double v[3], int e)
  {
    const double m = detail::MaxAbs3(v);
    return m > 0.0 ? e + detail::Exponent2(m) : INT_MIN;
  }

  /// First pass: V * 2^E for `point` (finite V); a zero vector is not counted.
  PHONGVTK_INLINE void Count(std::int32_t point, const double v[3], int e)
  {
    this->Count(point, TopOf(v, e));
  }

  /// Count() with TopOf(v, e) already known (one face, several corners).
  PHONGVTK_INLINE void Count(std::int32_t point, int top)
  {
    if (top == INT_MIN)
    {
      return;
    }
    const std::size_t p = static_cast<std::size_t>(point);
    PointState& state = this->Points[p];
    state.Top = std::max(state.Top, top);
    ++state.Count;
  }

  /// Ends the first pass: every point's grids.
  void StartDeposits()
  {
    const std::size_t n = this->Size();
    this->Parts.assign(n, Part{});
    this->Grid.resize(n);
    for (std::size_t p = 0; p < n; ++p)
    {
      const PointState& state = this->Points[p];
      this->Grid[p] = GridOf(state.Count, state.Count > 0 ? -state.Top - 1 : 0);
    }
  }

  /// Second pass: the same contribution as given to Count(), rounded onto the point's grids and
  /// added exactly.
  PHONGVTK_INLINE void Deposit(std::int32_t point, const double v[3], int e)
  {
    this->Deposit(point, detail::V4{ v[0], v[1], v[2], 0.0 }, e);
  }

  /// Deposit() of (v0, v1, v2, 0).
  PHONGVTK_INLINE void Deposit(std::int32_t point, const detail::V4& v, int e)
  {
    using detail::V4;
    if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0)
    {
      return; // not counted either
    }
    const std::size_t p = static_cast<std::size_t>(point);
    const Magic& m = this->Grid[p];
    V4 x;
    if (e == 0 && m.Scale != 0.0)
    {
      x = v * m.Scale; // exact: a power of two within the normal range
    }
    else
    {
      const int k = e - this->Points[p].Top - 1;
      x = V4{ detail::Scale2(v[0], k), detail::Scale2(v[1], k), detail::Scale2(v[2], k), 0.0 };
    }
    // fl(x + M) - M is x rounded to M's ulp, a function of x alone (ties to even), and exact.
    const V4 high = (x + m.High) - m.High;
    const V4 low = ((x - high) + m.Low) - m.Low;
    Part& part = this->Parts[p];
    part.Hi += high;
    part.Lo += low;
  }

  /**
   * Every point's sum after the second pass: `write(point, s, exponent)` with the sum
   * s * 2^exponent (s zero for a point without contributions).
   */
  template <class WriteFn>
  void Finish(const WriteFn& write) const
  {
    for (std::size_t p = 0; p < this->Size(); ++p)
    {
      double s[3];
      this->SumOf(static_cast<vtkIdType>(p), s);
      write(static_cast<std::int32_t>(p), s, this->ExponentOf(static_cast<vtkIdType>(p)));
    }
  }

  /// Point p's sum after the second pass is s * 2^ExponentOf(p).
  PHONGVTK_INLINE void SumOf(vtkIdType p, double s[3]) const
  {
    const Part& part = this->Parts[static_cast<std::size_t>(p)];
    const detail::V4 sum = part.Hi + part.Lo;
    s[0] = sum[0];
    s[1] = sum[1];
    s[2] = sum[2];
  }

  int ExponentOf(vtkIdType p) const
  {
    const std::size_t i = static_cast<std::size_t>(p);
    return this->Points[i].Count > 0 ? this->Points[i].Top + 1 : 0;
  }

  /// The two rounding constants of a point with `count` contributions (1.5 * 2^52 times the grid
  /// of the high and of the low part), and 2^k, the scale of its contributions of exponent 0
  /// (zero when 2^k is not a normal double).
  struct Magic
  {
    double High;
    double Low;
    double Scale;
  };

  /**
   * With h = bit width of count + 1 (so count < 2^(h-1)) and every scaled contribution below 1
   * in magnitude: the high part is rounded onto the grid 2^(h-53), the rest onto 2^(2h-106);
   * sums of count such parts stay below 2^53 of their grid, hence exact.
   */
  static Magic GridOf(std::int32_t count, int k)
  {
    int h = 2;
    for (std::uint32_t c = static_cast<std::uint32_t>(count); c > 1; c >>= 1)
    {
      ++h;
    }
    return Magic{ 0x1.8p0 * detail::Pow2(h - 1), 0x1.8p0 * detail::Pow2(2 * h - 54),
      k >= -1022 && k <= 1023 ? detail::Pow2(k) : 0.0 };
  }

private:
  struct Part
  {
    detail::V4 Hi = {}, Lo = {}; // the exact sums of the high and of the low parts
  };
  struct PointState // the first pass's findings, side by side: one cache line a corner
  {
    int Top = INT_MIN;      // largest exponent of a contribution's largest component
    std::int32_t Count = 0; // contributions
  };
  std::vector<PointState> Points;
  std::vector<Part> Parts;
  std::vector<Magic> Grid; // each point's rounding constants
};

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKPointSums.h
