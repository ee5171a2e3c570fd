#include "vtkCMPLandmarkWriter.h"

#include <cmp/io/Landmarks.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPLandmarkWriter);

int vtkCMPLandmarkWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkCMPLandmarkWriter::WriteData()
{
  auto* surface = vtkPolyData::SafeDownCast(this->GetInput());
  const std::string model = cmp::bridge::modelPrefix(surface);
  if (this->FileName.empty())
  {
    vtkErrorMacro("no file name set");
    return;
  }
  vtkDataArray* featureIds = surface ? surface->GetPointData()->GetArray(cmp::bridge::kFeatureIdArray) : nullptr;
  if (!featureIds)
  {
    vtkErrorMacro(<< model << "the surface has no FeatureId point array: mark its landmarks first");
    return;
  }
  cmp::TriangleMesh mesh;
  if (cmp::Status s = cmp::bridge::toTriangleMesh(surface, mesh); !s.ok())
  {
    vtkErrorMacro(<< model << s.message());
    return;
  }
  std::vector<int> values(featureIds->GetNumberOfTuples());
  for (vtkIdType v = 0; v < featureIds->GetNumberOfTuples(); ++v)
    values[v] = static_cast<int>(featureIds->GetComponent(v, 0));
  const std::vector<int> fileToMeshPoint = cmp::bridge::fileToMeshPointMap(surface);
  cmp::LandmarkList landmarks;
  // A feature missing on this model (none of its vertices carries it) is
  // written as -1.
  cmp::Status status =
    cmp::landmarksFromFeatureIds(values, landmarks, cmp::bridge::featureCountOf(surface), true);
  if (status.ok())
    status = cmp::writeLandmarkFile(this->FileName, landmarks, mesh, fileToMeshPoint);
  if (!status.ok())
    vtkErrorMacro(<< model << status.message());
}

void vtkCMPLandmarkWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
