"""What PhongVTK's trades cost and buy, measured from Python against references computed here.

1. The normals ladder: for each accuracy mode of vtkPolygonNormals, the median time of the cell
   normals of a mesh (and the ratio to DOUBLE in the same run) and the error of the unit normals
   against exact rational arithmetic (Python integers from the definition
   ``w = sum (p_i - p0) x (p_(i+1) - p0)``, the unit normal to 60 decimal digits), on a sample of
   cells, for an ordinary mesh, the same mesh moved far from the origin, and needle triangles.
2. Shading error against tessellation: a sphere at several resolutions drawn by
   vtkPhongPolyDataMapper flat, Gouraud and Phong, compared pixel by pixel with the exact sphere
   shaded by the Phong model in numpy (ray-sphere intersection, exact normal), in 8-bit LSB.

Nothing here uses the C++ code's arithmetic: the references follow the definitions.
"""

import decimal
import math
import statistics
import time
from dataclasses import dataclass, field
from decimal import Decimal
from typing import Optional

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkSMPTools
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
from vtkmodules.vtkFiltersSources import vtkSphereSource

import phongvtk

from .errors import CommandError
from .io import polydata_from_arrays
from .progress import Progress
from .render import (
    SHADING_LABELS,
    Light,
    Material,
    Scene,
    capture,
    make_renderer,
    make_window,
    normals_filter,
    pixels,
    shaded_actor,
)

#: vtkPolygonNormals' accuracy modes, fastest first (the value is the index).
MODES = ("FAST", "DOUBLE", "COMPENSATED", "EXACT")
#: Decimal digits of the exact unit normals: far beyond double's 17.
REFERENCE_CONTEXT = decimal.Context(prec=60)

# --- exact arithmetic -----------------------------------------------------------------------


