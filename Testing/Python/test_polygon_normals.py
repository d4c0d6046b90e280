"""vtkPolygonNormals from Python: the package imports, the API constants exist, and the filter
runs in a VTK pipeline with results that follow from geometry (a sphere's faces look outward)."""

import math

import numpy as np
import pytest
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand, vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm, vtkPolyDataAlgorithm
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource

from phongvtk import vtkPolygonNormals

CENTER = (1.0, -2.0, 0.5)
RADIUS = 3.0


#: Cell normals of the cells as given, nothing else: where the tests start from (the defaults,
#: vtkPolyDataNormals', are tested on their own).
CELLS_AS_GIVEN = {"ComputeCellNormals": True, "ComputePointNormals": False, "Splitting": False,
                  "Consistency": False}


def sphere_pipeline(**settings):
    """vtkSphereSource -> vtkPolygonNormals with CELLS_AS_GIVEN, then Set<name>(value) for each
    setting."""
    source = vtkSphereSource()
    source.SetCenter(*CENTER)
    source.SetRadius(RADIUS)
    source.SetThetaResolution(48)
    source.SetPhiResolution(32)
    normals = vtkPolygonNormals()
    normals.SetInputConnection(source.GetOutputPort())
    for name, value in {**CELLS_AS_GIVEN, **settings}.items():
        getattr(normals, "Set" + name)(value)
    normals.Update()
    return normals.GetOutput()


def cell_centroids(mesh):
    ids = vtkIdList()
    points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    centroids = np.empty((mesh.GetNumberOfCells(), 3))
    for cell in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(cell, ids)
        corners = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        centroids[cell] = points[corners].mean(axis=0)
    return centroids


def test_filter_is_a_polydata_algorithm():
    assert isinstance(vtkPolygonNormals(), vtkPolyDataAlgorithm)


@pytest.mark.parametrize(
    "name, value", [("FAST", 0), ("DOUBLE", 1), ("COMPENSATED", 2), ("EXACT", 3)]
)
def test_accuracy_constants(name, value):
    assert getattr(vtkPolygonNormals, name) == value
    f = vtkPolygonNormals()
    getattr(f, "SetAccuracyTo" + name.capitalize())()
    assert f.GetAccuracy() == value
    assert f.GetAccuracyAsString() == name


@pytest.mark.parametrize("name, value", [("AREA", 0), ("ANGLE", 1), ("UNIFORM", 2), ("MAX", 3)])
def test_point_weighting_constants(name, value):
    assert getattr(vtkPolygonNormals, name) == value
    f = vtkPolygonNormals()
    getattr(f, "SetPointWeightingTo" + name.capitalize())()
    assert f.GetPointWeighting() == value
    assert f.GetPointWeightingAsString() == name


def test_defaults():
    f = vtkPolygonNormals()
    assert f.GetAccuracy() == vtkPolygonNormals.DOUBLE
    assert f.GetPointWeighting() == vtkPolygonNormals.AREA
    vtk = vtkPolyDataNormals()  # its options, under their names and with their defaults
    for name in ("ComputeCellNormals", "ComputePointNormals", "Splitting", "Consistency",
                 "AutoOrientNormals", "NonManifoldTraversal", "FlipNormals", "FeatureAngle",
                 "OutputPointsPrecision"):
        assert getattr(f, "Get" + name)() == getattr(vtk, "Get" + name)(), name
    assert f.GetTriangulateStrips()
    assert not f.GetComputeAreaVectors()
    assert not f.GetComputeAreas()
    assert not f.GetComputeNormalStatus()
    assert f.GetOutputPrecision() == vtkAlgorithm.SINGLE_PRECISION


@pytest.mark.parametrize("accuracy", [0, 1, 2, 3])
def test_sphere_cell_normals_are_unit_and_point_outward(accuracy):
    mesh = sphere_pipeline(Accuracy=accuracy)
    normals = numpy_support.vtk_to_numpy(mesh.GetCellData().GetNormals())
    assert normals.shape == (mesh.GetNumberOfCells(), 3)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-6)
    outward = cell_centroids(mesh) - np.array(CENTER)
    assert np.all(np.einsum("ij,ij->i", normals, outward) > 0.0)


