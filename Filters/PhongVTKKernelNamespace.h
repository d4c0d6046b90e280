/**
 * @file PhongVTKKernelNamespace.h
 * @brief The namespace of the kernels' code: one per instruction set they are compiled for.
 *
 * On x86-64 the filters' computations are compiled twice, for the baseline instruction set and for
 * AVX + FMA, and chosen when a filter runs (PhongVTKKernels.h). Everything the private headers
 * define lives in the inline namespace `phongvtk::PHONGVTK_KERNELS`, named after the instruction
 * set of the translation unit that includes them: the two compilations of an inline function are
 * then two functions, and the linker cannot hand the AVX copy to a baseline caller (which would
 * die with SIGILL on a processor without AVX).
 */
#ifndef PhongVTKKernelNamespace_h
#define PhongVTKKernelNamespace_h

// The kernels' floating-point contract: every product and sum rounded as written. The error-free
// transformations, the documented error bounds and the bitwise agreement of the scalar and 4-lane
// paths and of the two kernel sets depend on it. GCC and Clang contract a * b + c into an FMA by
// default, GCC after inlining, where no pragma in a header reaches: a translation unit that
// includes the kernels is compiled with -ffp-contract=off, and PHONGVTK_FP_CONTRACT_OFF is the
// build's word that it is (phongvtk_kernel_options in CMakeLists.txt).
#if (defined(__GNUC__) || defined(__clang__)) && !defined(PHONGVTK_FP_CONTRACT_OFF)
#error "PhongVTK's kernels need -ffp-contract=off (with -DPHONGVTK_FP_CONTRACT_OFF)"
#endif

// The AVX + FMA set is compiled for its instruction set by target pragmas around the kernels'
// own code (PHONGVTK_KERNEL_TARGET_BEGIN / END, inside the namespace), not by -mavx -mfma on
// the translation unit: the standard library's and VTK's inline functions and templates it
// instantiates stay baseline code, so that no copy of theirs the linker may keep for the whole
// library holds AVX instructions (the test KernelIsolation checks the built library). AVX, not
// AVX2: nothing here uses AVX2's integer instructions, and GCC's AVX2 code for FAST and DOUBLE
// was measured 4-8 % slower on the bunny.
// PHONGVTK_HAVE_AVX_FMA: the code being compiled may use AVX and FMA instructions.
// PHONGVTK_KERNEL_TABLE(X): the name of this set's table of entry points X (PhongVTKKernels.h).
#if defined(PHONGVTK_KERNELS_AVX_FMA)
#define PHONGVTK_KERNELS avx_fma
#define PHONGVTK_KERNEL_TABLE(name) name##AvxFma
#define PHONGVTK_HAVE_AVX_FMA 1
#if defined(__clang__)
#define PHONGVTK_KERNEL_TARGET_BEGIN                                                               \
  _Pragma("clang attribute push(__attribute__((target(\"avx,fma\"))), apply_to = function)")
#define PHONGVTK_KERNEL_TARGET_END _Pragma("clang attribute pop")
#else
#define PHONGVTK_KERNEL_TARGET_BEGIN _Pragma("GCC push_options") _Pragma("GCC target(\"avx,fma\")")
#define PHONGVTK_KERNEL_TARGET_END _Pragma("GCC pop_options")
#endif
#else
#define PHONGVTK_KERNELS baseline
#define PHONGVTK_KERNEL_TABLE(name) name##Baseline
#if defined(__AVX__) && defined(__FMA__)
#define PHONGVTK_HAVE_AVX_FMA 1 // a build for a processor that has them (-march=native)
#endif
#define PHONGVTK_KERNEL_TARGET_BEGIN
#define PHONGVTK_KERNEL_TARGET_END
#endif

#endif
// VTK-HeaderTest-Exclude: PhongVTKKernelNamespace.h
