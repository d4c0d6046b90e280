/**
 * libFuzzer target: vtkPolygonNormals and then vtkVisibleArea on polydata decoded from the input
 * (float or double points with any bits, four cell arrays with any sizes and ids, or offsets and
 * connectivity taken as they come, every option), checked against what the filters document:
 * - a malformed cell array (offsets not starting at 0, decreasing, not ending at the connectivity's
 *   size) or a point id outside the points is an error (ErrorEvent) and an empty output; anything
 *   else is no error;
 * - otherwise every cell passes through (each kind's count), every point keeps its id (copies of
 *   split points appended, `OriginalPointIds` naming their source, the point array `Ids` copied to
 *   them), the other arrays pass through;
 * - `Normals` are unit vectors or zero, never NaN or infinite; `NormalStatus` one of the
 *   documented values and zero normals exactly for statuses 1-3 (an input without cells passes
 *   through as it is, without them); no NaN in `AreaVectors`, `Areas`,
 *   `VisibleArea` or the totals.
 * A violation aborts with its description.
 */
#include "vtkPolygonNormals.h"
#include "vtkVisibleArea.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include PHONGVTK_FUZZED_DATA_PROVIDER // <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <unistd.h>

namespace
{
int ReportFd = 2;         // stderr as it was before libFuzzer's -close_fd_mask
std::string InputSummary; // the decoded input and options, for the report

[[noreturn]] void Violation(const std::string& why)
{
  dprintf(ReportFd, "FuzzPolyDataFilters: %s\n  input: %s\n", why.c_str(), InputSummary.c_str());
  std::abort();
}

void Require(bool condition, const std::string& why)
{
  if (!condition)
  {
    Violation(why);
  }
}

/// Counts the ErrorEvents of the object it observes (and keeps them off the terminal).
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long event, void*) override
  {
    this->Errors += event == vtkCommand::ErrorEvent ? 1 : 0;
  }
  int Errors = 0;
};

double Coordinate(FuzzedDataProvider& in, bool raw, int exponent)
{
  if (raw)
  {
    const std::uint64_t bits = in.ConsumeIntegral<std::uint64_t>();
    double x;
    std::memcpy(&x, &bits, sizeof(x));
    return x;
  }
  return std::ldexp(in.ConsumeIntegral<std::int8_t>(), exponent);
}

/// One cell array: cells of 0..10 ids, ids in range unless `stray`; or, when `raw`, offsets and
/// connectivity exactly as the input gives them. Sets `wellFormed` false when the array is not.
vtkSmartPointer<vtkCellArray> DecodeCells(
  FuzzedDataProvider& in, vtkIdType numPoints, bool& wellFormed, bool& idsInRange)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  const int kind = in.ConsumeIntegralInRange<int>(0, 7);
  const int count = in.ConsumeIntegralInRange<int>(0, kind == 0 ? 0 : 24);
  if (kind == 7)
  {
    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    const int ids = in.ConsumeIntegralInRange<int>(0, 48);
    for (int i = 0; i < ids; ++i)
    {
      connectivity->InsertNextValue(in.ConsumeIntegralInRange<vtkIdType>(-2, numPoints + 1));
    }
    for (int i = 0; i <= count; ++i)
    {
      offsets->InsertNextValue(in.ConsumeIntegralInRange<vtkIdType>(-2, ids + 2));
    }
    // No cell reads the connectivity of an array without cells, whatever it holds.
    bool ordered = count == 0 || (offsets->GetValue(0) == 0 && offsets->GetValue(count) == ids);
    for (int i = 0; i < count; ++i)
    {
      ordered = ordered && offsets->GetValue(i) <= offsets->GetValue(i + 1);
    }
    for (int i = 0; ordered && count > 0 && i < ids; ++i)
    {
      const vtkIdType id = connectivity->GetValue(i);
      idsInRange = idsInRange && id >= 0 && id < numPoints;
    }
    wellFormed = wellFormed && ordered;
    cells->SetData(offsets, connectivity);
    if (!ordered && std::getenv("PHONGVTK_FUZZ_VERBOSE"))
    {
      for (int i = 0; i <= count; ++i)
      {
        dprintf(ReportFd, "%lld ", static_cast<long long>(offsets->GetValue(i)));
      }
      dprintf(ReportFd, "(offsets of %d ids; %lld cells)\n", ids,
        static_cast<long long>(cells->GetNumberOfCells()));
    }
    return cells;
  }
  const bool stray = kind == 6;
  for (int c = 0; c < count; ++c)
  {
    const int size = in.ConsumeIntegralInRange<int>(0, 10);
    cells->InsertNextCell(size);
    for (int i = 0; i < size; ++i)
    {
      vtkIdType id = 0;
      if (stray)
      {
        id = in.ConsumeIntegralInRange<vtkIdType>(-3, numPoints + 3);
      }
      else if (numPoints > 0)
      {
        id = in.ConsumeIntegralInRange<vtkIdType>(0, numPoints - 1);
      }
      idsInRange = idsInRange && id >= 0 && id < numPoints;
      cells->InsertCellPoint(id);
    }
  }
  return cells;
}

