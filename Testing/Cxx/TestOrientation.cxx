// Consistency and FlipNormals of vtkPolygonNormals (PhongVTKOrientation.h): orientations
// restored after random reversals, checked edge by edge and against vtkPolyDataNormals'
// Consistency; a Moebius strip reported, not looped on; bitwise the same for every backend and
// thread count.
#include "PhongVTKFilterTestSupport.h"
#include "PhongVTKOFFReader.h"
#include "PhongVTKOrientation.h"
#include "PhongVTKSkip.h"
#include "vtkPolygonNormals.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{
using phongvtk_test::Cell;
using phongvtk_test::Cells;
using phongvtk_test::MakePolyData;
using phongvtk_test::MessageObserver;
using phongvtk_test::Moebius;
using phongvtk_test::Point;
using phongvtk_test::PolygonsOf;
using phongvtk_test::RoughSphere;
using phongvtk_test::RunFilter;
using phongvtk_test::SphereMesh;

/// `mesh` with a random share of its polygons reversed: VTK's way (the whole list backwards) or,
/// with keepFirst, keeping the first point.
vtkSmartPointer<vtkPolyData> RandomlyReversed(vtkPolyData* mesh, double share, unsigned seed,
  std::vector<bool>* reversed = nullptr, bool keepFirst = false)
{
  std::mt19937_64 random(seed);
  std::bernoulli_distribution flip(share);
  Cells cells;
  cells.Polys = PolygonsOf(mesh);
  for (Cell& cell : cells.Polys)
  {
    const bool r = flip(random);
    if (r)
    {
      std::reverse(cell.begin() + (keepFirst ? 1 : 0), cell.end());
    }
    if (reversed)
    {
      reversed->push_back(r);
    }
  }
  return MakePolyData(phongvtk_test::PointsOf(mesh), cells);
}

/// Edges shared by exactly two polygons: how many run the same way in both (disagree).
int DisagreeingEdges(vtkPolyData* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, std::vector<int>> edges; // (min, max) -> directions
  for (const Cell& cell : PolygonsOf(mesh))
  {
    for (std::size_t k = 0; k < cell.size(); ++k)
    {
      const vtkIdType a = cell[k], b = cell[(k + 1) % cell.size()];
      if (a != b)
      {
        edges[{ std::min(a, b), std::max(a, b) }].push_back(a < b ? 1 : -1);
      }
    }
  }
  int disagreeing = 0;
  for (const auto& edge : edges)
  {
    disagreeing += edge.second.size() == 2 && edge.second[0] == edge.second[1];
  }
  return disagreeing;
}

void ExpectSameBits(vtkDataArray* a, vtkDataArray* b, const std::string& what)
{
  ASSERT_NE(a, nullptr) << what;
  ASSERT_NE(b, nullptr) << what;
  ASSERT_EQ(a->GetDataSize(), b->GetDataSize()) << what;
  EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
              static_cast<std::size_t>(a->GetDataSize() * a->GetDataTypeSize())),
    0)
    << what;
}
} // namespace

TEST(Orientation, RandomReversalsOfAClosedSurfaceAreUndone)
{
  auto sphere = SphereMesh(40);
  ASSERT_EQ(DisagreeingEdges(sphere), 0);
  std::vector<bool> reversed;
  auto scrambled = RandomlyReversed(sphere, 0.3, 1, &reversed, true);
  ASSERT_GT(DisagreeingEdges(scrambled), 100);
  auto out = RunFilter(scrambled, [](vtkPolygonNormals* f) { f->ConsistencyOn(); });
  EXPECT_EQ(DisagreeingEdges(out), 0);
  // The first polygon keeps its order, so the sphere points the way polygon 0 did: every
  // polygon's normal is the original one times the same sign, exactly (a reversed triangle keeps
  // its first point, so its area vector is exactly negated).
  auto plain = RunFilter(
    sphere, [](vtkPolygonNormals* f) { f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION); });
  vtkDataArray* original = plain->GetCellData()->GetNormals();
  auto exact = RunFilter(scrambled,
    [](vtkPolygonNormals* f)
    {
      f->ConsistencyOn();
      f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    });
  vtkDataArray* restored = exact->GetCellData()->GetNormals();
  const double sign = reversed[0] ? -1.0 : 1.0;
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    double a[3], b[3];
    original->GetTuple(c, a);
    restored->GetTuple(c, b);
    ASSERT_TRUE(b[0] == sign * a[0] && b[1] == sign * a[1] && b[2] == sign * a[2]) << "cell " << c;
  }
}

