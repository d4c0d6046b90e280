// Feature-angle splitting of vtkPolygonNormals: the regions around a point (PhongVTKSplitting.h),
// the sharp-edge decision (PhongVTKFeatureAngle.h) against exact rational arithmetic, and the
// filter's output (copies, OriginalPointIds, pass-through) against hand-counted meshes and
// VTK's own vtkPolyDataNormals where its float test cannot be fooled.
#include "PhongVTKExactReference.h"
#include "PhongVTKFeatureAngle.h"
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKOFFReader.h"
#include "PhongVTKSkip.h"
#include "PhongVTKSplitting.h"
#include "vtkPolygonNormals.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace
{
using phongvtk_test::Cell;
using phongvtk_test::Cells;
using phongvtk_test::MakePolyData;
using phongvtk_test::MessageObserver;
using phongvtk_test::Point;
using phongvtk_test::PolygonsOf;
using phongvtk_test::RoughSphere;

constexpr int Modes[] = { vtkPolygonNormals::FAST, vtkPolygonNormals::DOUBLE,
  vtkPolygonNormals::COMPENSATED, vtkPolygonNormals::EXACT };

const char* ModeName(int mode)
{
  static const char* const names[] = { "FAST", "DOUBLE", "COMPENSATED", "EXACT" };
  return names[mode];
}

/// The filter with point normals and splitting on, then `configure`; no error expected.
vtkSmartPointer<vtkPolyData> Split(vtkPolyData* input, int mode = vtkPolygonNormals::DOUBLE,
  double angle = 30.0, const std::function<void(vtkPolygonNormals*)>& configure = {})
{
  vtkNew<vtkPolygonNormals> filter;
  phongvtk_test::CellNormalsOfTheCellsAsGiven(filter);
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  filter->SetAccuracy(mode);
  filter->ComputePointNormalsOn();
  filter->SplittingOn();
  filter->ConsistencyOff(); // the polygons as given: splitting alone
  filter->SetFeatureAngle(angle);
  if (configure)
  {
    configure(filter);
  }
  filter->SetInputData(input);
  filter->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors.front();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}

/// vtkPolyDataNormals' point count with splitting alone (no consistency, no orientation).
vtkIdType VTKSplitPointCount(vtkPolyData* input, double angle = 30.0)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(input);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->SetFeatureAngle(angle);
  normals->Update();
  return normals->GetOutput()->GetNumberOfPoints();
}

/// The unit cube as six quads, outward.
vtkSmartPointer<vtkPolyData> Cube(double offset = 0.0)
{
  std::vector<Point> p;
  for (int i = 0; i < 8; ++i)
  {
    p.push_back({ offset + (i & 1), offset + ((i >> 1) & 1), offset + ((i >> 2) & 1) });
  }
  Cells cells;
  cells.Polys = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 },
    { 1, 3, 7, 5 } };
  return MakePolyData(p, cells);
}

/// A flat n x n grid of squares, each split into two triangles.
vtkSmartPointer<vtkPolyData> FlatGrid(int n)
{
  std::vector<Point> p;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      p.push_back({ double(i), double(j), 0.0 });
    }
  }
  Cells cells;
  auto id = [n](int i, int j)
  {
    return vtkIdType(j * (n + 1) + i);
  };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      cells.Polys.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      cells.Polys.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MakePolyData(p, cells);
}

/**
 * How the corners of each input point are grouped: for every input point, the set of groups of
 * (input polygon, corner) that share an output point. `polygonOf[i]` is the input polygon of
 * output polygon i.
 */
using Grouping = std::map<vtkIdType, std::set<std::set<std::pair<vtkIdType, vtkIdType>>>>;
Grouping CornerGroups(vtkPolyData* out, const std::vector<vtkIdType>& polygonOf)
{
  auto* original = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("OriginalPointIds"));
  EXPECT_NE(original, nullptr);
  std::map<vtkIdType, std::set<std::pair<vtkIdType, vtkIdType>>> byOutputPoint;
  const std::vector<Cell> polys = PolygonsOf(out);
  for (std::size_t i = 0; i < polys.size(); ++i)
  {
    for (std::size_t k = 0; k < polys[i].size(); ++k)
    {
      byOutputPoint[polys[i][k]].insert({ polygonOf[i], vtkIdType(k) });
    }
  }
  Grouping groups;
  for (const auto& entry : byOutputPoint)
  {
    groups[original->GetValue(entry.first)].insert(entry.second);
  }
  return groups;
}

//------------------------------------------------------------------------------
// The exact truth of a feature edge, written from the definition with rationals.

/// Whether w1.w2 <= c |w1| |w2| for the exact area vectors of two polygons.
bool ReferenceSharp(const std::vector<Point>& a, const std::vector<Point>& b, double c)
{
  const phongvtk_test::ExactAreaVector w1 = phongvtk_test::ComputeExactAreaVector(a);
  const phongvtk_test::ExactAreaVector w2 = phongvtk_test::ComputeExactAreaVector(b);
  mpq_class dot = 0, n1 = 0, n2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    dot += w1.W[k] * w2.W[k];
    n1 += w1.W[k] * w1.W[k];
    n2 += w2.W[k] * w2.W[k];
  }
  if (n1 == 0 || n2 == 0)
  {
    return true;
  }
  // dot <= c sqrt(n1 n2): compare signs first, then squares.
  const mpq_class cq(c);
  const mpq_class rhsSquared = cq * cq * n1 * n2;
  if (c >= 0)
  {
    return dot <= 0 || dot * dot <= rhsSquared;
  }
  return dot < 0 && dot * dot >= rhsSquared;
}

/**
 * Two triangles hinged on the edge (o, o, o)-(o + 1, o, o): the first flat in z = o, the second
 * rising to the apex (o + 0.5, apexY, apexZ) (absolute coordinates). With apexY = o + y and
 * apexZ = o + z the angle between their area vectors has the cosine y / sqrt(y^2 + z^2).
 */
vtkSmartPointer<vtkPolyData> Hinge(double o, double apexY, double apexZ,
  std::vector<Point>* t1 = nullptr, std::vector<Point>* t2 = nullptr)
{
  const std::vector<Point> p = { { o, o, o }, { o + 1, o, o }, { o + 0.5, o - 1, o },
    { o + 0.5, apexY, apexZ } };
  if (t1 && t2)
  {
    *t1 = { p[0], p[1], p[2] };
    *t2 = { p[1], p[0], p[3] };
  }
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 1, 0, 3 } };
  return MakePolyData(p, cells);
}

