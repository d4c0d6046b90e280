/**
 * @file PhongVTKPointNormals.h
 * @brief Private: vtkPolygonNormals' point pass. Every point's normal is the normalised sum of its
 * faces' contributions (area vector, unit normal, or a corner-weighted normal), computed in
 * parallel and bitwise the same for any number of threads; piece-invariant, also the same for
 * any order of the cells and any partition of the mesh (PhongVTKPointSums.h).
 */
#ifndef PhongVTKPointNormals_h
#define PhongVTKPointNormals_h

#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"
#include "PhongVTKPointRanges.h"
#include "PhongVTKPointSums.h"
#include "vtkPolygonNormals.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN

/**
 * The edge from v to q scaled by 2^-k so that its largest component lies in [1, 2); returns k,
 * or INT_MIN for a zero edge. Coordinates whose difference overflows are halved first.
 */
template <class T>
inline int ScaledEdge(const T* q, const T* v, double e[3])
{
  int extra = 0;
  for (int c = 0; c < 3; ++c)
  {
    e[c] = static_cast<double>(q[c]) - static_cast<double>(v[c]);
  }
  if (!std::isfinite(phongvtk::detail::MaxAbs3(e)))
  {
    for (int c = 0; c < 3; ++c)
    {
      e[c] = 0.5 * static_cast<double>(q[c]) - 0.5 * static_cast<double>(v[c]);
    }
    extra = 1;
  }
  const double m = phongvtk::detail::MaxAbs3(e);
  if (!(m > 0.0) || !std::isfinite(m))
  {
    return INT_MIN;
  }
  const int k = phongvtk::detail::Exponent2(m);
  for (int c = 0; c < 3; ++c)
  {
    e[c] = phongvtk::detail::Scale2(e[c], -k);
  }
  return k + extra;
}

/// What a pass of the point pass does with a contribution: add it to the cell-order sum, or
/// count it (first pass of the piece-invariant sums) or deposit it (second pass).
enum class SumPass
{
  CellOrder,
  Count,
  Deposit
};

/**
 * The points [First, First + Count) whose normals one task of the point pass computes. A face
 * adds its contribution to the corners inside the range only: to their sums, in cell order, or,
 * piece-invariant, to sums that do not depend on the order (InvariantSums, in two passes).
 */
template <SumPass P>
struct PointRange
{
  vtkIdType First = 0;
  vtkIdType Count = 0;
  ScaledSum* Sums = nullptr;          // in cell order, or
  InvariantSums* Invariant = nullptr; // independent of the order

  PHONGVTK_INLINE bool Contains(vtkIdType id) const
  {
    const auto i = static_cast<std::make_unsigned_t<vtkIdType>>(id - this->First);
    return i < static_cast<std::make_unsigned_t<vtkIdType>>(this->Count);
  }

  PHONGVTK_INLINE void Add(vtkIdType id, const double v[3], int e) const
  {
    const auto i = static_cast<std::int32_t>(id - this->First);
    if constexpr (P == SumPass::CellOrder)
    {
      this->Sums[id - this->First].Add(v, e);
    }
    else if constexpr (P == SumPass::Count)
    {
      this->Invariant->Count(i, v, e);
    }
    else
    {
      this->Invariant->Deposit(i, v, e);
    }
  }

  /// Add() of a face (v0, v1, v2, 0) of exponent 0 whose InvariantSums::TopOf is `top` (used by
  /// the count only).
  PHONGVTK_INLINE void AddFace(vtkIdType id, const detail::V4& v, int top) const
  {
    const auto i = static_cast<std::int32_t>(id - this->First);
    if constexpr (P == SumPass::CellOrder)
    {
      this->Sums[id - this->First].Add(v);
    }
    else if constexpr (P == SumPass::Count)
    {
      this->Invariant->Count(i, top);
    }
    else
    {
      this->Invariant->Deposit(i, v, 0);
    }
  }
};

/**
 * Adds one face's contribution to the point normal sums of its corners in `range`. `vertexId(i)`
 * gives the face's i-th point id; the face is the area vector `r.Vector * 2^r.Exponent` for AREA
 * weighting, the unit normal otherwise. Faces without a normal contribute nothing.
 */
