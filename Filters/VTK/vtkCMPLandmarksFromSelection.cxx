#include "vtkCMPLandmarksFromSelection.h"

#include <cmp/io/Landmarks.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkConvertSelection.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSelection.h>
#include <vtkSelectionNode.h>
#include <vtkSmartPointer.h>

#include <string>

vtkStandardNewMacro(vtkCMPLandmarksFromSelection);

namespace
{

/// The point ids of `selection`, in the order its nodes list them.
cmp::Status selectedPointIds(vtkSelection* selection, vtkPolyData* surface, std::vector<int>& ids)
{
  ids.clear();
  for (unsigned n = 0; n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    if (node->GetFieldType() != vtkSelectionNode::POINT)
      return cmp::Status::error("the selection holds cells, not points: select points (for example with "
                                "'Interactive Select Points On' or 'Select Points On')");
  }
  // Ids stay as listed; anything else (a frustum, values, ...) becomes ids.
  vtkSmartPointer<vtkSelection> indices = selection;
  for (unsigned n = 0; n < selection->GetNumberOfNodes(); ++n)
    if (selection->GetNode(n)->GetContentType() != vtkSelectionNode::INDICES)
    {
      indices = vtkSmartPointer<vtkSelection>::Take(vtkConvertSelection::ToIndexSelection(selection, surface));
      break;
    }
  for (unsigned n = 0; indices && n < indices->GetNumberOfNodes(); ++n)
  {
    vtkAbstractArray* list = indices->GetNode(n)->GetSelectionList();
    auto* values = vtkDataArray::SafeDownCast(list);
    for (vtkIdType i = 0; values && i < values->GetNumberOfTuples(); ++i)
      ids.push_back(static_cast<int>(values->GetComponent(i, 0)));
  }
  return {};
}

} // namespace

vtkCMPLandmarksFromSelection::vtkCMPLandmarksFromSelection()
{
  this->SetNumberOfInputPorts(2);
}

void vtkCMPLandmarksFromSelection::SetPointIds(const std::vector<int>& ids)
{
  if (ids != this->PointIds)
  {
    this->PointIds = ids;
    this->Modified();
  }
}

void vtkCMPLandmarksFromSelection::AddPointId(int id)
{
  this->PointIds.push_back(id);
  this->Modified();
}

void vtkCMPLandmarksFromSelection::RemoveAllPointIds()
{
  if (!this->PointIds.empty())
  {
    this->PointIds.clear();
    this->Modified();
  }
}

int vtkCMPLandmarksFromSelection::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkSelection");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

int vtkCMPLandmarksFromSelection::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkSelection* selection = vtkSelection::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const std::string model = cmp::bridge::modelPrefix(input);
  cmp::TriangleMesh mesh;
  if (cmp::Status s = cmp::bridge::toCheckedSurfaceWithBoundaries(input, mesh); !s.ok())
  {
    vtkErrorMacro(<< model << s.message());
    return 0;
  }
  cmp::LandmarkList landmarks = this->PointIds;
  if (landmarks.empty())
  {
    if (!selection)
    {
      vtkErrorMacro(<< model << "no landmarks: select the landmark points (in order) or give PointIds");
      return 0;
    }
    if (cmp::Status s = selectedPointIds(selection, input, landmarks); !s.ok())
    {
      vtkErrorMacro(<< model << s.message());
      return 0;
    }
    if (landmarks.empty())
    {
      vtkErrorMacro(
        << model << "the selection holds no points: select the landmark points (in order) or give PointIds");
      return 0;
    }
  }
  if (cmp::Status s = cmp::validateLandmarks(landmarks, mesh.vertexCount(), this->ExpectedLandmarkCount); !s.ok())
  {
    vtkErrorMacro(<< model << s.message());
    return 0;
  }
  output->ShallowCopy(input);
  cmp::bridge::setFeatureIds(output, landmarks);
  return 1;
}

void vtkCMPLandmarksFromSelection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PointIds:";
  for (int id : this->PointIds)
    os << " " << id;
  os << "\n" << indent << "ExpectedLandmarkCount: " << this->ExpectedLandmarkCount << "\n";
}
