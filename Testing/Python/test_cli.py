"""The command-line interface, ``python3 -m phongvtk``, run as a user runs it: in a subprocess,
headless (no DISPLAY), on meshes written here by hand (OFF, PLY, STL) whose normals, areas and
images follow from geometry. Outputs are read back and checked against values computed here."""

import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
import pytest
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

import phongvtk
from phongvtk import io as phongvtk_io
from phongvtk.errors import CommandError
from phongvtk.progress import Bar

HAVE_VISIBLE_AREA = hasattr(phongvtk, "vtkVisibleArea")
needs_visible_area = pytest.mark.skipif(
    not HAVE_VISIBLE_AREA, reason="this build of phongvtk has no vtkVisibleArea yet")


# --- running the program ----------------------------------------------------------------------


@pytest.fixture(scope="session")
def environment(tmp_path_factory):
    """The environment of the runs: no X display, and a cache of CGAL's data of our own."""
    env = dict(os.environ)
    # The package the tests import, whatever the working directory of a run.
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(phongvtk.__file__)))
    paths = [os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join([package_parent] + paths)
    env.pop("DISPLAY", None)
    env.pop("PHONGVTK_HEADLESS", None)
    env["XDG_CACHE_HOME"] = str(tmp_path_factory.mktemp("cache"))
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    return env


@pytest.fixture
def phongvtk_cli(environment, tmp_path):
    """Runs ``python3 -m phongvtk ARGS`` in tmp_path; returns the CompletedProcess (text)."""

    def run(*args):
        return subprocess.run(
            [sys.executable, "-m", "phongvtk", *map(str, args)], cwd=tmp_path, env=environment,
            capture_output=True, text=True, timeout=300)

    return run


def expect_clean_error(result, *words):
    """Exit status 2 and exactly one line on stderr, ``phongvtk: error: ...`` with `words`."""
    assert result.returncode == 2, result
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("phongvtk: error: "), lines
    for word in words:
        assert word in lines[0], (word, lines[0])


# --- meshes written by hand -------------------------------------------------------------------

# The unit cube [0, 1]^3, six quads counter-clockwise seen from outside.
CUBE_POINTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
               (0, 1, 1)]
CUBE_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (0, 4, 7, 3), (1, 2, 6, 5)]
CUBE_NORMALS = [(0, 0, -1), (0, 0, 1), (0, -1, 0), (0, 1, 0), (-1, 0, 0), (1, 0, 0)]


def uv_sphere(radius=1.0, rings=16, segments=32):
    """A sphere with poles on the y axis: triangles at the poles, quads between, all
    counter-clockwise seen from outside. Returns (points, faces)."""
    points = [(0.0, radius, 0.0)]
    for k in range(1, rings):
        phi = math.pi * k / rings
        for i in range(segments):
            theta = 2 * math.pi * i / segments
            points.append((radius * math.sin(phi) * math.sin(theta), radius * math.cos(phi),
                           radius * math.sin(phi) * math.cos(theta)))
    points.append((0.0, -radius, 0.0))

    def ring(k, i):  # point i of ring k (1 ... rings - 1, from the north pole)
        return 1 + (k - 1) * segments + i % segments

    south = len(points) - 1
    faces = [(0, ring(1, i), ring(1, i + 1)) for i in range(segments)]
    for k in range(1, rings - 1):
        faces += [(ring(k, i + 1), ring(k, i), ring(k + 1, i), ring(k + 1, i + 1))
                  for i in range(segments)]
    faces += [(south, ring(rings - 1, i + 1), ring(rings - 1, i)) for i in range(segments)]
    return points, faces


def write_off(path, points, faces, header="OFF"):
    lines = [header, f"{len(points)} {len(faces)} 0"]
    lines += [" ".join(repr(float(c)) for c in p) for p in points]
    lines += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def write_ply(path, points, faces):
    header = ["ply", "format ascii 1.0", f"element vertex {len(points)}", "property double x",
              "property double y", "property double z", f"element face {len(faces)}",
              "property list uchar int vertex_indices", "end_header"]
    body = [" ".join(repr(float(c)) for c in p) for p in points]
    body += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    path.write_text("\n".join(header + body) + "\n")
    return path


def write_stl(path, triangles):
    """ASCII STL of triangles given by their corners (the facet normals are not used)."""
    lines = ["solid test"]
    for corners in triangles:
        lines += ["facet normal 0 0 0", "outer loop"]
        lines += ["vertex " + " ".join(repr(float(c)) for c in corner) for corner in corners]
        lines += ["endloop", "endfacet"]
    lines.append("endsolid test")
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.fixture
def sphere_off(tmp_path):
    return write_off(tmp_path / "sphere.off", *uv_sphere())


@pytest.fixture
def cube_ply(tmp_path):
    return write_ply(tmp_path / "cube.ply", CUBE_POINTS, CUBE_FACES)


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def read_png(path):
    """The PNG at `path` as an int array rows x columns x channels, top row first."""
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    values = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars())
    return values.reshape(height, width, -1)[::-1].astype(int)


def cell_centroids(mesh):
    points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    polys = mesh.GetPolys()
    offsets = numpy_support.vtk_to_numpy(polys.GetOffsetsArray())
    connectivity = numpy_support.vtk_to_numpy(polys.GetConnectivityArray())
    return np.array([points[connectivity[a:b]].mean(axis=0)
                     for a, b in zip(offsets[:-1], offsets[1:])])


# --- help -------------------------------------------------------------------------------------


def test_help_lists_every_command(phongvtk_cli):
    result = phongvtk_cli("--help")
    assert result.returncode == 0
    for command in ("render", "normals", "area", "bench", "demo"):
        assert command in result.stdout


@pytest.mark.parametrize("command", ["render", "normals", "area", "bench", "demo"])
def test_each_command_has_help(phongvtk_cli, command):
    result = phongvtk_cli(command, "--help")
    assert result.returncode == 0
    assert result.stdout.startswith(f"usage: phongvtk {command}")


