/**
 * @file PhongVTKOptions.h
 * @brief Part of PhongVTK::Filters' public headers: setters of enumerated options that reject an
 * unknown value with an error instead of clamping it silently to a neighbouring mode (the
 * filters' and the ParaView plugin's representation's).
 */
#ifndef PhongVTKOptions_h
#define PhongVTKOptions_h

#include "vtkObject.h"
#include "vtkSetGet.h"

#include <cstddef>
#include <sstream>

namespace phongvtk
{
/// The accuracy modes of both filters by value (vtkPolygonNormals::AccuracyModes).
constexpr const char* const AccuracyNames[] = { "FAST", "DOUBLE", "COMPENSATED", "EXACT" };

/**
 * Sets `member` to `value` when it names one of the option's values (`names[value]`, values
 * 0 .. N-1) and says whether it changed; otherwise reports an error that names the option, the
 * value and the values accepted, and keeps the current one.
 */
template <std::size_t N>
bool SetEnumeratedOption(
  vtkObject* self, const char* option, int& member, int value, const char* const (&names)[N])
{
  if (value < 0 || value >= static_cast<int>(N))
  {
    std::ostringstream accepted;
    for (std::size_t i = 0; i < N; ++i)
    {
      accepted << (i == 0 ? "" : (i + 1 == N ? " or " : ", ")) << names[i] << " (" << i << ")";
    }
    vtkErrorWithObjectMacro(self,
      "Unknown " << option << " " << value << ": expected " << accepted.str() << "; keeping "
                 << names[member] << ".");
    return false;
  }
  if (value == member)
  {
    return false;
  }
  member = value;
  return true;
}
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKOptions.h
