/**
 * @file PhongVTKBenchmarkMeshes.h
 * @brief Inputs shared by the benchmark and the trade table: the 2M-triangle sphere, CGAL's
 * bunny and the classes of hard input (far offsets, needles, extreme scales, non-planar).
 */
#ifndef PhongVTKBenchmarkMeshes_h
#define PhongVTKBenchmarkMeshes_h

#include "PhongVTKOFFReader.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <random>
#include <string>

namespace phongvtk_bench
{
/// vtkSphereSource with the given resolution (1000 x 1000: 1,996,000 triangles, float points) as
/// bare geometry: its points and triangles, without the source's normals and texture coordinates
/// (as a reader of a plain mesh delivers it, and as phongvtk.speed times it from Python).
inline vtkSmartPointer<vtkPolyData> Sphere(int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  auto bare = vtkSmartPointer<vtkPolyData>::New();
  bare->SetPoints(sphere->GetOutput()->GetPoints());
  bare->SetPolys(sphere->GetOutput()->GetPolys());
  return bare;
}

/// A CGAL sample mesh (double points), or nullptr with a message on stderr.
inline vtkSmartPointer<vtkPolyData> CGALMesh(const std::string& name)
{
  std::string error;
  auto mesh = phongvtk_test::ReadOFF(phongvtk_test::CGALMeshPath(name), &error);
  if (!mesh)
  {
    std::fprintf(
      stderr, "cannot read %s: %s\n", phongvtk_test::CGALMeshPath(name).c_str(), error.c_str());
  }
  return mesh;
}

/// A copy of `mesh` with double points p * 2^exponent + offset.
inline vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* mesh, int exponent, double offset)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType n = mesh->GetNumberOfPoints();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (double& x : p)
    {
      x = std::ldexp(x, exponent) + offset;
    }
    points->SetPoint(i, p);
  }
  out->SetPoints(points);
  return out;
}

/// `count` independent polygons with `n` vertices each, made by `make(rng, xyz)`.
template <class Make>
vtkSmartPointer<vtkPolyData> Polygons(vtkIdType count, int n, unsigned seed, Make make)
{
  std::mt19937_64 rng(seed);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count * n);
  vtkNew<vtkCellArray> polys;
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  std::vector<vtkIdType> ids(n);
  for (vtkIdType c = 0; c < count; ++c)
  {
    make(rng, xyz.data());
    for (int i = 0; i < n; ++i)
    {
      ids[i] = c * n + i;
      points->SetPoint(ids[i], xyz.data() + 3 * i);
    }
    polys->InsertNextCell(n, ids.data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

/// Needle triangles: length 1, width 1e-12 (aspect 1e12), random orientation, near the origin.
inline vtkSmartPointer<vtkPolyData> Needles(vtkIdType count, unsigned seed = 7)
{
  return Polygons(count, 3, seed,
    [](std::mt19937_64& rng, double* p)
    {
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      double a[3] = { u(rng), u(rng), u(rng) };
      double d[3] = { u(rng), u(rng), u(rng) };
      double e[3] = { u(rng), u(rng), u(rng) };
      for (int c = 0; c < 3; ++c)
      {
        p[c] = a[c];
        p[3 + c] = a[c] + d[c];
        p[6 + c] = a[c] + 0.5 * d[c] + 1e-12 * e[c];
      }
    });
}

/// Non-planar hexagons: a regular hexagon with random heights (up to 0.3 of the radius),
/// randomly rotated and placed.
inline vtkSmartPointer<vtkPolyData> NonPlanar(vtkIdType count, unsigned seed = 11)
{
  return Polygons(count, 6, seed,
    [](std::mt19937_64& rng, double* p)
    {
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      // A random orthonormal frame (e1, e2, e3) by Gram-Schmidt.
      double e1[3] = { u(rng), u(rng), u(rng) };
      double e2[3] = { u(rng), u(rng), u(rng) };
      const double n1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
      for (double& x : e1)
      {
        x /= n1;
      }
      const double d = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
      for (int c = 0; c < 3; ++c)
      {
        e2[c] -= d * e1[c];
      }
      const double n2 = std::sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
      for (double& x : e2)
      {
        x /= n2;
      }
      const double e3[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0] };
      const double centre[3] = { u(rng), u(rng), u(rng) };
      for (int i = 0; i < 6; ++i)
      {
        const double t = i * M_PI / 3.0;
        const double h = 0.3 * u(rng);
        for (int c = 0; c < 3; ++c)
        {
          p[3 * i + c] = centre[c] + std::cos(t) * e1[c] + std::sin(t) * e2[c] + h * e3[c];
        }
      }
    });
}
} // namespace phongvtk_bench

#endif
