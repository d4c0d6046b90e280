/**
 * @file PhongVTKEdgeSum.h
 * @brief Private: vtkVisibleArea's sum w over the polygons, from the edges that do not cancel.
 *
 * A polygon's area vector is sum_i p_i x p_(i+1) over its directed edges, so an edge also used in
 * the opposite direction cancels exactly; only the rest (a closed, consistently oriented surface
 * has none) is evaluated, every product split exactly (TwoProduct) into a double-double sum.
 *
 * Two stages, both parallel and bitwise the same for any number of threads:
 * 1. the net count of every undirected edge, gathered under its smaller point id in point ranges
 *    (PhongVTKPointRanges.h): a range's task collects the edges whose smaller id it holds,
 *    buckets them by that id (counting sort), sorts each bucket by the larger id and keeps the
 *    edges with a non-zero net count. The ranges are concatenated in order, so the list is
 *    ordered by (smaller id, larger id) however the points were split.
 * 2. the sum of those edges in chunks of a fixed number of edges, each chunk's double-double sum
 *    in list order, the chunks' sums added in chunk order.
 */
#ifndef PhongVTKEdgeSum_h
#define PhongVTKEdgeSum_h

#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKKernelNamespace.h"
#include "PhongVTKParallel.h"
#include "PhongVTKPointRanges.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkSMPThreadLocal.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <type_traits>
#include <utility>
#include <vector>

namespace phongvtk
{
inline namespace PHONGVTK_KERNELS
{
PHONGVTK_KERNEL_TARGET_BEGIN
/// An undirected edge that does not cancel: Net times the directed edge Low -> High (Net < 0:
/// High -> Low), Low < High.
struct NetEdge
{
  vtkIdType Low;
  vtkIdType High;
  vtkIdType Net;
};

/// A cell array whose cells are polygons (Strips false) or triangle strips (their outline).
struct SurfaceCells
{
  vtkCellArray* Cells;
  vtkIdType FirstCell; // output cell id of its first cell
  bool Strips;
};

/**
 * sum w = sum over the directed edges of the given surface cells of p_a x p_b, skipping the cells
 * for which `skip(output cell id)` holds (non-finite coordinates). The points' ids are valid.
 */
template <class T>
class EdgeSum
{
public:
  /// Edges per chunk of the sum: fixed, so that the result does not depend on the threads.
  static constexpr std::size_t Chunk = 4096;

  EdgeSum(const T* points, vtkIdType numberOfPoints)
    : Points(points)
    , NumberOfPoints(numberOfPoints)
  {
  }

  /// Points per range for tests (0: PointRangeSize's choice).
  vtkIdType ForcedRangeSize = 0;

  /// The edges with a non-zero net count, ordered by (Low, High).
  template <class SkipFn>
  std::vector<NetEdge> NetEdges(const std::vector<SurfaceCells>& surfaces, const SkipFn& skip,
    vtkAlgorithm* filter = nullptr) const
  {
    std::vector<std::vector<IdSpan>> spans;
    std::vector<IdSpan> all;
    vtkIdType numCells = 0;
    for (const SurfaceCells& s : surfaces)
    {
      spans.push_back(BlockSpans(s.Cells));
      all.insert(all.end(), spans.back().begin(), spans.back().end());
      numCells += s.Cells ? s.Cells->GetNumberOfCells() : 0;
    }
    const vtkIdType size = this->ForcedRangeSize > 0
      ? this->ForcedRangeSize
      : PointRangeSize(all, numCells, this->NumberOfPoints, Threads(numCells), 16384);
    const vtkIdType numRanges = (this->NumberOfPoints + size - 1) / size;
    std::vector<std::vector<NetEdge>> found(static_cast<std::size_t>(numRanges));
    struct Buffers
    {
      std::vector<std::pair<vtkIdType, vtkIdType>> Edges; // (Low - first, key)
      std::vector<vtkIdType> Start, Keys;
    };
    vtkSMPThreadLocal<Buffers> local;
    phongvtk::For(
      0, numRanges, 6 * numCells,
      [&](vtkIdType begin, vtkIdType end)
      {
        Buffers& buffers = local.Local();
        for (vtkIdType r = begin; r < end; ++r)
        {
          if (filter && filter->GetAbortExecute())
          {
            return;
          }
          const vtkIdType first = r * size;
          const vtkIdType count = std::min(size, this->NumberOfPoints - first);
          buffers.Edges.clear();
          for (std::size_t k = 0; k < surfaces.size(); ++k)
          {
            Collect(surfaces[k], spans[k], skip, first, count, buffers.Edges);
          }
          NetOfRange(first, count, buffers, found[static_cast<std::size_t>(r)]);
        }
      },
      1);
    std::vector<NetEdge> net;
    for (const std::vector<NetEdge>& range : found)
    {
      net.insert(net.end(), range.begin(), range.end());
    }
    return net;
  }

  /// sum w from the net edges: each component a double-double in units of 2^(2 Scale).
  void Sum(const std::vector<NetEdge>& net, detail::DD sum[3])
  {
    this->Scale = this->ScaleExponent(net);
    const std::size_t numChunks = (net.size() + Chunk - 1) / Chunk;
    std::vector<detail::DD> chunks(3 * numChunks, detail::DD{ 0.0, 0.0 });
    // About four polygons' work per edge.
    phongvtk::For(0, static_cast<vtkIdType>(numChunks), 4 * static_cast<vtkIdType>(net.size()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType c = begin; c < end; ++c)
        {
          detail::DD* s = chunks.data() + 3 * c;
          const std::size_t stop = std::min(net.size(), (static_cast<std::size_t>(c) + 1) * Chunk);
          for (std::size_t e = static_cast<std::size_t>(c) * Chunk; e < stop; ++e)
          {
            for (vtkIdType k = 0; k < std::llabs(net[e].Net); ++k)
            {
              this->AddCross(net[e].Low, net[e].High, net[e].Net > 0, s);
            }
          }
        }
      });
    sum[0] = sum[1] = sum[2] = detail::DD{ 0.0, 0.0 };
    for (std::size_t c = 0; c < numChunks; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        sum[k] = detail::Add(sum[k], chunks[3 * c + k]);
      }
    }
  }

