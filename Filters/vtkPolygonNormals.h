/**
 * @class   vtkPolygonNormals
 * @brief   cell and point normals by the summed cross-product rule, in a ladder of accuracy modes
 *
 * For every polygon p0 ... p(n-1) vtkPolygonNormals computes the area vector
 * `w = sum_{i=1}^{n-2} (p_i - p0) x (p_(i+1) - p0)`: `|w|` is twice the area and `w/|w|` the unit
 * normal, for any number of vertices, concave, non-planar or self-intersecting polygons alike.
 * Triangle strips are broken into triangles first (TriangulateStrips). Vertices and lines are
 * not surfaces.
 *
 * Cell outputs: `Normals` (unit normals, set as the active cell normals) and, on request,
 * `AreaVectors` (w/2: its length is the area), `Areas` and `NormalStatus` (0 ok, 1 degenerate:
 * zero area, 2 non-finite input coordinates, 3 not a surface cell, 4 along an edge where a
 * non-orientable surface could not be made consistent: see Consistency). A degenerate, non-finite
 * or non-surface cell gets the zero vector: never a NaN and never an invented direction.
 *
 * Point outputs (on request): `Normals` from the faces around each point, weighted by
 * PointWeighting: AREA (the sum of the faces' area vectors, i.e. the same rule applied to the
 * vertex star), ANGLE (Thuermer-Wuethrich: unit face normal times the corner angle), UNIFORM
 * (the sum of unit face normals, as vtkPolyDataNormals does) or MAX (Nelson Max 1999: corner
 * cross product divided by the squared lengths of the corner's edges).
 *
 * Accuracy (error bounds with u = 2^-53, measured numbers in the README):
 * - FAST: float32 arithmetic (differences of nearby points in the points' precision).
 * - DOUBLE (default): double arithmetic, fan from p0, as VTK computes polygon normals.
 * - COMPENSATED: error-free transformations (TwoDiff, FMA TwoProduct, compensated sums): a few
 *   ulp per component unless the component is cancelled below u times its condition.
 * - EXACT: every component of the unit normal within 1 ulp of the exact value (faithful), and
 *   the normal is zero exactly when the exact area vector is zero. A double-double evaluation
 *   with a certified error bound decides almost every polygon; exact GMP integer arithmetic
 *   decides the rest.
 * No mode overflows or underflows for finite input; non-finite coordinates flag the cell
 * (status 2, zero normal) and raise one warning with their count. Point ids outside the point
 * range are an error naming the first bad cell: the output is empty and the update fails
 * (RequestData returns 0), as for a malformed cell array or cells without points.
 *
 * Everything the filter does not compute passes through: points, all cells, every other point,
 * cell and field array. Work is split with vtkSMPTools and the output is bitwise identical for
 * every thread count and SMP backend. With PieceInvariant (default) a point normal does not
 * depend on the order of the cells nor on the partition of the mesh among processes either: it is
 * a function of the set of its faces, their contributions summed exactly and rounded once.
 *
 * In place of vtkPolyDataNormals, with its options under their names and with its defaults
 * (ComputePointNormals, Splitting at FeatureAngle 30, Consistency, NonManifoldTraversal and
 * TriangulateStrips on; ComputeCellNormals, AutoOrientNormals and FlipNormals off;
 * OutputPointsPrecision): Consistency reorders the polygons so that neighbours agree,
 * AutoOrientNormals turns every component outward by the exact sign of its volume (cavities
 * inward), NonManifoldTraversal joins components across non-manifold edges, FlipNormals reverses
 * every polygon, and Splitting duplicates the points along edges sharper than FeatureAngle
 * (decided exactly in EXACT), with `OriginalPointIds` mapping the copies back. PhongVTK's own
 * options come on top: Accuracy, PointWeighting (AREA by default: each face counts by its area,
 * where vtkPolyDataNormals sums unit face normals, UNIFORM here, so that slivers count as much
 * as large faces), the area, status and original-id arrays, PieceInvariant, OutputPrecision.
 * A `Normals` array already on the input is never reused: the normals always follow the
 * (reordered) polygons.
 *
 * @sa vtkPolyDataNormals vtkTriangleMeshPointNormals vtkPolygon
 */
