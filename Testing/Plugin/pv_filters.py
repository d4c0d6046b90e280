"""Run by pvpython: the plugin loads, its proxies drive the VTK objects with the values asked
for, and the filters' results agree with the summed cross-product rule computed here in numpy."""
import sys

import numpy as np
import phongvtk  # noqa: F401  (the filters' Python classes, for GetClientSideObject)
from paraview import servermanager as sm
from paraview.simple import (CreateView, LoadPlugin, Sphere)
from vtkmodules.util.numpy_support import vtk_to_numpy

LoadPlugin(sys.argv[1], remote=False, ns=globals())  # adds the plugin's proxies here

sphere = Sphere(ThetaResolution=24, PhiResolution=18, Radius=2.0)
normals = PolygonNormals(Input=sphere)
# Defaults of the proxy are those of the C++ class.
vtk_normals = normals.GetClientSideObject()
assert (vtk_normals.GetAccuracy(), vtk_normals.GetPointWeighting()) == (1, 0)
# vtkPolyDataNormals' defaults (ParaView's Generate Surface Normals has the same).
assert not vtk_normals.GetComputeCellNormals() and vtk_normals.GetComputePointNormals()
assert vtk_normals.GetSplitting() and vtk_normals.GetConsistency()
assert vtk_normals.GetNonManifoldTraversal() and vtk_normals.GetTriangulateStrips()
assert vtk_normals.GetOutputPointsPrecision() == 2
assert vtk_normals.GetPieceInvariant() and vtk_normals.GetOutputPrecision() == 0
# Every option reaches the filter.
normals.ComputeCellNormals = 1
normals.TriangulateStrips = 0
normals.OutputPointsPrecision = "Double"
normals.Accuracy = "Exact"
normals.PointWeighting = "Max"
normals.ComputePointNormals = 1
normals.ComputeAreaVectors = 1
normals.ComputeAreas = 1
normals.ComputeNormalStatus = 1
normals.OutputPrecision = "Double"
normals.UpdatePipeline()
assert vtk_normals.GetAccuracy() == 3 and vtk_normals.GetPointWeighting() == 3
assert vtk_normals.GetOutputPrecision() == 1
assert not vtk_normals.GetTriangulateStrips() and vtk_normals.GetOutputPointsPrecision() == 1

out = sm.Fetch(normals)
points = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
cells = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
p0, p1, p2 = points[cells[:, 0]], points[cells[:, 1]], points[cells[:, 2]]
w = np.cross(p1 - p0, p2 - p0)  # the rule for a triangle
area = 0.5 * np.linalg.norm(w, axis=1)
cell_normals = vtk_to_numpy(out.GetCellData().GetArray("Normals"))
np.testing.assert_allclose(cell_normals, w / (2 * area[:, None]), rtol=0, atol=1e-14)
np.testing.assert_allclose(vtk_to_numpy(out.GetCellData().GetArray("Areas")), area, rtol=1e-14)
np.testing.assert_allclose(vtk_to_numpy(out.GetCellData().GetArray("AreaVectors")), w / 2,
                           rtol=0, atol=1e-14)
assert (vtk_to_numpy(out.GetCellData().GetArray("NormalStatus")) == 0).all()
point_normals = vtk_to_numpy(out.GetPointData().GetArray("Normals"))
radial = points / np.linalg.norm(points, axis=1)[:, None]
# Max's weights make the normals of a polyhedron inscribed in a sphere radial; the source's
# points are floats, on the sphere to about 1e-7 only.
assert np.abs(point_normals - radial).max() < 1e-6, np.abs(point_normals - radial).max()

# Visible Area through a view's camera (parallel projection: toward the viewer is -DOP).
view = CreateView("RenderView")
view.CameraPosition = [3.0, 4.0, 12.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraParallelProjection = 1
area_filter = VisibleArea(Input=normals, View=view)
area_filter.UpdatePipeline()
seen = sm.Fetch(area_filter)
toward = np.array([3.0, 4.0, 12.0]) / 13.0
visible = vtk_to_numpy(seen.GetCellData().GetArray("VisibleArea"))
np.testing.assert_allclose(visible, 0.5 * w @ toward, rtol=0, atol=1e-13)
total = seen.GetFieldData().GetArray("TotalVisibleArea").GetValue(0)
assert abs(total - np.clip(0.5 * w @ toward, 0, None).sum()) < 1e-12, total
# Without a view, ViewDirection.
area_filter.View = None
area_filter.ViewDirection = [0.0, 0.0, 5.0]
area_filter.UpdatePipeline()
seen = sm.Fetch(area_filter)
np.testing.assert_allclose(vtk_to_numpy(seen.GetCellData().GetArray("VisibleArea")),
                           0.5 * w[:, 2], rtol=0, atol=1e-13)
print("plugin filters OK:", out.GetNumberOfCells(), "cells")