std::vector<double> Flat(const std::vector<Point>& polygon)
{
  std::vector<double> xyz;
  for (const Point& p : polygon)
  {
    xyz.insert(xyz.end(), p.begin(), p.end());
  }
  return xyz;
}
} // namespace

//==============================================================================
// The regions around one point

TEST(SplittingRegions, AFanSplitsAtItsSharpEdgesOnly)
{
  // Point 0 with a closed fan of six triangles; triangles f and f + 1 (mod 6) share an edge.
  // The edges between 5 and 0 and between 2 and 3 are sharp.
  const std::vector<vtkIdType> cells = { 0, 1, 2, 3, 4, 5 };
  auto across = [](vtkIdType f, auto&& fn)
  {
    fn((f + 1) % 6);
    fn((f + 5) % 6);
  };
  auto directed = [](vtkIdType)
  {
    return true;
  };
  auto smooth = [](vtkIdType a, vtkIdType b)
  {
    const vtkIdType lo = std::min(a, b), hi = std::max(a, b);
    return !((lo == 0 && hi == 5) || (lo == 2 && hi == 3));
  };
  phongvtk::PointRegions regions;
  regions.Compute(0, cells.data(), 6, across, directed, smooth);
  EXPECT_EQ(regions.Regions, 2);
  for (vtkIdType f = 0; f < 6; ++f)
  {
    EXPECT_EQ(regions.LabelOf(f), f < 3 ? 0 : 1) << f;
  }
}

TEST(SplittingRegions, UndirectedPolygonsJoinNothingAndKeepThePoint)
{
  // A chain 0 - 3 - 1 - 2 across manifold edges, every edge smooth, but polygon 3 has no
  // direction: regions {0}, {1, 2}; polygon 3 keeps the point (label 0) and adds no region.
  const std::map<vtkIdType, std::vector<vtkIdType>> neighbours = { { 0, { 3 } }, { 3, { 0, 1 } },
    { 1, { 3, 2 } }, { 2, { 1 } } };
  const std::vector<vtkIdType> cells = { 3, 2, 1, 0, 0 }; // unsorted, one listed twice
  auto across = [&](vtkIdType f, auto&& fn)
  {
    for (vtkIdType g : neighbours.at(f))
    {
      fn(g);
    }
  };
  auto directed = [](vtkIdType f)
  {
    return f != 3;
  };
  auto smooth = [](vtkIdType, vtkIdType)
  {
    return true;
  };
  phongvtk::PointRegions regions;
  regions.Compute(0, cells.data(), 5, across, directed, smooth);
  EXPECT_EQ(regions.Regions, 2);
  EXPECT_EQ(regions.LabelOf(0), 0);
  EXPECT_EQ(regions.LabelOf(1), 1);
  EXPECT_EQ(regions.LabelOf(2), 1);
  EXPECT_EQ(regions.LabelOf(3), 0);
}

TEST(SplittingRegions, RegionsAreNumberedByTheirSmallestPolygon)
{
  // Two smooth pairs {7, 9} and {3, 8} around point 0, listed in any order: {3, 8} keeps it.
  const std::map<vtkIdType, vtkIdType> partner = { { 7, 9 }, { 9, 7 }, { 3, 8 }, { 8, 3 } };
  auto across = [&](vtkIdType f, auto&& fn)
  {
    fn(partner.at(f));
  };
  auto directed = [](vtkIdType)
  {
    return true;
  };
  auto smooth = [](vtkIdType, vtkIdType)
  {
    return true;
  };
  for (const std::vector<vtkIdType>& cells :
    { std::vector<vtkIdType>{ 7, 9, 3, 8 }, std::vector<vtkIdType>{ 8, 3, 9, 7 } })
  {
    phongvtk::PointRegions regions;
    regions.Compute(0, cells.data(), 4, across, directed, smooth);
    EXPECT_EQ(regions.Regions, 2);
    EXPECT_EQ(regions.LabelOf(3), 0);
    EXPECT_EQ(regions.LabelOf(8), 0);
    EXPECT_EQ(regions.LabelOf(7), 1);
    EXPECT_EQ(regions.LabelOf(9), 1);
  }
}

TEST(SplittingRegions, CornersAtAPointAreFoundWhereverAndHoweverOftenItIs)
{
  // Polygons of 3 to 70 corners (past the 64 of the corner mask) with point 0 at one, two or
  // three corners at every place: ForCornersAt against a plain scan of the ids.
  struct Corner
  {
    vtkIdType K, Previous, Next;
    bool operator==(const Corner& b) const
    {
      return this->K == b.K && this->Previous == b.Previous && this->Next == b.Next;
    }
  };
  std::mt19937 random(7);
  int polygons = 0;
  for (const vtkIdType m : { 3, 4, 5, 8, 63, 64, 65, 70 })
  {
    for (int trial = 0; trial < 40; ++trial)
    {
      std::vector<vtkIdType> ids(static_cast<std::size_t>(m));
      std::iota(ids.begin(), ids.end(), vtkIdType(1));
      const int times = 1 + trial % 3;
      for (int t = 0; t < times; ++t)
      {
        ids[random() % static_cast<std::size_t>(m)] = 0;
      }
      const std::vector<vtkIdType> offsets = { 0, m };
      std::vector<Corner> found, expected;
      phongvtk::ForCornersAt(offsets.data(), ids.data(), 0, 0,
        [&](vtkIdType k, vtkIdType previous, vtkIdType next) {
          found.push_back({ k, previous, next });
        });
      for (vtkIdType k = 0; k < m; ++k)
      {
        if (ids[static_cast<std::size_t>(k)] == 0)
        {
          expected.push_back({ k, ids[static_cast<std::size_t>((k + m - 1) % m)],
            ids[static_cast<std::size_t>((k + 1) % m)] });
        }
      }
      EXPECT_TRUE(found == expected) << m << " corners, trial " << trial;
      ++polygons;
    }
  }
  EXPECT_EQ(polygons, 320);
}

/// A fan's edges at point 0, (polygon, slot, 1 when it runs from 0), by their other point.
using FanEdgeSets = std::map<vtkIdType, std::multiset<std::tuple<vtkIdType, vtkIdType, int>>>;

/// Point 0's fan of `polys` as a plain listing has it: the cell array (Offsets, Conn), the links
/// of point 0 (every polygon once per corner at 0, increasing) and the edges at 0.
struct ListedFan
{
  std::vector<vtkIdType> Offsets = { 0 }, Conn, Cells;
  FanEdgeSets Edges;

