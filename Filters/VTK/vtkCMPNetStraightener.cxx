#include "vtkCMPNetStraightener.h"

#include <cmp/layout/CurveSpread.h>
#include <cmp/layout/LayoutValidator.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/Straighten.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkCMPNetStraightener);

vtkCMPNetStraightener::vtkCMPNetStraightener()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkCMPNetStraightener::FillInputPortInformation(int, vtkInformation* info)
{
  // A multiblock on port 0 is handled by the composite pipeline, which runs
  // this filter block by block (as for the tracer).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{

using cmp::bridge::kBaseTriangleArray;
using cmp::bridge::kBaseCoordinatesArray;

/// Point data of the straightened surface: every input array interpolated
/// with the input location of each new vertex, FeatureId written anew, and
/// the base-domain coordinates.
void fillPointData(vtkPointData* points, vtkPointData* input, const cmp::StraightenedNet& straight,
  const cmp::BaseDomain& domain, const cmp::PatchParameterization& parameterization, const cmp::OpenPart& kept)
{
  const int vertices = kept.mesh.vertexCount();
  // FeatureId marks exactly the landmarks: interpolating it would spread
  // feature numbers onto the points around them. The base arrays of an input
  // that was straightened before are replaced below.
  for (const char* name : { cmp::bridge::kFeatureIdArray, kBaseTriangleArray, kBaseCoordinatesArray })
    points->CopyFieldOff(name);
  points->InterpolateAllocate(input, vertices);
  vtkNew<vtkIdList> ids;
  double weights[3];
  for (int v = 0; v < vertices; ++v)
  {
    const cmp::SurfacePoint& at = straight.inputPoint[kept.vertexOf[v]];
    ids->Reset();
    for (int k = 0; k < 3; ++k)
      if (at.vertex[k] >= 0 && at.weight[k] != 0.0) // (a cap's centre has no data, and weighs nothing here)
      {
        weights[ids->GetNumberOfIds()] = at.weight[k];
        ids->InsertNextId(at.vertex[k]);
      }
    points->InterpolatePoint(input, v, ids, weights);
  }

  // Same array type as the input's, so readers of FeatureId see no change.
  vtkDataArray* inputFeatureIds = input->GetArray(cmp::bridge::kFeatureIdArray);
  auto featureIds = vtk::TakeSmartPointer(inputFeatureIds->NewInstance());
  featureIds->SetName(cmp::bridge::kFeatureIdArray);
  featureIds->SetNumberOfComponents(1);
  featureIds->SetNumberOfTuples(vertices);
  featureIds->Fill(-1);
  for (int bv = 0; bv < domain.mesh.vertexCount(); ++bv)
    if (const int v = kept.newIndex[straight.net.landmarkVertex[bv]]; v >= 0) // not a cap's centre
      featureIds->SetComponent(v, 0, domain.featureIds[bv]);
  points->AddArray(featureIds);

  vtkNew<vtkIntArray> baseTriangles;
  baseTriangles->SetName(kBaseTriangleArray);
  baseTriangles->SetNumberOfValues(vertices);
  vtkNew<vtkDoubleArray> baseCoordinates;
  baseCoordinates->SetName(kBaseCoordinatesArray);
  baseCoordinates->SetNumberOfComponents(3);
  baseCoordinates->SetNumberOfTuples(vertices);
  for (int v = 0; v < vertices; ++v)
  {
    baseTriangles->SetValue(v, parameterization.baseTriangle[kept.vertexOf[v]]);
    baseCoordinates->SetTypedTuple(v, parameterization.baseCoordinates[kept.vertexOf[v]].data());
  }
  points->AddArray(baseTriangles);
  points->AddArray(baseCoordinates);
}

/// Cell data of the straightened surface: every input array copied from the
/// input triangle each triangle lies in, and the new PatchId.
void fillCellData(vtkCellData* cells, vtkCellData* input, const cmp::TriangleMesh& inputMesh,
  const cmp::StraightenedNet& straight, const cmp::OpenPart& kept)
{
  const int triangles = kept.mesh.triangleCount();
  // A straight curve may cut an input triangle: its pieces need not stay in
  // the input triangle's patch.
  cells->CopyFieldOff(cmp::bridge::kPatchIdArray);
  cells->CopyAllocate(input, triangles);
  for (int t = 0; t < triangles; ++t)
    cells->CopyData(input, straight.inputTriangle[kept.triangleOf[t]], t);
  vtkDataArray* corners = cells->GetArray(cmp::bridge::kCornerTCoordsArray);
  vtkDataArray* inputCorners = input->GetArray(cmp::bridge::kCornerTCoordsArray);
  if (corners && inputCorners && corners->GetNumberOfComponents() == 6)
    cmp::bridge::interpolateCornerTCoords(corners, inputCorners, inputMesh, triangles,
      [&](int t) { return straight.inputTriangle[kept.triangleOf[t]]; },
      [&](int t, int c) { return straight.inputPoint[straight.net.mesh.triangle(kept.triangleOf[t])[c]]; });

  vtkNew<vtkIntArray> patchIds;
  patchIds->SetName(cmp::bridge::kPatchIdArray);
  patchIds->SetNumberOfValues(triangles);
  for (int t = 0; t < triangles; ++t)
    patchIds->SetValue(t, straight.net.patchOfTriangle[kept.triangleOf[t]]);
  cells->AddArray(patchIds);
}

} // namespace

