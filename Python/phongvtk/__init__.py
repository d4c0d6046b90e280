"""PhongVTK: polygon normals by the summed cross-product rule, Phong shading, headless rendering.

The wrapped C++ classes are importable from the package itself::

    from phongvtk import vtkPolygonNormals
"""

from .vtkPhongVTKFilters import *  # noqa: F401,F403
