/**
 * @file PhongVTKPointRanges.h
 * @brief Private to PhongVTK::Filters: splitting a pass that gathers per point (point normals, the
 * edges under their smaller point id) into ranges of point ids, one task each, without a map
 * from points to cells. Every block of CellBlock cells records the span of point ids it uses;
 * a range's task visits only the blocks whose span reaches into it. On a coherent mesh (ids of a
 * neighbourhood close together, as sources and most readers deliver them) that is the blocks
 * around the range; on an incoherent one the ranges grow until the repeated block visits stay
 * bounded.
 */
#ifndef PhongVTKPointRanges_h
#define PhongVTKPointRanges_h

#include "PhongVTKCells.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkType.h"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// Cells per block of a span.
constexpr vtkIdType CellBlock = 1024;

/// Smallest and largest point id used by a block of cells (empty: First > Last).
struct IdSpan
{
  vtkIdType First;
  vtkIdType Last;

  /// Whether the block uses a point id in [first, first + count).
  bool Reaches(vtkIdType first, vtkIdType count) const
  {
    return this->Last >= first && this->First < first + count;
  }

  /// Whether every point id of the block lies in [first, first + count).
  bool Inside(vtkIdType first, vtkIdType count) const
  {
    return this->First >= first && this->Last < first + count;
  }
};

/**
 * The smallest and the largest of ids[0, n) (n > 0). Eight independent minima and maxima, so that
 * the comparisons of one id do not wait for those of the previous one (the loop then runs at
 * the memory's speed; one running pair took twice as long).
 */
template <class Id>
inline void IdExtent(const Id* ids, std::size_t n, Id& first, Id& last)
{
  constexpr int Lanes = 8;
  Id lo[Lanes], hi[Lanes];
  std::fill(lo, lo + Lanes, ids[0]);
  std::fill(hi, hi + Lanes, ids[0]);
  std::size_t k = 0;
  for (; k + Lanes <= n; k += Lanes)
  {
    for (int j = 0; j < Lanes; ++j)
    {
      lo[j] = ids[k + j] < lo[j] ? ids[k + j] : lo[j];
      hi[j] = ids[k + j] > hi[j] ? ids[k + j] : hi[j];
    }
  }
  for (; k < n; ++k)
  {
    lo[0] = std::min(lo[0], ids[k]);
    hi[0] = std::max(hi[0], ids[k]);
  }
  first = *std::min_element(lo, lo + Lanes);
  last = *std::max_element(hi, hi + Lanes);
}

/// The span of every block of CellBlock cells of `cells` (in parallel).
inline std::vector<IdSpan> BlockSpans(vtkCellArray* cells)
{
  const vtkIdType numCells = cells ? cells->GetNumberOfCells() : 0;
  const vtkIdType numBlocks = (numCells + CellBlock - 1) / CellBlock;
  std::vector<IdSpan> spans(static_cast<std::size_t>(numBlocks));
  if (numCells == 0)
  {
    return spans;
  }
  ForRawCells(cells,
    [&](const auto* offsets, const auto* conn)
    {
      phongvtk::For(0, numBlocks, numCells,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType b = begin; b < end; ++b)
          {
            const auto start = offsets[b * CellBlock];
            const auto stop = offsets[std::min(numCells, (b + 1) * CellBlock)];
            IdSpan& span = spans[static_cast<std::size_t>(b)];
            span = IdSpan{ 0, -1 };
            if (stop > start)
            {
              std::remove_cv_t<std::remove_pointer_t<decltype(conn)>> first, last;
              IdExtent(conn + start, static_cast<std::size_t>(stop - start), first, last);
              span = IdSpan{ first, last };
            }
          }
        });
    });
  return spans;
}

/**
 * Points per range for a pass over `numCells` cells with block spans `spans`: at most `cap` (a
 * range's per-point state stays in cache) and at least four ranges a thread, so that small
 * meshes keep every thread busy too; then grown (times four) until the blocks visited by more
 * than one range (those whose span crosses a range boundary) add at most a quarter to the work.
 * At worst one range per thread: each then visits every block once, in parallel.
 */
inline vtkIdType PointRangeSize(const std::vector<IdSpan>& spans, vtkIdType numCells,
  vtkIdType numPoints, vtkIdType threads, vtkIdType cap)
{
  const vtkIdType widest = std::max<vtkIdType>(1, (numPoints + threads - 1) / threads);
  vtkIdType size = std::max<vtkIdType>(
    1024, std::min<vtkIdType>(cap, (numPoints + 4 * threads - 1) / (4 * threads)));
  size = std::min(size, widest);
  for (; size < widest; size *= 4)
  {
    vtkIdType visits = 0;
    for (const IdSpan& span : spans)
    {
      if (span.First <= span.Last)
      {
        visits += span.Last / size - span.First / size + 1;
      }
    }
    if (visits * CellBlock <= numCells + numCells / 4 + CellBlock)
    {
      return size;
    }
  }
  return widest;
}
PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKPointRanges.h