  /// The sum is in units of 2^(2 Scale).
  int Scale = 0;

private:
  /// Appends (Low - first, 2 High + [direction Low -> High]) for every edge of `s` whose smaller
  /// id lies in [first, first + count).
  template <class SkipFn>
  static void Collect(const SurfaceCells& s, const std::vector<IdSpan>& spans, const SkipFn& skip,
    vtkIdType first, vtkIdType count, std::vector<std::pair<vtkIdType, vtkIdType>>& out)
  {
    const vtkIdType numCells = s.Cells ? s.Cells->GetNumberOfCells() : 0;
    if (numCells == 0)
    {
      return;
    }
    const auto limit = static_cast<std::make_unsigned_t<vtkIdType>>(count);
    auto add = [&](vtkIdType a, vtkIdType b)
    {
      const vtkIdType low = std::min(a, b);
      if (a != b && static_cast<std::make_unsigned_t<vtkIdType>>(low - first) < limit)
      {
        out.emplace_back(low - first, 2 * std::max(a, b) + (a < b ? 1 : 0));
      }
    };
    ForRawCells(s.Cells,
      [&](const auto* offsets, const auto* conn)
      {
        for (std::size_t b = 0; b < spans.size(); ++b)
        {
          if (!spans[b].Reaches(first, count))
          {
            continue;
          }
          const vtkIdType begin = static_cast<vtkIdType>(b) * CellBlock;
          const vtkIdType end = std::min(numCells, begin + CellBlock);
          for (vtkIdType cell = begin; cell < end; ++cell)
          {
            PrefetchCells(offsets, conn, cell);
            const std::int64_t m = offsets[cell + 1] - offsets[cell];
            if (m < 2 || skip(s.FirstCell + cell))
            {
              continue;
            }
            const auto* ids = conn + offsets[cell];
            if (!s.Strips)
            {
              for (std::int64_t i = 0; i + 1 < m; ++i)
              {
                add(static_cast<vtkIdType>(ids[i]), static_cast<vtkIdType>(ids[i + 1]));
              }
              add(static_cast<vtkIdType>(ids[m - 1]), static_cast<vtkIdType>(ids[0]));
            }
            else
            {
              auto id = [&](std::int64_t i)
              {
                return static_cast<vtkIdType>(ids[StripOutlineIndex(i, m)]);
              };
              for (std::int64_t i = 0; i + 1 < m; ++i)
              {
                add(id(i), id(i + 1));
              }
              add(id(m - 1), id(0));
            }
          }
        }
      });
  }

