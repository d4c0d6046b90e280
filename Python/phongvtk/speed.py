"""Speed as a Python user gets it: vtkPolygonNormals and vtkVisibleArea against VTK's own filters,
each filter's ``Update()`` after ``Modified()``, for both SMP backends (one child process each:
VTK's default Sequential, then STDThread on every core).

    python3 -m phongvtk bench --speed          # or: python3 -m phongvtk.speed [--rounds N]

Inputs are bare geometry as a reader delivers it (points and polygons, no arrays): vtkSphereSource
1000 x 1000 (1,996,000 triangles, float points) and CGAL's bunny (75,408 triangles, double points)
when Debian's libcgal-demo is installed. Every filter is warmed up, then timed in rounds, a
different filter first in each round; a sample is a batch of calls lasting at least 20 ms,
after one untimed call of the same filter. The figures are medians of the rounds; ratios are anchor time / PhongVTK time in the same process.
The memory floor of a kernel is the bytes it must read and write over the single-thread copy
bandwidth measured in the same run (numpy copying 256 MiB).

The same calls on the same inputs are timed in C++ by PhongVTKBenchPolygonNormals. This module
imports nothing of PhongVTK's Rendering module, so it also runs against VTK 9.3 and later.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np
from vtkmodules.vtkCommonCore import vtkSMPTools, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals, vtkTriangleMeshPointNormals
from vtkmodules.vtkFiltersModeling import vtkLinearSubdivisionFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource

import phongvtk

from . import io

#: The goals of issues 15 and 16, per VTK generation: (metric, at least).
GOALS = {
    "9.2": {"cells DOUBLE / vtkPolyDataNormals": 40.0, "cells EXACT / vtkPolyDataNormals": 20.0,
            "points DOUBLE / vtkTriangleMeshPointNormals": 5.0,
            "split + consistency DOUBLE / vtkPolyDataNormals defaults": 10.0,
            "split + consistency EXACT / vtkPolyDataNormals defaults": 5.0,
            "split + auto-orient DOUBLE / vtkPolyDataNormals defaults + auto-orient": 10.0,
            "split + auto-orient EXACT / vtkPolyDataNormals defaults + auto-orient": 5.0},
    "9.3+": {"cells DOUBLE / vtkPolyDataNormals": 4.0, "cells EXACT / vtkPolyDataNormals": 2.0,
             "points DOUBLE / vtkTriangleMeshPointNormals": 2.0,
             "points DOUBLE / vtkPolyDataNormals points": 8.0,
             "split + consistency DOUBLE / vtkPolyDataNormals defaults": 3.0,
             "split + auto-orient DOUBLE / vtkPolyDataNormals defaults + auto-orient": 3.0},
}

BATCH_SECONDS = 0.02


def bare(mesh):
    """Points and polygons of `mesh`, nothing else (as a reader of a plain mesh delivers them)."""
    out = vtkPolyData()
    out.SetPoints(mesh.GetPoints())
    out.SetPolys(mesh.GetPolys())
    return out


def meshes():
    """[(name, mesh)]: the sphere, and, when CGAL's meshes are available, the bunny and fandisk
    (a CAD part with creases) refined to 828,544 triangles by three linear subdivisions."""
    source = vtkSphereSource()
    source.SetThetaResolution(1000)
    source.SetPhiResolution(1000)
    source.Update()
    found = [("sphere 2M", bare(source.GetOutput()))]
    path = io.cgal_mesh()
    if path is not None:
        found.append(("bunny", bare(io.read_mesh(path))))
    path = io.cgal_mesh("fandisk.off")
    if path is not None:
        subdivide = vtkLinearSubdivisionFilter()
        subdivide.SetInputData(bare(io.read_mesh(path)))
        subdivide.SetNumberOfSubdivisions(3)
        subdivide.Update()
        found.append(("fandisk 830K", bare(subdivide.GetOutput())))
    return found


def polydata_normals(mesh, points):
    """vtkPolyDataNormals doing what vtkPolygonNormals does: no splitting, no reordering."""
    f = vtkPolyDataNormals()
    f.SetInputData(mesh)
    f.SplittingOff()
    f.ConsistencyOff()
    f.AutoOrientNormalsOff()
    f.SetComputeCellNormals(not points)
    f.SetComputePointNormals(points)
    return f


def polydata_normals_defaults(mesh, auto_orient=False):
    """vtkPolyDataNormals as users run it: splitting at 30 degrees and consistency, and
    optionally AutoOrientNormals."""
    f = vtkPolyDataNormals()
    f.SetInputData(mesh)
    f.SetAutoOrientNormals(auto_orient)
    return f


def polygon_normals(mesh, accuracy, points, piece_invariant=True, split=False, auto_orient=False):
    """vtkPolygonNormals; with split, as vtkPolyDataNormals' defaults: consistency, splitting at
    30 degrees, point normals only; auto_orient adds AutoOrientNormals."""
    f = phongvtk.vtkPolygonNormals()
    f.SetInputData(mesh)
    f.SetAccuracy(accuracy)
    f.SetComputeCellNormals(not points)
    f.SetComputePointNormals(points)
    f.SetPieceInvariant(piece_invariant)
    f.SetSplitting(split)
    f.SetConsistency(split)
    f.SetAutoOrientNormals(auto_orient)
    return f


def visible_area(mesh, accuracy, max_area):
    f = phongvtk.vtkVisibleArea()
    f.SetInputData(mesh)
    f.SetAccuracy(accuracy)
    f.SetViewDirection(1.0, 2.0, 2.0)
    f.SetComputeMaxVisibleArea(max_area)
    return f


def filters_for(mesh):
    """The filters timed on one mesh, by name."""
    N = phongvtk.vtkPolygonNormals
    tmpn = vtkTriangleMeshPointNormals()
    tmpn.SetInputData(mesh)
    return {
        "vtkPolyDataNormals cells": polydata_normals(mesh, False),
        "vtkPolyDataNormals points": polydata_normals(mesh, True),
        "vtkTriangleMeshPointNormals": tmpn,
        "vtkPolyDataNormals defaults": polydata_normals_defaults(mesh),
        "split + consistency DOUBLE": polygon_normals(mesh, N.DOUBLE, True, split=True),
        "split + consistency EXACT": polygon_normals(mesh, N.EXACT, True, split=True),
        "vtkPolyDataNormals defaults + auto-orient": polydata_normals_defaults(mesh, True),
        "split + auto-orient DOUBLE": polygon_normals(mesh, N.DOUBLE, True, True, True, True),
        "split + auto-orient EXACT": polygon_normals(mesh, N.EXACT, True, True, True, True),
        "cells DOUBLE": polygon_normals(mesh, N.DOUBLE, False),
        "cells EXACT": polygon_normals(mesh, N.EXACT, False),
        "points DOUBLE": polygon_normals(mesh, N.DOUBLE, True),
        "points DOUBLE in cell order": polygon_normals(mesh, N.DOUBLE, True, False),
        "points EXACT": polygon_normals(mesh, N.EXACT, True),
        "visible area DOUBLE": visible_area(mesh, N.DOUBLE, False),
        "visible area EXACT": visible_area(mesh, N.EXACT, False),
        "visible area DOUBLE + max": visible_area(mesh, N.DOUBLE, True),
        "visible area EXACT + max": visible_area(mesh, N.EXACT, True),
    }


def run_once(f):
    f.Modified()
    f.Update()


def batch_size(f):
    """Calls per sample so that one sample lasts at least BATCH_SECONDS."""
    start = time.perf_counter()
    run_once(f)
    once = max(time.perf_counter() - start, 1e-6)
    return max(1, int(np.ceil(BATCH_SECONDS / once)))


def time_filters(filters, rounds):
    """Median seconds per call of every filter: warmed up, timed in rotating order."""
    for f in filters.values():
        run_once(f)
        run_once(f)
    batches = {name: batch_size(f) for name, f in filters.items()}
    samples = {name: [] for name in filters}
    order = list(filters)
    for r in range(rounds):
        for name in order[r % len(order):] + order[:r % len(order)]:
            f, k = filters[name], batches[name]
            # One untimed call first: the first call after another filter (or any pause) is
            # several times slower on this project's virtual machine, whose page tables are
            # rebuilt lazily after the address space changes; a warm call is what the C++
            # benchmark's back-to-back iterations time.
            run_once(f)
            start = time.perf_counter()
            for _ in range(k):
                run_once(f)
            samples[name].append((time.perf_counter() - start) / k)
    return {name: statistics.median(values) for name, values in samples.items()}


def copy_bandwidth(rounds=7):
    """Single-thread copy bandwidth in bytes per second (read + write), numpy on 256 MiB."""
    a = np.ones(32 << 20)
    b = np.empty_like(a)
    np.copyto(b, a)
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        np.copyto(b, a)
        times.append(time.perf_counter() - start)
    return 2 * a.nbytes / statistics.median(times)


def touched_bytes(mesh, per_cell, per_point):
    """Bytes a normals kernel must read (points, offsets, connectivity) and write."""
    points = mesh.GetPoints().GetData()
    polys = mesh.GetPolys()
    read = (points.GetNumberOfValues() * points.GetDataTypeSize()
            + polys.GetOffsetsArray().GetNumberOfValues() * polys.GetOffsetsArray().GetDataTypeSize()
            + polys.GetConnectivityArray().GetNumberOfValues()
            * polys.GetConnectivityArray().GetDataTypeSize())
    return read + per_cell * mesh.GetNumberOfCells() + per_point * mesh.GetNumberOfPoints()


def measure(rounds):
    """This process's figures (its SMP backend), as a dict for the parent."""
    bandwidth = copy_bandwidth()
    result = {"vtk": vtkVersion.GetVTKVersion(), "backend": vtkSMPTools.GetBackend(),
              "threads": vtkSMPTools.GetEstimatedNumberOfThreads(), "bandwidth": bandwidth,
              "meshes": []}
    for name, mesh in meshes():
        ms = {k: 1e3 * v for k, v in time_filters(filters_for(mesh), rounds).items()}
        result["meshes"].append({
            "name": name, "cells": mesh.GetNumberOfCells(), "points": mesh.GetNumberOfPoints(),
            "ms": ms,
            "floor cells ms": 1e3 * touched_bytes(mesh, 12, 0) / bandwidth,
            "floor points ms": 1e3 * touched_bytes(mesh, 0, 12) / bandwidth})
    return result