  explicit ListedFan(const std::vector<std::vector<vtkIdType>>& polys)
  {
    for (vtkIdType f = 0; f < static_cast<vtkIdType>(polys.size()); ++f)
    {
      const auto& polygon = polys[static_cast<std::size_t>(f)];
      this->Conn.insert(this->Conn.end(), polygon.begin(), polygon.end());
      this->Offsets.push_back(static_cast<vtkIdType>(this->Conn.size()));
      const auto m = static_cast<vtkIdType>(polygon.size());
      for (vtkIdType k = 0; k < m; ++k)
      {
        if (polygon[static_cast<std::size_t>(k)] != 0)
        {
          continue;
        }
        this->Cells.push_back(f);
        const vtkIdType next = polygon[static_cast<std::size_t>((k + 1) % m)];
        const vtkIdType previous = polygon[static_cast<std::size_t>((k + m - 1) % m)];
        if (next != 0)
        {
          this->Edges[next].insert({ f, k, 1 });
        }
        if (previous != 0)
        {
          this->Edges[previous].insert({ f, (k + m - 1) % m, 0 });
        }
      }
    }
  }

  /// Point 0's fan built from them.
  void Build(phongvtk::PointFan& fan) const
  {
    fan.Build(0, this->Cells.data(), static_cast<vtkIdType>(this->Cells.size()),
      this->Offsets.data(), this->Conn.data(), false);
  }
};

/// The edges of a fan's groups (ForGroups), each group checked to hold the edges to one point,
/// each point's edges in one group.
FanEdgeSets GroupsOf(const phongvtk::PointFan& fan)
{
  FanEdgeSets found;
  fan.ForGroups(
    [&](const phongvtk::PointFan::Group& group)
    {
      const vtkIdType q = group[0].Q;
      EXPECT_EQ(found.count(q), 0u) << "two groups of q = " << q;
      for (std::size_t j = 0; j < group.Size; ++j)
      {
        EXPECT_EQ(group[j].Q, q);
        EXPECT_EQ(fan.Faces[group[j].Face], group[j].Polygon);
        found[q].insert({ group[j].Polygon, group[j].Slot, group[j].Forward });
      }
    });
  return found;
}

TEST(SplittingRegions, AFanGroupsItsEdgesByTheirOtherPoint)
{
  // Point 0's fan: triangles around it, a quad, and a degenerate polygon that has point 0 twice
  // (each of its corners at 0 brings its two edges); some fans with a hub's many edges (past
  // the 64 of the scan, grouped by a sort). Every group holds exactly the edges (polygon, slot,
  // direction) to one point q, as a plain listing of every polygon's edges at 0 says.
  std::mt19937 random(11);
  for (const int n : { 3, 6, 12, 40, 90 })
  {
    std::vector<std::vector<vtkIdType>> polys;
    for (int f = 0; f < n; ++f)
    {
      polys.push_back({ 0, vtkIdType(1 + f), vtkIdType(1 + (f + 1) % n) });
    }
    polys.push_back({ 0, 2, 9, 3 });    // a quad (its edges join the groups of 2 and 3)
    polys.push_back({ 0, 5, 0, 6, 7 }); // point 0 twice
    std::shuffle(polys.begin(), polys.end(), random);
    const ListedFan listed(polys);
    phongvtk::PointFan fan;
    listed.Build(fan);
    EXPECT_TRUE(GroupsOf(fan) == listed.Edges) << n << " triangles";
  }
}

TEST(SplittingRegions, PlainTriangleFansAreTheOnesAPlainListingSaysAndPairAsItDoes)
{
  // Fans of 2 to 20 polygons around point 0 (at most PlainMax make a plain fan), with point ids
  // from a small range (edges to one point meet often: manifold pairs, triangles running the same
  // way, non-manifold edges) or a large one (the fast test's hashes of distinct ids meet as often
  // as chance has them), and now and then a quad, a triangle with point 0 twice or one with another
  // point twice. A fan is plain exactly when a plain listing finds every polygon a triangle with 0
  // at one corner and no point twice among the points after 0 nor among those before; its pairs
  // then match the point after 0 in one triangle with the point before 0 in another; and its groups
  // (ForGroups) are every fan's.
  std::mt19937 random(29);
  int plain = 0, notPlain = 0;
  for (int trial = 0; trial < 4000; ++trial)
  {
    const int n = 2 + static_cast<int>(random() % 19);
    const vtkIdType range = trial % 2 ? 4 + n : 1000000;
    std::vector<std::vector<vtkIdType>> polys;
    for (int f = 0; f < n; ++f)
    {
      auto id = [&]
      {
        return 1 + static_cast<vtkIdType>(random() % static_cast<unsigned>(range));
      };
      std::vector<vtkIdType> polygon = { 0, id(), id() };
      while (polygon[2] == polygon[1] && random() % 8 != 0) // now and then (0, q, q)
      {
        polygon[2] = id();
      }
      const unsigned odd = random() % 60;
      if (odd == 0)
      {
        polygon.push_back(id()); // a quad
      }
      else if (odd == 1)
      {
        polygon[2] = 0; // point 0 twice
      }
      std::rotate(polygon.begin(), polygon.begin() + random() % polygon.size(), polygon.end());
      polys.push_back(polygon);
    }
    const ListedFan listed(polys);
    // The plain listing.
    std::vector<vtkIdType> next, previous, corner;
    bool expectPlain = static_cast<std::size_t>(n) <= phongvtk::PointFan::PlainMax;
    for (const auto& polygon : polys)
    {
      const auto at = std::count(polygon.begin(), polygon.end(), vtkIdType(0));
      if (polygon.size() != 3 || at != 1)
      {
        expectPlain = false;
        break;
      }
      const auto k = std::find(polygon.begin(), polygon.end(), vtkIdType(0)) - polygon.begin();
      corner.push_back(k);
      next.push_back(polygon[static_cast<std::size_t>((k + 1) % 3)]);
      previous.push_back(polygon[static_cast<std::size_t>((k + 2) % 3)]);
      expectPlain = expectPlain && next.back() != previous.back();
    }
    if (expectPlain)
    {
      expectPlain = std::set<vtkIdType>(next.begin(), next.end()).size() == next.size() &&
        std::set<vtkIdType>(previous.begin(), previous.end()).size() == previous.size();
    }
    phongvtk::PointFan fan;
    listed.Build(fan);
    ASSERT_EQ(fan.Plain, expectPlain) << "trial " << trial;
    (expectPlain ? plain : notPlain)++;
    if (expectPlain)
    {
      for (int i = 0; i < n; ++i)
      {
        ASSERT_EQ(fan.Faces[i], i);
        EXPECT_EQ(fan.Next[i], next[static_cast<std::size_t>(i)]);
        EXPECT_EQ(fan.Previous[i], previous[static_cast<std::size_t>(i)]);
        EXPECT_EQ(fan.Corner[i], corner[static_cast<std::size_t>(i)]);
        const auto j =
          std::find(previous.begin(), previous.end(), next[static_cast<std::size_t>(i)]);
        EXPECT_EQ(fan.Match[i], j == previous.end() ? -1 : j - previous.begin())
          << "trial " << trial;
      }
    }
    // The groups, plain or not: each holds exactly the edges to one point.
    ASSERT_TRUE(GroupsOf(fan) == listed.Edges) << "trial " << trial;
  }
  // Both kinds, many times over.
  EXPECT_GT(plain, 500);
  EXPECT_GT(notPlain, 500);
}