TEST(Orientation, OneReversedPolygonAnywhereIsTurnedBack)
{
  // Consistency first asks whether the polygons agree already, stopping at the first edge where
  // they do not: a single reversed polygon must be found wherever it lies (among the first
  // points, the middle ones, the last; one thread or several), with Splitting or without.
  auto sphere = SphereMesh(60);
  const Cells given{ {}, {}, PolygonsOf(sphere), {} };
  const vtkIdType numPolys = sphere->GetNumberOfPolys();
  const std::string backend = vtkSMPTools::GetBackend();
  for (const auto& config :
    std::vector<std::pair<const char*, int>>{ { "Sequential", 1 }, { "STDThread", 3 } })
  {
    ASSERT_TRUE(vtkSMPTools::SetBackend(config.first));
    vtkSMPTools::Initialize(config.second);
    for (const vtkIdType f : { vtkIdType(1), numPolys / 2, numPolys - 1 })
    {
      Cells cells = given;
      std::reverse(cells.Polys[static_cast<std::size_t>(f)].begin() + 1,
        cells.Polys[static_cast<std::size_t>(f)].end());
      auto turned = MakePolyData(phongvtk_test::PointsOf(sphere), cells);
      ASSERT_EQ(DisagreeingEdges(turned), 3) << f;
      for (const bool split : { false, true })
      {
        auto out = RunFilter(turned,
          [split](vtkPolygonNormals* filter)
          {
            filter->ConsistencyOn();
            filter->SetSplitting(split);
            filter->ComputePointNormalsOn();
          });
        EXPECT_EQ(PolygonsOf(out), given.Polys)
          << config.first << " " << config.second << " polygon " << f << " split " << split;
      }
    }
  }
  vtkSMPTools::SetBackend(backend.c_str());
}

TEST(Orientation, AgreesWithVTKsConsistencyOnRealMeshes)
{
  if (!phongvtk_test::HaveCGALMeshes())
  {
    PHONGVTK_SKIP() << "CGAL's sample meshes are not unpacked";
  }
  for (const char* name : { "fandisk.off", "elephant.off", "bunny00.off" })
  {
    auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name));
    ASSERT_NE(mesh, nullptr) << name;
    auto scrambled = RandomlyReversed(mesh, 0.5, 2);
    auto ours = RunFilter(scrambled, [](vtkPolygonNormals* f) { f->ConsistencyOn(); });
    vtkNew<vtkPolyDataNormals> vtk;
    vtk->SetInputData(scrambled);
    vtk->ConsistencyOn();
    vtk->SplittingOff();
    vtk->AutoOrientNormalsOff();
    vtk->Update();
    EXPECT_EQ(DisagreeingEdges(ours), DisagreeingEdges(vtk->GetOutput())) << name;
    EXPECT_EQ(DisagreeingEdges(ours), 0) << name;
    // The same polygons reversed: same cell normals up to rounding (VTK reverses the whole list,
    // which changes the fan's first point).
    vtkDataArray* a = ours->GetCellData()->GetNormals();
    auto theirs = RunFilter(vtk->GetOutput(), [](vtkPolygonNormals*) {});
    vtkDataArray* b = theirs->GetCellData()->GetNormals();
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      double x[3], y[3];
      a->GetTuple(c, x);
      b->GetTuple(c, y);
      ASSERT_GT(x[0] * y[0] + x[1] * y[1] + x[2] * y[2], 0.99) << name << " cell " << c;
    }
  }
}

TEST(Orientation, EachComponentKeepsItsFirstPolygon)
{
  // Two separate triangles pairs: the second component's first polygon (cell 2) is reversed
  // against its neighbour (cell 3); the first component agrees already.
  const std::vector<Point> p = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 5, 0, 0 },
    { 6, 0, 0 }, { 5, 1, 0 }, { 6, 1, 0 } };
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 1, 3, 2 }, { 4, 6, 5 }, { 5, 7, 6 } };
  auto out = RunFilter(MakePolyData(p, cells), [](vtkPolygonNormals* f) { f->ConsistencyOn(); });
  const std::vector<Cell> polys = PolygonsOf(out);
  EXPECT_EQ(polys[0], (Cell{ 0, 1, 2 }));
  EXPECT_EQ(polys[1], (Cell{ 1, 3, 2 }));
  EXPECT_EQ(polys[2], (Cell{ 4, 6, 5 }));
  EXPECT_EQ(polys[3], (Cell{ 5, 6, 7 })) << "reversed keeping its first point";
}

