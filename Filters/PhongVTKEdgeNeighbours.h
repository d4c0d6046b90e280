/**
 * @file PhongVTKEdgeNeighbours.h
 * @brief Private: the polygons around every point (links) and the polygon across every edge of
 * every polygon, for vtkPolygonNormals' Consistency and Splitting.
 *
 * Edge k of a polygon runs from its corner k to corner k + 1; its slot is the polygon's offset
 * plus k, so the neighbours are laid out like the connectivity. An edge p-q is manifold when
 * exactly two distinct polygons have it (counting each time a polygon runs along it); its two
 * slots then hold `2 g + s`, g the polygon across and s 1 when both run along the edge the same
 * way (they disagree in orientation), 0 otherwise. Every other slot (boundary, non-manifold, an
 * edge from a point to itself) holds -1. Each edge is found from its smaller point, each slot
 * written once: the same result for any number of threads.
 */
#ifndef PhongVTKEdgeNeighbours_h
#define PhongVTKEdgeNeighbours_h

#include "PhongVTKCells.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"
#include "PhongVTKPolygonLinks.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/**
 * The polygons around every point (polygon indices of `polys`; every point id valid), as ids of
 * type Id (PhongVTKPolygonLinks.h): `CompactPolygonLinks` (32 bits: half the memory and half the
 * time to build) when the mesh fits them (FitsCompactLinks), `PolygonLinks` otherwise.
 */
using PolygonLinks = PolygonLinksOf<vtkIdType>;
using CompactPolygonLinks = PolygonLinksOf<unsigned int>;

/// The id type of links (PolygonLinksOf).
template <class Links>
using LinkId =
  std::remove_const_t<std::remove_pointer_t<decltype(std::declval<Links&>().GetCells(0))>>;

/// Whether the links of `polys` over `numPoints` points fit CompactPolygonLinks: every polygon,
/// corner and point id below 2^31.
inline bool FitsCompactLinks(vtkIdType numPoints, vtkCellArray* polys)
{
  return numPoints < VTK_INT_MAX && polys->GetNumberOfCells() < VTK_INT_MAX &&
    polys->GetConnectivityArray()->GetNumberOfValues() < VTK_INT_MAX;
}

/// The links of `polys` over the points `points`: each point's polygons in increasing order.
template <class Id>
void BuildPolygonLinks(vtkPoints* points, vtkCellArray* polys, PolygonLinksOf<Id>& links)
{
  links.Build(points->GetNumberOfPoints(), polys);
}

/**
 * The polygons at a point (its links `cells[0 .. count)`), each once and in increasing order:
 * the links themselves when they already are (a serial build), reversed when strictly
 * decreasing, else sorted into `scratch`. Returns the first and sets `n`.
 */
template <class Id>
const Id* DistinctSorted(const Id* cells, vtkIdType count, std::vector<Id>& scratch, std::size_t& n)
{
  bool increasing = true, decreasing = true;
  for (vtkIdType j = 1; j < count; ++j)
  {
    increasing = increasing && cells[j - 1] < cells[j];
    decreasing = decreasing && cells[j - 1] > cells[j];
  }
  n = static_cast<std::size_t>(count);
  if (increasing)
  {
    return cells;
  }
  scratch.assign(cells, cells + count);
  if (decreasing)
  {
    std::reverse(scratch.begin(), scratch.end());
  }
  else
  {
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    n = scratch.size();
  }
  return scratch.data();
}

/**
 * Calls fn(k, previous, next) for every corner k of polygon f (of the cell array's `offsets` and
 * `conn`) at point p, with the point ids before and after it. No division: its latency showed in
 * the profile of the splitting; and no branch on which corner is p (a mesh's polygons meet a
 * point at any of their corners, which the branch predictor cannot guess): the corners at p
 * are found as a mask, and a polygon has p once but for degenerate ones.
 */
