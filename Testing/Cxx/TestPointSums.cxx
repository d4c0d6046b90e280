/**
 * The order-independent point sums (Filters/PhongVTKPointSums.h) against exact rational sums
 * (GMP): the same bits for every order of the contributions, and within the documented distance
 * of the exact sum, for contributions of every scale.
 */
#include "PhongVTKPointSums.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace
{
using phongvtk::InvariantSums;

struct Contribution
{
  double V[3];
  int E;
};

/// x * 2^e as an exact rational.
mpq_class Exact(double x, int e)
{
  mpq_class q(x);
  if (e > 0)
  {
    q.get_num() <<= e;
  }
  else if (e < 0)
  {
    q.get_den() <<= -e;
  }
  q.canonicalize();
  return q;
}

struct Sum
{
  double S[3];
  int E;
};

/// One point's sum of `items` taken in the given order.
Sum SumOf(const std::vector<Contribution>& items)
{
  InvariantSums sums;
  sums.Reset(1);
  for (const Contribution& c : items)
  {
    sums.Count(0, c.V, c.E);
  }
  // The second pass in the reverse order: each pass is order-independent by itself.
  sums.StartDeposits();
  for (auto c = items.rbegin(); c != items.rend(); ++c)
  {
    sums.Deposit(0, c->V, c->E);
  }
  Sum out{};
  sums.Finish(
    [&](std::int32_t, const double s[3], int e)
    {
      std::copy(s, s + 3, out.S);
      out.E = e;
    });
  return out;
}

bool SameBits(const Sum& a, const Sum& b)
{
  return std::memcmp(a.S, b.S, sizeof a.S) == 0 && (a.E == b.E);
}

/// Largest |component| * 2^E over the contributions, exactly.
mpq_class Largest(const std::vector<Contribution>& items)
{
  mpq_class top = 0;
  for (const Contribution& c : items)
  {
    for (double v : c.V)
    {
      top = std::max<mpq_class>(top, abs(Exact(v, c.E)));
    }
  }
  return top;
}

/// Checks every order gives the same bits and each component is the exact sum to within half an
/// ulp of the result plus count 2^(2h - 106) of the largest contribution (the header's bound).
void CheckAgainstExact(const std::vector<Contribution>& items, std::mt19937_64& random)
{
  const Sum first = SumOf(items);
  std::vector<Contribution> shuffled = items;
  for (int round = 0; round < 8; ++round)
  {
    std::shuffle(shuffled.begin(), shuffled.end(), random);
    ASSERT_TRUE(SameBits(first, SumOf(shuffled))) << "order changed the sum, round " << round;
  }
  std::reverse(shuffled.begin(), shuffled.end());
  ASSERT_TRUE(SameBits(first, SumOf(shuffled)));

  int h = 1;
  for (std::size_t c = items.size(); c != 0; c >>= 1)
  {
    ++h;
  }
  const mpq_class largest = Largest(items);
  for (int c = 0; c < 3; ++c)
  {
    mpq_class exact = 0;
    for (const Contribution& item : items)
    {
      exact += Exact(item.V[c], item.E);
    }
    const mpq_class got = Exact(first.S[c], first.E);
    // Half an ulp of the result (one rounding of the exact two-part sum) ...
    const double magnitude = std::fabs(first.S[c]);
    const mpq_class halfUlp =
      magnitude > 0 ? Exact(std::ldexp(1.0, std::ilogb(magnitude) - 53), first.E) : mpq_class(0);
    // ... plus the parts below the low grid.
    mpq_class lost = largest * static_cast<unsigned long>(items.size());
    lost.get_den() <<= (106 - 2 * h);
    lost.canonicalize();
    EXPECT_LE(abs(got - exact), halfUlp + 2 * lost)
      << "component " << c << " of " << items.size() << " contributions";
  }
}

std::vector<Contribution> RandomFan(std::mt19937_64& random, int count, int spread, int exponent)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-spread, spread);
  std::vector<Contribution> items;
  for (int i = 0; i < count; ++i)
  {
    Contribution c{};
    for (double& v : c.V)
    {
      v = std::ldexp(unit(random), scale(random));
    }
    c.E = exponent;
    items.push_back(c);
  }
  return items;
}
} // namespace

