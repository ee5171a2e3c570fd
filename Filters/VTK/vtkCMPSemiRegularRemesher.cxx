#include "vtkCMPSemiRegularRemesher.h"

#include <cmp/remesh/FoldRepair.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/remesh/SampleRelaxation.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/SurfaceDistance.h>
#include <cmp/mesh/TriangleShape.h>
#include "vtkCMPCollection.h"
#include "vtkCMPControllerCommunicator.h"
#include "vtkCMPParameterizedInput.h"
#include "vtkCMPPolyDataBridge.h"

#include <Eigen/Geometry>

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
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
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


/// What every model's remesh shares: the connectivity and the arrays that
/// depend only on L0 and the level. Built once; the outputs share the VTK
/// objects (the same cell array, byte for byte).
struct SharedRemesh
{
  cmp::SemiRegularMesh mesh;
  vtkSmartPointer<vtkCellArray> polys;
  vtkSmartPointer<vtkIntArray> patchIds, levels, baseTriangles, vertexLevels;
  vtkSmartPointer<vtkDoubleArray> baseCoordinates;
  std::vector<int> featureIds; ///< f at vertex f, -1 elsewhere.
  std::vector<int> nearestLandmark; ///< Per triangle, for FoldsNearFeature.
  int relaxationRounds = 0;         ///< Sample relaxation rounds made.
  double relaxationSeconds = 0.0;   ///< Their time (the whole collection's).

  /// The relaxation's figures, on every output.
  void describeRelaxation(vtkFieldData* field) const
  {
    cmp::bridge::setFieldValue(field, "SampleRelaxationRounds", relaxationRounds);
    cmp::bridge::setFieldValue(field, "SampleRelaxationSeconds", relaxationSeconds);
  }

  /// Output 1: the connectivity drawn on L0.
  vtkSmartPointer<vtkPolyData> build(const cmp::BaseDomain& domain)
  {
    const int vertices = mesh.vertexCount();
    cmp::TriangleMesh drawn;
    drawn.points.reserve(vertices);
    for (const cmp::BaseLocation& at : mesh.locations)
    {
      cmp::Vec3 p = cmp::Vec3::Zero();
      for (int k = 0; k < 3; ++k)
        p += at.coordinates[k] * domain.mesh.points[domain.mesh.triangles[at.triangle][k]];
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
      baseCoordinates->SetTypedTuple(v, mesh.locations[v].coordinates.data());
    }
    baseTriangles = intArray(kBaseTriangleArray, triangles);
    featureIds.assign(vertices, -1);
    for (int f = 0; f < domain.mesh.vertexCount(); ++f)
      featureIds[f] = f;
    nearestLandmark = cmp::nearestLandmarkOfTriangles(mesh, domain.mesh.vertexCount());

    vtkPointData* points = connectivity->GetPointData();
    points->AddArray(baseTriangles);
    points->AddArray(baseCoordinates);
    points->AddArray(vertexLevels);
    points->AddArray(intArray(cmp::bridge::kFeatureIdArray, featureIds));
    connectivity->GetCellData()->AddArray(patchIds);
    connectivity->GetCellData()->AddArray(levels);
    vtkFieldData* field = connectivity->GetFieldData();
    cmp::bridge::setFieldValue(field, "RemeshLevel", mesh.level);
    cmp::bridge::setFieldValue(field, "VertexCount", vertices);
    cmp::bridge::setFieldValue(field, "TriangleCount", static_cast<double>(mesh.triangles.size()));
    describeRelaxation(field);
    return connectivity;
  }
};

/// Point data of one remesh: every input point array carried to the remesh
/// vertices, FeatureId written anew, and the shared base-domain arrays.
void fillPointData(vtkPointData* points, vtkPointData* input, const std::vector<cmp::SurfaceSample>& samples,
  const SharedRemesh& shared)
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

/// Shape of the remesh and its orientation against the input surface.
struct RemeshQuality
{
  std::vector<char> folded; ///< Per triangle: faces against the surface.
  int flippedTriangles = 0;
  double minimumAngleDegrees = 0.0;
  double meanShapeQuality = 0.0;
};

