"""The ParaView plugin, driven through ParaView's own executables (pvpython, pvbatch, mpiexec
pvbatch) as a user drives it. Environment (set by CTest): PHONGVTK_PLUGIN (PhongVTK.so),
PHONGVTK_PVPYTHON, PHONGVTK_PVBATCH, PHONGVTK_MPIEXEC, PHONGVTK_BASELINES, PHONGVTK_INSTALLED_PLUGIN_DIR
(optional: the plugin directory of an installed tree)."""
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
PLUGIN = os.environ["PHONGVTK_PLUGIN"]
PVPYTHON = os.environ["PHONGVTK_PVPYTHON"]
PVBATCH = os.environ["PHONGVTK_PVBATCH"]
MPIEXEC = os.environ.get("PHONGVTK_MPIEXEC", "")
BASELINES = Path(os.environ["PHONGVTK_BASELINES"])

# Lines ParaView's logger marks as errors, and crashes it reports.
ERROR_LINE = re.compile(r"ERR\||FATL\||Loguru caught a signal|Aborting")


def headless_env(**extra):
    env = dict(os.environ)
    env.pop("DISPLAY", None)  # no X server: PhongVTK's headless window or nothing
    env.pop("PHONGVTK_HEADLESS", None)
    env.pop("PV_PLUGIN_PATH", None)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env.update(extra)
    return env


def run(command, env=None, timeout=240):
    done = subprocess.run(command, env=env or headless_env(), capture_output=True, text=True,
                          timeout=timeout)
    log = done.stdout + done.stderr
    assert done.returncode == 0, f"{command} exited {done.returncode}:\n{log}"
    return log


def error_lines(log):
    return [line for line in log.splitlines() if ERROR_LINE.search(line)]


def test_filters_drive_the_vtk_objects_and_follow_the_rule():
    log = run([PVPYTHON, str(HERE / "pv_filters.py"), PLUGIN])
    assert "plugin filters OK" in log
    assert error_lines(log) == []