template <class T, class VertexIdFn, class Range>
void ScatterFace(int weighting, const T* pts, const VertexIdFn& vertexId, std::int64_t n,
  const AreaVector& r, const Range& range)
{
  if (r.Status != phongvtk::StatusOk)
  {
    return; // degenerate or flagged: no direction to contribute
  }
  if (weighting == vtkPolygonNormals::AREA || weighting == vtkPolygonNormals::UNIFORM)
  {
    const bool area = weighting == vtkPolygonNormals::AREA;
    const double* face = area ? r.Vector : r.Normal;
    const int exponent = area ? r.Exponent : 0;
    for (std::int64_t i = 0; i < n; ++i)
    {
      if (range.Contains(vertexId(i)))
      {
        range.Add(vertexId(i), face, exponent);
      }
    }
    return;
  }
  // ANGLE and MAX look at each corner: the edges to the previous and the next vertex, each
  // scaled by its own power of two (the angle does not change; Max's weight scales back).
  const double* face = r.Normal;
  for (std::int64_t i = 0; i < n; ++i)
  {
    if (!range.Contains(vertexId(i)))
    {
      continue;
    }
    const T* v = pts + 3 * vertexId(i);
    double a[3], b[3];
    const int ka = ScaledEdge(pts + 3 * vertexId((i + n - 1) % n), v, a);
    const int kb = ScaledEdge(pts + 3 * vertexId((i + 1) % n), v, b);
    if (ka == INT_MIN || kb == INT_MIN)
    {
      continue; // a repeated vertex has no corner
    }
    const double x[3] = { b[1] * a[2] - b[2] * a[1], b[2] * a[0] - b[0] * a[2],
      b[0] * a[1] - b[1] * a[0] };
    if (weighting == vtkPolygonNormals::ANGLE)
    {
      const double sine = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      const double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const double angle = std::atan2(sine, cosine);
      const double weighted[3] = { angle * face[0], angle * face[1], angle * face[2] };
      range.Add(vertexId(i), weighted, 0);
    }
    else
    {
      // (b x a) / (|a|^2 |b|^2) with a = a' 2^ka, b = b' 2^kb is the same of a', b' times
      // 2^-(ka + kb).
      const double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
      const double bb = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
      const double inv = 1.0 / (aa * bb);
      const double weighted[3] = { x[0] * inv, x[1] * inv, x[2] * inv };
      range.Add(vertexId(i), weighted, -(ka + kb));
    }
  }
}

/// The unit normal of a sum (zero for a zero or non-finite sum).
template <class O>
void WriteNormal(const double s[3], O* normal)
{
  double unit[3] = { 0.0, 0.0, 0.0 };
  double length;
  int k;
  if (std::isfinite(s[0]) && std::isfinite(s[1]) && std::isfinite(s[2]))
  {
    phongvtk::detail::NormalizeDouble(s, unit, length, k);
  }
  for (int c = 0; c < 3; ++c)
  {
    normal[c] = static_cast<O>(unit[c]);
  }
}

/**
 * The unit normals of a range's points. Piece-invariant, each point's sum is a function of the
 * set of its contributions alone: the same whatever the order of the cells or their partition
 * among processes.
 */
/**
 * WriteNormal of four consecutive points' sums, bit for bit: the four square roots and
 * divisions at once where the sums lie in NormalizeDouble's unscaled window.
 */
template <class O>
PHONGVTK_INLINE void WriteNormals4(const double s[4][3], O* normals)
{
  using detail::V4;
  V4 v[3];
  for (int c = 0; c < 3; ++c)
  {
    v[c] = V4{ s[0][c], s[1][c], s[2][c], s[3][c] };
  }
  const int window = detail::InWindow(v, detail::DoubleWindow);
  const V4 length = detail::Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  V4 n[3];
  for (int c = 0; c < 3; ++c)
  {
    n[c] = v[c] / length;
  }
  if (window == 15)
  {
    StoreNormals4(normals, n);
    return;
  }
  for (int j = 0; j < 4; ++j)
  {
    if (window & (1 << j))
    {
      for (int c = 0; c < 3; ++c)
      {
        normals[3 * j + c] = static_cast<O>(n[c][j]);
      }
    }
    else
    {
      WriteNormal(s[j], normals + 3 * j);
    }
  }
}

