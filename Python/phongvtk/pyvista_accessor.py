"""``mesh.phong``: PhongVTK on PyVista meshes (PyVista 0.48 and later).

Importing this module registers the accessor ``phong`` on :class:`pyvista.PolyData`. That happens
by itself: ``import phongvtk`` imports it when PyVista is already imported, and PyVista imports it
the first time ``mesh.phong`` is used otherwise (the ``pyvista.accessors`` entry point of the
``phongvtk`` distribution)::

    import pyvista as pv
    mesh = pv.Cube()
    split = mesh.phong.compute_normals(split_vertices=True, accuracy="exact")
    seen = mesh.phong.visible_area(view_direction=(0, 0, 1))
    plotter = pv.Plotter(off_screen=True)
    mesh.phong.add_to(plotter, shading="phong", preset="plastic")
    plotter.screenshot("cube.png")

``compute_normals`` takes the keywords of :meth:`pyvista.PolyData.compute_normals`, with its
defaults, and ``accuracy`` and ``weighting`` on top.
"""

import numpy as np
import pyvista

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkActor

from .progress import vtk_message
from .vtkPhongVTKFilters import vtkPolygonNormals, vtkVisibleArea

try:
    from .vtkPhongVTKRendering import vtkPhongPolyDataMapper
except ImportError:  # a build without PhongVTK::Rendering
    vtkPhongPolyDataMapper = None

ACCURACIES = {"fast": 0, "double": 1, "compensated": 2, "exact": 3}
WEIGHTINGS = {"area": 0, "angle": 1, "uniform": 2, "max": 3}
SHADINGS = {"flat": 0, "gouraud": 1, "phong": 2}


def _choice(name, value, choices):
    key = str(value).lower()
    if key not in choices:
        raise ValueError(f"{name} must be one of {', '.join(choices)}, not {value!r}")
    return choices[key]


def _run(algorithm, progress_bar, message, mesh):
    """Updates `algorithm` on `mesh` and returns its output wrapped, with the PyVista metadata
    of `mesh` (the types of its bool and complex arrays...) as PyVista's own filters keep it;
    raises RuntimeError with VTK's own words when it reports an error (VTK's output window
    stays quiet about it: the exception says it)."""
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, text):
        errors.append(vtk_message(text or f"{caller.GetClassName()} failed"))

    tags = [(algorithm, algorithm.AddObserver(vtkCommand.ErrorEvent, on_error))]
    executive = algorithm.GetExecutive()
    tags.append((executive, executive.AddObserver(vtkCommand.ErrorEvent, on_error)))
    bar = None
    if progress_bar:
        try:
            from tqdm import tqdm
        except ImportError as error:
            raise ImportError("progress_bar=True needs tqdm (pip install tqdm)") from error
        bar = tqdm(total=1.0, desc=message, bar_format="{l_bar}{bar}[{elapsed}<{remaining}]")

        def on_progress(caller, event):
            bar.update(caller.GetProgress() - bar.n)

        tags.append((algorithm, algorithm.AddObserver(vtkCommand.ProgressEvent, on_progress)))
    try:
        algorithm.Update()
    finally:
        for obj, tag in tags:
            obj.RemoveObserver(tag)
        if bar is not None:
            bar.close()
    if errors:
        raise RuntimeError(f"{algorithm.GetClassName()}: {errors[0]}")
    output = pyvista.wrap(algorithm.GetOutput())
    output.copy_meta_from(mesh, deep=True)
    return output


