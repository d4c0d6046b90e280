#include "vtkPolygonNormals.h"

#include "PhongVTKAreaVector.h"
#include "PhongVTKCells.h"
#include "PhongVTKKernels.h"
#include "PhongVTKOptions.h"
#include "PhongVTKStripTriangles.h"
#include "PhongVTKWellFormedCells.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

vtkStandardNewMacro(vtkPolygonNormals);

//------------------------------------------------------------------------------
vtkPolygonNormals::vtkPolygonNormals() = default;
vtkPolygonNormals::~vtkPolygonNormals() = default;

//------------------------------------------------------------------------------
const char* vtkPolygonNormals::GetAccuracyAsString()
{
  return phongvtk::AccuracyNames[this->Accuracy];
}

//------------------------------------------------------------------------------
namespace
{
constexpr const char* const WeightingNames[] = { "AREA", "ANGLE", "UNIFORM", "MAX" };
constexpr const char* const PrecisionNames[] = { "SINGLE_PRECISION", "DOUBLE_PRECISION",
  "DEFAULT_PRECISION" };
}

//------------------------------------------------------------------------------
const char* vtkPolygonNormals::GetPointWeightingAsString()
{
  return WeightingNames[this->PointWeighting];
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetAccuracy(int mode)
{
  if (phongvtk::SetEnumeratedOption(
        this, "accuracy", this->Accuracy, mode, phongvtk::AccuracyNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetPointWeighting(int weighting)
{
  if (phongvtk::SetEnumeratedOption(
        this, "point weighting", this->PointWeighting, weighting, WeightingNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetOutputPrecision(int precision)
{
  if (phongvtk::SetEnumeratedOption(
        this, "output precision", this->OutputPrecision, precision, PrecisionNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::SetOutputPointsPrecision(int precision)
{
  if (phongvtk::SetEnumeratedOption(
        this, "output points precision", this->OutputPointsPrecision, precision, PrecisionNames))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
namespace
{
/// The first cell (VTK's numbering) with a point id outside [0, number of points), or -1.
vtkIdType FirstInvalidCell(vtkPolyData* input)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkIdType first = 0;
  for (vtkCellArray* cells :
    { input->GetVerts(), input->GetLines(), input->GetPolys(), input->GetStrips() })
  {
    const vtkIdType n = cells ? cells->GetNumberOfCells() : 0;
    vtkIdType bad = -1;
    if (n > 0)
    {
      phongvtk::ForRawCells(cells,
        [&](const auto* offsets, const auto* conn)
        {
          for (vtkIdType c = 0; c < n && bad < 0; ++c)
          {
            if (!phongvtk::ValidIds(conn + offsets[c], offsets[c + 1] - offsets[c], numPoints))
            {
              bad = c;
            }
          }
        });
    }
    if (bad >= 0)
    {
      return first + bad;
    }
    first += n;
  }
  return -1;
}
} // namespace

//------------------------------------------------------------------------------
namespace
{
/// Whether the filter asks upstream for one more level of ghost cells than downstream asked for:
/// when it computes point normals of one piece among several (the faces across the piece's
/// boundary belong to the boundary points' normals).
bool WantsExtraGhostLevel(vtkPolygonNormals* self, vtkInformation* outInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  return self->GetComputePointNormals() && self->GetPieceInvariant() &&
    outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) > 1;
}
}

//------------------------------------------------------------------------------
int vtkPolygonNormals::RequestUpdateExtent(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int ghostLevels = outInfo->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS());
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()));
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()));
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(),
    ghostLevels + (WantsExtraGhostLevel(this, outInfo) ? 1 : 0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkPolygonNormals::RequestData(vtkInformation* vtkNotUsed(request),
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
  output->ShallowCopy(original);
  vtkPoints* points = input->GetPoints();
  if (!points || input->GetNumberOfCells() == 0)
  {
    if (input->GetNumberOfCells() > 0)
    {
      vtkErrorMacro("Input has " << input->GetNumberOfCells() << " cells but no points.");
      output->Initialize();
      return 0; // the update fails
    }
    return 1; // nothing to compute: the input passes through
  }
  const vtkIdType malformed = phongvtk::FirstMalformedCell(input);
  if (malformed >= 0)
  {
    vtkErrorMacro("Cell " << malformed << phongvtk::MalformedCellReason);
    output->Initialize();
    return 0; // the update fails
  }
  vtkIdType firstBadCell = -1;
  bool ok = true;
  bool validated = false; // every point id checked already
  vtkSmartPointer<vtkPolyData> triangulated;
  if (this->TriangulateStrips && input->GetNumberOfStrips() > 0)
  {
    // Checked first, so that an error names the input's cell, not one of a strip's triangles.
    firstBadCell = FirstInvalidCell(input);
    ok = firstBadCell < 0;
    validated = true;
    if (ok)
    {
      triangulated = phongvtk::StripsAsTriangles(input);
      input = triangulated;
      output->ShallowCopy(triangulated);
    }
  }

  const phongvtk::PolygonNormalsKernels& kernels = phongvtk::SelectedPolygonNormalsKernels();
  vtkIdType nonFinite = 0;
  double progressStart = 0.0;
  vtkSmartPointer<vtkPolyData> source = input;
  // Orientation and splitting first: the normals follow the reordered and split polygons.
  std::vector<vtkIdType> clashes;
  vtkIdType nonOrientable = 0;
  const bool orient = (this->Consistency || this->AutoOrientNormals || this->FlipNormals) &&
    input->GetNumberOfPolys() > 0;
  const bool split = this->Splitting && this->ComputePointNormals;
  if (ok && orient && !split && !validated)
  {
    // Splitting validates every cell on its first pass (SharpEdges::Decide), before anything
    // reads a polygon's points; reordering alone reads them first.
    firstBadCell = FirstInvalidCell(input);
    ok = firstBadCell < 0;
  }
  if (ok && (orient || split))
  {
    source = kernels.OrientAndSplit(this, input, phongvtk::KernelCoordinates(points), orient, split,
      clashes, nonOrientable, firstBadCell);
    ok = source != nullptr;
    if (ok)
    {
      output->ShallowCopy(source);
      points = source->GetPoints();
      progressStart = split ? phongvtk::PolygonNormalsKernels::SplitShare : 0.0;
    }
  }

  const int pointType = points->GetData()->GetDataType();
  const bool doubleOutput = this->OutputPrecision == DOUBLE_PRECISION ||
    (this->OutputPrecision == DEFAULT_PRECISION && pointType == VTK_DOUBLE);
  if (ok && !this->GetAbortExecute())
  {
    ok = kernels.Normals(this, source, output, phongvtk::KernelCoordinates(points), doubleOutput,
      progressStart, nonFinite, firstBadCell);
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
    // Stopped part-way: the output arrays hold unwritten values, so nothing is delivered.
    output->Initialize();
    return 1;
  }
  if (split && this->OutputPointsPrecision != DEFAULT_PRECISION)
  {
    const int wanted = this->OutputPointsPrecision == SINGLE_PRECISION ? VTK_FLOAT : VTK_DOUBLE;
    if (output->GetPoints()->GetDataType() != wanted)
    {
      vtkNew<vtkPoints> converted;
      converted->SetDataType(wanted);
      converted->GetData()->DeepCopy(output->GetPoints()->GetData());
      output->SetPoints(converted);
    }
  }
  if (nonOrientable > 0)
  {
    // The status array the kernels made (it replaced any input array of that name), never another.
    auto* status = this->ComputeNormalStatus
      ? vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray("NormalStatus"))
      : nullptr;
    if (status)
    {
      const vtkIdType firstPoly = source->GetNumberOfVerts() + source->GetNumberOfLines();
      for (vtkIdType f : clashes)
      {
        unsigned char& value = status->GetPointer(0)[firstPoly + f];
        value = value == phongvtk::StatusOk ? phongvtk::StatusInconsistent : value;
      }
    }
    vtkWarningMacro(<< nonOrientable
                    << " connected component(s) are not orientable: their polygons cannot all "
                       "agree; "
                    << clashes.size()
                    << " polygon(s) lie along the edges where they still disagree (NormalStatus "
                       "4 with ComputeNormalStatus).");
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " cell(s) have non-finite (NaN or Inf) point coordinates; they are flagged "
                       "with NormalStatus 2 and get a zero normal.");
  }
  // The ghost cells asked for on downstream's behalf go again; with ghost levels requested
  // downstream the extra (outermost) layer stays, marked as ghosts like the others.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (WantsExtraGhostLevel(this, outInfo) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) == 0 &&
    output->GetCellGhostArray())
  {
    output->RemoveGhostCells();
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPolygonNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Accuracy: " << this->GetAccuracyAsString() << "\n";
  os << indent << "PointWeighting: " << this->GetPointWeightingAsString() << "\n";
  os << indent << "ComputeCellNormals: " << (this->ComputeCellNormals ? "On" : "Off") << "\n";
  os << indent << "ComputePointNormals: " << (this->ComputePointNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeAreaVectors: " << (this->ComputeAreaVectors ? "On" : "Off") << "\n";
  os << indent << "ComputeAreas: " << (this->ComputeAreas ? "On" : "Off") << "\n";
  os << indent << "ComputeNormalStatus: " << (this->ComputeNormalStatus ? "On" : "Off") << "\n";
  os << indent << "PieceInvariant: " << (this->PieceInvariant ? "On" : "Off") << "\n";
  os << indent << "Consistency: " << (this->Consistency ? "On" : "Off") << "\n";
  os << indent << "AutoOrientNormals: " << (this->AutoOrientNormals ? "On" : "Off") << "\n";
  os << indent << "NonManifoldTraversal: " << (this->NonManifoldTraversal ? "On" : "Off") << "\n";
  os << indent << "FlipNormals: " << (this->FlipNormals ? "On" : "Off") << "\n";
  os << indent << "Splitting: " << (this->Splitting ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "ComputeOriginalPointIds: " << (this->ComputeOriginalPointIds ? "On" : "Off")
     << "\n";
  os << indent << "OutputPrecision: " << PrecisionNames[this->OutputPrecision] << "\n";
  os << indent << "TriangulateStrips: " << (this->TriangulateStrips ? "On" : "Off") << "\n";
  os << indent << "OutputPointsPrecision: " << PrecisionNames[this->OutputPointsPrecision] << "\n";
}
