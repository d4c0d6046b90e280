/**
 * @file PhongVTKCells.h
 * @brief Private helpers shared by the PhongVTK filters for reading a vtkPolyData's raw storage:
 * point coordinates and cell arrays.
 */
#ifndef PhongVTKCells_h
#define PhongVTKCells_h

#include "PhongVTKKernelNamespace.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnsignedCharArray.h"

#include <cstdint>
#include <type_traits>

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

/// vtkCellArray::Visit functor handing the typed offsets and connectivity pointers to `fn`.
struct RawCells
{
  template <class CellStateT, class Fn>
  void operator()(CellStateT& state, Fn&& fn) const
  {
    fn(state.GetOffsets()->GetPointer(0), state.GetConnectivity()->GetPointer(0));
  }
};

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