TEST(Orientation, MoebiusStripIsReportedAndItsSeamFlagged)
{
  auto strip = Moebius(24);
  vtkNew<MessageObserver> messages;
  auto out = RunFilter(
    strip,
    [](vtkPolygonNormals* f)
    {
      f->ConsistencyOn();
      f->ComputeNormalStatusOn();
      f->ComputePointNormalsOn();
    },
    messages);
  EXPECT_TRUE(messages->Errors.empty());
  ASSERT_EQ(messages->Warnings.size(), 1u);
  EXPECT_NE(
    messages->Warnings[0].find("1 connected component(s) are not orientable"), std::string::npos)
    << messages->Warnings[0];
  EXPECT_EQ(DisagreeingEdges(out), 1) << "one seam is the least a Moebius strip needs";
  auto* status = vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("NormalStatus"));
  ASSERT_NE(status, nullptr);
  int flagged = 0;
  for (vtkIdType c = 0; c < status->GetNumberOfTuples(); ++c)
  {
    EXPECT_TRUE(status->GetValue(c) == 0 || status->GetValue(c) == 4);
    flagged += status->GetValue(c) == 4;
  }
  EXPECT_EQ(flagged, 2) << "the two quads along the seam";
  // Without ComputeNormalStatus nothing is written, not even into a NormalStatus array that came
  // with the input.
  vtkNew<MessageObserver> again;
  auto second = RunFilter(
    out, [](vtkPolygonNormals* f) { f->ConsistencyOn(); }, again);
  EXPECT_EQ(again->Warnings.size(), 1u);
  EXPECT_EQ(second->GetCellData()->GetArray("NormalStatus"), status);
  vtkIdType stillFlagged = 0;
  for (vtkIdType c = 0; c < status->GetNumberOfTuples(); ++c)
  {
    stillFlagged += status->GetValue(c) == 4;
  }
  EXPECT_EQ(stillFlagged, 2);
  auto plain = RunFilter(strip, [](vtkPolygonNormals* f) { f->ConsistencyOn(); });
  EXPECT_EQ(plain->GetCellData()->GetArray("NormalStatus"), nullptr);
  // An orientable strip (no twist) gives neither warning nor flag.
  Cells ring;
  ring.Polys = PolygonsOf(strip);
  ring.Polys.back() = { 46, 0, 1, 47 };
  vtkNew<MessageObserver> quiet;
  RunFilter(
    MakePolyData(phongvtk_test::PointsOf(strip), ring),
    [](vtkPolygonNormals* f) { f->ConsistencyOn(); }, quiet);
  EXPECT_TRUE(quiet->Warnings.empty());
}

/// A torus of n x n quads (not planar: each point moved radially at random).
vtkSmartPointer<vtkPolyData> RoughQuadTorus(int n, double roughness)
{
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> uniform(-roughness, roughness);
  std::vector<Point> p;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double u = 2.0 * vtkMath::Pi() * i / n, v = 2.0 * vtkMath::Pi() * j / n;
      const double r = 0.4 * (1.0 + uniform(random));
      p.push_back({ (1.0 + r * std::cos(v)) * std::cos(u), (1.0 + r * std::cos(v)) * std::sin(u),
        r * std::sin(v) });
    }
  }
  Cells cells;
  auto id = [n](int i, int j)
  {
    return vtkIdType((i % n) * n + j % n);
  };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      cells.Polys.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MakePolyData(p, cells);
}

