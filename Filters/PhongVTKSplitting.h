/**
 * @file PhongVTKSplitting.h
 * @brief Private: feature-angle splitting of vtkPolygonNormals. The polygons around each point
 * are grouped into regions joined across smooth manifold edges; the first region keeps the
 * point, every further region gets a copy of it appended to the points, and the polygons of that
 * region refer to the copy.
 *
 * Two polygons around point p are joined across the edge (p, q) when exactly two polygons have
 * the edge p-q as one of their edges at p (a manifold edge), both have a direction (a non-zero,
 * finite area vector) and the edge is smooth (`smooth(f1, f2)`). Boundary and non-manifold edges
 * (three or more polygons) separate regions, as in vtkPolyDataNormals. A polygon without a
 * direction joins no region and keeps the point: it contributes to no normal and adds no copy.
 * Regions are numbered by their smallest polygon index, so the one holding the point's first
 * polygon keeps the point; which polygons form a region depends on the geometry alone, never on
 * the thread count, the cell order or the partition of the mesh.
 */
#ifndef PhongVTKSplitting_h
#define PhongVTKSplitting_h

#include "PhongVTKCells.h"
#include "PhongVTKEdgeNeighbours.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// The result of splitting: the polygons with their new point ids, and the input point of every
/// appended copy (copy i is output point numberOfPoints + i).
struct SplitPolygons
{
  vtkSmartPointer<vtkCellArray> Polys;
  std::vector<vtkIdType> CopyOf;
};

/**
 * The regions of the polygons around one point: the `Label` of each of its polygons (sorted,
 * each once: `Faces` when given its links, the fan's when given a PointFan), 0 for the first
 * region and for polygons without a direction, 1, 2, ... for the regions whose copies are
 * appended; `Regions` their number. Polygons are ids of type Id, the links'.
 */
template <class Id>
struct PointRegionsOf
{
  std::vector<Id> Faces;
  std::vector<std::int32_t> Label;
  std::int32_t Regions = 0;

  std::vector<std::int32_t> Parent; // scratch: union-find

  std::int32_t Root(std::int32_t i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]];
      i = this->Parent[i];
    }
    return i;
  }

  /**
   * Groups the polygons `cells[0 .. count)` around point p (a polygon listed once for each time
   * it uses p). `across(f, fn)` calls fn(g) for every polygon g across a manifold edge of f at p
   * (EdgeNeighbours); `directed(f)` says whether f has a direction, `smooth(f1, f2)` whether the
   * edge between two directed polygons is smooth.
   */
  template <class AcrossFn, class DirectedFn, class SmoothFn>
  void Compute(vtkIdType p, const Id* cells, vtkIdType count, const AcrossFn& across,
    const DirectedFn& directed, const SmoothFn& smooth)
  {
    (void)p;
    std::size_t distinct;
    const Id* faces = DistinctSorted(cells, count, this->Faces, distinct);
    if (faces == cells)
    {
      this->Faces.assign(cells, cells + count);
    }
    this->Start(this->Faces.data(), this->Faces.size());
    const auto n = static_cast<std::int32_t>(this->Faces.size());
    for (std::int32_t a = 0; a < n; ++a)
    {
      const vtkIdType fa = this->Faces[a];
      if (!directed(fa))
      {
        continue;
      }
      across(fa,
        [&](vtkIdType fb)
        {
          // Each edge is seen from both sides: join from the smaller polygon only.
          if (fb < fa || !directed(fb) || !smooth(fa, fb))
          {
            return;
          }
          this->Join(a, this->IndexOf(fb));
        });
    }
    this->Finish(directed);
  }

  /**
   * Groups the polygons of `fan` (PointFan, with every edge at its point): two polygons join
   * across each manifold edge of the fan when both have a direction (`directed(f)`) and
   * `smooth(f1, f2, same)` says the edge is smooth, `same` when both run along it the same way.
   */
  template <class DirectedFn, class SmoothFn>
  void Compute(const PointFanOf<Id>& fan, const DirectedFn& directed, const SmoothFn& smooth)
  {
    this->Start(fan.Faces, fan.NumberOfFaces);
    if (fan.Plain)
    {
      fan.ForPlainPairs(
        [&](std::int32_t i, std::int32_t j)
        {
          // In the order the general listing gives (the smaller index first).
          const std::int32_t a = std::min(i, j), b = std::max(i, j);
          const vtkIdType fa = fan.Faces[a], fb = fan.Faces[b];
          if (directed(fa) && directed(fb) && smooth(fa, fb, false))
          {
            this->Join(a, b);
          }
        });
      this->Finish(directed);
      return;
    }
    fan.ForGroups(
      [&](const FanGroup& group)
      {
        if (!group.Manifold())
        {
          return;
        }
        const FanEdge& a = group[0];
        const FanEdge& b = group[1];
        if (directed(a.Polygon) && directed(b.Polygon) &&
          smooth(a.Polygon, b.Polygon, a.Forward == b.Forward))
        {
          this->Join(a.Face, b.Face);
        }
      });
    this->Finish(directed);
  }

  /// The index of polygon f (one of Faces) in Faces: a linear search, as a point has few.
  std::int32_t IndexOf(vtkIdType f) const
  {
    const Id* faces = this->FaceList;
    const auto n = static_cast<std::int32_t>(this->NumberOfFaces);
    if (n > 16)
    {
      return static_cast<std::int32_t>(std::lower_bound(faces, faces + n, f) - faces);
    }
    std::int32_t i = 0;
    while (faces[i] != f)
    {
      ++i;
    }
    return i;
  }

  /// The label of polygon f (one of Faces).
  std::int32_t LabelOf(vtkIdType f) const { return this->Label[this->IndexOf(f)]; }

