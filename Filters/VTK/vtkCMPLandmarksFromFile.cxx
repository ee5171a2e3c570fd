#include "vtkCMPLandmarksFromFile.h"

#include "vtkCMPPolyDataBridge.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPLandmarksFromFile);

int vtkCMPLandmarksFromFile::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const std::string model = cmp::bridge::modelPrefix(input);
  if (this->LandmarkFile.empty())
  {
    vtkErrorMacro(<< model << "no landmark file set");
    return 0;
  }
  cmp::TriangleMesh mesh;
  if (cmp::Status s = cmp::bridge::toCheckedSurfaceWithBoundaries(input, mesh); !s.ok())
  {
    vtkErrorMacro(<< model << s.message());
    return 0;
  }
  const std::vector<int> fileToMeshPoint = cmp::bridge::fileToMeshPointMap(input);
  cmp::LandmarkList landmarks;
  cmp::Status status = cmp::readLandmarkFile(this->LandmarkFile, mesh, fileToMeshPoint, landmarks);
  if (status.ok())
    status = cmp::validateLandmarks(landmarks, mesh.vertexCount(), this->ExpectedLandmarkCount, true);
  if (!status.ok())
  {
    vtkErrorMacro(<< model << status.message());
    return 0;
  }
  output->ShallowCopy(input);
  cmp::bridge::setFeatureIds(output, landmarks);
  return 1;
}

void vtkCMPLandmarksFromFile::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LandmarkFile: " << this->LandmarkFile << "\n";
  os << indent << "ExpectedLandmarkCount: " << this->ExpectedLandmarkCount << "\n";
}
