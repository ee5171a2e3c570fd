#include "vtkCMPShapeBlend.h"

#include <cmp/analysis/ShapeBlend.h>
#include "vtkCMPConsistentCollection.h"
#include "vtkCMPControllerCommunicator.h"
#include "vtkCMPPolyDataBridge.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPShapeBlend);

vtkCxxSetSmartPointerMacro(vtkCMPShapeBlend, Controller, vtkMultiProcessController);

vtkMultiProcessController* vtkCMPShapeBlend::GetController()
{
  return this->Controller;
}

vtkCMPShapeBlend::vtkCMPShapeBlend()
{
  this->Controller = vtkMultiProcessController::GetGlobalController();
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

void vtkCMPShapeBlend::SetWeights(const std::vector<double>& weights)
{
  if (weights != this->Weights)
  {
    this->Weights = weights;
    this->Modified();
  }
}

void vtkCMPShapeBlend::AddWeight(double weight)
{
  this->Weights.push_back(weight);
  this->Modified();
}

void vtkCMPShapeBlend::RemoveAllWeights()
{
  if (!this->Weights.empty())
  {
    this->Weights.clear();
    this->Modified();
  }
}

int vtkCMPShapeBlend::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkCMPShapeBlend::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
  return 1;
}

int vtkCMPShapeBlend::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  cmp::bridge::ControllerCommunicator communicator(this->Controller);
  cmp::bridge::ConsistentCollection collection;
  if (cmp::Status s = cmp::bridge::readConsistentCollection(input, communicator, collection); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  if (static_cast<int>(this->Weights.size()) != collection.globalModelCount)
  {
    vtkErrorMacro("give one weight per model: " << this->Weights.size() << " weights for "
                                                 << collection.globalModelCount << " models");
    return 0;
  }
  cmp::ShapeList aligned;
  if (cmp::Status s = cmp::bridge::alignCollection(
        collection, static_cast<cmp::bridge::CollectionAlignment>(this->Alignment), communicator, aligned);
      !s.ok())
  {
    vtkErrorMacro(<< "alignment: " << s.message());
    return 0;
  }
  this->UpdateProgress(0.5);
  cmp::ShapeBlend blend;
  if (cmp::Status s = cmp::blendShapes(aligned, this->Weights, communicator, blend); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  if (blend.extrapolating)
    vtkWarningMacro("a weight lies outside [0, 1]: the blend extrapolates beyond the models");
  if (communicator.rank() != 0)
    return 1;
  vtkSmartPointer<vtkPolyData> result = cmp::bridge::toPolyData(blend.positions, collection.triangles);
  cmp::bridge::copyCorrespondenceArrays(
    collection.surfaces.surfaces.empty() ? nullptr : collection.surfaces.surfaces[0], result);
  cmp::bridge::setFieldValue(result->GetFieldData(), cmp::bridge::kExtrapolatingField, blend.extrapolating ? 1.0 : 0.0);
  auto weights = vtkSmartPointer<vtkDoubleArray>::New();
  weights->SetName(cmp::bridge::kWeightsArray);
  for (double w : this->Weights)
    weights->InsertNextValue(w);
  result->GetFieldData()->AddArray(weights);
  output->ShallowCopy(result);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPShapeBlend::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weights:";
  for (double w : this->Weights)
    os << " " << w;
  os << "\n" << indent << "Alignment: " << this->Alignment << "\n";
}