template <class Offsets, class Connectivity, class Fn>
inline void ForCornersAt(
  const Offsets* offsets, const Connectivity* conn, vtkIdType f, vtkIdType p, Fn&& fn)
{
  const Connectivity* ids = conn + offsets[f];
  const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
  auto corner = [&](vtkIdType k)
  {
    fn(k, static_cast<vtkIdType>(ids[k == 0 ? m - 1 : k - 1]),
      static_cast<vtkIdType>(ids[k + 1 == m ? 0 : k + 1]));
  };
  if (m > 64)
  {
    for (vtkIdType k = 0; k < m; ++k)
    {
      if (static_cast<vtkIdType>(ids[k]) == p)
      {
        corner(k);
      }
    }
    return;
  }
  std::uint64_t at = 0;
  if (m == 3)
  {
    at = std::uint64_t(static_cast<vtkIdType>(ids[0]) == p ? 1 : 0) |
      std::uint64_t(static_cast<vtkIdType>(ids[1]) == p ? 2 : 0) |
      std::uint64_t(static_cast<vtkIdType>(ids[2]) == p ? 4 : 0);
  }
  else
  {
    for (vtkIdType k = 0; k < m; ++k)
    {
      at |= std::uint64_t(static_cast<vtkIdType>(ids[k]) == p ? 1 : 0) << k;
    }
  }
  for (; at != 0; at &= at - 1)
  {
    corner(static_cast<vtkIdType>(__builtin_ctzll(at)));
  }
}

/**
 * Two polygons around a non-manifold edge (three or more polygons, or one running along it
 * twice): `First`, the smallest polygon around the edge, at its edge `Slot`, and `Other`, another
 * polygon around it; `Same` when both run along the edge the same way.
 */
struct NonManifoldPair
{
  vtkIdType First, Slot, Other;
  int Same;

  bool operator<(const NonManifoldPair& b) const
  {
    return this->Slot < b.Slot ||
      (this->Slot == b.Slot &&
        (this->Other < b.Other || (this->Other == b.Other && this->Same < b.Same)));
  }
};

/// An edge p-q of a fan (PointFanOf): of polygon `Polygon` (index `Face` in Faces) in its edge slot
/// `Slot` (corner index), `Forward` 1 when it runs p -> q.
struct FanEdge
{
  vtkIdType Q, Polygon, Slot;
  std::int32_t Face, Forward;

  /// Polygon, then slot.
  bool Before(const FanEdge& b) const
  {
    return this->Polygon < b.Polygon || (this->Polygon == b.Polygon && this->Slot < b.Slot);
  }
};

/// The edges of one group of a fan, in the order of its Edges.
struct FanGroup
{
  const FanEdge* Edges;
  const std::int32_t* Index;
  std::size_t Size;

  const FanEdge& operator[](std::size_t i) const { return this->Edges[this->Index[i]]; }

  /// Whether the group is a manifold edge (two distinct polygons).
  bool Manifold() const { return this->Size == 2 && (*this)[0].Polygon != (*this)[1].Polygon; }
};

/**
 * The fan of polygons around one point p: its polygons (`Faces`, sorted, each once) and its
 * edges at p (`Edges`), each edge p-q of each polygon with q != p, grouped by q: a manifold edge
 * when two distinct polygons, a non-manifold one when more (or one polygon twice). Every polygon
 * having the edge p-q has p, so the whole group is in p's fan. The edges are listed in the order
 * of the sorted polygons, so the groups and their members do not depend on the order of the
 * links. Its polygons are ids of type Id, the links'.
 *
 * Most fans of most meshes are plain triangle fans (`Plain`): every polygon a triangle with p at
 * one corner, no two of them running from p to the same point or from the same point to p. Then
 * every edge p-q is either one triangle's (a boundary) or two triangles' running along it in
 * opposite directions (a manifold edge where they agree), and the fan is kept as its triangles'
 * points after and before p and the pairs (`Next`, `Previous`, `Match`), found with a hash of the
 * point ids and without listing the edges; the edges and groups are listed (as for any other fan)
 * only if ForGroups asks for them.
 */
