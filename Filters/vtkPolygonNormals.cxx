#include "vtkPolygonNormals.h"

#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKOptions.h"
#include "PhongVTKPointSums.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkPolygonNormals);

namespace
{
using phongvtk::Accuracy;
using phongvtk::AreaVector;
using phongvtk::InvariantSums;
using phongvtk::RawCells;
using phongvtk::ScaledSum;
using phongvtk::ValidIds;

/// Per-thread bookkeeping of a pass over the cells.
struct CellCounts
{
  vtkIdType NonFinite = 0;
  vtkIdType FirstBadCell = -1; // first cell with a point id outside [0, number of points)
};

/// Conversion to the output precision; magnitudes beyond its range saturate at its largest value.
template <class O>
inline O Saturate(double x)
{
  constexpr double top = static_cast<double>(std::numeric_limits<O>::max());
  return static_cast<O>(std::max(-top, std::min(top, x)));
}

/// Where a pass over one of the input's cell arrays writes. Arrays the user did not ask for are
/// null.
template <class O>
struct CellOutputs
{
  O* Normals = nullptr;
  O* AreaVectors = nullptr;
  O* Areas = nullptr;
  unsigned char* Status = nullptr;

  bool Any() const { return this->Normals || this->AreaVectors || this->Areas || this->Status; }
};

template <class O>
inline void WriteCell(const CellOutputs<O>& out, vtkIdType cell, const AreaVector& r)
{
  if (out.Normals)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Normals[3 * cell + c] = static_cast<O>(r.Normal[c]);
    }
  }
  if (out.AreaVectors)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.AreaVectors[3 * cell + c] = Saturate<O>(std::ldexp(r.Vector[c], r.Exponent - 1));
    }
  }
  if (out.Areas)
  {
    out.Areas[cell] = Saturate<O>(std::ldexp(r.Length, r.Exponent - 1));
  }
  if (out.Status)
  {
    out.Status[cell] = r.Status;
  }
}