def test_numpy_conversion_of_every_output():
    mesh = sphere_pipeline(
        OutputPrecision=vtkAlgorithm.DOUBLE_PRECISION,
        ComputeAreas=True,
        ComputeAreaVectors=True,
        ComputeNormalStatus=True,
        ComputePointNormals=True,
    )
    cells = mesh.GetNumberOfCells()
    cd = mesh.GetCellData()
    normals = numpy_support.vtk_to_numpy(cd.GetArray("Normals"))
    area_vectors = numpy_support.vtk_to_numpy(cd.GetArray("AreaVectors"))
    areas = numpy_support.vtk_to_numpy(cd.GetArray("Areas"))
    status = numpy_support.vtk_to_numpy(cd.GetArray("NormalStatus"))
    assert normals.dtype == np.float64 and normals.shape == (cells, 3)
    assert areas.dtype == np.float64 and areas.shape == (cells,)
    assert status.dtype == np.uint8 and np.all(status == 0)
    # AreaVectors = area times unit normal.
    np.testing.assert_allclose(area_vectors, normals * areas[:, None], rtol=1e-12, atol=1e-15)
    # The inscribed polyhedron's area is a little below the sphere's.
    sphere_area = 4.0 * math.pi * RADIUS**2
    assert 0.99 * sphere_area < areas.sum() < sphere_area
    # Area-weighted point normals of a sphere are close to radial.
    point_normals = numpy_support.vtk_to_numpy(mesh.GetPointData().GetNormals())
    points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData())
    radial = points - np.array(CENTER)
    radial /= np.linalg.norm(radial, axis=1)[:, None]
    assert np.all(np.einsum("ij,ij->i", point_normals, radial) > math.cos(0.05))


def test_single_precision_by_default():
    mesh = sphere_pipeline()
    assert numpy_support.vtk_to_numpy(mesh.GetCellData().GetNormals()).dtype == np.float32


def test_source_point_normals_pass_through_when_not_computed():
    source = vtkSphereSource()
    source.Update()
    f = vtkPolygonNormals()
    f.SetInputConnection(source.GetOutputPort())
    f.ComputePointNormalsOff()
    f.ComputeCellNormalsOn()
    f.Update()
    # vtkSphereSource makes its own point normals; the filter was not asked for any.
    source_normals = source.GetOutput().GetPointData().GetNormals()
    assert f.GetOutput().GetPointData().GetNormals() is source_normals


def test_numpy_points_in_numpy_normals_out():
    # A unit square in the plane z = 0 as one quad, built from numpy arrays.
    points = vtkPoints()
    corners = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
    points.SetData(numpy_support.numpy_to_vtk(corners, deep=True))
    polys = vtkCellArray()
    polys.InsertNextCell(4, [0, 1, 2, 3])
    square = vtkPolyData()
    square.SetPoints(points)
    square.SetPolys(polys)
    f = vtkPolygonNormals()
    f.SetInputData(square)
    f.ComputeCellNormalsOn()
    f.ComputeAreasOn()
    f.Update()
    cd = f.GetOutput().GetCellData()
    np.testing.assert_array_equal(numpy_support.vtk_to_numpy(cd.GetNormals()), [[0.0, 0.0, 1.0]])
    np.testing.assert_array_equal(numpy_support.vtk_to_numpy(cd.GetArray("Areas")), [1.0])


def test_bad_point_ids_report_an_error_and_give_an_empty_output():
    points = vtkPoints()
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]:
        points.InsertNextPoint(p)
    polys = vtkCellArray()
    polys.InsertNextCell(3, [0, 1, 2])
    polys.InsertNextCell(3, [0, 1, 7])
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    errors = []
    f = vtkPolygonNormals()
    f.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    failures = []  # the executive's "returned failure for request"
    f.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda caller, event: failures.append(1))
    f.SetInputData(mesh)
    assert f.GetExecutive().Update() == 0  # the update fails
    assert len(errors) == 1 and failures
    assert f.GetOutput().GetNumberOfCells() == 0