bool IsNaN(vtkDataArray* array)
{
  for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
  {
    if (std::isnan(array->GetVariantValue(i).ToDouble()))
    {
      return true;
    }
  }
  return false;
}

/// Unit (within the output precision's rounding) or zero, never non-finite.
void RequireUnitOrZero(vtkDataArray* normals, vtkIdType i, const char* what)
{
  double n[3];
  normals->GetTuple(i, n);
  Require(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]),
    std::string(what) + " normal " + std::to_string(i) + " is not finite");
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  Require(length == 0.0 || std::fabs(length - 1.0) <= 1e-6,
    std::string(what) + " normal " + std::to_string(i) + " has length " + std::to_string(length));
}

void CheckNormals(vtkPolyData* input, vtkPolyData* output, vtkPolygonNormals* filter)
{
  const vtkIdType inPoints = input->GetNumberOfPoints();
  const vtkIdType outPoints = output->GetNumberOfPoints();
  Require(output->GetNumberOfVerts() == input->GetNumberOfVerts() &&
      output->GetNumberOfLines() == input->GetNumberOfLines() &&
      output->GetNumberOfPolys() == input->GetNumberOfPolys() &&
      output->GetNumberOfStrips() == input->GetNumberOfStrips(),
    "cells lost or added");
  const bool splits = filter->GetSplitting() && filter->GetComputePointNormals();
  Require(splits ? outPoints >= inPoints : outPoints == inPoints, "points lost or added");
  vtkDataArray* ids = output->GetPointData()->GetArray("Ids");
  Require(ids && ids->GetNumberOfTuples() == outPoints, "point array Ids not passed through");
  vtkDataArray* original = output->GetPointData()->GetArray("OriginalPointIds");
  Require(!original || original->GetNumberOfTuples() == outPoints, "OriginalPointIds size");
  for (vtkIdType p = 0; p < outPoints; ++p)
  {
    const vtkIdType source = p < inPoints ? p
      : original                          ? static_cast<vtkIdType>(original->GetTuple1(p))
                                          : -1;
    Require(source == -1 || (source >= 0 && source < inPoints), "OriginalPointIds out of range");
    Require(!original || original->GetTuple1(p) == static_cast<double>(source),
      "OriginalPointIds of an input point is not itself");
    Require(source == -1 || ids->GetTuple1(p) == static_cast<double>(source),
      "point array not copied to point " + std::to_string(p));
    double a[3], b[3];
    output->GetPoint(p, a);
    if (source >= 0)
    {
      input->GetPoint(source, b);
      Require(std::memcmp(a, b, sizeof(a)) == 0, "point " + std::to_string(p) + " moved");
    }
  }
  const vtkIdType cells = input->GetNumberOfCells();
  if (cells == 0)
  {
    return; // nothing to compute: the input passes through as it is
  }
  vtkDataArray* cellIds = output->GetCellData()->GetArray("CellIds");
  Require(cellIds && cellIds->GetNumberOfTuples() == cells, "cell array not passed through");
  Require(output->GetFieldData()->GetArray("Field") != nullptr, "field array not passed through");
  vtkDataArray* status = output->GetCellData()->GetArray("NormalStatus");
  vtkDataArray* cellNormals =
    filter->GetComputeCellNormals() ? output->GetCellData()->GetArray("Normals") : nullptr;
  Require(
    !filter->GetComputeCellNormals() || (cellNormals && cellNormals->GetNumberOfTuples() == cells),
    "cell normals missing");
  Require(!filter->GetComputeNormalStatus() || (status && status->GetNumberOfTuples() == cells),
    "NormalStatus missing");
  for (vtkIdType c = 0; cellNormals && c < cells; ++c)
  {
    RequireUnitOrZero(cellNormals, c, "cell");
    if (status)
    {
      const int s = static_cast<int>(status->GetTuple1(c));
      Require(s >= 0 && s <= 4, "NormalStatus " + std::to_string(s));
      double n[3];
      cellNormals->GetTuple(c, n);
      const bool zero = n[0] == 0 && n[1] == 0 && n[2] == 0;
      Require(zero == (s >= 1 && s <= 3),
        "cell " + std::to_string(c) + ": status " + std::to_string(s) +
          (zero ? " with a zero normal" : " with a non-zero normal"));
    }
  }
  vtkDataArray* pointNormals =
    filter->GetComputePointNormals() ? output->GetPointData()->GetArray("Normals") : nullptr;
  Require(!filter->GetComputePointNormals() ||
      (pointNormals && pointNormals->GetNumberOfTuples() == outPoints),
    "point normals missing");
  for (vtkIdType p = 0; pointNormals && p < outPoints; ++p)
  {
    RequireUnitOrZero(pointNormals, p, "point");
  }
  Require(!IsNaN(output->GetCellData()->GetArray("AreaVectors")), "NaN in AreaVectors");
  Require(!IsNaN(output->GetCellData()->GetArray("Areas")), "NaN in Areas");
}

