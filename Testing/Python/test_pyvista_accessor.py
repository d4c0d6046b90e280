"""The `phong` accessor on pyvista.PolyData, under PyVista from PyPI (Python.PyVista).

Truth comes from outside the filter: the geometry of a cube and of a sphere, exact rational
arithmetic (fractions) for the area vectors, numpy cross products of the output's own cells.
"""
import gc
import inspect
import math
import os
import subprocess
import sys
from decimal import Decimal, getcontext
from fractions import Fraction
import weakref

import numpy as np
import pytest
import pyvista as pv

import phongvtk  # noqa: F401  (registers the accessor: PyVista is imported already)


def cell_point_ids(mesh):
    """The point ids of each polygon of a PolyData of polygons only."""
    faces, cells, i = mesh.faces, [], 0
    while i < len(faces):
        cells.append(faces[i + 1:i + 1 + faces[i]].tolist())
        i += 1 + faces[i]
    return cells


def area_vector(points, ids):
    """The summed cross-product rule in numpy, from the first vertex."""
    p = points[ids].astype(float)
    return sum(np.cross(p[i] - p[0], p[i + 1] - p[0]) for i in range(1, len(ids) - 1))


def test_the_accessor_is_registered_on_polydata():
    names = {(r.name, r.target) for r in pv.registered_accessors()}
    assert ("phong", pv.PolyData) in names


def test_split_cube_has_24_points_with_axis_aligned_normals():
    cube = pv.Cube()
    before = cube.copy(deep=True)
    split = cube.phong.compute_normals(split_vertices=True)
    assert isinstance(split, pv.PolyData)
    assert split.n_points == 24 and split.n_cells == 6
    normals = split.point_data["Normals"]
    # Each point's normal is one of the six axis directions, exactly, and it is the outward
    # normal of the one face the point belongs to (a cube's faces meet at 90 degrees > 30).
    assert np.all(np.sort(np.abs(normals), axis=1) == [0.0, 0.0, 1.0])
    for ids in cell_point_ids(split):
        centre = split.points[ids].mean(axis=0)
        outward = np.round(centre / np.abs(centre).max())
        for i in ids:
            assert np.array_equal(normals[i], outward)
    # Each copy maps back to a point at the same place; the input is left as it was.
    original = split.point_data["pyvistaOriginalPointIds"]
    assert np.array_equal(split.points, cube.points[original])
    assert np.array_equal(original, split.point_data["OriginalPointIds"])
    assert cube.point_data.keys() == before.point_data.keys()
    assert cube.n_points == 8 and np.array_equal(cube.points, before.points)


def test_defaults_are_pyvistas():
    ours = inspect.signature(pv.PolyData.phong.compute_normals).parameters
    theirs = inspect.signature(pv.PolyData.compute_normals).parameters
    for name, parameter in theirs.items():
        if name != "self":
            assert ours[name].default == parameter.default, name
    sphere = pv.Sphere()
    mine = sphere.phong.compute_normals()
    pyvistas = sphere.compute_normals()
    assert mine.n_points == pyvistas.n_points and mine.n_cells == pyvistas.n_cells
    assert mine.point_data.active_normals_name == "Normals"
    assert mine.cell_data.active_normals_name == "Normals"
    # Both are outward unit normals of a sphere: within the facet angle of the radius direction.
    radial = mine.points / np.linalg.norm(mine.points, axis=1)[:, None]
    assert np.all(np.einsum("ij,ij->i", mine.point_data["Normals"], radial) > math.cos(0.1))
    assert np.allclose(mine.point_data["Normals"], pyvistas.point_data["Normals"], atol=0.05)


