"""Headless rendering from Python: after ``import phongvtk`` a plain ``vtkRenderWindow()`` renders
without an X server, and the two backends, made by name, render a scene to the same pixels."""

import numpy as np
import pytest
from vtkmodules.vtkRenderingCore import vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (VTK's own window registered first)

import phongvtk
from headless_scene import render_sphere

SIZE = (200, 150)


@pytest.fixture(autouse=True)
def no_display(monkeypatch):
    """No test may depend on the machine having an X server."""
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("PHONGVTK_HEADLESS", raising=False)


def test_plain_render_window_is_headless_without_display():
    window = vtkRenderWindow()
    assert window.IsA("vtkHeadlessRenderWindow"), window.GetClassName()
    assert window.GetClassName() == "vtkHeadlessOSMesaRenderWindow"
    image = render_sphere(window, SIZE)
    assert (image[SIZE[1] // 2, SIZE[0] // 2] >= 253).all()
    assert (image[0, 0] == 0).all()


def test_environment_selects_the_backend(monkeypatch):
    monkeypatch.setenv("PHONGVTK_HEADLESS", "egl")
    assert vtkRenderWindow().GetClassName() == "vtkHeadlessEGLRenderWindow"
    monkeypatch.setenv("PHONGVTK_HEADLESS", "off")
    assert not vtkRenderWindow().IsA("vtkHeadlessRenderWindow")


def test_backends_by_name_render_the_same_pixels():
    osmesa = phongvtk.vtkHeadlessOSMesaRenderWindow()
    egl = phongvtk.vtkHeadlessEGLRenderWindow()
    assert osmesa.GetBackendName() == "OSMesa"
    assert egl.GetBackendName() == "EGL"
    a = render_sphere(osmesa, SIZE)
    b = render_sphere(egl, SIZE)
    assert np.abs(a - b).max() <= 1
    assert (a[SIZE[1] // 2, SIZE[0] // 2] >= 253).all()
    assert osmesa.GetMultiSamples() == 0 and egl.GetMultiSamples() == 0
