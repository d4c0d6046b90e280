#include "vtkVisibleArea.h"

#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKKernels.h"
#include "PhongVTKOptions.h"
#include "PhongVTKVisibleArea.h"
#include "PhongVTKWellFormedCells.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkVisibleArea);
vtkCxxSetObjectMacro(vtkVisibleArea, Camera, vtkCamera);

namespace
{
using phongvtk::detail::DD;

vtkSmartPointer<vtkDoubleArray> NewScalar(const char* name, int components, const double* values)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(1);
  for (int c = 0; c < components; ++c)
  {
    a->SetComponent(0, c, values[c]);
  }
  return a;
}
} // namespace

//------------------------------------------------------------------------------
vtkVisibleArea::vtkVisibleArea() = default;

vtkVisibleArea::~vtkVisibleArea()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkVisibleArea::GetAccuracyAsString()
{
  return phongvtk::AccuracyNames[this->Accuracy];
}

//------------------------------------------------------------------------------
void vtkVisibleArea::SetAccuracy(int mode)
{
  if (phongvtk::SetEnumeratedOption(
        this, "accuracy", this->Accuracy, mode, phongvtk::AccuracyNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkVisibleArea::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Camera)
  {
    t = std::max(t, this->Camera->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------

//------------------------------------------------------------------------------
int vtkVisibleArea::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* original = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!original || !output)
  {
    return 0;
  }
  // Read through plain cell arrays (a copy of VTK 9.6's fixed-size or generic ones: PlainCells);
  // the output passes the original arrays through.
  const vtkSmartPointer<vtkPolyData> plain = phongvtk::PlainCells(original);
  vtkPolyData* input = plain;
  this->TotalVisibleArea = 0.0;
  this->MaxVisibleArea = 0.0;
  std::fill_n(this->MaxVisibleAreaDirection, 3, 0.0);
  output->ShallowCopy(original);

  // The view.
  phongvtk::View view;
  double v[3];
  if (this->Camera)
  {
    if (this->Camera->GetParallelProjection())
    {
      const double* dop = this->Camera->GetDirectionOfProjection();
      for (int c = 0; c < 3; ++c)
      {
        v[c] = -dop[c];
      }
    }
    else
    {
      view.Eye = true;
      this->Camera->GetPosition(v);
    }
  }
  else
  {
    std::copy(this->ViewDirection, this->ViewDirection + 3, v);
  }
  bool usable = std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
  if (usable && view.Eye)
  {
    std::copy(v, v + 3, view.Vector);
  }
  else if (usable)
  {
    usable = phongvtk::detail::SetDirection(view, v);
  }
  if (!usable)
  {
    vtkErrorMacro("The " << (view.Eye ? "camera position" : "view direction") << " (" << v[0]
                         << ", " << v[1] << ", " << v[2]
                         << ") is not a finite non-zero vector; the output is empty.");
    output->Initialize();
    return 0; // the update fails
  }

  const vtkIdType numCells = input->GetNumberOfCells();
  vtkPoints* points = input->GetPoints();
  if (!points && numCells > 0)
  {
    vtkErrorMacro("Input has " << numCells << " cells but no points.");
    output->Initialize();
    return 0; // the update fails
  }
  const vtkIdType malformed = phongvtk::FirstMalformedCell(input);
  if (malformed >= 0)
  {
    vtkErrorMacro("Cell " << malformed << phongvtk::MalformedCellReason);
    output->Initialize();
    return 0; // the update fails
  }

  // The input's area vectors, as doubles.
  vtkSmartPointer<vtkDoubleArray> inputAreaVectors;
  vtkDataArray* given = input->GetCellData()->GetArray("AreaVectors");
  if (this->UseInputAreaVectors && this->Accuracy != EXACT && given &&
    given->GetNumberOfComponents() == 3 && given->GetNumberOfTuples() == numCells)
  {
    inputAreaVectors = vtkDoubleArray::SafeDownCast(given);
    if (!inputAreaVectors)
    {
      inputAreaVectors = vtkSmartPointer<vtkDoubleArray>::New();
      inputAreaVectors->DeepCopy(given);
    }
  }

  auto areas = vtkSmartPointer<vtkDoubleArray>::New();
  areas->SetName("VisibleArea");
  areas->SetNumberOfTuples(numCells);
  vtkIdType nonFinite = 0, firstBadCell = -1;
  double sumW[3][2] = { { 0.0, 0.0 }, { 0.0, 0.0 }, { 0.0, 0.0 } };
  int sumScale = 0;
  bool ok = true;
  if (numCells > 0)
  {
    const double* reuse = inputAreaVectors ? inputAreaVectors->GetPointer(0) : nullptr;
    ok = phongvtk::SelectedVisibleAreaKernels().VisibleAreas(this, input,
      phongvtk::KernelCoordinates(points), v, view.Eye, reuse, areas, nonFinite, firstBadCell, sumW,
      sumScale);
  }
  if (!ok)
  {
    vtkErrorMacro("Cell " << firstBadCell << " refers to a point id outside [0, "
                          << input->GetNumberOfPoints() << "); the output is empty.");
    output->Initialize();
    return 0; // the update fails
  }
  if (this->GetAbortExecute())
  {
    output->Initialize();
    return 1;
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " cell(s) have non-finite (NaN or Inf) point coordinates or area vectors; "
                       "their visible area is 0.");
  }

  // The front faces' total, the same bits for any number of threads. Ghost cells belong to
  // another piece: they count as zero here (so the pieces' totals add up to the whole mesh's)
  // and keep their visible areas in the cell array.
  double total[2];
  phongvtk::SelectedVisibleAreaKernels().Total(
    areas->GetPointer(0), phongvtk::CellGhostFlags(input), numCells, total);
  // Every term is positive: a sum that is not finite overflowed the double range (a TwoSum past
  // it gives infinity minus infinity), and the total saturates at its largest value, as
  // MaxVisibleArea does.
  const double sum = total[0] + total[1];
  this->TotalVisibleArea = std::isfinite(sum) ? sum : std::numeric_limits<double>::max();

  vtkCellData* cd = output->GetCellData();
  cd->AddArray(areas);
  vtkFieldData* fd = output->GetFieldData();
  fd->AddArray(NewScalar("TotalVisibleArea", 1, &this->TotalVisibleArea));
  if (this->ComputeMaxVisibleArea)
  {
    double length;
    int exponent;
    const DD w[3] = { { sumW[0][0], sumW[0][1] }, { sumW[1][0], sumW[1][1] },
      { sumW[2][0], sumW[2][1] } };
    if (phongvtk::detail::NormalizeFaithful(w, this->MaxVisibleAreaDirection, length, exponent))
    {
      this->MaxVisibleArea = phongvtk::detail::ScaleSaturated(length, exponent + 2 * sumScale - 1);
    }
    fd->AddArray(NewScalar("MaxVisibleAreaDirection", 3, this->MaxVisibleAreaDirection));
    fd->AddArray(NewScalar("MaxVisibleArea", 1, &this->MaxVisibleArea));
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkVisibleArea::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ViewDirection: (" << this->ViewDirection[0] << ", " << this->ViewDirection[1]
     << ", " << this->ViewDirection[2] << ")\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Accuracy: " << this->GetAccuracyAsString() << "\n";
  os << indent << "UseInputAreaVectors: " << (this->UseInputAreaVectors ? "On" : "Off") << "\n";
  os << indent << "ComputeMaxVisibleArea: " << (this->ComputeMaxVisibleArea ? "On" : "Off") << "\n";
  os << indent << "TotalVisibleArea: " << this->TotalVisibleArea << "\n";
  os << indent << "MaxVisibleArea: " << this->MaxVisibleArea << "\n";
}