private:
  const Id* FaceList = nullptr; // Faces' data, or the fan's
  std::size_t NumberOfFaces = 0;

  void Start(const Id* faces, std::size_t n)
  {
    this->FaceList = faces;
    this->NumberOfFaces = n;
    this->Parent.resize(n);
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
    this->Unions = 0;
  }

  std::int32_t Unions = 0; // joins of two regions into one

  void Join(std::int32_t a, std::int32_t b)
  {
    const std::int32_t ra = this->Root(a);
    const std::int32_t rb = this->Root(b);
    this->Parent[std::max(ra, rb)] = std::min(ra, rb);
    this->Unions += ra != rb ? 1 : 0;
  }

  /// The labels from the joins: faces are sorted, so regions are met in the order of their
  /// smallest polygon.
  template <class DirectedFn>
  void Finish(const DirectedFn& directed)
  {
    const auto n = static_cast<std::int32_t>(this->NumberOfFaces);
    this->Label.resize(this->NumberOfFaces);
    if (n > 1 && this->Unions == n - 1)
    {
      // All joined (then all have a direction): one region, the common case, in one sweep.
      std::fill(this->Label.begin(), this->Label.end(), 0);
      this->Regions = 1;
      return;
    }
    this->Regions = 0;
    for (std::int32_t i = 0; i < n; ++i)
    {
      this->Label[i] = directed(this->FaceList[i]) ? this->Root(i) : -1;
    }
    std::vector<std::int32_t>& labelOfRoot = this->Parent; // reused once the roots are known
    std::fill(labelOfRoot.begin(), labelOfRoot.end(), -1);
    for (std::int32_t i = 0; i < n; ++i)
    {
      const std::int32_t root = this->Label[i];
      if (root < 0)
      {
        this->Label[i] = 0;
        continue;
      }
      if (labelOfRoot[root] < 0)
      {
        labelOfRoot[root] = this->Regions++;
      }
      this->Label[i] = labelOfRoot[root];
    }
  }
};

/// The regions of a point whose links are of vtkIdType.
using PointRegions = PointRegionsOf<vtkIdType>;

/**
 * The regions of every point: the number of copies of every point (`Copies[p + 1]`, then summed
 * into the first copy's number) and the label of every link (point, polygon) of the points with
 * copies; the other points' labels are never written (most points of most meshes have one
 * region: their memory is never touched).
 */
struct RegionLabels
{
  std::unique_ptr<std::int32_t[]> LinkLabel;
  std::vector<vtkIdType> Copies;

