#include "vtkCMPInputCheck.h"

#include "vtkCMPPolyDataBridge.h"

#include <vtkAlgorithm.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPInputCheck);

vtkCMPInputCheck::vtkCMPInputCheck()
{
  this->SetNumberOfInputPorts(2);
}

int vtkCMPInputCheck::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

namespace
{

cmp::Status checkInputs(vtkPolyData* surface, vtkPolyData* baseDomain, bool requireLandmarks, bool allowMissing)
{
  cmp::TriangleMesh mesh;
  if (cmp::Status s = cmp::bridge::toCheckedSurface(surface, mesh); !s.ok())
    return s;
  const bool hasLandmarks = surface->GetPointData()->GetArray(cmp::bridge::kFeatureIdArray) != nullptr;
  cmp::LandmarkList landmarks;
  if (hasLandmarks || requireLandmarks || baseDomain)
  {
    // Against a base domain every feature must be there.
    if (cmp::Status s = cmp::bridge::readLandmarks(surface, landmarks, allowMissing && !baseDomain); !s.ok())
      return s;
  }
  if (baseDomain)
  {
    cmp::BaseDomain domain;
    return cmp::bridge::toBaseDomain(baseDomain, domain, static_cast<int>(landmarks.size()));
  }
  return {};
}

} // namespace

int vtkCMPInputCheck::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* baseDomain = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const cmp::Status status =
    checkInputs(surface, baseDomain, this->RequireLandmarks, this->AllowMissingLandmarks);
  this->LastError = status.message();
  if (!status.ok())
  {
    vtkErrorMacro(<< cmp::bridge::modelPrefix(surface) << status.message());
    return 0;
  }
  output->ShallowCopy(surface);
  cmp::bridge::setFieldString(output->GetFieldData(), cmp::bridge::kInputCheckField, "ok");
  return 1;
}

void vtkCMPInputCheck::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RequireLandmarks: " << this->RequireLandmarks << "\n";
  os << indent << "AllowMissingLandmarks: " << this->AllowMissingLandmarks << "\n";
}