TEST(SplittingRegions, CompactAndWideLinksGiveTheSameRegionsNeighboursAndPolygons)
{
  // The filter takes 32-bit links wherever a mesh fits them (every mesh of this suite); the
  // vtkIdType links serve the meshes that do not. Both, on real meshes, give the same copies, the
  // same labels of the split points, the same split polygons and the same edge neighbours.
  std::vector<vtkSmartPointer<vtkPolyData>> meshes = { RoughSphere(40, 0.3, 3) };
  {
    // Every seventh triangle reversed: edges where two triangles run the same way.
    auto flipped = RoughSphere(30, 0.2, 5);
    vtkNew<vtkCellArray> polys;
    vtkIdType f = 0;
    for (auto polygon : PolygonsOf(flipped))
    {
      if (f++ % 7 == 3)
      {
        std::reverse(polygon.begin() + 1, polygon.end());
      }
      polys->InsertNextCell(static_cast<vtkIdType>(polygon.size()), polygon.data());
    }
    flipped->SetPolys(polys);
    meshes.push_back(flipped);
  }
  if (phongvtk_test::HaveCGALMeshes())
  {
    for (const char* name : { "fandisk.off", "cross.off" })
    {
      meshes.push_back(phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name)));
    }
  }
  for (vtkPolyData* mesh : meshes)
  {
    ASSERT_NE(mesh, nullptr);
    vtkCellArray* polys = mesh->GetPolys();
    const vtkIdType numPoints = mesh->GetNumberOfPoints();
    ASSERT_TRUE(phongvtk::FitsCompactLinks(numPoints, polys));
    // Unit normals of the polygons (Newell), sharp at 30 degrees.
    std::vector<double> normals;
    for (const auto& polygon : PolygonsOf(mesh))
    {
      double n[3] = { 0, 0, 0 };
      for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        double a[3], b[3];
        mesh->GetPoint(polygon[i], a);
        mesh->GetPoint(polygon[(i + 1) % polygon.size()], b);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
      }
      vtkMath::Normalize(n);
      normals.insert(normals.end(), n, n + 3);
    }
    auto directed = [](vtkIdType)
    {
      return true;
    };
    auto smooth = [&](vtkIdType f, vtkIdType g, bool same)
    {
      const double d = vtkMath::Dot(&normals[3 * f], &normals[3 * g]);
      return (same ? -d : d) > std::cos(vtkMath::RadiansFromDegrees(30.0));
    };
    // The neighbours are recorded as wide as the links' ids (32 bits with compact links) and
    // compared as vtkIdType, the empty slot -1.
    auto regions = [&](auto& links, auto neighbourType, phongvtk::SplitPolygons& split,
                     std::vector<vtkIdType>& copies, std::vector<std::int32_t>& labels,
                     std::vector<vtkIdType>& neighbours)
    {
      using N = decltype(neighbourType);
      phongvtk::BuildPolygonLinks(mesh->GetPoints(), polys, links);
      // The neighbours as the pass over the fans records them on the way (each edge from its
      // smaller point, where the fan is plain from its own listing) must be those of a pass
      // that lists every fan's edges.
      std::vector<N> recorded(
        static_cast<std::size_t>(polys->GetConnectivityArray()->GetNumberOfValues()),
        phongvtk::NoNeighbour<N>);
      phongvtk::EdgeRecordsOf<N> records;
      records.Neighbours = recorded.data();
      phongvtk::RegionLabels found = phongvtk::SharpEdgeRegions(
        numPoints, polys, links, records, directed, smooth, [](vtkIdType) {});
      copies = found.Copies;
      for (vtkIdType p = 0; p < numPoints; ++p)
      {
        if (found.Copies[static_cast<std::size_t>(p) + 1] > 0) // labels of split points only
        {
          const auto first = static_cast<std::size_t>(links.GetOffset(p));
          labels.insert(labels.end(), found.LinkLabel.get() + first,
            found.LinkLabel.get() + first + links.GetNumberOfCells(p));
        }
      }
      split = phongvtk::ApplyRegions(numPoints, polys, links, found);
      const std::vector<N> listed = phongvtk::EdgeNeighbours<N>(numPoints, polys, links);
      EXPECT_EQ(recorded, listed);
      neighbours.clear();
      for (N n : listed)
      {
        neighbours.push_back(n == phongvtk::NoNeighbour<N> ? -1 : static_cast<vtkIdType>(n));
      }
    };
    phongvtk::CompactPolygonLinks compact;
    phongvtk::PolygonLinks wide;
    phongvtk::SplitPolygons a, b;
    std::vector<vtkIdType> copiesA, copiesB, neighboursA, neighboursB;
    std::vector<std::int32_t> labelsA, labelsB;
    regions(compact, phongvtk::CompactNeighbour{}, a, copiesA, labelsA, neighboursA);
    regions(wide, vtkIdType{}, b, copiesB, labelsB, neighboursB);
    EXPECT_GT(std::accumulate(copiesA.begin(), copiesA.end(), vtkIdType(0)), 0)
      << "the test mesh must split somewhere";
    EXPECT_EQ(copiesA, copiesB);
    EXPECT_EQ(labelsA, labelsB);
    EXPECT_EQ(a.CopyOf, b.CopyOf);
    vtkNew<vtkPolyData> ma, mb;
    ma->SetPolys(a.Polys);
    mb->SetPolys(b.Polys);
    EXPECT_EQ(PolygonsOf(ma), PolygonsOf(mb));
    EXPECT_EQ(neighboursA, neighboursB);
  }
}

//==============================================================================
// The sharp-edge decision against exact rational arithmetic

