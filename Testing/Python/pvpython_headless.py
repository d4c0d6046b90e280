"""Run by pvpython with no X display: after ``import phongvtk`` VTK's plain vtkRenderWindow() is
a headless window and renders inside ParaView's interpreter."""
import os
import sys

os.environ.pop("DISPLAY", None)
os.environ.pop("PHONGVTK_HEADLESS", None)

from paraview import servermanager  # noqa: F401,E402  (ParaView's Python is what is under test)
import phongvtk  # noqa: F401,E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)

window = vtkRenderWindow()
assert window.IsA("vtkHeadlessRenderWindow"), window.GetClassName()
mapper = vtkPolyDataMapper()
sphere = vtkSphereSource()
mapper.SetInputConnection(sphere.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetAmbient(0.0)
actor.GetProperty().SetDiffuse(1.0)
actor.GetProperty().SetSpecular(0.0)
renderer = vtkRenderer()
renderer.AddActor(actor)
window.AddRenderer(renderer)
window.SetSize(64, 48)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ShouldRerenderOff()
grab.Update()
centre = grab.GetOutput().GetScalarComponentAsDouble
assert all(centre(32, 24, 0, c) >= 253 for c in range(3)), [centre(32, 24, 0, c) for c in range(3)]
print("pvpython: headless", window.GetClassName(), "renders")
sys.exit(0)
