// vtkPolygonNormals in a piece-wise pipeline with real ghost cells: VTK's own
// vtkExtractPolyDataPiece serves each piece with the ghost levels the pipeline asks for, marked
// in vtkGhostType arrays. With PieceInvariant the filter asks for one ghost level more than
// downstream did, gives every point of the piece the whole mesh's normal bit for bit, and
// removes the ghost cells it asked for on its own behalf (keeping those downstream asked for).
#include "PhongVTKFilterTestSupport.h"
#include "vtkPolygonNormals.h"
#include "vtkVisibleArea.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <string>

namespace
{
// A sphere with jittered points: no two points share coordinates, no symmetry hides an error.
// Float points, as vtkExtractPolyDataPiece writes its pieces' points.
vtkSmartPointer<vtkPolyData> Mesh()
{
  auto mesh = phongvtk_test::JitteredSphere(60, 1e-3, 17);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->DeepCopy(mesh->GetPoints());
  mesh->SetPoints(points);
  return mesh;
}

using Key = std::array<double, 3>;

Key At(vtkPolyData* mesh, vtkIdType point)
{
  Key key;
  mesh->GetPoint(point, key.data());
  return key;
}

// The ghost cells of `mesh` (cells whose vtkGhostType has DUPLICATECELL).
vtkIdType GhostCells(vtkPolyData* mesh)
{
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  vtkIdType count = 0;
  for (vtkIdType c = 0; ghosts && c < ghosts->GetNumberOfTuples(); ++c)
  {
    count += (ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL) != 0;
  }
  return count;
}

struct PieceRun
{
  vtkSmartPointer<vtkPolyData> Input;  // what the filter read (the piece with its ghosts)
  vtkSmartPointer<vtkPolyData> Output; // what it gave
};

PieceRun RunPiece(vtkPolyData* whole, int piece, int pieces, int ghostLevels, bool invariant)
{
  vtkNew<vtkExtractPolyDataPiece> extract;
  extract->SetInputData(whole);
  vtkNew<vtkPolygonNormals> normals;
  normals->SetInputConnection(extract->GetOutputPort());
  normals->ComputePointNormalsOn();
  normals->SplittingOff(); // the point normals of the mesh as given
  normals->ConsistencyOff();
  normals->SetAccuracy(vtkPolygonNormals::EXACT);
  normals->SetPieceInvariant(invariant);
  normals->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  normals->UpdatePiece(piece, pieces, ghostLevels);
  PieceRun run;
  run.Input = extract->GetOutput();
  run.Output = normals->GetOutput();
  return run;
}

// Of the points of `cells`' cells (ghost cells too when `ghosts`), how many have in `output` a
// normal that differs (bits) from the whole mesh's normal of the same point.
int DifferentNormals(vtkPolyData* output, vtkPolyData* cells, bool ghosts, vtkPolyData* whole)
{
  std::map<Key, vtkIdType> wholeIds, outputIds;
  for (vtkIdType p = 0; p < whole->GetNumberOfPoints(); ++p)
  {
    wholeIds[At(whole, p)] = p;
  }
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    outputIds[At(output, p)] = p;
  }
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  vtkDataArray* reference = whole->GetPointData()->GetNormals();
  vtkUnsignedCharArray* ghostArray = cells->GetCellGhostArray();
  vtkNew<vtkIdList> cell;
  int different = 0;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    if (!ghosts && ghostArray && (ghostArray->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL))
    {
      continue;
    }
    cells->GetCellPoints(c, cell);
    for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
    {
      const Key key = At(cells, cell->GetId(k));
      const auto inWhole = wholeIds.find(key);
      const auto inOutput = outputIds.find(key);
      if (inWhole == wholeIds.end() || inOutput == outputIds.end())
      {
        ADD_FAILURE() << "point " << cell->GetId(k) << " of cell " << c << " is missing";
        return -1;
      }
      double a[3], b[3];
      normals->GetTuple(inOutput->second, a);
      reference->GetTuple(inWhole->second, b);
      different += std::memcmp(a, b, sizeof(a)) != 0;
    }
  }
  return different;
}