@pyvista.register_dataset_accessor("phong", pyvista.PolyData)
class PhongAccessor:
    """PhongVTK's filters and mapper on a :class:`pyvista.PolyData` (``mesh.phong``)."""

    def __init__(self, mesh):
        self._mesh = mesh

    def _target(self):
        """The mesh, with this accessor taken out of its cache: PyVista keeps the accessor in the
        mesh's __dict__, and a VTK object's __dict__ is not searched for reference cycles (VTK
        9.2's wrapping), so a mesh and its accessor holding each other would never be freed."""
        self._mesh.__dict__.pop("phong", None)
        return self._mesh

    def compute_normals(self, cell_normals=True, point_normals=True, split_vertices=False,
                        flip_normals=False, consistent_normals=True, auto_orient_normals=False,
                        non_manifold_traversal=True, feature_angle=30.0, inplace=False,
                        progress_bar=False, *, accuracy="double", weighting="area"):
        """Normals by the summed cross-product rule (:class:`phongvtk.vtkPolygonNormals`).

        The keywords and defaults of :meth:`pyvista.PolyData.compute_normals`, plus:

        accuracy : str, default "double"
            "fast", "double", "compensated" or "exact" (every component faithful).
        weighting : str, default "area"
            Weighting of the faces around a point: "area" (each face by its area: the summed
            cross-product rule over the point's star), "angle", "uniform" (the plain sum of unit
            face normals, what VTK's filter and so PyVista's compute_normals do) or "max".

        Returns a new :class:`pyvista.PolyData` (the mesh itself with ``inplace=True``) with the
        ``Normals`` arrays asked for, active. With ``split_vertices`` the points along edges
        sharper than ``feature_angle`` are duplicated, and ``pyvistaOriginalPointIds`` (as
        PyVista names it) and ``OriginalPointIds`` give each output point its input point; the
        input mesh is left as it was. ``flip_normals`` reverses the polygons themselves, so that
        the cells and their normals agree. Raises TypeError for a mesh without polygons or
        strips, ValueError for an unknown accuracy or weighting, RuntimeError when the filter
        fails (an invalid point id, with the cell it is in).
        """
        mesh = self._target()
        if mesh.n_verts + mesh.n_lines == mesh.n_cells:
            raise TypeError(
                "Normals cannot be computed for PolyData containing only vertex cells (e.g. "
                "point clouds) and/or line cells. The PolyData cells must be polygons (e.g. "
                "triangle cells).")
        normals = vtkPolygonNormals()
        normals.SetAccuracy(_choice("accuracy", accuracy, ACCURACIES))
        normals.SetPointWeighting(_choice("weighting", weighting, WEIGHTINGS))
        normals.SetComputeCellNormals(bool(cell_normals))
        normals.SetComputePointNormals(bool(point_normals))
        normals.SetSplitting(bool(split_vertices))
        normals.SetFeatureAngle(float(feature_angle))
        normals.SetFlipNormals(bool(flip_normals))
        normals.SetConsistency(bool(consistent_normals))
        normals.SetAutoOrientNormals(bool(auto_orient_normals))
        normals.SetNonManifoldTraversal(bool(non_manifold_traversal))
        normals.SetInputData(mesh)
        output = _run(normals, progress_bar, "Computing Normals", mesh)
        if split_vertices:
            # As PyVista names it; without point normals nothing is split: each point is its own.
            split = point_normals and "OriginalPointIds" in output.point_data
            output.point_data["pyvistaOriginalPointIds"] = (
                np.array(output.point_data["OriginalPointIds"]) if split
                else np.arange(output.n_points, dtype=pyvista.ID_TYPE))
        if point_normals:
            output.GetPointData().SetActiveNormals("Normals")
        if cell_normals:
            output.GetCellData().SetActiveNormals("Normals")
        if inplace:
            mesh.copy_from(output, deep=False)
            return mesh
        return output

    def visible_area(self, view_direction=(0.0, 0.0, 1.0), camera=None, *, accuracy="double",
                     progress_bar=False):
        """The area of each polygon a viewer sees (:class:`phongvtk.vtkVisibleArea`).

        view_direction : sequence of 3 floats, default (0, 0, 1)
            Toward the viewer (any non-zero length), under parallel projection.
        camera : pyvista.Camera or vtkCamera, optional
            A camera instead: a parallel one looks along its direction of projection, a
            perspective one gives each polygon its own direction to the eye.
        accuracy : str, default "double"
            As in :meth:`compute_normals`.

        Returns a new :class:`pyvista.PolyData` with the cell array ``VisibleArea`` (positive
        where the front is seen) and the field data ``TotalVisibleArea``, ``MaxVisibleArea`` and
        ``MaxVisibleAreaDirection``.
        """
        direction = np.asarray(view_direction, dtype=float)
        if direction.shape != (3,) or not np.all(np.isfinite(direction)) or not direction.any():
            raise ValueError(f"view_direction must be 3 finite numbers, not all zero: "
                             f"{view_direction!r}")
        area = vtkVisibleArea()
        area.SetAccuracy(_choice("accuracy", accuracy, ACCURACIES))
        area.SetViewDirection(*direction)
        if camera is not None:
            area.SetCamera(camera)
        mesh = self._target()
        area.SetInputData(mesh)
        return _run(area, progress_bar, "Computing Visible Area", mesh)

    def actor(self, shading="phong", preset="plastic", color=None):
        """A vtkActor drawing the mesh through :class:`phongvtk.vtkPhongPolyDataMapper`.

        shading : str, default "phong"
            "flat", "gouraud" or "phong" (the mesh's point normals are used as they are: call
            :meth:`compute_normals` first for the normals you want).
        preset : str or None, default "plastic"
            A material preset of vtkPhongPolyDataMapper ("plastic", "metal", "matte"), or None
            to keep VTK's default material.
        color : color, optional
            The diffuse colour, anything :class:`pyvista.Color` takes.
        """
        if vtkPhongPolyDataMapper is None:
            raise RuntimeError("this PhongVTK was built without its Rendering module")
        interpolation = _choice("shading", shading, SHADINGS)
        mapper = vtkPhongPolyDataMapper()
        mapper.SetInputData(self._target())
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        if color is not None:  # first: a preset derives its ambient (and metal's specular) colour
            prop.SetColor(pyvista.Color(color).float_rgb)
        if preset is not None and not vtkPhongPolyDataMapper.ApplyPreset(prop, str(preset).lower()):
            raise ValueError(f"unknown preset {preset!r}")
        prop.SetInterpolation(interpolation)
        return actor

    def add_to(self, plotter, shading="phong", preset="plastic", color=None, **kwargs):
        """Adds :meth:`actor` to a :class:`pyvista.Plotter` (``plotter.add_actor``, which takes
        ``kwargs`` such as ``name`` and ``reset_camera``); returns the actor."""
        actor = self.actor(shading=shading, preset=preset, color=color)
        plotter.add_actor(actor, **kwargs)
        return actor
