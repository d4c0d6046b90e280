"""Run by pvbatch, serial or under mpiexec: reads a mesh, distributes it with ParaView's own
machinery (RedistributeDataSet, ExtractSurface, then GhostCellsGenerator, which answers the ghost
level Polygon Normals asks for; RedistributeDataSet gives none), computes cell and point
normals with the plugin's Polygon Normals, gathers the result on rank 0 and saves, for every cell
and point that a process owns (not a ghost), its original id and its normal.

    pv_distributed_normals.py PLUGIN MESH.vtp OUTPUT.npz ACCURACY WEIGHTING SPLITTING [AUTO]

SPLITTING 1 splits the points at sharp edges (30 degrees): a split point's copies carry its
original id too. AUTO 1 turns Auto Orient Normals on.
"""
import sys

import numpy as np
from paraview import servermanager as sm
from paraview.simple import (ExtractSurface, GhostCellsGenerator, LoadPlugin,
                             RedistributeDataSet, XMLPolyDataReader)
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, mesh, output, accuracy, weighting, splitting = sys.argv[1:7]
auto_orient = int(sys.argv[7]) if len(sys.argv) > 7 else 0
LoadPlugin(plugin, remote=True, ns=globals())  # adds the plugin's proxies here
source = XMLPolyDataReader(FileName=[mesh])
pieces = ExtractSurface(Input=RedistributeDataSet(Input=source))
ghosts = GhostCellsGenerator(Input=pieces)
normals = PolygonNormals(Input=ghosts, ComputePointNormals=1, Accuracy=accuracy,
                         PointWeighting=weighting, OutputPrecision="Double",
                         Splitting=int(splitting), AutoOrientNormals=auto_orient)
gathered = sm.Fetch(normals)


def owned(data, name):
    """Original ids and normals of the non-ghost tuples of `data` (point or cell data)."""
    ids = vtk_to_numpy(data.GetArray(name))
    values = vtk_to_numpy(data.GetArray("Normals"))
    ghost = data.GetArray("vtkGhostType")
    keep = np.ones(len(ids), bool) if ghost is None else vtk_to_numpy(ghost) == 0
    return ids[keep], values[keep]


cell_ids, cell_normals = owned(gathered.GetCellData(), "OriginalCellId")
point_ids, point_normals = owned(gathered.GetPointData(), "OriginalPointId")
np.savez(output, cell_ids=cell_ids, cell_normals=cell_normals, point_ids=point_ids,
         point_normals=point_normals)
print("ranks' pieces gathered:", gathered.GetNumberOfCells(), "cells,", len(cell_ids), "owned")
