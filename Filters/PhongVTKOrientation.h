/**
 * @file PhongVTKOrientation.h
 * @brief Private: consistent ordering of the polygons (vtkPolygonNormals' Consistency) and their
 * reversal (FlipNormals).
 *
 * Two polygons sharing a manifold edge (exactly two polygons have it) agree when they run along
 * it in opposite directions. Each connected component (polygons joined by manifold edges) keeps
 * the order of its first polygon, and every other polygon is reversed or not so that it agrees
 * with its neighbours: the edges are taken one by one in the polygons' order, so the result does
 * not depend on the thread count. On an orientable component the answer is
 * unique (and so independent of the cell order but for the choice of the first polygon); on a
 * non-orientable one (a Moebius strip) some edges must disagree, and the polygons along them are
 * reported. A polygon is reversed keeping its first point: (p0, p(n-1), ..., p1), so that its
 * fan, and for a triangle its area vector, is the same but for the sign.
 */
#ifndef PhongVTKOrientation_h
#define PhongVTKOrientation_h

#include "PhongVTKCells.h"
#include "PhongVTKEdgeNeighbours.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// Which polygons to reverse, and what could not be made consistent.
struct Orientation
{
  std::vector<unsigned char> Reverse; // per polygon
  vtkIdType Reversed = 0;
  vtkIdType NonOrientable = 0;    // components whose polygons cannot all agree
  std::vector<vtkIdType> Clashes; // polygons along an edge where they still disagree, sorted
  // With `components` (AutoOrient): the connected components (polygons joined by manifold
  // edges), numbered in the order of their smallest polygon: each polygon's component, and
  // whether each is non-orientable.
  std::vector<vtkIdType> Component;
  std::vector<unsigned char> ComponentClashes;
  std::vector<vtkIdType> ComponentFirst; // the smallest polygon of each
  // Every edge slot without a neighbour (boundary, non-manifold or from a point to itself), as
  // (polygon, slot) pairs in slot order.
  std::vector<std::pair<vtkIdType, vtkIdType>> OpenSlots;
};

/**
 * Consistent ordering of `numPolys` polygons whose edge slots (`offsets[f]` to `offsets[f + 1]`)
 * hold their `neighbours` (EdgeNeighbours): which to reverse so that every manifold edge is run
 * along in opposite directions, each component keeping the order of its first polygon; a
 * component where that is impossible is counted and the polygons of every pair left disagreeing
 * are listed.
 *
 * A union-find with parity over the edges in slot order (the neighbours are read once, in
 * memory order: a breadth-first walk waited on the memory for most of its time): a set's root
 * is its smallest polygon, which keeps its order, and every polygon's parity to the root says
 * whether it is reversed. An edge between two polygons already in one set whose parities
 * disagree is where a non-orientable component cannot agree. With `nonManifold` (EdgeNeighbours'
 * pairs), components are then joined across non-manifold edges, in slot order; with
 * `components`, the components and open slots are listed as well. The neighbours are taken by
 * value: a caller done with them moves them in, and their memory goes before the answers'.
 */
