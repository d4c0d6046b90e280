"""The command-line interface: ``python3 -m phongvtk {render,normals,area,bench,demo} ...``.

Each subcommand is a small function of the parsed arguments and a :class:`Progress`; the work is
done by :mod:`phongvtk.io`, :mod:`phongvtk.render` and :mod:`phongvtk.bench`. A problem the user
can fix (see :class:`CommandError`) ends the program with one line on stderr,
``phongvtk: error: ...``, and exit status 2, as argparse does for bad arguments.
"""

import argparse
import json
import math
import os
import signal
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkFiltersCore import vtkQuadricDecimation, vtkTriangleFilter
from vtkmodules.vtkRenderingCore import vtkCamera

import phongvtk

from . import bench
from .errors import CommandError
from .io import (
    MESH_EXTENSIONS,
    MESH_WRITERS,
    check_output,
    default_mesh,
    read_mesh,
    torus,
    write_mesh,
    write_png,
)
from .progress import Progress
from .render import (
    ACCURACIES,
    BACKENDS,
    PRESETS,
    SHADING_LABELS,
    SHADINGS,
    WEIGHTINGS,
    Light,
    Material,
    Scene,
    View,
    Panel,
    render_grid,
    render_panels,
)

#: The normals filter's output precisions by their command-line names.
PRECISIONS = {"single": 0, "double": 1, "default": 2}  # vtkAlgorithm's *_PRECISION


# --- argument types -------------------------------------------------------------------------


def finite_float(text):
    """An argparse type: a finite number."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: '{text}'") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"not a finite number: '{text}'")
    return value


def feature_angle(text):
    """An argparse type: an angle in degrees from 0 to 180."""
    value = finite_float(text)
    if not 0.0 <= value <= 180.0:
        raise argparse.ArgumentTypeError(f"not between 0 and 180 degrees: '{text}'")
    return value


def non_negative(text):
    """An argparse type: a finite number >= 0 (a coefficient or a colour component)."""
    value = finite_float(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"must not be negative: '{text}'")
    return value


def positive_float(text):
    """An argparse type: a finite number > 0."""
    value = finite_float(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be positive: '{text}'")
    return value


def positive_int(text):
    """An argparse type: an integer >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not an integer: '{text}'") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1: '{text}'")
    return value


class LightAction(argparse.Action):
    """``--light X Y Z [R G B]``, repeatable: collects :class:`Light` records."""

    def __call__(self, parser, namespace, values, option_string=None):
        if len(values) not in (3, 6):
            parser.error(f"{option_string} takes X Y Z or X Y Z R G B, not {len(values)} values")
        try:
            numbers = [finite_float(value) for value in values]
        except argparse.ArgumentTypeError as error:
            parser.error(f"{option_string}: {error}")
        if not any(numbers[:3]):
            parser.error(f"{option_string}: the direction must not be zero")
        if any(value < 0 for value in numbers[3:]):
            parser.error(f"{option_string}: colour components must not be negative")
        colour = tuple(numbers[3:]) if len(numbers) == 6 else (1.0, 1.0, 1.0)
        lights = list(getattr(namespace, self.dest) or [])
        lights.append(Light(direction=tuple(numbers[:3]), color=colour))
        setattr(namespace, self.dest, lights)


# --- shared options -------------------------------------------------------------------------


def add_common(parser):
    """--quiet and --threads on a subcommand (also accepted before the subcommand)."""
    parser.add_argument("-q", "--quiet", action="store_true", default=argparse.SUPPRESS,
                        help="no progress bars, warnings or other chatter on stderr")
    parser.add_argument("--threads", type=positive_int, metavar="N", default=argparse.SUPPRESS,
                        help="threads of the filters (VTK's STDThread SMP backend; 1: "
                             "Sequential); default: every core, unless VTK_SMP_BACKEND_IN_USE "
                             "names a backend")


def use_threads(threads):
    """The SMP backend of this process: the command line owns it, so by default it uses every
    core (STDThread); `threads` = 1 is VTK's Sequential backend. With neither --threads nor
    VTK_SMP_BACKEND_IN_USE, STDThread on os.cpu_count() threads. (The library itself keeps to
    whatever backend the application chose.)"""
    from vtkmodules.vtkCommonCore import vtkSMPTools

    if threads is None:
        if os.environ.get("VTK_SMP_BACKEND_IN_USE"):
            return
        threads = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (
            os.cpu_count() or 1)
    if threads == 1:
        vtkSMPTools.SetBackend("Sequential")
        return
    if vtkSMPTools.SetBackend("STDThread"):
        vtkSMPTools.Initialize(threads)