TEST(Orientation, SplittingAfterConsistencyIsTheSplittingOfTheOrderedPolygons)
{
  // The sharp edges are decided before the polygons are reordered (on the normals as given, one
  // negated where the two will be turned against each other): the result must be that of
  // splitting the mesh Consistency delivers. A reversed triangle's area vector is exactly the
  // negated one, so triangles agree bit for bit in every mode; quads in EXACT, whose decision is
  // exact either way.
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Mesh;
    std::vector<int> Modes;
  };
  const Case cases[] = { { RoughSphere(40, 0.05),
                           { vtkPolygonNormals::DOUBLE, vtkPolygonNormals::EXACT } },
    { RoughQuadTorus(30, 0.3), { vtkPolygonNormals::EXACT } } };
  for (const Case& c : cases)
  {
    for (unsigned seed : { 1u, 2u })
    {
      auto reversed = RandomlyReversed(c.Mesh, 0.4, seed);
      for (int mode : c.Modes)
      {
        auto configure = [mode](vtkPolygonNormals* f)
        {
          f->SetAccuracy(mode);
          f->ComputePointNormalsOn();
          f->SplittingOn();
        };
        auto together = RunFilter(reversed,
          [&](vtkPolygonNormals* f)
          {
            configure(f);
            f->ConsistencyOn();
          });
        auto ordered = RunFilter(reversed,
          [](vtkPolygonNormals* f)
          {
            f->ConsistencyOn();
            f->ComputeCellNormalsOff();
          });
        auto apart = RunFilter(ordered, configure);
        ASSERT_GT(apart->GetNumberOfPoints(), c.Mesh->GetNumberOfPoints() + 10)
          << "the mesh must have sharp edges";
        ASSERT_EQ(together->GetNumberOfPoints(), apart->GetNumberOfPoints()) << mode;
        EXPECT_EQ(PolygonsOf(together), PolygonsOf(apart)) << mode;
        vtkDataArray* a = together->GetPointData()->GetNormals();
        vtkDataArray* b = apart->GetPointData()->GetNormals();
        ASSERT_EQ(a->GetDataSize(), b->GetDataSize());
        EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
                    static_cast<std::size_t>(a->GetDataSize() * a->GetDataTypeSize())),
          0)
          << mode;
      }
    }
  }
}

TEST(Orientation, SplittingCutsAMoebiusStripAtTheSeamConsistencyLeaves)
{
  // Every edge of the strip is smooth as given, but after Consistency the two quads along the
  // seam face opposite ways: the edge between them is sharp, and every point normal must lean
  // towards each polygon it belongs to (averaging across the seam would cancel them).
  auto out = RunFilter(Moebius(24),
    [](vtkPolygonNormals* f)
    {
      f->ConsistencyOn();
      f->SplittingOn();
      f->ComputePointNormalsOn();
      f->ComputeCellNormalsOn();
    });
  EXPECT_EQ(out->GetNumberOfPoints(), 48 + 2) << "the two points of the seam get a copy each";
  phongvtk_test::ForEachCornerNormal(out,
    [](std::size_t f, vtkIdType p, const double* n, const double* m)
    {
      EXPECT_GT(vtkMath::Dot(n, m), std::cos(vtkMath::RadiansFromDegrees(30.0)))
        << "polygon " << f << " point " << p;
    });
}

TEST(Orientation, NonManifoldEdgesImposeNothing)
{
  // A fin of three triangles on the edge 0-1 running the same way: no pair is manifold there.
  const std::vector<Point> p = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 },
    { 0.5, 0, 1 } };
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 1, 4 } };
  auto out = RunFilter(MakePolyData(p, cells), [](vtkPolygonNormals* f) { f->ConsistencyOn(); });
  EXPECT_EQ(PolygonsOf(out), cells.Polys);
}