  /// Keeps what `regions` (of point p, whose links are `cells[0 .. count)` from `first`) says.
  template <class Id>
  void Store(vtkIdType p, const Id* cells, vtkIdType count, std::size_t first,
    const PointFanOf<Id>& fan, const PointRegionsOf<Id>& regions)
  {
    this->Copies[static_cast<std::size_t>(p) + 1] = std::max<vtkIdType>(regions.Regions - 1, 0);
    if (regions.Regions <= 1)
    {
      return;
    }
    std::int32_t* label = this->LinkLabel.get() + first;
    if (fan.Faces == cells) // the links were sorted and distinct: the labels are theirs
    {
      std::copy_n(regions.Label.data(), count, label);
      return;
    }
    for (vtkIdType j = 0; j < count; ++j)
    {
      label[j] = regions.LabelOf(cells[j]);
    }
  }
};

/**
 * Each point's regions (PointRegions) from its fan of `polys` (every point id valid; `links`
 * theirs), `directed(f)` and `smooth(f1, f2, same)` (both called from several threads, f the
 * index of a polygon in `polys`, `same` when both run along their edge the same way). The points
 * are taken in parallel, each on its own: the same result for any number of threads. The fans
 * give what `records` asks for about the edges on the way (EdgeRecords).
 */
template <class Links, class N, class DirectedFn, class SmoothFn, class AheadFn>
RegionLabels SharpEdgeRegions(vtkIdType numPoints, vtkCellArray* polys, Links& links,
  EdgeRecordsOf<N>& records, const DirectedFn& directed, const SmoothFn& smooth,
  const AheadFn& ahead)
{
  RegionLabels labels;
  // Not zero-filled: written only for the points with copies, read only for them.
  labels.LinkLabel.reset(new std::int32_t[static_cast<std::size_t>(links.GetLinksSize())]);
  labels.Copies.assign(static_cast<std::size_t>(numPoints) + 1, 0);
  ForPointFans<PointRegionsOf<LinkId<Links>>>(
    numPoints, polys, links, false, records,
    [&](vtkIdType p, const auto& fan, auto& regions)
    {
      const vtkIdType count = links.GetNumberOfCells(p);
      const auto first = static_cast<std::size_t>(links.GetOffset(p));
      if (count < 2)
      {
        return; // one region, no copy (Copies[p + 1] is 0)
      }
      regions.Compute(fan, directed, smooth);
      labels.Store(p, links.GetCells(p), count, first, fan, regions);
    },
    ahead);
  return labels;
}

/**
 * Decides the regions of the points `redo` (sorted, each once) again, as SharpEdgeRegions does:
 * after the polygons were reordered, for the points of the polygons whose edges still disagree.
 */
template <class Links, class DirectedFn, class SmoothFn>
void RedoRegions(const std::vector<vtkIdType>& redo, vtkCellArray* polys, Links& links,
  RegionLabels& labels, const DirectedFn& directed, const SmoothFn& smooth)
{
  PointFanOf<LinkId<Links>> fan;
  PointRegionsOf<LinkId<Links>> regions;
  ForRawCells(polys,
    [&](const auto* offsets, const auto* conn)
    {
      for (vtkIdType p : redo)
      {
        const vtkIdType count = links.GetNumberOfCells(p);
        if (count < 2)
        {
          continue;
        }
        fan.Build(p, links.GetCells(p), count, offsets, conn, false);
        regions.Compute(fan, directed, smooth);
        labels.Store(
          p, links.GetCells(p), count, static_cast<std::size_t>(links.GetOffset(p)), fan, regions);
      }
    });
}

/**
 * The polygons of `polys` (the same polygons as when `labels` were decided, reordered or not;
 * `links` theirs) with each point's polygons of region r > 0 referring to its copy r, the
 * copies numbered point by point. Without a split point the polygons are `polys` itself.
 */