def add_accuracy(parser, what):
    """--accuracy fast|double|compensated|exact."""
    parser.add_argument("--accuracy", choices=ACCURACIES, default="double",
                        help=f"arithmetic of {what} (vtkPolygonNormals' ladder; default: double)")


def add_camera(parser, zoom=1.0):
    """--azimuth, --elevation, --parallel, --zoom: the camera of View."""
    group = parser.add_argument_group(
        "camera", "The mesh is framed from the front (+z, y up), then the camera turns.")
    group.add_argument("--azimuth", type=finite_float, default=0.0, metavar="DEG",
                       help="turn about the vertical, degrees (default 0)")
    group.add_argument("--elevation", type=finite_float, default=0.0, metavar="DEG",
                       help="raise the camera, degrees (default 0)")
    group.add_argument("--parallel", action="store_true",
                       help="parallel projection (default: perspective, 30 degree view angle)")
    group.add_argument("--zoom", type=positive_float, default=zoom, metavar="F",
                       help=f"magnify by F about the centre of the mesh (default {zoom:g})")
    return group


def add_weighting(parser):
    """--weighting area|angle|uniform|max (of the point normals)."""
    parser.add_argument("--weighting", choices=WEIGHTINGS, default="area",
                        help="weights of the faces around a point for its normal: area "
                             "(default; the sum of their area vectors), angle, uniform (VTK's) "
                             "or max (Nelson Max's, exact on a sphere)")


def add_splitting(parser, split=True):
    """--feature-angle DEG and --no-splitting (of the point normals); with split False (the
    demo, whose meshes are smooth surfaces sampled coarsely) no splitting unless an angle is
    given."""
    if not split:
        parser.add_argument("--feature-angle", type=feature_angle, default=None, metavar="DEG",
                            help="split the point normals at edges whose faces meet at this "
                                 "angle or more (default: no splitting; the demo's meshes are "
                                 "smooth surfaces, coarsely sampled)")
        return
    parser.add_argument("--feature-angle", type=feature_angle, default=30.0, metavar="DEG",
                        help="split the point normals at edges whose faces meet at this angle "
                             "or more, so that creases stay sharp under smooth shading "
                             "(default 30, as ParaView's Generate Surface Normals; 0 to 180)")
    parser.add_argument("--no-splitting", action="store_true",
                        help="average the normals across every edge, creases included")


def add_orientation(parser):
    """--consistency, --auto-orient, --non-manifold-traversal and --flip (of the polygons,
    before the normals)."""
    group = parser.add_argument_group("orientation", "How the polygons are ordered before the "
                                                     "normals are computed (default: as given).")
    group.add_argument("--consistency", action="store_true",
                       help="reorder the polygons so that neighbours agree in orientation "
                            "(a non-orientable surface is reported and its seam flagged)")
    group.add_argument("--auto-orient", action="store_true",
                       help="also turn every connected part outward: a closed part by the "
                            "exact sign of its volume (a cavity inward, facing out of the "
                            "material), an open part away from the centre of its box")
    group.add_argument("--non-manifold-traversal", action="store_true",
                       help="with --consistency or --auto-orient, also make parts that meet "
                            "only at edges of three or more polygons agree across them")
    group.add_argument("--flip", action="store_true",
                       help="reverse every polygon, and so every normal")


def orientation_of(args):
    """The vtkPolygonNormals orientation options the command-line options ask for."""
    return {"Consistency": args.consistency, "AutoOrientNormals": args.auto_orient,
            "NonManifoldTraversal": args.non_manifold_traversal, "FlipNormals": args.flip}


def orient(normals, args):
    """The orientation options of the vtkPolygonNormals `normals` as the options say."""
    for name, value in orientation_of(args).items():
        getattr(normals, f"Set{name}")(value)


def feature_angle_of(args):
    """The feature angle the options ask for, or None for no splitting."""
    return None if getattr(args, "no_splitting", False) else args.feature_angle