def exact_area_vector(polygon):
    """The exact area vector of `polygon` (a sequence of (x, y, z) floats) as three Python
    integers, scaled by a power of two (which does not change its direction); None when a
    coordinate is not finite.

    Every double is an integer times a power of two, so the polygon's coordinates are integers
    over the largest denominator, and w = sum (p_i - p0) x (p_(i+1) - p0) is integer arithmetic.
    """
    try:
        ratios = [[value.as_integer_ratio() for value in point] for point in polygon]
    except (OverflowError, ValueError):
        return None
    scale = max(denominator for point in ratios for _, denominator in point)
    p = [[numerator * (scale // denominator) for numerator, denominator in point]
         for point in ratios]
    x0, y0, z0 = p[0]
    wx = wy = wz = 0
    for (x1, y1, z1), (x2, y2, z2) in zip(p[1:-1], p[2:]):
        ax, ay, az = x1 - x0, y1 - y0, z1 - z0
        bx, by, bz = x2 - x0, y2 - y0, z2 - z0
        wx += ay * bz - az * by
        wy += az * bx - ax * bz
        wz += ax * by - ay * bx
    return wx, wy, wz


def exact_unit_normal(w):
    """w/|w| for the integer vector `w`, each component to 60 significant digits; None for 0."""
    if not any(w):
        return None
    with decimal.localcontext(REFERENCE_CONTEXT):
        length = Decimal(sum(c * c for c in w)).sqrt()
        return tuple(Decimal(c) / length for c in w)


def ulp_error(value, exact, single):
    """|value - exact| in units in the last place of `exact` in float (`single`) or double: the
    spacing of the format in the binade of `exact` (the subnormal spacing below the normal
    range). A faithfully rounded value is within 1."""
    digits, min_exp = (24, -125) if single else (53, -1021)  # 2^(min_exp - 1): smallest normal
    with decimal.localcontext(REFERENCE_CONTEXT):
        difference = abs(Decimal(value) - exact)
        if exact == 0:
            return float(difference / (Decimal(2) ** (min_exp - digits)))
        size = abs(exact)
        exponent = math.frexp(float(size))[1]  # size ~ m 2^exponent, 0.5 <= m < 1
        if Decimal(2) ** (exponent - 1) > size:  # float() rounded up to the next binade
            exponent -= 1
        return float(difference / Decimal(2) ** (max(exponent, min_exp) - digits))


def angle_error(value, exact):
    """Angle in radians between the computed vector `value` and the exact unit vector."""
    with decimal.localcontext(REFERENCE_CONTEXT):
        v = [Decimal(c) for c in value]
        cross = [v[1] * exact[2] - v[2] * exact[1], v[2] * exact[0] - v[0] * exact[2],
                 v[0] * exact[1] - v[1] * exact[0]]
        sine = sum(c * c for c in cross).sqrt()
        cosine = sum(a * b for a, b in zip(v, exact))
        return math.atan2(float(sine), float(cosine))


# --- inputs ---------------------------------------------------------------------------------


@dataclass
class LadderInput:
    """A mesh of the ladder (double points, polygons only) and how the table names it."""

    name: str
    mesh: vtkPolyData


def polygons_of(mesh):
    """(points as float64 n x 3, offsets, connectivity) of the polygons of `mesh`."""
    if mesh.GetNumberOfPolys() == 0:
        raise CommandError("the normals ladder needs a mesh with polygons")
    points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    polys = mesh.GetPolys()
    offsets = numpy_support.vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    connectivity = numpy_support.vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    return points, offsets, connectivity


def translated(mesh, offset):
    """The polygons of `mesh` with double points moved by (offset, offset, offset)."""
    points, offsets, connectivity = polygons_of(mesh)
    return polydata_from_arrays(points + offset, offsets, connectivity)


def needles(count, aspect=1e12, seed=1):
    """`count` separate needle triangles: a unit-long edge and an apex `1/aspect` off its
    midpoint, in random directions (their cross products cancel to 1/aspect of their terms)."""
    rng = np.random.default_rng(seed)
    start = rng.random((count, 3))
    along = rng.normal(size=(count, 3))
    along /= np.linalg.norm(along, axis=1)[:, None]
    across = np.cross(along, rng.normal(size=(count, 3)))
    across /= np.linalg.norm(across, axis=1)[:, None]
    corners = np.stack([start, start + along, start + 0.5 * along + across / aspect], axis=1)
    offsets = np.arange(0, 3 * count + 1, 3, dtype=np.int64)
    return polydata_from_arrays(corners.reshape(-1, 3), offsets, np.arange(3 * count))


def short(number):
    """A number as a person writes it in a table: 1e7, 2.5e-3, 1000."""
    return f"{number:g}".replace("e+0", "e").replace("e+", "e").replace("e-0", "e-")


def ladder_inputs(mesh, label, offset=1e7, needle_count=20000):
    """The ladder's inputs: `mesh` as it is, moved by `offset`, scaled by 2^-1000 and by 2^1000
    (exactly: the same polygons at the ends of the double range, where a product of two
    coordinates under- or overflows), and needles of aspect 1e12."""
    points, offsets, connectivity = polygons_of(mesh)
    ordinary = polydata_from_arrays(points, offsets, connectivity)
    return [
        LadderInput(f"ordinary: {label}", ordinary),
        LadderInput(f"offset {short(offset)}: {label}", translated(ordinary, offset)),
        LadderInput(f"tiny, x 2^-1000: {label}",
                    polydata_from_arrays(np.ldexp(points, -1000), offsets, connectivity)),
        LadderInput(f"huge, x 2^1000: {label}",
                    polydata_from_arrays(np.ldexp(points, 1000), offsets, connectivity)),
        LadderInput("needles, aspect 1e12", needles(needle_count)),
    ]


# --- the normals ladder ---------------------------------------------------------------------


@dataclass
class LadderRow:
    """One mode on one input: median seconds, time / DOUBLE's, errors of the unit normals (ulps
    of the output precision, float for FAST; radians; None when no normal could be compared),
    count of zero/non-zero mismatches."""

    input: str
    mode: str
    polygons: int
    seconds: float
    ratio: float
    worst_ulp: Optional[float]
    median_ulp: Optional[float]
    worst_rad: Optional[float]
    median_rad: Optional[float]
    zero_errors: int

    @property
    def single(self):
        """FAST writes float normals: its ulps are float ulps."""
        return self.mode == "FAST"


def sample_polygons(count, sample, seed=2):
    """Sorted ids of `sample` polygons out of `count` (all when there are fewer)."""
    if count <= sample:
        return np.arange(count)
    return np.sort(np.random.default_rng(seed).choice(count, sample, replace=False))


def reference_normals(mesh, ids):
    """For each polygon id: the exact unit normal (Decimals), or None when the exact area
    vector is zero, or "skip" when a coordinate is not finite."""
    points, offsets, connectivity = polygons_of(mesh)
    result = []
    for cell in ids:
        corners = points[connectivity[offsets[cell]:offsets[cell + 1]]]
        w = exact_area_vector([tuple(map(float, corner)) for corner in corners])
        result.append("skip" if w is None else exact_unit_normal(w))
    return result


def normals_by_mode(mesh):
    """One vtkPolygonNormals per mode on `mesh`: cell normals only, float output for FAST and
    double for the others (so that each mode's own rounding is what is measured)."""
    filters = {}
    for index, mode in enumerate(MODES):
        normals = phongvtk.vtkPolygonNormals()
        normals.SetInputData(mesh)
        normals.SetAccuracy(index)
        normals.SetComputeCellNormals(True)
        normals.SetComputePointNormals(False)
        normals.SetConsistency(False)  # the polygons as given: the area vectors alone are timed
        normals.SetOutputPrecision(
            vtkAlgorithm.SINGLE_PRECISION if mode == "FAST" else vtkAlgorithm.DOUBLE_PRECISION
        )
        filters[mode] = normals
    return filters


#: Shortest timed sample: a mode that takes less per run is timed over several runs at once, so
#: that the clock's resolution and the noise of one short run do not decide the ranking.
MIN_SAMPLE_SECONDS = 0.02


def median_times(filters, repeats):
    """Median seconds of one Update() per filter. Every filter is warmed up first (allocation,
    first touch of the input and output), then each sample times a batch of runs of that filter
    long enough to measure; the filters take turns, starting with a different one each round,
    so that the machine's drift and noise fall on all of them alike."""

    def run(normals, count):
        start = time.perf_counter()
        for _ in range(count):
            normals.Modified()
            normals.Update()
        return (time.perf_counter() - start) / count

    once = {}
    for _ in range(2):  # the first round allocates; the second is what a run costs
        once = {mode: run(normals, 1) for mode, normals in filters.items()}
    batches = {mode: max(1, math.ceil(MIN_SAMPLE_SECONDS / max(seconds, 1e-9)))
               for mode, seconds in once.items()}
    times = {mode: [] for mode in filters}
    order = list(filters)
    for round_ in range(repeats):
        for mode in order[round_ % len(order):] + order[:round_ % len(order)]:
            times[mode].append(run(filters[mode], batches[mode]))
    return {mode: statistics.median(values) for mode, values in times.items()}


def errors_of(normals, ids, reference, single):
    """(ulp errors, angle errors, zero mismatches) of the computed cell `normals` (a numpy
    array indexed by polygon id) against the reference."""
    ulps, angles, zero_errors = [], [], 0
    for cell, exact in zip(ids, reference):
        if exact == "skip":
            continue
        value = [float(c) for c in normals[cell]]
        computed_zero = not any(value)
        if exact is None or computed_zero:
            zero_errors += (exact is None) != computed_zero
            continue
        ulps.append(max(ulp_error(v, e, single) for v, e in zip(value, exact)))
        angles.append(angle_error(value, exact))
    return ulps, angles, zero_errors


def measure_ladder(inputs, repeats=7, sample=2000, progress=None):
    """The ladder's rows for every input and mode."""
    progress = progress or Progress(quiet=True)
    rows = []
    for item in inputs:
        bar = progress.bar(f"ladder: {item.name}")
        polygons = item.mesh.GetNumberOfPolys()
        first_poly = item.mesh.GetNumberOfVerts() + item.mesh.GetNumberOfLines()
        ids = sample_polygons(polygons, sample)
        reference = reference_normals(item.mesh, ids)
        bar.update(0.3)
        filters = normals_by_mode(item.mesh)
        seconds = median_times(filters, repeats)
        bar.update(0.6)
        for mode, normals in filters.items():
            array = numpy_support.vtk_to_numpy(normals.GetOutput().GetCellData().GetNormals())
            ulps, angles, zeros = errors_of(array[first_poly:], ids, reference, mode == "FAST")
            rows.append(LadderRow(
                input=item.name, mode=mode, polygons=polygons, seconds=seconds[mode],
                ratio=seconds[mode] / seconds["DOUBLE"],
                worst_ulp=max(ulps, default=None), median_ulp=median(ulps),
                worst_rad=max(angles, default=None), median_rad=median(angles),
                zero_errors=zeros))
        bar.finish()
    return rows


def median(values):
    """The median, None for no values."""
    return statistics.median(values) if values else None


def number(value, spec, width):
    """`value` formatted by `spec` and right-aligned in `width`; "-" for None."""
    return f"{'-' if value is None else format(value, spec):>{width}}"


def format_ladder(rows, repeats, sample):
    """The ladder as a Markdown table with a caption."""
    lines = [
        f"vtkPolygonNormals speed/accuracy ladder (cell normals; SMP backend "
        f"{vtkSMPTools.GetBackend()}, {vtkSMPTools.GetEstimatedNumberOfThreads()} threads; "
        f"time = median of {repeats} samples after a warm-up, the modes taking turns, each "
        f"sample a batch of runs of at least {1e3 * MIN_SAMPLE_SECONDS:g} ms; ratio to DOUBLE "
        "in the same run)",
        f"Errors of the unit normals against exact rational arithmetic on up to {sample} "
        "polygons per input: largest component in ulps of the output precision ((f) float, "
        "(d) double), and the angle in radians.",
        "",
        "| input                          | mode        |  polygons |    ms | vs DOUBLE "
        "|     worst ulp | median ulp |  worst rad | median rad | zero err |",
        "|--------------------------------|-------------|-----------|-------|-----------"
        "|---------------|------------|------------|------------|----------|",
    ]
    for row in rows:
        unit = "(f)" if row.single else "(d)"
        lines.append(
            f"| {row.input:<30.30} | {row.mode:<11} | {row.polygons:>9} | "
            f"{1e3 * row.seconds:>5.2f} | {row.ratio:>8.2f}x | "
            f"{number(row.worst_ulp, '.3g', 9)} {unit} | {number(row.median_ulp, '.3g', 10)} | "
            f"{number(row.worst_rad, '.2e', 10)} | {number(row.median_rad, '.2e', 10)} | "
            f"{row.zero_errors:>8} |"
        )
    lines.append("")
    lines.append("zero err: polygons whose computed normal is zero while the exact area vector "
                 "is not, or the reverse (not in the other columns; '-': none left to compare).")
    return "\n".join(lines)


# --- shading error against tessellation -----------------------------------------------------


@dataclass
class SphereScene:
    """The sphere the shading benchmark draws, and everything that lights and frames it."""

    radius: float = 0.5
    eye: tuple = (0.0, 0.0, 3.2)
    view_angle: float = 30.0
    parallel: bool = False
    parallel_scale: float = 0.6
    light: Light = field(default_factory=lambda: Light(direction=(1.0, 1.0, 2.0)))
    ambient: tuple = (0.2, 0.2, 0.2)
    material: Material = field(default_factory=lambda: Material(
        color=(0.9, 0.6, 0.3), preset=None, ambient=0.15, diffuse=0.7, specular=0.5,
        specular_power=40.0, specular_color=(1.0, 1.0, 1.0)))
    margin: float = 0.3  # pixels where the exact sphere is seen more obliquely are not compared

    def apply(self, renderer):
        """Points the renderer's camera (focal point at the centre, y up)."""
        camera = renderer.GetActiveCamera()
        camera.SetPosition(*self.eye)
        camera.SetFocalPoint(0.0, 0.0, 0.0)
        camera.SetViewUp(0.0, 1.0, 0.0)
        camera.SetViewAngle(self.view_angle)
        camera.SetParallelProjection(self.parallel)
        camera.SetParallelScale(self.parallel_scale)
        camera.SetClippingRange(0.5, 20.0)

    def rays(self, width, height):
        """Origins and unit directions of the rays through the pixel centres, rows from the top
        (width x height pixels, the camera of :meth:`apply`)."""
        eye = np.array(self.eye)
        forward = -eye / np.linalg.norm(eye)
        right = np.cross(forward, [0.0, 1.0, 0.0])
        right /= np.linalg.norm(right)
        up = np.cross(right, forward)
        x = (np.arange(width) + 0.5) / width * 2 - 1
        y = ((np.arange(height) + 0.5) / height * 2 - 1)[::-1]  # top row first
        x, y = np.meshgrid(x * width / height, y)
        if self.parallel:
            s = self.parallel_scale
            origins = eye + s * x[..., None] * right + s * y[..., None] * up
            directions = np.broadcast_to(forward, origins.shape)
        else:
            t = math.tan(math.radians(self.view_angle) / 2)
            directions = forward + t * x[..., None] * right + t * y[..., None] * up
            directions /= np.linalg.norm(directions, axis=-1, keepdims=True)
            origins = np.broadcast_to(eye, directions.shape)
        return origins, directions

    def reference(self, width, height):
        """(colours in [0, 1], mask): the exact sphere shaded by the Phong model per pixel,
        rows from the top; the mask marks the pixels to compare."""
        origins, directions = self.rays(width, height)
        b = np.einsum("ijk,ijk->ij", origins, directions)
        disc = b * b - (np.einsum("ijk,ijk->ij", origins, origins) - self.radius**2)
        hit = disc > 0
        s = -b - np.sqrt(np.where(hit, disc, 0.0))
        points = origins + s[..., None] * directions
        n = points / self.radius
        v = -directions
        mask = hit & (np.einsum("ijk,ijk->ij", n, v) >= self.margin)
        return self.phong(n, v), mask

    def phong(self, n, v):
        """The Phong model with unit normals `n` and eye vectors `v` (arrays ... x 3):
        ka Ia + kd Id max(n.l, 0) + ks Is max(v.r, 0)^alpha, r = 2 (l.n) n - l, nothing from the
        light when n.l <= 0, clamped to [0, 1]."""
        m = self.material
        color = np.array(m.color)
        ka, kd = m.ambient * color, m.diffuse * color
        ks = m.specular * np.array(m.specular_color)
        light = self.light
        to_light = np.array(light.direction) / np.linalg.norm(light.direction)
        i_d = i_s = light.intensity * np.array(light.color)
        nl = np.einsum("...k,k->...", n, to_light)
        r = 2 * nl[..., None] * n - to_light
        vr = np.maximum(np.einsum("...k,...k->...", v, r), 0.0)
        lit = (nl > 0)[..., None]
        colour = ka * np.array(self.ambient) + lit * (
            kd * i_d * np.maximum(nl, 0.0)[..., None] + ks * i_s * (vr**m.specular_power)[..., None]
        )
        return np.clip(colour, 0.0, 1.0)

    def mesh(self, theta):
        """vtkSphereSource's sphere with `theta` x (theta/2 + 2) divisions: theta^2 triangles,
        without the source's own normals (vtkPolygonNormals computes them, as in render)."""
        source = vtkSphereSource()
        source.SetRadius(self.radius)
        source.SetThetaResolution(theta)
        source.SetPhiResolution(theta // 2 + 2)
        source.Update()
        mesh = source.GetOutput()
        mesh.GetPointData().RemoveArray("Normals")
        return mesh


@dataclass
class ShadingRow:
    """Error of one tessellation: {shading: (rms, max)} in 8-bit LSB over `pixels` pixels."""

    triangles: int
    pixels: int
    errors: dict


def measure_shading(thetas, size=400, parallel=False, weighting="area", backend="osmesa",
                    progress=None):
    """Draws the sphere of :class:`SphereScene` at each resolution in `thetas` flat, Gouraud
    and Phong (point normals weighted by `weighting`; one window, `size` pixels square) and
    compares it with the exact sphere."""
    progress = progress or Progress(quiet=True)
    sphere = SphereScene(parallel=parallel)
    expected, mask = sphere.reference(size, size)
    expected = 255.0 * expected[mask]
    window = make_window((size, size), backend)
    renderer = make_renderer(Scene(lights=[sphere.light], ambient=sphere.ambient,
                                   background=(0.0, 0.0, 0.0)))
    sphere.apply(renderer)
    window.AddRenderer(renderer)
    rows = []
    bar = progress.bar("shading")
    for step, theta in enumerate(thetas):
        mesh = sphere.mesh(theta)
        errors = {}
        for shading in SHADING_LABELS:
            normals = normals_filter(mesh, shading, weighting=weighting)
            normals.Update()
            renderer.RemoveAllViewProps()
            renderer.AddActor(shaded_actor(normals.GetOutput(), shading, sphere.material))
            window.Render()
            difference = pixels(capture(window))[mask].astype(float) - expected
            errors[shading] = (float(np.sqrt(np.mean(difference**2))),
                               float(np.abs(difference).max()))
        rows.append(ShadingRow(mesh.GetNumberOfPolys(), int(mask.sum()), errors))
        bar.update((step + 1) / len(thetas))
    bar.finish()
    window.Finalize()
    return rows


def format_shading(rows, size, parallel, weighting="area"):
    """The shading errors as a table, and where each mode reaches 1 LSB RMS."""
    projection = "parallel" if parallel else "perspective"
    lines = [
        f"Shading error against the exact sphere ({size} x {size} pixels, {projection}, one "
        f"directional light, ambient + diffuse + specular; {rows[0].pixels if rows else 0} "
        "pixels where the sphere is seen at a cosine >= 0.3): RMS / max in 8-bit LSB",
        f"Normals by vtkPolygonNormals: cell normals (flat), point normals weighted by "
        f"{weighting.upper()} (Gouraud, Phong).",
        "",
        f"{'triangles':>10} " + " ".join(f"{SHADING_LABELS[s] + ' rms/max':>17}"
                                         for s in SHADING_LABELS),
    ]
    for row in rows:
        lines.append(f"{row.triangles:>10} " + " ".join(
            f"{row.errors[s][0]:>8.2f} / {row.errors[s][1]:>6.1f}" for s in SHADING_LABELS))
    for shading in SHADING_LABELS:
        reached = [row.triangles for row in rows if row.errors[shading][0] <= 1.0]
        where = f"at {reached[0]} triangles" if reached else "not within these resolutions"
        lines.append(f"{SHADING_LABELS[shading]:<8} reaches 1 LSB RMS {where}")
    return "\n".join(lines)


# --- plots ----------------------------------------------------------------------------------


def pyplot():
    """matplotlib's pyplot with the file-only Agg backend (no display needed)."""
    try:
        import matplotlib
    except ImportError:
        raise CommandError("plots need matplotlib (Debian: python3-matplotlib)") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def blend(axis):
    """Coordinates of `axis`: x in data units, y as a fraction of the axis height."""
    from matplotlib.transforms import blended_transform_factory

    return blended_transform_factory(axis.transData, axis.transAxes)


def plot_ladder(rows, path):
    """The ladder per input: each mode's time relative to DOUBLE (left) and the worst (solid)
    and median (dashed) angle error of its unit normals (right, log scale)."""
    plt = pyplot()
    figure, (cost, error) = plt.subplots(1, 2, figsize=(10, 4.2))
    steps = range(len(MODES))
    inputs = list(dict.fromkeys(row.input for row in rows))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for name, marker, colour in zip(inputs, "osD^v", colours):
        mine = {row.mode: row for row in rows if row.input == name}
        cost.plot(steps, [mine[mode].ratio for mode in MODES], marker=marker, color=colour,
                  label=name)
        for attribute, style in (("worst_rad", "-"), ("median_rad", "--")):
            values = [getattr(mine[mode], attribute) for mode in MODES]
            values = [np.nan if value is None else max(value, 1e-18) for value in values]
            error.semilogy(steps, values, marker=marker, linestyle=style, color=colour)
        for step, mode in zip(steps, MODES):
            row = mine[mode]
            if row.zero_errors:  # not in the angles: say how many normals came out zero
                error.text(step + 0.08, 0.97, f"{row.zero_errors} of the sampled\nnormals zero",
                           color=colour, fontsize=7, ha="left", va="top",
                           transform=blend(error))
    for axis in (cost, error):
        axis.set_xticks(list(steps), [mode.lower() for mode in MODES])
        axis.grid(True, which="both", alpha=0.3)
    cost.set_ylabel("time / DOUBLE's time (same run)")
    cost.set_title("what a mode costs")
    cost.legend(fontsize=8)
    error.set_ylabel("angle to the exact normal, radians")
    error.set_title("what it buys: worst (solid), median (dashed) error")
    figure.suptitle("vtkPolygonNormals' accuracy ladder")
    figure.tight_layout()
    figure.savefig(path, dpi=80)
    plt.close(figure)


def plot_shading(rows, path):
    """RMS error against the triangle count, log-log, one line per shading mode."""
    plt = pyplot()
    figure, axis = plt.subplots(figsize=(6.4, 4.4))
    triangles = [row.triangles for row in rows]
    for shading, marker in zip(SHADING_LABELS, "os^"):
        axis.loglog(triangles, [row.errors[shading][0] for row in rows], marker=marker,
                    label=SHADING_LABELS[shading])
    axis.axhline(1.0, color="grey", linestyle="--", linewidth=1)
    axis.text(triangles[0], 1.05, "1 LSB", color="grey", fontsize=8)
    axis.set_xlabel("triangles")
    axis.set_ylabel("RMS error against the exact sphere (8-bit LSB)")
    axis.set_title("Shading error against tessellation (vtkPhongPolyDataMapper)")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=80)
    plt.close(figure)
