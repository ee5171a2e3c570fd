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
  if (this->LandmarkFile.empty())
  {
    vtkErrorMacro("no landmark file set");
    return 0;
  }
  cmp::TriangleMesh mesh;
  if (cmp::Status s = cmp::bridge::toCheckedSurface(input, mesh); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  std::vector<int> fileToMeshPoint;
  if (vtkDataArray* map = input->GetFieldData()->GetArray(cmp::bridge::kFileToMeshPointArray))
  {
    fileToMeshPoint.resize(map->GetNumberOfTuples());
    for (vtkIdType i = 0; i < map->GetNumberOfTuples(); ++i)
      fileToMeshPoint[i] = static_cast<int>(map->GetComponent(i, 0));
  }
  cmp::LandmarkList landmarks;
  cmp::Status status = cmp::readLandmarkFile(this->LandmarkFile, mesh, fileToMeshPoint, landmarks);
  if (status.ok())
    status = cmp::validateLandmarks(landmarks, mesh.vertexCount(), this->ExpectedLandmarkCount);
  if (!status.ok())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  output->ShallowCopy(input);
  auto featureIds = vtkSmartPointer<vtkIntArray>::New();
  featureIds->SetName(cmp::bridge::kFeatureIdArray);
  const std::vector<int> values = cmp::featureIdsOf(landmarks, mesh.vertexCount());
  featureIds->SetNumberOfValues(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
    featureIds->SetValue(v, values[v]);
  output->GetPointData()->AddArray(featureIds);
  return 1;
}

void vtkCMPLandmarksFromFile::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LandmarkFile: " << this->LandmarkFile << "\n";
  os << indent << "ExpectedLandmarkCount: " << this->ExpectedLandmarkCount << "\n";
}