def test_version(phongvtk_cli):
    result = phongvtk_cli("--version")
    assert result.returncode == 0
    assert result.stdout.startswith(f"phongvtk {phongvtk.__version__}")


def test_no_command_is_a_usage_error(phongvtk_cli):
    assert phongvtk_cli().returncode == 2


# --- render -----------------------------------------------------------------------------------


def lambert(light=(0, 0, 1)):
    """Options for a white, purely diffuse surface under one white light from `light`, no
    ambient light, parallel projection, a blue background: a pixel shows max(n.l, 0)."""
    return ["--preset", "none", "--color", "1", "1", "1", "--ambient", "0", "--diffuse", "1",
            "--specular", "0", "--scene-ambient", "0", "0", "0", "--light", *map(str, light),
            "--background", "0", "0", "0.5", "--parallel"]


WIDTH, HEIGHT = 160, 120


@pytest.fixture(scope="module")
def images(tmp_path_factory, environment):
    """The unit sphere rendered in each shading mode under lambert() (rendered once)."""
    directory = tmp_path_factory.mktemp("render")
    mesh = write_off(directory / "sphere.off", *uv_sphere())
    result = {}
    for shading in ("flat", "gouraud", "phong"):
        output = directory / f"{shading}.png"
        run = subprocess.run(
            [sys.executable, "-m", "phongvtk", "render", str(mesh), "-o", str(output),
             "--shading", shading, "--size", str(WIDTH), str(HEIGHT), *lambert()],
            env=environment, capture_output=True, text=True, timeout=120)
        assert run.returncode == 0, run.stderr
        result[shading] = read_png(output)
    return result


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_render_writes_an_image_of_the_requested_size(images, shading):
    image = images[shading]
    assert image.shape == (HEIGHT, WIDTH, 3)
    assert image.std() > 10  # not blank


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_render_corners_show_the_background(images, shading):
    for corner in (images[shading][0, 0], images[shading][-1, -1]):
        assert np.abs(corner - [0, 0, 128]).max() <= 1, corner


def test_render_phong_pixels_follow_the_sphere(images):
    # The camera frames the bounding sphere of the mesh's bounds (radius sqrt(3) for the unit
    # sphere) in the image height: the sphere's silhouette has radius HEIGHT / (2 sqrt(3)).
    image = images["phong"]
    radius = HEIGHT / (2 * math.sqrt(3))
    cx, cy = WIDTH / 2, HEIGHT / 2
    for dx in (0, 10, 20, 28):
        x, y = int(cx + dx), int(cy)
        rho = math.hypot(x + 0.5 - cx, y + 0.5 - cy) / radius
        expected = 255 * math.sqrt(1 - rho * rho)
        assert abs(image[y, x].mean() - expected) <= 6, (dx, image[y, x], expected)


def test_render_flat_differs_from_phong(images):
    assert np.abs(images["flat"] - images["phong"]).max() > 20


def test_render_light_from_behind_leaves_the_front_dark(phongvtk_cli, sphere_off, tmp_path):
    result = phongvtk_cli("render", sphere_off, "-o", "dark.png", "--size", 64, 48,
                          *lambert(light=(0, 0, -1)))
    assert result.returncode == 0, result.stderr
    assert read_png(tmp_path / "dark.png")[24, 32].max() <= 1


def test_render_accepts_materials_lights_and_camera(phongvtk_cli, sphere_off, tmp_path):
    result = phongvtk_cli("render", sphere_off, "-o", "metal.png", "--size", 64, 64,
                          "--preset", "metal", "--light", 1, 1, 1, 1, 0, 0, "--light", -1, 0, 1,
                          "--azimuth", 30, "--elevation", 90, "--accuracy", "exact",
                          "--weighting", "max", "--zoom", 1.5, "--derived-ambient")
    assert result.returncode == 0, result.stderr
    assert read_png(tmp_path / "metal.png").shape == (64, 64, 3)


@pytest.mark.parametrize("light, words", [((1, 2, 3, 4), "X Y Z or X Y Z R G B"),
                                          (("a", 0, 1), "not a number: 'a'"),
                                          ((0, 0, 0), "must not be zero")])
def test_render_rejects_a_bad_light(phongvtk_cli, sphere_off, light, words):
    result = phongvtk_cli("render", sphere_off, "-o", "x.png", "--light", *light)
    assert result.returncode == 2
    assert words in result.stderr
    assert "Traceback" not in result.stderr


# --- normals ----------------------------------------------------------------------------------


def test_normals_of_a_sphere_point_outward(phongvtk_cli, sphere_off, tmp_path):
    result = phongvtk_cli("normals", sphere_off, "-o", "out.vtp", "--point-normals", "--areas",
                          "--area-vectors", "--status", "--accuracy", "exact")
    assert result.returncode == 0, result.stderr
    mesh = read_vtp(tmp_path / "out.vtp")
    cells, points = mesh.GetCellData(), mesh.GetPointData()
    for name in ("Normals", "AreaVectors", "Areas", "NormalStatus"):
        assert cells.GetArray(name) is not None, name
    cell_normals = numpy_support.vtk_to_numpy(cells.GetArray("Normals"))
    assert (np.einsum("ij,ij->i", cell_normals, cell_centroids(mesh)) > 0).all()
    point_normals = numpy_support.vtk_to_numpy(points.GetArray("Normals"))
    positions = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData())
    assert (np.einsum("ij,ij->i", point_normals, positions) > 0.99).all()
    assert not numpy_support.vtk_to_numpy(cells.GetArray("NormalStatus")).any()
    areas = numpy_support.vtk_to_numpy(cells.GetArray("Areas"))
    assert 0.97 * 4 * math.pi < areas.sum() < 4 * math.pi  # inscribed polyhedron


def test_normals_of_a_cube_are_the_axes(phongvtk_cli, cube_ply, tmp_path):
    result = phongvtk_cli("normals", cube_ply, "-o", "cube.vtp", "--precision", "double")
    assert result.returncode == 0, result.stderr
    normals = read_vtp(tmp_path / "cube.vtp").GetCellData().GetArray("Normals")
    assert normals.GetDataTypeAsString() == "double"
    assert numpy_support.vtk_to_numpy(normals).tolist() == [list(map(float, n))
                                                            for n in CUBE_NORMALS]