/// Pointers to the coordinates of the corners of triangles `cell` ... `cell + 3`.
template <class T, class Offsets, class Connectivity>
inline void TriangleCorners(const T* points, const Offsets* offsets,
  const Connectivity* connectivity, vtkIdType cell, const T* corner[3][4])
{
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

/// The unit normals of four cells (component by component, one cell per lane) as 12
/// consecutive values x0 y0 z0 x1 ... z3.
template <class O>
PHONGVTK_INLINE void StoreNormals4(O* out, const phongvtk::detail::V4 n[3])
{
  using Vec =
    std::conditional_t<std::is_same<O, float>::value, phongvtk::detail::V4f, phongvtk::detail::V4>;
  const Vec x = __builtin_convertvector(n[0], Vec);
  const Vec y = __builtin_convertvector(n[1], Vec);
  const Vec z = __builtin_convertvector(n[2], Vec);
  const Vec v[3] = { { x[0], y[0], z[0], x[1] }, { y[1], z[1], x[2], y[2] },
    { z[2], x[3], y[3], z[3] } };
  std::memcpy(out, v, sizeof(v));
}

/**
 * vtkSMPTools functor over a range of one cell array (polygons or strips): validates the point
 * ids, evaluates the area vector kernel and writes the requested outputs.
 */
template <Accuracy A, class T, class O, class Offsets, class Connectivity>
struct AreaVectorWorker
{
  const T* Points;
  vtkIdType NumberOfPoints;
  const Offsets* CellOffsets;
  const Connectivity* CellConnectivity;
  bool Strips;
  vtkIdType FirstOutputCell;
  CellOutputs<O> Out;
  vtkSMPThreadLocal<CellCounts>* Counts;
  bool NormalsOnly; // Out holds only Normals

  /// EXACT completes its pending cells in batches (four faithful normalisations per SIMD
  /// register, their square roots and divisions overlapping). The other modes' normals are cheap
  /// enough that the round trip through a batch costs more than it saves (measured: DOUBLE 24.7
  /// -> 20.0 ms on 2M triangles): their batch holds only the leftovers of one group of triangles.
  static constexpr vtkIdType Batch = A == Accuracy::Exact ? 64 : 4;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    CellCounts& counts = this->Counts->Local();
    AreaVector results[Batch];
    vtkIdType cells[Batch];
    vtkIdType pending = 0;
    for (vtkIdType cell = begin; cell < end;)
    {
      if (!this->Strips && cell + 4 <= end && this->AreFourValidTriangles(cell))
      {
        // Runs of triangles go four at a time, one per SIMD lane; a triangle outside the
        // common case takes the per-polygon path.
        const T* corner[3][4];
        TriangleCorners(this->Points, this->CellOffsets, this->CellConnectivity, cell, corner);
        phongvtk::TriangleLanes lanes;
        phongvtk::ComputeTriangles4<A, T>(corner, lanes);
        if (lanes.Done == 15 && this->NormalsOnly)
        {
          StoreNormals4(this->Out.Normals + 3 * (this->FirstOutputCell + cell), lanes.Normal);
        }
        else
        {
          for (int j = 0; j < 4; ++j)
          {
            if (lanes.Done & (1 << j))
            {
              WriteCell(this->Out, this->FirstOutputCell + cell + j, lanes.Result(j));
            }
            else
            {
              cells[pending] = cell + j;
              this->ComputePolygon(cell + j, counts, results[pending++]);
            }
          }
        }
        cell += 4;
      }
      else
      {
        cells[pending] = cell;
        this->ComputePolygon(cell, counts, results[pending++]);
        ++cell;
      }
      if (pending + 4 > Batch || cell >= end)
      {
        phongvtk::CompleteAreaVectors<A, T>(results, pending);
        for (vtkIdType j = 0; j < pending; ++j)
        {
          counts.NonFinite += (results[j].Status == phongvtk::StatusNonFinite);
          WriteCell(this->Out, this->FirstOutputCell + cells[j], results[j]);
        }
        pending = 0;
      }
    }
  }

  /// Whether cells cell ... cell + 3 are triangles with valid point ids.
  bool AreFourValidTriangles(vtkIdType cell) const
  {
    if (!AreFourTriangles(this->CellOffsets, cell))
    {
      return false;
    }
    return ValidIds(this->CellConnectivity + this->CellOffsets[cell], 12, this->NumberOfPoints);
  }

  /// The area vector of one cell, its normal possibly pending; an out-of-range point id is
  /// recorded and the cell left degenerate.
  void ComputePolygon(vtkIdType cell, CellCounts& counts, AreaVector& r) const
  {
    const Connectivity* ids = this->CellConnectivity + this->CellOffsets[cell];
    const std::int64_t n = this->CellOffsets[cell + 1] - this->CellOffsets[cell];
    const T* pts = this->Points;
    if (!ValidIds(ids, n, this->NumberOfPoints))
    {
      const vtkIdType outCell = this->FirstOutputCell + cell;
      if (counts.FirstBadCell < 0 || outCell < counts.FirstBadCell)
      {
        counts.FirstBadCell = outCell;
      }
      r.SetZero(phongvtk::StatusDegenerate);
    }
    else if (!this->Strips)
    {
      auto vertex = [pts, ids](std::int64_t i)
      {
        return pts + 3 * static_cast<std::int64_t>(ids[i]);
      };
      phongvtk::ComputeAreaVectorDeferred<A, T>(vertex, n, r);
    }
    else
    {
      auto vertex = [pts, ids, n](std::int64_t i)
      {
        return pts + 3 * static_cast<std::int64_t>(ids[phongvtk::StripOutlineIndex(i, n)]);
      };
      phongvtk::ComputeAreaVectorDeferred<A, T>(vertex, n, r);
    }
  }
};

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