/// The unit normals of the points [first, first + count) from their sums: `sum(i, s)` gives
/// point first + i's sum.
template <class O, class SumFn>
void NormalizeSums(vtkIdType first, vtkIdType count, const SumFn& sum, O* normals)
{
  vtkIdType i = 0;
  for (; i + 4 <= count; i += 4)
  {
    double s[4][3];
    for (int j = 0; j < 4; ++j)
    {
      sum(i + j, s[j]);
    }
    WriteNormals4(s, normals + 3 * (first + i));
  }
  for (; i < count; ++i)
  {
    double s[3];
    sum(i, s);
    WriteNormal(s, normals + 3 * (first + i));
  }
}

/**
 * The point pass for point type T and output type O: `Run<A>(normals)` writes a unit normal (or
 * zero) for every point. The cells' point ids have been checked.
 */
template <class T, class O>
struct PointNormalPass
{
  vtkAlgorithm* Filter; // progress and abort
  vtkCellArray* Polys;
  vtkCellArray* Strips;
  const T* Points;
  vtkIdType NumberOfPoints;
  int Weighting;
  bool PieceInvariant;
  std::vector<IdSpan> Spans = {}; // see ComputeSpans
  bool SpansReady = false;
  double ProgressStart = 0.0; // the pass reports progress start + scale * [0, 1]
  double ProgressScale = 1.0;
  vtkIdType ForcedRangeSize = 0; // points per range for tests (0: RangeSize's choice)

  /// Polygons per block of the point pass.
  static constexpr vtkIdType PolyBlock = CellBlock;

  /**
   * The first polygon (index in the polygon array) with a point id outside [0, number of points),
   * or -1: found from the blocks' id spans, which Run() then uses.
   */
  vtkIdType FirstInvalidPolygon()
  {
    this->ComputeSpans();
    vtkIdType first = -1;
    const vtkIdType numPolys = this->Polys ? this->Polys->GetNumberOfCells() : 0;
    for (std::size_t b = 0; b < this->Spans.size() && first < 0; ++b)
    {
      const IdSpan& span = this->Spans[b];
      if (span.First <= span.Last && (span.First < 0 || span.Last >= this->NumberOfPoints))
      {
        const vtkIdType begin = static_cast<vtkIdType>(b) * PolyBlock;
        const vtkIdType end = std::min(numPolys, begin + PolyBlock);
        ForRawCells(this->Polys,
          [&](const auto* offsets, const auto* conn)
          {
            for (vtkIdType cell = begin; cell < end && first < 0; ++cell)
            {
              if (!ValidIds(
                    conn + offsets[cell], offsets[cell + 1] - offsets[cell], this->NumberOfPoints))
              {
                first = cell;
              }
            }
          });
      }
    }
    return first;
  }

  /**
   * Point normals, in parallel and bitwise the same for any number of threads. The points are
   * split into ranges, one task each; a task visits every block of polygons that uses one of its
   * points, recomputes those faces and adds their contributions to its own points only: in cell
   * order, or, piece-invariant, into sums that do not depend on the order (InvariantSums, which
   * takes the range's faces twice). A point's normal is therefore the same
   * however the points are split (and, piece-invariant, however the cells are ordered or the mesh
   * is partitioned among processes). Blocks record the span of point ids they use, so on a
   * coherent mesh a task visits only the blocks around its range; on an incoherent one the
   * ranges grow until the repeated face work stays bounded.
   */
  template <Accuracy A>
  void Run(O* pointNormals)
  {
    this->ComputeSpans();
    vtkCellArray* polys = this->Polys;
    const vtkIdType numPolys = polys ? polys->GetNumberOfCells() : 0;
    const std::vector<IdSpan>& spans = this->Spans;
    const vtkIdType rangeSize = this->RangeSize(spans, numPolys);
    const vtkIdType numRanges = (this->NumberOfPoints + rangeSize - 1) / rangeSize;
    this->Filter->UpdateProgress(this->ProgressStart + this->ProgressScale * 0.6);

    struct Buffers
    {
      std::vector<ScaledSum> Sums;
      InvariantSums Invariant;
    };
    vtkSMPThreadLocal<Buffers> localBuffers;
    phongvtk::For(
      0, numRanges, numPolys,
      [&](vtkIdType begin, vtkIdType end)
      {
        Buffers& buffers = localBuffers.Local();
        for (vtkIdType r = begin; r < end && !this->Filter->GetAbortExecute(); ++r)
        {
          const vtkIdType first = r * rangeSize;
          const vtkIdType count = std::min(rangeSize, this->NumberOfPoints - first);
          if (this->PieceInvariant)
          {
            // Two passes over the range's faces (InvariantSums).
            buffers.Invariant.Reset(static_cast<std::size_t>(count));
            this->ScatterRange<A>(
              PointRange<SumPass::Count>{ first, count, nullptr, &buffers.Invariant });
            buffers.Invariant.StartDeposits();
            this->ScatterRange<A>(
              PointRange<SumPass::Deposit>{ first, count, nullptr, &buffers.Invariant });
            const InvariantSums& sums = buffers.Invariant;
            NormalizeSums(
              first, count, [&sums](vtkIdType i, double s[3]) { sums.SumOf(i, s); }, pointNormals);
          }
          else
          {
            buffers.Sums.assign(static_cast<std::size_t>(count), ScaledSum());
            this->ScatterRange<A>(
              PointRange<SumPass::CellOrder>{ first, count, buffers.Sums.data(), nullptr });
            const ScaledSum* sums = buffers.Sums.data();
            NormalizeSums(
              first, count,
              [sums](vtkIdType i, double s[3]) { std::copy(sums[i].S, sums[i].S + 3, s); },
              pointNormals);
          }
        }
      },
      1);
  }