int vtkCMPNetStraightener::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* baseInput = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* surfaceOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* curvesOutput = vtkPolyData::GetData(outputVector, 1);
  const std::string model = cmp::bridge::modelPrefix(input);
  if (!baseInput)
  {
    vtkErrorMacro(<< model << "no base domain: connect L0 (the one the net was traced against) to the second input");
    return 0;
  }
  cmp::StraightenOptions options;
  options.net.maxSweeps = this->MaximumSweeps;
  options.net.tolerance = this->Tolerance;
  options.net.snapTolerance = this->SnapTolerance;
  options.patches.lowerStretch = this->LowerStretch;
  options.freeCurves = this->FreeCurves;
  options.map.maximumIterations = this->MapIterations;
  options.freeCurvesMaximumTriangles = this->FreeCurvesMaximumTriangles;
  options.progress = [this](double fraction) { this->UpdateProgress(0.8 * fraction); };
  if (const cmp::Status problem = cmp::checkStraightenOptions(options); !problem.ok())
  {
    vtkErrorMacro(<< model << problem.message());
    return 0;
  }
  cmp::LandmarkList landmarks;
  cmp::BaseDomain domain;
  cmp::BaseDomainHoles holes;
  cmp::bridge::ClosedSurface surface;
  std::vector<int> patchIds;
  // The surface's own defects first, then its landmarks, then L0.
  cmp::TriangleMesh asGiven;
  cmp::Status status = cmp::bridge::toCheckedSurfaceWithBoundaries(input, asGiven);
  if (status.ok())
    status = cmp::bridge::readLandmarks(input, landmarks);
  if (status.ok())
    status = cmp::bridge::toClosedBaseDomain(baseInput, domain, holes, static_cast<int>(landmarks.size()));
  if (status.ok())
    status = cmp::bridge::toClosedSurface(std::move(asGiven), landmarks, holes, surface);
  if (status.ok())
    status = cmp::bridge::readPatchIds(input, patchIds);
  if (status.ok())
  {
    // The caps, closed anew, lie in the holes' base triangles.
    const std::vector<int> caps = cmp::capPatchIds(surface.holes, holes);
    patchIds.insert(patchIds.end(), caps.begin(), caps.end());
  }
  const cmp::TriangleMesh& mesh = surface.open;
  // The core only rebuilds a layout that is one; checking first names the
  // problem in the user's terms (for example L0 from another collection).
  if (status.ok())
    if (const std::string problem =
          layoutProblem(cmp::toLabelledSurface(surface.closed, patchIds, surface.closedLandmarks), domain);
        !problem.empty())
      status = cmp::Status::error("the input's PatchId layout is not equivalent to L0: " + problem);
  cmp::TracedNet traced;
  if (status.ok())
    status = cmp::layoutFromPatchIds(surface.closed, patchIds, surface.closedLandmarks, domain, traced);
  if (!holes.empty())
  {
    // The caps stay as they are: their curves, and their vertices in the map.
    options.net.keptFeatures = holes.keptFeatures();
    options.map.fixedPatches = holes.holeTriangle;
  }
  cmp::StraightenedNet straight;
  cmp::PatchParameterization parameterization;
  cmp::StraightenReport straightenReport;
  if (status.ok())
    status = cmp::straighten(traced, domain, straight, parameterization, options, &straightenReport);
  const cmp::NetStraightenerReport& report = straightenReport.net;
  const cmp::FreeCurvesReport& freeCurves = straightenReport.freeCurves;
  if (status.ok() && !straightenReport.tracedCurvesKept.empty())
    vtkWarningMacro(<< model << straightenReport.tracedCurvesKept);
  if (status.ok() && this->FreeCurves && !freeCurves.applied)
    vtkWarningMacro(<< model << "FreeCurves kept the straightened curves: " << freeCurves.reason);
  if (!status.ok())
  {
    vtkErrorMacro(<< model << status.message());
    return 0;
  }
  this->UpdateProgress(0.9);

  const std::string problem = layoutProblem(cmp::toLabelledSurface(straight.net, domain), domain);
  if (!problem.empty())
    vtkWarningMacro(<< model << "the straightened net failed the layout check: " << problem);
  if (parameterization.flippedTriangles > 0)
    vtkWarningMacro(<< model << parameterization.flippedTriangles
                    << " triangles are flipped in their patch's map onto its base triangle");

  const cmp::OpenPart kept =
    cmp::openPart(straight.net.mesh.toTriangleMesh(), straight.net.patchOfTriangle, holes.holeTriangle);
  vtkSmartPointer<vtkPolyData> straightened = cmp::bridge::toPolyData(kept.mesh);
  fillPointData(straightened->GetPointData(), input->GetPointData(), straight, domain, parameterization, kept);
  fillCellData(straightened->GetCellData(), input->GetCellData(), mesh, straight, kept);
  surfaceOutput->ShallowCopy(straightened);
  curvesOutput->ShallowCopy(cmp::bridge::toPolyLines(straight.net, domain, holes));
  // Scale-free, like the tracer's NetLengthPerSqrtArea: the area is unchanged.
  const double lengthPerSqrtArea = report.netLengthAfter / std::sqrt(cmp::surfaceArea(mesh));
  const cmp::CurveGap widestGap = cmp::widestCurveGap(straight.net);
  const int widestGapFeature = widestGap.baseVertex >= 0 ? domain.featureIds[widestGap.baseVertex] : -1;
  for (vtkPolyData* output : { surfaceOutput, curvesOutput })
  {
    vtkFieldData* field = output->GetFieldData();
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetLengthBeforeField, report.netLengthBefore);
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetLengthAfterField, report.netLengthAfter);
    cmp::bridge::setFieldValue(field, cmp::bridge::kStraightenedNetLengthField, straightenReport.straightenedNetLength);
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetLengthPerSqrtAreaAfterField, lengthPerSqrtArea);
    cmp::bridge::setFieldValue(field, cmp::bridge::kAreaVariationBeforeField, report.areaVariationBefore);
    cmp::bridge::setFieldValue(field, cmp::bridge::kAreaVariationAfterField, report.areaVariationAfter);
    cmp::bridge::setFieldValue(field, cmp::bridge::kSweepsField, report.sweeps);
    cmp::bridge::setFieldValue(field, cmp::bridge::kSkippedStarsField, report.skippedStars);
    cmp::bridge::setFieldValue(field, cmp::bridge::kFlippedTrianglesField, parameterization.flippedTriangles);
    cmp::bridge::setFieldValue(field, cmp::bridge::kSmallestAreaRatioField, parameterization.smallestAreaRatio);
    cmp::bridge::setFieldValue(field, cmp::bridge::kWidestCurveGapField, widestGap.degrees);
    cmp::bridge::setFieldValue(field, cmp::bridge::kWidestCurveGapFeatureField, widestGapFeature);
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetValidField, problem.empty() ? 1 : 0);
    if (this->FreeCurves)
    {
      cmp::bridge::setFieldValue(field, cmp::bridge::kFreeCurvesAppliedField, freeCurves.applied ? 1 : 0);
      cmp::bridge::setFieldValue(field, cmp::bridge::kMapDistortionBeforeField, freeCurves.map.distortionBefore);
      cmp::bridge::setFieldValue(field, cmp::bridge::kMapDistortionAfterField, freeCurves.map.distortionAfter);
      cmp::bridge::setFieldValue(field, cmp::bridge::kMapIterationsField, freeCurves.map.iterations);
      cmp::bridge::setFieldValue(field, cmp::bridge::kMapCrossingVerticesField, freeCurves.map.crossingVertices);
      cmp::bridge::setFieldString(field, cmp::bridge::kFreeCurvesReasonField, freeCurves.applied ? "" : freeCurves.reason);
    }
    // The outputs are built anew: keep the model's name for the remesher.
    cmp::bridge::copySourceFile(input, output);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPNetStraightener::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumSweeps: " << this->MaximumSweeps << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "SnapTolerance: " << this->SnapTolerance << "\n";
  os << indent << "LowerStretch: " << this->LowerStretch << "\n";
  os << indent << "FreeCurves: " << this->FreeCurves << "\n";
  os << indent << "MapIterations: " << this->MapIterations << "\n";
  os << indent << "FreeCurvesMaximumTriangles: " << this->FreeCurvesMaximumTriangles << "\n";
}
