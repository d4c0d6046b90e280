/**
 * @file PhongVTKWellFormedCells.h
 * @brief Private to PhongVTK::Filters: whether a vtkCellArray's offsets describe its cells.
 *
 * vtkCellArray promises offsets[0] = 0, offsets that never decrease, and a last offset equal
 * to the connectivity's length, but nothing enforces it: a reader handed a corrupt file (VTK's
 * legacy reader takes the OFFSETS of a binary file as they are) builds a cell array that breaks
 * it, and a pass that reads cell c's ids from offsets[c] to offsets[c + 1] then reads outside
 * the connectivity (measured: 4 of 154 malformed files through the CLI ended in SIGSEGV inside
 * vtkPolygonNormals before this check). The filters check every cell array they read once,
 * before any pass: one read of the offsets, threaded as a polygon pass.
 */
#ifndef PhongVTKWellFormedCells_h
#define PhongVTKWellFormedCells_h

#include "PhongVTKCells.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"
#include "vtkType.h"

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// What the filters say after "Cell <id>" when FirstMalformedCell finds one.
constexpr const char* MalformedCellReason =
  " has no extent in the input's cell array: its offsets are corrupt (they must start at 0, "
  "never decrease and end at the connectivity's length); the output is empty.";

/**
 * The first cell c of the `numCells` cells whose extent offsets[c] ... offsets[c + 1] does not
 * lie inside [0, size] in order (offsets[0] must be 0 and offsets[numCells] = size: a cell
 * array whose first cell starts late or whose last ends early is malformed too, as cell 0 or
 * cell numCells - 1); -1 when every cell's does. The same answer for any thread count.
 */
template <class Offsets>
vtkIdType FirstMalformedCell(const Offsets* offsets, vtkIdType numCells, std::int64_t size)
{
  if (numCells <= 0)
  {
    return -1;
  }
  if (static_cast<std::int64_t>(offsets[0]) != 0)
  {
    return 0;
  }
  std::atomic<vtkIdType> first{ numCells };
  For(0, numCells, numCells,
    [&](vtkIdType begin, vtkIdType end)
    {
      // Branch-free over the range (it vectorises); the cell is looked for only on a failure.
      bool decreasing = false;
      for (vtkIdType c = begin; c < end; ++c)
      {
        decreasing |= offsets[c + 1] < offsets[c];
      }
      if (!decreasing)
      {
        return;
      }
      vtkIdType bad = begin;
      while (offsets[bad + 1] >= offsets[bad])
      {
        ++bad;
      }
      vtkIdType seen = first.load();
      while (bad < seen && !first.compare_exchange_weak(seen, bad))
      {
      }
    });
  if (first.load() < numCells)
  {
    return first.load();
  }
  // Never decreasing from 0: every extent is in order, and inside [0, size] when the last ends
  // at size; else the first cell that ends past size (or the last, when it ends short of it).
  if (static_cast<std::int64_t>(offsets[numCells]) == size)
  {
    return -1;
  }
  const Offsets* past = std::upper_bound(offsets, offsets + numCells + 1, size,
    [](std::int64_t value, Offsets offset) { return value < static_cast<std::int64_t>(offset); });
  return std::min<vtkIdType>(static_cast<vtkIdType>(past - offsets) - 1, numCells - 1);
}

/// FirstMalformedCell of a vtkCellArray (nullptr or empty: -1).
inline vtkIdType FirstMalformedCell(vtkCellArray* cells)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return -1;
  }
  vtkIdType bad = -1;
  ForRawCells(cells,
    [&](const auto* offsets, const auto*)
    {
      bad = FirstMalformedCell(
        offsets, cells->GetNumberOfCells(), cells->GetConnectivityArray()->GetNumberOfValues());
    });
  return bad;
}

/**
 * The first cell (id in the order of vtkPolyData: vertices, lines, polygons, strips) of `mesh`
 * whose extent its cell array's offsets do not give; -1 when every cell array is well formed.
 */
inline vtkIdType FirstMalformedCell(vtkPolyData* mesh)
{
  vtkIdType first = 0;
  for (vtkCellArray* cells :
    { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    const vtkIdType bad = FirstMalformedCell(cells);
    if (bad >= 0)
    {
      return first + bad;
    }
    first += cells ? cells->GetNumberOfCells() : 0;
  }
  return -1;
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
