// The choice of the kernel set (PhongVTKKernels.h). Compiled for the baseline instruction set.
#include "PhongVTKKernels.h"

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
  // registers.
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
}

bool UseAvxFmaKernels()
{
  // Read on every run, so that a test can force each set in one process.
  const char* forced = std::getenv("PHONGVTK_KERNELS");
  return ProcessorHasAvxFma() && !(forced && std::strcmp(forced, "baseline") == 0);
}
} // namespace phongvtk
