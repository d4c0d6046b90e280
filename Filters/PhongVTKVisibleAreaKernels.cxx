// vtkVisibleArea's computation after its input checks (PhongVTKKernels.h): every cell's visible
// area and, with ComputeMaxVisibleArea, the net area vector. Compiled once per instruction set;
// everything here lives in phongvtk::PHONGVTK_KERNELS.
#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKEdgeSum.h"
#include "PhongVTKKernels.h"
#include "PhongVTKParallel.h"
#include "PhongVTKVisibleArea.h"

#include "vtkCellArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkVisibleArea.h"

#include <algorithm>
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
namespace
{
using detail::DD;

/// Per-thread bookkeeping of the pass over the cells.
struct CellCounts
{
  vtkIdType NonFinite = 0;
  vtkIdType FirstBadCell = -1; // first cell with a point id outside [0, number of points)

  void BadCell(vtkIdType cell)
  {
    if (this->FirstBadCell < 0 || cell < this->FirstBadCell)
    {
      this->FirstBadCell = cell;
    }
  }
};

/**
 * The pass over the polygons and strips for one accuracy mode and point type: the visible area
 * and the status of every surface cell.
 */
template <Accuracy A, class T>
struct CellPass
{
  vtkVisibleArea* Filter;
  const T* Points;
  vtkIdType NumberOfPoints;
  View TheView;
  const double* InputAreaVectors; // w / 2 per cell, or null: computed from the points
  double* Areas;
  unsigned char* Status;
  vtkSMPThreadLocal<CellCounts>* Counts;

  template <class Off, class Conn>
  void Run(const Off* offsets, const Conn* conn, vtkIdType n, vtkIdType first, bool strips,
    double progressBegin, double progressEnd) const
  {
    const vtkIdType block = phongvtk::ProgressBlock(n);
    for (vtkIdType begin = 0; begin < n && !this->Filter->GetAbortExecute(); begin += block)
    {
      const vtkIdType end = std::min(n, begin + block);
      phongvtk::For(begin, end, n,
        [&](vtkIdType b, vtkIdType e)
        {
          CellCounts& counts = this->Counts->Local();
          // Runs of triangles go four at a time, one per SIMD lane; a triangle outside the
          // common case takes the per-polygon path.
          const bool lanes = !strips && !this->InputAreaVectors;
          for (vtkIdType cell = b; cell < e; ++cell)
          {
            if (lanes && cell + 4 <= e &&
              phongvtk::AreFourValidTriangles(offsets, conn, cell, this->NumberOfPoints))
            {
              const T* corner[3][4];
              phongvtk::TriangleCorners(this->Points, offsets, conn, cell, corner);
              double area[4];
              const int done = phongvtk::VisibleAreas4<A, T>(corner, this->TheView, area);
              for (int j = 0; j < 4; ++j)
              {
                if (done & (1 << j))
                {
                  this->Areas[first + cell + j] = area[j];
                  this->Status[first + cell + j] = phongvtk::StatusOk;
                }
                else
                {
                  this->Polygon(offsets, conn, cell + j, first + cell + j, false, counts);
                }
              }
              cell += 3;
              continue;
            }
            this->Polygon(offsets, conn, cell, first + cell, strips, counts);
          }
        });
      this->Filter->UpdateProgress(progressBegin +
        (progressEnd - progressBegin) * static_cast<double>(end) / static_cast<double>(n));
    }
  }

  /// One polygon or strip by the per-polygon kernels.
  template <class Off, class Conn>
  void Polygon(const Off* offsets, const Conn* conn, vtkIdType cell, vtkIdType out, bool strips,
    CellCounts& counts) const
  {
    const Conn* ids = conn + offsets[cell];
    const std::int64_t m = offsets[cell + 1] - offsets[cell];
    if (!ValidIds(ids, m, this->NumberOfPoints))
    {
      counts.BadCell(out);
      return;
    }
    const T* pts = this->Points;
    VisibleAreaResult r;
    if (strips)
    {
      r = this->Cell([pts, ids, m](std::int64_t i)
        { return pts + 3 * static_cast<std::int64_t>(ids[phongvtk::StripOutlineIndex(i, m)]); },
        m, out);
    }
    else
    {
      r = this->Cell(
        [pts, ids](std::int64_t i) { return pts + 3 * static_cast<std::int64_t>(ids[i]); }, m, out);
    }
    this->Areas[out] = r.Area;
    this->Status[out] = r.Status;
    counts.NonFinite += (r.Status == phongvtk::StatusNonFinite);
  }

