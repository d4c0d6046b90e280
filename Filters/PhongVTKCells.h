/**
 * @file PhongVTKCells.h
 * @brief Private helpers shared by the PhongVTK filters for reading a vtkPolyData's raw storage:
 * point coordinates and cell arrays.
 */
#ifndef PhongVTKCells_h
#define PhongVTKCells_h

#include "PhongVTKKernelNamespace.h"
#include "vtkAOSDataArrayTemplate.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <utility>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// Whether the n point ids all lie in [0, numberOfPoints) (a negative id wraps to a huge one).
template <class Connectivity>
inline bool ValidIds(const Connectivity* ids, std::int64_t n, vtkIdType numberOfPoints)
{
  using UnsignedId = std::make_unsigned_t<Connectivity>;
  const auto limit = static_cast<UnsignedId>(numberOfPoints);
  bool valid = true;
  for (std::int64_t k = 0; k < n; ++k)
  {
    valid &= static_cast<UnsignedId>(ids[k]) < limit;
  }
  return valid;
}

/// The coordinates as the kernels read them: the points' own array when float or double (read in
/// place), else a double copy made once.
inline vtkSmartPointer<vtkDataArray> KernelCoordinates(vtkPoints* points)
{
  vtkDataArray* data = points->GetData();
  if (data->GetDataType() == VTK_FLOAT || data->GetDataType() == VTK_DOUBLE)
  {
    return data;
  }
  auto converted = vtkSmartPointer<vtkDoubleArray>::New();
  converted->DeepCopy(data);
  return converted;
}

/// The cell ghost flags of `input` (its vtkGhostType array), or null when it has none.
inline const unsigned char* CellGhostFlags(vtkPolyData* input)
{
  vtkUnsignedCharArray* ghosts = input->GetCellGhostArray();
  if (!ghosts || ghosts->GetNumberOfTuples() != input->GetNumberOfCells() ||
    ghosts->GetNumberOfComponents() != 1)
  {
    return nullptr;
  }
  return ghosts->GetPointer(0);
}

/// Whether `cells` keeps its offsets and point ids in plain 32- or 64-bit arrays of one type,
/// the storage the filters read through raw pointers: always up to VTK 9.5; VTK 9.6 adds
/// fixed-size cells (implicit offsets: vtkFlyingEdges3D's triangles) and arrays of any type.
inline bool IsPlainStorage(vtkCellArray* cells)
{
  using Plain32 = vtkAOSDataArrayTemplate<vtkTypeInt32>;
  using Plain64 = vtkAOSDataArrayTemplate<vtkTypeInt64>;
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  return (vtkArrayDownCast<Plain64>(offsets) && vtkArrayDownCast<Plain64>(connectivity)) ||
    (vtkArrayDownCast<Plain32>(offsets) && vtkArrayDownCast<Plain32>(connectivity));
}

/// `cells` itself when its storage is plain (IsPlainStorage), else a copy in plain 64-bit arrays
/// (a copy of both arrays: VTK's own storage conversion frees the arrays it converts from,
/// which the copy would share with the input).
inline vtkSmartPointer<vtkCellArray> PlainCells(vtkCellArray* cells)
{
  if (!cells || IsPlainStorage(cells))
  {
    return cells;
  }
  auto offsets = vtkSmartPointer<vtkTypeInt64Array>::New();
  auto connectivity = vtkSmartPointer<vtkTypeInt64Array>::New();
  offsets->DeepCopy(cells->GetOffsetsArray());
  connectivity->DeepCopy(cells->GetConnectivityArray());
  auto plain = vtkSmartPointer<vtkCellArray>::New();
  plain->SetData(offsets, connectivity);
  return plain;
}

/// `mesh` itself when all its cell arrays are in plain storage, else a shallow copy whose cell
/// arrays are (PlainCells): what a filter reads its input through.
inline vtkSmartPointer<vtkPolyData> PlainCells(vtkPolyData* mesh)
{
  vtkCellArray* arrays[4] = { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(),
    mesh->GetStrips() };
  if (std::all_of(std::begin(arrays), std::end(arrays),
        [](vtkCellArray* cells) { return !cells || IsPlainStorage(cells); }))
  {
    return mesh;
  }
  auto plain = vtkSmartPointer<vtkPolyData>::New();
  plain->ShallowCopy(mesh);
  plain->SetVerts(PlainCells(arrays[0]));
  plain->SetLines(PlainCells(arrays[1]));
  plain->SetPolys(PlainCells(arrays[2]));
  plain->SetStrips(PlainCells(arrays[3]));
  return plain;
}