TEST(PointSums, SameBitsInEveryOrderAndCloseToTheExactSum)
{
  std::mt19937_64 random(7);
  for (int count : { 1, 2, 3, 5, 6, 7, 8, 12, 31, 64, 1000 })
  {
    for (int spread : { 0, 3, 30, 70 })
    {
      SCOPED_TRACE(::testing::Message() << count << " contributions, spread 2^" << spread);
      CheckAgainstExact(RandomFan(random, count, spread, 0), random);
    }
  }
}

TEST(PointSums, FacesOfEveryScaleAtOnePoint)
{
  // Exponents of their own from 2^-2000 to 2^2000 and double values near both ends of the range.
  std::mt19937_64 random(11);
  std::uniform_int_distribution<int> exponent(-2000, 2000);
  for (int round = 0; round < 50; ++round)
  {
    std::vector<Contribution> items = RandomFan(random, 9, 20, 0);
    for (Contribution& c : items)
    {
      c.E = exponent(random);
    }
    items[0].V[0] = 0x1p-1074; // subnormal
    items[1].V[1] = 0x1.fffffffffffffp1023;
    CheckAgainstExact(items, random);
  }
}

TEST(PointSums, CancellingContributionsGiveExactlyZero)
{
  std::mt19937_64 random(3);
  std::vector<Contribution> items = RandomFan(random, 40, 40, -300);
  const std::size_t n = items.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    Contribution c = items[i];
    for (double& v : c.V)
    {
      v = -v;
    }
    items.push_back(c);
  }
  const Sum s = SumOf(items);
  for (double v : s.S)
  {
    EXPECT_EQ(v, 0.0);
  }
}

TEST(PointSums, ContributionsNearOneAnotherAddAsTheExactSumRoundedOnce)
{
  // Three faces whose double sum rounds twice: 1 + 2^-53 + 2^-53 is 1 in cell order, 1 + 2^-52
  // exactly.
  const std::vector<Contribution> items = { { { 1.0, 0.0, 0.0 }, 0 }, { { 0x1p-53, 0.0, 0.0 }, 0 },
    { { 0x1p-53, 0.0, 0.0 }, 0 } };
  const Sum s = SumOf(items);
  EXPECT_EQ(std::ldexp(s.S[0], s.E), 1.0 + 0x1p-52);
}

TEST(PointSums, PointsWithoutContributionsAndZeroContributionsGiveZero)
{
  InvariantSums sums;
  sums.Reset(3);
  const double zero[3] = { 0.0, -0.0, 0.0 };
  const double one[3] = { 0.0, 1.0, 0.0 };
  sums.Count(1, zero, 5);
  sums.Count(2, one, 0);
  sums.StartDeposits();
  sums.Deposit(1, zero, 5);
  sums.Deposit(2, one, 0);
  std::vector<Sum> out(3);
  sums.Finish(
    [&](std::int32_t p, const double s[3], int e)
    {
      std::copy(s, s + 3, out[static_cast<std::size_t>(p)].S);
      out[static_cast<std::size_t>(p)].E = e;
    });
  for (int p = 0; p < 2; ++p)
  {
    EXPECT_EQ(out[p].S[0], 0.0);
    EXPECT_EQ(out[p].S[1], 0.0);
    EXPECT_EQ(out[p].S[2], 0.0);
  }
  EXPECT_EQ(std::ldexp(out[2].S[1], out[2].E), 1.0);
}

TEST(PointSums, AHundredThousandFacesAtOnePoint)
{
  std::mt19937_64 random(5);
  CheckAgainstExact(RandomFan(random, 100000, 2, 0), random);
}

TEST(PointSums, DoublesAtBothEndsOfTheRangeWithoutAnExponent)
{
  // Exponent 0 throughout: the largest contribution near 2^1023 or a point whose contributions
  // are all subnormal takes the scaling that leaves the normal range.
  std::mt19937_64 random(13);
  std::vector<Contribution> huge = RandomFan(random, 6, 3, 0);
  for (Contribution& c : huge)
  {
    for (double& v : c.V)
    {
      v = std::ldexp(v, 1018);
    }
  }
  huge[2].V[0] = 0x1.fffffffffffffp1023;
  CheckAgainstExact(huge, random);
  std::vector<Contribution> tiny = RandomFan(random, 6, 3, 0);
  for (Contribution& c : tiny)
  {
    for (double& v : c.V)
    {
      v = std::ldexp(v, -1060); // subnormal
    }
  }
  CheckAgainstExact(tiny, random);
}
