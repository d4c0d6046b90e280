/**
 * @file PhongVTKKernels.h
 * @brief The filters' computations, one set per instruction set, and the choice among them.
 *
 * vtkPolygonNormals and vtkVisibleArea check their input and options themselves and hand the
 * computation to a kernel set: PhongVTKPolygonNormalsKernels.cxx and
 * PhongVTKVisibleAreaKernels.cxx, compiled for the baseline instruction set and, on x86-64, again
 * for AVX + FMA by target pragmas (namespace `phongvtk::avx_fma`, PhongVTKKernelNamespace.h).
 * Nothing is compiled for the build machine: a binary built anywhere runs everywhere, and uses AVX
 * and FMA where the processor has them. Both sets perform the same IEEE operations in the same
 * order (hardware FMA and the C library's fma are the same correctly rounded operation), so their
 * results are the same bits; TestKernelSets checks it by running each.
 *
 * The environment variable PHONGVTK_KERNELS=baseline forces the baseline set, for tests and
 * comparisons; avx_fma is only taken where the processor has AVX and FMA.
 */
#ifndef PhongVTKKernels_h
#define PhongVTKKernels_h

#include "PhongVTKKernelNamespace.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkDataArray;
class vtkDoubleArray;
class vtkPolyData;
class vtkPolygonNormals;
class vtkVisibleArea;

namespace phongvtk
{
/// vtkPolygonNormals' computation (PhongVTKPolygonNormalsKernels.cxx). `coordinates` is the
/// points' float or double array as the kernels read it (KernelCoordinates).
struct PolygonNormalsKernels
{
  /// Progress: splitting reports [0, SplitShare), the normals of the split mesh the rest.
  static constexpr double SplitShare = 0.3;

  /// Consistency, AutoOrientNormals, FlipNormals (`orient`) and Splitting (`split`) of `input`:
  /// the polygons reordered, then split at their sharp edges. Null when a cell refers to a point
  /// that does not exist (firstBadCell names it).
  vtkSmartPointer<vtkPolyData> (*OrientAndSplit)(vtkPolygonNormals* self, vtkPolyData* input,
    vtkDataArray* coordinates, bool orient, bool split, std::vector<vtkIdType>& clashes,
    vtkIdType& nonOrientable, vtkIdType& firstBadCell);
  /// The normals, area vectors, areas and status of `input`, added to `output`. False when a
  /// cell refers to a point that does not exist (firstBadCell names it).
  bool (*Normals)(vtkPolygonNormals* self, vtkPolyData* input, vtkPolyData* output,
    vtkDataArray* coordinates, bool doubleOutput, double progressStart, vtkIdType& nonFinite,
    vtkIdType& firstBadCell);
};

/// vtkVisibleArea's computation (PhongVTKVisibleAreaKernels.cxx).
struct VisibleAreaKernels
{
  /// Every cell's visible area into `areas` (seen from the eye point `view` when `eye`, else
  /// from the direction `view`, finite and non-zero), and with ComputeMaxVisibleArea the net
  /// area vector sumW (double-double hi, lo per component) * 2^(2 sumScale). False when a cell
  /// refers to a point that does not exist (firstBadCell names it).
  bool (*VisibleAreas)(vtkVisibleArea* self, vtkPolyData* input, vtkDataArray* coordinates,
    const double view[3], bool eye, const double* inputAreaVectors, vtkDoubleArray* areas,
    vtkIdType& nonFinite, vtkIdType& firstBadCell, double sumW[3][2], int& sumScale);
  /// The sum of the areas (double-double hi, lo), the cells whose ghost flag (when `ghosts` is
  /// given) marks a duplicate counted as zero: the same bits for any number of threads.
  void (*Total)(
    const double* areas, const unsigned char* ghosts, vtkIdType numCells, double total[2]);
};

/// Each set's entry points, defined by the kernel files (PHONGVTK_KERNEL_TABLE).
extern const PolygonNormalsKernels PolygonNormalsBaseline;
extern const VisibleAreaKernels VisibleAreaBaseline;
#if defined(PHONGVTK_HAVE_AVX_FMA_KERNELS)
extern const PolygonNormalsKernels PolygonNormalsAvxFma;
extern const VisibleAreaKernels VisibleAreaAvxFma;
#endif

/// Whether this build holds the AVX + FMA set (x86-64 with GCC or Clang and the CMake option
/// PHONGVTK_AVX_FMA_KERNELS on).
bool AvxFmaKernelsBuilt();

/// Whether the next filter run takes the AVX + FMA set: where the build has it and the
/// processor has AVX and FMA, unless PHONGVTK_KERNELS=baseline. Another value of
/// PHONGVTK_KERNELS than "baseline" or "avx_fma" is reported once, as a warning, and ignored.
bool UseAvxFmaKernels();

/// "avx_fma" or "baseline": the set the next filter run takes.
const char* SelectedKernels();

/// The entry points of the set the next filter run takes.
const PolygonNormalsKernels& SelectedPolygonNormalsKernels();
const VisibleAreaKernels& SelectedVisibleAreaKernels();
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKKernels.h