  /// The net edges of one range from its collected edges, ordered by (Low, High).
  template <class Buffers>
  static void NetOfRange(
    vtkIdType first, vtkIdType count, Buffers& buffers, std::vector<NetEdge>& net)
  {
    std::vector<vtkIdType>& start = buffers.Start;
    std::vector<vtkIdType>& keys = buffers.Keys;
    start.assign(static_cast<std::size_t>(count) + 1, 0);
    for (const auto& e : buffers.Edges)
    {
      ++start[e.first + 1];
    }
    for (std::size_t i = 1; i < start.size(); ++i)
    {
      start[i] += start[i - 1];
    }
    keys.resize(buffers.Edges.size());
    for (const auto& e : buffers.Edges)
    {
      keys[static_cast<std::size_t>(start[e.first]++)] = e.second;
    }
    // start[i] is now the end of bucket i.
    vtkIdType begin = 0;
    for (std::size_t low = 0; low < static_cast<std::size_t>(count); ++low)
    {
      const vtkIdType end = start[low];
      // Buckets mostly hold a handful of edges (insertion sort); a point of high degree (a
      // fan's centre, a pole) must not cost the square of it.
      auto* bucket = keys.data() + begin;
      const vtkIdType size = end - begin;
      if (size > 32)
      {
        std::sort(bucket, bucket + size);
      }
      for (vtkIdType i = 1; i < size && size <= 32; ++i)
      {
        const vtkIdType key = bucket[i];
        vtkIdType hole = i;
        for (; hole > 0 && bucket[hole - 1] > key; --hole)
        {
          bucket[hole] = bucket[hole - 1];
        }
        bucket[hole] = key;
      }
      for (vtkIdType i = begin; i < end;)
      {
        const vtkIdType high = keys[static_cast<std::size_t>(i)] / 2;
        vtkIdType sum = 0;
        for (; i < end && keys[static_cast<std::size_t>(i)] / 2 == high; ++i)
        {
          sum += (keys[static_cast<std::size_t>(i)] & 1) ? 1 : -1;
        }
        if (sum != 0)
        {
          net.push_back(NetEdge{ first + static_cast<vtkIdType>(low), high, sum });
        }
      }
      begin = end;
    }
  }

  /// Power of two bringing the largest coordinate of the net edges' points near 1 when their
  /// products could overflow or underflow.
  int ScaleExponent(const std::vector<NetEdge>& net) const
  {
    double largest = 0.0;
    for (const NetEdge& e : net)
    {
      for (vtkIdType p : { e.Low, e.High })
      {
        for (int c = 0; c < 3; ++c)
        {
          largest = std::max(largest, std::fabs(static_cast<double>(this->Points[3 * p + c])));
        }
      }
    }
    if (largest == 0.0 || (largest >= 0x1p-400 && largest <= 0x1p400))
    {
      return 0;
    }
    return detail::Exponent2(largest);
  }

  /// sum += (p_a x p_b) or its opposite, every product split exactly (TwoProduct).
  void AddCross(vtkIdType a, vtkIdType b, bool positive, detail::DD sum[3]) const
  {
    using namespace detail;
    double p[3], q[3];
    for (int c = 0; c < 3; ++c)
    {
      p[c] = Scale2(static_cast<double>(this->Points[3 * a + c]), -this->Scale);
      q[c] = Scale2(static_cast<double>(this->Points[3 * b + c]), -this->Scale);
    }
    const double sign = positive ? 1.0 : -1.0;
    for (int c = 0; c < 3; ++c)
    {
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      double h1, l1, h2, l2;
      TwoProduct(p[c1], q[c2], h1, l1);
      TwoProduct(p[c2], q[c1], h2, l2);
      sum[c] = Add(sum[c], DD{ sign * h1, sign * l1 });
      sum[c] = Add(sum[c], DD{ -sign * h2, -sign * l2 });
    }
  }

  const T* Points;
  vtkIdType NumberOfPoints;
};
PHONGVTK_KERNEL_TARGET_END
} // namespace PHONGVTK_KERNELS
} // namespace phongvtk

#endif
// VTK-HeaderTest-Exclude: PhongVTKEdgeSum.h