/**
 * The points [First, First + Count) whose normals one task of the point pass computes. A face
 * adds its contribution to the corners inside the range only: to their sums, in cell order, or,
 * piece-invariant, to sums that do not depend on the order (InvariantSums).
 */
struct PointRange
{
  vtkIdType First = 0;
  vtkIdType Count = 0;
  ScaledSum* Sums = nullptr;          // in cell order, or
  InvariantSums* Invariant = nullptr; // independent of the order

  bool Contains(vtkIdType id) const
  {
    const auto i = static_cast<std::make_unsigned_t<vtkIdType>>(id - this->First);
    return i < static_cast<std::make_unsigned_t<vtkIdType>>(this->Count);
  }

  void Add(vtkIdType id, const double v[3], int e) const
  {
    if (this->Sums)
    {
      this->Sums[id - this->First].Add(v, e);
      return;
    }
    this->Invariant->Add(static_cast<std::int32_t>(id - this->First), v, e);
  }
};

/**
 * Adds one face's contribution to the point normal sums of its corners in `range`. `vertexId(i)`
 * gives the face's i-th point id; the face is the area vector `r.Vector * 2^r.Exponent` for AREA
 * weighting, the unit normal otherwise. Faces without a normal contribute nothing.
 */
template <class T, class VertexIdFn>
void ScatterFace(int weighting, const T* pts, const VertexIdFn& vertexId, std::int64_t n,
  const AreaVector& r, const PointRange& range)
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
template <class O>
void NormalizeSums(const PointRange& range, O* normals)
{
  if (range.Sums)
  {
    for (vtkIdType i = 0; i < range.Count; ++i)
    {
      WriteNormal(range.Sums[i].S, normals + 3 * (range.First + i));
    }
    return;
  }
  range.Invariant->Finish([&](std::int32_t i, const double sum[3], int)
    { WriteNormal(sum, normals + 3 * (range.First + i)); });
}

/// Smallest and largest point id used by a block of polygons (empty: First > Last).
struct IdSpan
{
  vtkIdType First;
  vtkIdType Last;
};

/**
 * The whole computation for one combination of point type T and output type O. Returns false
 * when a cell refers to a point that does not exist (firstBadCell names it).
 */
template <class T, class O>
class Computation
{
public:
  vtkPolygonNormals* Filter;
  vtkPolyData* Input;
  const T* Points;
  vtkIdType NumberOfPoints;
  int AccuracyMode;
  int Weighting;
  bool PointNormals;
  bool PieceInvariant;
  CellOutputs<O> Out;
  vtkIdType NonFinite = 0;
  vtkIdType FirstBadCell = -1;