TEST(FeatureAngleDecision, ExactIsRightOneUlpEitherSideOfTheThresholdAtEveryOffset)
{
  // 30 degrees (apex above the first triangle's far side) and 135 degrees (folded back over it).
  struct Threshold
  {
    double Degrees, Y, Z;
  };
  for (const Threshold& t : { Threshold{ 30.0, 1.0, std::tan(vtkMath::RadiansFromDegrees(30.0)) },
         Threshold{ 135.0, -1.0, 1.0 } })
  {
    const double c = std::cos(vtkMath::RadiansFromDegrees(t.Degrees));
    for (double offset : { 0.0, 1.0, 1e4, 1e8, -3e7 })
    {
      int sharp = 0, smooth = 0;
      // The apex height one representable step at a time around the threshold.
      double z = offset + t.Z;
      for (int k = 0; k < 12; ++k)
      {
        z = std::nextafter(z, -HUGE_VAL);
      }
      for (int k = -12; k <= 12; ++k, z = std::nextafter(z, HUGE_VAL))
      {
        std::vector<Point> t1, t2;
        auto mesh = Hinge(offset, offset + t.Y, z, &t1, &t2);
        const bool expected = ReferenceSharp(t1, t2, c);
        (expected ? sharp : smooth)++;
        const std::string where = std::to_string(t.Degrees) + " degrees, offset " +
          std::to_string(offset) + ", step " + std::to_string(k);
        EXPECT_EQ(
          phongvtk::detail::ExactFeatureEdgeIsSharp(Flat(t1).data(), 3, Flat(t2).data(), 3, c),
          expected)
          << where;
        // The filter in EXACT: the two shared points split (6 points) exactly when sharp.
        EXPECT_EQ(
          Split(mesh, vtkPolygonNormals::EXACT, t.Degrees)->GetNumberOfPoints(), expected ? 6 : 4)
          << where;
      }
      EXPECT_GT(sharp, 0) << t.Degrees << " offset " << offset;
      EXPECT_GT(smooth, 0) << t.Degrees << " offset " << offset
                           << ": the steps must straddle the threshold";
    }
  }
}

TEST(FeatureAngleDecision, VTKsFloatTestMisjudgesEdgesNearTheThreshold)
{
  // The same hinges: vtkPolyDataNormals (float normals, float dot product) decides a band of
  // about 1e-7 around cos(30 degrees) by rounding, so some of these edges come out wrong.
  const double c = std::cos(vtkMath::RadiansFromDegrees(30.0));
  const double z0 = std::tan(vtkMath::RadiansFromDegrees(30.0));
  int vtkWrong = 0, exactWrong = 0, cases = 0;
  for (int k = -40; k <= 40; ++k)
  {
    const double z = z0 + k * 2e-9;
    std::vector<Point> t1, t2;
    auto mesh = Hinge(0.0, 1.0, z, &t1, &t2);
    const bool sharp = ReferenceSharp(t1, t2, c);
    const vtkIdType expected = sharp ? 6 : 4;
    vtkWrong += VTKSplitPointCount(mesh) != expected;
    exactWrong += Split(mesh, vtkPolygonNormals::EXACT)->GetNumberOfPoints() != expected;
    ++cases;
  }
  EXPECT_EQ(exactWrong, 0);
  EXPECT_GT(vtkWrong, 0) << "VTK's float decision was right on all " << cases << " hinges";
}

TEST(FeatureAngleDecision, CertifiedStageDecidesOnlyWhereTheBoundAllows)
{
  const double c = std::cos(vtkMath::RadiansFromDegrees(30.0));
  const double n1[3] = { 0.0, 0.0, 1.0 };
  // n2 at angle t from n1: n1.n2 = cos t.
  auto at = [&](double cosine)
  {
    const double n2[3] = { 0.0, std::sqrt(1.0 - cosine * cosine), cosine };
    return phongvtk::CertifiedFeatureEdge(n1, n2, c);
  };
  EXPECT_EQ(at(c + 1e-12), phongvtk::FeatureEdge::Smooth);
  EXPECT_EQ(at(c - 1e-12), phongvtk::FeatureEdge::Sharp);
  EXPECT_EQ(at(c), phongvtk::FeatureEdge::Undecided);
  EXPECT_EQ(at(std::nextafter(c, 2.0)), phongvtk::FeatureEdge::Undecided);
  // The inexact modes decide everything, an edge exactly at the angle as sharp.
  const double n2[3] = { 0.0, std::sqrt(1.0 - c * c), c };
  EXPECT_EQ(phongvtk::FeatureEdgeFromNormals(n1, n2, phongvtk::UnitDot(n1, n2)),
    phongvtk::FeatureEdge::Sharp);
}

TEST(FeatureAngleDecision, RandomPolygonPairsNearTheAngleAgreeWithRationals)
{
  // Quads and triangles sharing nothing in particular, with angles drawn around several
  // feature angles (obtuse ones too) and coordinates over many binades.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int checked = 0;
  for (double degrees : { 0.0, 1e-6, 30.0, 89.999, 90.0, 135.0, 179.9, 180.0 })
  {
    const double c = std::cos(vtkMath::RadiansFromDegrees(degrees));
    for (int trial = 0; trial < 200; ++trial)
    {
      const double scale = std::ldexp(1.0, static_cast<int>(unit(random) * 300));
      std::vector<Point> a, b;
      for (int v = 0; v < 3 + trial % 2; ++v)
      {
        a.push_back({ scale * unit(random), scale * unit(random), scale * unit(random) });
      }
      // b: a's first edge and a point placed at about the feature angle, then nudged.
      b = { a[1], a[0] };
      const double t = vtkMath::RadiansFromDegrees(degrees) + 1e-15 * unit(random);
      const double w = std::tan(t) * scale;
      b.push_back({ a[2][0] + w * unit(random), a[2][1], a[2][2] + w * unit(random) });
      const bool expected = ReferenceSharp(a, b, c);
      ASSERT_EQ(phongvtk::detail::ExactFeatureEdgeIsSharp(
                  Flat(a).data(), static_cast<std::int64_t>(a.size()), Flat(b).data(), 3, c),
        expected)
        << degrees << " degrees, trial " << trial;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1600);
}

//==============================================================================
// The filter's output

TEST(Splitting, CubeGetsThreeCopiesOfEveryCornerAndAxisAlignedNormals)
{
  for (double offset : { 0.0, 1e8 })
  {
    auto cube = Cube(offset);
    for (int mode : Modes)
    {
      auto out = Split(cube, mode);
      ASSERT_EQ(out->GetNumberOfPoints(), 24) << ModeName(mode);
      ASSERT_EQ(VTKSplitPointCount(cube), 24);
      vtkDataArray* normals = out->GetPointData()->GetNormals();
      ASSERT_NE(normals, nullptr);
      auto* original =
        vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("OriginalPointIds"));
      ASSERT_NE(original, nullptr);
      std::vector<int> copies(8, 0);
      for (vtkIdType i = 0; i < 24; ++i)
      {
        double n[3];
        normals->GetTuple(i, n);
        const double sorted[3] = { std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) };
        EXPECT_EQ(*std::max_element(sorted, sorted + 3), 1.0) << ModeName(mode) << " point " << i;
        EXPECT_EQ(sorted[0] + sorted[1] + sorted[2], 1.0) << ModeName(mode) << " point " << i;
        const vtkIdType from = original->GetValue(i);
        ASSERT_GE(from, 0);
        ASSERT_LT(from, 8);
        copies[from]++;
        double p[3], q[3];
        out->GetPoint(i, p);
        cube->GetPoint(from, q);
        EXPECT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
        EXPECT_EQ(i < 8, i == from) << "input points keep their ids";
      }
      EXPECT_EQ(copies, std::vector<int>(8, 3));
      // Every face's corners now carry its own normal.
      phongvtk_test::ForEachCornerNormal(out,
        [](std::size_t, vtkIdType, const double* nf, const double* n)
        { EXPECT_TRUE(n[0] == nf[0] && n[1] == nf[1] && n[2] == nf[2]); });
    }
  }
}