TEST(Orientation, NonManifoldTraversalJoinsThePagesOfABook)
{
  // Three pages on the spine 0-1, each two quads (a component of its own without the
  // traversal), pages 1 and 2 given either against page 0 along the spine or the same way as it.
  // With NonManifoldTraversal every page runs along the spine against page 0 (the smallest
  // polygon around it), as in VTK's traversal from cell 0: in the second book pages 1 and 2 turn.
  // +1 when the polygon runs 0 -> 1 along the spine, -1 for 1 -> 0.
  auto spine = [](const Cell& cell)
  {
    for (std::size_t k = 0; k < cell.size(); ++k)
    {
      const vtkIdType a = cell[k], b = cell[(k + 1) % cell.size()];
      if (a == 0 && b == 1)
      {
        return 1;
      }
      if (a == 1 && b == 0)
      {
        return -1;
      }
    }
    return 0;
  };
  for (const bool pagesAgainst : { true, false })
  {
    std::vector<Point> p = { { 0, 0, 0 }, { 0, 0, 1 } };
    Cells cells;
    for (int page = 0; page < 3; ++page)
    {
      const double t = 2.0 * M_PI * page / 3.0;
      const double c = std::cos(t), s = std::sin(t);
      const auto base = static_cast<vtkIdType>(p.size());
      p.insert(p.end(), { { c, s, 0 }, { c, s, 1 }, { 2 * c, 2 * s, 0 }, { 2 * c, 2 * s, 1 } });
      Cell inner = { 0, base, base + 1, 1 };
      Cell outer = { base, base + 2, base + 3, base + 1 };
      if (page > 0 && pagesAgainst)
      {
        std::reverse(inner.begin(), inner.end());
        std::reverse(outer.begin(), outer.end());
      }
      cells.Polys.push_back(inner);
      cells.Polys.push_back(outer);
    }
    auto book = MakePolyData(p, cells);
    EXPECT_EQ(spine(cells.Polys[2]), pagesAgainst ? 1 : -1);
    auto alone = PolygonsOf(RunFilter(book, [](vtkPolygonNormals* f) { f->ConsistencyOn(); }));
    EXPECT_EQ(alone, PolygonsOf(book)) << "each page keeps its first polygon's order";
    auto joined = PolygonsOf(RunFilter(book,
      [](vtkPolygonNormals* f)
      {
        f->ConsistencyOn();
        f->NonManifoldTraversalOn();
      }));
    EXPECT_EQ(spine(joined[0]), -1);
    EXPECT_EQ(spine(joined[2]), 1) << pagesAgainst;
    EXPECT_EQ(spine(joined[4]), 1) << pagesAgainst;
    EXPECT_EQ(DisagreeingEdges(MakePolyData(p, Cells{ {}, {}, joined, {} })), 0);
    // With Splitting too: its pass over the fans finds every manifold edge agreeing, yet the
    // spine still decides the pages (the polygons read back through OriginalPointIds).
    auto split = RunFilter(book,
      [](vtkPolygonNormals* f)
      {
        f->ConsistencyOn();
        f->NonManifoldTraversalOn();
        f->SplittingOn();
        f->ComputePointNormalsOn();
      });
    EXPECT_EQ(split->GetNumberOfPoints(), 14 + 4) << "each end of the spine on three pages";
    auto* original =
      vtkIdTypeArray::SafeDownCast(split->GetPointData()->GetArray("OriginalPointIds"));
    ASSERT_NE(original, nullptr);
    std::vector<Cell> splitBack = PolygonsOf(split);
    for (Cell& cell : splitBack)
    {
      for (vtkIdType& id : cell)
      {
        id = original->GetValue(id);
      }
    }
    EXPECT_EQ(splitBack, joined) << pagesAgainst;
    vtkNew<vtkPolyDataNormals> vtk;
    vtk->SetInputData(book);
    vtk->SplittingOff();
    vtk->ConsistencyOn();
    vtk->NonManifoldTraversalOn();
    vtk->Update();
    const std::vector<Cell> theirs = PolygonsOf(vtk->GetOutput());
    for (std::size_t f = 0; f < theirs.size(); f += 2)
    {
      EXPECT_EQ(spine(theirs[f]), spine(joined[f])) << "page " << f / 2 << " " << pagesAgainst;
    }
  }
}

TEST(Orientation, FlipNormalsTurnsTheCellsAndEveryNormalTogether)
{
  auto sphere = SphereMesh(30);
  for (bool consistency : { false, true })
  {
    auto configure = [consistency](vtkPolygonNormals* f)
    {
      f->SetConsistency(consistency);
      f->ComputePointNormalsOn();
      f->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    };
    auto plain = RunFilter(sphere, configure);
    auto flipped = RunFilter(sphere,
      [&](vtkPolygonNormals* f)
      {
        configure(f);
        f->FlipNormalsOn();
      });
    const std::vector<Cell> a = PolygonsOf(plain), b = PolygonsOf(flipped);
    for (std::size_t c = 0; c < a.size(); ++c)
    {
      Cell expected = { a[c][0] };
      expected.insert(expected.end(), a[c].rbegin(), a[c].rend() - 1);
      ASSERT_EQ(b[c], expected);
    }
    for (vtkDataArray* n :
      { plain->GetCellData()->GetNormals(), plain->GetPointData()->GetNormals() })
    {
      vtkDataArray* m = n == plain->GetCellData()->GetNormals()
        ? flipped->GetCellData()->GetNormals()
        : flipped->GetPointData()->GetNormals();
      for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          ASSERT_EQ(m->GetComponent(i, k), -n->GetComponent(i, k)) << i;
        }
      }
    }
  }
}