  bool Run(O* pointNormals)
  {
    vtkPolyData* input = this->Input;
    const vtkIdType numVerts = input->GetNumberOfVerts();
    const vtkIdType numLines = input->GetNumberOfLines();
    const vtkIdType numPolys = input->GetNumberOfPolys();
    const vtkIdType numStrips = input->GetNumberOfStrips();
    const vtkIdType numCells = numVerts + numLines + numPolys + numStrips;

    // Vertices and lines are not surfaces; their point ids are checked all the same, since the
    // output passes them through.
    vtkSMPThreadLocal<CellCounts> counts;
    this->CheckCells(input->GetVerts(), 0, counts, true);
    this->CheckCells(input->GetLines(), numVerts, counts, true);
    const double share = this->PointNormals ? 0.5 : 1.0;
    if (this->Out.Any() || this->HasNonFinitePoint())
    {
      this->RunSurfaces(input->GetPolys(), numVerts + numLines, false, counts, numCells, share);
      this->RunSurfaces(
        input->GetStrips(), numVerts + numLines + numPolys, true, counts, numCells, share);
    }
    else
    {
      // Point normals only, of finite points: the cell pass has nothing to write or count; the
      // point pass computes the faces it needs.
      this->CheckCells(input->GetPolys(), numVerts + numLines, counts, false);
      this->CheckCells(input->GetStrips(), numVerts + numLines + numPolys, counts, false);
    }
    for (const CellCounts& c : counts)
    {
      this->NonFinite += c.NonFinite;
      if (c.FirstBadCell >= 0 && (this->FirstBadCell < 0 || c.FirstBadCell < this->FirstBadCell))
      {
        this->FirstBadCell = c.FirstBadCell;
      }
    }
    if (this->FirstBadCell >= 0)
    {
      return false;
    }
    if (this->PointNormals && !this->Filter->GetAbortExecute())
    {
      switch (this->AccuracyMode)
      {
        case vtkPolygonNormals::FAST:
          this->ComputePointNormals<Accuracy::Fast>(pointNormals);
          break;
        case vtkPolygonNormals::COMPENSATED:
          this->ComputePointNormals<Accuracy::Compensated>(pointNormals);
          break;
        case vtkPolygonNormals::EXACT:
          this->ComputePointNormals<Accuracy::Exact>(pointNormals);
          break;
        default:
          this->ComputePointNormals<Accuracy::Double>(pointNormals);
          break;
      }
    }
    return true;
  }

private:
  /// Checks the point ids of a cell array (and marks its cells as not surfaces).
  void CheckCells(
    vtkCellArray* cells, vtkIdType first, vtkSMPThreadLocal<CellCounts>& counts, bool notSurfaces)
  {
    const vtkIdType n = cells ? cells->GetNumberOfCells() : 0;
    if (n == 0)
    {
      return;
    }
    AreaVector notSurface;
    notSurface.SetZero(phongvtk::StatusNotSurface);
    cells->Visit(RawCells{},
      [&](const auto* offsets, const auto* conn)
      {
        vtkSMPTools::For(0, n,
          [&](vtkIdType begin, vtkIdType end)
          {
            CellCounts& local = counts.Local();
            for (vtkIdType cell = begin; cell < end; ++cell)
            {
              const bool valid = ValidIds(
                conn + offsets[cell], offsets[cell + 1] - offsets[cell], this->NumberOfPoints);
              if (!valid && (local.FirstBadCell < 0 || first + cell < local.FirstBadCell))
              {
                local.FirstBadCell = first + cell;
              }
              if (notSurfaces)
              {
                WriteCell(this->Out, first + cell, notSurface);
              }
            }
          });
      });
  }

  /// Whether any point coordinate is NaN or infinite.
  bool HasNonFinitePoint() const
  {
    vtkSMPThreadLocal<unsigned char> found(0);
    const T* pts = this->Points;
    vtkSMPTools::For(0, 3 * this->NumberOfPoints,
      [&](vtkIdType begin, vtkIdType end)
      {
        // x - x is 0 for finite x and NaN otherwise; the sum is NaN if any term is.
        T sum = 0;
        for (vtkIdType i = begin; i < end; ++i)
        {
          sum += pts[i] - pts[i];
        }
        found.Local() |= !(sum == 0);
      });
    for (unsigned char f : found)
    {
      if (f)
      {
        return true;
      }
    }
    return false;
  }

  /// Polygons or strips, in blocks so that progress is reported and abort honoured.
  void RunSurfaces(vtkCellArray* cells, vtkIdType firstCell, bool strips,
    vtkSMPThreadLocal<CellCounts>& counts, vtkIdType numCells, double share)
  {
    const vtkIdType n = cells ? cells->GetNumberOfCells() : 0;
    if (n == 0)
    {
      return;
    }
    cells->Visit(RawCells{},
      [&](const auto* offsets, const auto* conn)
      {
        using Off = std::remove_cv_t<std::remove_pointer_t<decltype(offsets)>>;
        using Conn = std::remove_cv_t<std::remove_pointer_t<decltype(conn)>>;
        switch (this->AccuracyMode)
        {
          case vtkPolygonNormals::FAST:
            this->RunBlocks<Accuracy::Fast, Off, Conn>(
              offsets, conn, n, firstCell, strips, counts, numCells, share);
            break;
          case vtkPolygonNormals::COMPENSATED:
            this->RunBlocks<Accuracy::Compensated, Off, Conn>(
              offsets, conn, n, firstCell, strips, counts, numCells, share);
            break;
          case vtkPolygonNormals::EXACT:
            this->RunBlocks<Accuracy::Exact, Off, Conn>(
              offsets, conn, n, firstCell, strips, counts, numCells, share);
            break;
          default:
            this->RunBlocks<Accuracy::Double, Off, Conn>(
              offsets, conn, n, firstCell, strips, counts, numCells, share);
            break;
        }
      });
  }

