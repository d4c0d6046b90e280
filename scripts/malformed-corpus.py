"""Malformed mesh files against the CLI: how many end in a signal instead of a clean error.

    build/bin/phongvtk-python scripts/malformed-corpus.py [--seed N] [--keep DIR]

Writes a small sphere (12 x 8 segments) in every format the CLI reads (PLY, STL and legacy VTK
in ASCII and binary; VTP inline, ASCII and appended; OBJ; OFF), then for each: five truncations
(2, 10, 30, 50, 90 %), eight mutations of 1, 4 or 16 random bytes, and 600 random bytes; and
the EDITS below (counts far beyond the file's size, types no reader knows): 173 files. Each
file goes through `python3 -m phongvtk normals FILE -o OUT` under a 4 GiB address-space limit and
a 60 s timeout. A clean outcome is exit 0, or exit 2 with `phongvtk: error: ...` as the last line
of stderr; every other outcome (a signal, a traceback, a timeout) is listed. Exit status: 1 when
any file was not clean, else 0. Run by Testing/Python/test_hostile_input.py (one seed); other
seeds find other mutations.
"""
import argparse
import os
import random
import resource
import subprocess
import sys
import tempfile

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

TRUNCATIONS = (0.02, 0.1, 0.3, 0.5, 0.9)
MUTATIONS = 8


def valid_files(directory):
    """{file name: bytes} of the sphere in every format the CLI reads."""
    source = vtkSphereSource()
    source.SetThetaResolution(12)
    source.SetPhiResolution(8)
    source.Update()
    mesh = source.GetOutput()
    files = {}
    writers = {
        "ascii.ply": (vtkPLYWriter, lambda w: w.SetFileTypeToASCII()),
        "binary.ply": (vtkPLYWriter, lambda w: w.SetFileTypeToBinary()),
        "ascii.stl": (vtkSTLWriter, lambda w: w.SetFileTypeToASCII()),
        "binary.stl": (vtkSTLWriter, lambda w: w.SetFileTypeToBinary()),
        "ascii.vtk": (vtkPolyDataWriter, lambda w: w.SetFileTypeToASCII()),
        "binary.vtk": (vtkPolyDataWriter, lambda w: w.SetFileTypeToBinary()),
        "inline.vtp": (vtkXMLPolyDataWriter, lambda w: w.SetDataModeToBinary()),
        "ascii.vtp": (vtkXMLPolyDataWriter, lambda w: w.SetDataModeToAscii()),
        "appended.vtp": (vtkXMLPolyDataWriter, lambda w: None),
    }
    for name, (kind, setup) in writers.items():
        writer = kind()
        writer.SetInputData(mesh)
        writer.SetFileName(os.path.join(directory, name))
        setup(writer)
        if writer.Write() != 1:
            raise RuntimeError(f"{kind.__name__} could not write {name}")
        with open(os.path.join(directory, name), "rb") as file:
            files[name] = file.read()
    points = [mesh.GetPoint(i) for i in range(mesh.GetNumberOfPoints())]
    faces = [[mesh.GetCell(c).GetPointId(k) for k in range(mesh.GetCell(c).GetNumberOfPoints())]
             for c in range(mesh.GetNumberOfCells())]
    files["mesh.obj"] = ("".join("v %r %r %r\n" % p for p in points) +
                         "".join("f " + " ".join(str(i + 1) for i in f) + "\n"
                                 for f in faces)).encode()
    files["mesh.off"] = (f"OFF\n{len(points)} {len(faces)} 0\n" +
                         "".join("%r %r %r\n" % p for p in points) +
                         "".join(f"{len(f)} " + " ".join(map(str, f)) + "\n"
                                 for f in faces)).encode()
    return files


