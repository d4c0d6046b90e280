"""Headless rendering from Python: after ``import phongvtk`` a plain ``vtkRenderWindow()`` renders
without an X server, and the two backends, made by name, render a scene to the same pixels."""

import os
import subprocess
import sys

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


EXIT_SCRIPT = """
import sys
import phongvtk
from vtkmodules.vtkRenderingCore import vtkRenderWindow
from headless_scene import render_sphere
windows = [vtkRenderWindow(), phongvtk.vtkHeadlessEGLRenderWindow(), vtkRenderWindow()]
for window in windows[:2]:
    render_sphere(window, (64, 48))  # the third is never rendered
print("rendered", flush=True)
if sys.argv[1] == "exit3":
    sys.exit(3)
if sys.argv[1] == "exit0":
    sys.exit(0)
if sys.argv[1] == "raise":
    raise RuntimeError("a script failing")
"""


@pytest.mark.parametrize("ending, status", [("end", 0), ("exit0", 0), ("exit3", 3),
                                            ("raise", 1)])
def test_python_leaves_with_its_status_and_windows_alive(ending, status):
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    here = os.path.dirname(os.path.abspath(__file__))
    env["PYTHONPATH"] = os.pathsep.join([here, env.get("PYTHONPATH", "")])
    for attempt in range(3):
        done = subprocess.run([sys.executable, "-c", EXIT_SCRIPT, ending], env=env,
                              capture_output=True, text=True, timeout=60)  # a hang fails
        log = done.stdout + done.stderr
        assert done.returncode == status, (attempt, done.returncode, log)
        assert "rendered" in done.stdout, log
        assert "double free" not in log and "corrupted" not in log, log
