"""Run by pvpython with no X display: after ``import phongvtk`` VTK's plain vtkRenderWindow() is
a headless window and renders inside ParaView's interpreter."""
import os
import sys

os.environ.pop("DISPLAY", None)
os.environ.pop("PHONGVTK_HEADLESS", None)

from paraview import servermanager  # noqa: F401,E402  (ParaView's Python is what is under test)
import phongvtk  # noqa: F401,E402
from vtkmodules.vtkRenderingCore import vtkRenderWindow  # noqa: E402

from headless_scene import render_sphere  # noqa: E402

window = vtkRenderWindow()
assert window.IsA("vtkHeadlessRenderWindow"), window.GetClassName()
image = render_sphere(window, (64, 48))
assert (image[24, 32] >= 253).all(), image[24, 32]
print("pvpython: headless", window.GetClassName(), "renders")
sys.exit(0)