  template <class VertexFn>
  VisibleAreaResult Cell(const VertexFn& vertex, std::int64_t n, vtkIdType out) const
  {
    if (!this->InputAreaVectors)
    {
      return phongvtk::ComputeVisibleArea<A, T>(vertex, n, this->TheView);
    }
    const double* h = this->InputAreaVectors + 3 * out;
    if (!(std::isfinite(h[0]) && std::isfinite(h[1]) && std::isfinite(h[2])))
    {
      return { 0.0, phongvtk::StatusNonFinite };
    }
    if (h[0] == 0.0 && h[1] == 0.0 && h[2] == 0.0)
    {
      return { 0.0, phongvtk::StatusDegenerate };
    }
    return { phongvtk::VisibleAreaOfVector<A, T>(vertex, n, this->TheView, h, 1),
      phongvtk::StatusOk };
  }
};

/// The cell pass in accuracy mode A over the polygons and the strips.
template <Accuracy A, class T>
void RunCells(const CellPass<A, T>& pass, vtkPolyData* input)
{
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const vtkIdType numPolys = input->GetNumberOfPolys();
  const double total = std::max<double>(1.0, static_cast<double>(input->GetNumberOfCells()));
  const double polyShare = 0.8 * static_cast<double>(numPolys) / total;
  if (numPolys > 0)
  {
    ForRawCells(input->GetPolys(),
      [&](const auto* offsets, const auto* conn)
      { pass.Run(offsets, conn, numPolys, firstPoly, false, 0.0, polyShare); });
  }
  const vtkIdType numStrips = input->GetNumberOfStrips();
  if (numStrips > 0)
  {
    ForRawCells(input->GetStrips(),
      [&](const auto* offsets, const auto* conn)
      { pass.Run(offsets, conn, numStrips, firstPoly + numPolys, true, polyShare, 0.8); });
  }
}

template <class T>
void RunCells(CellPass<Accuracy::Double, T> pass, int accuracy, vtkPolyData* input)
{
  // The same members for every mode: copy them into the mode's pass.
  auto as = [&](auto mode)
  {
    constexpr Accuracy M = decltype(mode)::value;
    CellPass<M, T> p{ pass.Filter, pass.Points, pass.NumberOfPoints, pass.TheView,
      pass.InputAreaVectors, pass.Areas, pass.Status, pass.Counts };
    RunCells(p, input);
  };
  switch (accuracy)
  {
    case vtkVisibleArea::FAST:
      as(std::integral_constant<Accuracy, Accuracy::Fast>{});
      break;
    case vtkVisibleArea::COMPENSATED:
      as(std::integral_constant<Accuracy, Accuracy::Compensated>{});
      break;
    case vtkVisibleArea::EXACT:
      as(std::integral_constant<Accuracy, Accuracy::Exact>{});
      break;
    default:
      RunCells(pass, input);
      break;
  }
}

/// Checks the point ids of the vertices and lines (they pass through; their visible area is 0).
void CheckNonSurfaces(vtkPolyData* input, CellCounts& counts)
{
  vtkCellArray* arrays[2] = { input->GetVerts(), input->GetLines() };
  vtkIdType first = 0;
  for (vtkCellArray* cells : arrays)
  {
    const vtkIdType n = cells ? cells->GetNumberOfCells() : 0;
    if (n > 0)
    {
      ForRawCells(cells,
        [&](const auto* offsets, const auto* conn)
        {
          for (vtkIdType cell = 0; cell < n; ++cell)
          {
            if (!ValidIds(conn + offsets[cell], offsets[cell + 1] - offsets[cell],
                  input->GetNumberOfPoints()))
            {
              counts.BadCell(first + cell);
            }
          }
        });
    }
    first += n;
  }
}

/// Everything for one point type. Returns false (and firstBadCell) for out-of-range point ids.
template <class T>
bool Execute(vtkVisibleArea* self, vtkPolyData* input, const T* points, const View& view,
  const double* inputAreaVectors, vtkDoubleArray* areas, vtkIdType& nonFinite,
  vtkIdType& firstBadCell, DD sumW[3], int& sumScale)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  // The pass over the surfaces writes every surface cell's area and status.
  std::vector<unsigned char> status(
    static_cast<std::size_t>(numCells), static_cast<unsigned char>(phongvtk::StatusNotSurface));
  std::fill_n(areas->GetPointer(0), input->GetNumberOfVerts() + input->GetNumberOfLines(), 0.0);
  vtkSMPThreadLocal<CellCounts> counts;
  CheckNonSurfaces(input, counts.Local());
  CellPass<Accuracy::Double, T> pass{ self, points, input->GetNumberOfPoints(), view,
    inputAreaVectors, areas->GetPointer(0), status.data(), &counts };
  RunCells(pass, self->GetAccuracy(), input);
  for (const CellCounts& c : counts)
  {
    nonFinite += c.NonFinite;
    if (c.FirstBadCell >= 0 && (firstBadCell < 0 || c.FirstBadCell < firstBadCell))
    {
      firstBadCell = c.FirstBadCell;
    }
  }
  if (firstBadCell >= 0 || self->GetAbortExecute())
  {
    return firstBadCell < 0;
  }
  if (self->GetComputeMaxVisibleArea())
  {
    const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
    const std::vector<phongvtk::SurfaceCells> surfaces = { { input->GetPolys(), firstPoly, false },
      { input->GetStrips(), firstPoly + input->GetNumberOfPolys(), true } };
    phongvtk::EdgeSum<T> edges(points, input->GetNumberOfPoints());
    const unsigned char* s = status.data();
    // Ghost cells belong to another piece: its own sum counts them.
    const unsigned char* ghosts = CellGhostFlags(input);
    edges.Sum(edges.NetEdges(
                surfaces,
                [s, ghosts](vtkIdType cell)
                {
                  return s[cell] == phongvtk::StatusNonFinite ||
                    (ghosts && (ghosts[cell] & vtkDataSetAttributes::DUPLICATECELL));
                },
                self),
      sumW);
    sumScale = edges.Scale;
  }
  return true;
}

