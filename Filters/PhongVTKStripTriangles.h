/**
 * Private to vtkPolygonNormals: triangle strips broken into triangles, as vtkPolyDataNormals
 * does before it computes anything (it runs vtkTriangleFilter with PreservePolys, which VTK
 * before 9.3 lacks). The polygons keep their ids and are followed by each strip's triangles
 * (vtkTriangleStrip::DecomposeStrip: alternate triangles reversed, so that all face the strip's
 * way), each with its strip's cell data; points, point data, field data, vertices and lines pass
 * through.
 */
#ifndef PhongVTKStripTriangles_h
#define PhongVTKStripTriangles_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleStrip.h"

namespace phongvtk
{

/// `input` with its strips as triangles; every point id must be valid (checked before).
inline vtkSmartPointer<vtkPolyData> StripsAsTriangles(vtkPolyData* input)
{
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(input->GetPoints());
  output->GetPointData()->PassData(input->GetPointData());
  output->GetFieldData()->PassData(input->GetFieldData());
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());

  vtkCellArray* strips = input->GetStrips();
  const vtkIdType kept =
    input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfPolys();
  vtkIdType triangles = 0;
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (strips->InitTraversal(); strips->GetNextCell(npts, pts);)
  {
    triangles += npts > 2 ? npts - 2 : 0;
  }
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(input->GetPolys());
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, kept + triangles);
  if (kept > 0)
  {
    outCD->CopyData(inCD, 0, kept, 0);
  }
  vtkIdType outId = kept;
  vtkIdType stripId = kept;
  for (strips->InitTraversal(); strips->GetNextCell(npts, pts); ++stripId)
  {
    if (npts < 3)
    {
      continue; // no triangle: the strip is dropped, as vtkTriangleFilter drops it
    }
    vtkTriangleStrip::DecomposeStrip(static_cast<int>(npts), pts, polys);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      outCD->CopyData(inCD, stripId, outId++);
    }
  }
  output->SetPolys(polys);
  return output;
}

}

#endif
// VTK-HeaderTest-Exclude: PhongVTKStripTriangles.h
