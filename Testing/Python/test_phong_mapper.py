"""vtkPhongPolyDataMapper and vtkPhongCompositePolyDataMapper from Python: the wrapped mappers draw
the model (checked at a pixel whose normal faces a light behind the camera under parallel
projection, n.l = 1 and v.r = 1), the presets are callable by name, and the generated shader is
inspectable."""

import numpy as np
import pytest
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkLight,
    vtkProperty,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import phongvtk

SIZE = 120


@pytest.fixture(autouse=True)
def no_display(monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("PHONGVTK_HEADLESS", raising=False)


def rendered_pixels(renderer):
    """The RGB pixels (SIZE * SIZE x 3, bottom row first) of `renderer` drawn in a window of its
    own: headless, as there is no display."""
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(SIZE, SIZE)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.Update()
    return numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())


def render(interpolation, specular=0.4, composite=False):
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(128)
    sphere.SetPhiResolution(64)
    if composite:
        sphere.Update()
        blocks = vtkMultiBlockDataSet()
        blocks.SetBlock(0, sphere.GetOutput())
        mapper = phongvtk.vtkPhongCompositePolyDataMapper()
        mapper.SetInputDataObject(blocks)
    else:
        mapper = phongvtk.vtkPhongPolyDataMapper()
        mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetInterpolation(interpolation)
    prop.SetAmbient(0.1)
    prop.SetAmbientColor(1.0, 1.0, 1.0)
    prop.SetDiffuse(0.5)
    prop.SetDiffuseColor(0.8, 0.4, 0.2)
    prop.SetSpecular(specular)
    prop.SetSpecularColor(0.5, 1.0, 0.5)
    prop.SetSpecularPower(20)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(1, 0, 0)
    light.SetFocalPoint(0, 0, 0)
    light.SetDiffuseColor(1.0, 0.5, 1.0)
    light.SetSpecularColor(1.0, 1.0, 0.5)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddLight(light)
    renderer.SetAmbient(0.2, 0.4, 0.6)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(4, 0, 0)
    camera.SetViewUp(0, 0, 1)
    camera.SetParallelProjection(True)
    camera.SetParallelScale(0.6)
    return mapper, rendered_pixels(renderer).reshape(SIZE, SIZE, 3).astype(float)


@pytest.mark.parametrize("composite", [False, True])
def test_centre_pixel_is_the_model(composite):
    mapper, image = render(2, composite=composite)
    ka, ia = 0.1 * np.ones(3), np.array([0.2, 0.4, 0.6])
    kd, i_d = 0.5 * np.array([0.8, 0.4, 0.2]), np.array([1.0, 0.5, 1.0])
    ks, i_s = 0.4 * np.array([0.5, 1.0, 0.5]), np.array([1.0, 1.0, 0.5])
    expected = np.clip(ka * ia + kd * i_d + ks * i_s, 0, 1) * 255
    centre = image[SIZE // 2 - 1 : SIZE // 2 + 1, SIZE // 2 - 1 : SIZE // 2 + 1].mean(axis=(0, 1))
    # Within 2 LSB: the four centre pixels are about half a pixel off n = l = v.
    assert np.abs(centre - expected).max() <= 2.0, (centre, expected)
    assert mapper.GetShaderConfiguration().startswith("phong parallel")


@pytest.mark.parametrize("interpolation", [0, 1])
def test_flat_and_gouraud_are_selected_by_the_property(interpolation):
    mapper, image = render(interpolation)
    assert mapper.GetShaderConfiguration().startswith(["flat", "gouraud"][interpolation])
    assert image[SIZE // 2, SIZE // 2].max() > 100


@pytest.mark.parametrize("composite", [False, True])
def test_no_specular_code_without_a_specular_term(composite):
    mapper, _ = render(2, specular=0.0, composite=composite)
    assert "phongSpecular" not in mapper.GetFragmentShaderSource()
    assert "phongDiffuse" in mapper.GetFragmentShaderSource()


def test_presets_by_name():
    prop = vtkProperty()
    prop.SetDiffuseColor(0.8, 0.2, 0.1)
    assert phongvtk.vtkPhongPolyDataMapper.ApplyPreset(prop, "metal")
    assert prop.GetSpecularColor() == pytest.approx((0.8, 0.2, 0.1))
    assert not phongvtk.vtkPhongPolyDataMapper.ApplyPreset(prop, "velvet")


def render_preset(preset, colour, scene_ambient):
    """A sphere of `colour` with `preset` in VTK's default lighting: the headlight VTK makes
    (white, intensity 1) and the renderer's default ambient light (1, 1, 1). Returns the pixels
    the sphere covers (n x 3, 0-255)."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(96)
    sphere.SetPhiResolution(48)
    mapper = phongvtk.vtkPhongPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    mapper.SetSceneAmbient(scene_ambient)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetDiffuseColor(*colour)
    assert phongvtk.vtkPhongPolyDataMapper.ApplyPreset(actor.GetProperty(), preset)
    actor.GetProperty().SetInterpolationToPhong()
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    pixels = rendered_pixels(renderer)
    return pixels[np.any(pixels != pixels[0], axis=1)].astype(int)


@pytest.mark.parametrize("scene_ambient", [False, True])
@pytest.mark.parametrize("preset", ["plastic", "metal", "matte"])
@pytest.mark.parametrize("colour", [(0.2, 0.5, 1.0), (1.0, 1.0, 1.0), (0.9, 0.6, 0.3)])
def test_presets_do_not_wash_out_in_vtks_default_light(preset, colour, scene_ambient):
    sphere = render_preset(preset, colour, scene_ambient)
    clipped = np.mean(np.any(sphere == 255, axis=1))
    assert clipped <= 0.03, f"{100 * clipped:.1f}% of the sphere saturates"
    brightest = sphere.max(axis=1)
    assert np.median(brightest) >= 0.3 * 255 * max(colour), "too dark to see"