template <class Links>
SplitPolygons ApplyRegions(
  vtkIdType numPoints, vtkCellArray* polys, Links& links, RegionLabels& labels)
{
  const vtkIdType numPolys = polys->GetNumberOfCells();
  std::vector<vtkIdType>& copies = labels.Copies;
  // Copy (p, r) is numPoints + copies[p] + r - 1.
  std::partial_sum(copies.begin(), copies.end(), copies.begin());
  SplitPolygons result;
  const vtkIdType numCopies = copies.back();
  result.CopyOf.resize(static_cast<std::size_t>(numCopies));
  if (numCopies == 0)
  {
    result.Polys = polys;
    return result;
  }
  result.Polys = vtkSmartPointer<vtkCellArray>::New();
  result.Polys->DeepCopy(polys);
  if (!result.Polys->IsStorage64Bit() && numPoints + numCopies > VTK_INT_MAX)
  {
    result.Polys->ConvertTo64BitStorage();
  }
  // A corner belongs to exactly one point, so the writes never meet; corners are found in the
  // input's ids.
  ForRawCells(polys,
    [&](const auto* offsets, const auto* conn)
    {
      ForOwnRawCells(result.Polys,
        [&](const auto* outOffsets, auto* outConn)
        {
          using Id = std::remove_pointer_t<decltype(outConn)>;
          phongvtk::For(0, numPoints, numPolys,
            [&](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType p = begin; p < end; ++p)
              {
                const std::size_t at = static_cast<std::size_t>(p);
                const vtkIdType start = numPoints + copies[at];
                const vtkIdType added = copies[at + 1] - copies[at];
                if (added == 0)
                {
                  continue;
                }
                std::fill_n(result.CopyOf.begin() + (start - numPoints), added, p);
                const vtkIdType count = links.GetNumberOfCells(p);
                const auto* cells = links.GetCells(p);
                const std::size_t first = static_cast<std::size_t>(links.GetOffset(p));
                for (vtkIdType j = 0; j < count; ++j)
                {
                  const std::int32_t label = labels.LinkLabel[first + static_cast<std::size_t>(j)];
                  if (label == 0)
                  {
                    continue;
                  }
                  const vtkIdType f = cells[j];
                  ForCornersAt(offsets, conn, f, p,
                    [&](vtkIdType k, vtkIdType, vtkIdType)
                    { outConn[outOffsets[f] + k] = static_cast<Id>(start + label - 1); });
                }
              }
            });
        });
    });
  return result;
}

/**
 * The mesh after splitting: `input` with the copies appended to its points (every point array
 * copied to them, a global id array too, which then is no longer the GlobalIds attribute), its
 * polygons replaced by the split ones, and, with `originalIds`, the point array
 * `OriginalPointIds`. Everything else is shared with `input`.
 */
inline vtkSmartPointer<vtkPolyData> MeshWithCopies(
  vtkPolyData* input, const SplitPolygons& split, bool originalIds)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(input);
  const vtkIdType n = input->GetNumberOfPoints();
  const auto m = static_cast<vtkIdType>(split.CopyOf.size());
  if (m > 0)
  {
    vtkNew<vtkIdList> from, to;
    from->SetNumberOfIds(m);
    to->SetNumberOfIds(m);
    for (vtkIdType i = 0; i < m; ++i)
    {
      from->SetId(i, split.CopyOf[static_cast<std::size_t>(i)]);
      to->SetId(i, n + i);
    }
    vtkDataArray* source = input->GetPoints()->GetData();
    vtkNew<vtkPoints> points;
    points->SetDataType(source->GetDataType());
    points->SetNumberOfPoints(n + m);
    points->GetData()->InsertTuples(0, n, 0, source);
    points->GetData()->InsertTuples(to, from, source);
    out->SetPoints(points);
    vtkNew<vtkPointData> pointData;
    pointData->CopyAllOn();
    pointData->CopyAllocate(input->GetPointData(), n + m);
    pointData->CopyData(input->GetPointData(), 0, n, 0);
    pointData->CopyData(input->GetPointData(), from, to);
    // A copy carries its point's global id: the ids are no longer unique, so the array stays
    // (nothing is lost; OriginalPointIds says which point is which) but is no longer the
    // GlobalIds attribute, which promises uniqueness.
    pointData->SetActiveAttribute(-1, vtkDataSetAttributes::GLOBALIDS);
    out->GetPointData()->ShallowCopy(pointData);
    out->SetPolys(split.Polys);
  }
  if (originalIds)
  {
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("OriginalPointIds");
    ids->SetNumberOfTuples(n + m);
    vtkIdType* id = ids->GetPointer(0);
    std::iota(id, id + n, vtkIdType(0));
    std::copy(split.CopyOf.begin(), split.CopyOf.end(), id + n);
    out->GetPointData()->AddArray(ids);
  }
  return out;
}

PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKSplitting.h
