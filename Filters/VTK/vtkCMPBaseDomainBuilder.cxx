#include "vtkCMPBaseDomainBuilder.h"

#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/mesh/SurfaceCheck.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkFieldData.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPBaseDomainBuilder);

int vtkCMPBaseDomainBuilder::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  cmp::TriangleMesh mesh;
  cmp::LandmarkList landmarks;
  // Read without refusing boundary loops: buildBaseDomain() caps them and
  // checks the contract of surfaces with boundaries (beyond the paper). Any
  // other defect is refused here, first, as before.
  cmp::Status status = cmp::bridge::toTriangleMesh(input, mesh);
  if (status.ok())
  {
    const cmp::SurfaceCheckResult check = cmp::checkSurface(mesh);
    if (!check.ok() && check.defect != cmp::SurfaceDefect::BoundaryEdge)
      status = cmp::Status::error(check.message);
  }
  if (status.ok())
  {
    // A base domain is built from the landmarks a user placed, all of them.
    status = cmp::bridge::readLandmarks(input, landmarks, true);
    if (status.ok() && cmp::missingLandmarkCount(landmarks) > 0)
    {
      std::string features;
      for (std::size_t f = 0; f < landmarks.size(); ++f)
        if (landmarks[f] == cmp::kMissingLandmark)
          features += (features.empty() ? "" : ", ") + std::to_string(f);
      status = cmp::Status::error("this model misses landmark" +
        std::string(cmp::missingLandmarkCount(landmarks) > 1 ? "s " : " ") + features +
        ": a base domain is built from a model with every landmark (Missing Landmark Placer places missing "
        "ones from the models that have them)");
    }
  }
  cmp::BaseDomain domain;
  cmp::BaseDomainBuilderReport report;
  if (status.ok())
  {
    cmp::BaseDomainBuilderOptions options;
    options.shapeWeight = this->ShapeWeight;
    options.progress = [this](double fraction) { this->UpdateProgress(fraction); };
    status = cmp::buildBaseDomain(mesh, landmarks, domain, options, &report);
  }
  if (!status.ok())
  {
    vtkErrorMacro(<< cmp::bridge::modelPrefix(input) << status.message());
    return 0;
  }
  output->ShallowCopy(cmp::bridge::toPolyData(domain));
  vtkFieldData* field = output->GetFieldData();
  cmp::bridge::setFieldValue(field, cmp::bridge::kMinimumAngleField, report.minAngleDegrees);
  cmp::bridge::setFieldValue(field, cmp::bridge::kMeanShapeQualityField, report.meanShapeQuality);
  cmp::bridge::setFieldValue(field, cmp::bridge::kFoldingCollapsesField, report.foldingCollapses);
  return 1;
}

void vtkCMPBaseDomainBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
}