  template <Accuracy A, class Off, class Conn>
  void RunBlocks(const Off* offsets, const Conn* conn, vtkIdType n, vtkIdType firstCell,
    bool strips, vtkSMPThreadLocal<CellCounts>& counts, vtkIdType numCells, double share)
  {
    AreaVectorWorker<A, T, O, Off, Conn> worker{ this->Points, this->NumberOfPoints, offsets, conn,
      strips, firstCell, this->Out, &counts,
      this->Out.Normals && !this->Out.AreaVectors && !this->Out.Areas && !this->Out.Status };
    const vtkIdType block = std::max<vtkIdType>(65536, (n + 9) / 10);
    for (vtkIdType begin = 0; begin < n && !this->Filter->GetAbortExecute(); begin += block)
    {
      const vtkIdType end = std::min(n, begin + block);
      vtkSMPTools::For(begin, end, worker);
      this->Filter->UpdateProgress(
        share * static_cast<double>(firstCell + end) / static_cast<double>(numCells));
    }
  }

  /// Polygons per block of the point pass.
  static constexpr vtkIdType PolyBlock = 1024;

  /**
   * Point normals, in parallel and bitwise the same for any number of threads. The points are
   * split into ranges, one task each; a task visits every block of polygons that uses one of its
   * points, recomputes those faces and adds their contributions to its own points only: in cell
   * order, or, piece-invariant, in an order set by their values (NormalizeSums). A point's normal
   * is therefore the same however the points are split (and, piece-invariant, however the cells
   * are ordered or the mesh is partitioned among processes), and no per-face buffer makes a
   * round trip through memory. Blocks record
   * the span of point ids they use, so on a coherent mesh a task visits only the blocks around
   * its range; on an incoherent one the ranges grow until the repeated face work stays bounded.
   */
  template <Accuracy A>
  void ComputePointNormals(O* pointNormals)
  {
    vtkCellArray* polys = this->Input->GetPolys();
    const vtkIdType numPolys = polys ? polys->GetNumberOfCells() : 0;
    const vtkIdType numBlocks = (numPolys + PolyBlock - 1) / PolyBlock;
    std::vector<IdSpan> spans(static_cast<std::size_t>(numBlocks));
    if (numPolys > 0)
    {
      polys->Visit(RawCells{},
        [&](const auto* offsets, const auto* conn)
        {
          vtkSMPTools::For(0, numBlocks,
            [&](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType b = begin; b < end; ++b)
              {
                IdSpan span{ this->NumberOfPoints, -1 };
                const auto last = offsets[std::min(numPolys, (b + 1) * PolyBlock)];
                for (auto k = offsets[b * PolyBlock]; k < last; ++k)
                {
                  span.First = std::min<vtkIdType>(span.First, conn[k]);
                  span.Last = std::max<vtkIdType>(span.Last, conn[k]);
                }
                spans[b] = span;
              }
            });
        });
    }
    const vtkIdType rangeSize = this->PointRangeSize(spans, numPolys);
    const vtkIdType numRanges = (this->NumberOfPoints + rangeSize - 1) / rangeSize;
    this->Filter->UpdateProgress(0.6);

