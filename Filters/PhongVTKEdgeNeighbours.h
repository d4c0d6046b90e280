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
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkStaticCellLinksTemplate.h"

#include <algorithm>
#include <vector>

namespace phongvtk
{
/// The polygons around every point (polygon indices of `polys`; every point id valid).
using PolygonLinks = vtkStaticCellLinksTemplate<vtkIdType>;

/**
 * The links of `polys`. On one thread VTK's serial build (no atomics; each point's polygons come
 * in increasing order, which the passes over them use); its threaded build otherwise.
 */
inline void BuildPolygonLinks(vtkPoints* points, vtkCellArray* polys, PolygonLinks& links)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(polys);
  links.SetSequentialProcessing(Threads(polys->GetNumberOfCells()) == 1);
  links.BuildLinks(surface);
}

/**
 * The polygons at a point (its links `cells[0 .. count)`), each once and in increasing order:
 * the links themselves when they already are (a serial build), reversed when strictly
 * decreasing, else sorted into `scratch`. Returns the first and sets `n`.
 */
inline const vtkIdType* DistinctSorted(
  const vtkIdType* cells, vtkIdType count, std::vector<vtkIdType>& scratch, std::size_t& n)
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
 * the profile of the splitting.
 */
template <class Offsets, class Connectivity, class Fn>
inline void ForCornersAt(
  const Offsets* offsets, const Connectivity* conn, vtkIdType f, vtkIdType p, Fn&& fn)
{
  const Connectivity* ids = conn + offsets[f];
  const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
  for (vtkIdType k = 0; k < m; ++k)
  {
    if (static_cast<vtkIdType>(ids[k]) == p)
    {
      fn(k, static_cast<vtkIdType>(ids[k == 0 ? m - 1 : k - 1]),
        static_cast<vtkIdType>(ids[k + 1 == m ? 0 : k + 1]));
    }
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
    return this->Slot < b.Slot || (this->Slot == b.Slot && this->Other < b.Other);
  }
};

/**
 * The neighbour across every edge slot of `polys` (valid point ids, `links` theirs); with
 * `nonManifold`, also every polygon around each non-manifold edge paired with the smallest one
 * around it, sorted by slot.
 */
