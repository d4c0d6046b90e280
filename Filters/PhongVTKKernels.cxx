// The choice of the kernel set (PhongVTKKernels.h). Compiled for the baseline instruction set.
#include "PhongVTKKernels.h"

#include "vtkObject.h" // vtkGenericWarningMacro

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace phongvtk
{
namespace
{
bool ProcessorHasAvxFma()
{
#if defined(PHONGVTK_HAVE_AVX_FMA_KERNELS)
  // GCC's and Clang's run-time check: CPUID, and whether the operating system saves the AVX
  // registers. PHONGVTK_HAVE_AVX_FMA_KERNELS is only defined on x86-64.
  static const bool has = []
  {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") && __builtin_cpu_supports("fma");
  }();
  return has;
#else
  return false;
#endif
}

/// Whether PHONGVTK_KERNELS forces the baseline set. A value other than "baseline" or "avx_fma"
/// (the default choice) is a typo more likely than a wish: it is reported once and ignored.
bool BaselineForced()
{
  const char* forced = std::getenv("PHONGVTK_KERNELS");
  if (!forced || !*forced || std::strcmp(forced, "avx_fma") == 0)
  {
    return false;
  }
  if (std::strcmp(forced, "baseline") == 0)
  {
    return true;
  }
  static std::atomic<bool> reported{ false };
  if (!reported.exchange(true))
  {
    vtkGenericWarningMacro("PHONGVTK_KERNELS=" << forced
                                               << " is neither 'baseline' nor 'avx_fma': ignored"
                                                  " (the kernel set is chosen from the processor)");
  }
  return false;
}
} // namespace

bool AvxFmaKernelsBuilt()
{
#if defined(PHONGVTK_HAVE_AVX_FMA_KERNELS)
  return true;
#else
  return false;
#endif
}

bool UseAvxFmaKernels()
{
  // Read on every run, so that a test can force each set in one process.
  const bool forcedBaseline = BaselineForced();
  return ProcessorHasAvxFma() && !forcedBaseline;
}

const char* SelectedKernels()
{
  return UseAvxFmaKernels() ? "avx_fma" : "baseline";
}

const PolygonNormalsKernels& SelectedPolygonNormalsKernels()
{
#if defined(PHONGVTK_HAVE_AVX_FMA_KERNELS)
  if (UseAvxFmaKernels())
  {
    return PolygonNormalsAvxFma;
  }
#endif
  return PolygonNormalsBaseline;
}

const VisibleAreaKernels& SelectedVisibleAreaKernels()
{
#if defined(PHONGVTK_HAVE_AVX_FMA_KERNELS)
  if (UseAvxFmaKernels())
  {
    return VisibleAreaAvxFma;
  }
#endif
  return VisibleAreaBaseline;
}
} // namespace phongvtk
