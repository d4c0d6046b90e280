/**
 * The polygons around every point (Filters/PhongVTKPolygonLinks.h) against brute force: for
 * every point, every corner of every polygon at it, in polygon order. Serial and blocked builds
 * (every block count up to MaxBlocks and past it), both id widths, both cell-array storages,
 * polygons of every size, a polygon at a point twice, empty polygons, unused points, no polygons,
 * and a large random mesh built on several threads with every SMP backend VTK has.
 */
#include "PhongVTKPolygonLinks.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace
{
using Polygons = std::vector<std::vector<vtkIdType>>;

/// For every point, the polygon of each corner at it, in the order of the polygons and corners.
std::vector<std::vector<vtkIdType>> BruteForce(vtkIdType numPoints, const Polygons& polygons)
{
  std::vector<std::vector<vtkIdType>> around(static_cast<std::size_t>(numPoints));
  for (std::size_t f = 0; f < polygons.size(); ++f)
  {
    for (const vtkIdType p : polygons[f])
    {
      around[static_cast<std::size_t>(p)].push_back(static_cast<vtkIdType>(f));
    }
  }
  return around;
}

vtkSmartPointer<vtkCellArray> CellArray(const Polygons& polygons, bool bits64)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (bits64)
  {
    cells->Use64BitStorage();
  }
  else
  {
    cells->Use32BitStorage();
  }
  for (const auto& polygon : polygons)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(polygon.size()), polygon.data());
  }
  return cells;
}

template <class Id>
void ExpectLinks(vtkIdType numPoints, const Polygons& polygons, bool bits64, vtkIdType blocks,
  const std::string& what)
{
  SCOPED_TRACE(what + (bits64 ? ", 64-bit cells" : ", 32-bit cells") + ", " +
    std::to_string(sizeof(Id) * 8) + "-bit links, blocks " + std::to_string(blocks));
  const auto expected = BruteForce(numPoints, polygons);
  auto cells = CellArray(polygons, bits64);
  phongvtk::PolygonLinksOf<Id> links;
  links.Build(numPoints, cells, blocks);
  ASSERT_EQ(links.GetNumberOfPoints(), numPoints);
  ASSERT_EQ(links.GetLinksSize(), cells->GetNumberOfConnectivityIds());
  vtkIdType offset = 0;
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    const auto& want = expected[static_cast<std::size_t>(p)];
    ASSERT_EQ(static_cast<vtkIdType>(links.GetOffset(p)), offset) << "point " << p;
    ASSERT_EQ(links.GetNumberOfCells(p), static_cast<vtkIdType>(want.size())) << "point " << p;
    const Id* got = links.GetCells(p);
    for (std::size_t j = 0; j < want.size(); ++j)
    {
      ASSERT_EQ(static_cast<vtkIdType>(got[j]), want[j]) << "point " << p << ", link " << j;
    }
    offset += static_cast<vtkIdType>(want.size());
  }
  ASSERT_EQ(static_cast<vtkIdType>(links.GetOffset(numPoints)), links.GetLinksSize());
}

void ExpectLinksEveryWay(vtkIdType numPoints, const Polygons& polygons, const std::string& what)
{
  for (const bool bits64 : { false, true })
  {
    for (vtkIdType blocks = 1; blocks <= phongvtk::PolygonLinksOf<vtkIdType>::MaxBlocks + 2;
         ++blocks)
    {
      ExpectLinks<unsigned int>(numPoints, polygons, bits64, blocks, what);
      ExpectLinks<vtkIdType>(numPoints, polygons, bits64, blocks, what);
    }
    ExpectLinks<unsigned int>(numPoints, polygons, bits64, 0, what); // the filter's choice
  }
}

Polygons RandomPolygons(std::mt19937_64& random, vtkIdType numPoints, std::size_t count)
{
  std::uniform_int_distribution<vtkIdType> point(0, numPoints - 1);
  std::uniform_int_distribution<int> size(0, 9);
  Polygons polygons(count);
  for (auto& polygon : polygons)
  {
    const int m = size(random) < 7 ? 3 : size(random);
    for (int k = 0; k < m; ++k)
    {
      polygon.push_back(point(random));
    }
  }
  return polygons;
}
} // namespace

TEST(PolygonLinks, SmallMeshesOfEveryKind)
{
  // Two triangles sharing an edge, a quad, a point used by no polygon (4), a polygon at one
  // point twice, an empty polygon, a single-point polygon.
  const Polygons polygons = { { 0, 1, 2 }, { 2, 1, 3 }, { 0, 2, 5, 6 }, { 3, 5, 3, 6 }, {}, { 6 },
    { 1, 2, 3, 5, 6, 0 } };
  ExpectLinksEveryWay(7, polygons, "small mesh");
  ExpectLinksEveryWay(3, Polygons{}, "no polygons");
  ExpectLinksEveryWay(0, Polygons{}, "no points");
  ExpectLinksEveryWay(4, Polygons{ {}, {}, {} }, "empty polygons only");
  ExpectLinksEveryWay(1, Polygons{ { 0, 0, 0 } }, "one point three times");
}

TEST(PolygonLinks, RandomMeshes)
{
  std::mt19937_64 random(20261204);
  for (const vtkIdType numPoints : { 1, 2, 7, 64, 1000 })
  {
    for (const std::size_t count : { std::size_t(1), std::size_t(5), std::size_t(300) })
    {
      ExpectLinksEveryWay(numPoints, RandomPolygons(random, numPoints, count),
        "random, " + std::to_string(numPoints) + " points, " + std::to_string(count) + " polygons");
    }
  }
}

TEST(PolygonLinks, LargeMeshOnEveryBackend)
{
  // Large enough for the filter's own choice to cut it into blocks on several threads.
  std::mt19937_64 random(7);
  const vtkIdType numPoints = 90000;
  const Polygons polygons = RandomPolygons(random, numPoints, 200000);
  for (const char* backend : { "Sequential", "STDThread", "OpenMP", "TBB" })
  {
    if (!vtkSMPTools::SetBackend(backend))
    {
      continue;
    }
    vtkSMPTools::Initialize(2);
    ExpectLinks<unsigned int>(numPoints, polygons, false, 0, std::string(backend));
    ExpectLinks<vtkIdType>(numPoints, polygons, true, 3, std::string(backend));
  }
  vtkSMPTools::SetBackend("Sequential");
}
