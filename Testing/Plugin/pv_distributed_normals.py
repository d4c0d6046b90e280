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
                             ProcessIdScalars, RedistributeDataSet, XMLPolyDataReader)
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, mesh, output, accuracy, weighting, splitting = sys.argv[1:7]
auto_orient = int(sys.argv[7]) if len(sys.argv) > 7 else 0
LoadPlugin(plugin, remote=True, ns=globals())  # adds the plugin's proxies here
source = XMLPolyDataReader(FileName=[mesh])
pieces = ExtractSurface(Input=RedistributeDataSet(Input=source))
ghosts = GhostCellsGenerator(Input=pieces)
normals = PolygonNormals(Input=ghosts, ComputePointNormals=1, Accuracy=accuracy,
                         PointWeighting=weighting, OutputPrecision="Double",
                         Splitting=int(splitting), AutoOrientNormals=auto_orient,
                         Consistency=0, ComputeCellNormals=1)
# Each point carries the rank that computed it ("ProcessId"; a piece's points are its own
# copies, so a cell's rank is its first point's): the test sees that every rank had a piece,
# and how many ghost cells the pieces had.
gathered = sm.Fetch(ProcessIdScalars(Input=normals))


def owned(data, name):
    """Original ids and normals of the non-ghost tuples of `data` (point or cell data)."""
    ids = vtk_to_numpy(data.GetArray(name))
    values = vtk_to_numpy(data.GetArray("Normals"))
    ghost = data.GetArray("vtkGhostType")
    keep = np.ones(len(ids), bool) if ghost is None else vtk_to_numpy(ghost) == 0
    return ids[keep], values[keep]


cell_ids, cell_normals = owned(gathered.GetCellData(), "OriginalCellId")
point_ids, point_normals = owned(gathered.GetPointData(), "OriginalPointId")
polys = gathered.GetPolys()
first_points = vtk_to_numpy(polys.GetConnectivityArray())[
    vtk_to_numpy(polys.GetOffsetsArray())[:-1]]
ranks = vtk_to_numpy(gathered.GetPointData().GetArray("ProcessId"))[first_points].astype(int)
ghost = gathered.GetCellData().GetArray("vtkGhostType")
is_ghost = np.zeros(len(ranks), bool) if ghost is None else vtk_to_numpy(ghost) != 0
np.savez(output, cell_ids=cell_ids, cell_normals=cell_normals, point_ids=point_ids,
         point_normals=point_normals, owned_cells_per_rank=np.bincount(ranks[~is_ghost]),
         ghost_cells=int(is_ghost.sum()))
print("ranks' pieces gathered:", gathered.GetNumberOfCells(), "cells,", len(cell_ids), "owned")