def add_scene(parser, size, what="image", zoom=1.0, split=True):
    """Material, lights, camera, background and window options of render and demo."""
    add_accuracy(parser, "the normals")
    add_weighting(parser)
    add_splitting(parser, split)
    add_orientation(parser)
    parser.add_argument("--size", type=positive_int, nargs=2, default=size, metavar=("W", "H"),
                        help=f"{what} size in pixels (default {size[0]} {size[1]})")
    parser.add_argument("--backend", choices=BACKENDS, default="osmesa",
                        help="headless window: Mesa's OSMesa (default) or EGL; no X server needed")
    material = parser.add_argument_group(
        "material", "A preset applied to --color, then any coefficient given here.")
    material.add_argument("--preset", choices=PRESETS + ("none",), default="plastic",
                          help="ka = kd as colours, ambient 0.1, and: plastic, diffuse 0.8, white "
                               "highlight (default); metal, diffuse 0.45, tinted highlight; "
                               "matte, diffuse 0.9, none; none: VTK's property defaults")
    material.add_argument("--color", type=non_negative, nargs=3, default=(0.9, 0.6, 0.3),
                          metavar=("R", "G", "B"), help="diffuse colour (default 0.9 0.6 0.3)")
    for name, what in (("ambient", "ka"), ("diffuse", "kd"), ("specular", "ks")):
        material.add_argument(f"--{name}", type=non_negative, metavar="K",
                              help=f"{name} coefficient ({what})")
    material.add_argument("--specular-power", type=non_negative, metavar="ALPHA",
                          help="specular exponent")
    lights = parser.add_argument_group("lights")
    lights.add_argument("--light", action=LightAction, nargs="+", metavar=("X Y Z", "R G B"),
                        dest="lights", default=[],
                        help="a directional light from direction X Y Z (world coordinates, "
                             "from the mesh toward the light), white or of colour R G B; "
                             "repeatable (default: a white key light from the viewer's upper "
                             "left)")
    lights.add_argument("--scene-ambient", type=non_negative, nargs=3, default=(1.0, 1.0, 1.0),
                        metavar=("R", "G", "B"),
                        help="the scene's ambient light Ia (default 1 1 1, VTK's and "
                             "ParaView's; the material's ambient coefficient sets its share)")
    lights.add_argument("--derived-ambient", action="store_true",
                        help="derive Ia from the lights and the mean kd instead "
                             "(vtkPhongPolyDataMapper's SceneAmbient)")
    camera = add_camera(parser, zoom)
    camera.add_argument("--background", type=non_negative, nargs=3, default=(0.1, 0.1, 0.12),
                        metavar=("R", "G", "B"), help="background colour (default 0.1 0.1 0.12)")


def scene_from(args):
    """The :class:`Scene` the options of :func:`add_scene` describe."""
    material = Material(
        color=tuple(args.color), preset=None if args.preset == "none" else args.preset,
        ambient=args.ambient, diffuse=args.diffuse, specular=args.specular,
        specular_power=args.specular_power)
    return Scene(
        material=material, lights=args.lights, ambient=tuple(args.scene_ambient),
        derived_ambient=args.derived_ambient,
        view=View(azimuth=args.azimuth, elevation=args.elevation, parallel=args.parallel,
                  zoom=args.zoom),
        background=tuple(args.background), accuracy=args.accuracy, weighting=args.weighting,
        feature_angle=feature_angle_of(args), orientation=orientation_of(args))


def say(args, text):
    """Chatter on stderr (what was written where), unless --quiet."""
    if not args.quiet:
        print(text, file=sys.stderr)


# --- render ---------------------------------------------------------------------------------


def run_render(args, progress):
    """render: one image of the mesh."""
    check_output(args.output, [".png"], args.mesh)
    mesh = read_mesh(args.mesh, progress)
    image = render_panels(mesh, [args.shading], scene_from(args), args.size, args.backend,
                          progress=progress)
    write_png(image, args.output, progress)
    say(args, f"wrote {args.output} ({args.size[0]} x {args.size[1]}, {args.shading} shading)")


# --- normals --------------------------------------------------------------------------------