RemeshQuality measureQuality(const cmp::SemiRegularMesh& remesh, const std::vector<cmp::Vec3>& positions,
  const std::vector<cmp::SurfaceSample>& samples, const cmp::EditableMesh& surface)
{
  RemeshQuality quality;
  const cmp::TriangleShapeSummary shape = cmp::measureTriangleShapes(positions, remesh.triangles);
  quality.folded = cmp::foldedTriangles(remesh, surface, samples);
  quality.flippedTriangles = static_cast<int>(std::count(quality.folded.begin(), quality.folded.end(), 1));
  quality.minimumAngleDegrees = shape.minimumAngleDegrees;
  quality.meanShapeQuality = shape.meanShapeQuality;
  return quality;
}

/// The base vertex whose landmark lies nearest to `point` (straight-line
/// distance in `distance`), -1 if the net has none.
int nearestLandmark(const cmp::TracedNet& net, const cmp::Vec3& point, double& distance)
{
  int nearest = -1;
  distance = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < net.landmarkVertex.size(); ++b)
  {
    if (net.landmarkVertex[b] < 0)
      continue;
    const double d = (net.mesh.point(net.landmarkVertex[b]) - point).norm();
    if (d < distance)
    {
      distance = d;
      nearest = static_cast<int>(b);
    }
  }
  return nearest;
}

/// The filter's work on one model, in two steps: `prepare()` rebuilds the
/// layout and its map (every model is prepared before the shared
/// connectivity is built, because adaptive refinement asks all of them),
/// `place()` puts the shared remesh on it. Not movable: the parameterized
/// surface points into the net.
class ModelRemesher
{
public:
  ModelRemesher(const cmp::BaseDomain& domain, vtkPolyData* input)
    : input_(domain, input)
  {
  }
  ModelRemesher(const ModelRemesher&) = delete;
  ModelRemesher& operator=(const ModelRemesher&) = delete;

  const cmp::ParameterizedSurface& surface() const { return input_.surface(); }

  cmp::Status prepare()
  {
    const Clock::time_point start = Clock::now();
    cmp::Status status = input_.prepare();
    rebuildSeconds_ = secondsSince(start);
    return status;
  }