def test_normals_options_turn_arrays_off_and_on(phongvtk_cli, cube_ply, tmp_path):
    result = phongvtk_cli("normals", cube_ply, "-o", "points.vtp", "--no-cell-normals",
                          "--point-normals", "--weighting", "angle", "--no-splitting")
    assert result.returncode == 0, result.stderr
    mesh = read_vtp(tmp_path / "points.vtp")
    assert mesh.GetCellData().GetArray("Normals") is None
    normals = numpy_support.vtk_to_numpy(mesh.GetPointData().GetArray("Normals"))
    assert normals.dtype == np.float32  # single precision by default
    corners = np.array(CUBE_POINTS, dtype=float) - 0.5
    expected = corners / np.linalg.norm(corners, axis=1)[:, None]  # angle weights: symmetric
    assert np.abs(normals - expected).max() < 1e-6


def test_normals_split_at_30_degrees_by_default(phongvtk_cli, cube_ply, tmp_path):
    # The cube's 90 degree edges are sharp at the default feature angle: each corner becomes
    # three points, one per face, each with its face's normal.
    assert phongvtk_cli("normals", cube_ply, "-o", "split.vtp", "--point-normals").returncode == 0
    mesh = read_vtp(tmp_path / "split.vtp")
    assert mesh.GetNumberOfPoints() == 24
    normals = numpy_support.vtk_to_numpy(mesh.GetPointData().GetArray("Normals"))
    assert sorted(map(tuple, np.abs(normals).tolist())) == sorted(
        [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)] * 8)
    original = numpy_support.vtk_to_numpy(mesh.GetPointData().GetArray("OriginalPointIds"))
    assert sorted(original.tolist()) == sorted(list(range(8)) * 3)
    # Wider than 90 degrees, or no splitting: the eight corners stay.
    for options in (("--feature-angle", "90.5"), ("--no-splitting",)):
        assert phongvtk_cli("normals", cube_ply, "-o", "whole.vtp", "--point-normals",
                            *options).returncode == 0
        assert read_vtp(tmp_path / "whole.vtp").GetNumberOfPoints() == 8


def test_normals_consistency_and_flip(phongvtk_cli, tmp_path):
    # The cube with two faces reversed: --consistency makes every face agree with the first
    # (outward), --flip then turns every face and normal inward.
    faces = [list(f) for f in CUBE_FACES]
    for k in (3, 4):
        faces[k] = [faces[k][0]] + faces[k][:0:-1]
    scrambled = write_ply(tmp_path / "scrambled.ply", CUBE_POINTS, faces)
    outward = np.array(CUBE_NORMALS, dtype=float)
    for options, expected in (((), outward * [[1], [1], [1], [-1], [-1], [1]]),
                              (("--consistency",), outward),
                              (("--consistency", "--flip"), -outward)):
        assert phongvtk_cli("normals", scrambled, "-o", "out.vtp", "--precision", "double",
                            *options).returncode == 0
        mesh = read_vtp(tmp_path / "out.vtp")
        normals = numpy_support.vtk_to_numpy(mesh.GetCellData().GetArray("Normals"))
        assert (normals == expected).all(), options


def test_normals_auto_orient_turns_an_inside_out_cube_outward(phongvtk_cli, tmp_path):
    # Every face reversed: --consistency keeps them all inward (they agree), --auto-orient turns
    # the cube outward by the sign of its volume, --flip on top turns it back.
    faces = [[f[0]] + list(f[:0:-1]) for f in CUBE_FACES]
    inside_out = write_ply(tmp_path / "inside_out.ply", CUBE_POINTS, faces)
    outward = np.array(CUBE_NORMALS, dtype=float)
    for options, expected in ((("--consistency",), -outward), (("--auto-orient",), outward),
                              (("--auto-orient", "--flip"), -outward)):
        assert phongvtk_cli("normals", inside_out, "-o", "out.vtp", "--precision", "double",
                            *options).returncode == 0
        mesh = read_vtp(tmp_path / "out.vtp")
        normals = numpy_support.vtk_to_numpy(mesh.GetCellData().GetArray("Normals"))
        assert (normals == expected).all(), options


@pytest.mark.parametrize("angle", ["-1", "180.5", "nan"])
def test_feature_angle_outside_0_to_180_is_a_usage_error(phongvtk_cli, cube_ply, angle):
    result = phongvtk_cli("normals", cube_ply, "-o", "x.vtp", "--feature-angle", angle)
    assert result.returncode == 2
    assert "--feature-angle" in result.stderr.splitlines()[-1]


def test_render_keeps_creases_sharp_under_phong_shading(phongvtk_cli, cube_ply, tmp_path):
    # A cube seen along a diagonal: with split normals every face is flat, so Phong shading
    # equals flat shading; averaged across the edges it does not.
    images = {}
    for name, options in (("flat", ("--shading", "flat")), ("phong", ()),
                          ("smooth", ("--no-splitting",))):
        result = phongvtk_cli("render", cube_ply, "-o", f"{name}.png", "--azimuth", "30",
                              "--elevation", "25", "--size", "160", "120", *options)
        assert result.returncode == 0, result.stderr
        images[name] = read_png(tmp_path / f"{name}.png").astype(int)
    assert np.abs(images["phong"] - images["flat"]).max() <= 1
    assert np.abs(images["smooth"] - images["flat"]).max() > 20


def test_normals_writes_legacy_vtk_by_extension(phongvtk_cli, cube_ply, tmp_path):
    assert phongvtk_cli("normals", cube_ply, "-o", "cube.vtk").returncode == 0
    reader = vtkPolyDataReader()
    reader.SetFileName(str(tmp_path / "cube.vtk"))
    reader.Update()
    assert reader.GetOutput().GetCellData().GetArray("Normals").GetNumberOfTuples() == 6