def reference_point_normals(mesh, weighting):
    """Each point's normal from its triangles, weighted as documented, in numpy."""
    sums = np.zeros((mesh.n_points, 3))
    for ids in cell_point_ids(mesh):
        p = mesh.points[ids].astype(float)
        w = np.cross(p[1] - p[0], p[2] - p[0])
        unit = w / np.linalg.norm(w)
        for corner in range(3):
            a, b, c = p[corner], p[(corner + 1) % 3], p[(corner + 2) % 3]
            e1, e2 = b - a, c - a
            if weighting == "area":
                contribution = w
            elif weighting == "uniform":
                contribution = unit
            elif weighting == "angle":
                cosine = np.dot(e1, e2) / (np.linalg.norm(e1) * np.linalg.norm(e2))
                contribution = unit * math.acos(max(-1.0, min(1.0, cosine)))
            else:  # max: the corner's cross product over its edges' squared lengths
                contribution = np.cross(e1, e2) / (np.dot(e1, e1) * np.dot(e2, e2))
            sums[ids[corner]] += contribution
    return sums / np.linalg.norm(sums, axis=1)[:, None]


@pytest.mark.parametrize("weighting", ["area", "angle", "uniform", "max"])
def test_each_weighting_is_the_documented_one(weighting):
    # A sphere with its points moved at random: the four weightings differ by 0.05 and more.
    sphere = pv.Sphere(theta_resolution=12, phi_resolution=8).triangulate().clean()
    sphere.points += np.random.default_rng(3).uniform(-0.03, 0.03, sphere.points.shape)
    got = sphere.phong.compute_normals(weighting=weighting, cell_normals=False,
                                       consistent_normals=False).point_data["Normals"]
    expected = reference_point_normals(sphere, weighting)
    assert np.max(np.abs(got - expected)) < 1e-6
    others = [w for w in ("area", "angle", "uniform", "max") if w != weighting]
    for other in others:
        assert np.max(np.abs(reference_point_normals(sphere, other) - expected)) > 1e-3


def exact_unit_normal(corners):
    """The unit normal of a triangle of double corners: its area vector in exact rationals, the
    division by the length to 50 digits, rounded once to double."""
    p = [[Fraction(float(x)) for x in corner] for corner in corners]
    u = [p[1][k] - p[0][k] for k in range(3)]
    v = [p[2][k] - p[0][k] for k in range(3)]
    w = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    squared = sum(x * x for x in w)
    length = (Decimal(squared.numerator) / Decimal(squared.denominator)).sqrt()
    return [float(Decimal(x.numerator) / Decimal(x.denominator) / length) for x in w]


def test_exact_cell_normals_are_faithful_to_rational_arithmetic():
    getcontext().prec = 50
    rng = np.random.default_rng(7)
    # Needles: the third corner 1e-12 off the segment of the first two, whose cross product
    # cancels in double to a few digits (DOUBLE misses by far more than a float ulp here).
    n = 200
    p0 = rng.uniform(-1, 1, (n, 3))
    d = rng.uniform(-1, 1, (n, 3))
    p1 = p0 + d
    p2 = p0 + 0.5 * d + rng.uniform(-1e-12, 1e-12, (n, 3))
    points = np.concatenate([p0, p1, p2])
    faces = np.column_stack([np.full(n, 3), np.arange(n), np.arange(n) + n,
                             np.arange(n) + 2 * n]).ravel()
    mesh = pv.PolyData(points, faces=faces)
    normals = mesh.phong.compute_normals(point_normals=False, consistent_normals=False,
                                         accuracy="exact").cell_data["Normals"]
    assert normals.dtype == np.float32
    for c in range(n):
        exact = exact_unit_normal(points[[c, c + n, c + 2 * n]])
        for k in range(3):
            # The faithful double rounded to float: within one float ulp of the exact value.
            ulp = float(np.spacing(np.float32(abs(exact[k]))))
            assert abs(float(normals[c, k]) - exact[k]) <= ulp, (c, k)


def test_flip_normals_turns_the_cells_too():
    sphere = pv.Sphere()
    flipped = sphere.phong.compute_normals(flip_normals=True, point_normals=False)
    cells = cell_point_ids(flipped)
    for c, ids in enumerate(cells):
        w = area_vector(flipped.points, ids)
        # The cells' own orientation and the normal agree, and both now point inward.
        assert np.dot(w, flipped.cell_data["Normals"][c]) > 0
        assert np.dot(w, flipped.points[ids].mean(axis=0)) < 0