TEST(GhostCells, PiecesGetTheWholeMeshNormalsAndLoseTheGhostCellsTheyAskedFor)
{
  auto whole = Mesh();
  vtkNew<vtkPolygonNormals> reference;
  reference->SetInputData(whole);
  reference->ComputePointNormalsOn();
  reference->SplittingOff(); // the point normals of the mesh as given
  reference->ConsistencyOff();
  reference->SetAccuracy(vtkPolygonNormals::EXACT);
  reference->SetOutputPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  reference->Update();
  vtkPolyData* wholeNormals = reference->GetOutput();

  for (int pieces : { 2, 3, 5 })
  {
    vtkIdType ownCells = 0;
    for (int piece = 0; piece < pieces; ++piece)
    {
      const std::string what = "piece " + std::to_string(piece) + " of " + std::to_string(pieces);
      // Downstream asks for no ghost cells: the filter asked for one level, used it, removed it.
      const PieceRun run = RunPiece(whole, piece, pieces, 0, true);
      const vtkIdType ghosts = GhostCells(run.Input);
      EXPECT_GT(ghosts, 0) << what << ": no ghost level was asked for";
      EXPECT_EQ(GhostCells(run.Output), 0) << what;
      EXPECT_EQ(run.Output->GetNumberOfCells(), run.Input->GetNumberOfCells() - ghosts) << what;
      EXPECT_EQ(DifferentNormals(run.Output, run.Output, false, wholeNormals), 0) << what;
      ownCells += run.Output->GetNumberOfCells();

      // Downstream asks for one level: the filter reads two and passes both on, marked as
      // ghosts (as documented); every point of the piece and of the level asked for has the
      // whole mesh's normal.
      const PieceRun one = RunPiece(whole, piece, pieces, 1, true);
      vtkNew<vtkExtractPolyDataPiece> direct;
      direct->SetInputData(whole);
      direct->UpdatePiece(piece, pieces, 1);
      const vtkIdType oneLevel = GhostCells(direct->GetOutput());
      EXPECT_GT(GhostCells(one.Input), oneLevel) << what << ": no second level was asked for";
      EXPECT_EQ(GhostCells(one.Output), GhostCells(one.Input)) << what;
      EXPECT_EQ(one.Output->GetNumberOfCells(), one.Input->GetNumberOfCells()) << what;
      EXPECT_EQ(DifferentNormals(one.Output, direct->GetOutput(), true, wholeNormals), 0) << what;

      // Without PieceInvariant no level is asked for, and the boundary points differ.
      const PieceRun plain = RunPiece(whole, piece, pieces, 0, false);
      EXPECT_EQ(GhostCells(plain.Input), 0) << what;
      EXPECT_GT(DifferentNormals(plain.Output, plain.Output, false, wholeNormals), 0) << what;
    }
    // The pieces' own cells are the mesh's cells, once each.
    EXPECT_EQ(ownCells, whole->GetNumberOfCells()) << pieces << " pieces";
  }
}

// vtkVisibleArea on pieces with ghost cells: the ghost cells keep their visible areas in the
// cell array but count in neither the total nor the max visible area, so the pieces' totals add
// up to the whole mesh's and their area vectors to the whole (closed) mesh's, zero.
TEST(GhostCells, VisibleAreaTotalsOfPiecesAddUpToTheWholeMesh)
{
  auto whole = Mesh();
  const double v[3] = { 0.3, -0.5, 0.8 };
  auto run = [&v](vtkAlgorithmOutput* port, int piece, int pieces, int ghostLevels)
  {
    auto area = vtkSmartPointer<vtkVisibleArea>::New();
    area->SetInputConnection(port);
    area->SetAccuracy(vtkVisibleArea::EXACT);
    area->SetViewDirection(v[0], v[1], v[2]);
    area->UpdatePiece(piece, pieces, ghostLevels);
    return area;
  };
  vtkNew<vtkVisibleArea> reference;
  reference->SetInputData(whole);
  reference->SetAccuracy(vtkVisibleArea::EXACT);
  reference->SetViewDirection(v[0], v[1], v[2]);
  reference->Update();
  const double total = reference->GetTotalVisibleArea();
  ASSERT_GT(total, 0.5);
  for (int pieces : { 2, 3, 5 })
  {
    double sum = 0.0;
    double sumW[3] = { 0.0, 0.0, 0.0 };
    double withGhosts = 0.0;
    for (int piece = 0; piece < pieces; ++piece)
    {
      vtkNew<vtkExtractPolyDataPiece> extract;
      extract->SetInputData(whole);
      auto area = run(extract->GetOutputPort(), piece, pieces, 1);
      vtkPolyData* out = area->GetOutput();
      ASSERT_GT(GhostCells(out), 0);
      sum += area->GetTotalVisibleArea();
      const double* direction = area->GetMaxVisibleAreaDirection();
      for (int c = 0; c < 3; ++c)
      {
        sumW[c] += direction[c] * area->GetMaxVisibleArea();
      }
      // The ghost cells' visible areas are there (what the total leaves out).
      auto* areas = vtkDoubleArray::SafeDownCast(out->GetCellData()->GetArray("VisibleArea"));
      ASSERT_NE(areas, nullptr);
      for (vtkIdType c = 0; c < areas->GetNumberOfTuples(); ++c)
      {
        withGhosts += std::max(0.0, areas->GetValue(c));
      }
    }
    // Sums of a few hundred faithful values in another order: within 1e-13 relative.
    EXPECT_NEAR(sum, total, 1e-13 * total) << pieces << " pieces";
    EXPECT_GT(withGhosts, total * 1.01) << pieces << " pieces: the ghost cells are counted";
    EXPECT_LT(std::sqrt(sumW[0] * sumW[0] + sumW[1] * sumW[1] + sumW[2] * sumW[2]), 1e-13 * total)
      << pieces << " pieces";
  }
}
}