  /// Every face that has a corner in the range adds its contributions there.
  template <Accuracy A, class Range>
  void ScatterRange(const Range& range) const
  {
    vtkCellArray* polys = this->Polys;
    const vtkIdType numPolys = polys ? polys->GetNumberOfCells() : 0;
    if (numPolys > 0)
    {
      const std::vector<IdSpan>& spans = this->Spans;
      ForRawCells(polys,
        [&](const auto* offsets, const auto* conn)
        {
          for (std::size_t b = 0; b < spans.size(); ++b)
          {
            if (spans[b].Reaches(range.First, range.Count))
            {
              // A block inside the range needs no test of its corners.
              const vtkIdType begin = static_cast<vtkIdType>(b) * PolyBlock;
              this->ScatterPolygons<A>(offsets, conn, begin, std::min(numPolys, begin + PolyBlock),
                range, spans[b].Inside(range.First, range.Count));
            }
          }
        });
    }
    if (this->Strips && this->Strips->GetNumberOfCells() > 0)
    {
      this->ScatterStrips<A>(this->Strips, range);
    }
  }

  /// The smallest and largest point id of every block of PolyBlock polygons (once).
  void ComputeSpans()
  {
    if (!this->SpansReady)
    {
      this->Spans = BlockSpans(this->Polys);
      this->SpansReady = true;
    }
  }

  /// Points per range (PointRangeSize): invariant sums hold three times the state a point
  /// (exponent and count, grids, two-part sums: about 100 bytes), so their ranges are smaller.
  vtkIdType RangeSize(const std::vector<IdSpan>& spans, vtkIdType numPolys) const
  {
    if (this->ForcedRangeSize > 0)
    {
      return this->ForcedRangeSize;
    }
    return PointRangeSize(spans, numPolys, this->NumberOfPoints, phongvtk::Threads(numPolys),
      this->PieceInvariant ? 4096 : 16384);
  }