def test_consistent_and_auto_oriented_normals_face_out():
    sphere = pv.Sphere(theta_resolution=16, phi_resolution=12).triangulate()
    faces = np.asarray(sphere.faces).reshape(-1, 4).copy()
    faces[::3, 1:] = faces[::3, 1:][:, ::-1]  # every third triangle reversed
    shuffled = pv.PolyData(sphere.points, faces=faces.ravel())
    shuffled.faces = faces.ravel()
    out = shuffled.phong.compute_normals(auto_orient_normals=True, flip_normals=False)
    for c, ids in enumerate(cell_point_ids(out)):
        centre = out.points[ids].mean(axis=0)
        assert np.dot(out.cell_data["Normals"][c], centre) > 0
        assert np.dot(area_vector(out.points, ids), centre) > 0
    radial = out.points / np.linalg.norm(out.points, axis=1)[:, None]
    assert np.all(np.einsum("ij,ij->i", out.point_data["Normals"], radial) > 0.9)


def test_inplace_returns_the_mesh_itself():
    cube = pv.Cube()
    result = cube.phong.compute_normals(inplace=True, split_vertices=True)
    assert result is cube and cube.n_points == 24 and "Normals" in cube.point_data


def test_weighting_and_accuracy_are_checked():
    cube = pv.Cube()
    with pytest.raises(ValueError, match="accuracy"):
        cube.phong.compute_normals(accuracy="quad")
    with pytest.raises(ValueError, match="weighting"):
        cube.phong.compute_normals(weighting="mass")


def test_a_mesh_used_through_the_accessor_is_freed():
    mesh = pv.Sphere()
    mesh.phong.compute_normals()
    mesh.phong.visible_area()
    mesh.phong.actor()
    gone = weakref.ref(mesh)
    del mesh
    gc.collect()
    assert gone() is None


def test_pyvista_metadata_follows_the_mesh():
    cube = pv.Cube()
    cube.point_data["flag"] = np.arange(cube.n_points) % 2 == 0
    for out in (cube.phong.compute_normals(), cube.phong.visible_area(),
                cube.phong.compute_normals(inplace=True)):
        assert out.point_data["flag"].dtype == bool


def test_split_without_point_normals_keeps_every_point():
    cube = pv.Cube()
    out = cube.phong.compute_normals(split_vertices=True, point_normals=False)
    assert out.n_points == 8
    assert np.array_equal(out.point_data["pyvistaOriginalPointIds"], np.arange(8))


def test_meshes_without_polygons_and_bad_point_ids_raise():
    # PyVista's own errors for no polygons (an empty mesh included).
    for mesh in (pv.PolyData(np.random.default_rng(1).random((5, 3))), pv.Line(), pv.PolyData()):
        with pytest.raises(TypeError, match="only vertex cells"):
            mesh.phong.compute_normals()
    # A point id past the points: PyVista's compute_normals crashes the process on it.
    bad = pv.PolyData(np.random.default_rng(2).random((4, 3)), faces=[3, 0, 1, 7])
    with pytest.raises(RuntimeError, match="Cell 0"):
        bad.phong.compute_normals()


def test_lines_beside_polygons_get_no_invented_normal():
    mesh = pv.Cube().merge(pv.Line((0, 0, 2), (0, 0, 3)), merge_points=False)
    normals = mesh.phong.compute_normals().cell_data["Normals"]
    kinds = [mesh.get_cell(c).type for c in range(mesh.n_cells)]
    for c, kind in enumerate(kinds):
        if kind == pv.CellType.LINE:
            assert normals[c].tolist() == [0.0, 0.0, 0.0]
        else:
            assert np.linalg.norm(normals[c]) == pytest.approx(1.0, abs=1e-6)


def test_existing_normals_are_recomputed():
    sphere = pv.Sphere()
    sphere.points[:, 2] *= 3.0  # the Normals array sphere came with is now stale
    fresh = sphere.phong.compute_normals(cell_normals=False)
    for i in range(sphere.n_points):
        # The ellipsoid's own normal direction at a point: the gradient of x^2+y^2+(z/3)^2.
        x, y, z = sphere.points[i]
        gradient = np.array([x, y, z / 9.0])
        cosine = np.dot(fresh.point_data["Normals"][i], gradient) / np.linalg.norm(gradient)
        assert cosine > 0.95, i


