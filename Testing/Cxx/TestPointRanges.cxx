/**
 * The point ranges' bookkeeping (Filters/PhongVTKPointRanges.h), against brute force: the
 * extent of an id array (every length around the eight-lane stride, negative and huge ids, 32-
 * and 64-bit ids), the span of every block of cells (cells of every size, empty cells, both
 * storage types, blocks cut by the end of the array) and the range size's guarantees.
 */
#include "PhongVTKPointRanges.h"

#include "vtkCellArray.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace
{
using phongvtk::CellBlock;
using phongvtk::IdSpan;

template <class Id>
void CheckExtents(std::mt19937_64& random)
{
  std::uniform_int_distribution<Id> any(
    std::numeric_limits<Id>::lowest(), std::numeric_limits<Id>::max());
  for (std::size_t n = 1; n <= 70; ++n)
  {
    for (int trial = 0; trial < 20; ++trial)
    {
      std::vector<Id> ids(n);
      for (Id& id : ids)
      {
        id = any(random);
      }
      // The extreme values at every position in turn (the tail after the last full stride too).
      const std::size_t at = static_cast<std::size_t>(trial) % n;
      if (trial % 3 == 1)
      {
        ids[at] = std::numeric_limits<Id>::lowest();
      }
      if (trial % 3 == 2)
      {
        ids[at] = std::numeric_limits<Id>::max();
      }
      Id first = 0, last = 0;
      phongvtk::IdExtent(ids.data(), n, first, last);
      const auto expected = std::minmax_element(ids.begin(), ids.end());
      ASSERT_EQ(first, *expected.first) << "n = " << n << ", trial " << trial;
      ASSERT_EQ(last, *expected.second) << "n = " << n << ", trial " << trial;
    }
  }
}

TEST(PointRanges, IdExtentIsTheSmallestAndLargestId)
{
  std::mt19937_64 random(7);
  CheckExtents<std::int32_t>(random);
  CheckExtents<std::int64_t>(random);
  // A single id, and every id equal.
  const std::int64_t one = -5;
  std::int64_t first = 0, last = 0;
  phongvtk::IdExtent(&one, 1, first, last);
  EXPECT_EQ(first, -5);
  EXPECT_EQ(last, -5);
  const std::vector<std::int32_t> same(19, 42);
  std::int32_t f = 0, l = 0;
  phongvtk::IdExtent(same.data(), same.size(), f, l);
  EXPECT_EQ(f, 42);
  EXPECT_EQ(l, 42);
}

/// Random cells of 0 to 9 points with ids in [-3, points + 3): invalid ids belong to spans too.
vtkSmartPointer<vtkCellArray> RandomCells(
  std::mt19937_64& random, vtkIdType cells, vtkIdType points, bool use64)
{
  auto array = vtkSmartPointer<vtkCellArray>::New();
  if (use64)
  {
    array->Use64BitStorage();
  }
  else
  {
    array->Use32BitStorage();
  }
  std::uniform_int_distribution<int> size(0, 9);
  std::uniform_int_distribution<vtkIdType> id(-3, points + 2);
  std::vector<vtkIdType> ids;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    ids.resize(static_cast<std::size_t>(size(random)));
    for (vtkIdType& i : ids)
    {
      i = id(random);
    }
    array->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  return array;
}

TEST(PointRanges, BlockSpansHoldEveryBlocksSmallestAndLargestId)
{
  std::mt19937_64 random(11);
  for (const bool use64 : { false, true })
  {
    for (const vtkIdType cells : { vtkIdType(1), CellBlock - 1, CellBlock, 3 * CellBlock + 17 })
    {
      auto array = RandomCells(random, cells, 100000, use64);
      const std::vector<IdSpan> spans = phongvtk::BlockSpans(array);
      ASSERT_EQ(spans.size(), static_cast<std::size_t>((cells + CellBlock - 1) / CellBlock));
      for (std::size_t b = 0; b < spans.size(); ++b)
      {
        vtkIdType first = std::numeric_limits<vtkIdType>::max();
        vtkIdType last = std::numeric_limits<vtkIdType>::lowest();
        const vtkIdType end = std::min(cells, static_cast<vtkIdType>(b + 1) * CellBlock);
        for (vtkIdType c = static_cast<vtkIdType>(b) * CellBlock; c < end; ++c)
        {
          vtkIdType n;
          const vtkIdType* ids;
          array->GetCellAtId(c, n, ids);
          for (vtkIdType k = 0; k < n; ++k)
          {
            first = std::min(first, ids[k]);
            last = std::max(last, ids[k]);
          }
        }
        if (first > last)
        {
          EXPECT_GT(spans[b].First, spans[b].Last) << "block " << b << " has no point";
        }
        else
        {
          EXPECT_EQ(spans[b].First, first) << "block " << b << ", 64-bit " << use64;
          EXPECT_EQ(spans[b].Last, last) << "block " << b << ", 64-bit " << use64;
        }
      }
    }
  }
  // A block of empty cells only has an empty span.
  auto empty = vtkSmartPointer<vtkCellArray>::New();
  for (int c = 0; c < 10; ++c)
  {
    empty->InsertNextCell(0);
  }
  const std::vector<IdSpan> spans = phongvtk::BlockSpans(empty);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_GT(spans[0].First, spans[0].Last);
  EXPECT_FALSE(spans[0].Reaches(0, 100));
}

TEST(PointRanges, RangeSizeBoundsTheRepeatedWork)
{
  // Coherent blocks (each spans its own 600 ids): the cap holds and few blocks are repeated.
  const vtkIdType cells = 200 * CellBlock, points = 200 * 600;
  std::vector<IdSpan> coherent;
  for (vtkIdType b = 0; b < 200; ++b)
  {
    coherent.push_back(IdSpan{ 600 * b, 600 * b + 599 });
  }
  for (const vtkIdType threads : { 1, 2, 8 })
  {
    const vtkIdType size = phongvtk::PointRangeSize(coherent, cells, points, threads, 16384);
    EXPECT_GE(size, 1024);
    EXPECT_LE(size, 16384);
    vtkIdType visits = 0;
    for (const IdSpan& s : coherent)
    {
      visits += s.Last / size - s.First / size + 1;
    }
    EXPECT_LE(visits * CellBlock, cells + cells / 4 + CellBlock) << threads << " threads";
  }
  // Every block reaching over all the points: one range a thread.
  const std::vector<IdSpan> incoherent(200, IdSpan{ 0, points - 1 });
  EXPECT_EQ(phongvtk::PointRangeSize(incoherent, cells, points, 2, 16384), points / 2);
  EXPECT_EQ(phongvtk::PointRangeSize(incoherent, cells, points, 1, 16384), points);
}
} // namespace
