// Specification of the tests' OFF reader (PhongVTKOFFReader.h): CGAL's sample meshes and the
// variants of the format they use, and clear errors for missing or garbled files.
#include "PhongVTKOFFReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h> // getpid

namespace
{
/// A file in the temporary directory holding `text`, removed at the end of the test. The name
/// carries the test's name and the process id: CTest runs tests in parallel processes.
class TextFile
{
public:
  TextFile(const std::string& name, const std::string& text)
    : Path(::testing::TempDir() + "PhongVTKOFFReader_" +
        ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
        std::to_string(getpid()) + "_" + name + ".off")
  {
    std::ofstream(this->Path, std::ios::binary) << text;
  }
  ~TextFile() { std::remove(this->Path.c_str()); }
  const std::string Path;
};

std::vector<vtkIdType> Face(vtkPolyData* mesh, vtkIdType face)
{
  vtkIdType n;
  const vtkIdType* ids;
  mesh->GetPolys()->GetCellAtId(face, n, ids);
  return std::vector<vtkIdType>(ids, ids + n);
}

void ExpectPoint(vtkPolyData* mesh, vtkIdType id, double x, double y, double z)
{
  double p[3];
  mesh->GetPoint(id, p);
  EXPECT_EQ(p[0], x) << "point " << id;
  EXPECT_EQ(p[1], y) << "point " << id;
  EXPECT_EQ(p[2], z) << "point " << id;
}

/// Reading must fail with an error that contains every one of `fragments`.
void ExpectError(const std::string& text, const std::vector<std::string>& fragments)
{
  static int count = 0;
  TextFile file("bad" + std::to_string(count++), text);
  std::string error;
  EXPECT_EQ(phongvtk_test::ReadOFF(file.Path, &error), nullptr) << text;
  for (const std::string& fragment : fragments)
  {
    EXPECT_NE(error.find(fragment), std::string::npos)
      << "error '" << error << "' should mention '" << fragment << "'";
  }
}
} // namespace

TEST(OFFReader, ReadsPolygonsOfMixedSizesWithComments)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath("cube_poly.off"), &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 8);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 7);
  EXPECT_EQ(mesh->GetNumberOfCells(), 7);
  ExpectPoint(mesh, 0, -1, -1, 1);
  ExpectPoint(mesh, 7, 1, -1, -1);
  EXPECT_EQ(Face(mesh, 0), (std::vector<vtkIdType>{ 3, 2, 1 }));
  EXPECT_EQ(Face(mesh, 2), (std::vector<vtkIdType>{ 0, 1, 5, 4 }));
  EXPECT_EQ(Face(mesh, 6), (std::vector<vtkIdType>{ 4, 5, 6, 7 }));
}

TEST(OFFReader, ReadsLargeMesh)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath("bunny00.off"), &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 37706);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 75408);
  EXPECT_EQ(mesh->GetPolys()->GetMaxCellSize(), 3);
  ExpectPoint(mesh, 0, -0.167662, -0.411917, -0.0732205);
}

TEST(OFFReader, ReadsColouredOFFWithCommentsBeforeTheHeader)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath("mesh_with_colors.off"), &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 8);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 4);
  ExpectPoint(mesh, 2, 1, -1, 0); // "1 -1 0 0.9 0 0#red": comment glued to the colour
  EXPECT_EQ(Face(mesh, 0), (std::vector<vtkIdType>{ 0, 1, 7 }));
  EXPECT_EQ(Face(mesh, 3), (std::vector<vtkIdType>{ 1, 3, 4, 5, 7 }));
}

TEST(OFFReader, ReadsCOFFWithVertexColours)
{
  PHONGVTK_SKIP_WITHOUT_CGAL_MESHES();
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath("cactus.off"), &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 620);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 1236);
  ExpectPoint(mesh, 0, 0.0687881, 0.0462836, -0.0243483);
}

