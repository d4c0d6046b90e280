/**
 * @file PhongVTKCells.h
 * @brief Private helpers shared by the PhongVTK filters for walking a vtkCellArray's raw storage.
 */
#ifndef PhongVTKCells_h
#define PhongVTKCells_h

#include "vtkType.h"

#include <cstdint>
#include <type_traits>

namespace phongvtk
{
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

/// vtkCellArray::Visit functor handing the typed offsets and connectivity pointers to `fn`.
struct RawCells
{
  template <class CellStateT, class Fn>
  void operator()(CellStateT& state, Fn&& fn) const
  {
    fn(state.GetOffsets()->GetPointer(0), state.GetConnectivity()->GetPointer(0));
  }
};
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKCells.h
