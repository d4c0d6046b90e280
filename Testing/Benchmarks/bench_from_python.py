"""vtkPolygonNormals against VTK's normals filters as a Python user calls them: one process, the
SMP backend VTK gives it (VTK_SMP_BACKEND_IN_USE, default Sequential in ParaView 5.11's VTK),
each filter's Update() after Modified() on a 2,000,000-triangle sphere (vtkSphereSource
1000 x 1000, its point normals removed), all filters warmed up and then timed in turns (a
different one first each round), medians. Ratios are anchor time / PhongVTK time in this run.

    scripts/bench-python.sh            # both backends, one after the other
"""
import statistics
import sys
import time

from vtkmodules.vtkCommonCore import vtkSMPTools, vtkVersion
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals, vtkTriangleMeshPointNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource

import phongvtk

ROUNDS = int(sys.argv[1]) if len(sys.argv) > 1 else 7

source = vtkSphereSource()
source.SetThetaResolution(1000)
source.SetPhiResolution(1000)
source.Update()
mesh = source.GetOutput()
mesh.GetPointData().RemoveArray("Normals")


def vtk_normals(points):
    """vtkPolyDataNormals doing what vtkPolygonNormals does: no splitting, no reordering."""
    f = vtkPolyDataNormals()
    f.SetInputData(mesh)
    f.SplittingOff()
    f.ConsistencyOff()
    f.AutoOrientNormalsOff()
    f.SetComputeCellNormals(not points)
    f.SetComputePointNormals(points)
    return f


def polygon_normals(accuracy, points, piece_invariant=True):
    f = phongvtk.vtkPolygonNormals()
    f.SetInputData(mesh)
    f.SetAccuracy(accuracy)
    f.SetComputeCellNormals(not points)
    f.SetComputePointNormals(points)
    f.SetPieceInvariant(piece_invariant)
    return f


triangle_mesh = vtkTriangleMeshPointNormals()
triangle_mesh.SetInputData(mesh)
DOUBLE, EXACT = phongvtk.vtkPolygonNormals.DOUBLE, phongvtk.vtkPolygonNormals.EXACT
filters = {
    "vtkPolyDataNormals cells": vtk_normals(False),
    "PhongVTK DOUBLE cells": polygon_normals(DOUBLE, False),
    "PhongVTK EXACT cells": polygon_normals(EXACT, False),
    "vtkPolyDataNormals points": vtk_normals(True),
    "vtkTriangleMeshPointNormals": triangle_mesh,
    "PhongVTK DOUBLE points": polygon_normals(DOUBLE, True),
    "PhongVTK DOUBLE points, PieceInvariant off": polygon_normals(DOUBLE, True, False),
}
for f in filters.values():  # warm-up: allocation, first touch
    f.Update()
    f.Modified()
    f.Update()
times = {name: [] for name in filters}
order = list(filters)
for r in range(ROUNDS):
    for name in order[r % len(order):] + order[:r % len(order)]:
        f = filters[name]
        f.Modified()
        start = time.perf_counter()
        f.Update()
        times[name].append(time.perf_counter() - start)
ms = {name: 1e3 * statistics.median(values) for name, values in times.items()}
print(f"VTK {vtkVersion.GetVTKVersion()}, SMP backend {vtkSMPTools.GetBackend()}, "
      f"{vtkSMPTools.GetEstimatedNumberOfThreads()} threads, {mesh.GetNumberOfPolys()} triangles, "
      f"medians of {ROUNDS}")
for name, value in ms.items():
    print(f"  {name:44s} {value:8.1f} ms")
cells = ms["vtkPolyDataNormals cells"]
print(f"  cell normals vs vtkPolyDataNormals: DOUBLE {cells / ms['PhongVTK DOUBLE cells']:.1f}x, "
      f"EXACT {cells / ms['PhongVTK EXACT cells']:.1f}x")
print(f"  point normals vs vtkTriangleMeshPointNormals: DOUBLE "
      f"{ms['vtkTriangleMeshPointNormals'] / ms['PhongVTK DOUBLE points']:.2f}x (PieceInvariant "
      f"off {ms['vtkTriangleMeshPointNormals'] / ms['PhongVTK DOUBLE points, PieceInvariant off']:.2f}x)"
      f"; vs vtkPolyDataNormals points "
      f"{ms['vtkPolyDataNormals points'] / ms['PhongVTK DOUBLE points']:.1f}x")