  /// Adds the faces of polygons [begin, end) to a range's sums, triangles four at a time.
  template <Accuracy A, class Off, class Conn, class Range>
  void ScatterPolygons(const Off* offsets, const Conn* conn, vtkIdType begin, vtkIdType end,
    const Range& range, bool inside) const
  {
    const T* pts = this->Points;
    const int weighting = this->Weighting;
    for (vtkIdType cell = begin; cell < end;)
    {
      if constexpr (A == Accuracy::Double)
      {
        if (weighting == vtkPolygonNormals::AREA && cell + 4 <= end &&
          AreFourTriangles(offsets, cell))
        {
          // The area vectors are all AREA weighting needs: no normals.
          const T* corner[3][4];
          TriangleCorners(pts, offsets, conn, cell, corner);
          detail::V4 w[3];
          detail::DoubleAreaVectors4<T>(corner, w);
          const int done = detail::InWindow(w, detail::DoubleWindow);
          // InvariantSums::TopOf of the four faces (in the window: normal, non-zero).
          detail::V4i tops = {};
          if constexpr (std::is_same<Range, PointRange<SumPass::Count>>::value)
          {
            tops = detail::Exponent2(detail::MaxAbs4(w));
          }
          for (int j = 0; j < 4; ++j, ++cell)
          {
            const Conn* ids = conn + offsets[cell];
            if (done & (1 << j))
            {
              const detail::V4 face = { w[0][j], w[1][j], w[2][j], 0.0 };
              const int top = static_cast<int>(tops[j]);
              for (int i = 0; i < 3; ++i)
              {
                const vtkIdType id = static_cast<vtkIdType>(ids[i]);
                if (inside || range.Contains(id))
                {
                  range.AddFace(id, face, top);
                }
              }
              continue;
            }
            AreaVector r;
            phongvtk::ComputeAreaVector<A, T>([pts, ids](std::int64_t i)
              { return pts + 3 * static_cast<std::int64_t>(ids[i]); },
              3, r);
            ScatterFace(
              weighting, pts, [ids](std::int64_t i) { return static_cast<vtkIdType>(ids[i]); }, 3,
              r, range);
          }
          continue;
        }
      }
      if (cell + 4 <= end && AreFourTriangles(offsets, cell))
      {
        const T* corner[3][4];
        TriangleCorners(pts, offsets, conn, cell, corner);
        phongvtk::TriangleLanes lanes;
        phongvtk::ComputeTriangles4<A, T>(corner, lanes);
        for (int j = 0; j < 4; ++j, ++cell)
        {
          const Conn* ids = conn + offsets[cell];
          auto vertexId = [ids](std::int64_t i)
          {
            return static_cast<vtkIdType>(ids[i]);
          };
          if (lanes.Done & (1 << j))
          {
            ScatterFace(weighting, pts, vertexId, 3, lanes.Result(j), range);
          }
          else
          {
            AreaVector r;
            phongvtk::ComputeAreaVector<A, T>([pts, ids](std::int64_t i)
              { return pts + 3 * static_cast<std::int64_t>(ids[i]); },
              3, r);
            ScatterFace(weighting, pts, vertexId, 3, r, range);
          }
        }
        continue;
      }
      const Conn* ids = conn + offsets[cell];
      const std::int64_t n = offsets[cell + 1] - offsets[cell];
      AreaVector r;
      phongvtk::ComputeAreaVector<A, T>(
        [pts, ids](std::int64_t i) { return pts + 3 * static_cast<std::int64_t>(ids[i]); }, n, r);
      ScatterFace(
        weighting, pts, [ids](std::int64_t i) { return static_cast<vtkIdType>(ids[i]); }, n, r,
        range);
      ++cell;
    }
  }

  /// A strip contributes triangle by triangle, each with the strip's alternating orientation.
  template <Accuracy A, class Range>
  void ScatterStrips(vtkCellArray* strips, const Range& range) const
  {
    const T* pts = this->Points;
    ForRawCells(strips,
      [&](const auto* offsets, const auto* conn)
      {
        for (vtkIdType cell = 0; cell < strips->GetNumberOfCells(); ++cell)
        {
          const auto* ids = conn + offsets[cell];
          const std::int64_t n = offsets[cell + 1] - offsets[cell];
          for (std::int64_t j = 0; j + 2 < n; ++j)
          {
            const vtkIdType tri[3] = { static_cast<vtkIdType>(ids[j + (j & 1)]),
              static_cast<vtkIdType>(ids[j + 1 - (j & 1)]), static_cast<vtkIdType>(ids[j + 2]) };
            if (!range.Contains(tri[0]) && !range.Contains(tri[1]) && !range.Contains(tri[2]))
            {
              continue;
            }
            AreaVector r;
            phongvtk::ComputeAreaVector<A, T>(
              [pts, &tri](std::int64_t i) { return pts + 3 * tri[i]; }, 3, r);
            ScatterFace(
              this->Weighting, pts, [&tri](std::int64_t i) { return tri[i]; }, 3, r, range);
          }
        }
      });
  }
};

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKPointNormals.h
