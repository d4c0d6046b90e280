#include "vtkVisibleArea.h"

#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKEdgeSum.h"
#include "PhongVTKOptions.h"
#include "PhongVTKParallel.h"
#include "PhongVTKVisibleArea.h"
#include "PhongVTKWellFormedCells.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkVisibleArea);
vtkCxxSetObjectMacro(vtkVisibleArea, Camera, vtkCamera);

namespace
{
using phongvtk::Accuracy;
using phongvtk::RawCells;
using phongvtk::ValidIds;
using phongvtk::View;
using phongvtk::VisibleAreaResult;
using phongvtk::detail::DD;

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

vtkSmartPointer<vtkDoubleArray> NewScalar(const char* name, int components, const double* values)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(1);
  for (int c = 0; c < components; ++c)
  {
    a->SetComponent(0, c, values[c]);
  }
  return a;
}
} // namespace

//------------------------------------------------------------------------------
vtkVisibleArea::vtkVisibleArea() = default;

vtkVisibleArea::~vtkVisibleArea()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkVisibleArea::GetAccuracyAsString()
{
  return phongvtk::AccuracyNames[this->Accuracy];
}

//------------------------------------------------------------------------------
void vtkVisibleArea::SetAccuracy(int mode)
{
  if (phongvtk::SetEnumeratedOption(
        this, "accuracy", this->Accuracy, mode, phongvtk::AccuracyNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkVisibleArea::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Camera)
  {
    t = std::max(t, this->Camera->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
namespace
{
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
    input->GetPolys()->Visit(RawCells{},
      [&](const auto* offsets, const auto* conn)
      { pass.Run(offsets, conn, numPolys, firstPoly, false, 0.0, polyShare); });
  }
  const vtkIdType numStrips = input->GetNumberOfStrips();
  if (numStrips > 0)
  {
    input->GetStrips()->Visit(RawCells{},
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
      cells->Visit(RawCells{},
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

/// The input's cell ghost flags (its vtkGhostType array), or null when it has none.
const unsigned char* GhostFlags(vtkPolyData* input)
{
  vtkUnsignedCharArray* ghosts = input->GetCellGhostArray();
  if (!ghosts || ghosts->GetNumberOfTuples() != input->GetNumberOfCells() ||
    ghosts->GetNumberOfComponents() != 1)
  {
    return nullptr;
  }
  return ghosts->GetPointer(0);
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
    const unsigned char* ghosts = GhostFlags(input);
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
} // namespace

//------------------------------------------------------------------------------
int vtkVisibleArea::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    return 0;
  }
  this->TotalVisibleArea = 0.0;
  this->MaxVisibleArea = 0.0;
  std::fill_n(this->MaxVisibleAreaDirection, 3, 0.0);
  output->ShallowCopy(input);

  // The view.
  View view;
  double v[3];
  if (this->Camera)
  {
    if (this->Camera->GetParallelProjection())
    {
      const double* dop = this->Camera->GetDirectionOfProjection();
      for (int c = 0; c < 3; ++c)
      {
        v[c] = -dop[c];
      }
    }
    else
    {
      view.Eye = true;
      this->Camera->GetPosition(v);
    }
  }
  else
  {
    std::copy(this->ViewDirection, this->ViewDirection + 3, v);
  }
  bool usable = std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
  if (usable && view.Eye)
  {
    std::copy(v, v + 3, view.Vector);
  }
  else if (usable)
  {
    usable = phongvtk::detail::SetDirection(view, v);
  }
  if (!usable)
  {
    vtkErrorMacro("The " << (view.Eye ? "camera position" : "view direction") << " (" << v[0]
                         << ", " << v[1] << ", " << v[2]
                         << ") is not a finite non-zero vector; the output is empty.");
    output->Initialize();
    return 1;
  }

  const vtkIdType numCells = input->GetNumberOfCells();
  vtkPoints* points = input->GetPoints();
  if (!points && numCells > 0)
  {
    vtkErrorMacro("Input has " << numCells << " cells but no points.");
    output->Initialize();
    return 1;
  }
  const vtkIdType malformed = phongvtk::FirstMalformedCell(input);
  if (malformed >= 0)
  {
    vtkErrorMacro("Cell " << malformed << phongvtk::MalformedCellReason);
    output->Initialize();
    return 1;
  }

  // The input's area vectors, as doubles.
  vtkSmartPointer<vtkDoubleArray> inputAreaVectors;
  vtkDataArray* given = input->GetCellData()->GetArray("AreaVectors");
  if (this->UseInputAreaVectors && this->Accuracy != EXACT && given &&
    given->GetNumberOfComponents() == 3 && given->GetNumberOfTuples() == numCells)
  {
    inputAreaVectors = vtkDoubleArray::SafeDownCast(given);
    if (!inputAreaVectors)
    {
      inputAreaVectors = vtkSmartPointer<vtkDoubleArray>::New();
      inputAreaVectors->DeepCopy(given);
    }
  }

  auto areas = vtkSmartPointer<vtkDoubleArray>::New();
  areas->SetName("VisibleArea");
  areas->SetNumberOfTuples(numCells);
  vtkIdType nonFinite = 0, firstBadCell = -1;
  DD sumW[3] = { { 0.0, 0.0 }, { 0.0, 0.0 }, { 0.0, 0.0 } };
  int sumScale = 0;
  bool ok = true;
  if (numCells > 0)
  {
    vtkSmartPointer<vtkDataArray> data = phongvtk::KernelCoordinates(points);
    const double* reuse = inputAreaVectors ? inputAreaVectors->GetPointer(0) : nullptr;
    void* raw = data->GetVoidPointer(0);
    ok = data->GetDataType() == VTK_FLOAT
      ? Execute(this, input, static_cast<const float*>(raw), view, reuse, areas, nonFinite,
          firstBadCell, sumW, sumScale)
      : Execute(this, input, static_cast<const double*>(raw), view, reuse, areas, nonFinite,
          firstBadCell, sumW, sumScale);
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
    output->Initialize();
    return 1;
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " cell(s) have non-finite (NaN or Inf) point coordinates or area vectors; "
                       "their visible area is 0.");
  }

  // The front faces' total: double-double sums of fixed chunks of cells, added in chunk order
  // (the same bits for any number of threads).
  constexpr vtkIdType chunk = 65536;
  const vtkIdType numChunks = (numCells + chunk - 1) / chunk;
  std::vector<DD> partial(static_cast<std::size_t>(numChunks));
  const double* a = areas->GetPointer(0);
  // Ghost cells belong to another piece: they count as zero here (so the pieces' totals add up
  // to the whole mesh's) and keep their visible areas in the cell array.
  std::vector<double> owned;
  if (const unsigned char* ghosts = GhostFlags(input))
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
  phongvtk::For(0, numChunks, numCells / 8,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        partial[static_cast<std::size_t>(k)] =
          phongvtk::PositiveSum(a + k * chunk, std::min(chunk, numCells - k * chunk));
      }
    });
  DD total = { 0.0, 0.0 };
  for (const DD& p : partial)
  {
    total = phongvtk::detail::Add(total, p);
  }
  // Every term is positive: a sum that is not finite overflowed the double range (a TwoSum past
  // it gives infinity minus infinity), and the total saturates at its largest value, as
  // MaxVisibleArea does.
  const double sum = total.Hi + total.Lo;
  this->TotalVisibleArea = std::isfinite(sum) ? sum : std::numeric_limits<double>::max();

  vtkCellData* cd = output->GetCellData();
  cd->AddArray(areas);
  vtkFieldData* fd = output->GetFieldData();
  fd->AddArray(NewScalar("TotalVisibleArea", 1, &this->TotalVisibleArea));
  if (this->ComputeMaxVisibleArea)
  {
    double length;
    int exponent;
    if (phongvtk::detail::NormalizeFaithful(sumW, this->MaxVisibleAreaDirection, length, exponent))
    {
      this->MaxVisibleArea = phongvtk::detail::ScaleSaturated(length, exponent + 2 * sumScale - 1);
    }
    fd->AddArray(NewScalar("MaxVisibleAreaDirection", 3, this->MaxVisibleAreaDirection));
    fd->AddArray(NewScalar("MaxVisibleArea", 1, &this->MaxVisibleArea));
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkVisibleArea::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ViewDirection: (" << this->ViewDirection[0] << ", " << this->ViewDirection[1]
     << ", " << this->ViewDirection[2] << ")\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Accuracy: " << this->GetAccuracyAsString() << "\n";
  os << indent << "UseInputAreaVectors: " << (this->UseInputAreaVectors ? "On" : "Off") << "\n";
  os << indent << "ComputeMaxVisibleArea: " << (this->ComputeMaxVisibleArea ? "On" : "Off") << "\n";
  os << indent << "TotalVisibleArea: " << this->TotalVisibleArea << "\n";
  os << indent << "MaxVisibleArea: " << this->MaxVisibleArea << "\n";
}
