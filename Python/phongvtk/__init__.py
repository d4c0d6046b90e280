"""PhongVTK: polygon normals by the summed cross-product rule, Phong shading, headless rendering.

The wrapped C++ classes are importable from the package itself::

    from phongvtk import vtkPolygonNormals, vtkHeadlessOSMesaRenderWindow

On VTK before 9.4, importing the package also makes ``vtkRenderWindow()`` headless when there
is no X display (PhongVTK::RenderingHeadless, see vtkHeadlessRenderWindow; environment variable
PHONGVTK_HEADLESS=auto|osmesa|egl|off). VTK 9.4 and later choose their own OSMesa or EGL window.

The command-line interface is ``python3 -m phongvtk`` (render, normals, area, bench, demo; see
phongvtk.cli).
"""

#: The version of PhongVTK (project(VERSION) in the top-level CMakeLists.txt).
__version__ = "0.1.0"

from ._build import HEADLESS, RENDERING
from .vtkPhongVTKFilters import *  # noqa: F401,F403

if RENDERING:  # PHONGVTK_BUILD_RENDERING
    from .vtkPhongVTKRendering import *  # noqa: F401,F403
if HEADLESS:  # PHONGVTK_BUILD_HEADLESS: Linux, VTK before 9.4
    from .vtkPhongVTKRenderingHeadless import *  # noqa: F401,F403
