#include "vtkCMPMissingLandmarkPlacer.h"

#include "vtkCMPArrayNames.h"
#include "vtkCMPCollection.h"
#include "vtkCMPPolyDataBridge.h"

#include <cmp/remesh/MissingLandmarks.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>


vtkStandardNewMacro(vtkCMPMissingLandmarkPlacer);

vtkCMPMissingLandmarkPlacer::vtkCMPMissingLandmarkPlacer()
{
  this->SetNumberOfInputPorts(2);
}

int vtkCMPMissingLandmarkPlacer::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    // The L0 the collection will be mapped over, to judge the climbs by.
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

int vtkCMPMissingLandmarkPlacer::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkCMPMissingLandmarkPlacer::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  cmp::bridge::matchOutputType(vtkDataObject::GetData(inputVector[0], 0), outputVector, 0);
  return 1;
}

int vtkCMPMissingLandmarkPlacer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  const auto fail = [&](const std::string& message) {
    vtkErrorMacro(<< message);
    output->Initialize();
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
  cmp::MissingLandmarkOptions options;
  options.baseDomainModel = this->BaseDomainModel;
  options.level = this->Level;
  options.maximumSources = this->MaximumSources;
  options.climbToTips = this->ClimbToTips;
  options.progress = [this](double f) { this->UpdateProgress(0.95 * f); };
  cmp::BaseDomain domain;
  if (vtkPolyData* domainInput = vtkPolyData::GetData(inputVector[1]))
  {
    // Open or closed: the core closes it as the other stages do.
    if (cmp::Status s = cmp::bridge::toCheckedBaseDomain(domainInput, domain); !s.ok())
      return fail("the base domain: " + s.message());
    options.domain = &domain;
  }
  cmp::MissingLandmarkReport report;
  if (cmp::Status s = cmp::placeMissingLandmarks(surfaces, landmarks, options, &report); !s.ok())
    return fail(s.message());
  for (std::size_t m = 0; m < count; ++m)
    if (!report.modelErrors[m].empty() && cmp::missingLandmarkCount(landmarks[m]) > 0)
      vtkWarningMacro(<< collection.labels[m] << "its missing features could not be placed: "
                      << report.modelErrors[m]);

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
    std::vector<int> placedIds(static_cast<std::size_t>(result->GetNumberOfPoints()), -1);
    std::vector<int> features;
    std::vector<double> spreads, climbs, tipDistortions, mappedDistortions;
    for (const cmp::PlacedLandmark& placed : report.placed)
      if (placed.model == static_cast<int>(m))
      {
        placedIds[placed.vertex] = placed.feature;
        features.push_back(placed.feature);
        spreads.push_back(placed.spread);
        climbs.push_back(placed.climbed);
        tipDistortions.push_back(placed.tipDistortion);
        mappedDistortions.push_back(placed.mappedDistortion);
      }
    result->GetPointData()->AddArray(cmp::bridge::intArray(cmp::bridge::kPlacedFeatureIdArray, placedIds));
    result->GetFieldData()->AddArray(cmp::bridge::intArray(cmp::bridge::kPlacedFeaturesArray, features));
    result->GetFieldData()->AddArray(
      cmp::bridge::valueArray<vtkDoubleArray>(cmp::bridge::kPlacedFeatureSpreadArray, spreads));
    result->GetFieldData()->AddArray(
      cmp::bridge::valueArray<vtkDoubleArray>(cmp::bridge::kPlacedFeatureClimbArray, climbs));
    result->GetFieldData()->AddArray(
      cmp::bridge::valueArray<vtkDoubleArray>(cmp::bridge::kPlacedFeatureTipDistortionArray, tipDistortions));
    result->GetFieldData()->AddArray(
      cmp::bridge::valueArray<vtkDoubleArray>(cmp::bridge::kPlacedFeatureMappedDistortionArray, mappedDistortions));
    results.push_back(result);
  }
  cmp::bridge::assembleOutput(input, output, results);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPMissingLandmarkPlacer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BaseDomainModel: " << this->BaseDomainModel << "\n";
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "MaximumSources: " << this->MaximumSources << "\n";
  os << indent << "ClimbToTips: " << this->ClimbToTips << "\n";
}
