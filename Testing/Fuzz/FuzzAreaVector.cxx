/**
 * libFuzzer target: the area-vector kernels of every accuracy mode on one polygon decoded from
 * the input, differential against exact GMP arithmetic (PhongVTKDocumentedBounds.h, the oracle of
 * TestAreaVectorKernels.cxx). A violated promise aborts with the polygon in hexadecimal:
 * - finite input: each mode within its documented bound; EXACT faithful (each normal component
 *   one of the two doubles next to the exact value) and zero with status Degenerate exactly when
 *   the exact area vector is zero; never a NaN or an infinity;
 * - non-finite input: status NonFinite and a zero result;
 * - triangles: the four-lane kernel, with the triangle in the lane the input names, bitwise equal
 *   to the per-polygon kernel whenever it completes the lane.
 *
 * Input: one byte of encoding, the vertex count, a shared exponent and offset, then coordinates,
 * each either raw bits (any double or float: NaN, infinities, subnormals) or a small integer
 * times the shared power of two plus the offset (collinear, repeated, needle-like and
 * far-from-the-origin polygons that random bits almost never give).
 */
#include "PhongVTKDocumentedBounds.h"

#include PHONGVTK_FUZZED_DATA_PROVIDER // <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace
{
int ReportFd = 2; // stderr as it was before libFuzzer's -close_fd_mask

using phongvtk::Accuracy;
using phongvtk::AreaVector;
using phongvtk_test::Polygon;

constexpr Accuracy Modes[] = { Accuracy::Fast, Accuracy::Double, Accuracy::Compensated,
  Accuracy::Exact };

template <class T>
[[noreturn]] void Violation(Accuracy mode, const Polygon<T>& polygon, const std::string& why)
{
  dprintf(ReportFd, "FuzzAreaVector: %s (%s) on a %s polygon with %zu vertices:\n", why.c_str(),
    phongvtk_test::ModeName(mode), sizeof(T) == 4 ? "float" : "double", polygon.size());
  for (const auto& p : polygon)
  {
    dprintf(ReportFd, "  (%a, %a, %a)\n", static_cast<double>(p[0]), static_cast<double>(p[1]),
      static_cast<double>(p[2]));
  }
  std::abort();
}

template <class T>
T RawBits(FuzzedDataProvider& in)
{
  using Bits = typename std::conditional<sizeof(T) == 8, std::uint64_t, std::uint32_t>::type;
  const Bits bits = in.ConsumeIntegral<Bits>();
  T x;
  std::memcpy(&x, &bits, sizeof(x));
  return x;
}

template <class T>
void Check(const Polygon<T>& polygon, int lane)
{
  bool finite = true;
  for (const auto& p : polygon)
  {
    finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  }
  const phongvtk_test::Truth truth =
    finite ? phongvtk_test::MakeTruth(polygon) : phongvtk_test::Truth();
  for (Accuracy mode : Modes)
  {
    std::string laneMismatch;
    const AreaVector r = phongvtk_test::Compute(mode, polygon, lane, laneMismatch);
    if (!laneMismatch.empty())
    {
      Violation(mode, polygon, laneMismatch);
    }
    if (!finite)
    {
      const bool zero = r.Normal[0] == 0 && r.Normal[1] == 0 && r.Normal[2] == 0 &&
        r.Vector[0] == 0 && r.Vector[1] == 0 && r.Vector[2] == 0 && r.Length == 0;
      if (r.Status != phongvtk::StatusNonFinite || !zero)
      {
        Violation(mode, polygon, "non-finite input without status NonFinite and a zero result");
      }
      continue;
    }
    const std::string why =
      phongvtk_test::BoundViolation(mode, phongvtk_test::Measure(mode, r, truth));
    if (!why.empty())
    {
      Violation(mode, polygon, why);
    }
  }
}

template <class T>
Polygon<T> Decode(FuzzedDataProvider& in, bool raw)
{
  const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(3, 40);
  const int maxExponent = sizeof(T) == 8 ? 1023 : 127;
  const int minExponent = sizeof(T) == 8 ? -1074 : -149;
  const int exponent = in.ConsumeIntegralInRange<int>(minExponent, maxExponent);
  const bool offset = in.ConsumeBool();
  const double shift[3] = { offset ? std::ldexp(in.ConsumeIntegral<std::int8_t>(), maxExponent / 2)
                                   : 0.0,
    offset ? std::ldexp(in.ConsumeIntegral<std::int8_t>(), in.ConsumeIntegralInRange<int>(-60, 60))
           : 0.0,
    offset ? in.ConsumeIntegral<std::int16_t>() : 0.0 };
  Polygon<T> polygon(n);
  for (auto& p : polygon)
  {
    for (int c = 0; c < 3; ++c)
    {
      p[c] = raw
        ? RawBits<T>(in)
        : static_cast<T>(std::ldexp(in.ConsumeIntegral<std::int8_t>(), exponent) + shift[c]);
    }
  }
  return polygon;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  ReportFd = dup(2);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  const int encoding = in.ConsumeIntegralInRange<int>(0, 3);
  const int lane = in.ConsumeIntegralInRange<int>(0, 3);
  if (encoding < 2)
  {
    Check(Decode<double>(in, encoding == 0), lane);
  }
  else
  {
    Check(Decode<float>(in, encoding == 2), lane);
  }
  return 0;
}
