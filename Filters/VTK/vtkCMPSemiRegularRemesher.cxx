#include "vtkCMPSemiRegularRemesher.h"

#include <cmp/numerics/Communicator.h>
#include <cmp/remesh/Remesh.h>
#include "vtkCMPCollection.h"
#include "vtkCMPControllerCommunicator.h"
#include "vtkCMPParameterizedInput.h"
#include "vtkCMPPolyDataBridge.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCMPSemiRegularRemesher);

vtkCMPSemiRegularRemesher::vtkCMPSemiRegularRemesher()
{
  this->Controller = vtkMultiProcessController::GetGlobalController();
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkCxxSetSmartPointerMacro(vtkCMPSemiRegularRemesher, Controller, vtkMultiProcessController);

vtkMultiProcessController* vtkCMPSemiRegularRemesher::GetController()
{
  return this->Controller;
}

int vtkCMPSemiRegularRemesher::FillInputPortInformation(int port, vtkInformation* info)
{
  // The filter takes a multiblock on port 0 whole (the composite pipeline
  // does not iterate), so that the connectivity is built once and output 1
  // holds it once.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 0)
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

int vtkCMPSemiRegularRemesher::FillOutputPortInformation(int port, vtkInformation* info)
{
  // Output 0 follows input 0 (vtkPolyData or vtkMultiBlockDataSet).
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkDataObject" : "vtkPolyData");
  return 1;
}

int vtkCMPSemiRegularRemesher::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  cmp::bridge::matchOutputType(vtkDataObject::GetData(inputVector[0], 0), outputVector, 0);
  vtkInformation* connectivityInfo = outputVector->GetInformationObject(1);
  if (!vtkPolyData::GetData(connectivityInfo))
    connectivityInfo->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
  return 1;
}

namespace
{

using cmp::bridge::kBaseCoordinatesArray;
using cmp::bridge::kBaseTriangleArray;
using cmp::bridge::intArray;
using cmp::bridge::kLevelArray;
using cmp::bridge::kVertexLevelArray;

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The VTK objects every model's remesh shares: the connectivity and the
/// arrays that depend only on L0 and the level. Built once; the outputs
/// share them (the same cell array, byte for byte).
struct SharedArrays
{
  vtkSmartPointer<vtkCellArray> polys;
  vtkSmartPointer<vtkIntArray> patchIds, levels, baseTriangles, vertexLevels;
  vtkSmartPointer<vtkDoubleArray> baseCoordinates;
  std::vector<int> featureIds; ///< f at vertex f, -1 elsewhere.

  /// Output 1: the connectivity drawn on L0.
  vtkSmartPointer<vtkPolyData> build(const cmp::SemiRegularMesh& mesh, const cmp::BaseDomain& domain,
    const cmp::BaseDomainHoles& holes, const cmp::RemeshReport& report)
  {
    const int vertices = mesh.vertexCount();
    cmp::TriangleMesh drawn;
    drawn.points.reserve(vertices);
    for (const cmp::SurfacePoint& at : mesh.locations)
    {
      cmp::Vec3 p = cmp::Vec3::Zero();
      for (int k = 0; k < 3; ++k)
        p += at.weight[k] * domain.mesh.points[domain.mesh.triangles[at.triangle][k]];
      drawn.points.push_back(p);
    }
    drawn.triangles = mesh.triangles;
    vtkSmartPointer<vtkPolyData> connectivity = cmp::bridge::toPolyData(drawn);
    polys = connectivity->GetPolys();

    patchIds = intArray(cmp::bridge::kPatchIdArray, mesh.patchOfTriangle);
    // The core records each triangle's level (all equal for a uniform remesh).
    levels = intArray(kLevelArray, mesh.levelOfTriangle.size() == mesh.triangles.size()
        ? mesh.levelOfTriangle
        : std::vector<int>(mesh.triangles.size(), mesh.level));
    vertexLevels = intArray(kVertexLevelArray, mesh.levelOfVertex);
    std::vector<int> triangles(vertices);
    baseCoordinates = vtkSmartPointer<vtkDoubleArray>::New();
    baseCoordinates->SetName(kBaseCoordinatesArray);
    baseCoordinates->SetNumberOfComponents(3);
    baseCoordinates->SetNumberOfTuples(vertices);
    for (int v = 0; v < vertices; ++v)
    {
      triangles[v] = mesh.locations[v].triangle;
      baseCoordinates->SetTypedTuple(v, mesh.locations[v].weight.data());
    }
    baseTriangles = intArray(kBaseTriangleArray, triangles);
    featureIds.assign(vertices, -1);
    // An open L0's caps are left out of the remesh: its features are F first.
    const int features = holes.empty() ? domain.mesh.vertexCount() : holes.openVertexCount;
    for (int f = 0; f < features && f < vertices; ++f)
      featureIds[f] = f;

    vtkPointData* points = connectivity->GetPointData();
    points->AddArray(baseTriangles);
    points->AddArray(baseCoordinates);
    points->AddArray(vertexLevels);
    points->AddArray(intArray(cmp::bridge::kFeatureIdArray, featureIds));
    connectivity->GetCellData()->AddArray(patchIds);
    connectivity->GetCellData()->AddArray(levels);
    vtkFieldData* field = connectivity->GetFieldData();
    describeSize(field, mesh);
    describeRelaxation(field, report);
    return connectivity;
  }

  /// The remesh's size, on every output.
  static void describeSize(vtkFieldData* field, const cmp::SemiRegularMesh& mesh)
  {
    cmp::bridge::setFieldValue(field, cmp::bridge::kRemeshLevelField, mesh.level);
    cmp::bridge::setFieldValue(field, cmp::bridge::kVertexCountField, mesh.vertexCount());
    cmp::bridge::setFieldValue(field, cmp::bridge::kTriangleCountField, static_cast<double>(mesh.triangles.size()));
  }

  /// The relaxation's figures, on every output.
  static void describeRelaxation(vtkFieldData* field, const cmp::RemeshReport& report)
  {
    cmp::bridge::setFieldValue(field, cmp::bridge::kSampleRelaxationRoundsField, report.sampleRelaxationRounds);
    cmp::bridge::setFieldValue(field, cmp::bridge::kSampleRelaxationSecondsField, report.sampleRelaxationSeconds);
    cmp::bridge::setFieldValue(field, cmp::bridge::kAdaptivePassesField, report.adaptivePasses);
  }
};

/// Point data of one remesh: every input point array carried to the remesh
/// vertices, FeatureId written anew, and the shared base-domain arrays.
void fillPointData(vtkPointData* points, vtkPointData* input, const std::vector<cmp::SurfacePoint>& samples,
  const SharedArrays& shared)
{
  const auto vertices = static_cast<vtkIdType>(samples.size());
  // Rewritten or replaced below: FeatureId marks exactly the landmarks, the
  // base arrays are the remesh's own.
  cmp::bridge::sampleArrays(points, input, samples,
    { cmp::bridge::kFeatureIdArray, cmp::bridge::kBaseTriangleArray, cmp::bridge::kBaseCoordinatesArray });

  // Same array type as the input's, so readers of FeatureId see no change.
  vtkDataArray* inputFeatureIds = input->GetArray(cmp::bridge::kFeatureIdArray);
  auto featureIds = vtk::TakeSmartPointer(inputFeatureIds->NewInstance());
  featureIds->SetName(cmp::bridge::kFeatureIdArray);
  featureIds->SetNumberOfComponents(1);
  featureIds->SetNumberOfTuples(vertices);
  for (vtkIdType v = 0; v < vertices; ++v)
    featureIds->SetComponent(v, 0, shared.featureIds[v]);
  points->AddArray(featureIds);
  points->AddArray(shared.baseTriangles);
  points->AddArray(shared.baseCoordinates);
  // Lets a remesh alone say its levels (the wavelet filter needs them).
  points->AddArray(shared.vertexLevels);
}

/// One model read back from its arrays (layout and map indexed), with the
/// time that took.
struct PreparedInput
{
  PreparedInput(const cmp::BaseDomain& domain, const cmp::BaseDomainHoles& holes, vtkPolyData* surface)
    : input(domain, surface, &holes)
  {
  }
  cmp::bridge::ParameterizedInput input;
  double rebuildSeconds = 0.0;
};

/// The remesh of one model as VTK data: the core's placement and figures,
/// the input's point arrays carried over, the shared arrays added.
vtkSmartPointer<vtkPolyData> toOutput(const PreparedInput& prepared, const cmp::SemiRegularMesh& mesh,
  const cmp::RemeshedModel& placed, const cmp::RemeshModelReport& figures, const cmp::RemeshReport& report,
  const SharedArrays& shared)
{
  const Clock::time_point start = Clock::now();
  const cmp::bridge::ParameterizedInput& input = prepared.input;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(placed.positions.size()));
  for (std::size_t v = 0; v < placed.positions.size(); ++v)
    points->SetPoint(static_cast<vtkIdType>(v), placed.positions[v].data());
  auto remesh = vtkSmartPointer<vtkPolyData>::New();
  remesh->SetPoints(points);
  remesh->SetPolys(shared.polys);
  fillPointData(remesh->GetPointData(), input.input()->GetPointData(), placed.samples, shared);
  remesh->GetCellData()->AddArray(shared.patchIds);
  remesh->GetCellData()->AddArray(shared.levels);
  // Per model, unlike PatchId and Level: lets a user threshold the folds.
  remesh->GetCellData()->AddArray(
    cmp::bridge::valueArray<vtkUnsignedCharArray>(cmp::bridge::kFoldedArray, placed.folded));
  remesh->GetCellData()->AddArray(
    cmp::bridge::valueArray<vtkUnsignedCharArray>(cmp::bridge::kCentroidFlippedArray, placed.centroidFlipped));

  vtkFieldData* field = remesh->GetFieldData();
  // Where folds stay after repair, the landmark to move or to add one
  // beside: one count per feature, in FeatureId order.
  field->AddArray(intArray(cmp::bridge::kFoldsNearFeatureArray, placed.foldsNearFeature));
  // The remesh is still that model: keep its name (never on the shared
  // connectivity output, which is no model's).
  cmp::bridge::copySourceFile(input.input(), remesh);
  SharedArrays::describeSize(field, mesh);
  cmp::bridge::setFieldValue(field, cmp::bridge::kFlippedTrianglesField, figures.foldedAfterRepair);
  cmp::bridge::setFieldValue(field, cmp::bridge::kFoldedBeforeRepairField, figures.foldedBeforeRepair);
  cmp::bridge::setFieldValue(field, cmp::bridge::kCentroidFlipsField, figures.centroidFlips);
  cmp::bridge::setFieldValue(field, cmp::bridge::kRepairedVerticesField, figures.repair.movedVertices);
  cmp::bridge::setFieldValue(field, cmp::bridge::kMinimumAngleField, figures.minimumAngleDegrees);
  cmp::bridge::setFieldValue(field, cmp::bridge::kMeanShapeQualityField, figures.meanShapeQuality);
  cmp::bridge::setFieldValue(field, cmp::bridge::kRebuildSecondsField, prepared.rebuildSeconds);
  SharedArrays::describeRelaxation(field, report);
  cmp::bridge::setFieldValue(field, cmp::bridge::kPlacementSecondsField, figures.placementSeconds);
  if (figures.distanceMeasured)
  {
    cmp::bridge::setFieldValue(field, cmp::bridge::kHausdorffDistanceField, figures.hausdorffDistance);
    cmp::bridge::setFieldValue(field, cmp::bridge::kHausdorffDistanceRelativeField, figures.hausdorffDistanceRelative);
    cmp::bridge::setFieldValue(field, cmp::bridge::kMeanDistanceField, figures.meanDistance);
    cmp::bridge::setFieldTuple(field, cmp::bridge::kHausdorffPointField, figures.hausdorffPoint);
    cmp::bridge::setFieldValue(
      field, cmp::bridge::kHausdorffPointOnInputField, figures.hausdorffPointOnInput ? 1.0 : 0.0);
    cmp::bridge::setFieldValue(field, cmp::bridge::kHausdorffNearestFeatureField, figures.hausdorffNearestFeature);
    cmp::bridge::setFieldValue(
      field, cmp::bridge::kHausdorffFeatureDistanceRelativeField, figures.hausdorffFeatureDistanceRelative);
    cmp::bridge::setFieldValue(field, cmp::bridge::kDistanceSecondsField, figures.distanceSeconds);
  }
  cmp::bridge::setFieldValue(
    field, cmp::bridge::kTotalSecondsField, prepared.rebuildSeconds + figures.seconds + secondsSince(start));
  return remesh;
}

} // namespace

int vtkCMPSemiRegularRemesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* baseInput = vtkPolyData::GetData(inputVector[1]);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkPolyData* connectivityOutput = vtkPolyData::GetData(outputVector, 1);
  const auto fail = [&](const std::string& message)
  {
    vtkErrorMacro(<< message);
    output->Initialize();
    return 0;
  };
  cmp::RemeshOptions options;
  options.level = this->Level;
  options.adaptiveTolerance = this->AdaptiveTolerance;
  options.sampleRelaxationIterations = this->SampleRelaxationIterations;
  options.repairFolds = this->RepairFolds;
  options.computeDistance = this->ComputeDistance;
  options.progress = [this](double f) { this->UpdateProgress(0.3 + 0.4 * f); };
  // The properties are the same on every rank: a bad one stops them all.
  if (cmp::Status checked = cmp::checkRemeshOptions(options); !checked.ok())
    return fail(checked.message());

  // The inputs may differ between ranks. Relaxation sums over every rank's
  // models, so with it a rank whose input fails says so to the others
  // (agreeOnStatus) instead of leaving them waiting in the sums.
  const bool relax = this->SampleRelaxationIterations > 0;
  cmp::bridge::ControllerCommunicator communicator(this->Controller);
  cmp::BaseDomain domain;
  cmp::BaseDomainHoles holes;
  cmp::Status local = baseInput
    ? cmp::bridge::toClosedBaseDomain(baseInput, domain, holes)
    : cmp::Status::error("no base domain: connect L0 (the one the surfaces were parameterized over) to the second input");
  // An open L0's caps are not remeshed: the remesh's boundary lies on the surfaces'.
  options.holeTriangles = holes.holeTriangle;

  // The surfaces to remesh: the input itself, or every leaf of a multiblock.
  cmp::bridge::SurfaceCollection collection;
  if (local.ok())
    local = cmp::bridge::collectSurfaces(input, collection, /*allowEmpty=*/relax && communicator.size() > 1);
  // Not movable: each index points into its layout.
  std::vector<std::unique_ptr<PreparedInput>> prepared;
  if (local.ok())
    for (vtkPolyData* surface : collection.surfaces)
      prepared.push_back(std::make_unique<PreparedInput>(domain, holes, surface));
  const std::vector<std::string>& names = collection.labels;
  const double modelCount = std::max<double>(1.0, static_cast<double>(prepared.size()));
  for (std::size_t m = 0; m < prepared.size() && local.ok(); ++m)
  {
    const Clock::time_point start = Clock::now();
    if (cmp::Status status = prepared[m]->input.prepare(); !status.ok())
      local = cmp::Status::error(names[m] + status.message());
    prepared[m]->rebuildSeconds = secondsSince(start);
    this->UpdateProgress(0.3 * (m + 1) / modelCount);
  }
  if (relax)
    local = cmp::agreeOnStatus(local, communicator);
  if (!local.ok())
    return fail(local.message());

  // The whole stage in the core: one connectivity for the collection,
  // placed on every model, repaired and measured.
  std::vector<cmp::RemeshModel> models;
  for (const auto& model : prepared)
    models.push_back({ &model->input.mesh(), &model->input.surface() });
  cmp::CollectionRemesh remesh;
  cmp::RemeshReport report;
  if (cmp::Status status = cmp::remesh(domain, models, communicator, remesh, options, &report); !status.ok())
    return fail(report.failedModel >= 0 ? names[report.failedModel] + status.message() : status.message());

  SharedArrays shared;
  vtkSmartPointer<vtkPolyData> connectivity = shared.build(remesh.mesh, domain, holes, report);
  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (std::size_t m = 0; m < prepared.size(); ++m)
  {
    results.push_back(
      toOutput(*prepared[m], remesh.mesh, remesh.models[m], report.models[m], report, shared));
    this->UpdateProgress(0.7 + 0.3 * (m + 1) / modelCount);
  }
  cmp::bridge::assembleOutput(input, output, results);
  connectivityOutput->ShallowCopy(connectivity);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPSemiRegularRemesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "AdaptiveTolerance: " << this->AdaptiveTolerance << "\n";
  os << indent << "ComputeDistance: " << this->ComputeDistance << "\n";
  os << indent << "RepairFolds: " << this->RepairFolds << "\n";
  os << indent << "SampleRelaxationIterations: " << this->SampleRelaxationIterations << "\n";
  os << indent << "Controller: " << this->Controller.Get() << "\n";
}