def read_png(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = vtk_to_numpy(image.GetPointData().GetScalars())
    return scalars.reshape(height, width, -1)[::-1, :, :3].astype(int)


@pytest.mark.parametrize("executable", ["pvbatch", "pvpython"])
def test_phong_surface_renders_headless_like_the_baseline(tmp_path, executable):
    image = tmp_path / "PluginPhongSurface.png"
    log = run([PVBATCH if executable == "pvbatch" else PVPYTHON, str(HERE / "pv_render.py"),
               PLUGIN, str(image)])
    # No abort, and no error at all in the log (ParaView's per-view windows share PhongVTK's
    # headless context and initialise on it).
    assert error_lines(log) == [], "\n".join(error_lines(log))
    baseline = BASELINES / "PluginPhongSurface.png"
    if os.environ.get("PHONGVTK_REGENERATE_BASELINES") == "1" and executable == "pvbatch":
        baseline.write_bytes(image.read_bytes())
    actual, expected = read_png(image), read_png(baseline)
    assert actual.shape == expected.shape == (180, 240, 3)
    difference = np.abs(actual - expected)
    # llvmpipe is deterministic; a few LSB of slack for rasterisation corner cases.
    assert (difference > 4).sum() <= 20, (difference > 4).sum()
    # Independent of the baseline: the background where no sphere is, a blue diffuse sphere with
    # a white highlight above-right of centre (ParaView's light kit: key light up and right).
    assert (actual[2, 2] == [26, 26, 38]).all(), actual[2, 2]
    centre = actual[90, 120]
    assert centre[2] > centre[0] and centre[2] > 150, centre
    sphere = actual[40:140, 70:170]
    brightest = np.unravel_index(sphere.sum(axis=2).argmax(), sphere.shape[:2])
    # The highlight is white: it lifts the red of a blue surface, which its diffuse term cannot.
    assert sphere[brightest][0] > centre[0] + 40, (sphere[brightest], centre)


def test_bad_property_values_are_clear_errors_not_crashes():
    log = run([PVBATCH, str(HERE / "pv_bad_values.py"), PLUGIN])
    assert "bad values handled" in log
    errors = "\n".join(error_lines(log))
    assert "Unknown accuracy 7: expected FAST (0), DOUBLE (1), COMPENSATED (2) or EXACT (3); " \
        "keeping COMPENSATED." in errors, log
    assert "Invalid specular power -5" in errors, log
    assert "Invalid specular coefficient nan" in errors, log
    assert "Unknown shading 9" in errors, log
    assert "GLEW" not in log and "Loguru caught" not in log


# How a batch script leaves, and the status the process must return. sys.exit() in pvbatch and
# pvpython used to free a registry of PhongVTK's contexts twice at exit (ParaView destroys its
# views from a static of libvtkRemotingCore, after the plugin's statics), and Loguru's handler
# then deadlocked: the process never returned.
ENDINGS = {"end": 0, "exit0": 0, "exit3": 3, "raise": 1}


@pytest.mark.parametrize("ending", sorted(ENDINGS))
@pytest.mark.parametrize("executable", ["pvbatch", "pvpython"])
def test_every_way_out_of_a_batch_script_returns_its_status_cleanly(executable, ending):
    for attempt in range(3):
        done = subprocess.run([PVBATCH if executable == "pvbatch" else PVPYTHON,
                               str(HERE / "pv_exit.py"), PLUGIN, ending], env=headless_env(),
                              capture_output=True, text=True, timeout=60)  # a hang fails
        log = done.stdout + done.stderr
        assert done.returncode == ENDINGS[ending], (attempt, done.returncode, log)
        assert "rendered; leaving by" in done.stdout, log
        assert not re.search(r"double free|corrupted|free\(\)|Loguru caught a signal", log), log


def test_plugin_loads_from_pv_plugin_path():
    script = ("from paraview.simple import *\n"
              "assert 'PolygonNormals' in dir(), 'no PolygonNormals'\n"
              "n = PolygonNormals(Input=Sphere())\nn.UpdatePipeline()\n"
              "print('cells', n.GetDataInformation().GetNumberOfCells())\n")
    for directory in [str(Path(PLUGIN).parent), os.environ.get("PHONGVTK_INSTALLED_PLUGIN_DIR")]:
        if not directory:
            continue
        log = run([PVPYTHON, "-c", script], env=headless_env(PV_PLUGIN_PATH=directory))
        assert "cells 96" in log, log
        assert error_lines(log) == []


def write_jittered_sphere(path, reverse_two_in_three=False):
    """Writes the jittered sphere of the distributed tests to `path` (made afresh in pvpython:
    Debian's VTK 9.2 reads no cells back from an appended-mode VTP on a newer expat, so a test
    file is never read back without the plugin's fix loaded)."""
    script = f"""
import numpy as np
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkPoints
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
s = vtkSphereSource(); s.SetThetaResolution(70); s.SetPhiResolution(50); s.Update()
mesh = s.GetOutput()
xyz = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
xyz += np.random.default_rng(7).uniform(-2e-3, 2e-3, xyz.shape)
points = vtkPoints()
points.SetData(numpy_to_vtk(xyz.astype(np.float32), deep=1))
mesh.SetPoints(points)
mesh.GetPointData().Initialize()
for data, name, n in [(mesh.GetPointData(), "OriginalPointId", mesh.GetNumberOfPoints()),
                      (mesh.GetCellData(), "OriginalCellId", mesh.GetNumberOfCells())]:
    ids = numpy_to_vtk(np.arange(n, dtype=np.int64), deep=1, array_type=16)
    ids.SetName(name); data.AddArray(ids)
if {reverse_two_in_three!r}:
    for c in range(mesh.GetNumberOfCells()):
        if c % 3:
            mesh.ReverseCell(c)
w = vtkXMLPolyDataWriter(); w.SetFileName({str(path)!r}); w.SetInputData(mesh); w.Write()
"""
    run([PVPYTHON, "-c", script])
    return path


@pytest.fixture(scope="module")
def distributed_mesh(tmp_path_factory):
    """A jittered sphere (rounding differs by summation order on it: with PieceInvariant off,
    22 points of 3362 differ by an ulp on 2 ranks) with its original ids. Float coordinates:
    ParaView 5.11's GhostCellsGenerator finds no interface between pieces of this mesh when its
    coordinates are doubles that floats cannot represent, and generates no ghost cells."""
    return write_jittered_sphere(tmp_path_factory.mktemp("mesh") / "jittered.vtp")


@pytest.mark.skipif(not MPIEXEC, reason="no mpiexec")
@pytest.mark.parametrize("accuracy,weighting", [("Double", "Area"), ("Exact", "Angle")])
def test_distributed_normals_equal_the_serial_ones_bit_for_bit(tmp_path, distributed_mesh,
                                                               accuracy, weighting):
    script = str(HERE / "pv_distributed_normals.py")
    serial = tmp_path / "serial.npz"
    run([PVBATCH, script, PLUGIN, str(distributed_mesh), str(serial), accuracy, weighting, "0"])
    reference = np.load(serial)
    n_cells, n_points = 70 * 48 * 2, 70 * 48 + 2
    assert sorted(reference["cell_ids"]) == list(range(n_cells))
    assert sorted(reference["point_ids"]) == list(range(n_points))
    for ranks in (2, 3):
        result = tmp_path / f"ranks{ranks}.npz"
        log = run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks), PVBATCH,
                   script, PLUGIN, str(distributed_mesh), str(result), accuracy, weighting, "0"])
        assert error_lines(log) == [], "\n".join(error_lines(log))
        got = np.load(result)
        # The ranks really split the mesh, and the pieces had the ghost layer the filter asks for.
        per_rank = got["owned_cells_per_rank"]
        assert len(per_rank) == ranks and (per_rank > 0).all(), (ranks, per_rank)
        assert per_rank.sum() == n_cells, (ranks, per_rank)
        assert got["ghost_cells"] > 0, ranks
        for kind in ("cell", "point"):
            ids, normals = got[f"{kind}_ids"], got[f"{kind}_normals"]
            expected = reference[f"{kind}_normals"][np.argsort(reference[f"{kind}_ids"])]
            # Every original cell and point is owned somewhere; boundary points may be owned by
            # more than one piece, and every copy must carry the serial normal.
            assert set(ids.tolist()) == set(range(len(expected))), (ranks, kind)
            same = (normals.view(np.int64) == expected[ids].view(np.int64)).all(axis=1)
            assert same.all(), (f"{ranks} ranks: {(~same).sum()} {kind} normals differ from "
                                f"the serial run, e.g. id {ids[~same][:5]}")