@pytest.mark.parametrize("consistent", [False, True])
@pytest.mark.parametrize("auto_orient", [False, True])
def test_cells_and_normals_agree_for_every_orientation_option(consistent, auto_orient):
    """PyVista's flip_normals reverses the faces without the normals, or the normals without the
    faces, depending on the other two options: here the cells and their normals always agree,
    and flipping turns both."""
    sphere = pv.Sphere()
    results = {}
    for flip in (False, True):
        out = sphere.phong.compute_normals(flip_normals=flip, consistent_normals=consistent,
                                           auto_orient_normals=auto_orient, point_normals=False)
        outward = 0
        for c, ids in enumerate(cell_point_ids(out)):
            w = area_vector(out.points, ids)
            assert np.dot(w, out.cell_data["Normals"][c]) > 0, (flip, c)
            outward += np.dot(w, out.points[ids].mean(axis=0)) > 0
        results[flip] = outward
    assert results[False] == sphere.n_cells and results[True] == 0


def test_progress_bar():
    pytest.importorskip("tqdm")
    assert pv.Sphere().phong.compute_normals(progress_bar=True).n_points == pv.Sphere().n_points


def test_visible_area_of_a_unit_cube():
    cube = pv.Cube()
    assert cube.phong.visible_area().field_data["TotalVisibleArea"][0] == 1.0
    # From the diagonal a unit cube shows |nx| + |ny| + |nz| = sqrt(3).
    diagonal = cube.phong.visible_area(view_direction=(1, 1, 1), accuracy="exact")
    assert diagonal.field_data["TotalVisibleArea"][0] == pytest.approx(math.sqrt(3), rel=1e-15)
    assert diagonal.field_data["MaxVisibleArea"][0] == 0.0  # closed: front and back cancel
    with pytest.raises(ValueError, match="view_direction"):
        cube.phong.visible_area(view_direction=(0, 0, 0))


def test_phong_actor_in_a_plotter():
    sphere = pv.Sphere(theta_resolution=24, phi_resolution=12).phong.compute_normals(
        cell_normals=False)
    plotter = pv.Plotter(off_screen=True, window_size=(160, 120))
    plotter.set_background("black")
    actor = sphere.phong.add_to(plotter, shading="phong", preset="plastic", color="red")
    image = plotter.screenshot(return_img=True)
    mapper = actor.GetMapper()
    assert mapper.IsA("vtkPhongPolyDataMapper")
    assert actor.GetProperty().GetInterpolation() == 2  # VTK_PHONG
    # The sphere is drawn in the middle (red, lit), the corners are the background.
    centre = image[60, 80].astype(int)
    assert centre[0] > 100 and centre[0] > centre[1] + 50 and centre[0] > centre[2] + 50
    assert image[0, 0].tolist() == [0, 0, 0]
    configuration = mapper.GetShaderConfiguration()
    assert "specular" in configuration.lower()
    plotter.close()
    with pytest.raises(ValueError, match="preset"):
        sphere.phong.actor(preset="velvet")
    # The colour is the material's: the preset's ambient (and metal's specular) colour follow it.
    metal = sphere.phong.actor(preset="Metal", color="gold").GetProperty()
    gold = pv.Color("gold").float_rgb
    assert metal.GetDiffuseColor() == pytest.approx(gold)
    assert metal.GetSpecularColor() == pytest.approx(gold)


def test_entry_point_registers_without_importing_phongvtk():
    code = ("import sys, pyvista as pv; m = pv.Cube().phong.compute_normals(split_vertices=True);"
            "print(m.n_points, 'phongvtk' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ), check=True).stdout.split()
    assert out == ["24", "True"]


def test_strips_become_triangles_as_in_pyvista():
    strips = pv.Plane(i_resolution=4, j_resolution=3).triangulate().strip()
    ours = strips.phong.compute_normals()
    theirs = strips.compute_normals()
    assert strips.n_strips > 0 and ours.n_strips == 0
    assert ours.n_cells == theirs.n_cells == 24
    assert np.all(ours.cell_data["Normals"] == [0.0, 0.0, 1.0])  # the plane faces +z