def test_normals_rejects_an_unknown_output_format(phongvtk_cli, cube_ply):
    expect_clean_error(phongvtk_cli("normals", cube_ply, "-o", "cube.xyz", "-q"), "cube.xyz")


# --- area -------------------------------------------------------------------------------------


def area_json(phongvtk_cli, mesh, *args):
    result = phongvtk_cli("area", mesh, "--json", "-q", *args)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


@needs_visible_area
def test_area_of_a_cube_seen_along_z(phongvtk_cli, cube_ply):
    report = area_json(phongvtk_cli, cube_ply, "--view", 0, 0, 1)
    assert report["total_visible_area"] == pytest.approx(1.0, abs=1e-15)
    assert report["max_visible_area"] == 0.0  # closed: exactly zero
    assert report["max_visible_area_direction"] == [0.0, 0.0, 0.0]
    assert (report["front_cells"], report["back_cells"], report["edge_on_cells"]) == (1, 1, 4)


@needs_visible_area
def test_area_of_a_cube_seen_along_a_diagonal(phongvtk_cli, cube_ply):
    report = area_json(phongvtk_cli, cube_ply, "--view", 1, 1, 0, "--accuracy", "exact")
    assert report["total_visible_area"] == pytest.approx(math.sqrt(2), rel=1e-15)
    assert report["accuracy"] == "EXACT"


@needs_visible_area
def test_area_perspective_camera_sees_the_sides_from_behind(phongvtk_cli, cube_ply):
    # The eye on the +z axis: every side face turns its back to it; under parallel projection
    # along z the sides are exactly edge-on.
    perspective = area_json(phongvtk_cli, cube_ply, "--azimuth", 0)
    assert perspective["total_visible_area"] == pytest.approx(1.0, rel=1e-12)
    assert (perspective["front_cells"], perspective["back_cells"]) == (1, 5)
    parallel = area_json(phongvtk_cli, cube_ply, "--azimuth", 0, "--parallel")
    assert (parallel["front_cells"], parallel["edge_on_cells"]) == (1, 4)


@needs_visible_area
def test_area_of_an_open_square_looks_largest_along_its_normal(phongvtk_cli, tmp_path):
    square = [((0, 0, 0), (1, 0, 0), (1, 1, 0)), ((0, 0, 0), (1, 1, 0), (0, 1, 0))]
    mesh = write_stl(tmp_path / "square.stl", square)
    back = area_json(phongvtk_cli, mesh, "--view", 0, 0, -2)
    assert back["total_visible_area"] == 0.0
    assert back["back_cells"] == 2
    assert back["max_visible_area"] == pytest.approx(1.0, rel=1e-15)
    assert back["max_visible_area_direction"] == [0.0, 0.0, 1.0]


@needs_visible_area
def test_area_prints_a_summary_and_writes_the_cell_array(phongvtk_cli, cube_ply, tmp_path):
    result = phongvtk_cli("area", cube_ply, "-o", "area.vtp")
    assert result.returncode == 0, result.stderr
    assert "total visible area:" in result.stdout
    visible = read_vtp(tmp_path / "area.vtp").GetCellData().GetArray("VisibleArea")
    assert numpy_support.vtk_to_numpy(visible).tolist() == [-1.0, 1.0, 0.0, 0.0, 0.0, 0.0]


def test_area_rejects_a_zero_view(phongvtk_cli, cube_ply):
    if HAVE_VISIBLE_AREA:
        expect_clean_error(phongvtk_cli("area", cube_ply, "--view", 0, 0, 0, "-q"), "--view")
    else:
        expect_clean_error(phongvtk_cli("area", cube_ply, "-q"), "vtkVisibleArea")


# --- bench and demo ---------------------------------------------------------------------------


def test_bench_quick_prints_both_tables_and_writes_plots(phongvtk_cli, tmp_path):
    pytest.importorskip("matplotlib")
    result = phongvtk_cli("bench", "--quick", "--plot-dir", "plots")
    assert result.returncode == 0, result.stderr
    for mode in ("FAST", "DOUBLE", "COMPENSATED", "EXACT"):
        assert f"| {mode}" in result.stdout
    assert "needles, aspect 1e12" in result.stdout
    assert "Phong rms/max" in result.stdout
    for plot in ("normals-ladder.png", "shading-error-vs-tessellation.png"):
        assert read_png(tmp_path / "plots" / plot).shape[0] > 100


class CountingFilter:
    """Stands in for a VTK filter in the speed harness: counts its updates, each lasting longer
    than the harness's batch (so a batch is one call)."""

    def __init__(self):
        self.updates = 0

    def Modified(self):
        pass

    def Update(self):
        time.sleep(0.025)
        self.updates += 1