template <class Id>
struct PointFanOf
{
  using Edge = FanEdge;
  using Group = FanGroup;

  const Id* Faces = nullptr;
  std::size_t NumberOfFaces = 0;
  std::vector<Edge> Edges; // the first NumberOfEdges are the fan's (ForGroups lists them)
  std::size_t NumberOfEdges = 0;

  /// At most this many triangles make a plain fan.
  static constexpr std::size_t PlainMax = 16;
  bool Plain = false;
  vtkIdType Next[PlainMax];      // triangle i runs p -> Next[i] (its edge slot Corner[i])
  vtkIdType Previous[PlainMax];  // and Previous[i] -> p (its slot Corner[i] - 1, mod 3)
  std::int32_t Corner[PlainMax]; // p's corner
  std::int32_t Match[PlainMax];  // j with Previous[j] == Next[i] (the edge's other triangle), -1

  /**
   * The fan of p from its links `cells[0 .. count)` in `offsets` and `conn`; with `after`, only
   * the edges to points q > p (each edge is then found from one side only).
   */
  template <class Offsets, class Connectivity>
  void Build(vtkIdType p, const Id* cells, vtkIdType count, const Offsets* offsets,
    const Connectivity* conn, bool after)
  {
    this->Faces = DistinctSorted(cells, count, this->SortedFaces, this->NumberOfFaces);
    this->Listed = false;
    this->Plain = !after && this->BuildPlain(p, offsets, conn);
    if (this->Plain)
    {
      return;
    }
    // Each edge written field by field into room kept from point to point: an Edge built aside
    // and copied in cost a stalled store-to-load forwarding per edge (a tenth of the splitting).
    this->NumberOfEdges = 0;
    const vtkIdType least = after ? p + 1 : 0;
    for (std::size_t i = 0; i < this->NumberOfFaces; ++i)
    {
      const vtkIdType f = this->Faces[i];
      const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
      ForCornersAt(offsets, conn, f, p,
        [&](vtkIdType k, vtkIdType previous, vtkIdType next)
        {
          if (this->NumberOfEdges + 2 > this->Edges.size())
          {
            this->Edges.resize(2 * this->Edges.size() + 16);
          }
          if (next != p && next >= least)
          {
            this->Add(next, f, k, i, 1);
          }
          if (previous != p && previous >= least)
          {
            this->Add(previous, f, k == 0 ? m - 1 : k - 1, i, 0);
          }
        });
    }
    this->GroupEdges();
  }

  /// Calls fn(group) for every group of edges to one point q (a Group).
  template <class Fn>
  void ForGroups(Fn&& fn) const
  {
    this->ListPlain();
    std::size_t begin = 0;
    for (const std::size_t end : this->GroupEnd)
    {
      fn(Group{ this->Edges.data(), this->Members.data() + begin, end - begin });
      begin = end;
    }
  }

  /// The pairs of a plain fan: calls fn(i, j) for every manifold edge p-q, i and j the indices
  /// in Faces of its triangle running p -> q and of the one running q -> p.
  template <class Fn>
  void ForPlainPairs(Fn&& fn) const
  {
    for (std::size_t i = 0; i < this->NumberOfFaces; ++i)
    {
      if (this->Match[i] >= 0)
      {
        fn(static_cast<std::int32_t>(i), this->Match[i]);
      }
    }
  }

private:
  std::vector<Id> SortedFaces;
  bool Listed = false; // a plain fan's edges and groups are listed

  /// A hash of a point id into [0, 64) (Fibonacci hashing: neighbouring ids land apart).
  static unsigned Hash(vtkIdType q)
  {
    return static_cast<unsigned>((static_cast<std::uint64_t>(q) * 0x9E3779B97F4A7C15ull) >> 58);
  }