#: Counts far beyond what a file holds, and types no reader knows, put into each kind of file:
#: (file name, stem of the case, bytes replaced, replacement); every occurrence is replaced (an
#: offset instead of bytes: the replacement is written there).
EDITS = [
    ("ascii.ply", "oversized", b"element vertex 74", b"element vertex 99999999999"),
    ("binary.ply", "oversized", b"element face 144", b"element face 99999999999"),
    ("binary.ply", "wrongtype", b"property float x", b"property float128 x"),
    ("ascii.ply", "wrongtype", b"list uchar int", b"list uchar string"),
    ("ascii.vtk", "oversized", b"POINTS 74", b"POINTS 99999999999"),
    ("binary.vtk", "oversized", b"POLYGONS 145", b"POLYGONS 99999999999"),
    ("binary.vtk", "wrongtype", b"POINTS 74 float", b"POINTS 74 quux"),
    ("ascii.vtk", "wrongtype", b"vtktypeint64", b"vtktypeint128"),
    ("inline.vtp", "oversized", b'NumberOfPoints="74"', b'NumberOfPoints="99999999999"'),
    ("ascii.vtp", "oversized", b'NumberOfPolys="144"', b'NumberOfPolys="99999999999"'),
    ("appended.vtp", "oversized", b'NumberOfPoints="74"', b'NumberOfPoints="4000000000"'),
    ("inline.vtp", "wrongtype", b'type="Float32"', b'type="Float128"'),
    ("ascii.vtp", "wrongtype", b'type="Int64"', b'type="Banana"'),
    ("mesh.off", "oversized", b"\n74 144 0\n", b"\n74 99999999999 0\n"),
    ("mesh.off", "wrongtype", b"\n3 ", b"\n3.5 "),
    ("mesh.obj", "oversized", b"f 3 ", b"f 99999999999 "),
    ("mesh.obj", "wrongtype", b"v ", b"v x"),
    ("binary.stl", "oversized", 80, b"\xff\xff\xff\x7f"),  # the triangle count
    ("ascii.stl", "wrongtype", b"vertex ", b"vertex x"),
]


def edited(files):
    """[(file name, bytes)]: the EDITS made to the files (each must take)."""
    cases = []
    for name, stem, old, new in EDITS:
        data = files[name]
        if isinstance(old, int):
            data = data[:old] + new + data[old + len(new):]
        elif old in data:
            data = data.replace(old, new)
        else:
            raise RuntimeError(f"{name} has no {old!r} to replace")
        base, ext = os.path.splitext(name)
        cases.append((f"{base}-{stem}{ext}", data))
    return cases


def malformed(files, rng):
    """[(file name, bytes)]: truncations, byte mutations and random bytes of every file."""
    cases = []
    for name, data in files.items():
        stem, ext = os.path.splitext(name)
        for fraction in TRUNCATIONS:
            cases.append((f"{stem}-cut{round(100 * fraction)}{ext}",
                          data[: int(len(data) * fraction)]))
        for k in range(MUTATIONS):
            mutated = bytearray(data)
            for _ in range(rng.choice([1, 4, 16])):
                mutated[rng.randrange(len(mutated))] = rng.randrange(256)
            cases.append((f"{stem}-mutated{k}{ext}", bytes(mutated)))
        cases.append((f"{stem}-random{ext}", bytes(rng.randrange(256) for _ in range(600))))
    return cases


def limit_address_space():
    resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))


def outcome(path, output):
    """None when the CLI handled `path` cleanly, else what happened."""
    try:
        done = subprocess.run([sys.executable, "-m", "phongvtk", "normals", path, "-o", output,
                               "--quiet"], capture_output=True, text=True, errors="replace",
                              timeout=60, preexec_fn=limit_address_space)
    except subprocess.TimeoutExpired:
        return "timeout"
    lines = done.stderr.strip().splitlines()
    if done.returncode == 0 or (done.returncode == 2 and lines and
                                lines[-1].startswith("phongvtk: error: ") and
                                "Traceback" not in done.stderr):
        return None
    return f"exit {done.returncode}: {lines[-1][:120] if lines else ''}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=7, help="of the mutations (default 7)")
    parser.add_argument("--keep", metavar="DIR", help="write the files into DIR and keep them")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        directory = args.keep or scratch
        os.makedirs(directory, exist_ok=True)
        files = valid_files(scratch)
        cases = malformed(files, random.Random(args.seed)) + edited(files)
        failures = 0
        for name, data in cases:
            path = os.path.join(directory, name)
            with open(path, "wb") as file:
                file.write(data)
            what = outcome(path, os.path.join(scratch, "out.vtp"))
            if what:
                failures += 1
                print(f"{name}: {what}")
        print(f"{failures} of {len(cases)} files not handled cleanly")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
