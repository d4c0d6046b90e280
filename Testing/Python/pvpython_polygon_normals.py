"""Run by pvpython (ParaView's interpreter): the phongvtk package imports there too and its
filter works in a VTK pipeline next to ParaView's own modules."""
import math
import sys

from paraview import servermanager  # noqa: F401  (ParaView's Python is what is under test)
from phongvtk import vtkPolygonNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource

sphere = vtkSphereSource()
sphere.SetThetaResolution(16)
sphere.SetPhiResolution(16)
normals = vtkPolygonNormals()
normals.SetInputConnection(sphere.GetOutputPort())
normals.SetAccuracyToExact()
normals.ComputeCellNormalsOn()
normals.ComputePointNormalsOff()
normals.ComputeAreasOn()
normals.Update()
out = normals.GetOutput()
cell_normals = out.GetCellData().GetNormals()
areas = out.GetCellData().GetArray("Areas")
assert cell_normals is not None and areas is not None
assert cell_normals.GetNumberOfTuples() == out.GetNumberOfCells() > 0
for i in range(out.GetNumberOfCells()):
    n = cell_normals.GetTuple3(i)
    assert abs(math.sqrt(sum(x * x for x in n)) - 1.0) < 1e-6, (i, n)
    assert areas.GetValue(i) > 0.0
print("pvpython: phongvtk OK,", out.GetNumberOfCells(), "cells")
sys.exit(0)