def id_normal_pairs(ids, normals):
    """The set of (original point id, the normal's bits) pairs."""
    bits = normals.view(np.int64)
    return {(int(i), tuple(b)) for i, b in zip(ids.tolist(), bits.tolist())}


@pytest.mark.skipif(not MPIEXEC, reason="no mpiexec")
@pytest.mark.parametrize("accuracy", ["Double", "Exact"])
def test_distributed_splitting_gives_the_serial_regions_and_normals(tmp_path, distributed_mesh,
                                                                    accuracy):
    """Split at 30 degrees, each piece with the ghost layer the filter asks for: every point
    region of the serial run, identified by the original id and the normal of its point, is
    found in the pieces, and nothing else is. (Which region of a point keeps the point and which
    get copies depends on the cell numbering, which differs between pieces.)"""
    script = str(HERE / "pv_distributed_normals.py")
    serial = tmp_path / "serial.npz"
    run([PVBATCH, script, PLUGIN, str(distributed_mesh), str(serial), accuracy, "Area", "1"])
    reference = np.load(serial)
    expected = id_normal_pairs(reference["point_ids"], reference["point_normals"])
    n_points = 70 * 48 + 2
    assert len(expected) > n_points, "the mesh must have sharp edges at 30 degrees"
    assert len(reference["point_ids"]) == len(expected)
    for ranks in (2, 3):
        result = tmp_path / f"ranks{ranks}.npz"
        log = run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks), PVBATCH,
                   script, PLUGIN, str(distributed_mesh), str(result), accuracy, "Area", "1"])
        assert error_lines(log) == [], "\n".join(error_lines(log))
        got = np.load(result)
        pairs = id_normal_pairs(got["point_ids"], got["point_normals"])
        assert pairs - expected == set(), (ranks, sorted(pairs - expected)[:3])
        assert expected - pairs == set(), (ranks, sorted(expected - pairs)[:3])


