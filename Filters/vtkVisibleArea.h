/**
 * @class   vtkVisibleArea
 * @brief   the area of each polygon a viewer sees, v.w / 2, in the accuracy modes of
 * vtkPolygonNormals
 *
 * For a polygon with area vector `w = sum_i (p_i - p0) x (p_(i+1) - p0)` (twice the area, as a
 * vector) and the unit vector `v` toward the viewer, `v.w / 2` is the area the viewer sees of it
 * under parallel projection: positive when its front is seen, negative when its back is.
 *
 * The view is either ViewDirection (toward the viewer, any non-zero length) or, when set, a
 * vtkCamera: a parallel camera looks along its direction of projection (v is its reverse); a
 * perspective camera gives every polygon its own v, from the mean of its vertices to the eye.
 *
 * Outputs (everything else passes through):
 * - cell array `VisibleArea` (double): v.w / 2 per cell; zero for vertices and lines (not
 *   surfaces), degenerate polygons and polygons with non-finite coordinates (those raise one
 *   warning with their count).
 * - field data `TotalVisibleArea`: the sum of the positive visible areas, the area of the
 *   input's polygons seen from the front (also GetTotalVisibleArea()); saturated at the largest
 *   double when it exceeds the double range. Ghost cells (vtkGhostType DUPLICATECELL) keep
 *   their visible area in the cell array but count neither here nor in the max visible area:
 *   they belong to another piece, so the pieces' totals add up to the whole mesh's.
 * - field data `MaxVisibleAreaDirection` and `MaxVisibleArea` (ComputeMaxVisibleArea, on by
 *   default): `sum w / |sum w|`, the direction from which the polygons together (front minus
 *   back) look largest, and that area, `|sum w| / 2`. Sum w is evaluated from the edges the
 *   polygons do not share with an oppositely oriented neighbour (the other edges cancel in the
 *   exact sum), so a closed, consistently oriented surface gets exactly the zero vector and
 *   zero, whatever its coordinates. Edges are matched by point id.
 *
 * Accuracy (the same ladder as vtkPolygonNormals; the area vectors come from the same kernels):
 * - FAST: float arithmetic; DOUBLE (default): double; COMPENSATED: compensated area vector,
 *   compensated eye vector and twice-the-precision dot product.
 * - EXACT: each visible area is faithful (within 1 ulp) of the exact value for the double
 *   coordinates, the double view vector (and for a perspective camera the exact vertex mean);
 *   exactly zero when the polygon is seen exactly edge-on. Double-double with a certified error
 *   bound, exact GMP integers where it cannot certify.
 *
 * When the input has the cell array `AreaVectors` (w / 2, as vtkPolygonNormals writes it) and
 * UseInputAreaVectors is on (default), FAST, DOUBLE and COMPENSATED use it instead of
 * recomputing the area vectors; EXACT always recomputes them from the points.
 *
 * Work is split with vtkSMPTools; the output is bitwise identical for every thread count.
 *
 * @sa vtkPolygonNormals vtkMassProperties
 */
#ifndef vtkVisibleArea_h
#define vtkVisibleArea_h

#include "vtkPhongVTKFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkCamera;

class VTKPHONGVTKFILTERS_EXPORT vtkVisibleArea : public vtkPolyDataAlgorithm
{
public:
  static vtkVisibleArea* New();
  vtkTypeMacro(vtkVisibleArea, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Accuracy modes, fastest first (the values of vtkPolygonNormals').
  enum AccuracyModes
  {
    FAST = 0,
    DOUBLE = 1,
    COMPENSATED = 2,
    EXACT = 3
  };

  ///@{
  /**
   * Direction toward the viewer (from the surface to the eye), used when no camera is set. Any
   * non-zero finite length. Default (0, 0, 1).
   */
  vtkSetVector3Macro(ViewDirection, double);
  vtkGetVector3Macro(ViewDirection, double);
  ///@}

  ///@{
  /**
   * Camera to see the input from; overrides ViewDirection when set. Default none.
   */
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /**
   * Arithmetic: FAST, DOUBLE, COMPENSATED or EXACT. Default is DOUBLE.
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
   * Use the input's `AreaVectors` cell array when present (not in EXACT). Default is on.
   */
  vtkSetMacro(UseInputAreaVectors, bool);
  vtkGetMacro(UseInputAreaVectors, bool);
  vtkBooleanMacro(UseInputAreaVectors, bool);
  ///@}

  ///@{
  /**
   * Produce MaxVisibleAreaDirection and MaxVisibleArea (a pass over the edges). Default is on.
   */
  vtkSetMacro(ComputeMaxVisibleArea, bool);
  vtkGetMacro(ComputeMaxVisibleArea, bool);
  vtkBooleanMacro(ComputeMaxVisibleArea, bool);
  ///@}

  ///@{
  /**
   * Results of the last execution (also in the output's field data).
   */
  vtkGetMacro(TotalVisibleArea, double);
  vtkGetMacro(MaxVisibleArea, double);
  vtkGetVector3Macro(MaxVisibleAreaDirection, double);
  ///@}

  /// Includes the camera's modification time.
  vtkMTimeType GetMTime() override;

protected:
  vtkVisibleArea();
  ~vtkVisibleArea() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double ViewDirection[3] = { 0.0, 0.0, 1.0 };
  vtkCamera* Camera = nullptr;
  int Accuracy = DOUBLE;
  bool UseInputAreaVectors = true;
  bool ComputeMaxVisibleArea = true;

  double TotalVisibleArea = 0.0;
  double MaxVisibleArea = 0.0;
  double MaxVisibleAreaDirection[3] = { 0.0, 0.0, 0.0 };

private:
  vtkVisibleArea(const vtkVisibleArea&) = delete;
  void operator=(const vtkVisibleArea&) = delete;
};

#endif
