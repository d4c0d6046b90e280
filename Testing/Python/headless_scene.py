"""The scene the headless-rendering tests draw (pytest under python3 and the pvpython script)."""

from vtkmodules.util import numpy_support
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkWindowToImageFilter


def render_sphere(window, size):
    """A unit-diffuse white sphere facing VTK's headlight on black: its centre pixel is white
    (n.l = 1). Returns the frame as an int array of rows (bottom first) x columns x RGB."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.0)
    actor.GetProperty().SetDiffuse(1.0)
    actor.GetProperty().SetSpecular(0.0)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ShouldRerenderOff()
    grab.Update()
    pixels = numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return pixels.reshape(size[1], size[0], 3).astype(int)