@pytest.fixture(scope="module")
def inside_out_mesh(tmp_path_factory):
    """The distributed mesh with two cells in three reversed (every one in the same order of
    cells, so that no piece holds a consistently outward patch to start from)."""
    return write_jittered_sphere(tmp_path_factory.mktemp("mesh") / "inside_out.vtp", True)


@pytest.mark.skipif(not MPIEXEC, reason="no mpiexec")
def test_distributed_auto_orientation_of_a_closed_convex_surface(tmp_path, distributed_mesh,
                                                                 inside_out_mesh):
    """What holds across pieces: each piece is oriented by itself, so a closed surface cut into
    pieces is oriented by the open-part rule in every piece (its faces turned away from the centre
    of the piece's box). On a convex surface that centre lies inside, and every piece, like the
    serial run, turns every cell outward: the same cell normals, bit for bit."""
    script = str(HERE / "pv_distributed_normals.py")
    serial = tmp_path / "serial.npz"
    run([PVBATCH, script, PLUGIN, str(inside_out_mesh), str(serial), "Double", "Area", "0", "1"])
    reference = np.load(serial)
    expected = reference["cell_normals"][np.argsort(reference["cell_ids"])]
    for ranks in (2, 3):
        result = tmp_path / f"ranks{ranks}.npz"
        log = run([MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks), PVBATCH,
                   script, PLUGIN, str(inside_out_mesh), str(result), "Double", "Area", "0",
                   "1"])
        assert error_lines(log) == [], "\n".join(error_lines(log))
        got = np.load(result)
        ids, normals = got["cell_ids"], got["cell_normals"]
        assert set(ids.tolist()) == set(range(len(expected)))
        same = (normals.view(np.int64) == expected[ids].view(np.int64)).all(axis=1)
        assert same.all(), f"{ranks} ranks: {(~same).sum()} cells oriented otherwise"
    # And outward: every cell as vtkSphereSource made it (outward; jittered cells near the poles
    # folded over keep that), though two in three were reversed.
    source = tmp_path / "source.npz"
    run([PVBATCH, script, PLUGIN, str(distributed_mesh), str(source), "Double", "Area", "0"])
    original = np.load(source)
    original = original["cell_normals"][np.argsort(original["cell_ids"])]
    agree = np.einsum("ij,ij->i", original, expected)
    assert (agree > 0.999).all(), (agree <= 0.999).sum()


def test_presets_look_sensible_in_paraviews_light_kit(tmp_path):
    """Phong Surface's presets on a (0.2, 0.5, 1.0) sphere in ParaView's default light kit, with
    SceneAmbient off and on: hardly any saturated pixel (they washed out to 96% before), and not
    darker than a third of ParaView's own Surface."""
    log = run([PVBATCH, str(HERE / "pv_presets.py"), PLUGIN, str(tmp_path / "presets.png"), "120"])
    assert error_lines(log) == []
    measured = json.loads(log.split("measured:", 1)[1].splitlines()[0])
    surface = measured["Surface, SceneAmbient off"]["median"]
    assert len(measured) == 10
    for name, values in measured.items():
        assert values["clipped"] <= 0.03, (name, values)
        assert values["median"] >= surface / 3, (name, values, surface)