def run_normals(args, progress):
    """normals: vtkPolygonNormals with the options, written to a mesh file."""
    check_output(args.output, MESH_WRITERS, args.mesh)
    mesh = read_mesh(args.mesh, progress)
    normals = phongvtk.vtkPolygonNormals()
    normals.SetInputData(mesh)
    normals.SetAccuracy(ACCURACIES[args.accuracy])
    normals.SetComputeCellNormals(not args.no_cell_normals)
    normals.SetComputePointNormals(args.point_normals)
    normals.SetPointWeighting(WEIGHTINGS[args.weighting])
    normals.SetComputeAreaVectors(args.area_vectors)
    normals.SetComputeAreas(args.areas)
    normals.SetComputeNormalStatus(args.status)
    normals.SetOutputPrecision(PRECISIONS[args.precision])
    feature_angle = feature_angle_of(args)
    normals.SetSplitting(feature_angle is not None)
    if feature_angle is not None:
        normals.SetFeatureAngle(feature_angle)
    orient(normals, args)
    progress.run(normals, "normals", f"cannot compute the normals of '{args.mesh}'")
    output = normals.GetOutput()
    write_mesh(output, args.output, progress)
    cell_arrays = [output.GetCellData().GetArrayName(i)
                   for i in range(output.GetCellData().GetNumberOfArrays())]
    point_arrays = [output.GetPointData().GetArrayName(i)
                    for i in range(output.GetPointData().GetNumberOfArrays())]
    say(args, f"wrote {args.output}: {output.GetNumberOfCells()} cells "
              f"({', '.join(cell_arrays) or 'no cell arrays'}), {output.GetNumberOfPoints()} "
              f"points ({', '.join(point_arrays) or 'no point arrays'}); accuracy "
              f"{normals.GetAccuracyAsString()}")


# --- area -----------------------------------------------------------------------------------


def visible_area_filter(args, mesh):
    """A vtkVisibleArea on `mesh` seen along --view or from the camera the options describe;
    also returns a description of the view for the report."""
    if not hasattr(phongvtk, "vtkVisibleArea"):
        raise CommandError("this build of phongvtk has no vtkVisibleArea "
                           "(rebuild with ./scripts/build.sh)")
    area = phongvtk.vtkVisibleArea()
    area.SetInputData(mesh)
    area.SetAccuracy(ACCURACIES[args.accuracy])
    camera_given = args.azimuth is not None or args.elevation is not None or args.parallel
    if args.view is not None and camera_given:
        raise CommandError("give either --view or the camera (--azimuth, --elevation, "
                           "--parallel), not both")
    if camera_given:
        view = View(azimuth=args.azimuth or 0.0, elevation=args.elevation or 0.0,
                    parallel=args.parallel)
        camera = vtkCamera()
        view.frame(camera, mesh.GetBounds())
        area.SetCamera(camera)
        described = {"camera": "parallel" if view.parallel else "perspective",
                     "azimuth": view.azimuth, "elevation": view.elevation,
                     "eye": list(camera.GetPosition()),
                     "focal_point": list(camera.GetFocalPoint())}
    else:
        direction = tuple(args.view) if args.view is not None else (0.0, 0.0, 1.0)
        if not any(direction):
            raise CommandError("--view must be a non-zero direction")
        area.SetViewDirection(*direction)
        described = {"view_direction": list(direction)}
    return area, described


def area_report(area, mesh_path, described):
    """The results of an executed vtkVisibleArea as a dictionary (the --json output)."""
    output = area.GetOutput()
    visible = numpy_support.vtk_to_numpy(output.GetCellData().GetArray("VisibleArea"))
    return {
        "mesh": mesh_path,
        "cells": int(output.GetNumberOfCells()),
        **described,
        "accuracy": area.GetAccuracyAsString(),
        "total_visible_area": area.GetTotalVisibleArea(),
        "back_visible_area": abs(float(visible[visible < 0].sum())),
        "max_visible_area": area.GetMaxVisibleArea(),
        "max_visible_area_direction": list(area.GetMaxVisibleAreaDirection()),
        "front_cells": int(np.count_nonzero(visible > 0)),
        "back_cells": int(np.count_nonzero(visible < 0)),
        "edge_on_cells": int(np.count_nonzero(visible == 0)),
    }


def format_area(report):
    """The --json-less output of area: one result a line."""
    if "view_direction" in report:
        view = "direction ({}) toward the viewer".format(
            ", ".join(f"{c:g}" for c in report["view_direction"]))
    else:
        eye = ", ".join(f"{c:.6g}" for c in report["eye"])
        view = (f"{report['camera']} camera, azimuth {report['azimuth']:g}, elevation "
                f"{report['elevation']:g}, eye ({eye})")
    direction = ", ".join(f"{c:.10g}" for c in report["max_visible_area_direction"])
    return "\n".join([
        f"mesh:                       {report['mesh']} ({report['cells']} cells)",
        f"view:                       {view}",
        f"accuracy:                   {report['accuracy']}",
        f"total visible area:         {report['total_visible_area']:.10g} (fronts seen)",
        f"back visible area:          {report['back_visible_area']:.10g} (backs seen)",
        f"max visible area:           {report['max_visible_area']:.10g}",
        f"max visible area direction: ({direction})",
        f"cells front/back/edge-on:   {report['front_cells']} / {report['back_cells']} / "
        f"{report['edge_on_cells']}",
    ])


