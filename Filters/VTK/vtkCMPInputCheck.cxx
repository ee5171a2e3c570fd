#include "vtkCMPInputCheck.h"

#include "vtkCMPPolyDataBridge.h"

#include <vtkAlgorithm.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <utility>

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
  if (cmp::Status s = cmp::bridge::toTriangleMesh(surface, mesh); !s.ok())
    return s;
  // The surface's defects first: a closed genus-0 surface, or a sphere
  // with holes (beyond the paper: surfaces with boundaries).
  if (cmp::Status s = cmp::checkSurfaceWithBoundaries(mesh); !s.ok())
    return s;
  const bool hasLandmarks = surface->GetPointData()->GetArray(cmp::bridge::kFeatureIdArray) != nullptr;
  cmp::LandmarkList landmarks;
  if (hasLandmarks || requireLandmarks || baseDomain)
  {
    // Against a base domain every feature must be there (boundary
    // landmarks in particular: they cannot be placed).
    if (cmp::Status s = cmp::bridge::readLandmarks(surface, landmarks, allowMissing && !baseDomain); !s.ok())
      return s;
  }
  if (!baseDomain)
    // Each boundary loop through at least 3 landmarks (when it has landmarks).
    return landmarks.empty() ? cmp::Status{} : cmp::checkSurfaceWithBoundaries(mesh, &landmarks);
  cmp::BaseDomain domain;
  cmp::BaseDomainHoles holes;
  if (cmp::Status s = cmp::bridge::toClosedBaseDomain(baseDomain, domain, holes); !s.ok())
    return s;
  // The contract of surfaces with boundaries: loops, boundary landmarks
  // and their cyclic order as L0's. An open surface against a closed L0
  // (or the other way round) says so before the landmark counts differ.
  std::vector<std::vector<int>> loops;
  const bool openSurface = cmp::boundaryLoops(mesh, loops).ok() && !loops.empty();
  cmp::bridge::ClosedSurface closed;
  if (openSurface == holes.empty())
    return cmp::bridge::toClosedSurface(std::move(mesh), landmarks, holes, closed);
  if (static_cast<int>(landmarks.size()) != holes.openVertexCount)
    return cmp::Status::error("base domain has " + std::to_string(holes.openVertexCount) +
      " vertices but the surface has " + std::to_string(landmarks.size()) +
      " landmarks; they must match one to one");
  return cmp::bridge::toClosedSurface(std::move(mesh), landmarks, holes, closed);
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