/// Calls fn(offsets, connectivity) with the raw pointers of `plain`, a cell array in plain
/// storage; the point ids writable when `Writable`.
template <bool Writable, class Fn>
inline void CallWithRawPointers(vtkCellArray* plain, Fn&& fn)
{
  const auto call = [&](auto* offsets, auto* connectivity)
  {
    using Id = std::remove_pointer_t<decltype(connectivity)>;
    fn(static_cast<const std::remove_pointer_t<decltype(offsets)>*>(offsets),
      static_cast<std::conditional_t<Writable, Id*, const Id*>>(connectivity));
  };
  using Plain32 = vtkAOSDataArrayTemplate<vtkTypeInt32>;
  using Plain64 = vtkAOSDataArrayTemplate<vtkTypeInt64>;
  if (auto* offsets64 = vtkArrayDownCast<Plain64>(plain->GetOffsetsArray()))
  {
    call(offsets64->GetPointer(0),
      vtkArrayDownCast<Plain64>(plain->GetConnectivityArray())->GetPointer(0));
  }
  else
  {
    call(vtkArrayDownCast<Plain32>(plain->GetOffsetsArray())->GetPointer(0),
      vtkArrayDownCast<Plain32>(plain->GetConnectivityArray())->GetPointer(0));
  }
}

/**
 * Calls fn(offsets, connectivity) with const pointers to the raw offsets and point ids of
 * `cells` (32- or 64-bit integers); for storage that is not plain, those of a plain copy.
 */
template <class Fn>
inline void ForRawCells(vtkCellArray* cells, Fn&& fn)
{
  const vtkSmartPointer<vtkCellArray> plain = PlainCells(cells);
  CallWithRawPointers<false>(plain, std::forward<Fn>(fn));
}

/**
 * Calls fn(offsets, connectivity) with the raw offsets (const) and the point ids (to be
 * written) of `cells`, a cell array the filter made and owns, first made plain in place.
 */
template <class Fn>
inline void ForOwnRawCells(vtkCellArray* cells, Fn&& fn)
{
  if (!IsPlainStorage(cells))
  {
    cells->ShallowCopy(PlainCells(cells));
  }
  CallWithRawPointers<true>(cells, std::forward<Fn>(fn));
}

/**
 * Asks the memory for the point ids a kilobyte past cell `cell`'s: the passes read the
 * connectivity once, in order, and with the hardware's prefetcher alone the loads of the ids
 * kept the passes waiting (measured on 2M triangles: a quarter of the point pass's time on one
 * load; point normals 45 -> 38 ms, DOUBLE cell normals 18.4 -> 16.0 ms).
 */
template <class Offsets, class Connectivity>
inline void PrefetchCells(const Offsets* offsets, const Connectivity* connectivity, vtkIdType cell)
{
#if defined(__GNUC__) || defined(__clang__)
  // An address, not a pointer into the array: it may lie past the end.
  __builtin_prefetch(reinterpret_cast<const void*>(
    reinterpret_cast<std::uintptr_t>(connectivity + offsets[cell]) + 1024));
#else
  (void)offsets;
  (void)connectivity;
  (void)cell;
#endif
}

/// Asks the memory for the data at `address` (any address: nothing is read).
inline void PrefetchAddress(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}

/// Asks for a small record `first` ... `last` (both ends: a triangle's ids or a normal, 24
/// bytes, straddle two cache lines one time in three).
inline void PrefetchRecord(const void* first, const void* last)
{
  PrefetchAddress(first);
  PrefetchAddress(last);
}

/// Pointers to the coordinates of the corners of triangles `cell` ... `cell + 3` (and the
/// connectivity further on asked for: PrefetchCells).
template <class T, class Offsets, class Connectivity>
inline void TriangleCorners(const T* points, const Offsets* offsets,
  const Connectivity* connectivity, vtkIdType cell, const T* corner[3][4])
{
  PrefetchCells(offsets, connectivity, cell);
  for (int j = 0; j < 4; ++j)
  {
    const Connectivity* ids = connectivity + offsets[cell + j];
    for (int v = 0; v < 3; ++v)
    {
      corner[v][j] = points + 3 * static_cast<std::int64_t>(ids[v]);
    }
  }
}

/// Whether cells cell ... cell + 3 are triangles.
template <class Offsets>
inline bool AreFourTriangles(const Offsets* offsets, vtkIdType cell)
{
  const Offsets* o = offsets + cell;
  return o[1] - o[0] == 3 && o[2] - o[1] == 3 && o[3] - o[2] == 3 && o[4] - o[3] == 3;
}

/// Whether cells cell ... cell + 3 are triangles whose point ids lie in [0, numberOfPoints).
template <class Offsets, class Connectivity>
inline bool AreFourValidTriangles(const Offsets* offsets, const Connectivity* connectivity,
  vtkIdType cell, vtkIdType numberOfPoints)
{
  return AreFourTriangles(offsets, cell) &&
    ValidIds(connectivity + offsets[cell], 12, numberOfPoints);
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKCells.h