def test_memory_harness_measures_a_filters_peak_in_a_child(environment):
    # The sphere (mesh 0, always there): one Update()'s peak is at least what the split mesh's
    # point normals and polygons take, and the output's arrays are counted apart.
    done = subprocess.run([sys.executable, "-m", "phongvtk.memory", "--child", "0",
                           "split + consistency DOUBLE"], env=environment, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    normals_mib = 998002 * 3 * 4 / 2**20  # the point normals alone, float
    assert result["peak MiB"] > normals_mib
    assert result["output MiB"] > normals_mib
    assert result["backend"] in ("Sequential", "STDThread", "TBB", "OpenMP")  # Debian's VTK 9.1: TBB


def test_speed_harness_warms_up_and_calls_untimed_before_every_batch():
    from phongvtk import speed
    filters = {"a": CountingFilter(), "b": CountingFilter()}
    assert speed.batch_size(CountingFilter()) == 1
    speed.time_filters(filters, rounds=2)
    for f in filters.values():
        # Two warm-up calls, one to size the batch, then per round one untimed call and the
        # batch of one.
        assert f.updates == 2 + 1 + 2 * 2


def speed_result(vtk, pdn_cells, cells, exact, tmpn, points, in_cell_order):
    ms = {"vtkPolyDataNormals cells": pdn_cells, "cells DOUBLE": cells, "cells EXACT": exact,
          "vtkTriangleMeshPointNormals": tmpn, "vtkPolyDataNormals points": 10 * tmpn,
          "points DOUBLE": points, "points DOUBLE in cell order": in_cell_order,
          "visible area DOUBLE": cells, "visible area EXACT": exact,
          "visible area DOUBLE + max": 3 * cells, "vtkPolyDataNormals defaults": 30 * points,
          "split + consistency DOUBLE": 2 * points, "split + consistency EXACT": 4 * points,
          "vtkPolyDataNormals defaults + auto-orient": 40 * points,
          "split + auto-orient DOUBLE": 2 * points, "split + auto-orient EXACT": 5 * points}
    mesh = {"name": "m", "cells": 8, "points": 6, "ms": ms, "floor cells ms": 1.0,
            "floor points ms": 1.0}
    return {"vtk": vtk, "backend": "Sequential", "threads": 1, "bandwidth": 1e10,
            "meshes": [mesh]}


def goal_lines(report):
    """The report's ratio lines that carry a goal, by ratio name."""
    return {line[2:76].strip(): line for line in report.splitlines()
            if line.startswith("  ") and ">=" in line}


def test_speed_report_marks_each_goal_for_its_vtk_generation():
    from phongvtk import speed
    # VTK 9.2: cells 50x (goal 40), EXACT 10x (goal 20), points 6x TMPN (goal 5).
    lines = goal_lines(speed.format_report(
        [speed_result("9.2.20230111", 500.0, 10.0, 50.0, 60.0, 10.0, 5.0)]))
    assert lines["cells DOUBLE / vtkPolyDataNormals"].endswith(">= 40 met")
    assert lines["cells EXACT / vtkPolyDataNormals"].endswith(">= 20 NOT met")
    assert lines["points DOUBLE / vtkTriangleMeshPointNormals"].endswith(">= 5 met")
    assert "points DOUBLE / vtkPolyDataNormals points" not in lines  # no goal against 9.2
    # Splitting and consistency against vtkPolyDataNormals' defaults: 15x (10), 7.5x (5).
    assert lines["split + consistency DOUBLE / vtkPolyDataNormals defaults"].endswith(">= 10 met")
    assert lines["split + consistency EXACT / vtkPolyDataNormals defaults"].endswith(">= 5 met")
    # With AutoOrientNormals on both sides: 20x (10), 8x (5).
    assert lines["split + auto-orient DOUBLE / vtkPolyDataNormals defaults + auto-orient"
                 ].endswith(">= 10 met")
    assert lines["split + auto-orient EXACT / vtkPolyDataNormals defaults + auto-orient"
                 ].endswith(">= 5 met")
    # VTK 9.6: cells 5x (4), EXACT 2.5x (2), points 1.5x TMPN (2), 15x PDN points (8).
    lines = goal_lines(speed.format_report(
        [speed_result("9.6.2", 50.0, 10.0, 20.0, 15.0, 10.0, 5.0)]))
    assert lines["cells DOUBLE / vtkPolyDataNormals"].endswith(">= 4 met")
    assert lines["cells EXACT / vtkPolyDataNormals"].endswith(">= 2 met")
    assert lines["points DOUBLE / vtkTriangleMeshPointNormals"].endswith(">= 2 NOT met")
    assert lines["points DOUBLE / vtkPolyDataNormals points"].endswith(">= 8 met")
    assert lines["split + consistency DOUBLE / vtkPolyDataNormals defaults"].endswith(">= 3 met")


def test_bench_exact_mode_is_faithful_on_the_sample(phongvtk_cli, sphere_off):
    result = phongvtk_cli("bench", "--quick", "--only", "normals", "--mesh", sphere_off)
    assert result.returncode == 0, result.stderr
    for row in result.stdout.splitlines():
        if "| EXACT" in row:
            worst_ulp = float(row.split("|")[6].split()[0])
            assert worst_ulp <= 1.0, row


def test_demo_prints_both_tables_and_where_the_picture_is(phongvtk_cli, tmp_path):
    result = phongvtk_cli("demo", "--quick", "--size", 64, 48, "-o", "demo.png")
    assert result.returncode == 0, result.stderr
    assert read_png(tmp_path / "demo.png").shape == (2 * 48, 4 * 64, 3)
    assert "| EXACT" in result.stdout and "tiny, x 2^-1000" in result.stdout
    assert "Phong    reaches 1 LSB RMS" in result.stdout
    assert result.stdout.strip().splitlines()[-1].startswith(f"picture: {tmp_path / 'demo.png'}")


def panel_rms(a, b):
    """RMS difference of two panels in 8-bit LSB."""
    return float(np.sqrt(np.mean((a.astype(float) - b.astype(float)) ** 2)))


def test_demo_picture_shows_phong_shading_a_coarse_mesh_like_the_fine_one(phongvtk_cli, tmp_path):
    """Panels: flat, Gouraud, Phong of a coarse mesh, then Phong of the fine one; the bunny
    (decimated, whole) above a torus (576 triangles, 131,072). On the smooth torus the coarse
    Phong panel is closer to the fine one than the coarse flat and Gouraud panels are. (On the
    bunny it is not, by pixels: its whole mesh has bumps a row of 2,000 triangles cannot hold,
    and flat facets keep more of them than interpolated normals do.)"""
    size = 160
    result = phongvtk_cli("demo", "--no-table", "--size", size, size, "-o", "demo.png")
    assert result.returncode == 0, result.stderr
    image = read_png(tmp_path / "demo.png")
    assert image.shape == (2 * size, 4 * size, 3)
    label = size // 4  # the rows of each panel below its two-line label

    def panel(row, column):
        return image[row * size + label:(row + 1) * size, column * size:(column + 1) * size]

    for row in (0, 1):
        assert panel_rms(panel(row, 0), panel(row, 2)) > 5.0, row  # coarse flat, coarse Phong
    flat, gouraud, phong, fine = (panel(1, column) for column in range(4))
    assert panel_rms(phong, fine) < 0.8 * panel_rms(flat, fine)
    assert panel_rms(phong, fine) < panel_rms(gouraud, fine)


def test_launcher_runs_the_cli_with_nothing_set(environment, sphere_off, tmp_path):
    default = os.path.join(os.path.dirname(os.path.abspath(phongvtk.__file__)), "..", "..", "..",
                           "..", "bin", "phongvtk")
    launcher = os.environ.get("PHONGVTK_LAUNCHER", default)
    env = {key: value for key, value in environment.items() if key != "PYTHONPATH"}
    result = subprocess.run([launcher, "normals", "sphere.off", "-o", "out.vtp", "-q"],
                            cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert read_vtp(tmp_path / "out.vtp").GetNumberOfPolys() == len(uv_sphere()[1])


# --- reading meshes ---------------------------------------------------------------------------

OFF_WITH_EVERYTHING = """\
# a comment before the header
COFF   # the header may carry a comment

5 3 0
0 0 0   255 0 0 255
1 0 0
1 1 0
0 1 0
0.5 0.5 1e0
# faces: a quad, a triangle with a colour, a triangle
4 0 1 2 3
3 0 1 4 0.5 0.5 0.5 1.0

3 1 2 4
"""


def test_off_reader_understands_comments_quads_and_colours():
    points, offsets, connectivity = phongvtk_io.parse_off(OFF_WITH_EVERYTHING)
    assert points.tolist() == [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]]
    assert offsets.tolist() == [0, 4, 7, 10]
    assert connectivity.tolist() == [0, 1, 2, 3, 0, 1, 4, 1, 2, 4]


@pytest.mark.parametrize("text", ["3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",  # no header
                                  "NOFF 3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"])
def test_off_reader_takes_the_counts_without_or_on_the_header_line(text):
    points, offsets, _ = phongvtk_io.parse_off(text)
    assert (len(points), len(offsets) - 1) == (3, 1)


@pytest.mark.parametrize("text, words", [
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n", "vertex 2 of 3"),
    ("OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n", "vertex 1"),
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "vertex index 7"),
    ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "n >= 3"),
    ("4OFF\n3 1 0\n", "'4OFF' is not supported"),
    ("hello world\n", "expected the OFF header"),
])
def test_off_reader_reports_the_line_of_a_malformed_file(text, words):
    with pytest.raises(CommandError) as error:
        phongvtk_io.parse_off(text, "m.off")
    assert words in str(error.value)