def run_area(args, progress):
    """area: the visible area of the mesh toward a direction or a camera."""
    if args.output:
        check_output(args.output, MESH_WRITERS, args.mesh)
    mesh = read_mesh(args.mesh, progress)
    area, described = visible_area_filter(args, mesh)
    progress.run(area, "visible area", f"cannot compute the visible area of '{args.mesh}'")
    report = area_report(area, args.mesh, described)
    if args.output:
        write_mesh(area.GetOutput(), args.output, progress)
    print(json.dumps(report, indent=2) if args.json else format_area(report))


# --- bench and demo -------------------------------------------------------------------------

#: The benchmarks' sizes: full, and --quick (seconds, for tests).
FULL = {"repeats": 9, "sample": 20000, "needles": 20000,
        "thetas": [8, 16, 32, 64, 128, 256, 512, 1024], "size": 400}
QUICK = {"repeats": 3, "sample": 200, "needles": 2000, "thetas": [8, 16, 32], "size": 128}


def bench_settings(args):
    """FULL or QUICK, with what the options override."""
    settings = dict(QUICK if args.quick else FULL)
    for key in ("repeats", "sample"):
        if getattr(args, key) is not None:
            settings[key] = getattr(args, key)
    if getattr(args, "shading_size", None) is not None:
        settings["size"] = args.shading_size
    return settings


def the_mesh(args, progress):
    """(mesh, label): --mesh, else CGAL's bunny, else a torus."""
    if args.mesh:
        return read_mesh(args.mesh, progress), os.path.basename(args.mesh)
    return default_mesh(progress)


def normals_ladder(mesh, label, args, progress):
    """Measures and prints the normals ladder of `mesh` (and its stress variants); returns
    the rows."""
    settings = bench_settings(args)
    inputs = bench.ladder_inputs(mesh, label, args.offset, settings["needles"])
    rows = bench.measure_ladder(inputs, settings["repeats"], settings["sample"], progress)
    print(bench.format_ladder(rows, settings["repeats"], settings["sample"]), flush=True)
    return rows


def plot_path(args, name):
    """Where a plot goes: --plot-dir (made when missing)."""
    try:
        os.makedirs(args.plot_dir, exist_ok=True)
    except OSError as error:
        raise CommandError(f"cannot make the plot directory '{args.plot_dir}': "
                           f"{error.strerror}") from None
    return os.path.join(args.plot_dir, name)


def save_plot(plot, rows, path, args):
    """Writes one plot, or a clean error."""
    try:
        plot(rows, path)
    except OSError as error:
        raise CommandError(f"cannot write '{path}': {error.strerror}") from None
    say(args, f"wrote {path}")


def run_bench(args, progress):
    """bench: the normals ladder and the shading error against tessellation, with plots; or
    --speed, the speed against VTK's filters with both SMP backends."""
    if args.speed:
        from . import speed  # imports no rendering: runs on every VTK

        speed.main(["--rounds", str(args.repeats or 7)])
        return
    settings = bench_settings(args)
    if args.only in (None, "normals"):
        rows = normals_ladder(*the_mesh(args, progress), args, progress)
        if args.plot_dir:
            save_plot(bench.plot_ladder, rows, plot_path(args, "normals-ladder.png"), args)
    if args.only in (None, "shading"):
        if args.only is None:
            print()
        rows = bench.measure_shading(settings["thetas"], settings["size"], args.parallel,
                                     args.weighting, args.backend, progress)
        print(bench.format_shading(rows, settings["size"], args.parallel, args.weighting),
              flush=True)
        if args.plot_dir:
            path = plot_path(args, "shading-error-vs-tessellation.png")
            save_plot(bench.plot_shading, rows, path, args)


def coarse_copy(mesh, triangles, progress):
    """`mesh` decimated to about `triangles` triangles by VTK's quadric decimation (volume kept),
    or None when it has no more than twice that many."""
    if mesh.GetNumberOfPolys() + mesh.GetNumberOfStrips() <= 2 * triangles:
        return None
    split = vtkTriangleFilter()
    split.SetInputData(mesh)
    split.PassVertsOff()
    split.PassLinesOff()
    progress.run(split, "triangulate", "cannot triangulate the mesh")
    decimation = vtkQuadricDecimation()
    decimation.SetInputConnection(split.GetOutputPort())
    decimation.SetTargetReduction(1.0 - triangles / split.GetOutput().GetNumberOfPolys())
    decimation.VolumePreservationOn()
    progress.run(decimation, f"decimate to {triangles} triangles", "cannot decimate the mesh")
    return decimation.GetOutput()