  /**
   * Whether the fan of p (Faces) is plain, filling Next, Previous, Corner and Match if so. The
   * points after p are distinct when their hashes are (and those before p too); where two
   * hashes meet the fan is taken as not plain (the general listing then decides): a few fans in
   * five with random ids, so the test stays a handful of operations per triangle.
   */
  template <class Offsets, class Connectivity>
  bool BuildPlain(vtkIdType p, const Offsets* offsets, const Connectivity* conn)
  {
    const std::size_t n = this->NumberOfFaces;
    if (n > PlainMax)
    {
      return false;
    }
    std::uint64_t nextHashes = 0, previousHashes = 0;
    std::int32_t previousAt[64];
    for (std::size_t i = 0; i < n; ++i)
    {
      const vtkIdType f = this->Faces[i];
      if (offsets[f + 1] - offsets[f] != 3)
      {
        return false;
      }
      const Connectivity* ids = conn + offsets[f];
      const unsigned at = unsigned(static_cast<vtkIdType>(ids[0]) == p) |
        unsigned(static_cast<vtkIdType>(ids[1]) == p) << 1 |
        unsigned(static_cast<vtkIdType>(ids[2]) == p) << 2;
      if (at != 1 && at != 2 && at != 4)
      {
        return false; // p at no corner, or at two (a degenerate triangle)
      }
      // The corners after and before p by index, not by a branch on which corner p is (meshes
      // meet a point at any corner: the predictor cannot guess it).
      const unsigned k = at >> 1;
      const vtkIdType next = static_cast<vtkIdType>(ids[(0x021u >> (4 * k)) & 3]);
      const vtkIdType previous = static_cast<vtkIdType>(ids[(0x102u >> (4 * k)) & 3]);
      if (next == previous)
      {
        return false; // a triangle (p, q, q): one polygon along p-q twice
      }
      this->Next[i] = next;
      this->Previous[i] = previous;
      this->Corner[i] = static_cast<std::int32_t>(k);
      const unsigned hp = Hash(previous);
      nextHashes |= std::uint64_t(1) << Hash(next);
      previousHashes |= std::uint64_t(1) << hp;
      previousAt[hp] = static_cast<std::int32_t>(i);
    }
    if (static_cast<std::size_t>(__builtin_popcountll(nextHashes)) != n ||
      static_cast<std::size_t>(__builtin_popcountll(previousHashes)) != n)
    {
      return this->MatchPlain();
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      const unsigned h = Hash(this->Next[i]);
      const std::int32_t j = (previousHashes >> h & 1) ? previousAt[h] : -1;
      this->Match[i] = j >= 0 && this->Previous[j] == this->Next[i] ? j : -1;
    }
    return true;
  }

  /// BuildPlain's test and pairs where two hashes met: by comparing every two ids.
  bool MatchPlain()
  {
    const auto n = static_cast<std::int32_t>(this->NumberOfFaces);
    for (std::int32_t i = 0; i < n; ++i)
    {
      this->Match[i] = -1;
      for (std::int32_t j = 0; j < n; ++j)
      {
        if (j != i && (this->Next[j] == this->Next[i] || this->Previous[j] == this->Previous[i]))
        {
          return false;
        }
        if (this->Previous[j] == this->Next[i])
        {
          this->Match[i] = j;
        }
      }
    }
    return true;
  }

  /// Lists a plain fan's edges and groups as any other fan's (the same edges in the same order).
  void ListPlain() const
  {
    if (!this->Plain || this->Listed)
    {
      return;
    }
    auto* self = const_cast<PointFanOf*>(this);
    self->Listed = true;
    self->NumberOfEdges = 0;
    if (self->Edges.size() < 2 * this->NumberOfFaces)
    {
      self->Edges.resize(2 * this->NumberOfFaces);
    }
    for (std::size_t i = 0; i < this->NumberOfFaces; ++i)
    {
      const std::int32_t k = this->Corner[i];
      self->Add(this->Next[i], this->Faces[i], k, i, 1);
      self->Add(this->Previous[i], this->Faces[i], k == 0 ? 2 : k - 1, i, 0);
    }
    self->GroupEdges();
  }