TEST(Splitting, OnByDefaultAndOnlyWithPointNormals)
{
  auto cube = Cube();
  vtkNew<vtkPolygonNormals> f;
  EXPECT_TRUE(f->GetSplitting()); // vtkPolyDataNormals' default
  EXPECT_EQ(f->GetFeatureAngle(), 30.0);
  EXPECT_TRUE(f->GetComputeOriginalPointIds());
  f->SetInputData(cube);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 24); // the defaults split a cube's corners
  phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
  f->SetFeatureAngle(-5.0);
  EXPECT_EQ(f->GetFeatureAngle(), 0.0);
  f->SetFeatureAngle(200.0);
  EXPECT_EQ(f->GetFeatureAngle(), 180.0);
  f->SetFeatureAngle(30.0);
  f->ComputePointNormalsOn();
  f->SetInputData(cube);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 8);
  EXPECT_EQ(f->GetOutput()->GetPointData()->GetArray("OriginalPointIds"), nullptr);
  // Splitting without point normals changes nothing: nothing depends on it.
  auto out = Split(cube, vtkPolygonNormals::DOUBLE, 30.0,
    [](vtkPolygonNormals* filter) { filter->ComputePointNormalsOff(); });
  EXPECT_EQ(out->GetNumberOfPoints(), 8);
  EXPECT_EQ(out->GetPointData()->GetArray("OriginalPointIds"), nullptr);
  EXPECT_EQ(out->GetPolys(), cube->GetPolys());
  // Without OriginalPointIds the copies are made all the same.
  out = Split(cube, vtkPolygonNormals::DOUBLE, 30.0,
    [](vtkPolygonNormals* filter) { filter->ComputeOriginalPointIdsOff(); });
  EXPECT_EQ(out->GetNumberOfPoints(), 24);
  EXPECT_EQ(out->GetPointData()->GetArray("OriginalPointIds"), nullptr);
}

TEST(Splitting, FeatureAngleZeroSplitsEveryEdgeAnd180OnlyFoldedOnes)
{
  auto grid = FlatGrid(4); // 25 points, 32 triangles, 3 * 32 corners
  // 0 degrees: c = 1 and every w1.w2 <= |w1| |w2|: every corner its own point.
  EXPECT_EQ(Split(grid, vtkPolygonNormals::EXACT, 0.0)->GetNumberOfPoints(), 96);
  EXPECT_EQ(VTKSplitPointCount(grid, 0.0), 96);
  // A flat grid is smooth at any positive angle.
  EXPECT_EQ(Split(grid, vtkPolygonNormals::EXACT, 1e-6)->GetNumberOfPoints(), 25);
  // 180 degrees: only faces folded back onto each other split; a cube's 90 degree edges do not.
  EXPECT_EQ(Split(Cube(), vtkPolygonNormals::EXACT, 180.0)->GetNumberOfPoints(), 8);
  EXPECT_EQ(Split(Cube(), vtkPolygonNormals::EXACT, 90.0)->GetNumberOfPoints(), 24);
  EXPECT_EQ(Split(Cube(), vtkPolygonNormals::EXACT, 90.0001)->GetNumberOfPoints(), 8);
  // Two triangles folded flat onto each other (opposite area vectors): sharp even at 180.
  const std::vector<Point> p = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, 2, 0 } };
  Cells folded;
  folded.Polys = { { 0, 1, 2 }, { 1, 0, 3 } };
  auto fold = MakePolyData(p, folded);
  EXPECT_EQ(Split(fold, vtkPolygonNormals::EXACT, 180.0)->GetNumberOfPoints(), 6);
}

TEST(Splitting, BoundaryNonManifoldAndUndirectedPolygonsSeparateAsInVTK)
{
  // A fin: three triangles on the edge 0-1, coplanar pairs included (smooth at 30 degrees),
  // yet the non-manifold edge separates all three at both its points.
  const std::vector<Point> p = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 },
    { 0.5, 0, 1 }, { 2, 1, 0 }, { 2, -1, 0 } };
  Cells fin;
  fin.Polys = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  auto finMesh = MakePolyData(p, fin);
  EXPECT_EQ(Split(finMesh, vtkPolygonNormals::EXACT)->GetNumberOfPoints(), 7 + 2 + 2);
  EXPECT_EQ(VTKSplitPointCount(finMesh), 11);
  // A bow tie: two triangles touching at one point only, coplanar: no shared edge joins them.
  Cells bowtie;
  bowtie.Polys = { { 1, 2, 5 }, { 1, 6, 3 } };
  auto bowtieMesh = MakePolyData(p, bowtie);
  EXPECT_EQ(Split(bowtieMesh, vtkPolygonNormals::EXACT)->GetNumberOfPoints(), 8);
  // A zero-area triangle between two coplanar ones keeps its points and bridges nothing: the
  // two real triangles share no edge, so point 1 splits once; the sliver adds no copy.
  const std::vector<Point> q = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 1, 1, 0 }, { 1, -1, 0 } };
  Cells sliver;
  sliver.Polys = { { 0, 1, 3 }, { 0, 2, 1 }, { 1, 2, 4 } };
  auto out = Split(MakePolyData(q, sliver), vtkPolygonNormals::EXACT);
  EXPECT_EQ(out->GetNumberOfPoints(), 6);
  const std::vector<Cell> polys = PolygonsOf(out);
  EXPECT_EQ(polys[1], (Cell{ 0, 2, 1 })) << "the sliver keeps the input points";
}