inline std::vector<vtkIdType> EdgeNeighbours(vtkIdType numPoints, vtkCellArray* polys,
  PolygonLinks& links, std::vector<NonManifoldPair>* nonManifold = nullptr)
{
  std::vector<vtkIdType> neighbours(
    static_cast<std::size_t>(polys->GetConnectivityArray()->GetNumberOfValues()), -1);
  // Every edge p-q at p with q > p: q, the polygon, its slot, and 1 for p -> q or 0 for q -> p.
  struct Edge
  {
    vtkIdType Q, Polygon, Slot;
    int Forward;
  };
  struct Scratch
  {
    std::vector<Edge> Edges;
    std::vector<vtkIdType> Faces;
    std::vector<NonManifoldPair> Pairs;
    std::vector<const Edge*> Members;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  polys->Visit(RawCells{},
    [&](const auto* offsets, const auto* conn)
    {
      phongvtk::For(0, numPoints, polys->GetNumberOfCells(),
        [&](vtkIdType begin, vtkIdType end)
        {
          Scratch& local = scratch.Local();
          std::vector<Edge>& edges = local.Edges;
          std::vector<vtkIdType>& faces = local.Faces;
          for (vtkIdType p = begin; p < end; ++p)
          {
            std::size_t numFaces;
            const vtkIdType* atP =
              DistinctSorted(links.GetCells(p), links.GetNumberOfCells(p), faces, numFaces);
            edges.clear();
            for (std::size_t i = 0; i < numFaces; ++i)
            {
              const vtkIdType f = atP[i];
              const auto m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
              ForCornersAt(offsets, conn, f, p,
                [&](vtkIdType k, vtkIdType previous, vtkIdType next)
                {
                  if (next > p)
                  {
                    edges.push_back({ next, f, k, 1 });
                  }
                  if (previous > p)
                  {
                    edges.push_back({ previous, f, k == 0 ? m - 1 : k - 1, 0 });
                  }
                });
            }
            // The edges to the same q form a group: a manifold edge when two polygons, a
            // non-manifold one when more (or one polygon twice).
            auto group = [&](std::size_t members, const Edge* const* at)
            {
              if (members == 2 && at[0]->Polygon != at[1]->Polygon)
              {
                const Edge& a = *at[0];
                const Edge& b = *at[1];
                const vtkIdType same = a.Forward == b.Forward ? 1 : 0;
                neighbours[static_cast<std::size_t>(offsets[a.Polygon] + a.Slot)] =
                  2 * b.Polygon + same;
                neighbours[static_cast<std::size_t>(offsets[b.Polygon] + b.Slot)] =
                  2 * a.Polygon + same;
              }
              else if (nonManifold && members >= 2)
              {
                // Polygons then slots ascending: the smallest polygon's first edge comes first.
                const Edge* first = at[0];
                for (std::size_t j = 1; j < members; ++j)
                {
                  if (at[j]->Polygon < first->Polygon ||
                    (at[j]->Polygon == first->Polygon && at[j]->Slot < first->Slot))
                  {
                    first = at[j];
                  }
                }
                for (std::size_t j = 0; j < members; ++j)
                {
                  if (at[j]->Polygon != first->Polygon)
                  {
                    local.Pairs.push_back({ first->Polygon, offsets[first->Polygon] + first->Slot,
                      at[j]->Polygon, at[j]->Forward == first->Forward ? 1 : 0 });
                  }
                }
              }
            };
            std::vector<const Edge*>& members = local.Members;
            const std::size_t numEdges = edges.size();
            if (numEdges > 32)
            {
              // Many (a hub point): sorted by q, each group is a run.
              std::sort(
                edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.Q < b.Q; });
              for (std::size_t e = 0; e < numEdges;)
              {
                members.clear();
                std::size_t last = e;
                while (last < numEdges && edges[last].Q == edges[e].Q)
                {
                  members.push_back(&edges[last++]);
                }
                group(members.size(), members.data());
                e = last;
              }
              continue;
            }
            // Few (the rule): each group found by a scan, a sort cost more; its members taken.
            for (std::size_t e = 0; e < numEdges; ++e)
            {
              const vtkIdType q = edges[e].Q;
              if (q < 0)
              {
                continue;
              }
              members.clear();
              members.push_back(&edges[e]);
              for (std::size_t j = e + 1; j < numEdges; ++j)
              {
                if (edges[j].Q == q)
                {
                  members.push_back(&edges[j]);
                }
              }
              group(members.size(), members.data());
              for (std::size_t j = 1; j < members.size(); ++j)
              {
                edges[static_cast<std::size_t>(members[j] - edges.data())].Q = -1;
              }
            }
          }
        });
    });
  if (nonManifold)
  {
    nonManifold->clear();
    for (Scratch& local : scratch)
    {
      nonManifold->insert(nonManifold->end(), local.Pairs.begin(), local.Pairs.end());
    }
    std::sort(nonManifold->begin(), nonManifold->end());
  }
  return neighbours;
}

/**
 * The neighbours after the polygons marked in `reverse` are reversed keeping their first point
 * ((p0, p(n-1), ..., p1)): their new edge j is their old edge n - 1 - j. The polygons across stay
 * right; the same-direction bits are those of before.
 */
inline void ReverseEdgeSlots(std::vector<vtkIdType>& neighbours, vtkCellArray* polys,
  const std::vector<unsigned char>& reverse)
{
  polys->Visit(RawCells{},
    [&](const auto* offsets, const auto*)
    {
      for (vtkIdType f = 0; f < polys->GetNumberOfCells(); ++f)
      {
        if (reverse[static_cast<std::size_t>(f)])
        {
          std::reverse(neighbours.begin() + offsets[f], neighbours.begin() + offsets[f + 1]);
        }
      }
    });
}

} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKEdgeNeighbours.h