def test_off_file_through_the_command_line(phongvtk_cli, tmp_path):
    (tmp_path / "mixed.off").write_text(OFF_WITH_EVERYTHING)
    result = phongvtk_cli("normals", "mixed.off", "-o", "mixed.vtp", "--precision", "double")
    assert result.returncode == 0, result.stderr
    mesh = read_vtp(tmp_path / "mixed.vtp")
    assert [mesh.GetCell(i).GetNumberOfPoints() for i in range(3)] == [4, 3, 3]
    normals = numpy_support.vtk_to_numpy(mesh.GetCellData().GetArray("Normals"))
    assert normals[0].tolist() == [0.0, 0.0, 1.0]
    assert normals[1] == pytest.approx([0.0, -2 / math.sqrt(5), 1 / math.sqrt(5)], rel=1e-15)


def test_malformed_off_is_a_clean_error(phongvtk_cli, tmp_path):
    (tmp_path / "bad.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n")
    expect_clean_error(phongvtk_cli("render", "bad.off", "-o", "x.png"), "bad.off:6",
                       "vertex index 9")


# --- PLY headers against the file's size ---------------------------------------------------
# vtkPLYReader allocates what a header declares and reads on past the end of a shorter file: a
# header of 10^11 vertices with no data was a segmentation fault, a binary file cut after its
# header a heap corruption (free(): invalid pointer). The CLI checks the header first.

PLY_HEADER_BINARY = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                     b"property float x\nproperty float y\nproperty float z\nelement face 1\n"
                     b"property list uchar int vertex_indices\nend_header\n")


@pytest.mark.parametrize("content, words", [
    (b"ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\n"
     b"property float y\nproperty float z\nend_header\n", ["at least 299999999997 bytes", "has 0"]),
    (PLY_HEADER_BINARY + bytes(20), ["at least 37 bytes", "has 20"]),
    (PLY_HEADER_BINARY + bytes(36), ["at least 37 bytes", "has 36"]),
    (PLY_HEADER_BINARY.replace(b"float z", b"float128 z") + bytes(64), ["line 6", "float128"]),
    (PLY_HEADER_BINARY.replace(b"vertex 3", b"vertex -3"), ["line 3", "element NAME COUNT"]),
    # Elements without properties take no bytes: vtkPLYReader allocated 10^11 of them (SIGSEGV,
    # or an abort for faces).
    (b"ply\nformat ascii 1.0\nelement vertex 99999999999\nend_header\n",
     ["line 3", "without properties"]),
    (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
     b"property float z\nelement face 99999999999\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
     ["line 7", "without properties", "face 99999999999"]),
    # ASCII cut short: enough bytes for one character a value, too few lines (vtkPLY asserted).
    (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
     b"property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
     b"0 0 0\n1 0 0\n0 1 0", ["declares 4 elements", "has 2 whole lines"]),
])
def test_ply_whose_header_the_file_cannot_hold_is_a_clean_error(phongvtk_cli, tmp_path, content,
                                                                words):
    (tmp_path / "bad.ply").write_bytes(content)
    expect_clean_error(phongvtk_cli("normals", "bad.ply", "-o", "x.vtp"), "bad.ply", *words)
    assert not (tmp_path / "x.vtp").exists()