TEST(OFFReader, ReadsCountsOnTheHeaderLine)
{
  TextFile file("counts_on_header", "OFF 4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(file.Path, &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 4);
  EXPECT_EQ(Face(mesh, 1), (std::vector<vtkIdType>{ 0, 2, 3 }));
}

TEST(OFFReader, IgnoresBlankLinesCommentsAndCarriageReturns)
{
  TextFile file("blank_lines",
    "# leading comment\r\n\r\nOFF # keyword\r\n\r\n# counts next\r\n3 1\r\n\r\n"
    "0 0 0 # first\r\n\r\n1 0 0\r\n0 1 0\r\n\r\n# the face\r\n3 0 1 2 255 0 0\r\n");
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(file.Path, &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 3);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 1);
  ExpectPoint(mesh, 1, 1, 0, 0);
  EXPECT_EQ(Face(mesh, 0), (std::vector<vtkIdType>{ 0, 1, 2 }));
}

TEST(OFFReader, KeepsDoublePrecisionPoints)
{
  TextFile file(
    "double_points", "OFF\n3 1 0\n0.1 1e15 -2.5e-310\n1.0000000000000002 0 0\n0 1 0\n3 0 1 2\n");
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(file.Path, &error);
  ASSERT_NE(mesh, nullptr) << error;
  EXPECT_EQ(mesh->GetPoints()->GetDataType(), VTK_DOUBLE);
  ExpectPoint(mesh, 0, 0.1, 1e15, -2.5e-310);
  ExpectPoint(mesh, 1, 1.0000000000000002, 0, 0);
}

TEST(OFFReader, FaceIdsFollowFileOrder)
{
  TextFile file("face_order",
    "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 2\n"
    "4 0 1 2 3\n3 0 1 4\n5 4 3 2 1 0\n");
  auto mesh = phongvtk_test::ReadOFF(file.Path);
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(Face(mesh, 0).size(), 4u);
  EXPECT_EQ(Face(mesh, 1).size(), 3u);
  EXPECT_EQ(Face(mesh, 2), (std::vector<vtkIdType>{ 4, 3, 2, 1, 0 }));
}

TEST(OFFReader, MissingFileIsAnError)
{
  std::string error;
  EXPECT_EQ(phongvtk_test::ReadOFF("/nonexistent/dir/mesh.off", &error), nullptr);
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
  EXPECT_NE(error.find("/nonexistent/dir/mesh.off"), std::string::npos) << error;
  // Without an error string: still nullptr, no crash.
  EXPECT_EQ(phongvtk_test::ReadOFF("/nonexistent/dir/mesh.off"), nullptr);
}

TEST(OFFReader, EmptyFileIsAnError)
{
  ExpectError("", { "empty" });
  ExpectError("# only a comment\n\n", { "empty" });
}

TEST(OFFReader, WrongHeaderIsAnError)
{
  ExpectError("PLY\n3 1 0\n", { "expected the OFF header", "'PLY'", ":1:" });
  ExpectError("4OFF\n1 0 0\n0 0 0 0\n", { "not supported" });
  ExpectError("OFF BINARY\n", { "binary" });
}

TEST(OFFReader, GarbledCountsAreAnError)
{
  ExpectError("OFF\nthree 1 0\n", { "counts", ":2:" });
  ExpectError("OFF\n-3 1 0\n", { "counts" });
  ExpectError("OFF\n", { "counts" });
}

TEST(OFFReader, GarbledCoordinatesAreAnError)
{
  ExpectError("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", { "vertex 1", ":4:", "1 x 0" });
  ExpectError("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", { "vertex 1" });
}

TEST(OFFReader, TruncatedFileIsAnError)
{
  ExpectError("OFF\n3 1 0\n0 0 0\n1 0 0\n", { "end of file", "2 of 3 vertices" });
  ExpectError("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", { "end of file", "1 of 2 faces" });
}

TEST(OFFReader, GarbledFacesAreAnError)
{
  const std::string points = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  ExpectError(points + "3 0 1\n", { "face 0", ":6:" });
  ExpectError(points + "3 0 1 3\n", { "face 0", "'3'", "[0, 3)" });
  ExpectError(points + "3 0 -1 2\n", { "face 0", "'-1'" });
  ExpectError(points + "3 0 1.5 2\n", { "face 0", "'1.5'" });
  ExpectError(points + "x 0 1 2\n", { "face 0" });
}