#: The demo's smooth surface: a torus this coarse (2 x 24 x 12 triangles) beside a fine one.
DEMO_TORUS = (24, 12)
DEMO_TORUS_FINE = 256


def triangles_label(shading, surface):
    """A panel's label: the shading and the triangle count of `surface`."""
    count = surface.GetNumberOfPolys() + surface.GetNumberOfStrips()
    return f"{SHADING_LABELS[shading]}\n{count:,} triangles"


def demo_rows(mesh, coarse_triangles, progress):
    """The panels of the demo picture and the view of each row. Top: `mesh` decimated to
    `coarse_triangles` (when it has many more) flat, Gouraud and Phong, then the whole mesh in
    Phong shading. Bottom: the same for a coarse torus and a fine one, a smooth surface where
    Phong shading of the coarse mesh is what the fine mesh looks like."""
    coarse = coarse_copy(mesh, coarse_triangles, progress)
    shown = coarse if coarse is not None else mesh
    top = [Panel(shown, shading, triangles_label(shading, shown)) for shading in SHADINGS]
    if coarse is not None:
        top.append(Panel(mesh, "phong", triangles_label("phong", mesh)))
    coarse_torus, fine = torus(*DEMO_TORUS), torus(DEMO_TORUS_FINE)
    bottom = [Panel(coarse_torus, shading, triangles_label(shading, coarse_torus))
              for shading in SHADINGS]
    bottom.append(Panel(fine, "phong", triangles_label("phong", fine)))
    return [top, bottom]


def run_demo(args, progress):
    """demo: a real mesh and a torus, coarse and fine, flat, Gouraud and Phong; the normals
    ladder; the shading error against tessellation."""
    check_output(args.output, [".png"], args.mesh)
    mesh, label = the_mesh(args, progress)
    rows = demo_rows(mesh, args.coarse, progress)
    scene = scene_from(args)
    torus_view = View(azimuth=scene.view.azimuth, elevation=scene.view.elevation + 40.0,
                      parallel=scene.view.parallel, zoom=scene.view.zoom)
    image = render_grid(rows, scene, args.size, args.backend, labels=True, progress=progress,
                        views=[scene.view, torus_view])
    write_png(image, args.output, progress)
    if not args.no_table:
        normals_ladder(mesh, label, args, progress)
        print(flush=True)
        settings = bench_settings(args)
        shading = bench.measure_shading(settings["thetas"], settings["size"], False, args.weighting,
                                        args.backend, progress)
        print(bench.format_shading(shading, settings["size"], False, args.weighting), flush=True)
        print(flush=True)
    print(f"picture: {os.path.abspath(args.output)} (top: {label}, decimated and whole; bottom: "
          "a torus, coarse and fine; flat, Gouraud and Phong shading)", flush=True)


# --- the parser -----------------------------------------------------------------------------

DESCRIPTION = """\
PhongVTK from the command line: polygon normals by the summed cross-product rule
(vtkPolygonNormals), visible areas (vtkVisibleArea), and Phong shading (vtkPhongPolyDataMapper),
rendered headless (no X server).

Meshes: {formats} (OFF with a reader of its own; the others with VTK's readers).
Run `python3 -m phongvtk COMMAND --help` for a command's options.
"""

EPILOG = """\
examples:
  python3 -m phongvtk demo                                  # bunny, three shadings, tables
  python3 -m phongvtk render bunny.off -o bunny.png --shading phong --preset metal
  python3 -m phongvtk normals bunny.off -o bunny.vtp --accuracy exact --point-normals
  python3 -m phongvtk area cube.stl --view 0 0 1 --json
  python3 -m phongvtk bench --quick --plot-dir plots
"""