def test_ply_long_enough_for_its_header_is_read(phongvtk_cli, tmp_path):
    # The least the header above allows: three vertices and a face of no points; with a comment
    # and obj_info before 'format', as vtkPLYReader accepts; and a triangle on top.
    header = PLY_HEADER_BINARY.replace(b"ply\n", b"ply\ncomment c\nobj_info o\n", 1)
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype="<f4").tobytes()
    triangle = bytes([3]) + np.array([0, 1, 2], dtype="<i4").tobytes()
    (tmp_path / "tri.ply").write_bytes(header + vertices + triangle)
    result = phongvtk_cli("normals", "tri.ply", "-o", "tri.vtp", "--precision", "double")
    assert result.returncode == 0, result.stderr
    normals = numpy_support.vtk_to_numpy(read_vtp(tmp_path / "tri.vtp").GetCellData().GetArray(
        "Normals"))
    assert normals.tolist() == [[0.0, 0.0, 1.0]]


@pytest.mark.parametrize("binary", [False, True])
def test_ply_written_by_vtk_is_read(phongvtk_cli, sphere_off, tmp_path, binary):
    mesh = phongvtk_io.read_mesh(str(sphere_off))
    writer = vtkPLYWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(tmp_path / "sphere.ply"))
    writer.SetFileType(2 if binary else 1)  # VTK_BINARY, VTK_ASCII
    assert writer.Write() == 1
    assert phongvtk_cli("normals", "sphere.ply", "-o", "s.vtp").returncode == 0
    assert read_vtp(tmp_path / "s.vtp").GetNumberOfPolys() == len(uv_sphere()[1])


# --- VTP files on every expat -----------------------------------------------------------------
# VTK before 9.3.1 reads no cells from XML appended data when the system's expat defers reparsing
# (expat >= 2.6.0; Debian 12's libexpat1 2.5.0-1+deb12u2 and later), unless patched (Debian's
# VTK 9.1 is, ParaView 5.11's VTK 9.2 is not). The CLI writes files every VTK reads, and reads
# appended files with PhongVTK's fix (PhongVTKExpatDeferral.h) whatever the machine's expat and
# VTK; these tests hold on either, and ask a VTK program without PhongVTK which one this is.

PLAIN_VTK_READ = """
import sys
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
reader = vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
mesh = reader.GetOutput()
print(mesh.GetNumberOfPoints(), mesh.GetNumberOfPolys(), mesh.GetCellData().GetNumberOfArrays())
"""


def read_with_plain_vtk(path):
    """(points, polygons, cell arrays) of the VTP at `path` as a VTK program without PhongVTK
    (and so without its fix) reads it, in a process of its own."""
    result = subprocess.run([sys.executable, "-c", PLAIN_VTK_READ, str(path)], capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return tuple(int(word) for word in result.stdout.split())


def write_appended_vtp(path, mesh):
    """`mesh` in vtkXMLPolyDataWriter's default mode (appended data, base64-encoded and
    compressed)."""
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    assert writer.Write() == 1


def test_normals_writes_vtp_that_vtk_without_phongvtk_reads(phongvtk_cli, sphere_off, tmp_path):
    result = phongvtk_cli("normals", sphere_off, "-o", "out.vtp", "--areas")
    assert result.returncode == 0, result.stderr
    points, faces = uv_sphere()
    assert read_with_plain_vtk(tmp_path / "out.vtp") == (len(points), len(faces), 2)
    assert "<AppendedData" not in (tmp_path / "out.vtp").read_text(errors="replace")
    assert sorted(os.listdir(tmp_path)) == ["out.vtp", "sphere.off"]  # no temporary left


def test_output_replaces_an_existing_file_keeping_its_mode_and_writes_through_links(
        phongvtk_cli, sphere_off, tmp_path):
    (tmp_path / "kept").mkdir()
    old = tmp_path / "kept" / "out.vtp"
    old.write_text("an older result")
    old.chmod(0o640)
    (tmp_path / "link.vtp").symlink_to(old)
    result = phongvtk_cli("normals", sphere_off, "-o", "link.vtp")
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "link.vtp").is_symlink()
    assert read_vtp(old).GetNumberOfPolys() == len(uv_sphere()[1])
    assert old.stat().st_mode & 0o777 == 0o640
    assert os.listdir(tmp_path / "kept") == ["out.vtp"]


def test_output_onto_a_directory_is_a_clean_error_that_leaves_nothing(phongvtk_cli, sphere_off,
                                                                      tmp_path):
    (tmp_path / "out.vtp").mkdir()
    expect_clean_error(phongvtk_cli("normals", sphere_off, "-o", "out.vtp"), "out.vtp",
                       "directory")
    assert sorted(os.listdir(tmp_path)) == ["out.vtp", "sphere.off"]
    assert os.listdir(tmp_path / "out.vtp") == []


def test_appended_vtp_input_is_read_whole(phongvtk_cli, sphere_off, tmp_path):
    phongvtk_cli("normals", sphere_off, "-o", "inline.vtp")
    write_appended_vtp(tmp_path / "appended.vtp", read_vtp(tmp_path / "inline.vtp"))
    result = phongvtk_cli("area", "appended.vtp", "--view", "0", "1", "0", "--json")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    points, faces = uv_sphere()
    assert report["cells"] == len(faces), report


def test_appended_vtp_without_the_fix_is_a_clear_error_only_where_vtk_needs_it(
        phongvtk_cli, environment, sphere_off, tmp_path):
    phongvtk_cli("normals", sphere_off, "-o", "inline.vtp")
    write_appended_vtp(tmp_path / "appended.vtp", read_vtp(tmp_path / "inline.vtp"))
    points, faces = uv_sphere()
    vtk_needs_the_fix = read_with_plain_vtk(tmp_path / "appended.vtp")[1] != len(faces)
    environment["PHONGVTK_KEEP_EXPAT_DEFERRAL"] = "1"
    try:
        result = phongvtk_cli("normals", "appended.vtp", "-o", "out.vtp")
    finally:
        del environment["PHONGVTK_KEEP_EXPAT_DEFERRAL"]
    if vtk_needs_the_fix:
        expect_clean_error(result, "appended.vtp", "appended mode", "expat",
                           "PHONGVTK_KEEP_EXPAT_DEFERRAL", "inline binary")
    else:
        assert result.returncode == 0, result.stderr


