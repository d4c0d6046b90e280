// vtkPolygonNormals' computation after its input checks (PhongVTKKernels.h): orientation and
// splitting, then the cell and point normals. Compiled once per instruction set; everything here
// lives in phongvtk::PHONGVTK_KERNELS.
#include "PhongVTKAreaVector.h"
#include "PhongVTKAutoOrient.h"
#include "PhongVTKCells.h"
#include "PhongVTKFeatureAngle.h"
#include "PhongVTKKernels.h"
#include "PhongVTKOrientation.h"
#include "PhongVTKParallel.h"
#include "PhongVTKPointNormals.h"
#include "PhongVTKSplitting.h"
#include "PhongVTKWellFormedCells.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygonNormals.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
namespace
{

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
      if (!this->Strips && cell + 4 <= end &&
        phongvtk::AreFourValidTriangles(
          this->CellOffsets, this->CellConnectivity, cell, this->NumberOfPoints))
      {
        // Runs of triangles go four at a time, one per SIMD lane; a triangle outside the
        // common case takes the per-polygon path.
        const T* corner[3][4];
        TriangleCorners(this->Points, this->CellOffsets, this->CellConnectivity, cell, corner);
        phongvtk::TriangleLanes lanes;
        phongvtk::ComputeTriangles4<A, T>(corner, lanes);
        if (lanes.Done == 15 && this->NormalsOnly)
        {
          phongvtk::StoreNormals4(
            this->Out.Normals + 3 * (this->FirstOutputCell + cell), lanes.Normal);
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
  double ProgressStart = 0.0; // progress is reported as start + scale * [0, 1]
  double ProgressScale = 1.0;

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
    phongvtk::PointNormalPass<T, O> pointPass{ this->Filter, input->GetPolys(), input->GetStrips(),
      this->Points, this->NumberOfPoints, this->Weighting, this->PieceInvariant };
    pointPass.ProgressStart = this->ProgressStart;
    pointPass.ProgressScale = this->ProgressScale;
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
      // point pass computes the faces it needs, and the id spans of its blocks check the ids.
      const vtkIdType bad = pointPass.FirstInvalidPolygon();
      if (bad >= 0)
      {
        counts.Local().FirstBadCell = numVerts + numLines + bad;
      }
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
          pointPass.template Run<Accuracy::Fast>(pointNormals);
          break;
        case vtkPolygonNormals::COMPENSATED:
          pointPass.template Run<Accuracy::Compensated>(pointNormals);
          break;
        case vtkPolygonNormals::EXACT:
          pointPass.template Run<Accuracy::Exact>(pointNormals);
          break;
        default:
          pointPass.template Run<Accuracy::Double>(pointNormals);
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
    ForRawCells(cells,
      [&](const auto* offsets, const auto* conn)
      {
        phongvtk::For(0, n, n,
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
    // A value costs about a sixteenth of a polygon.
    phongvtk::For(0, 3 * this->NumberOfPoints, 3 * this->NumberOfPoints / 16,
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
    ForRawCells(cells,
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
    const vtkIdType block = phongvtk::ProgressBlock(n);
    for (vtkIdType begin = 0; begin < n && !this->Filter->GetAbortExecute(); begin += block)
    {
      const vtkIdType end = std::min(n, begin + block);
      vtkSMPTools::For(begin, end, phongvtk::Grain(end - begin, n), worker);
      this->Filter->UpdateProgress(this->ProgressStart +
        this->ProgressScale * share * static_cast<double>(firstCell + end) /
          static_cast<double>(numCells));
    }
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

/// The polygons around every point (PhongVTKEdgeNeighbours.h), built once for Consistency and
/// Splitting (reversing polygons keeps them), and the polygons across every edge, for
/// Consistency.
struct Adjacency
{
  phongvtk::CompactPolygonLinks CompactLinks; // 32-bit ids, where the mesh fits them
  phongvtk::PolygonLinks Links;               // vtkIdType, where it does not
  bool Compact = false;
  bool LinksBuilt = false;
  bool WantNeighbours = false;  // Consistency or AutoOrientNormals
  bool WantComponents = false;  // AutoOrientNormals: the neighbours even where all agree
  bool WantNonManifold = false; // and NonManifoldTraversal: the pairs across non-manifold edges
  std::vector<phongvtk::CompactNeighbour> CompactNeighbours; // with CompactLinks
  std::vector<vtkIdType> Neighbours;                         // with Links
  std::vector<phongvtk::NonManifoldPair> NonManifold;
  bool NeighboursBuilt = false;
  /// Consistency without AutoOrientNormals, and a pass over the fans found every manifold edge's
  /// polygons agreeing and no non-manifold edge that matters: there is nothing to do.
  bool Agreeing = false;

  void BuildLinks(vtkPolyData* mesh)
  {
    if (!this->LinksBuilt)
    {
      this->Compact = phongvtk::FitsCompactLinks(mesh->GetNumberOfPoints(), mesh->GetPolys());
      this->WithLinks([&](auto& links)
        { phongvtk::BuildPolygonLinks(mesh->GetPoints(), mesh->GetPolys(), links); });
      this->LinksBuilt = true;
    }
  }

  /// fn(links), with the links BuildLinks built.
  template <class Fn>
  void WithLinks(Fn&& fn)
  {
    this->WithLinksAndNeighbours([&](auto& links, auto&) { fn(links); });
  }

  /// fn(links, neighbours): the neighbours as wide as the links' ids.
  template <class Fn>
  void WithLinksAndNeighbours(Fn&& fn)
  {
    if (this->Compact)
    {
      fn(this->CompactLinks, this->CompactNeighbours);
    }
    else
    {
      fn(this->Links, this->Neighbours);
    }
  }

  /**
   * What a pass over the fans is to record (EdgeRecords) in `neighbours` (WithLinksAndNeighbours).
   * The neighbours' memory (every slot empty) only for AutoOrientNormals: Consistency first asks
   * whether the polygons agree already (most meshes' do), which spares it; where they do not,
   * BuildNeighbours walks the fans again.
   */
  template <class N>
  phongvtk::EdgeRecordsOf<N> RecordsToFill(vtkPolyData* mesh, std::vector<N>& neighbours)
  {
    phongvtk::EdgeRecordsOf<N> records;
    records.CountNonManifold = this->WantNonManifold;
    if (this->WantComponents)
    {
      neighbours.assign(
        static_cast<std::size_t>(mesh->GetPolys()->GetConnectivityArray()->GetNumberOfValues()),
        phongvtk::NoNeighbour<N>);
      this->NeighboursBuilt = true;
      records.Neighbours = neighbours.data();
      records.NonManifold = this->WantNonManifold ? &this->NonManifold : nullptr;
    }
    return records;
  }

  /// Keeps what the pass over the fans found (RecordsToFill): `disagreeing` edges.
  void Recorded(vtkIdType disagreeing)
  {
    this->Agreeing = this->WantNeighbours && !this->WantComponents && disagreeing == 0;
  }

  /**
   * For Consistency alone (no splitting pass to tell): whether the polygons agree already, from
   * a pass over the fans that stops at the first edge where they do not. A mesh whose polygons
   * agree is spared the neighbours and the union-find; one that does not pays little for asking
   * (ordered points, a disagreeing edge among the first ones) and at most one pass.
   */
  void CheckAgreement(vtkPolyData* mesh)
  {
    if (!this->WantNeighbours || this->WantComponents || this->NeighboursBuilt)
    {
      return;
    }
    this->BuildLinks(mesh);
    phongvtk::EdgeRecords records;
    records.CountNonManifold = this->WantNonManifold;
    records.StopAtDisagreeing = true;
    this->WithLinks([&](auto& links)
      { phongvtk::RecordEdges(mesh->GetNumberOfPoints(), mesh->GetPolys(), links, records); });
    this->Recorded(records.Disagreeing);
  }

  void BuildNeighbours(vtkPolyData* mesh)
  {
    if (!this->NeighboursBuilt)
    {
      this->BuildLinks(mesh);
      this->WithLinksAndNeighbours(
        [&](auto& links, auto& neighbours)
        {
          using N = typename std::decay_t<decltype(neighbours)>::value_type;
          neighbours = phongvtk::EdgeNeighbours<N>(mesh->GetNumberOfPoints(), mesh->GetPolys(),
            links, this->WantNonManifold ? &this->NonManifold : nullptr);
        });
      this->NeighboursBuilt = true;
    }
  }

  /// Hands the neighbours' memory back once the polygons are ordered.
  void ReleaseNeighbours()
  {
    std::vector<phongvtk::CompactNeighbour>().swap(this->CompactNeighbours);
    std::vector<vtkIdType>().swap(this->Neighbours);
    std::vector<phongvtk::NonManifoldPair>().swap(this->NonManifold);
  }
};

constexpr double SplitShare = PolygonNormalsKernels::SplitShare;

/**
 * Splitting (the Splitting option) in two stages around the reordering of the polygons. First
 * the polygons' unit normals and status in the accuracy mode, in double, of the polygons as
 * given, and the regions around every point (PhongVTKSplitting.h), the edges between them
 * decided as PhongVTKFeatureAngle.h says; then the mesh with the copies appended.
 *
 * The edges are decided before the polygons are reordered, on the normals of the polygons as
 * given: a polygon reversed by Consistency, AutoOrientNormals or FlipNormals has the negated
 * area vector (exactly; for a triangle even in floating point), so an edge is decided on
 * n1 . (-n2) where the two polygons will have opposite normals relative to each other. With
 * Consistency that is every manifold edge along which the two polygons run the same way but for
 * the edges left disagreeing on a non-orientable component, whose points are decided again
 * once the reordering is known (Redo). The fans are walked once for both: the same pass writes
 * the neighbours Consistency needs.
 */
template <class T>
struct SharpEdges
{
  vtkPolygonNormals* Self;
  vtkPolyData* Input;
  const T* Points;
  std::unique_ptr<double[]> Normals;
  std::unique_ptr<unsigned char[]> Status;
  vtkIdType FirstPoly = 0;
  bool Exact = false; // the accuracy mode, read once: Smooth runs for every edge twice
  phongvtk::RegionLabels Labels;

  /// Whether polygon f has a direction (a non-zero, finite area vector).
  bool Directed(vtkIdType f) const
  {
    return this->Status[static_cast<std::size_t>(this->FirstPoly + f)] == phongvtk::StatusOk;
  }

  /// Whether the edge between polygons f1 and f2 is smooth, with f2 reversed relative to f1 when
  /// `opposite`.
  template <class Offsets, class Connectivity>
  bool Smooth(vtkIdType f1, vtkIdType f2, bool opposite, const Offsets* offsets,
    const Connectivity* conn, double c) const
  {
    const double* n1 = this->Normals.get() + 3 * (this->FirstPoly + f1);
    const double* m2 = this->Normals.get() + 3 * (this->FirstPoly + f2);
    const double n2[3] = { opposite ? -m2[0] : m2[0], opposite ? -m2[1] : m2[1],
      opposite ? -m2[2] : m2[2] };
    if (!this->Exact)
    {
      return phongvtk::FeatureEdgeFromNormals(n1, n2, c) == phongvtk::FeatureEdge::Smooth;
    }
    const phongvtk::FeatureEdge edge = phongvtk::CertifiedFeatureEdge(n1, n2, c);
    if (edge != phongvtk::FeatureEdge::Undecided)
    {
      return edge == phongvtk::FeatureEdge::Smooth;
    }
    // Exactly: the coordinates of both, the second reversed keeping its first point (its area
    // vector negated exactly) when opposite.
    auto coordinates = [&](vtkIdType f, bool reverse, std::vector<double>& xyz)
    {
      const std::int64_t n = offsets[f + 1] - offsets[f];
      xyz.resize(static_cast<std::size_t>(3 * n));
      for (std::int64_t i = 0; i < n; ++i)
      {
        const std::int64_t corner = reverse && i > 0 ? n - i : i;
        const auto id = static_cast<std::int64_t>(conn[offsets[f] + corner]);
        for (int j = 0; j < 3; ++j)
        {
          xyz[static_cast<std::size_t>(3 * i + j)] = static_cast<double>(this->Points[3 * id + j]);
        }
      }
      return n;
    };
    std::vector<double> xyz1, xyz2;
    const std::int64_t k1 = coordinates(f1, false, xyz1);
    const std::int64_t k2 = coordinates(f2, opposite, xyz2);
    return !phongvtk::detail::ExactFeatureEdgeIsSharp(xyz1.data(), k1, xyz2.data(), k2, c);
  }

  double Cosine() const
  {
    return std::cos(vtkMath::RadiansFromDegrees(this->Self->GetFeatureAngle()));
  }

  /**
   * The first stage: the normals and the regions, and on the way the neighbours `adjacency`
   * wants. `consistent` when the polygons will be made to agree. False when a cell refers to a
   * point that does not exist (firstBadCell names it).
   */
  bool Decide(Adjacency& adjacency, bool consistent, vtkIdType& firstBadCell)
  {
    const vtkIdType numCells = this->Input->GetNumberOfCells();
    // Not zero-filled: the pass writes every cell's normal and status.
    this->Normals.reset(new double[3 * static_cast<std::size_t>(numCells)]);
    this->Status.reset(new unsigned char[static_cast<std::size_t>(numCells)]);
    Computation<T, double> faces;
    faces.Filter = this->Self;
    faces.Input = this->Input;
    faces.Points = this->Points;
    faces.NumberOfPoints = this->Input->GetNumberOfPoints();
    faces.AccuracyMode = this->Self->GetAccuracy();
    faces.Weighting = this->Self->GetPointWeighting();
    faces.PointNormals = false;
    faces.PieceInvariant = this->Self->GetPieceInvariant();
    faces.Out.Normals = this->Normals.get();
    faces.Out.Status = this->Status.get();
    faces.ProgressScale = SplitShare / 2;
    if (!faces.Run(nullptr))
    {
      firstBadCell = faces.FirstBadCell;
      return false;
    }
    this->FirstPoly = this->Input->GetNumberOfVerts() + this->Input->GetNumberOfLines();
    this->Exact = this->Self->GetAccuracy() == vtkPolygonNormals::EXACT;
    const vtkIdType numPolys = this->Input->GetNumberOfPolys();
    if (numPolys == 0 || this->Self->GetAbortExecute())
    {
      return true;
    }
    const double c = this->Cosine();
    adjacency.BuildLinks(this->Input);
    vtkCellArray* polys = this->Input->GetPolys();
    vtkIdType disagreeing = 0;
    ForRawCells(polys,
      [&](const auto* offsets, const auto* conn)
      {
        adjacency.WithLinksAndNeighbours(
          [&](auto& links, auto& neighbours)
          {
            auto records = adjacency.RecordsToFill(this->Input, neighbours);
            this->Labels = phongvtk::SharpEdgeRegions(
              this->Input->GetNumberOfPoints(), polys, links, records,
              [&](vtkIdType f) { return this->Directed(f); },
              [&](vtkIdType f1, vtkIdType f2, bool same)
              { return this->Smooth(f1, f2, consistent && same, offsets, conn, c); },
              [&](vtkIdType f)
              {
                const double* normal = this->Normals.get() + 3 * (this->FirstPoly + f);
                phongvtk::PrefetchRecord(normal, normal + 2);
                phongvtk::PrefetchAddress(this->Status.get() + this->FirstPoly + f);
              });
            disagreeing = records.Disagreeing;
          });
      });
    adjacency.Recorded(disagreeing);
    return true;
  }

  /// The regions of the points of the polygons `clashes` again, now that `reverse` (which
  /// polygons were reversed) is known.
  void Redo(Adjacency& adjacency, const std::vector<vtkIdType>& clashes,
    const std::vector<unsigned char>& reverse)
  {
    if (clashes.empty() || this->Labels.Copies.empty())
    {
      return;
    }
    vtkCellArray* polys = this->Input->GetPolys();
    const double c = this->Cosine();
    ForRawCells(polys,
      [&](const auto* offsets, const auto* conn)
      {
        std::vector<vtkIdType> redo;
        for (vtkIdType f : clashes)
        {
          redo.insert(redo.end(), conn + offsets[f], conn + offsets[f + 1]);
        }
        std::sort(redo.begin(), redo.end());
        redo.erase(std::unique(redo.begin(), redo.end()), redo.end());
        adjacency.WithLinks(
          [&](auto& links)
          {
            phongvtk::RedoRegions(
              redo, polys, links, this->Labels, [&](vtkIdType f) { return this->Directed(f); },
              [&](vtkIdType f1, vtkIdType f2, bool)
              {
                const bool opposite =
                  reverse[static_cast<std::size_t>(f1)] != reverse[static_cast<std::size_t>(f2)];
                return this->Smooth(f1, f2, opposite, offsets, conn, c);
              });
          });
      });
  }

  /// The second stage: `oriented` (the input's polygons, reordered or not) with the copies.
  vtkSmartPointer<vtkPolyData> Apply(vtkPolyData* oriented, Adjacency& adjacency)
  {
    // The polygons' normals have served: their memory goes before the copies' is taken.
    this->Normals.reset();
    this->Status.reset();
    phongvtk::SplitPolygons split;
    if (!this->Labels.Copies.empty()) // polygons to split
    {
      adjacency.WithLinks(
        [&](auto& links)
        {
          split = phongvtk::ApplyRegions(
            oriented->GetNumberOfPoints(), oriented->GetPolys(), links, this->Labels);
        });
      this->Labels = phongvtk::RegionLabels();
    }
    return phongvtk::MeshWithCopies(oriented, split, this->Self->GetComputeOriginalPointIds());
  }
};

/**
 * Consistency, AutoOrientNormals and FlipNormals: `input` (`points` its coordinates as the
 * kernels read them) with its polygons reordered (PhongVTKOrientation.h, PhongVTKAutoOrient.h);
 * `reverse` which polygons were reversed, `clashes` the polygons left disagreeing on a
 * non-orientable component, `nonOrientable` the number of such components. Every point id is
 * valid.
 */
template <class T>
vtkSmartPointer<vtkPolyData> Reoriented(vtkPolygonNormals* self, vtkPolyData* input,
  const T* points, Adjacency& adjacency, std::vector<unsigned char>& reverse,
  std::vector<vtkIdType>& clashes, vtkIdType& nonOrientable)
{
  vtkCellArray* polys = input->GetPolys();
  const vtkIdType numPolys = polys->GetNumberOfCells();
  phongvtk::Orientation orientation;
  if (adjacency.Agreeing)
  {
    orientation.Reverse.assign(static_cast<std::size_t>(numPolys), 0); // Consistency: all agree
  }
  else if (self->GetConsistency() || self->GetAutoOrientNormals())
  {
    adjacency.BuildNeighbours(input);
    ForRawCells(polys,
      [&](const auto* offsets, const auto*)
      {
        adjacency.WithLinksAndNeighbours(
          [&](auto&, auto& neighbours)
          {
            orientation = phongvtk::ConsistentOrientation(numPolys, offsets, std::move(neighbours),
              adjacency.WantNonManifold ? &adjacency.NonManifold : nullptr,
              self->GetAutoOrientNormals());
          });
      });
    adjacency.ReleaseNeighbours();
    clashes = orientation.Clashes;
    nonOrientable = orientation.NonOrientable;
  }
  else
  {
    orientation.Reverse.assign(static_cast<std::size_t>(numPolys), 0);
  }
  if (self->GetAutoOrientNormals())
  {
    ForRawCells(polys,
      [&](const auto* offsets, const auto* conn)
      {
        const phongvtk::AutoOrientReport report =
          phongvtk::AutoOrient(points, numPolys, offsets, conn, orientation);
        vtkDebugWithObjectMacro(
          self, << "AutoOrientNormals: " << report.Components << " component(s) oriented ("
                << report.Closed << " closed, " << report.Cavities << " cavities, " << report.Ties
                << " with zero flux kept, " << report.ExactSums << " decided exactly), "
                << report.Skipped << " left as they were.");
      });
  }
  if (self->GetFlipNormals())
  {
    for (unsigned char& r : orientation.Reverse)
    {
      r ^= 1;
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(input);
  out->SetPolys(phongvtk::ReversedPolygons(polys, orientation.Reverse));
  reverse = std::move(orientation.Reverse);
  return out;
}

/**
 * Orientation (`orient`: Consistency, AutoOrientNormals, FlipNormals) and Splitting (`split`)
 * of `input` (`points` its coordinates as the kernels read them), as the user sees them: the
 * polygons reordered, then split at their sharp edges, decided before the reordering
 * (SharpEdges). Null when a cell refers to a point that does not exist (firstBadCell names it).
 */
template <class T>
vtkSmartPointer<vtkPolyData> OrientAndSplit(vtkPolygonNormals* self, vtkPolyData* input,
  const T* points, bool orient, bool split, std::vector<vtkIdType>& clashes,
  vtkIdType& nonOrientable, vtkIdType& firstBadCell)
{
  Adjacency adjacency;
  adjacency.WantNeighbours = self->GetConsistency() || self->GetAutoOrientNormals();
  adjacency.WantComponents = self->GetAutoOrientNormals();
  adjacency.WantNonManifold = self->GetNonManifoldTraversal() && adjacency.WantNeighbours;
  SharpEdges<T> sharp{ self, input, points };
  if (split && !sharp.Decide(adjacency, adjacency.WantNeighbours, firstBadCell))
  {
    return nullptr;
  }
  if (self->GetAbortExecute())
  {
    return input;
  }
  vtkSmartPointer<vtkPolyData> oriented = input;
  std::vector<unsigned char> reverse;
  if (orient)
  {
    if (!split)
    {
      adjacency.CheckAgreement(input);
    }
    oriented = Reoriented(self, input, points, adjacency, reverse, clashes, nonOrientable);
  }
  if (!split)
  {
    return oriented;
  }
  sharp.Redo(adjacency, clashes, reverse);
  vtkSmartPointer<vtkPolyData> out = sharp.Apply(oriented, adjacency);
  self->UpdateProgress(SplitShare);
  return out;
}

template <class T, class O>
bool Dispatch(vtkPolygonNormals* self, vtkPolyData* input, vtkPolyData* output, const T* points,
  double progressStart, vtkIdType& nonFinite, vtkIdType& firstBadCell)
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
  run.ProgressStart = progressStart;
  run.ProgressScale = 1.0 - progressStart;

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

vtkSmartPointer<vtkPolyData> OrientAndSplitAny(vtkPolygonNormals* self, vtkPolyData* input,
  vtkDataArray* coordinates, bool orient, bool split, std::vector<vtkIdType>& clashes,
  vtkIdType& nonOrientable, vtkIdType& firstBadCell)
{
  void* raw = coordinates->GetVoidPointer(0);
  return coordinates->GetDataType() == VTK_FLOAT
    ? OrientAndSplit(self, input, static_cast<const float*>(raw), orient, split, clashes,
        nonOrientable, firstBadCell)
    : OrientAndSplit(self, input, static_cast<const double*>(raw), orient, split, clashes,
        nonOrientable, firstBadCell);
}

bool NormalsAny(vtkPolygonNormals* self, vtkPolyData* input, vtkPolyData* output,
  vtkDataArray* coordinates, bool doubleOutput, double progressStart, vtkIdType& nonFinite,
  vtkIdType& firstBadCell)
{
  void* raw = coordinates->GetVoidPointer(0);
  if (coordinates->GetDataType() == VTK_FLOAT)
  {
    const auto* p = static_cast<const float*>(raw);
    return doubleOutput
      ? Dispatch<float, double>(self, input, output, p, progressStart, nonFinite, firstBadCell)
      : Dispatch<float, float>(self, input, output, p, progressStart, nonFinite, firstBadCell);
  }
  const auto* p = static_cast<const double*>(raw);
  return doubleOutput
    ? Dispatch<double, double>(self, input, output, p, progressStart, nonFinite, firstBadCell)
    : Dispatch<double, float>(self, input, output, p, progressStart, nonFinite, firstBadCell);
}
} // namespace

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS

extern const PolygonNormalsKernels PHONGVTK_KERNEL_TABLE(
  PolygonNormals) = { &OrientAndSplitAny, &NormalsAny };
} // namespace phongvtk