  cmp::Status place(const SharedRemesh& shared, bool computeDistance, bool repairFolds, vtkPolyData* output,
    const std::function<void(double)>& progress)
  {
    const Clock::time_point placementStart = Clock::now();
    std::vector<cmp::SurfaceSample> samples;
    if (cmp::Status placed = cmp::placeOnSurface(shared.mesh, input_.surface(), samples); !placed.ok())
      return cmp::Status::error("cannot place the remesh on the input (BaseTriangle and BaseCoordinates do not "
                                "fit its PatchId): " +
        placed.message());
    cmp::FoldRepairReport repair;
    if (repairFolds)
    {
      if (cmp::Status repaired = cmp::repairFolds(shared.mesh, input_.net().mesh, samples, {}, &repair);
          !repaired.ok())
        return repaired;
    }
    const std::vector<cmp::Vec3> positions = cmp::samplePositions(input_.net(), samples);
    const double placementSeconds = secondsSince(placementStart);
    progress(0.5);

    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
    for (std::size_t v = 0; v < positions.size(); ++v)
      points->SetPoint(static_cast<vtkIdType>(v), positions[v].data());
    auto remesh = vtkSmartPointer<vtkPolyData>::New();
    remesh->SetPoints(points);
    remesh->SetPolys(shared.polys);
    fillPointData(remesh->GetPointData(), input_.input()->GetPointData(), samples, shared);
    remesh->GetCellData()->AddArray(shared.patchIds);
    remesh->GetCellData()->AddArray(shared.levels);
    const RemeshQuality quality = measureQuality(shared.mesh, positions, samples, input_.net().mesh);
    // Per model, unlike PatchId and Level: lets a user threshold the folds.
    auto folded = vtkSmartPointer<vtkUnsignedCharArray>::New();
    folded->SetName("Folded");
    folded->SetNumberOfValues(static_cast<vtkIdType>(quality.folded.size()));
    for (std::size_t t = 0; t < quality.folded.size(); ++t)
      folded->SetValue(static_cast<vtkIdType>(t), quality.folded[t]);
    remesh->GetCellData()->AddArray(folded);
    progress(0.7);

    vtkFieldData* field = remesh->GetFieldData();
    // Where folds stay after repair, the landmark to move or to add one
    // beside: one count per feature, in FeatureId order.
    const std::vector<int> foldsNear = cmp::foldsNearLandmarks(
      shared.nearestLandmark, static_cast<int>(input_.domain().featureIds.size()), quality.folded);
    auto foldsNearFeature = vtkSmartPointer<vtkIntArray>::New();
    foldsNearFeature->SetName("FoldsNearFeature");
    foldsNearFeature->SetNumberOfValues(static_cast<vtkIdType>(foldsNear.size()));
    for (std::size_t f = 0; f < foldsNear.size(); ++f)
      foldsNearFeature->SetValue(static_cast<vtkIdType>(f), foldsNear[f]);
    field->AddArray(foldsNearFeature);
    // The remesh is still that model: keep its name (never on the shared
    // connectivity output, which is no model's).
    cmp::bridge::copySourceFile(input_.input(), remesh);
    cmp::bridge::setFieldValue(field, "RemeshLevel", shared.mesh.level);
    cmp::bridge::setFieldValue(field, "VertexCount", shared.mesh.vertexCount());
    cmp::bridge::setFieldValue(field, "TriangleCount", static_cast<double>(shared.mesh.triangles.size()));
    cmp::bridge::setFieldValue(field, "FlippedTriangles", quality.flippedTriangles);
    cmp::bridge::setFieldValue(
      field, "FoldedBeforeRepair", repairFolds ? repair.foldedBefore : quality.flippedTriangles);
    cmp::bridge::setFieldValue(field, "RepairedVertices", repair.movedVertices);
    cmp::bridge::setFieldValue(field, "MinimumAngle", quality.minimumAngleDegrees);
    cmp::bridge::setFieldValue(field, "MeanShapeQuality", quality.meanShapeQuality);
    cmp::bridge::setFieldValue(field, "RebuildSeconds", rebuildSeconds_);
    shared.describeRelaxation(field);
    cmp::bridge::setFieldValue(field, "PlacementSeconds", placementSeconds);
    if (computeDistance)
    {
      // Sampled both ways: input to remesh catches features the remesh cuts
      // off, remesh to input catches triangles spanning concave regions.
      const Clock::time_point distanceStart = Clock::now();
      const cmp::SurfaceDistance distance =
        cmp::surfaceDistance(input_.mesh(), cmp::TriangleMesh{ positions, shared.mesh.triangles });
      const double hausdorff = distance.hausdorff();
      const double diagonal = cmp::boundingBoxDiagonal(input_.mesh());
      cmp::bridge::setFieldValue(field, "HausdorffDistance", hausdorff);
      cmp::bridge::setFieldValue(field, "HausdorffDistanceRelative", diagonal > 0.0 ? hausdorff / diagonal : 0.0);
      cmp::bridge::setFieldValue(field, "MeanDistance", 0.5 * (distance.meanAToB + distance.meanBToA));
      setFarthestPoint(field, distance, diagonal);
      cmp::bridge::setFieldValue(field, "DistanceSeconds", secondsSince(distanceStart));
    }
    cmp::bridge::setFieldValue(field, "TotalSeconds", rebuildSeconds_ + secondsSince(placementStart));
    output->ShallowCopy(remesh);
    progress(1.0);
    return {};
  }

private:
  /// Where the Hausdorff distance is reached, and the landmark nearest to
  /// it: a part without a landmark that the remesh misses (a tail's tip)
  /// shows up here, and a landmark there is the cure.
  void setFarthestPoint(vtkFieldData* field, const cmp::SurfaceDistance& distance, double diagonal) const
  {
    const cmp::Vec3 farthest = distance.farthestPoint();
    cmp::bridge::setFieldTuple(field, "HausdorffPoint", farthest);
    cmp::bridge::setFieldValue(field, "HausdorffPointOnInput", distance.reachedOnA() ? 1.0 : 0.0);
    double landmarkDistance = 0.0;
    const int base = nearestLandmark(input_.net(), farthest, landmarkDistance);
    cmp::bridge::setFieldValue(field, "HausdorffNearestFeature", base >= 0 ? input_.domain().featureIds[base] : -1.0);
    cmp::bridge::setFieldValue(
      field, "HausdorffFeatureDistanceRelative", base >= 0 && diagonal > 0.0 ? landmarkDistance / diagonal : 0.0);
  }