TEST(Splitting, PointArraysAreCopiedAndEverythingElsePasses)
{
  auto cube = Cube();
  // Lines and vertices on the cube's points, and arrays of every kind.
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 7 };
  lines->InsertNextCell(2, line);
  cube->SetLines(lines);
  vtkNew<vtkCellArray> verts;
  const vtkIdType vert[1] = { 3 };
  verts->InsertNextCell(1, vert);
  cube->SetVerts(verts);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("temperature");
  scalars->SetNumberOfComponents(2);
  vtkNew<vtkStringArray> labels;
  labels->SetName("label");
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("cell id");
  for (vtkIdType i = 0; i < 8; ++i)
  {
    scalars->InsertNextTuple2(i * 1.5, -double(i));
    labels->InsertNextValue("corner " + std::to_string(i));
  }
  for (vtkIdType i = 0; i < cube->GetNumberOfCells(); ++i)
  {
    cellIds->InsertNextValue(int(100 + i));
  }
  cube->GetPointData()->SetScalars(scalars);
  cube->GetPointData()->AddArray(labels);
  vtkNew<vtkIdTypeArray> globalIds;
  globalIds->SetName("GlobalIds");
  for (vtkIdType i = 0; i < 8; ++i)
  {
    globalIds->InsertNextValue(1000 + i);
  }
  cube->GetPointData()->SetGlobalIds(globalIds);
  cube->GetCellData()->AddArray(cellIds);
  vtkNew<vtkIntArray> field;
  field->SetName("run");
  field->InsertNextValue(42);
  cube->GetFieldData()->AddArray(field);

  auto out = Split(cube, vtkPolygonNormals::EXACT);
  ASSERT_EQ(out->GetNumberOfPoints(), 24);
  auto* original = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("OriginalPointIds"));
  ASSERT_NE(original, nullptr);
  auto* outScalars = vtkDoubleArray::SafeDownCast(out->GetPointData()->GetScalars());
  auto* outLabels = vtkStringArray::SafeDownCast(out->GetPointData()->GetAbstractArray("label"));
  ASSERT_NE(outScalars, nullptr);
  ASSERT_NE(outLabels, nullptr);
  ASSERT_EQ(outScalars->GetNumberOfTuples(), 24);
  for (vtkIdType i = 0; i < 24; ++i)
  {
    const vtkIdType from = original->GetValue(i);
    EXPECT_EQ(outScalars->GetComponent(i, 0), scalars->GetComponent(from, 0));
    EXPECT_EQ(outScalars->GetComponent(i, 1), scalars->GetComponent(from, 1));
    EXPECT_EQ(outLabels->GetValue(i), labels->GetValue(from));
  }
  // Global ids are kept, copies carrying their point's, but are no longer unique, so no longer
  // the GlobalIds attribute.
  auto* outGlobal = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("GlobalIds"));
  ASSERT_NE(outGlobal, nullptr);
  EXPECT_EQ(out->GetPointData()->GetGlobalIds(), nullptr);
  for (vtkIdType i = 0; i < 24; ++i)
  {
    EXPECT_EQ(outGlobal->GetValue(i), 1000 + original->GetValue(i));
  }
  EXPECT_EQ(cube->GetPointData()->GetGlobalIds(), globalIds.GetPointer());
  // Lines and vertices keep their ids; cell and field data pass.
  EXPECT_EQ(out->GetLines(), lines.GetPointer());
  EXPECT_EQ(out->GetVerts(), verts.GetPointer());
  EXPECT_EQ(out->GetCellData()->GetArray("cell id"), cellIds.GetPointer());
  EXPECT_EQ(out->GetFieldData()->GetArray("run"), field.GetPointer());
  // The input is untouched.
  EXPECT_EQ(cube->GetNumberOfPoints(), 8);
  EXPECT_EQ(cube->GetPointData()->GetArray("OriginalPointIds"), nullptr);
  EXPECT_EQ(PolygonsOf(cube)[0], (Cell{ 0, 2, 3, 1 }));
}

TEST(Splitting, AHubOf200000TrianglesSplitsWhereItsFanIsSharp)
{
  // A fan around point 0 closing on itself: 200,000 triangles on a cone whose rim is raised to a
  // spike every quarter turn. The two thin triangles at a spike face sideways, opposite each
  // other and at 90 degrees to the cone: each is a region of its own at the hub, which has 4 arcs
  // of cone and 8 such triangles around it (11 copies); at the rim the spike and its two
  // neighbours each split once (3 copies a spike).
  const int n = 200000;
  std::vector<Point> p = { { 0, 0, 1 } };
  for (int i = 0; i < n; ++i)
  {
    const double t = 2.0 * M_PI * i / n;
    const double z = i % 50000 == 0 ? 3.0 : 0.0; // a spike every quarter turn
    p.push_back({ std::cos(t), std::sin(t), z });
  }
  Cells cells;
  for (int i = 0; i < n; ++i)
  {
    cells.Polys.push_back({ 0, 1 + i, 1 + (i + 1) % n });
  }
  auto fan = MakePolyData(p, cells);
  for (bool consistency : { false, true })
  {
    auto out = Split(fan, vtkPolygonNormals::DOUBLE, 30.0,
      [consistency](vtkPolygonNormals* f) { f->SetConsistency(consistency); });
    EXPECT_EQ(out->GetNumberOfPoints(), n + 1 + 11 + 4 * 3) << consistency;
  }
}

TEST(Splitting, StripsKeepTheirPointIds)
{
  auto cube = Cube();
  Cells withStrip;
  withStrip.Polys = PolygonsOf(cube);
  withStrip.Strips = { { 0, 1, 2, 3 } }; // lies in the cube's bottom face
  auto mesh = MakePolyData(phongvtk_test::PointsOf(cube), withStrip);
  auto out = Split(mesh, vtkPolygonNormals::DOUBLE);
  EXPECT_EQ(out->GetNumberOfPoints(), 24);
  vtkNew<vtkIdList> ids;
  out->GetStrips()->GetCellAtId(0, ids);
  EXPECT_EQ(Cell(ids->begin(), ids->end()), (Cell{ 0, 1, 2, 3 }));
}