TEST(Orientation, SameOutputForEveryBackendAndThreadCount)
{
  auto scrambled = RandomlyReversed(SphereMesh(300), 0.4, 3); // 179,400 triangles
  const std::string original = vtkSMPTools::GetBackend();
  std::vector<vtkSmartPointer<vtkPolyData>> outputs;
  for (const auto& config : std::vector<std::pair<const char*, int>>{
         { "Sequential", 1 }, { "STDThread", 1 }, { "STDThread", 2 }, { "STDThread", 4 } })
  {
    ASSERT_TRUE(vtkSMPTools::SetBackend(config.first));
    vtkSMPTools::Initialize(config.second);
    outputs.push_back(RunFilter(scrambled,
      [](vtkPolygonNormals* f)
      {
        f->ConsistencyOn();
        f->SplittingOn();
        f->ComputePointNormalsOn();
      }));
  }
  vtkSMPTools::SetBackend(original.c_str());
  for (std::size_t k = 1; k < outputs.size(); ++k)
  {
    EXPECT_EQ(PolygonsOf(outputs[k]), PolygonsOf(outputs[0])) << k;
    ExpectSameBits(outputs[0]->GetPointData()->GetNormals(),
      outputs[k]->GetPointData()->GetNormals(), "point normals " + std::to_string(k));
  }
}