def ratios(m):
    """The derived figures of one mesh: name -> value (ratios: higher is faster for PhongVTK)."""
    ms = m["ms"]
    return {
        "cells DOUBLE / vtkPolyDataNormals": ms["vtkPolyDataNormals cells"] / ms["cells DOUBLE"],
        "cells EXACT / vtkPolyDataNormals": ms["vtkPolyDataNormals cells"] / ms["cells EXACT"],
        "points DOUBLE / vtkTriangleMeshPointNormals":
            ms["vtkTriangleMeshPointNormals"] / ms["points DOUBLE"],
        "points DOUBLE / vtkPolyDataNormals points":
            ms["vtkPolyDataNormals points"] / ms["points DOUBLE"],
        "split + consistency DOUBLE / vtkPolyDataNormals defaults":
            ms["vtkPolyDataNormals defaults"] / ms["split + consistency DOUBLE"],
        "split + consistency EXACT / vtkPolyDataNormals defaults":
            ms["vtkPolyDataNormals defaults"] / ms["split + consistency EXACT"],
        "split + auto-orient DOUBLE / vtkPolyDataNormals defaults + auto-orient":
            ms["vtkPolyDataNormals defaults + auto-orient"] / ms["split + auto-orient DOUBLE"],
        "split + auto-orient EXACT / vtkPolyDataNormals defaults + auto-orient":
            ms["vtkPolyDataNormals defaults + auto-orient"] / ms["split + auto-orient EXACT"],
        "piece-invariant cost (points / in cell order)":
            ms["points DOUBLE"] / ms["points DOUBLE in cell order"],
        "cells DOUBLE x memory floor": ms["cells DOUBLE"] / m["floor cells ms"],
        "points DOUBLE x memory floor": ms["points DOUBLE"] / m["floor points ms"],
        "visible area DOUBLE / cells DOUBLE": ms["visible area DOUBLE"] / ms["cells DOUBLE"],
        "visible area EXACT / cells EXACT": ms["visible area EXACT"] / ms["cells EXACT"],
        "max visible area pass, DOUBLE (ms)":
            ms["visible area DOUBLE + max"] - ms["visible area DOUBLE"],
    }