void ConfigureNormals(FuzzedDataProvider& in, vtkPolygonNormals* f)
{
  f->SetAccuracy(in.ConsumeIntegralInRange<int>(0, 3));
  f->SetPointWeighting(in.ConsumeIntegralInRange<int>(0, 3));
  f->SetComputeCellNormals(in.ConsumeBool());
  f->SetComputePointNormals(in.ConsumeBool());
  f->SetComputeAreaVectors(in.ConsumeBool());
  f->SetComputeAreas(in.ConsumeBool());
  f->SetComputeNormalStatus(in.ConsumeBool());
  f->SetPieceInvariant(in.ConsumeBool());
  f->SetConsistency(in.ConsumeBool());
  f->SetAutoOrientNormals(in.ConsumeBool());
  f->SetNonManifoldTraversal(in.ConsumeBool());
  f->SetFlipNormals(in.ConsumeBool());
  f->SetSplitting(in.ConsumeBool());
  f->SetFeatureAngle(in.ConsumeIntegralInRange<int>(0, 180));
  f->SetComputeOriginalPointIds(in.ConsumeBool());
  f->SetOutputPrecision(in.ConsumeIntegralInRange<int>(0, 2));
  f->SetTriangulateStrips(in.ConsumeBool());
  f->SetOutputPointsPrecision(in.ConsumeIntegralInRange<int>(0, 2));
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  ReportFd = dup(2);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  vtkNew<vtkPolyData> input;
  const bool doublePoints = in.ConsumeBool();
  const bool raw = in.ConsumeBool();
  const int exponent = in.ConsumeIntegralInRange<int>(-1074, 1023);
  const vtkIdType numPoints = in.ConsumeIntegralInRange<vtkIdType>(0, 40);
  vtkNew<vtkPoints> points;
  points->SetDataType(doublePoints ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    double x[3];
    for (double& c : x)
    {
      c = Coordinate(in, raw, exponent);
    }
    points->SetPoint(p, x);
    if (std::getenv("PHONGVTK_FUZZ_VERBOSE"))
    {
      points->GetPoint(p, x);
      dprintf(ReportFd, "point %lld: %a %a %a\n", static_cast<long long>(p), x[0], x[1], x[2]);
    }
  }
  if (numPoints > 0 || in.ConsumeBool())
  {
    input->SetPoints(points);
  }
  bool wellFormed = true;
  bool idsInRange = true;
  input->SetVerts(DecodeCells(in, numPoints, wellFormed, idsInRange));
  input->SetLines(DecodeCells(in, numPoints, wellFormed, idsInRange));
  input->SetPolys(DecodeCells(in, numPoints, wellFormed, idsInRange));
  input->SetStrips(DecodeCells(in, numPoints, wellFormed, idsInRange));
  const bool refused =
    !wellFormed || !idsInRange || (input->GetPoints() == nullptr && input->GetNumberOfCells() > 0);

  // Arrays to pass through (not when the cells cannot be counted: BuildCells would misread them).
  vtkNew<vtkDoubleArray> pointIds;
  pointIds->SetName("Ids");
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    pointIds->InsertNextValue(static_cast<double>(p));
  }
  input->GetPointData()->AddArray(pointIds);
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  field->InsertNextValue(42.0);
  input->GetFieldData()->AddArray(field);
  if (!refused)
  {
    vtkNew<vtkDoubleArray> cellIds;
    cellIds->SetName("CellIds");
    for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
    {
      cellIds->InsertNextValue(static_cast<double>(c));
    }
    input->GetCellData()->AddArray(cellIds);
  }

  vtkNew<vtkPolygonNormals> normals;
  ConfigureNormals(in, normals);
  vtkNew<ErrorCounter> normalErrors;
  normals->AddObserver(vtkCommand::ErrorEvent, normalErrors);
  normals->AddObserver(vtkCommand::WarningEvent, normalErrors);
  std::ostringstream summary;
  summary << numPoints << (doublePoints ? " double" : " float") << " points"
          << (input->GetPoints() ? "" : " (none set)") << ", cells " << input->GetNumberOfVerts()
          << " verts " << input->GetNumberOfLines() << " lines " << input->GetNumberOfPolys()
          << " polys " << input->GetNumberOfStrips() << " strips"
          << (wellFormed ? "" : ", malformed") << (idsInRange ? "" : ", ids out of range")
          << "; accuracy " << normals->GetAccuracy() << " weighting "
          << normals->GetPointWeighting() << " cell/point normals "
          << normals->GetComputeCellNormals() << normals->GetComputePointNormals()
          << " consistency " << normals->GetConsistency() << " auto-orient "
          << normals->GetAutoOrientNormals() << " non-manifold "
          << normals->GetNonManifoldTraversal() << " flip " << normals->GetFlipNormals()
          << " splitting " << normals->GetSplitting() << " at " << normals->GetFeatureAngle();
  InputSummary = summary.str();
  normals->SetInputData(input);
  normals->Update();
  vtkPolyData* output = normals->GetOutput();
  if (refused)
  {
    Require(normalErrors->Errors == 1, "vtkPolygonNormals: malformed input without one error");
    Require(output->GetNumberOfPoints() == 0 && output->GetNumberOfCells() == 0,
      "vtkPolygonNormals: malformed input, non-empty output");
  }
  else
  {
    Require(normalErrors->Errors == 0, "vtkPolygonNormals: an error on well-formed input");
    CheckNormals(input, output, normals);
  }

  vtkNew<vtkVisibleArea> area;
  area->SetAccuracy(in.ConsumeIntegralInRange<int>(0, 3));
  area->SetUseInputAreaVectors(in.ConsumeBool());
  area->SetComputeMaxVisibleArea(in.ConsumeBool());
  const int kind = in.ConsumeIntegralInRange<int>(0, 2);
  double v[3];
  for (double& c : v)
  {
    c = Coordinate(in, in.ConsumeBool(), in.ConsumeIntegralInRange<int>(-1074, 1023));
  }
  vtkNew<vtkCamera> camera;
  if (kind == 0)
  {
    area->SetViewDirection(v);
  }
  else
  {
    camera->SetParallelProjection(kind == 1);
    camera->SetPosition(v);
    area->SetCamera(camera);
  }
  vtkNew<ErrorCounter> areaErrors;
  area->AddObserver(vtkCommand::ErrorEvent, areaErrors);
  area->AddObserver(vtkCommand::WarningEvent, areaErrors);
  vtkPolyData* areaInput = in.ConsumeBool() ? input.GetPointer() : output;
  area->SetInputData(areaInput);
  char view[256];
  std::snprintf(view, sizeof(view),
    "; vtkVisibleArea: accuracy %d, %s (%a, %a, %a), on the %s, input area vectors %d",
    area->GetAccuracy(),
    kind == 0     ? "direction"
      : kind == 1 ? "parallel camera at"
                  : "perspective camera at",
    v[0], v[1], v[2], areaInput == output ? "normals' output" : "input",
    area->GetUseInputAreaVectors());
  InputSummary += view;
  area->Update();
  vtkPolyData* seen = area->GetOutput();
  Require(areaErrors->Errors <= 1, "vtkVisibleArea: more than one error");
  if (areaErrors->Errors == 1)
  {
    Require(seen->GetNumberOfPoints() == 0 && seen->GetNumberOfCells() == 0,
      "vtkVisibleArea: an error and a non-empty output");
  }
  else
  {
    Require(
      !refused || areaInput->GetNumberOfCells() == 0, "vtkVisibleArea: malformed input accepted");
    Require(!IsNaN(seen->GetCellData()->GetArray("VisibleArea")), "NaN in VisibleArea");
    Require(!std::isnan(area->GetTotalVisibleArea()), "TotalVisibleArea is NaN");
    Require(!std::isnan(area->GetMaxVisibleArea()), "MaxVisibleArea is NaN");
  }
  return 0;
}