  cmp::bridge::ParameterizedInput input_;
  double rebuildSeconds_ = 0.0;
};

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
  // The properties are the same on every rank: a bad one stops them all.
  if (!cmp::isRemeshLevel(this->Level))
    return fail("Level must be between 0 and " + std::to_string(cmp::kMaximumRemeshLevel) + " (it is " +
      std::to_string(this->Level) + ")");
  if (!(this->AdaptiveTolerance >= 0.0) || !std::isfinite(this->AdaptiveTolerance))
  {
    std::ostringstream message;
    message << "AdaptiveTolerance must be 0 (uniform) or a positive fraction of the bounding-box diagonal (it is "
            << this->AdaptiveTolerance << ")";
    return fail(message.str());
  }
  if (this->SampleRelaxationIterations < 0)
    return fail("SampleRelaxationIterations must be 0 (none) or a positive number of rounds (it is " +
      std::to_string(this->SampleRelaxationIterations) + ")");

  // The inputs may differ between ranks. Relaxation sums over every rank's
  // models, so with it a rank whose input fails says so to the others
  // (agreeOnStatus) instead of leaving them waiting in the sums.
  const bool relax = this->SampleRelaxationIterations > 0;
  cmp::bridge::ControllerCommunicator communicator(this->Controller);
  cmp::BaseDomain domain;
  cmp::Status local = baseInput
    ? cmp::bridge::toBaseDomain(baseInput, domain)
    : cmp::Status::error("no base domain: connect L0 (the one the surfaces were parameterized over) to the second input");

  // The surfaces to remesh: the input itself, or every leaf of a multiblock.
  cmp::bridge::SurfaceCollection collection;
  if (local.ok())
    local = cmp::bridge::collectSurfaces(input, collection, /*allowEmpty=*/relax && communicator.size() > 1);
  std::vector<std::unique_ptr<ModelRemesher>> models;
  if (local.ok())
    for (vtkPolyData* surface : collection.surfaces)
      models.push_back(std::make_unique<ModelRemesher>(domain, surface));
  const std::vector<std::string>& names = collection.labels;
  const double modelCount = std::max<double>(1.0, static_cast<double>(models.size()));
  for (std::size_t m = 0; m < models.size() && local.ok(); ++m)
  {
    if (cmp::Status status = models[m]->prepare(); !status.ok())
      local = cmp::Status::error(names[m] + status.message());
    this->UpdateProgress(0.3 * (m + 1) / modelCount);
  }
  std::vector<const cmp::ParameterizedSurface*> surfaces;
  for (const auto& model : models)
    surfaces.push_back(&model->surface());

  // One connectivity for the whole collection: with a tolerance, a triangle
  // is split when any model needs it.
  SharedRemesh shared;
  if (local.ok())
    local = this->AdaptiveTolerance > 0.0
      ? cmp::buildAdaptiveSemiRegularMesh(
          domain, this->Level, cmp::flatnessSplitRule(surfaces, this->AdaptiveTolerance), shared.mesh)
      : cmp::buildSemiRegularMesh(domain, this->Level, shared.mesh);
  if (relax)
    local = cmp::agreeOnStatus(local, communicator);
  if (!local.ok())
    return fail(local.message());
  if (relax)
  {
    const auto start = std::chrono::steady_clock::now();
    cmp::SampleRelaxationOptions options;
    options.iterations = this->SampleRelaxationIterations;
    cmp::SampleRelaxationReport report;
    if (cmp::Status relaxed =
          cmp::relaxSampleLocations(domain, surfaces, communicator, shared.mesh, options, &report);
        !relaxed.ok())
      return fail("sample relaxation: " + relaxed.message());
    shared.relaxationRounds = report.iterations;
    shared.relaxationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  vtkSmartPointer<vtkPolyData> connectivity = shared.build(domain);
  this->UpdateProgress(0.4);

  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    results.push_back(vtkSmartPointer<vtkPolyData>::New());
    const auto progress = [this, m, modelCount](double f) { this->UpdateProgress(0.4 + 0.6 * (m + f) / modelCount); };
    if (cmp::Status placed =
          models[m]->place(shared, this->ComputeDistance, this->RepairFolds, results.back(), progress);
        !placed.ok())
      return fail(names[m] + placed.message());
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