TEST(Orientation, BadPointIdsAreStillAnErrorNamingTheCell)
{
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 2, 1, 7 } };
  auto mesh = MakePolyData({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, cells);
  vtkNew<MessageObserver> messages;
  auto out = RunFilter(
    mesh, [](vtkPolygonNormals* f) { f->ConsistencyOn(); }, messages);
  ASSERT_EQ(messages->Errors.size(), 1u);
  EXPECT_NE(
    messages->Errors[0].find("Cell 1 refers to a point id outside [0, 3)"), std::string::npos)
    << messages->Errors[0];
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(OrientationKernel, ClashesAreThePolygonsOfTheDisagreeingPairsOnly)
{
  // A cycle of three polygons (two edge slots each) where every pair runs the same way along
  // its edge: odd, so not orientable. A neighbour is 2 * polygon + (1 for the same direction).
  const std::vector<vtkIdType> offsets = { 0, 2, 4, 6 };
  const std::vector<vtkIdType> odd = { 3, 5, 1, 5, 1, 3 };
  const phongvtk::Orientation o = phongvtk::ConsistentOrientation(3, offsets.data(), odd);
  EXPECT_EQ(o.NonOrientable, 1);
  EXPECT_EQ(o.Reverse, (std::vector<unsigned char>{ 0, 1, 1 }));
  EXPECT_EQ(o.Clashes, (std::vector<vtkIdType>{ 1, 2 }));
  // Even cycle 0-1-2-3-0, two pairs the same way: orientable. Boundary slots hold -1.
  const std::vector<vtkIdType> offsets4 = { 0, 3, 6, 9, 12 };
  const std::vector<vtkIdType> even = { 3, 6, -1, 1, 4, -1, 2, 7, -1, 0, 5, -1 };
  const phongvtk::Orientation e = phongvtk::ConsistentOrientation(4, offsets4.data(), even);
  EXPECT_EQ(e.NonOrientable, 0);
  EXPECT_TRUE(e.Clashes.empty());
  EXPECT_EQ(e.Reverse, (std::vector<unsigned char>{ 0, 1, 1, 0 }));
  EXPECT_TRUE(e.Component.empty() && e.OpenSlots.empty()) << "only asked for by AutoOrient";
  // With the components: one each, the odd one clashing; the even one's open slots.
  const phongvtk::Orientation oc =
    phongvtk::ConsistentOrientation(3, offsets.data(), odd, nullptr, true);
  EXPECT_EQ(oc.NonOrientable, 1);
  EXPECT_EQ(oc.Component, (std::vector<vtkIdType>{ 0, 0, 0 }));
  EXPECT_EQ(oc.ComponentClashes, (std::vector<unsigned char>{ 1 }));
  const phongvtk::Orientation ec =
    phongvtk::ConsistentOrientation(4, offsets4.data(), even, nullptr, true);
  EXPECT_EQ(ec.Reverse, e.Reverse);
  EXPECT_EQ(ec.Component, (std::vector<vtkIdType>{ 0, 0, 0, 0 }));
  EXPECT_EQ(ec.ComponentFirst, (std::vector<vtkIdType>{ 0 }));
  EXPECT_EQ(ec.ComponentClashes, (std::vector<unsigned char>{ 0 }));
  const std::vector<std::pair<vtkIdType, vtkIdType>> open = { { 0, 2 }, { 1, 5 }, { 2, 8 },
    { 3, 11 } };
  EXPECT_EQ(ec.OpenSlots, open);
  // The same neighbours in 32 bits (compact links), the empty slot all ones: the same answers.
  auto compact = [](const std::vector<vtkIdType>& wide)
  {
    std::vector<phongvtk::CompactNeighbour> c;
    for (vtkIdType n : wide)
    {
      c.push_back(n < 0 ? 0xFFFFFFFFu : static_cast<phongvtk::CompactNeighbour>(n));
    }
    return c;
  };
  const phongvtk::Orientation oc32 =
    phongvtk::ConsistentOrientation(3, offsets.data(), compact(odd), nullptr, true);
  EXPECT_EQ(oc32.Reverse, oc.Reverse);
  EXPECT_EQ(oc32.Clashes, (std::vector<vtkIdType>{ 1, 2 }));
  EXPECT_EQ(oc32.ComponentClashes, oc.ComponentClashes);
  const phongvtk::Orientation ec32 =
    phongvtk::ConsistentOrientation(4, offsets4.data(), compact(even), nullptr, true);
  EXPECT_EQ(ec32.Reverse, e.Reverse);
  EXPECT_EQ(ec32.OpenSlots, open);
  EXPECT_EQ(ec32.Component, ec.Component);
}

TEST(OrientationKernel, EdgeNeighboursOfAFanWithAFinAndABoundary)
{
  // Triangles 0 (0,1,2), 1 (0,2,3) share 0-2 running opposite ways; 2 (0,3,4) shares 0-3 with 1
  // running the same way; 3, 4, 5 all have 4-5 (non-manifold).
  Cells cells;
  cells.Polys = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 4, 3 }, { 4, 5, 6 }, { 5, 4, 7 }, { 4, 5, 8 } };
  std::vector<Point> p(9, Point{ 0, 0, 0 });
  auto mesh = MakePolyData(p, cells);
  phongvtk::PolygonLinks links;
  phongvtk::BuildPolygonLinks(mesh->GetPoints(), mesh->GetPolys(), links);
  const std::vector<vtkIdType> n = phongvtk::EdgeNeighbours(9, mesh->GetPolys(), links);
  const std::vector<vtkIdType> expected = {
    -1, -1, 2 * 1,                     // 0-1, 1-2 boundary; 2-0 with polygon 1, opposite
    2 * 0, -1, 2 * 2 + 1,              // 0-2 with 0; 2-3 boundary; 3-0 with 2, same way
    -1, -1, 2 * 1 + 1,                 // 0-4 boundary, 4-3 boundary, 3-0 with 1
    -1, -1, -1, -1, -1, -1, -1, -1, -1 // the fin: nothing manifold
  };
  EXPECT_EQ(n, expected);
  // With compact links, in 32 bits: the same slots, the empty ones all ones.
  phongvtk::CompactPolygonLinks compactLinks;
  phongvtk::BuildPolygonLinks(mesh->GetPoints(), mesh->GetPolys(), compactLinks);
  const std::vector<phongvtk::CompactNeighbour> n32 =
    phongvtk::EdgeNeighbours<phongvtk::CompactNeighbour>(9, mesh->GetPolys(), compactLinks);
  ASSERT_EQ(n32.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
  {
    EXPECT_EQ(
      n32[k], expected[k] < 0 ? 0xFFFFFFFFu : static_cast<phongvtk::CompactNeighbour>(expected[k]))
      << "slot " << k;
  }
  // The fin's pairs: polygon 3's edge 4-5 (slot 9) with 4 (running the other way) and 5 (the
  // same way).
  std::vector<phongvtk::NonManifoldPair> pairs;
  EXPECT_EQ(phongvtk::EdgeNeighbours(9, mesh->GetPolys(), links, &pairs), expected);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].First, 3);
  EXPECT_EQ(pairs[0].Slot, 9);
  EXPECT_EQ(pairs[0].Other, 4);
  EXPECT_EQ(pairs[0].Same, 0);
  EXPECT_EQ(pairs[1].Other, 5);
  EXPECT_EQ(pairs[1].Same, 1);
}
