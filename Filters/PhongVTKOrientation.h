/**
 * @file PhongVTKOrientation.h
 * @brief Private: consistent ordering of the polygons (vtkPolygonNormals' Consistency) and their
 * reversal (FlipNormals).
 *
 * Two polygons sharing a manifold edge (exactly two polygons have it) agree when they run along
 * it in opposite directions. Each connected component (polygons joined by manifold edges) keeps
 * the order of its first polygon, and every other polygon is reversed or not so that it agrees
 * with its neighbours: a breadth-first walk from that polygon, neighbours in increasing order, so
 * the result does not depend on the thread count. On an orientable component the answer is
 * unique (and so independent of the cell order but for the choice of the first polygon); on a
 * non-orientable one (a Moebius strip) some edges must disagree, and the polygons along them are
 * reported. A polygon is reversed keeping its first point: (p0, p(n-1), ..., p1), so that its
 * fan, and for a triangle its area vector, is the same but for the sign.
 */
#ifndef PhongVTKOrientation_h
#define PhongVTKOrientation_h

#include "PhongVTKCells.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLinksTemplate.h"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

namespace phongvtk
{
/// Which polygons to reverse, and what could not be made consistent.
struct Orientation
{
  std::vector<unsigned char> Reverse; // per polygon
  vtkIdType Reversed = 0;
  vtkIdType NonOrientable = 0;    // components whose polygons cannot all agree
  std::vector<vtkIdType> Clashes; // polygons along an edge where they still disagree, sorted
};

/// A manifold edge between polygons A < B; Same: they run along it in the same direction.
struct PolygonPair
{
  vtkIdType A, B;
  bool Same;
  bool operator<(const PolygonPair& o) const
  {
    return std::tie(A, B, Same) < std::tie(o.A, o.B, o.Same);
  }
};

/**
 * The manifold edges between the polygons of `polys` (valid point ids), each once, sorted: for
 * every point p the edges p-q with q > p that exactly two distinct polygons have.
 */
inline std::vector<PolygonPair> ManifoldEdges(vtkPoints* points, vtkCellArray* polys)
{
  const vtkIdType numPoints = points->GetNumberOfPoints();
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(polys);
  vtkStaticCellLinksTemplate<vtkIdType> links;
  links.BuildLinks(surface);
  struct Local
  {
    std::vector<PolygonPair> Pairs;
    std::vector<std::tuple<vtkIdType, vtkIdType, int>> Edges; // (q, polygon, +1 p->q / -1 q->p)
  };
  vtkSMPThreadLocal<Local> locals;
  polys->Visit(RawCells{},
    [&](const auto* offsets, const auto* conn)
    {
      phongvtk::For(0, numPoints, polys->GetNumberOfCells(),
        [&](vtkIdType begin, vtkIdType end)
        {
          Local& local = locals.Local();
          for (vtkIdType p = begin; p < end; ++p)
          {
            const vtkIdType count = links.GetNumberOfCells(p);
            const vtkIdType* cells = links.GetCells(p);
            local.Edges.clear();
            for (vtkIdType j = 0; j < count; ++j)
            {
              const vtkIdType f = cells[j];
              if (std::find(cells, cells + j, f) != cells + j)
              {
                continue; // a polygon that uses p twice is listed twice
              }
              const auto* ids = conn + offsets[f];
              const vtkIdType m = static_cast<vtkIdType>(offsets[f + 1] - offsets[f]);
              for (vtkIdType k = 0; k < m; ++k)
              {
                if (static_cast<vtkIdType>(ids[k]) != p)
                {
                  continue;
                }
                const auto next = static_cast<vtkIdType>(ids[(k + 1) % m]);
                const auto previous = static_cast<vtkIdType>(ids[(k + m - 1) % m]);
                if (next > p)
                {
                  local.Edges.emplace_back(next, f, +1);
                }
                if (previous > p)
                {
                  local.Edges.emplace_back(previous, f, -1);
                }
              }
            }
            std::sort(local.Edges.begin(), local.Edges.end());
            for (std::size_t e = 0; e < local.Edges.size();)
            {
              std::size_t end = e + 1;
              while (end < local.Edges.size() &&
                std::get<0>(local.Edges[end]) == std::get<0>(local.Edges[e]))
              {
                ++end;
              }
              const auto& a = local.Edges[e];
              const auto& b = local.Edges[e + 1];
              if (end - e == 2 && std::get<1>(a) != std::get<1>(b))
              {
                local.Pairs.push_back(
                  { std::get<1>(a), std::get<1>(b), std::get<2>(a) == std::get<2>(b) });
              }
              e = end;
            }
          }
        });
    });
  std::vector<PolygonPair> pairs;
  for (Local& local : locals)
  {
    pairs.insert(pairs.end(), local.Pairs.begin(), local.Pairs.end());
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/**
 * Consistent ordering of `numPolys` polygons joined by `pairs` (ManifoldEdges): which to reverse
 * so that every pair runs along its edge in opposite directions, each component keeping the
 * order of its first polygon; a component where that is impossible is counted and the polygons
 * of every pair left disagreeing are listed.
 */
inline Orientation ConsistentOrientation(vtkIdType numPolys, const std::vector<PolygonPair>& pairs)
{
  // Neighbours of every polygon, in increasing order (pairs are sorted by A, then B).
  std::vector<vtkIdType> first(static_cast<std::size_t>(numPolys) + 1, 0);
  for (const PolygonPair& pair : pairs)
  {
    ++first[static_cast<std::size_t>(pair.A) + 1];
    ++first[static_cast<std::size_t>(pair.B) + 1];
  }
  for (std::size_t f = 0; f < static_cast<std::size_t>(numPolys); ++f)
  {
    first[f + 1] += first[f];
  }
  struct Neighbour
  {
    vtkIdType Polygon;
    bool Same;
  };
  std::vector<Neighbour> neighbours(pairs.size() * 2);
  std::vector<vtkIdType> fill(first.begin(), first.end() - 1);
  for (const PolygonPair& pair : pairs)
  {
    neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(pair.A)]++)] = { pair.B,
      pair.Same };
    neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(pair.B)]++)] = { pair.A,
      pair.Same };
  }
  for (std::size_t f = 0; f < static_cast<std::size_t>(numPolys); ++f)
  {
    std::sort(neighbours.begin() + first[f], neighbours.begin() + first[f + 1],
      [](const Neighbour& a, const Neighbour& b) { return a.Polygon < b.Polygon; });
  }

  Orientation result;
  result.Reverse.assign(static_cast<std::size_t>(numPolys), 0);
  std::vector<unsigned char> visited(static_cast<std::size_t>(numPolys), 0);
  std::vector<vtkIdType> wave;
  for (vtkIdType seed = 0; seed < numPolys; ++seed)
  {
    if (visited[static_cast<std::size_t>(seed)])
    {
      continue;
    }
    visited[static_cast<std::size_t>(seed)] = 1;
    wave.assign(1, seed);
    bool clash = false;
    for (std::size_t w = 0; w < wave.size(); ++w)
    {
      const vtkIdType f = wave[w];
      const unsigned char reverseF = result.Reverse[static_cast<std::size_t>(f)];
      for (vtkIdType k = first[static_cast<std::size_t>(f)];
           k < first[static_cast<std::size_t>(f) + 1]; ++k)
      {
        const Neighbour& n = neighbours[static_cast<std::size_t>(k)];
        const auto g = static_cast<std::size_t>(n.Polygon);
        // Same direction: exactly one of the two must be reversed.
        const unsigned char wanted = reverseF ^ static_cast<unsigned char>(n.Same);
        if (!visited[g])
        {
          visited[g] = 1;
          result.Reverse[g] = wanted;
          wave.push_back(n.Polygon);
        }
        else if (result.Reverse[g] != wanted && f < n.Polygon)
        {
          clash = true;
          result.Clashes.push_back(f);
          result.Clashes.push_back(n.Polygon);
        }
      }
    }
    result.NonOrientable += clash;
  }
  std::sort(result.Clashes.begin(), result.Clashes.end());
  result.Clashes.erase(
    std::unique(result.Clashes.begin(), result.Clashes.end()), result.Clashes.end());
  for (unsigned char r : result.Reverse)
  {
    result.Reversed += r;
  }
  return result;
}

/// The polygons with those marked reversed as (p0, p(n-1), ..., p1).
inline vtkSmartPointer<vtkCellArray> ReversedPolygons(
  vtkCellArray* polys, const std::vector<unsigned char>& reverse)
{
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->DeepCopy(polys);
  out->Visit(RawCells{},
    [&](const auto* offsets, auto* conn)
    {
      phongvtk::For(0, out->GetNumberOfCells(), out->GetNumberOfCells(),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType f = begin; f < end; ++f)
          {
            if (reverse[static_cast<std::size_t>(f)] && offsets[f + 1] - offsets[f] > 2)
            {
              std::reverse(conn + offsets[f] + 1, conn + offsets[f + 1]);
            }
          }
        });
    });
  return out;
}

} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKOrientation.h
