/**
 * vtkVisibleArea's edge pass (Filters/PhongVTKEdgeSum.h): the edges that do not cancel, found by
 * hand on small meshes; sum w against the exact rational sum of every polygon's
 * sum_i p_i x p_(i+1) (GMP) on open meshes with scrambled point ids, strips and a high-degree
 * fan; and the same bits for every backend and thread count.
 */
#include "PhongVTKEdgeSum.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
using phongvtk::EdgeSum;
using phongvtk::NetEdge;
using phongvtk::SurfaceCells;
using phongvtk::detail::DD;
using Cell = std::vector<vtkIdType>;

vtkSmartPointer<vtkCellArray> MakeCells(const std::vector<Cell>& cells)
{
  auto array = vtkSmartPointer<vtkCellArray>::New();
  for (const Cell& c : cells)
  {
    array->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  return array;
}

/// The triangles of a strip, each with the strip's alternating orientation (vtkTriangleStrip).
std::vector<Cell> StripTriangles(const Cell& strip)
{
  std::vector<Cell> triangles;
  for (std::size_t j = 0; j + 2 < strip.size(); ++j)
  {
    triangles.push_back({ strip[j + (j & 1)], strip[j + 1 - (j & 1)], strip[j + 2] });
  }
  return triangles;
}

/// The exact sum over the polygons of sum_i p_i x p_(i+1), and the sum of the terms' magnitudes.
std::array<mpq_class, 3> ExactSumW(
  const std::vector<double>& xyz, const std::vector<Cell>& polygons, double magnitude[3])
{
  std::array<mpq_class, 3> sum;
  for (int c = 0; c < 3; ++c)
  {
    magnitude[c] = 0.0;
  }
  for (const Cell& p : polygons)
  {
    for (std::size_t i = 0; i < p.size(); ++i)
    {
      const double* a = &xyz[3 * p[i]];
      const double* b = &xyz[3 * p[(i + 1) % p.size()]];
      for (int c = 0; c < 3; ++c)
      {
        const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        sum[c] += mpq_class(a[c1]) * mpq_class(b[c2]) - mpq_class(a[c2]) * mpq_class(b[c1]);
        magnitude[c] += std::fabs(a[c1] * b[c2]) + std::fabs(a[c2] * b[c1]);
      }
    }
  }
  return sum;
}

struct Result
{
  std::vector<NetEdge> Net;
  DD Sum[3];
  int Scale;
};

Result SumEdges(const std::vector<double>& xyz, vtkCellArray* polys, vtkCellArray* strips,
  const std::vector<unsigned char>& skip = {}, vtkIdType rangeSize = 0)
{
  const vtkIdType numPolys = polys ? polys->GetNumberOfCells() : 0;
  std::vector<SurfaceCells> surfaces = { { polys, 0, false }, { strips, numPolys, true } };
  EdgeSum<double> edges(xyz.data(), static_cast<vtkIdType>(xyz.size() / 3));
  edges.ForcedRangeSize = rangeSize;
  Result r;
  r.Net = edges.NetEdges(surfaces,
    [&skip](vtkIdType cell)
    { return static_cast<std::size_t>(cell) < skip.size() && skip[cell] != 0; });
  edges.Sum(r.Net, r.Sum);
  r.Scale = edges.Scale;
  return r;
}

/// The sum in the input's units (2^(2 Scale) per unit) as an exact rational.
mpq_class Exact(const DD& d, int scale)
{
  mpq_class q = mpq_class(d.Hi) + mpq_class(d.Lo);
  if (scale > 0)
  {
    q.get_num() <<= 2 * scale;
  }
  else if (scale < 0)
  {
    q.get_den() <<= -2 * scale;
  }
  q.canonicalize();
  return q;
}

void ExpectNear(const Result& r, const std::array<mpq_class, 3>& exact, const double magnitude[3],
  const std::string& what)
{
  for (int c = 0; c < 3; ++c)
  {
    const double error = std::fabs(mpq_class(Exact(r.Sum[c], r.Scale) - exact[c]).get_d());
    // Every product is exact (TwoProduct); each double-double addition errs by at most
    // 2^-104 of the running sum's magnitude, bounded by the terms' total.
    EXPECT_LE(error, 0x1p-96 * magnitude[c]) << what << " component " << c;
  }
}

/// A height field z = f(x, y) on an n x n grid, triangulated, its point ids scrambled.
struct Patch
{
  std::vector<double> Points;
  std::vector<Cell> Triangles;
};

Patch ScrambledPatch(int n, std::uint64_t seed, double offset)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const vtkIdType numPoints = static_cast<vtkIdType>(n) * n;
  std::vector<vtkIdType> id(static_cast<std::size_t>(numPoints));
  std::iota(id.begin(), id.end(), 0);
  std::shuffle(id.begin(), id.end(), rng);
  Patch p;
  p.Points.resize(static_cast<std::size_t>(3 * numPoints));
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const vtkIdType k = id[static_cast<std::size_t>(i * n + j)];
      p.Points[3 * k] = offset + i + jitter(rng);
      p.Points[3 * k + 1] = offset + j + jitter(rng);
      p.Points[3 * k + 2] = std::sin(0.1 * i) * std::cos(0.07 * j) + jitter(rng);
    }
  }
  for (int i = 0; i + 1 < n; ++i)
  {
    for (int j = 0; j + 1 < n; ++j)
    {
      const vtkIdType a = id[i * n + j], b = id[(i + 1) * n + j], c = id[(i + 1) * n + j + 1],
                      d = id[i * n + j + 1];
      p.Triangles.push_back({ a, b, c });
      p.Triangles.push_back({ a, c, d });
    }
  }
  return p;
}
} // namespace

