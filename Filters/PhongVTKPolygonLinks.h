/**
 * @file PhongVTKPolygonLinks.h
 * @brief Private: the polygons around every point (links), each point's in increasing order, for
 * any number of threads.
 *
 * The same layout and accessors as vtkStaticCellLinksTemplate (GetNumberOfCells, GetCells,
 * GetOffset, GetLinksSize), built for what the fan passes need: only the polygons, and each
 * point's polygons in increasing order and the same for any thread count. VTK's own build does
 * not give that cheaply. VTK 9.2 builds serially, or on several threads with one atomic counter a
 * point, and then the order depends on the threads. VTK 9.3 and later always build with atomic
 * counters and then sort every point's list. On one thread that costs three times the serial
 * build: the bunny's links took 1.8 ms with VTK 9.6.2 against 0.6 ms with 9.2's serial build.
 *
 * The build is a counting sort. Serially: count every point's corners, take prefix sums, then
 * place the polygons in polygon order. On several threads the polygons are cut into a few blocks
 * (at most MaxBlocks); each block counts its corners in its own counters, and a polygon's slot
 * at a point is the point's offset plus the corners that earlier blocks and earlier polygons of
 * its block have there. So the links are the serial build's, bit for bit, however the mesh is cut.
 */
#ifndef PhongVTKPolygonLinks_h
#define PhongVTKPolygonLinks_h

#include "PhongVTKCells.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/**
 * The polygons around every point of a cell array, as ids of type Id (unsigned int where every
 * polygon and corner id fits 32 bits, FitsCompactLinks; vtkIdType otherwise).
 */
template <class Id>
class PolygonLinksOf
{
public:
  /// Blocks the polygons are cut into on several threads (each has a counter a point).
  static constexpr vtkIdType MaxBlocks = 8;

  /**
   * The links of `polys` over `numPoints` points (every point id valid). `blocks` is the number
   * of blocks the polygons are cut into: 0 for one a thread when the mesh is large enough
   * (Threads), at most MaxBlocks. Tests force other numbers; the links are the same for all.
   */
  void Build(vtkIdType numPoints, vtkCellArray* polys, vtkIdType blocks = 0)
  {
    const vtkIdType numPolys = polys->GetNumberOfCells();
    this->NumberOfPoints = numPoints;
    this->LinksSize = polys->GetNumberOfConnectivityIds();
    if (blocks <= 0)
    {
      // A block's counters (one a point) may not outgrow the links themselves: a mesh with
      // many unused points is built on fewer blocks.
      blocks =
        std::min<vtkIdType>(Threads(numPolys), this->LinksSize / std::max<vtkIdType>(numPoints, 1));
    }
    blocks =
      std::max<vtkIdType>(1, std::min({ blocks, MaxBlocks, std::max<vtkIdType>(numPolys, 1) }));
    this->Offsets.reset(new Id[static_cast<std::size_t>(numPoints) + 2]);
    this->Links.reset(new Id[static_cast<std::size_t>(this->LinksSize) + 1]);
    ForRawCells(polys,
      [&](const auto* offsets, const auto* conn)
      {
        if (blocks == 1)
        {
          this->Serial(numPolys, offsets, conn);
        }
        else
        {
          this->Blocked(numPolys, blocks, offsets, conn);
        }
      });
  }

  vtkIdType GetNumberOfPoints() const { return this->NumberOfPoints; }
  vtkIdType GetLinksSize() const { return this->LinksSize; }
  vtkIdType GetNumberOfCells(vtkIdType p) const
  {
    return static_cast<vtkIdType>(this->Offsets[p + 1] - this->Offsets[p]);
  }
  const Id* GetCells(vtkIdType p) const { return this->Links.get() + this->Offsets[p]; }
  Id* GetCells(vtkIdType p) { return this->Links.get() + this->Offsets[p]; }
  Id GetOffset(vtkIdType p) const { return this->Offsets[p]; }

private:
  template <class Offsets, class Connectivity>
  void Serial(vtkIdType numPolys, const Offsets* offsets, const Connectivity* conn)
  {
    // The corners at p counted in next[p + 2]; after the prefix sums next[p + 1] is where p's
    // polygons start, and placing them moves it on to where they end: p's offset is then
    // next[p], as Offsets holds it (two more entries than points for this).
    Id* next = this->Offsets.get();
    std::fill(next, next + this->NumberOfPoints + 2, Id(0));
    const auto corners = static_cast<std::size_t>(this->LinksSize);
    for (std::size_t k = 0; k < corners; ++k)
    {
      ++next[static_cast<std::size_t>(conn[k]) + 2];
    }
    for (vtkIdType p = 2; p < this->NumberOfPoints + 2; ++p)
    {
      next[p] += next[p - 1];
    }
    Id* links = this->Links.get();
    for (vtkIdType f = 0; f < numPolys; ++f)
    {
      for (auto k = offsets[f]; k < offsets[f + 1]; ++k)
      {
        links[next[static_cast<std::size_t>(conn[k]) + 1]++] = static_cast<Id>(f);
      }
    }
    links[this->LinksSize] = static_cast<Id>(this->NumberOfPoints);
  }

  template <class Offsets, class Connectivity>
  void Blocked(
    vtkIdType numPolys, vtkIdType blocks, const Offsets* offsets, const Connectivity* conn)
  {
    const auto n = static_cast<std::size_t>(this->NumberOfPoints);
    auto firstOf = [&](vtkIdType b)
    {
      return numPolys / blocks * b + std::min(b, numPolys % blocks);
    };
    // count[b * n + p]: the corners of block b at p; then where block b's polygons at p go.
    std::unique_ptr<Id[]> count(new Id[static_cast<std::size_t>(blocks) * n]);
    vtkSMPTools::For(0, blocks, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType b = begin; b < end; ++b)
        {
          Id* mine = count.get() + static_cast<std::size_t>(b) * n;
          std::fill(mine, mine + n, Id(0));
          for (auto k = offsets[firstOf(b)]; k < offsets[firstOf(b + 1)]; ++k)
          {
            ++mine[static_cast<std::size_t>(conn[k])];
          }
        }
      });
    Id start = 0;
    for (std::size_t p = 0; p < n; ++p)
    {
      this->Offsets[p] = start;
      for (vtkIdType b = 0; b < blocks; ++b)
      {
        Id& c = count[static_cast<std::size_t>(b) * n + p];
        const Id corners = c;
        c = start;
        start += corners;
      }
    }
    this->Offsets[n] = start;
    this->Offsets[n + 1] = start; // as the serial build leaves it
    Id* links = this->Links.get();
    vtkSMPTools::For(0, blocks, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType b = begin; b < end; ++b)
        {
          Id* next = count.get() + static_cast<std::size_t>(b) * n;
          for (vtkIdType f = firstOf(b); f < firstOf(b + 1); ++f)
          {
            for (auto k = offsets[f]; k < offsets[f + 1]; ++k)
            {
              links[next[static_cast<std::size_t>(conn[k])]++] = static_cast<Id>(f);
            }
          }
        }
      });
    links[this->LinksSize] = static_cast<Id>(this->NumberOfPoints);
  }

  vtkIdType NumberOfPoints = 0;
  vtkIdType LinksSize = 0;
  std::unique_ptr<Id[]> Offsets;
  std::unique_ptr<Id[]> Links;
};
PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKPolygonLinks.h
