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
#include "PhongVTKEdgeNeighbours.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

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

/**
 * Consistent ordering of `numPolys` polygons whose edge slots (`offsets[f]` to `offsets[f + 1]`)
 * hold their `neighbours` (EdgeNeighbours): which to reverse so that every manifold edge is run
 * along in opposite directions, each component keeping the order of its first polygon; a
 * component where that is impossible is counted and the polygons of every pair left disagreeing
 * are listed.
 */
template <class Offsets>
Orientation ConsistentOrientation(
  vtkIdType numPolys, const Offsets* offsets, const std::vector<vtkIdType>& neighbours)
{
  Orientation result;
  result.Reverse.assign(static_cast<std::size_t>(numPolys), 0);
  std::vector<unsigned char> visited(static_cast<std::size_t>(numPolys), 0);
  std::vector<vtkIdType> wave;
  wave.reserve(static_cast<std::size_t>(numPolys));
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
      for (auto k = static_cast<vtkIdType>(offsets[f]); k < static_cast<vtkIdType>(offsets[f + 1]);
           ++k)
      {
        const vtkIdType n = neighbours[static_cast<std::size_t>(k)];
        if (n < 0)
        {
          continue;
        }
        const vtkIdType polygon = n >> 1;
        const auto g = static_cast<std::size_t>(polygon);
        // Same direction: exactly one of the two must be reversed.
        const unsigned char wanted = reverseF ^ static_cast<unsigned char>(n & 1);
        if (!visited[g])
        {
          visited[g] = 1;
          result.Reverse[g] = wanted;
          wave.push_back(polygon);
        }
        else if (result.Reverse[g] != wanted && f < polygon)
        {
          clash = true;
          result.Clashes.push_back(f);
          result.Clashes.push_back(polygon);
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
