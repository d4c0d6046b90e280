/**
 * @file PhongVTKParallel.h
 * @brief Private to PhongVTK::Filters: how much work a vtkSMPTools::For is handed at once.
 *
 * VTK 9.1/9.2's STDThread backend starts and joins a thread pool on every For call, about
 * 0.2 ms on two cores under Python: half of what a whole pass over a 75K-triangle mesh takes
 * (measured: DOUBLE cell normals of the bunny 1.16 ms on two threads, 0.46 ms on one). So a pass
 * runs inline below a size where threads pay off, and progress (one For per block) is reported
 * in few blocks. Neither changes a result: every output is the same for any split.
 */
#ifndef PhongVTKParallel_h
#define PhongVTKParallel_h

#include "PhongVTKKernelNamespace.h"
#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// Work (in polygon-sized items) below which a pass runs on the calling thread.
constexpr vtkIdType SerialWork = 131072;

/**
 * What the walk around one point's fan (Consistency, Splitting) costs in polygon-sized items per
 * polygon: a bunny's fans took 9-16 ms on one thread against 0.46 ms for its cell normals
 * (about 30 times), so a fan pass pays for threads on meshes sixteen times smaller.
 */
constexpr vtkIdType FanWork = 16;

/**
 * What one pass of AutoOrientNormals over the polygons (their boxes, or their flux) costs in
 * polygon-sized items per polygon: the bunny's two passes took 2.8 ms on one thread against
 * 0.46 ms for its cell normals (about 3 each). Threaded from meshes four times smaller than a
 * polygon pass, the bunny's orientation with STDThread x2 went 2.7-4.8 -> 1.5-2.5 ms.
 */
constexpr vtkIdType FluxWork = 4;

/**
 * Polygons per progress block of a pass over n: a quarter of them (at least 65536), so that a
 * long run reports progress and honours an abort three times along the way while paying the
 * backend's per-call cost only four times.
 */
inline vtkIdType ProgressBlock(vtkIdType n)
{
  return std::max<vtkIdType>(65536, (n + 3) / 4);
}

/// The threads a pass of `work` polygon-sized units runs on.
inline vtkIdType Threads(vtkIdType work)
{
  return work < SerialWork ? 1 : std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
}

/**
 * The grain for vtkSMPTools::For over `items` items that together cost `work` polygon-sized
 * units: all of them at once (the backend then runs them inline) when `work` is below
 * SerialWork or only one thread is available, else `parallelGrain` (0: the backend's choice).
 */
inline vtkIdType Grain(vtkIdType items, vtkIdType work, vtkIdType parallelGrain = 0)
{
  if (Threads(work) == 1)
  {
    return std::max<vtkIdType>(items, 1);
  }
  return parallelGrain;
}

/// vtkSMPTools::For(begin, end, f) with the grain of Grain(end - begin, work, parallelGrain).
template <class F>
void For(vtkIdType begin, vtkIdType end, vtkIdType work, F&& f, vtkIdType parallelGrain = 0)
{
  const vtkIdType grain = Grain(end - begin, work, parallelGrain);
  if (grain > 0)
  {
    vtkSMPTools::For(begin, end, grain, f);
  }
  else
  {
    vtkSMPTools::For(begin, end, f);
  }
}
PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKParallel.h
