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

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <vector>

namespace phongvtk
{

/**
 * A point normal sum in cell order with a binary exponent of its own: the value is S * 2^E.
 * Contributions of any scale add without overflow or underflow; when every exponent is zero
 * (faces of ordinary size) the additions are exactly those of a plain double sum.
 */
struct ScaledSum
{
  double S[3] = { 0.0, 0.0, 0.0 };
  int E = 0;

  PHONGVTK_INLINE void Add(const double v[3], int e)
  {
    if (e != this->E)
    {
      this->AddScaled(v, e);
      return;
    }
    // Contributions lie below 2^500 and the sum is renormalised below 2^500 whenever exponents
    // differ, so plain additions (the common case) cannot overflow.
    for (int c = 0; c < 3; ++c)
    {
      this->S[c] += v[c];
    }
  }

  /// Adds v * 2^e when e differs from the sum's exponent: the smaller of the two is scaled to
  /// the larger one's exponent (and may vanish: it is then negligible).
  void AddScaled(const double v[3], int e)
  {
    using detail::Scale2;
    if (this->S[0] == 0.0 && this->S[1] == 0.0 && this->S[2] == 0.0)
    {
      std::copy(v, v + 3, this->S);
      this->E = e;
    }
    else if (e > this->E)
    {
      const int d = std::max(this->E - e, -2200);
      for (int c = 0; c < 3; ++c)
      {
        this->S[c] = Scale2(Scale2(this->S[c], d / 2), d - d / 2) + v[c];
      }
      this->E = e;
    }
    else
    {
      const int d = std::max(e - this->E, -2200);
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
    if (!(m <= 0x1p500) || (m < 0x1p-500 && m != 0.0))
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
      this->E += k;
    }
  }
};

/**
 * Order-independent sums of the contributions to a block of points [0, Size). Add() records
 * contributions (finite V); Finish() forms every point's sum. The result of a point depends only
 * on the multiset of (V, E) given to it, bit for bit.
 */
class InvariantSums
{
public:
  /// Forgets every contribution; the points are [0, points).
  void Reset(std::size_t points)
  {
    this->Top.assign(points, INT_MIN);
    this->Count.assign(points, 0);
    this->Items.clear();
  }

  std::size_t Size() const { return this->Top.size(); }

  /// The exponent Add() needs: that of V's largest component plus E (INT_MIN for a zero V).
  static PHONGVTK_INLINE int TopOf(const double v[3], int e)
  {
    const double m = detail::MaxAbs3(v);
    return m > 0.0 ? e + detail::Exponent2(m) : INT_MIN;
  }

  /// Records V * 2^E for `point`; a zero vector adds nothing and is not counted.
  PHONGVTK_INLINE void Add(std::int32_t point, const double v[3], int e)
  {
    this->Add(point, v, e, TopOf(v, e));
  }

  /// Add() with TopOf(v, e) already known (one face, several corners).
  PHONGVTK_INLINE void Add(std::int32_t point, const double v[3], int e, int top)
  {
    if (top == INT_MIN)
    {
      return;
    }
    int& t = this->Top[static_cast<std::size_t>(point)];
    t = std::max(t, top);
    ++this->Count[static_cast<std::size_t>(point)];
    this->Items.push_back(Item{ { v[0], v[1], v[2] }, e, point });
  }

  /**
   * Every point's sum: `write(point, s, exponent)` with the sum s * 2^exponent (s zero for a
   * point without contributions).
   */
  template <class WriteFn>
  void Finish(const WriteFn& write)
  {
    using detail::V4;
    const std::size_t n = this->Size();
    this->Parts.assign(n, Part{});
    this->Grid.resize(n);
    for (std::size_t p = 0; p < n; ++p)
    {
      this->Grid[p] = GridOf(this->Count[p]);
    }
    for (const Item& item : this->Items)
    {
      const std::size_t p = static_cast<std::size_t>(item.Point);
      Part& part = this->Parts[p];
      const Magic m = this->Grid[p];
      V4 x;
      const int k = item.E - this->Top[p] - 1;
      if (k >= -1022 && k <= 1023)
      {
        x = V4{ item.V[0], item.V[1], item.V[2], 0.0 } * detail::Pow2(k);
      }
      else
      {
        for (int c = 0; c < 3; ++c)
        {
          x[c] = detail::Scale2(item.V[c], k);
        }
        x[3] = 0.0;
      }
      // fl(x + M) - M is x rounded to M's ulp, a function of x alone (ties to even), and exact.
      const V4 high = (x + m.High) - m.High;
      const V4 low = ((x - high) + m.Low) - m.Low;
      part.Hi += high;
      part.Lo += low;
    }
    for (std::size_t p = 0; p < n; ++p)
    {
      const V4 sum = this->Parts[p].Hi + this->Parts[p].Lo;
      const double s[3] = { sum[0], sum[1], sum[2] };
      write(static_cast<std::int32_t>(p), s, this->Count[p] > 0 ? this->Top[p] + 1 : 0);
    }
  }

  /// The two rounding constants of a point with `count` contributions: 1.5 * 2^52 times the
  /// grid of the high and of the low part.
  struct Magic
  {
    double High;
    double Low;
  };

  /**
   * With h = bit width of count + 1 (so count < 2^(h-1)) and every scaled contribution below 1
   * in magnitude: the high part is rounded onto the grid 2^(h-53), the rest onto 2^(2h-106);
   * sums of count such parts stay below 2^53 of their grid, hence exact.
   */
  static Magic GridOf(std::int32_t count)
  {
    const int h = count > 0 ? 33 - __builtin_clz(static_cast<unsigned>(count)) : 2;
    return Magic{ 0x1.8p0 * detail::Pow2(h - 1), 0x1.8p0 * detail::Pow2(2 * h - 54) };
  }

private:
  struct Item
  {
    double V[3];
    int E;
    std::int32_t Point;
  };
  struct Part
  {
    detail::V4 Hi = {}, Lo = {}; // the exact sums of the high and of the low parts
  };
  std::vector<int> Top;            // largest exponent of a contribution's largest component
  std::vector<std::int32_t> Count; // contributions per point
  std::vector<Item> Items;
  std::vector<Part> Parts;
  std::vector<Magic> Grid; // each point's rounding constants
};

} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKPointSums.h
