"""Peak memory as a Python user gets it: what one ``Update()`` of vtkPolygonNormals with
vtkPolyDataNormals' defaults (split at 30 degrees + consistency, point normals; and with
AutoOrientNormals) adds to the process at its peak, against vtkPolyDataNormals itself, on the
meshes of :mod:`phongvtk.speed`.

    python3 -m phongvtk.memory

Each filter runs in a child process of its own (VTK's default SMP backend unless
VTK_SMP_BACKEND_IN_USE says otherwise): the mesh is built, the allocator's free memory handed
back (malloc_trim), then the filter updated once. The figure is the peak resident set after the
update (the kernel's high-water mark, VmHWM, reset just before the update through
/proc/self/clear_refs) minus the resident set just before it: the filter's working memory and its
output, in MiB. The output itself (points, polygons and normals the filter hands on) is printed
apart.
"""
import argparse
import ctypes
import json
import subprocess
import sys

from vtkmodules.vtkCommonCore import vtkSMPTools, vtkVersion

import phongvtk

from . import speed

#: The filters measured, by name: a function of the mesh returning the filter.
FILTERS = {
    "vtkPolyDataNormals defaults": lambda mesh: speed.polydata_normals_defaults(mesh),
    "vtkPolyDataNormals defaults + auto-orient":
        lambda mesh: speed.polydata_normals_defaults(mesh, True),
    "split + consistency DOUBLE": lambda mesh: speed.polygon_normals(
        mesh, phongvtk.vtkPolygonNormals.DOUBLE, True, split=True),
    "split + consistency EXACT": lambda mesh: speed.polygon_normals(
        mesh, phongvtk.vtkPolygonNormals.EXACT, True, split=True),
    "split + auto-orient DOUBLE": lambda mesh: speed.polygon_normals(
        mesh, phongvtk.vtkPolygonNormals.DOUBLE, True, True, True, True),
}


def resident_kib(field):
    """A field of /proc/self/status (VmRSS, VmHWM) in KiB."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    raise RuntimeError(f"no {field} in /proc/self/status")


def output_bytes(data):
    """Bytes of the arrays the filter's output holds (shared ones included)."""
    return data.GetActualMemorySize() * 1024


def measure_one(mesh_index, name):
    """The child: (peak MiB added by the update, the output's MiB)."""
    meshes = speed.meshes()
    mesh = meshes[mesh_index][1]
    f = FILTERS[name](mesh)
    ctypes.CDLL("libc.so.6").malloc_trim(0)
    with open("/proc/self/clear_refs", "w") as refs:
        refs.write("5")  # resets VmHWM to the current resident set
    before = resident_kib("VmRSS")
    f.Update()
    peak = resident_kib("VmHWM")
    return {"peak MiB": (peak - before) / 1024,
            "output MiB": output_bytes(f.GetOutput()) / 2**20,
            "backend": vtkSMPTools.GetBackend(), "vtk": vtkVersion.GetVTKVersion()}


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m phongvtk.memory",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("--child", nargs=2, metavar=("MESH", "FILTER"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        json.dump(measure_one(int(args.child[0]), args.child[1]), sys.stdout)
        return 0
    names = [name for name, _ in speed.meshes()]
    rows = []
    for index, mesh_name in enumerate(names):
        for name in FILTERS:
            done = subprocess.run([sys.executable, "-m", "phongvtk.memory", "--child", str(index),
                                   name], stdout=subprocess.PIPE, check=True, text=True)
            result = json.loads(done.stdout)
            rows.append((mesh_name, name, result))
    first = rows[0][2]
    print(f"Peak memory of one Update() (VTK {first['vtk']}, {first['backend']}), MiB:")
    print(f"  {'mesh':14s}{'filter':44s}{'peak added':>12s}{'output':>10s}")
    for mesh_name, name, result in rows:
        print(f"  {mesh_name:14s}{name:44s}{result['peak MiB']:12.1f}{result['output MiB']:10.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