  /// Appends an edge (there is room).
  void Add(vtkIdType q, vtkIdType f, vtkIdType slot, std::size_t face, std::int32_t forward)
  {
    Edge& e = this->Edges[this->NumberOfEdges++];
    e.Q = q;
    e.Polygon = f;
    e.Slot = slot;
    e.Face = static_cast<std::int32_t>(face);
    e.Forward = forward;
  }

  std::vector<std::int32_t> Members; // the edges' indices, group after group
  std::vector<std::size_t> GroupEnd;

  void GroupEdges()
  {
    const auto n = static_cast<std::int32_t>(this->NumberOfEdges);
    this->Members.resize(static_cast<std::size_t>(n));
    this->GroupEnd.clear();
    std::int32_t* members = this->Members.data();
    const Edge* e = this->Edges.data();
    if (n > 64)
    {
      // A hub point: sorted by q, each group is a run.
      std::iota(members, members + n, 0);
      std::sort(members, members + n,
        [e](std::int32_t a, std::int32_t b)
        { return e[a].Q < e[b].Q || (e[a].Q == e[b].Q && a < b); });
      for (std::int32_t i = 1; i <= n; ++i)
      {
        if (i == n || e[members[i]].Q != e[members[i - 1]].Q)
        {
          this->GroupEnd.push_back(static_cast<std::size_t>(i));
        }
      }
      return;
    }
    // Few (the rule: a dozen): each group found by a scan, which beats sorting them; the scan of
    // the qs side by side makes a mask of the matches, without a branch.
    vtkIdType q[64];
    for (std::int32_t i = 0; i < n; ++i)
    {
      q[i] = e[i].Q;
    }
    std::uint64_t taken = 0;
    std::size_t size = 0;
    for (std::int32_t i = 0; i < n; ++i)
    {
      if (taken >> i & 1)
      {
        continue;
      }
      std::uint64_t same = 0;
      for (std::int32_t j = i + 1; j < n; ++j)
      {
        same |= std::uint64_t(q[j] == q[i] ? 1 : 0) << j;
      }
      taken |= same;
      members[size++] = i;
      for (; same != 0; same &= same - 1)
      {
        members[size++] = static_cast<std::int32_t>(__builtin_ctzll(same));
      }
      this->GroupEnd.push_back(size);
    }
  }
};

/// The fan of links of vtkIdType.
using PointFan = PointFanOf<vtkIdType>;

/**
 * The neighbour across an edge slot (EdgeNeighbours): `2 g + s` for the polygon g across it, s 1
 * when both run along the edge the same way; all bits set (NoNeighbour) where there is none. As
 * vtkIdType, or as 32 bits (CompactNeighbour) for a mesh that fits compact links (every polygon
 * id below 2^31): half the memory a pass over the neighbours reads.
 */
using CompactNeighbour = std::uint32_t;
template <class N>
constexpr N NoNeighbour = static_cast<N>(-1);
static_assert(NoNeighbour<vtkIdType> == -1, "the wide neighbours' empty slot is -1");

/// The neighbour slot of g (`same` when both polygons run along the edge the same way).
template <class N>
inline N NeighbourSlot(vtkIdType g, vtkIdType same)
{
  return static_cast<N>(2 * g + same);
}

/**
 * Writes what a group of edges p-q (PointFan) says about the edge slots: for a manifold edge,
 * each polygon's slot holds the other (NeighbourSlot); for a non-manifold one, with `pairs`,
 * every polygon around it paired with the smallest polygon's first edge.
 */