# --- bad input --------------------------------------------------------------------------------


def lines_only_vtp(path):
    points = vtkPoints()
    for p in ((0, 0, 0), (1, 0, 0), (1, 1, 0)):
        points.InsertNextPoint(p)
    lines = vtkCellArray()
    lines.InsertNextCell(3, [0, 1, 2])
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetLines(lines)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    writer.Write()


# Bad inputs: file name, what is in it (None: no file), words the error message must contain.
BAD_INPUTS = {
    "missing": ("missing.ply", None, ["missing.ply", "no such file"]),
    "empty": ("empty.ply", b"", ["empty.ply", "empty"]),
    "garbage": ("garbage.ply", b"ply\nnot a header\n\x00\xff", ["garbage.ply", "PLY"]),
    "unknown extension": ("mesh.xyz", b"1 2 3\n", ["unknown mesh format '.xyz'"]),
    "lines only": ("lines.vtp", lines_only_vtp, ["lines.vtp", "not a surface", "1 line,"]),
    "corrupt": ("corrupt.vtp", b"<?xml version='1.0'?>\n<VTKFile", ["corrupt.vtp", "VTP"]),
}


def make_bad_input(directory, kind):
    """Writes the bad input `kind` of BAD_INPUTS into `directory`; returns (path, words)."""
    name, content, words = BAD_INPUTS[kind]
    path = directory / name
    if callable(content):
        content(path)
    elif content is not None:
        path.write_bytes(content)
    return path, words


@pytest.mark.parametrize("command", [["render", "-o", "out.png"], ["normals", "-o", "out.vtp"],
                                     ["area"]])
@pytest.mark.parametrize("kind", BAD_INPUTS)
def test_bad_input_is_a_one_line_error(phongvtk_cli, tmp_path, command, kind):
    if command == ["area"] and not HAVE_VISIBLE_AREA:
        pytest.skip("this build of phongvtk has no vtkVisibleArea yet")
    path, words = make_bad_input(tmp_path, kind)
    result = phongvtk_cli(command[0], path, *command[1:], "--quiet")
    expect_clean_error(result, *words)
    assert result.stdout == ""


def test_bad_input_without_quiet_ends_with_the_error(phongvtk_cli, tmp_path):
    path, _ = make_bad_input(tmp_path, "lines only")
    result = phongvtk_cli("render", path, "-o", "x.png")
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    assert result.stderr.strip().splitlines()[-1].startswith("phongvtk: error: ")
    assert result.stderr.count("phongvtk: error") == 1
    assert "(0x" not in result.stderr and "ERROR" not in result.stderr  # nothing from VTK


def test_unwritable_image_is_a_clean_error(phongvtk_cli, sphere_off):
    expect_clean_error(phongvtk_cli("render", sphere_off, "-o", "no/such/dir/x.png", "-q"),
                       "no/such/dir/x.png")


# --- progress ---------------------------------------------------------------------------------


def test_progress_bars_on_stderr_unless_quiet(phongvtk_cli, sphere_off):
    loud = phongvtk_cli("normals", sphere_off, "-o", "a.vtp")
    assert loud.returncode == 0
    assert "read sphere.off [" in loud.stderr and "] 100%" in loud.stderr
    assert "\r" not in loud.stderr  # not a terminal: final lines only
    quiet = phongvtk_cli("normals", sphere_off, "-o", "b.vtp", "--quiet")
    assert quiet.returncode == 0
    assert quiet.stderr == ""
    also_quiet = phongvtk_cli("--quiet", "normals", sphere_off, "-o", "c.vtp")
    assert also_quiet.stderr == ""


class Terminal:
    """A stream that says it is a terminal and keeps what is written."""

    def __init__(self):
        self.text = ""

    def isatty(self):
        return True

    def write(self, text):
        self.text += text

    def flush(self):
        pass


def test_progress_bar_is_redrawn_in_place_on_a_terminal():
    terminal = Terminal()
    bar = Bar("work", terminal, live=True)
    bar.update(0.25)
    bar.update(0.251)  # the same percentage: not redrawn
    bar.update(0.5)
    bar.finish()
    assert terminal.text.count("\r") == 3
    assert "\rwork [########                      ]  25%" in terminal.text
    assert terminal.text.endswith("work [" + "#" * 30 + "] 100%\n")


def ladder_backend(environment, tmp_path, smp_backend, *args):
    """The 'SMP backend X, N threads' the normals ladder of ``phongvtk ARGS`` reports, run with
    VTK_SMP_BACKEND_IN_USE = smp_backend (None: unset)."""
    env = dict(environment)
    env.pop("VTK_SMP_BACKEND_IN_USE", None)
    if smp_backend:
        env["VTK_SMP_BACKEND_IN_USE"] = smp_backend
    result = subprocess.run([sys.executable, "-m", "phongvtk", *args], cwd=tmp_path, env=env,
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    found = re.search(r"SMP backend (\w+), (\d+) threads", result.stdout)
    assert found, result.stdout
    return found.group(1), int(found.group(2))


def test_threads_every_core_by_default_one_is_sequential(environment, tmp_path):
    ladder = ("bench", "--only", "normals", "--quick")
    cores = len(os.sched_getaffinity(0))
    backend, threads = ladder_backend(environment, tmp_path, None, *ladder)
    if cores > 1:
        assert (backend, threads) == ("STDThread", cores)
    assert ladder_backend(environment, tmp_path, None, "--threads", "1", *ladder) == (
        "Sequential", 1)
    assert ladder_backend(environment, tmp_path, None, *ladder, "--threads", "2") == (
        "STDThread", 2)


def test_threads_default_keeps_the_backend_the_environment_names(environment, tmp_path):
    ladder = ("bench", "--only", "normals", "--quick")
    assert ladder_backend(environment, tmp_path, "Sequential", *ladder)[0] == "Sequential"
    # An explicit --threads wins over the environment.
    assert ladder_backend(environment, tmp_path, "Sequential", *ladder, "--threads", "2") == (
        "STDThread", 2)