def build_parser():
    """The argparse parser of ``python3 -m phongvtk``."""
    formats = ", ".join(extension[1:].upper() for extension in MESH_EXTENSIONS)
    parser = argparse.ArgumentParser(
        prog="phongvtk", description=DESCRIPTION.format(formats=formats), epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version",
                        version=f"phongvtk {phongvtk.__version__} (VTK {vtk_version()})")
    parser.add_argument("-q", "--quiet", action="store_true",
                        help="no progress bars, warnings or other chatter on stderr")
    parser.add_argument("--threads", type=positive_int, metavar="N",
                        help="threads of the filters (VTK's STDThread SMP backend; 1: "
                             "Sequential); default: every core, unless VTK_SMP_BACKEND_IN_USE "
                             "names a backend")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    render = commands.add_parser(
        "render", help="render a mesh to a PNG image",
        description="Render MESH with vtkPhongPolyDataMapper into a PNG image, headless. "
                    "Normals by vtkPolygonNormals: cell normals for flat shading, area-weighted "
                    "point normals for Gouraud and Phong, split at sharp edges "
                    "(--feature-angle).")
    render.add_argument("mesh", metavar="MESH", help="the mesh file")
    render.add_argument("-o", "--output", required=True, metavar="PNG", help="the image to write")
    render.add_argument("--shading", choices=SHADINGS, default="phong",
                        help="flat (a normal per face), gouraud (colours per vertex, "
                             "interpolated) or phong (the model per pixel; default)")
    add_scene(render, (640, 480))
    add_common(render)
    render.set_defaults(run=run_render)

    normals = commands.add_parser(
        "normals", help="compute normals (and areas) and write a mesh",
        description="Compute normals of MESH with vtkPolygonNormals and write the result "
                    f"({', '.join(MESH_WRITERS)} by extension; only VTP and VTK keep every "
                    "array, STL keeps triangles only).")
    normals.add_argument("mesh", metavar="MESH", help="the mesh file")
    normals.add_argument("-o", "--output", required=True, metavar="FILE",
                         help="the mesh to write, e.g. out.vtp")
    add_accuracy(normals, "the area vectors")
    normals.add_argument("--point-normals", action="store_true",
                         help="point normals (the point array Normals)")
    normals.add_argument("--no-cell-normals", action="store_true",
                         help="no cell normals (on by default)")
    add_weighting(normals)
    add_splitting(normals)
    add_orientation(normals)
    normals.add_argument("--area-vectors", action="store_true",
                         help="the cell array AreaVectors (w/2: its length is the area)")
    normals.add_argument("--areas", action="store_true", help="the cell array Areas")
    normals.add_argument("--status", action="store_true",
                         help="the cell array NormalStatus (0 ok, 1 degenerate, 2 non-finite, "
                              "3 not a surface, 4 on the seam of a non-orientable surface "
                              "with --consistency or --auto-orient)")
    normals.add_argument("--precision", choices=PRECISIONS, default="single",
                         help="precision of the output arrays: single (default), double, or "
                              "default (that of the points)")
    add_common(normals)
    normals.set_defaults(run=run_normals)

    area = commands.add_parser(
        "area", help="the area of a mesh a viewer sees",
        description="The visible (projected) area of MESH with vtkVisibleArea: the area seen "
                    "from the front, the direction from which the mesh looks largest and that "
                    "area (zero for a closed surface), and how many cells show their front or "
                    "back. The viewer is --view (a direction toward the viewer, parallel "
                    "projection) or a camera (--azimuth, --elevation, --parallel: perspective "
                    "by default, each cell seen from the eye).")
    area.add_argument("mesh", metavar="MESH", help="the mesh file")
    area.add_argument("--view", type=finite_float, nargs=3, metavar=("X", "Y", "Z"),
                      help="direction from the surface toward the viewer (default 0 0 1)")
    camera = area.add_argument_group("camera", "The mesh framed from the front (+z, y up), then "
                                               "turned, as in render.")
    camera.add_argument("--azimuth", type=finite_float, metavar="DEG",
                        help="turn about the vertical, degrees")
    camera.add_argument("--elevation", type=finite_float, metavar="DEG",
                        help="raise the camera, degrees")
    camera.add_argument("--parallel", action="store_true", help="parallel projection")
    add_accuracy(area, "the visible areas")
    area.add_argument("-o", "--output", metavar="FILE",
                      help="also write the mesh with the cell array VisibleArea (e.g. out.vtp)")
    area.add_argument("--json", action="store_true", help="print the results as JSON")
    add_common(area)
    area.set_defaults(run=run_area)

    benchmark = commands.add_parser(
        "bench", help="speed/accuracy tables and plots",
        description="(1) The normals ladder: time of each accuracy mode of vtkPolygonNormals "
                    "(median, and ratio to DOUBLE in the same run) and the error of its unit "
                    "normals against exact rational arithmetic computed in Python, on a mesh, "
                    "the mesh moved far from the origin, and needle triangles. (2) Shading "
                    "error against tessellation: a sphere at several resolutions drawn flat, "
                    "Gouraud and Phong, against the exact sphere shaded by the Phong model in "
                    "numpy. Plots (PNG, matplotlib) go to --plot-dir.")
    add_bench_options(benchmark)
    benchmark.add_argument("--only", choices=("normals", "shading"),
                           help="run one of the two benchmarks")
    benchmark.add_argument("--speed", action="store_true",
                           help="instead: time vtkPolygonNormals and vtkVisibleArea against "
                                "vtkPolyDataNormals, vtkTriangleMeshPointNormals and the memory "
                                "floor on a 2M-triangle sphere and the bunny, with VTK's default "
                                "(Sequential) and the STDThread SMP backend, one child process "
                                "each (--repeats: rounds, default 7); runs 1-2 minutes")
    benchmark.add_argument("--size", type=positive_int, metavar="N", dest="shading_size",
                           help="shading images are N x N pixels (default 400; --quick 128)")
    benchmark.add_argument("--parallel", action="store_true",
                           help="parallel projection for the shading benchmark")
    add_weighting(benchmark)
    benchmark.add_argument("--backend", choices=BACKENDS, default="osmesa",
                           help="headless window (default osmesa)")
    benchmark.add_argument("--plot-dir", default=".", metavar="DIR",
                           help="where the plots go (default: the current directory; '' for "
                                "none): normals-ladder.png, shading-error-vs-tessellation.png")
    add_common(benchmark)
    benchmark.set_defaults(run=run_bench)

    demo = commands.add_parser(
        "demo", help="the bunny coarse and whole, flat, Gouraud and Phong; both tables",
        description="Render a real mesh (CGAL's bunny from Debian's libcgal-demo; a "
                    "torus when it is not installed) flat, Gouraud and Phong side by side, "
                    "decimated to a few thousand triangles (where the shading modes differ "
                    "plainly) and, in the fourth panel, whole; below it a coarse torus the same "
                    "way beside a fine one; into one PNG; then print the "
                    "normals ladder of that mesh and the shading error against tessellation "
                    "(as bench does).")
    demo.add_argument("-o", "--output", default="phongvtk-demo.png", metavar="PNG",
                      help="the image to write (default phongvtk-demo.png)")
    demo.add_argument("--coarse", type=positive_int, default=2000, metavar="N",
                      help="triangles of the decimated copy (default 2000; none when the mesh "
                           "has fewer than 2N)")
    demo.add_argument("--no-table", action="store_true", help="only the picture")
    add_bench_options(demo)
    add_scene(demo, (400, 400), "panel", zoom=1.4, split=False)
    add_common(demo)
    demo.set_defaults(run=run_demo)
    return parser