TEST(EdgeSumNetEdges, SharedEdgesOfAConsistentPairCancel)
{
  // The unit square as two triangles 0-1-2 and 0-2-3: the diagonal 0-2 cancels.
  const std::vector<double> xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  auto polys = MakeCells({ { 0, 1, 2 }, { 0, 2, 3 } });
  const Result r = SumEdges(xyz, polys, nullptr);
  const std::vector<std::array<vtkIdType, 3>> expected = { { 0, 1, 1 }, { 0, 3, -1 }, { 1, 2, 1 },
    { 2, 3, 1 } };
  ASSERT_EQ(r.Net.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
  {
    EXPECT_EQ(r.Net[k].Low, expected[k][0]) << k;
    EXPECT_EQ(r.Net[k].High, expected[k][1]) << k;
    EXPECT_EQ(r.Net[k].Net, expected[k][2]) << k;
  }
  // sum w = (0, 0, 2): twice the square's area, along +z.
  EXPECT_EQ(r.Sum[0].Hi, 0.0);
  EXPECT_EQ(r.Sum[1].Hi, 0.0);
  EXPECT_EQ(r.Sum[2].Hi + r.Sum[2].Lo, 2.0);
}

TEST(EdgeSumNetEdges, AnInconsistentPairKeepsItsSharedEdgeTwice)
{
  // 0-1-2 and 0-3-2 (the second flipped): both use the diagonal as 2 -> 0.
  const std::vector<double> xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  auto polys = MakeCells({ { 0, 1, 2 }, { 0, 3, 2 } });
  const Result r = SumEdges(xyz, polys, nullptr);
  bool found = false;
  for (const NetEdge& e : r.Net)
  {
    if (e.Low == 0 && e.High == 2)
    {
      found = true;
      EXPECT_EQ(e.Net, -2);
    }
  }
  EXPECT_TRUE(found);
  // The two halves' area vectors cancel: (0, 0, 1) + (0, 0, -1).
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(r.Sum[c].Hi + r.Sum[c].Lo, 0.0) << c;
  }
}

