"""Scenes for the command-line interface: a mesh with vtkPolygonNormals' normals, drawn by
vtkPhongPolyDataMapper under directional lights in a headless window.

``render`` draws one panel, ``demo`` three side by side (flat, Gouraud, Phong), ``bench`` reuses
the pieces to draw a sphere many times; all of them describe the scene with the same small
records (:class:`Material`, :class:`Light`, :class:`View`, :class:`Scene`).
"""

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkLight,
    vtkRenderer,
    vtkTextActor,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text of the panel labels)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL actors, renderers, cameras)

import phongvtk

from .errors import CommandError
from .progress import Progress

RGB = Tuple[float, float, float]

#: Shading modes, as vtkProperty's interpolation (VTK_FLAT, VTK_GOURAUD, VTK_PHONG).
SHADINGS = {"flat": 0, "gouraud": 1, "phong": 2}
#: Names shown to people.
SHADING_LABELS = {"flat": "flat", "gouraud": "Gouraud", "phong": "Phong"}
#: vtkPolygonNormals' accuracy modes (the same values in vtkVisibleArea).
ACCURACIES = {"fast": 0, "double": 1, "compensated": 2, "exact": 3}
#: vtkPolygonNormals' weightings of the faces around a point.
WEIGHTINGS = {"area": 0, "angle": 1, "uniform": 2, "max": 3}
#: vtkPhongPolyDataMapper.ApplyPreset's names.
PRESETS = ("plastic", "metal", "matte")
def _backends():
    """Headless window classes by backend name: PhongVTK's own (PhongVTK::RenderingHeadless,
    VTK before 9.4), else VTK's (9.4 and later build OSMesa always and EGL by default)."""
    if phongvtk.HEADLESS:
        return {
            "osmesa": phongvtk.vtkHeadlessOSMesaRenderWindow,
            "egl": phongvtk.vtkHeadlessEGLRenderWindow,
        }
    import vtkmodules.vtkRenderingOpenGL2 as opengl

    found = {
        "osmesa": getattr(opengl, "vtkOSOpenGLRenderWindow", None),
        "egl": getattr(opengl, "vtkEGLRenderWindow", None),
    }
    return {name: window for name, window in found.items() if window is not None}


#: Headless window classes by backend name.
BACKENDS = _backends()


@dataclass
class Material:
    """The surface: a diffuse colour, a preset of vtkPhongPolyDataMapper (applied to that
    colour), then any coefficient given explicitly (None: the preset's or VTK's)."""

    color: RGB = (0.9, 0.6, 0.3)
    preset: Optional[str] = "plastic"
    ambient: Optional[float] = None
    diffuse: Optional[float] = None
    specular: Optional[float] = None
    specular_power: Optional[float] = None
    specular_color: Optional[RGB] = None

    def apply(self, prop):
        """Sets this material on the vtkProperty `prop`."""
        prop.SetDiffuseColor(*self.color)
        prop.SetAmbientColor(*self.color)
        if self.preset is not None:
            if not phongvtk.vtkPhongPolyDataMapper.ApplyPreset(prop, self.preset):
                raise CommandError(f"unknown material preset '{self.preset}'")
        for value, setter in (
            (self.ambient, prop.SetAmbient),
            (self.diffuse, prop.SetDiffuse),
            (self.specular, prop.SetSpecular),
            (self.specular_power, prop.SetSpecularPower),
        ):
            if value is not None:
                setter(value)
        if self.specular_color is not None:
            prop.SetSpecularColor(*self.specular_color)


@dataclass
class Light:
    """A directional light. `direction` points from the scene toward the light (vtkLight's
    position with the focal point at the origin): in world coordinates, or in the camera's
    frame (x right, y up, z toward the viewer) when `camera` is true."""

    direction: Tuple[float, float, float]
    color: RGB = (1.0, 1.0, 1.0)
    intensity: float = 1.0
    camera: bool = False

    def make(self):
        """The vtkLight: no ambient colour of its own (the scene's ambient light is separate)."""
        if not any(self.direction) or not all(map(math.isfinite, self.direction)):
            raise CommandError(f"a light direction must be finite and non-zero: {self.direction}")
        light = vtkLight()
        if self.camera:
            light.SetLightTypeToCameraLight()
        else:
            light.SetLightTypeToSceneLight()
        light.PositionalOff()
        light.SetPosition(*self.direction)
        light.SetFocalPoint(0.0, 0.0, 0.0)
        light.SetColor(*self.color)  # diffuse and specular
        light.SetAmbientColor(0.0, 0.0, 0.0)
        light.SetIntensity(self.intensity)
        return light


#: The light when none is given: a white key light from the viewer's upper left.
KEY_LIGHT = Light(direction=(-1.0, 1.0, 1.5), camera=True)