def child_environment(backend):
    env = dict(os.environ)
    env["VTK_SMP_BACKEND_IN_USE"] = backend
    if backend == "Sequential":
        env.pop("VTK_SMP_MAX_THREADS", None)
    return env


def format_report(results):
    """The table of both backends' figures."""
    first = results[0]
    major, minor = (int(x) for x in first["vtk"].split(".")[:2])
    generation = "9.2" if (major, minor) <= (9, 2) else "9.3+"
    goals = GOALS[generation]
    lines = [f"PhongVTK speed from Python (/usr/bin/python3), VTK {first['vtk']}; "
             f"medians, ratios = VTK time / PhongVTK time in the same process"]
    for backend in results:
        lines.append(f"  {backend['backend']}: {backend['threads']} threads, single-thread copy "
                     f"bandwidth {backend['bandwidth'] / 1e9:.1f} GB/s")
    for index, mesh in enumerate(first["meshes"]):
        lines.append("")
        lines.append(f"{mesh['name']}: {mesh['cells']:,} triangles, {mesh['points']:,} points")
        header = f"  {'':74s}" + "".join(f"{b['backend']:>14s}" for b in results) + "    goal"
        lines.append(header)
        for name in mesh["ms"]:
            row = f"  {name + ' (ms)':74s}" + "".join(
                f"{b['meshes'][index]['ms'][name]:14.2f}" for b in results)
            lines.append(row)
        lines.append(f"  {'memory floor, cells / points (ms)':74s}" + "".join(
            f"{b['meshes'][index]['floor cells ms']:7.2f}/{b['meshes'][index]['floor points ms']:<6.2f}"
            for b in results))
        derived = [ratios(b["meshes"][index]) for b in results]
        for name in derived[0]:
            goal = goals.get(name)
            met = "" if goal is None else (
                f"  >= {goal:g} " + ("met" if all(d[name] >= goal for d in derived) else "NOT met"))
            lines.append(f"  {name:74s}" + "".join(f"{d[name]:14.2f}" for d in derived) + met)
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m phongvtk.speed", description=__doc__.split(
        "\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=7, help="timed rounds (default 7)")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--json", metavar="FILE", help="also write the figures as JSON")
    args = parser.parse_args(argv)
    if args.child:
        json.dump(measure(args.rounds), sys.stdout)
        return 0
    results = []
    for backend in ("Sequential", "STDThread"):
        done = subprocess.run([sys.executable, "-m", "phongvtk.speed", "--child", "--rounds",
                               str(args.rounds)], env=child_environment(backend),
                              stdout=subprocess.PIPE, check=True, text=True)
        results.append(json.loads(done.stdout))
    print(format_report(results), flush=True)
    if args.json:
        with open(args.json, "w") as file:
            json.dump(results, file, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