    struct Buffers
    {
      std::vector<ScaledSum> Sums;
      InvariantSums Invariant;
    };
    vtkSMPThreadLocal<Buffers> localBuffers;
    vtkCellArray* strips = this->Input->GetStrips();
    vtkSMPTools::For(0, numRanges, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        Buffers& buffers = localBuffers.Local();
        for (vtkIdType r = begin; r < end && !this->Filter->GetAbortExecute(); ++r)
        {
          PointRange range;
          range.First = r * rangeSize;
          range.Count = std::min(rangeSize, this->NumberOfPoints - range.First);
          if (this->PieceInvariant)
          {
            buffers.Invariant.Reset(static_cast<std::size_t>(range.Count));
            range.Invariant = &buffers.Invariant;
          }
          else
          {
            buffers.Sums.assign(static_cast<std::size_t>(range.Count), ScaledSum());
            range.Sums = buffers.Sums.data();
          }
          if (numPolys > 0)
          {
            polys->Visit(RawCells{},
              [&](const auto* offsets, const auto* conn)
              {
                for (vtkIdType b = 0; b < numBlocks; ++b)
                {
                  if (spans[b].Last >= range.First && spans[b].First < range.First + range.Count)
                  {
                    this->ScatterPolygons<A>(
                      offsets, conn, b * PolyBlock, std::min(numPolys, (b + 1) * PolyBlock), range);
                  }
                }
              });
          }
          if (strips && strips->GetNumberOfCells() > 0)
          {
            this->ScatterStrips<A>(strips, range);
          }
          NormalizeSums(range, pointNormals);
        }
      });
  }

  /**
   * Points per range: small enough that a range's sums stay in cache and the ranges keep every
   * thread busy, large enough that the polygons visited by more than one range (those whose
   * span crosses a range boundary) add at most a quarter to the face work. At worst one range
   * per thread: each then computes every face once, in parallel.
   */
  vtkIdType PointRangeSize(const std::vector<IdSpan>& spans, vtkIdType numPolys) const
  {
    const vtkIdType threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
    const vtkIdType widest = std::max<vtkIdType>(1, (this->NumberOfPoints + threads - 1) / threads);
    // At least four ranges a thread, so that small meshes keep both threads busy too.
    vtkIdType size = std::max<vtkIdType>(
      1024, std::min<vtkIdType>(16384, (this->NumberOfPoints + 4 * threads - 1) / (4 * threads)));
    size = std::min(size, widest);
    for (; size < widest; size *= 4)
    {
      vtkIdType visits = 0;
      for (const IdSpan& span : spans)
      {
        if (span.First <= span.Last)
        {
          visits += span.Last / size - span.First / size + 1;
        }
      }
      if (visits * PolyBlock <= numPolys + numPolys / 4 + PolyBlock)
      {
        return size;
      }
    }
    return widest;
  }

  /// Adds the faces of polygons [begin, end) to a range's sums, triangles four at a time.
  template <Accuracy A, class Off, class Conn>
  void ScatterPolygons(
    const Off* offsets, const Conn* conn, vtkIdType begin, vtkIdType end, const PointRange& range)
  {
    const T* pts = this->Points;
    const int weighting = this->Weighting;
    for (vtkIdType cell = begin; cell < end;)
    {
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
  template <Accuracy A>
  void ScatterStrips(vtkCellArray* strips, const PointRange& range)
  {
    const T* pts = this->Points;
    strips->Visit(RawCells{},
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

template <class O>
vtkSmartPointer<vtkDataArray> NewArray(const char* name, int components, vtkIdType tuples)
{
  using ArrayT = std::conditional_t<std::is_same<O, float>::value, vtkFloatArray, vtkDoubleArray>;
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

template <class O>
O* Pointer(vtkDataArray* array)
{
  return array ? static_cast<O*>(array->GetVoidPointer(0)) : nullptr;
}
} // namespace

//------------------------------------------------------------------------------
vtkPolygonNormals::vtkPolygonNormals() = default;
vtkPolygonNormals::~vtkPolygonNormals() = default;

//------------------------------------------------------------------------------
const char* vtkPolygonNormals::GetAccuracyAsString()
{
  return phongvtk::AccuracyNames[this->Accuracy];
}

//------------------------------------------------------------------------------
namespace
{
constexpr const char* const WeightingNames[] = { "AREA", "ANGLE", "UNIFORM", "MAX" };
constexpr const char* const PrecisionNames[] = { "SINGLE_PRECISION", "DOUBLE_PRECISION",
  "DEFAULT_PRECISION" };
}

//------------------------------------------------------------------------------
const char* vtkPolygonNormals::GetPointWeightingAsString()
{
  return WeightingNames[this->PointWeighting];
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetAccuracy(int mode)
{
  if (phongvtk::SetEnumeratedOption(
        this, "accuracy", this->Accuracy, mode, phongvtk::AccuracyNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetPointWeighting(int weighting)
{
  if (phongvtk::SetEnumeratedOption(
        this, "point weighting", this->PointWeighting, weighting, WeightingNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetOutputPrecision(int precision)
{
  if (phongvtk::SetEnumeratedOption(
        this, "output precision", this->OutputPrecision, precision, PrecisionNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
namespace
{
template <class T, class O>
bool Dispatch(vtkPolygonNormals* self, vtkPolyData* input, vtkPolyData* output, const T* points,
  vtkIdType& nonFinite, vtkIdType& firstBadCell)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  Computation<T, O> run;
  run.Filter = self;
  run.Input = input;
  run.Points = points;
  run.NumberOfPoints = numPoints;
  run.AccuracyMode = self->GetAccuracy();
  run.Weighting = self->GetPointWeighting();
  run.PieceInvariant = self->GetPieceInvariant();
  run.PointNormals = self->GetComputePointNormals();

  vtkSmartPointer<vtkDataArray> normals, areaVectors, areas, pointNormals;
  vtkSmartPointer<vtkUnsignedCharArray> status;
  if (self->GetComputeCellNormals())
  {
    normals = NewArray<O>("Normals", 3, numCells);
  }
  if (self->GetComputeAreaVectors())
  {
    areaVectors = NewArray<O>("AreaVectors", 3, numCells);
  }
  if (self->GetComputeAreas())
  {
    areas = NewArray<O>("Areas", 1, numCells);
  }
  if (self->GetComputeNormalStatus())
  {
    status = vtkSmartPointer<vtkUnsignedCharArray>::New();
    status->SetName("NormalStatus");
    status->SetNumberOfTuples(numCells);
  }
  if (run.PointNormals)
  {
    pointNormals = NewArray<O>("Normals", 3, numPoints);
  }
  run.Out.Normals = Pointer<O>(normals);
  run.Out.AreaVectors = Pointer<O>(areaVectors);
  run.Out.Areas = Pointer<O>(areas);
  run.Out.Status = status ? status->GetPointer(0) : nullptr;

  const bool ok = run.Run(Pointer<O>(pointNormals));
  nonFinite = run.NonFinite;
  firstBadCell = run.FirstBadCell;
  if (!ok)
  {
    return false;
  }
  // AddArray + SetActiveNormals rather than SetNormals: SetNormals removes the current active
  // normals, and an input array of another name must pass through.
  vtkCellData* cd = output->GetCellData();
  if (normals)
  {
    cd->AddArray(normals);
    cd->SetActiveNormals(normals->GetName());
  }
  if (areaVectors)
  {
    cd->AddArray(areaVectors);
  }
  if (areas)
  {
    cd->AddArray(areas);
  }
  if (status)
  {
    cd->AddArray(status);
  }
  if (pointNormals)
  {
    output->GetPointData()->AddArray(pointNormals);
    output->GetPointData()->SetActiveNormals(pointNormals->GetName());
  }
  return true;
}
} // namespace

//------------------------------------------------------------------------------
namespace
{
/// Whether the filter asks upstream for one more level of ghost cells than downstream asked for:
/// when it computes point normals of one piece among several (the faces across the piece's
/// boundary belong to the boundary points' normals).
bool WantsExtraGhostLevel(vtkPolygonNormals* self, vtkInformation* outInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  return self->GetComputePointNormals() && self->GetPieceInvariant() &&
    outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) > 1;
}
}

//------------------------------------------------------------------------------
int vtkPolygonNormals::RequestUpdateExtent(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int ghostLevels = outInfo->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS());
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()));
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()));
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(),
    ghostLevels + (WantsExtraGhostLevel(this, outInfo) ? 1 : 0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkPolygonNormals::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    return 0;
  }
  output->ShallowCopy(input);
  vtkPoints* points = input->GetPoints();
  if (!points || input->GetNumberOfCells() == 0)
  {
    if (input->GetNumberOfCells() > 0)
    {
      vtkErrorMacro("Input has " << input->GetNumberOfCells() << " cells but no points.");
      output->Initialize();
    }
    return 1;
  }

  vtkSmartPointer<vtkDataArray> data = phongvtk::KernelCoordinates(points);
  const int pointType = points->GetData()->GetDataType();
  const bool doubleOutput = this->OutputPrecision == DOUBLE_PRECISION ||
    (this->OutputPrecision == DEFAULT_PRECISION && pointType == VTK_DOUBLE);

  vtkIdType nonFinite = 0;
  vtkIdType firstBadCell = -1;
  bool ok;
  void* raw = data->GetVoidPointer(0);
  if (data->GetDataType() == VTK_FLOAT)
  {
    const auto* p = static_cast<const float*>(raw);
    ok = doubleOutput ? Dispatch<float, double>(this, input, output, p, nonFinite, firstBadCell)
                      : Dispatch<float, float>(this, input, output, p, nonFinite, firstBadCell);
  }
  else
  {
    const auto* p = static_cast<const double*>(raw);
    ok = doubleOutput ? Dispatch<double, double>(this, input, output, p, nonFinite, firstBadCell)
                      : Dispatch<double, float>(this, input, output, p, nonFinite, firstBadCell);
  }
  if (!ok)
  {
    vtkErrorMacro("Cell " << firstBadCell << " refers to a point id outside [0, "
                          << input->GetNumberOfPoints() << "); the output is empty.");
    output->Initialize();
    return 1;
  }
  if (this->GetAbortExecute())
  {
    // Stopped part-way: the output arrays hold unwritten values, so nothing is delivered.
    output->Initialize();
    return 1;
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " cell(s) have non-finite (NaN or Inf) point coordinates; they are flagged "
                       "with NormalStatus 2 and get a zero normal.");
  }
  // The ghost cells asked for on downstream's behalf go again; with ghost levels requested
  // downstream the extra (outermost) layer stays, marked as ghosts like the others.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (WantsExtraGhostLevel(this, outInfo) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) == 0 &&
    output->GetCellGhostArray())
  {
    output->RemoveGhostCells();
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Accuracy: " << this->GetAccuracyAsString() << "\n";
  os << indent << "PointWeighting: " << this->GetPointWeightingAsString() << "\n";
  os << indent << "ComputeCellNormals: " << (this->ComputeCellNormals ? "On" : "Off") << "\n";
  os << indent << "ComputePointNormals: " << (this->ComputePointNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeAreaVectors: " << (this->ComputeAreaVectors ? "On" : "Off") << "\n";
  os << indent << "ComputeAreas: " << (this->ComputeAreas ? "On" : "Off") << "\n";
  os << indent << "ComputeNormalStatus: " << (this->ComputeNormalStatus ? "On" : "Off") << "\n";
  os << indent << "PieceInvariant: " << (this->PieceInvariant ? "On" : "Off") << "\n";
  os << indent << "OutputPrecision: " << PrecisionNames[this->OutputPrecision] << "\n";
}