@dataclass
class View:
    """The camera: the mesh's bounding sphere framed from the front (+z, y up), then turned by
    `azimuth` about the vertical and raised by `elevation` (degrees, as vtkCamera's Azimuth
    then Elevation); perspective (30 degree view angle) or parallel projection; magnified by
    `zoom` (vtkCamera's Zoom: the eye stays where it is)."""

    azimuth: float = 0.0
    elevation: float = 0.0
    parallel: bool = False
    zoom: float = 1.0

    def direction(self):
        """Unit vector from the focal point toward the eye."""
        a, e = math.radians(self.azimuth), math.radians(self.elevation)
        return (math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a))

    def up(self):
        """Unit view-up vector, perpendicular to :meth:`direction` (defined at the poles too)."""
        a, e = math.radians(self.azimuth), math.radians(self.elevation)
        return (-math.sin(e) * math.sin(a), math.cos(e), -math.sin(e) * math.cos(a))

    def frame(self, camera, bounds, aspect=1.0):
        """Points the vtkCamera `camera` at the bounding sphere of `bounds` (xmin, xmax, ...) so
        that the sphere fills the smaller side of a viewport of width/height `aspect`."""
        centre = np.array([(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                           (bounds[4] + bounds[5]) / 2])
        radius = 0.5 * math.dist(bounds[0::2], bounds[1::2]) or 1.0
        half_angle = math.radians(camera.GetViewAngle()) / 2
        if aspect < 1.0:  # the width is the smaller side: fit the horizontal angle
            half_angle = math.atan(math.tan(half_angle) * aspect)
        distance = radius / math.sin(half_angle)
        camera.SetFocalPoint(*centre)
        camera.SetPosition(*(centre + distance * np.array(self.direction())))
        camera.SetViewUp(*self.up())
        camera.SetParallelProjection(self.parallel)
        camera.SetParallelScale(radius / min(aspect, 1.0))
        camera.SetClippingRange(max(distance - 1.01 * radius, 1e-3 * distance),
                                distance + 1.01 * radius)
        camera.Zoom(self.zoom)


@dataclass
class Scene:
    """Everything but the mesh: material, lights (none: :data:`KEY_LIGHT`), the scene's ambient
    light Ia (or `derived_ambient`: vtkPhongPolyDataMapper's SceneAmbient), camera, background,
    and the accuracy, point weighting and feature angle of the normals (`feature_angle` None:
    no splitting at sharp edges), and how the polygons are oriented first (`orientation`:
    vtkPolygonNormals option name -> value, e.g. {"AutoOrientNormals": True})."""

    material: Material = field(default_factory=Material)
    lights: List[Light] = field(default_factory=list)
    ambient: RGB = (1.0, 1.0, 1.0)
    derived_ambient: bool = False
    view: View = field(default_factory=View)
    background: RGB = (0.1, 0.1, 0.12)
    accuracy: str = "double"
    weighting: str = "area"
    feature_angle: Optional[float] = None
    orientation: Dict[str, bool] = field(default_factory=dict)


def normals_filter(mesh, shading, accuracy="double", weighting="area", feature_angle=None,
                   orientation=None):
    """vtkPolygonNormals on `mesh` as `shading` needs them: cell normals for flat, point normals
    (faces weighted by `weighting`) for Gouraud and Phong, split at edges sharper than
    `feature_angle` degrees unless it is None; `orientation` sets the orientation options
    (Consistency, AutoOrientNormals, NonManifoldTraversal, FlipNormals) by name."""
    normals = phongvtk.vtkPolygonNormals()
    normals.SetInputData(mesh)
    normals.SetAccuracy(ACCURACIES[accuracy])
    normals.SetPointWeighting(WEIGHTINGS[weighting])
    smooth = shading != "flat"
    normals.SetComputeCellNormals(not smooth)
    normals.SetComputePointNormals(smooth)
    normals.SetSplitting(feature_angle is not None)
    if feature_angle is not None:
        normals.SetFeatureAngle(feature_angle)
    # The polygons as given unless `orientation` says otherwise (the filter's defaults are
    # vtkPolyDataNormals': Consistency and NonManifoldTraversal on).
    given = {"Consistency": False, "AutoOrientNormals": False, "NonManifoldTraversal": False,
             "FlipNormals": False}
    for name, value in {**given, **(orientation or {})}.items():
        getattr(normals, f"Set{name}")(value)
    return normals


def shaded_actor(surface, shading, material):
    """An actor drawing the vtkPolyData `surface` (with normals) by vtkPhongPolyDataMapper."""
    mapper = phongvtk.vtkPhongPolyDataMapper()
    mapper.SetInputData(surface)
    mapper.ScalarVisibilityOff()  # the material's colour, not whatever scalars a file holds
    actor = vtkActor()
    actor.SetMapper(mapper)
    material.apply(actor.GetProperty())
    actor.GetProperty().SetInterpolation(SHADINGS[shading])
    return actor


def make_renderer(scene, viewport=(0.0, 0.0, 1.0, 1.0)):
    """A renderer with the scene's lights, ambient light and background (no actors yet)."""
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(*scene.background)
    renderer.SetAmbient(*scene.ambient)
    renderer.AutomaticLightCreationOff()
    for light in scene.lights or [KEY_LIGHT]:
        renderer.AddLight(light.make())
    return renderer


def add_label(renderer, text, height, background):
    """Writes `text` in the top-left corner of `renderer` (a viewport `height` pixels
    tall), in white or black, whichever stands out from `background`."""
    label = vtkTextActor()
    label.SetInput(text)
    prop = label.GetTextProperty()
    prop.SetFontSize(max(10, height // (14 if "\n" in text else 12)))
    prop.SetVerticalJustificationToTop()
    luminance = 0.2126 * background[0] + 0.7152 * background[1] + 0.0722 * background[2]
    prop.SetColor(*((0.0,) * 3 if luminance > 0.5 else (1.0,) * 3))
    label.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    label.GetPositionCoordinate().SetValue(0.03, 0.97)
    renderer.AddActor2D(label)


def make_window(size, backend="osmesa"):
    """A headless render window of `size` (width, height): OSMesa by default, or EGL."""
    if backend not in BACKENDS:
        raise CommandError(f"unknown window backend '{backend}' (known: {', '.join(BACKENDS)})")
    window = BACKENDS[backend]()
    window.SetSize(*size)
    window.SetMultiSamples(0)
    return window


def capture(window):
    """The last frame of `window` as a vtkImageData (RGB, bottom row first, as VTK stores it)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    image = vtkImageData()
    image.DeepCopy(grab.GetOutput())
    return image


def pixels(image):
    """The RGB pixels of the vtkImageData `image` as a uint8 array rows x columns x 3, top row
    first (as a PNG file or matplotlib shows it)."""
    width, height, _ = image.GetDimensions()
    values = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars())
    return values.reshape(height, width, -1)[::-1, :, :3]


@dataclass
class Panel:
    """One panel of a picture: `mesh` drawn in `shading`, labelled `label` (when labels are on;
    empty: the shading's name)."""

    mesh: vtkPolyData
    shading: str
    label: str = ""


def render_panels(mesh, shadings, scene, size, backend="osmesa", labels=False, progress=None):
    """Draws `mesh` once per shading mode in `shadings`, side by side, each panel `size`
    (width, height) pixels, with a shared camera; optionally labels the panels. Returns the
    frame as a vtkImageData."""
    row = [Panel(mesh, shading) for shading in shadings]
    return render_grid([row], scene, size, backend, labels, progress)


def render_grid(rows, scene, size, backend="osmesa", labels=False, progress=None, views=None):
    """Draws rows of :class:`Panel` (the first row on top), each panel `size` (width, height)
    pixels; the panels of a row share one camera, which frames the row's first mesh as `views`
    (one :class:`View` per row; default: the scene's) says. Optionally labels each panel.
    Returns the frame as a vtkImageData."""
    progress = progress or Progress(quiet=True)
    width, height = size
    columns = max(len(row) for row in rows)
    window = make_window((width * columns, height * len(rows)), backend)
    for r, row in enumerate(rows):
        bottom = (len(rows) - 1 - r) / len(rows)
        camera = None
        for index, panel in enumerate(row):
            normals = normals_filter(panel.mesh, panel.shading, scene.accuracy, scene.weighting,
                                     scene.feature_angle, scene.orientation)
            progress.run(normals, f"normals ({panel.shading})", "cannot compute the normals")
            actor = shaded_actor(normals.GetOutput(), panel.shading, scene.material)
            actor.GetMapper().SetSceneAmbient(scene.derived_ambient)
            viewport = (index / columns, bottom, (index + 1) / columns, bottom + 1 / len(rows))
            renderer = make_renderer(scene, viewport)
            renderer.AddActor(actor)
            if camera is None:
                camera = renderer.GetActiveCamera()
                view = views[r] if views else scene.view
                view.frame(camera, panel.mesh.GetBounds(), width / height)
            else:
                renderer.SetActiveCamera(camera)
            if labels:
                add_label(renderer, panel.label or SHADING_LABELS[panel.shading], height,
                          scene.background)
            window.AddRenderer(renderer)
        for index in range(len(row), columns):  # a short row: the background fills the rest
            viewport = (index / columns, bottom, (index + 1) / columns, bottom + 1 / len(rows))
            window.AddRenderer(make_renderer(scene, viewport))
    progress.run(window, "render", "cannot render", "Render")
    image = capture(window)
    window.Finalize()
    return image
