/**
 * @file PhongVTKFilterTestSupport.h
 * @brief Building poly data from point and cell lists, and catching a filter's messages, for the
 * filter tests.
 */
#ifndef PhongVTKFilterTestSupport_h
#define PhongVTKFilterTestSupport_h

#include "PhongVTKExactReference.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygonNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace phongvtk_test
{
using Cell = std::vector<vtkIdType>;

struct Cells
{
  std::vector<Cell> Verts, Lines, Polys, Strips;
};

inline vtkSmartPointer<vtkCellArray> MakeCellArray(const std::vector<Cell>& cells)
{
  auto array = vtkSmartPointer<vtkCellArray>::New();
  for (const Cell& cell : cells)
  {
    array->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
  }
  return array;
}

/// Poly data from points (stored as float or double) and cells. The cell arrays are set in the
/// reverse of VTK's cell order, which must not matter.
inline vtkSmartPointer<vtkPolyData> MakePolyData(
  const std::vector<Point>& points, const Cells& cells, int pointType = VTK_DOUBLE)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataType(pointType);
  pts->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    pts->SetPoint(static_cast<vtkIdType>(i), points[i].data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(pts);
  if (!cells.Strips.empty())
  {
    mesh->SetStrips(MakeCellArray(cells.Strips));
  }
  if (!cells.Polys.empty())
  {
    mesh->SetPolys(MakeCellArray(cells.Polys));
  }
  if (!cells.Lines.empty())
  {
    mesh->SetLines(MakeCellArray(cells.Lines));
  }
  if (!cells.Verts.empty())
  {
    mesh->SetVerts(MakeCellArray(cells.Verts));
  }
  return mesh;
}

inline std::vector<Point> PointsOf(vtkPolyData* mesh)
{
  std::vector<Point> points(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, points[static_cast<std::size_t>(i)].data());
  }
  return points;
}

/// A copy of `mesh` with points p * scale + offset (computed in double, stored as pointType).
inline vtkSmartPointer<vtkPolyData> Transformed(
  vtkPolyData* mesh, double scale, double offset, int pointType = VTK_DOUBLE)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataType(pointType);
  pts->SetNumberOfPoints(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (double& x : p)
    {
      x = x * scale + offset;
    }
    pts->SetPoint(i, p);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->CopyStructure(mesh);
  out->SetPoints(pts);
  return out;
}

/// The point ids of every polygon of `mesh`.
inline std::vector<Cell> PolygonsOf(vtkPolyData* mesh)
{
  std::vector<Cell> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    polys.emplace_back(ids->begin(), ids->end());
  }
  return polys;
}

/// vtkSphereSource's closed, outward sphere of triangles with double points and no point data.
inline vtkSmartPointer<vtkPolyData> SphereMesh(int resolution)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(source->GetOutput());
  mesh->GetPointData()->Initialize();
  return mesh;
}

/// A UV sphere (vtkSphereSource, double points) with every point moved by a deterministic
/// random amount of relative size `jitter`: irregular but smooth triangles, no two points alike.
inline vtkSmartPointer<vtkPolyData> JitteredSphere(int resolution, double jitter, unsigned seed = 7)
{
  auto mesh = SphereMesh(resolution);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-jitter, jitter);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (double& x : p)
    {
      x += uniform(random);
    }
    mesh->GetPoints()->SetPoint(i, p);
  }
  return mesh;
}

/// A sphere whose points are moved radially at random: many edges either side of 30 degrees.
inline vtkSmartPointer<vtkPolyData> RoughSphere(
  int resolution, double roughness, unsigned seed = 11)
{
  auto mesh = SphereMesh(resolution);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(1.0 - roughness, 1.0 + roughness);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    const double s = uniform(random);
    mesh->GetPoints()->SetPoint(i, s * x[0], s * x[1], s * x[2]);
  }
  return mesh;
}

/// Calls fn(polygon, point, its cell normal, the point's normal) for every corner of `out`'s
/// polygons (a filter output with cell and point normals).
inline void ForEachCornerNormal(vtkPolyData* out,
  const std::function<void(std::size_t, vtkIdType, const double*, const double*)>& fn)
{
  vtkDataArray* cellNormals = out->GetCellData()->GetNormals();
  vtkDataArray* pointNormals = out->GetPointData()->GetNormals();
  const std::vector<Cell> polys = PolygonsOf(out);
  for (std::size_t f = 0; f < polys.size(); ++f)
  {
    double n[3];
    cellNormals->GetTuple(static_cast<vtkIdType>(f), n);
    for (vtkIdType p : polys[f])
    {
      double m[3];
      pointNormals->GetTuple(p, m);
      fn(f, p, n, m);
    }
  }
}

/// A Moebius strip of n quads.
inline vtkSmartPointer<vtkPolyData> Moebius(int n)
{
  std::vector<Point> p;
  for (int i = 0; i < n; ++i)
  {
    const double t = 2.0 * vtkMath::Pi() * i / n;
    for (double s : { -0.3, 0.3 })
    {
      const double r = 1.0 + s * std::cos(t / 2);
      p.push_back({ r * std::cos(t), r * std::sin(t), s * std::sin(t / 2) });
    }
  }
  Cells cells;
  for (int i = 0; i < n; ++i)
  {
    const vtkIdType a = 2 * i, b = 2 * i + 1;
    // The last quad joins the strip to its start with a half twist.
    const vtkIdType c = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    const vtkIdType d = i + 1 < n ? 2 * (i + 1) : 1;
    cells.Polys.push_back({ a, d, c, b });
  }
  return MakePolyData(p, cells);
}

/// Receives the error and warning events of a filter (what vtkTest::ErrorObserver does).
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject* caller, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    if (vtkExecutive::SafeDownCast(caller))
    {
      this->PipelineErrors.push_back(text);
      return;
    }
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  /// The object's errors and warnings and, for an algorithm, its executive's errors.
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
    if (auto* algorithm = vtkAlgorithm::SafeDownCast(object))
    {
      algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
    }
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  /// What the executive of a watched algorithm reported: an update that failed (RequestData
  /// returned 0) says so here ("... returned failure for request ...").
  std::vector<std::string> PipelineErrors;
};

/// The options that compute the cell normals of the cells as given and nothing else: cell normals
/// on; point normals, splitting, consistency, non-manifold traversal, strip triangulation off.
/// The tests of one stage start from here and turn on what they test; the defaults themselves
/// (vtkPolyDataNormals') are tested against vtkPolyDataNormals.
inline void CellNormalsOfTheCellsAsGiven(vtkPolygonNormals* filter)
{
  filter->ComputeCellNormalsOn();
  filter->ComputePointNormalsOff();
  filter->SplittingOff();
  filter->ConsistencyOff();
  filter->NonManifoldTraversalOff();
  filter->TriangulateStripsOff();
}

/// The filter with CellNormalsOfTheCellsAsGiven, then `configure`, its warnings and errors
/// collected.
inline vtkSmartPointer<vtkPolyData> RunFilter(vtkPolyData* input,
  const std::function<void(vtkPolygonNormals*)>& configure, MessageObserver* messages = nullptr)
{
  vtkNew<vtkPolygonNormals> filter;
  vtkNew<MessageObserver> own;
  (messages ? messages : own.GetPointer())->Watch(filter);
  CellNormalsOfTheCellsAsGiven(filter);
  configure(filter);
  filter->SetInputData(input);
  filter->Update();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}
} // namespace phongvtk_test

#endif