def add_bench_options(parser):
    """The normals ladder's options (bench and demo)."""
    parser.add_argument("--mesh", metavar="MESH",
                        help="the mesh (default: CGAL's bunny, else a torus)")
    parser.add_argument("--quick", action="store_true",
                        help="a small, fast version (a few seconds)")
    parser.add_argument("--repeats", type=positive_int, metavar="N",
                        help="timed runs per mode (default 9; --quick 3)")
    parser.add_argument("--sample", type=positive_int, metavar="N",
                        help="polygons per input checked against exact arithmetic "
                             "(default 20000; --quick 200)")
    parser.add_argument("--offset", type=finite_float, default=1e7, metavar="D",
                        help="the far copy of the mesh is moved by (D, D, D) (default 1e7)")


def vtk_version():
    """VTK's version string."""
    from vtkmodules.vtkCommonCore import vtkVersion

    return vtkVersion.GetVTKVersion()


def main(argv=None):
    """Runs the command line `argv` (default sys.argv[1:]); returns the exit status."""
    args = build_parser().parse_args(argv)
    progress = Progress(quiet=args.quiet)
    # A write past the file-size limit (ulimit -f) then fails with EFBIG, which the writers
    # report, instead of killing the process with half a temporary file left behind.
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    try:
        use_threads(getattr(args, "threads", None))
        args.run(args, progress)
    except CommandError as error:
        progress.abandon()
        message = " ".join(str(error).split())
        print(f"phongvtk: error: {message}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        progress.abandon()
        print("phongvtk: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # The reader of stdout went away (e.g. `| head`): point stdout at /dev/null so that
        # Python's final flush does not fail again.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    return 0