template <class Offsets, class N>
inline void RecordEdgeGroup(
  const FanGroup& group, const Offsets* offsets, N* neighbours, std::vector<NonManifoldPair>* pairs)
{
  if (group.Manifold())
  {
    const FanEdge& a = group[0];
    const FanEdge& b = group[1];
    const vtkIdType same = a.Forward == b.Forward ? 1 : 0;
    neighbours[static_cast<vtkIdType>(offsets[a.Polygon]) + a.Slot] =
      NeighbourSlot<N>(b.Polygon, same);
    neighbours[static_cast<vtkIdType>(offsets[b.Polygon]) + b.Slot] =
      NeighbourSlot<N>(a.Polygon, same);
  }
  else if (pairs && group.Size >= 2)
  {
    const FanEdge* first = &group[0];
    for (std::size_t j = 1; j < group.Size; ++j)
    {
      first = group[j].Before(*first) ? &group[j] : first;
    }
    for (std::size_t j = 0; j < group.Size; ++j)
    {
      if (group[j].Polygon != first->Polygon)
      {
        pairs->push_back(
          { first->Polygon, static_cast<vtkIdType>(offsets[first->Polygon]) + first->Slot,
            group[j].Polygon, group[j].Forward == first->Forward ? 1 : 0 });
      }
    }
  }
}

/**
 * What a pass over the fans (ForPointFans) writes about the edges. With `Neighbours` (as many as
 * the connectivity, filled with NoNeighbour), the neighbour across every edge slot; with
 * `NonManifold` as well, every polygon around each non-manifold edge paired with the smallest one
 * around it, sorted by slot. Always `Disagreeing`: the number of edges Consistency would act on,
 * the manifold edges along which both polygons run the same way and, with `CountNonManifold`, the
 * non-manifold edges. None: the polygons agree already, and Consistency has nothing to do. With
 * `StopAtDisagreeing`, the pass ends soon after the first such edge (Disagreeing then counts
 * some of them, at least one).
 */
template <class N>
struct EdgeRecordsOf
{
  N* Neighbours = nullptr;
  std::vector<NonManifoldPair>* NonManifold = nullptr;
  bool CountNonManifold = false;
  bool StopAtDisagreeing = false;
  vtkIdType Disagreeing = 0;
};
using EdgeRecords = EdgeRecordsOf<vtkIdType>;

/// How many points ahead ForPointFans asks for the data of the polygons around a point.
constexpr vtkIdType FanLookAhead = 8;

/**
 * Calls atPoint(p, fan, local) for every point p of `polys` (valid point ids, `links` theirs)
 * with its fan (PointFan; with `after`, only the edges to larger points) and the calling thread's
 * own `Local` (default-constructed, kept from point to point), from several threads, each point
 * on its own; first, each edge from its smaller point, what `records` asks for (EdgeRecords).
 */
