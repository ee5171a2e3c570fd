#include "vtkCMPProtrusionCones.h"

#include "vtkCMPArrayNames.h"
#include "vtkCMPCollection.h"
#include "vtkCMPPolyDataBridge.h"

#include <cmp/layout/ProtrusionCones.h>

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>


vtkStandardNewMacro(vtkCMPProtrusionCones);

vtkCMPProtrusionCones::vtkCMPProtrusionCones()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkCMPProtrusionCones::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  // The whole collection at once: the composite pipeline must not iterate.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

int vtkCMPProtrusionCones::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkDataObject" : "vtkPolyData");
  return 1;
}

int vtkCMPProtrusionCones::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  cmp::bridge::matchOutputType(vtkDataObject::GetData(inputVector[0], 0), outputVector, 0);
  return 1;
}

int vtkCMPProtrusionCones::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkPolyData* domainOutput = vtkPolyData::GetData(outputVector, 1);
  const auto fail = [&](const std::string& message) {
    vtkErrorMacro(<< message);
    output->Initialize();
    domainOutput->Initialize();
    return 0;
  };
  cmp::bridge::SurfaceCollection collection;
  if (cmp::Status s = cmp::bridge::collectSurfaces(input, collection); !s.ok())
    return fail(s.message());
  const std::size_t count = collection.surfaces.size();
  cmp::bridge::LandmarkedCollection read;
  if (cmp::Status s = cmp::bridge::toLandmarkedCollection(collection, true, read); !s.ok())
    return fail(s.message());
  const std::vector<const cmp::TriangleMesh*>& surfaces = read.surfaces;
  std::vector<cmp::LandmarkList>& landmarks = read.landmarks;
  cmp::ProtrusionConeOptions options;
  options.leastModels = this->LeastModels;
  options.largestBallShare = this->LargestBallShare;
  options.ballScales = this->BallScales;
  cmp::BaseDomain domain;
  cmp::ProtrusionConeReport report;
  if (vtkPolyData* givenInput = vtkPolyData::GetData(inputVector[1]))
  {
    // An open L0 (surfaces with boundaries) is checked closed; the cones
    // split triangles of the open one.
    cmp::BaseDomain given;
    if (cmp::Status s = cmp::bridge::toCheckedBaseDomain(givenInput, given); !s.ok())
      return fail("the base domain: " + s.message());
    if (cmp::Status s = cmp::addProtrusionCones(surfaces, landmarks, given, domain, options, &report); !s.ok())
      return fail(s.message());
  }
  else
  {
    if (this->BaseDomainModel < 0 || this->BaseDomainModel >= static_cast<int>(count))
      return fail("BaseDomainModel is " + std::to_string(this->BaseDomainModel) + ", but the input has " +
        std::to_string(count) + " surfaces");
    if (cmp::Status s =
          cmp::addProtrusionCones(surfaces, landmarks, this->BaseDomainModel, domain, options, &report);
        !s.ok())
      return fail(collection.labels[this->BaseDomainModel] + s.message());
  }

  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (std::size_t m = 0; m < count; ++m)
  {
    auto result = vtkSmartPointer<vtkPolyData>::New();
    result->ShallowCopy(collection.surfaces[m]);
    // An own field data: the arrays added below must not reach the input.
    auto fieldData = vtkSmartPointer<vtkFieldData>::New();
    fieldData->ShallowCopy(collection.surfaces[m]->GetFieldData());
    result->SetFieldData(fieldData);
    cmp::bridge::setFeatureIds(result, landmarks[m]);
    std::vector<int> tips, roots;
    for (const cmp::Protrusion& p : report.protrusions[m])
    {
      tips.push_back(p.vertex);
      roots.push_back(p.nearestFeature);
    }
    fieldData->AddArray(cmp::bridge::intArray(cmp::bridge::kProtrusionTipsArray, tips));
    fieldData->AddArray(cmp::bridge::intArray(cmp::bridge::kProtrusionRootsArray, roots));
    results.push_back(result);
  }
  cmp::bridge::assembleOutput(input, output, results);
  domainOutput->ShallowCopy(cmp::bridge::toPolyData(domain));
  auto domainField = vtkSmartPointer<vtkFieldData>::New();
  domainField->AddArray(cmp::bridge::intArray(cmp::bridge::kProtrusionConeRootsArray, report.roots));
  auto without = vtkSmartPointer<vtkIntArray>::New();
  without->SetName(cmp::bridge::kProtrusionsWithoutConeArray);
  without->SetNumberOfComponents(2);
  for (const auto& d : report.disagreeing)
  {
    const int pair[2] = { d.root, d.model };
    without->InsertNextTypedTuple(pair);
  }
  domainField->AddArray(without);
  domainOutput->SetFieldData(domainField);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPProtrusionCones::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BaseDomainModel: " << this->BaseDomainModel << "\n";
  os << indent << "LeastModels: " << this->LeastModels << "\n";
  os << indent << "LargestBallShare: " << this->LargestBallShare << "\n";
  os << indent << "BallScales: " << this->BallScales << "\n";
}