TEST(EdgeSumNetEdges, ClosedSurfaceHasNoneAndSkippedCellsAreLeftOut)
{
  // A tetrahedron, consistently oriented: every edge cancels.
  const std::vector<double> xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  auto polys = MakeCells({ { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } });
  EXPECT_TRUE(SumEdges(xyz, polys, nullptr).Net.empty());
  // Without its last face: the three others' sum, exactly (the face's rim, reversed).
  const Result open = SumEdges(xyz, polys, nullptr, { 0, 0, 0, 1 });
  EXPECT_EQ(open.Net.size(), 3u);
  double m[3];
  const auto exact = ExactSumW(xyz, { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 } }, m);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(mpq_class(Exact(open.Sum[c], open.Scale) - exact[c]), 0) << c;
  }
}

TEST(EdgeSumAccuracy, OpenPatchWithScrambledIdsAgainstExactArithmetic)
{
  for (double offset : { 0.0, 1e7 })
  {
    Patch p = ScrambledPatch(120, 3, offset);
    // Holes: drop every 7th triangle.
    std::vector<Cell> kept;
    for (std::size_t k = 0; k < p.Triangles.size(); ++k)
    {
      if (k % 7 != 3)
      {
        kept.push_back(p.Triangles[k]);
      }
    }
    // A quad and a pentagon on top, and a strip.
    kept.push_back({ 0, 5, 17, 9 });
    kept.push_back({ 3, 11, 4, 40, 8 });
    const Cell strip = { 20, 21, 22, 23, 24, 25 };
    auto polys = MakeCells(kept);
    auto strips = MakeCells({ strip });
    std::vector<Cell> all = kept;
    for (const Cell& t : StripTriangles(strip))
    {
      all.push_back(t);
    }
    double magnitude[3];
    const auto exact = ExactSumW(p.Points, all, magnitude);
    const Result r = SumEdges(p.Points, polys, strips);
    ExpectNear(r, exact, magnitude, "offset " + std::to_string(offset));
    EXPECT_GT(r.Net.size(), 0u);
    for (std::size_t k = 1; k < r.Net.size(); ++k)
    {
      const bool ordered = r.Net[k - 1].Low < r.Net[k].Low ||
        (r.Net[k - 1].Low == r.Net[k].Low && r.Net[k - 1].High < r.Net[k].High);
      ASSERT_TRUE(ordered) << "net edge " << k;
    }
  }
}

TEST(EdgeSumAccuracy, HighDegreeFanAgainstExactArithmetic)
{
  // A disc of 200,000 triangles around one centre (point 0), open at its rim, tilted.
  const int n = 200000;
  std::vector<double> xyz = { 0.25, -0.5, 0.125 };
  for (int k = 0; k < n; ++k)
  {
    const double t = 2 * M_PI * k / n;
    xyz.insert(xyz.end(), { std::cos(t), std::sin(t), 0.3 * std::cos(t) });
  }
  std::vector<Cell> fan;
  for (vtkIdType k = 0; k < n; ++k)
  {
    fan.push_back({ 0, 1 + k, 1 + (k + 1) % n });
  }
  auto polys = MakeCells(fan);
  double magnitude[3];
  const auto exact = ExactSumW(xyz, fan, magnitude);
  const Result r = SumEdges(xyz, polys, nullptr);
  EXPECT_EQ(r.Net.size(), static_cast<std::size_t>(n)); // the rim only
  ExpectNear(r, exact, magnitude, "fan");
}

TEST(EdgeSumAccuracy, ExtremeCoordinatesAreScaled)
{
  for (double scale : { 0x1p-700, 0x1p700 })
  {
    const std::vector<double> xyz = { 0, 0, 0, scale, 0, 0, scale, scale, 0, 0, scale, scale };
    const std::vector<Cell> polygons = { { 0, 1, 2 }, { 0, 2, 3 } };
    auto polys = MakeCells(polygons);
    const Result r = SumEdges(xyz, polys, nullptr);
    double m[3];
    const auto exact = ExactSumW(xyz, polygons, m);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(mpq_class(Exact(r.Sum[c], r.Scale) - exact[c]), 0) << scale << " " << c;
      EXPECT_TRUE(std::isfinite(r.Sum[c].Hi));
    }
  }
}