template <class Local, class Links, class N, class AtPoint, class AheadFn>
void ForPointFans(vtkIdType numPoints, vtkCellArray* polys, Links& links, bool after,
  EdgeRecordsOf<N>& records, const AtPoint& atPoint, const AheadFn& ahead)
{
  struct Scratch
  {
    PointFanOf<LinkId<Links>> Fan;
    std::vector<NonManifoldPair> Pairs;
    vtkIdType Disagreeing = 0;
    Local Own;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  N* neighbours = records.Neighbours;
  const bool pairs = neighbours && records.NonManifold;
  std::atomic<bool> stop(false);
  ForRawCells(polys,
    [&](const auto* offsets, const auto* conn)
    {
      phongvtk::For(0, numPoints, FanWork * polys->GetNumberOfCells(),
        [&](vtkIdType begin, vtkIdType end)
        {
          Scratch& local = scratch.Local();
          auto& fan = local.Fan;
          for (vtkIdType p = begin; p < end; ++p)
          {
            if (records.StopAtDisagreeing &&
              (local.Disagreeing > 0 || stop.load(std::memory_order_relaxed)))
            {
              stop.store(true, std::memory_order_relaxed);
              break;
            }
            // The fans come in point order but their polygons' ids and data lie apart: asked
            // for a few points ahead, their loads overlap. Where a polygon's ids are depends on
            // its offset, itself apart: the offsets are asked for twice as far ahead.
            if (p + 2 * FanLookAhead < end)
            {
              const auto* later = links.GetCells(p + 2 * FanLookAhead);
              for (vtkIdType j = 0, n = links.GetNumberOfCells(p + 2 * FanLookAhead); j < n; ++j)
              {
                PrefetchAddress(offsets + later[j]);
              }
            }
            if (p + FanLookAhead < end)
            {
              const auto* next = links.GetCells(p + FanLookAhead);
              for (vtkIdType j = 0, n = links.GetNumberOfCells(p + FanLookAhead); j < n; ++j)
              {
                PrefetchRecord(conn + offsets[next[j]], conn + offsets[next[j] + 1] - 1);
                ahead(next[j]);
              }
            }
            fan.Build(p, links.GetCells(p), links.GetNumberOfCells(p), offsets, conn, after);
            if (fan.Plain)
            {
              // Every edge agrees and is manifold or a boundary: only the neighbours to write.
              if (neighbours)
              {
                fan.ForPlainPairs(
                  [&](std::int32_t i, std::int32_t j)
                  {
                    if (fan.Next[i] > p)
                    {
                      const vtkIdType fi = fan.Faces[i], fj = fan.Faces[j];
                      const std::int32_t kj = fan.Corner[j];
                      neighbours[static_cast<vtkIdType>(offsets[fi]) + fan.Corner[i]] =
                        NeighbourSlot<N>(fj, 0);
                      neighbours[static_cast<vtkIdType>(offsets[fj]) + (kj == 0 ? 2 : kj - 1)] =
                        NeighbourSlot<N>(fi, 0);
                    }
                  });
              }
            }
            else
            {
              fan.ForGroups(
                [&](const FanGroup& group)
                {
                  // Each edge from its smaller point; counted without a branch on that.
                  const bool mine = group[0].Q > p;
                  local.Disagreeing += mine &
                    (group.Manifold() ? group[0].Forward == group[1].Forward
                                      : records.CountNonManifold && group.Size >= 2);
                  if (neighbours && mine)
                  {
                    RecordEdgeGroup(group, offsets, neighbours, pairs ? &local.Pairs : nullptr);
                  }
                });
            }
            atPoint(p, fan, local.Own);
          }
        });
    });
  records.Disagreeing = 0;
  for (Scratch& local : scratch)
  {
    records.Disagreeing += local.Disagreeing;
  }
  if (pairs)
  {
    records.NonManifold->clear();
    for (Scratch& local : scratch)
    {
      records.NonManifold->insert(
        records.NonManifold->end(), local.Pairs.begin(), local.Pairs.end());
    }
    std::sort(records.NonManifold->begin(), records.NonManifold->end());
  }
}

/**
 * What `records` asks for about the edges of `polys` (valid point ids, `links` theirs), from a
 * pass over the fans that does nothing else (each edge from its smaller point).
 */
template <class Links, class N>
void RecordEdges(vtkIdType numPoints, vtkCellArray* polys, Links& links, EdgeRecordsOf<N>& records)
{
  struct Nothing
  {
  };
  ForPointFans<Nothing>(
    numPoints, polys, links, true, records, [](vtkIdType, const auto&, Nothing&) {},
    [](vtkIdType) {});
}

/**
 * The neighbour across every edge slot of `polys` (valid point ids, `links` theirs) as N
 * (NeighbourSlot; CompactNeighbour only where the mesh fits compact links); with `nonManifold`,
 * also every polygon around each non-manifold edge paired with the smallest one around it,
 * sorted by slot.
 */
template <class N = vtkIdType, class Links>
std::vector<N> EdgeNeighbours(vtkIdType numPoints, vtkCellArray* polys, Links& links,
  std::vector<NonManifoldPair>* nonManifold = nullptr)
{
  std::vector<N> neighbours(
    static_cast<std::size_t>(polys->GetConnectivityArray()->GetNumberOfValues()), NoNeighbour<N>);
  EdgeRecordsOf<N> records;
  records.Neighbours = neighbours.data();
  records.NonManifold = nonManifold;
  RecordEdges(numPoints, polys, links, records);
  return neighbours;
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKEdgeNeighbours.h
