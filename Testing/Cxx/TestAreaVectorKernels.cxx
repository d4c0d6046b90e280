#include "vtkPolygonNormals.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

TEST(PolygonNormals, KernelSmoke)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(20);
  sphere->SetPhiResolution(20);
  vtkNew<vtkPolygonNormals> normals;
  normals->SetInputConnection(sphere->GetOutputPort());
  normals->Update();
  vtkDataArray* n = normals->GetOutput()->GetCellData()->GetNormals();
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->GetNumberOfTuples(), normals->GetOutput()->GetNumberOfCells());
}