template <class Offsets, class N>
Orientation ConsistentOrientation(vtkIdType numPolys, const Offsets* offsets,
  std::vector<N> neighbours, const std::vector<NonManifoldPair>* nonManifold = nullptr,
  bool components = false)
{
  // Polygon ids as the neighbours hold them (32 bits where they fit).
  std::vector<N> parent(static_cast<std::size_t>(numPolys));
  std::iota(parent.begin(), parent.end(), N(0));
  std::vector<unsigned char> parity(static_cast<std::size_t>(numPolys), 0);   // to the parent
  std::vector<unsigned char> clashing(static_cast<std::size_t>(numPolys), 0); // roots only
  // The root of f and f's parity to it, halving the path on the way (every node passed points
  // to its grandparent, with its parity to it): one walk.
  auto find = [&](vtkIdType f, unsigned char& toRoot)
  {
    unsigned char total = 0;
    for (;;)
    {
      const vtkIdType up = parent[static_cast<std::size_t>(f)];
      if (up == f)
      {
        break;
      }
      const vtkIdType upper = parent[static_cast<std::size_t>(up)];
      parity[static_cast<std::size_t>(f)] ^= parity[static_cast<std::size_t>(up)];
      parent[static_cast<std::size_t>(f)] = static_cast<N>(upper);
      total ^= parity[static_cast<std::size_t>(f)];
      f = upper;
    }
    toRoot = total;
    return f;
  };
  Orientation result;
  for (vtkIdType f = 0; f < numPolys; ++f)
  {
    // f's root and parity, found once for all its edges and kept through its joins.
    unsigned char pf;
    vtkIdType rf = find(f, pf);
    for (auto k = static_cast<vtkIdType>(offsets[f]); k < static_cast<vtkIdType>(offsets[f + 1]);
         ++k)
    {
      const N n = neighbours[static_cast<std::size_t>(k)];
      const auto g = static_cast<vtkIdType>(n >> 1);
      if (n == NoNeighbour<N>)
      {
        if (components)
        {
          result.OpenSlots.emplace_back(f, k);
        }
        continue;
      }
      if (g < f)
      {
        continue; // the edge was taken from g's side
      }
      // Same direction: exactly one of the two must be reversed.
      const auto same = static_cast<unsigned char>(n & 1);
      unsigned char pg;
      const vtkIdType rg = find(g, pg);
      if (rf == rg)
      {
        if ((pf ^ pg) != same)
        {
          clashing[static_cast<std::size_t>(rf)] = 1;
          result.Clashes.push_back(f);
          result.Clashes.push_back(g);
        }
        continue;
      }
      const vtkIdType low = std::min(rf, rg), high = std::max(rf, rg);
      parent[static_cast<std::size_t>(high)] = static_cast<N>(low);
      parity[static_cast<std::size_t>(high)] = pf ^ pg ^ same;
      clashing[static_cast<std::size_t>(low)] |= clashing[static_cast<std::size_t>(high)];
      if (high == rf) // f's root joined g's: f's parity to it through the old root
      {
        pf = static_cast<unsigned char>(pg ^ same);
        rf = low;
      }
    }
  }
  // Non-manifold traversal: components that meet only at non-manifold edges join, each pair
  // made to run along the edge in opposite directions where it joins two components; a pair
  // within one component is passed over (there is no right pairing around such an edge).
  if (nonManifold)
  {
    for (const NonManifoldPair& pair : *nonManifold)
    {
      unsigned char pf, pg;
      const vtkIdType rf = find(pair.First, pf);
      const vtkIdType rg = find(pair.Other, pg);
      if (rf != rg)
      {
        const vtkIdType low = std::min(rf, rg), high = std::max(rf, rg);
        parent[static_cast<std::size_t>(high)] = static_cast<N>(low);
        parity[static_cast<std::size_t>(high)] =
          static_cast<unsigned char>(pf ^ pg ^ static_cast<unsigned char>(pair.Same));
        clashing[static_cast<std::size_t>(low)] |= clashing[static_cast<std::size_t>(high)];
      }
    }
  }
  // The neighbours have served (moved in, they go here): their memory is handed back before
  // the answers per polygon take theirs.
  std::vector<N>().swap(neighbours);
  result.Reverse.resize(static_cast<std::size_t>(numPolys));
  if (components)
  {
    result.Component.resize(static_cast<std::size_t>(numPolys));
  }
  for (vtkIdType f = 0; f < numPolys; ++f)
  {
    unsigned char toRoot;
    const vtkIdType root = find(f, toRoot);
    result.Reverse[static_cast<std::size_t>(f)] = toRoot;
    result.Reversed += toRoot;
    if (!components)
    {
      result.NonOrientable += root == f && clashing[static_cast<std::size_t>(f)];
    }
    else if (root == f) // a root comes before every other polygon of its component
    {
      result.Component[static_cast<std::size_t>(f)] =
        static_cast<vtkIdType>(result.ComponentClashes.size());
      result.ComponentClashes.push_back(clashing[static_cast<std::size_t>(f)]);
      result.ComponentFirst.push_back(f);
      result.NonOrientable += clashing[static_cast<std::size_t>(f)];
    }
    else
    {
      result.Component[static_cast<std::size_t>(f)] =
        result.Component[static_cast<std::size_t>(root)];
    }
  }
  std::sort(result.Clashes.begin(), result.Clashes.end());
  result.Clashes.erase(
    std::unique(result.Clashes.begin(), result.Clashes.end()), result.Clashes.end());
  return result;
}

/// The polygons with those marked reversed as (p0, p(n-1), ..., p1) (`polys` itself when none
/// is).
inline vtkSmartPointer<vtkCellArray> ReversedPolygons(
  vtkCellArray* polys, const std::vector<unsigned char>& reverse)
{
  if (std::find(reverse.begin(), reverse.end(), 1) == reverse.end())
  {
    return polys;
  }
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->DeepCopy(polys);
  ForOwnRawCells(out,
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

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKOrientation.h