bool VisibleAreasAny(vtkVisibleArea* self, vtkPolyData* input, vtkDataArray* coordinates,
  const double viewVector[3], bool eye, const double* inputAreaVectors, vtkDoubleArray* areas,
  vtkIdType& nonFinite, vtkIdType& firstBadCell, double sumW[3][2], int& sumScale)
{
  View view;
  if (eye)
  {
    view.Eye = true;
    std::copy(viewVector, viewVector + 3, view.Vector);
  }
  else
  {
    detail::SetDirection(view, viewVector);
  }
  DD sum[3] = { { 0.0, 0.0 }, { 0.0, 0.0 }, { 0.0, 0.0 } };
  void* raw = coordinates->GetVoidPointer(0);
  const bool ok = coordinates->GetDataType() == VTK_FLOAT
    ? Execute(self, input, static_cast<const float*>(raw), view, inputAreaVectors, areas, nonFinite,
        firstBadCell, sum, sumScale)
    : Execute(self, input, static_cast<const double*>(raw), view, inputAreaVectors, areas,
        nonFinite, firstBadCell, sum, sumScale);
  for (int c = 0; c < 3; ++c)
  {
    sumW[c][0] = sum[c].Hi;
    sumW[c][1] = sum[c].Lo;
  }
  return ok;
}

void TotalAny(const double* areas, const unsigned char* ghosts, vtkIdType numCells, double total[2])
{
  // Double-double sums of fixed chunks of cells, added in chunk order.
  constexpr vtkIdType chunk = 65536;
  const vtkIdType numChunks = (numCells + chunk - 1) / chunk;
  std::vector<DD> partial(static_cast<std::size_t>(numChunks));
  const double* a = areas;
  std::vector<double> owned;
  if (ghosts)
  {
    owned.assign(a, a + numCells);
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      if (ghosts[c] & vtkDataSetAttributes::DUPLICATECELL)
      {
        owned[static_cast<std::size_t>(c)] = 0.0;
      }
    }
    a = owned.data();
  }
  For(0, numChunks, numCells / 8,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        partial[static_cast<std::size_t>(k)] =
          PositiveSum(a + k * chunk, std::min(chunk, numCells - k * chunk));
      }
    });
  DD sum = { 0.0, 0.0 };
  for (const DD& p : partial)
  {
    sum = detail::Add(sum, p);
  }
  total[0] = sum.Hi;
  total[1] = sum.Lo;
}
} // namespace

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS

extern const VisibleAreaKernels PHONGVTK_KERNEL_TABLE(
  VisibleArea) = { &VisibleAreasAny, &TotalAny };
} // namespace phongvtk