TEST(Splitting, BadPointIdsAreStillAnErrorNamingTheCell)
{
  auto cube = Cube();
  Cells cells;
  cells.Polys = PolygonsOf(cube);
  cells.Polys[4][2] = 8;
  auto bad = MakePolyData(phongvtk_test::PointsOf(cube), cells);
  // Alone, and with each reordering (then the splitting pass is the one that finds the cell).
  for (int orient = 0; orient < 3; ++orient)
  {
    vtkNew<vtkPolygonNormals> f;
    phongvtk_test::CellNormalsOfTheCellsAsGiven(f);
    vtkNew<MessageObserver> messages;
    messages->Watch(f);
    f->ComputePointNormalsOn();
    f->SplittingOn();
    f->SetConsistency(orient == 1);
    f->SetAutoOrientNormals(orient == 2);
    f->SetInputData(bad);
    f->Update();
    ASSERT_EQ(messages->Errors.size(), 1u) << orient;
    EXPECT_NE(
      messages->Errors[0].find("Cell 4 refers to a point id outside [0, 8)"), std::string::npos)
      << messages->Errors[0];
    EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
  }
}

TEST(Splitting, RealMeshesSplitAsVTKDoesWhereItsFloatTestCannotBeFooled)
{
  if (!phongvtk_test::HaveCGALMeshes())
  {
    PHONGVTK_SKIP() << "CGAL's sample meshes are not unpacked";
  }
  for (const char* name : { "fandisk.off", "cube_poly.off", "elephant.off", "cross.off" })
  {
    std::string error;
    auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name), &error);
    ASSERT_NE(mesh, nullptr) << name << ": " << error;
    const vtkIdType vtk = VTKSplitPointCount(mesh);
    for (int mode : Modes)
    {
      EXPECT_EQ(Split(mesh, mode)->GetNumberOfPoints(), vtk) << name << " " << ModeName(mode);
    }
  }
}

TEST(Splitting, SameOutputForEveryBackendAndThreadCount)
{
  auto mesh = RoughSphere(300, 0.03); // 180,000 triangles: the passes run in parallel
  const std::string original = vtkSMPTools::GetBackend();
  struct Config
  {
    const char* Backend;
    int Threads;
  };
  const Config configs[] = { { "Sequential", 1 }, { "STDThread", 1 }, { "STDThread", 2 },
    { "STDThread", 4 } };
  for (int mode : { vtkPolygonNormals::DOUBLE, vtkPolygonNormals::EXACT })
  {
    std::vector<vtkSmartPointer<vtkPolyData>> outputs;
    for (const Config& config : configs)
    {
      ASSERT_TRUE(vtkSMPTools::SetBackend(config.Backend));
      vtkSMPTools::Initialize(config.Threads);
      outputs.push_back(Split(mesh, mode));
    }
    const vtkIdType added = outputs[0]->GetNumberOfPoints() - mesh->GetNumberOfPoints();
    EXPECT_GT(added, 1000) << "the rough sphere must have sharp edges";
    EXPECT_LT(added, 3 * mesh->GetNumberOfPolys() - mesh->GetNumberOfPoints()) << "and smooth ones";
    for (std::size_t k = 1; k < outputs.size(); ++k)
    {
      ASSERT_EQ(outputs[k]->GetNumberOfPoints(), outputs[0]->GetNumberOfPoints());
      EXPECT_EQ(PolygonsOf(outputs[k]), PolygonsOf(outputs[0])) << ModeName(mode) << " " << k;
      vtkDataArray* a = outputs[0]->GetPointData()->GetNormals();
      vtkDataArray* b = outputs[k]->GetPointData()->GetNormals();
      ASSERT_EQ(a->GetDataSize(), b->GetDataSize());
      EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
                  static_cast<std::size_t>(a->GetDataSize() * a->GetDataTypeSize())),
        0)
        << ModeName(mode) << " run " << k;
    }
  }
  vtkSMPTools::SetBackend(original.c_str());
}

TEST(Splitting, RegionsDoNotDependOnTheCellOrder)
{
  auto mesh = RoughSphere(60, 0.05);
  const std::vector<Cell> polys = PolygonsOf(mesh);
  std::vector<vtkIdType> order(polys.size());
  std::iota(order.begin(), order.end(), vtkIdType(0));
  std::vector<vtkIdType> identity = order;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(3));
  Cells shuffled;
  for (vtkIdType f : order)
  {
    shuffled.Polys.push_back(polys[static_cast<std::size_t>(f)]);
  }
  auto other = MakePolyData(phongvtk_test::PointsOf(mesh), shuffled);
  for (int mode : Modes)
  {
    auto a = Split(mesh, mode);
    auto b = Split(other, mode);
    EXPECT_GT(a->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << ModeName(mode);
    EXPECT_EQ(CornerGroups(a, identity), CornerGroups(b, order)) << ModeName(mode);
  }
}

TEST(Splitting, InexactModesDecideFarFromTheOriginAsTheyDocument)
{
  // The trade table of the feature decision: on hinges straddling 30 degrees far from the
  // origin, how many edges each mode decides as EXACT does. EXACT matches rationals (above);
  // the others may not, but never by more than their normals' error allows: every edge they
  // misjudge lies within 1e-6 (FAST) or 1e-12 (DOUBLE, COMPENSATED) of the threshold in cosine.
  const double c = std::cos(vtkMath::RadiansFromDegrees(30.0));
  const double z0 = std::tan(vtkMath::RadiansFromDegrees(30.0));
  for (int mode :
    { vtkPolygonNormals::FAST, vtkPolygonNormals::DOUBLE, vtkPolygonNormals::COMPENSATED })
  {
    for (double offset : { 1e3, 1e6 })
    {
      for (int k = -20; k <= 20; ++k)
      {
        std::vector<Point> t1, t2;
        auto mesh = Hinge(offset, offset + 1.0, offset + z0 * (1.0 + k * 1e-8), &t1, &t2);
        const bool sharp = ReferenceSharp(t1, t2, c);
        const bool modeSharp = Split(mesh, mode)->GetNumberOfPoints() == 6;
        if (modeSharp != sharp)
        {
          const double z = t2[2][2] - offset; // exact: the stored height above the hinge
          const double cosine = 1.0 / std::sqrt(1.0 + z * z);
          EXPECT_LT(std::fabs(cosine - c), mode == vtkPolygonNormals::FAST ? 1e-5 : 1e-12)
            << ModeName(mode) << " offset " << offset << " step " << k;
        }
      }
    }
  }
}