#ifndef vtkPolygonNormals_h
#define vtkPolygonNormals_h

#include "vtkPhongVTKFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKPHONGVTKFILTERS_EXPORT vtkPolygonNormals : public vtkPolyDataAlgorithm
{
public:
  static vtkPolygonNormals* New();
  vtkTypeMacro(vtkPolygonNormals, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Accuracy modes, fastest first.
  enum AccuracyModes
  {
    FAST = 0,
    DOUBLE = 1,
    COMPENSATED = 2,
    EXACT = 3
  };

  /// Weightings of the face normals around a point.
  enum PointWeightingModes
  {
    AREA = 0,
    ANGLE = 1,
    UNIFORM = 2,
    MAX = 3
  };

  ///@{
  /**
   * Arithmetic of the area vectors: FAST, DOUBLE, COMPENSATED or EXACT. Default is DOUBLE.
   * Another value is an error and leaves the mode unchanged.
   */
  virtual void SetAccuracy(int mode);
  vtkGetMacro(Accuracy, int);
  void SetAccuracyToFast() { this->SetAccuracy(FAST); }
  void SetAccuracyToDouble() { this->SetAccuracy(DOUBLE); }
  void SetAccuracyToCompensated() { this->SetAccuracy(COMPENSATED); }
  void SetAccuracyToExact() { this->SetAccuracy(EXACT); }
  const char* GetAccuracyAsString();
  ///@}

  ///@{
  /**
   * Weighting of the face normals around a point: AREA, ANGLE, UNIFORM or MAX. Default is AREA.
   * Another value is an error and leaves the weighting unchanged.
   */
  virtual void SetPointWeighting(int weighting);
  vtkGetMacro(PointWeighting, int);
  void SetPointWeightingToArea() { this->SetPointWeighting(AREA); }
  void SetPointWeightingToAngle() { this->SetPointWeighting(ANGLE); }
  void SetPointWeightingToUniform() { this->SetPointWeighting(UNIFORM); }
  void SetPointWeightingToMax() { this->SetPointWeighting(MAX); }
  const char* GetPointWeightingAsString();
  ///@}

  ///@{
  /**
   * Produce the cell array `Normals` (unit normals, the active cell normals). Default is off,
   * as in vtkPolyDataNormals.
   */
  vtkSetMacro(ComputeCellNormals, bool);
  vtkGetMacro(ComputeCellNormals, bool);
  vtkBooleanMacro(ComputeCellNormals, bool);
  ///@}

  ///@{
  /**
   * Produce the point array `Normals` (the active point normals). Default is on, as in
   * vtkPolyDataNormals.
   */
  vtkSetMacro(ComputePointNormals, bool);
  vtkGetMacro(ComputePointNormals, bool);
  vtkBooleanMacro(ComputePointNormals, bool);
  ///@}

  ///@{
  /**
   * Produce the cell array `AreaVectors` (w/2: its length is the area). Default is off.
   * Values beyond the range of the output precision saturate at its largest finite value.
   */
  vtkSetMacro(ComputeAreaVectors, bool);
  vtkGetMacro(ComputeAreaVectors, bool);
  vtkBooleanMacro(ComputeAreaVectors, bool);
  ///@}

  ///@{
  /**
   * Produce the cell array `Areas`. Default is off. Saturates like AreaVectors.
   */
  vtkSetMacro(ComputeAreas, bool);
  vtkGetMacro(ComputeAreas, bool);
  vtkBooleanMacro(ComputeAreas, bool);
  ///@}

  ///@{
  /**
   * Produce the uint8 cell array `NormalStatus`: 0 ok, 1 degenerate (zero area), 2 non-finite
   * input, 3 not a surface cell, 4 inconsistent orientation (Consistency). Default is off.
   */
  vtkSetMacro(ComputeNormalStatus, bool);
  vtkGetMacro(ComputeNormalStatus, bool);
  vtkBooleanMacro(ComputeNormalStatus, bool);
  ///@}

  ///@{
  /**
   * Point normals independent of the order of the cells and of the partition of the mesh into
   * pieces. Default is on. A point's contributions are rounded onto grids fixed by the point's
   * own contributions and summed exactly, in two passes over its faces (measured: the point pass
   * takes about twice the cell-order one), and, computing one
   * piece of several (ParaView's pvbatch/pvserver), the filter asks upstream for one more level
   * of ghost cells: the points on the boundaries between pieces then get exactly, bit for bit,
   * the normals of the whole mesh. Ghost cells asked for only for this are removed from the
   * output again. Off: faces in cell order, no extra ghost cells.
   */
  vtkSetMacro(PieceInvariant, bool);
  vtkGetMacro(PieceInvariant, bool);
  vtkBooleanMacro(PieceInvariant, bool);
  ///@}

  ///@{
  /**
   * Reorder the polygons so that neighbours agree: two polygons sharing a manifold edge (one
   * that exactly two polygons have) run along it in opposite directions. Each connected component
   * keeps the order of its first polygon; the others are reversed as needed, keeping their first
   * point ((p0, p(n-1), ..., p1), so a reversed triangle's area vector is exactly the negated
   * one). The result does not depend on the thread count. A non-orientable component (a Moebius
   * strip) cannot agree everywhere: one warning gives the number of such components, and the
   * polygons along the edges where they still disagree get NormalStatus 4. Strips, lines and
   * vertices are not reordered. Everything computed (normals, areas, splitting) follows the
   * reordered polygons. Default is on, as in vtkPolyDataNormals.
   */
  vtkSetMacro(Consistency, bool);
  vtkGetMacro(Consistency, bool);
  vtkBooleanMacro(Consistency, bool);
  ///@}

  ///@{
  /**
   * Turn every connected component outward, after making its polygons agree (implies
   * Consistency). A closed component faces outward when its enclosed volume is positive; that
   * sign is exact (a certified double-precision sum, exact integer arithmetic when it cannot
   * decide), so meshes far from the origin or nearly flat are oriented right. A closed component
   * inside an odd number of other closed components (the cavity of a hollow solid) is turned
   * inward, so that it too faces out of the material. An open component (with a boundary or a
   * non-manifold edge) is turned so that the flux of the position field through it, taken from
   * the centre of its bounding box, is positive: its faces on the whole turn away from its middle
   * (a hemisphere or a surface with holes faces outward); a flux exactly zero (a planar
   * component) keeps the order of its first polygon. Non-orientable components are left as
   * Consistency leaves them. Decided per piece when the mesh comes in pieces. Default is off.
   */
  vtkSetMacro(AutoOrientNormals, bool);
  vtkGetMacro(AutoOrientNormals, bool);
  vtkBooleanMacro(AutoOrientNormals, bool);
  ///@}

  ///@{
  /**
   * With Consistency or AutoOrientNormals, also make polygons agree across non-manifold edges
   * (three or more polygons), as vtkPolyDataNormals' NonManifoldTraversal. Manifold edges decide
   * first; then the components they form are joined across non-manifold edges, in cell order:
   * every polygon around such an edge is paired with the smallest-numbered one around it, and a
   * pair that joins two components makes them run along the edge in opposite directions (a pair
   * within one component is passed over: around an edge of three or more polygons there is no
   * right pairing without the geometry). Joined components count as one, with a non-manifold
   * edge, for AutoOrientNormals (an open component). Default is on, as in vtkPolyDataNormals;
   * off, components touching at a non-manifold edge (two cubes sharing an edge) are oriented
   * each on its own.
   */
  vtkSetMacro(NonManifoldTraversal, bool);
  vtkGetMacro(NonManifoldTraversal, bool);
  vtkBooleanMacro(NonManifoldTraversal, bool);
  ///@}

  ///@{
  /**
   * Reverse every polygon ((p0, p(n-1), ..., p1)), after Consistency and AutoOrientNormals: the
   * cells' order and every normal computed from them turn together. Default is off.
   */
  vtkSetMacro(FlipNormals, bool);
  vtkGetMacro(FlipNormals, bool);
  vtkBooleanMacro(FlipNormals, bool);
  ///@}

  ///@{
  /**
   * Split the points at sharp edges before the point normals are computed, so that a crease
   * keeps its edge under smooth shading (vtkPolyDataNormals' Splitting). Around each point the
   * polygons are grouped into regions joined across smooth manifold edges; the first region keeps
   * the point, every further one gets a copy of it, appended to the points with every point array
   * copied, and its polygons refer to the copy. Boundary and non-manifold edges (three or more
   * polygons) separate regions; a polygon without a direction (zero area, non-finite) joins none
   * and keeps the point. Only polygons are split; strips, lines and vertices keep their ids.
   * Takes effect with ComputePointNormals only (nothing else depends on it). Default is on, as
   * in vtkPolyDataNormals.
   */
  vtkSetMacro(Splitting, bool);
  vtkGetMacro(Splitting, bool);
  vtkBooleanMacro(Splitting, bool);
  ///@}

  ///@{
  /**
   * The feature angle of Splitting, in degrees, clamped to [0, 180]: an edge is sharp when the
   * angle between its two polygons' area vectors is at least this angle, i.e. when
   * `w1.w2 <= c |w1| |w2|` with c the double value of cos(FeatureAngle). EXACT decides that sign
   * exactly from the double coordinates; FAST, DOUBLE and COMPENSATED compare the dot product of
   * their own unit normals with c. Default is 30.
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * With Splitting, produce the vtkIdType point array `OriginalPointIds`: for every output point
   * the input point it stands for (itself for the input's points, the split point for a copy).
   * Default is on.
   */
  vtkSetMacro(ComputeOriginalPointIds, bool);
  vtkGetMacro(ComputeOriginalPointIds, bool);
  vtkBooleanMacro(ComputeOriginalPointIds, bool);
  ///@}

  ///@{
  /**
   * Break triangle strips into triangles before anything else, as vtkPolyDataNormals does: each
   * triangle becomes a polygon of its own (after the input's polygons, with its strip's cell
   * data) and gets its own normal. Default is on. Off, each strip stays one cell whose area
   * vector is the sum of its triangles' (taken with the strip's alternating orientation).
   */
  vtkSetMacro(TriangulateStrips, bool);
  vtkGetMacro(TriangulateStrips, bool);
  vtkBooleanMacro(TriangulateStrips, bool);
  ///@}

  ///@{
  /**
   * Precision of the output points when Splitting makes new ones (with ComputePointNormals),
   * as in vtkPolyDataNormals: vtkAlgorithm::DEFAULT_PRECISION (default: that of the input
   * points), SINGLE_PRECISION or DOUBLE_PRECISION. Without splitting the input's points pass
   * through. Another value is an error and leaves the precision unchanged.
   */
  virtual void SetOutputPointsPrecision(int precision);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Precision of the output arrays: vtkAlgorithm::SINGLE_PRECISION (default, VTK's convention
   * for normals), DOUBLE_PRECISION, or DEFAULT_PRECISION (that of the input points). Another
   * value is an error and leaves the precision unchanged.
   */
  virtual void SetOutputPrecision(int precision);
  vtkGetMacro(OutputPrecision, int);
  ///@}

protected:
  vtkPolygonNormals();
  ~vtkPolygonNormals() override;

  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Accuracy = DOUBLE;
  int PointWeighting = AREA;
  bool ComputeCellNormals = false;
  bool ComputePointNormals = true;
  bool ComputeAreaVectors = false;
  bool ComputeAreas = false;
  bool ComputeNormalStatus = false;
  bool PieceInvariant = true;
  bool Consistency = true;
  bool AutoOrientNormals = false;
  bool NonManifoldTraversal = true;
  bool FlipNormals = false;
  bool Splitting = true;
  double FeatureAngle = 30.0;
  bool ComputeOriginalPointIds = true;
  int OutputPrecision = SINGLE_PRECISION;
  bool TriangulateStrips = true;
  int OutputPointsPrecision = DEFAULT_PRECISION;

private:
  vtkPolygonNormals(const vtkPolygonNormals&) = delete;
  void operator=(const vtkPolygonNormals&) = delete;
};

#endif