TEST(EdgeSumThreads, SameBitsForEveryBackendAndThreadCount)
{
  // Large enough to run in parallel (PhongVTKParallel.h), ids scrambled (ranges grow).
  Patch p = ScrambledPatch(400, 11, 0.5);
  std::vector<Cell> kept;
  for (std::size_t k = 0; k < p.Triangles.size(); ++k)
  {
    if (k % 5 != 0)
    {
      kept.push_back(p.Triangles[k]);
    }
  }
  auto polys = MakeCells(kept);
  ASSERT_GT(6 * polys->GetNumberOfCells(), phongvtk::SerialWork);
  const std::string original = vtkSMPTools::GetBackend();
  struct Config
  {
    const char* Backend;
    int Threads;
  };
  std::vector<Result> results;
  for (const Config& config : { Config{ "Sequential", 1 }, Config{ "STDThread", 1 },
         Config{ "STDThread", 2 }, Config{ "STDThread", 4 } })
  {
    ASSERT_TRUE(vtkSMPTools::SetBackend(config.Backend));
    vtkSMPTools::Initialize(config.Threads);
    results.push_back(SumEdges(p.Points, polys, nullptr));
  }
  // Forced range sizes, shared by two threads (on a few cores the sizes the sum picks barely
  // move with the thread count).
  for (vtkIdType size : { 997, 4099, 16384, 65537 })
  {
    ASSERT_TRUE(vtkSMPTools::SetBackend("STDThread"));
    vtkSMPTools::Initialize(2);
    results.push_back(SumEdges(p.Points, polys, nullptr, {}, size));
  }
  vtkSMPTools::SetBackend(original.c_str());
  vtkSMPTools::Initialize(0);
  ASSERT_GT(results[0].Net.size(), EdgeSum<double>::Chunk); // several chunks
  for (std::size_t k = 1; k < results.size(); ++k)
  {
    ASSERT_EQ(results[k].Net.size(), results[0].Net.size()) << k;
    EXPECT_EQ(std::memcmp(results[k].Net.data(), results[0].Net.data(),
                results[0].Net.size() * sizeof(NetEdge)),
      0)
      << k;
    EXPECT_EQ(std::memcmp(results[k].Sum, results[0].Sum, sizeof(results[0].Sum)), 0) << k;
  }
  double magnitude[3];
  ExpectNear(results[0], ExactSumW(p.Points, kept, magnitude), magnitude, "scrambled 400");
}

// Every range size, from one point a range (every boundary) to one range, on a small scrambled
// patch: the same net edges and the same sum.
TEST(EdgeSumThreads, SameBitsForEveryRangeSize)
{
  Patch p = ScrambledPatch(24, 5, 0.5);
  auto polys = MakeCells(p.Triangles);
  const vtkIdType n = static_cast<vtkIdType>(p.Points.size() / 3);
  const Result whole = SumEdges(p.Points, polys, nullptr, {}, n);
  ASSERT_FALSE(whole.Net.empty());
  for (vtkIdType size : { vtkIdType(1), vtkIdType(2), vtkIdType(7), vtkIdType(61), n - 1 })
  {
    const Result r = SumEdges(p.Points, polys, nullptr, {}, size);
    ASSERT_EQ(r.Net.size(), whole.Net.size()) << size;
    EXPECT_EQ(std::memcmp(r.Net.data(), whole.Net.data(), whole.Net.size() * sizeof(NetEdge)), 0)
      << size;
    EXPECT_EQ(std::memcmp(r.Sum, whole.Sum, sizeof(whole.Sum)), 0) << size;
  }
}
