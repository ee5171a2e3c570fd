#include "vtkCMPSemiRegularRemesher.h"

#include "BaseDomainBuilder.h"
#include "LayoutValidator.h"
#include "PatchLayout.h"
#include "PatchParameterization.h"
#include "SemiRegularRemesher.h"
#include "SurfaceCheck.h"
#include "SurfaceDistance.h"
#include "vtkCMPPolyDataBridge.h"

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCMPSemiRegularRemesher);

vtkCMPSemiRegularRemesher::vtkCMPSemiRegularRemesher()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
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
  const bool multiblock = vtkMultiBlockDataSet::GetData(inputVector[0], 0) != nullptr;
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(info);
  if (multiblock && !vtkMultiBlockDataSet::SafeDownCast(output))
    info->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkMultiBlockDataSet>::New());
  else if (!multiblock && !vtkPolyData::SafeDownCast(output))
    info->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
  vtkInformation* connectivityInfo = outputVector->GetInformationObject(1);
  if (!vtkPolyData::GetData(connectivityInfo))
    connectivityInfo->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
  return 1;
}

namespace
{

constexpr const char* kBaseTriangleArray = "BaseTriangle";
constexpr const char* kBaseCoordinatesArray = "BaseCoordinates";
constexpr const char* kLevelArray = "Level";
constexpr const char* kVertexLevelArray = "VertexLevel";
constexpr const char* kNormalsArray = "Normals";

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  return array;
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
    return connectivity;
  }
};

/// The first problem the independent layout check finds, or "".
std::string layoutProblem(const cmp::LabelledSurface& surface, const cmp::BaseDomain& domain)
{
  const std::vector<std::string> problems = cmp::validateLayout(surface, cmp::toBaseTriangles(domain));
  return problems.empty() ? "" : problems.front();
}

/// Reads the surface and checks what the remesher relies on: finite
/// coordinates and a closed genus-0 manifold. Unlike the other filters it
/// accepts zero-area triangles: the straightener's cuts may leave some, and
/// a vertex placed in one still lies on the surface (they add no normal to
/// FlippedTriangles).
cmp::Status toParameterizedSurface(vtkPolyData* input, cmp::TriangleMesh& mesh)
{
  if (cmp::Status s = cmp::bridge::toTriangleMesh(input, mesh); !s.ok())
    return s;
  cmp::SurfaceCheckOptions options;
  options.checkGeometry = false;
  const cmp::SurfaceCheckResult check = cmp::checkSurface(mesh, options);
  if (!check.ok())
    return cmp::Status::error(check.message);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (!mesh.points[v].allFinite())
      return cmp::Status::error("point " + std::to_string(v) + " has a NaN or infinite coordinate");
  return {};
}

/// Reads the straightener's per-point parameterization back, checking it
/// against the surface and L0 so that the core only sees sound values.
cmp::Status readParameterization(vtkPolyData* input, int baseTriangleCount, cmp::PatchParameterization& out)
{
  vtkPointData* points = input->GetPointData();
  const vtkIdType pointCount = input->GetNumberOfPoints();
  vtkDataArray* triangles = points->GetArray(kBaseTriangleArray);
  vtkDataArray* coordinates = points->GetArray(kBaseCoordinatesArray);
  for (const auto& [array, name] : { std::pair{ triangles, kBaseTriangleArray }, std::pair{ coordinates,
                                       kBaseCoordinatesArray } })
  {
    if (!array)
      return cmp::Status::error(std::string("input has no ") + name + " point array: run Net Straightener first");
    if (array->GetNumberOfTuples() != pointCount)
      return cmp::Status::error(std::string("point array '") + name + "' has " +
        std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(pointCount) + " points");
  }
  if (triangles->GetNumberOfComponents() != 1)
    return cmp::Status::error("point array 'BaseTriangle' must have one component (it has " +
      std::to_string(triangles->GetNumberOfComponents()) + ")");
  if (coordinates->GetNumberOfComponents() != 3)
    return cmp::Status::error("point array 'BaseCoordinates' must have 3 components (it has " +
      std::to_string(coordinates->GetNumberOfComponents()) + ")");
  out = cmp::PatchParameterization{};
  out.baseTriangle.resize(pointCount);
  out.baseCoordinates.resize(pointCount);
  for (vtkIdType v = 0; v < pointCount; ++v)
  {
    const double t = triangles->GetComponent(v, 0);
    if (!(t >= 0 && t < baseTriangleCount) || t != std::floor(t))
    {
      std::ostringstream problem;
      problem << "point array 'BaseTriangle' has " << t << " at point " << v << "; it must be an L0 triangle (0.."
              << baseTriangleCount - 1 << "): was the surface parameterized over this L0?";
      return cmp::Status::error(problem.str());
    }
    out.baseTriangle[v] = static_cast<int>(t);
    std::array<double, 3>& b = out.baseCoordinates[v];
    for (int k = 0; k < 3; ++k)
      b[k] = coordinates->GetComponent(v, k);
    // Loose bounds: they catch garbage, not the straightener's rounding.
    if (!std::isfinite(b[0]) || !std::isfinite(b[1]) || !std::isfinite(b[2]) ||
      std::min({ b[0], b[1], b[2] }) < -1e-6 || std::abs(b[0] + b[1] + b[2] - 1.0) > 1e-6)
    {
      std::ostringstream problem;
      problem << "point array 'BaseCoordinates' at point " << v << " is (" << b[0] << ", " << b[1] << ", " << b[2]
              << "): not barycentric coordinates (finite, >= 0, sum 1)";
      return cmp::Status::error(problem.str());
    }
  }
  return {};
}

bool isFloating(vtkAbstractArray* array)
{
  const int type = array->GetDataType();
  return vtkArrayDownCast<vtkDataArray>(array) && (type == VTK_FLOAT || type == VTK_DOUBLE);
}

/// Point data of one remesh: every input point array carried to the remesh
/// vertices, FeatureId written anew, and the shared base-domain arrays.
void fillPointData(vtkPointData* points, vtkPointData* input, const std::vector<cmp::SurfaceSample>& samples,
  const SharedRemesh& shared)
{
  const auto vertices = static_cast<vtkIdType>(samples.size());
  for (int i = 0; i < input->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* source = input->GetAbstractArray(i);
    const char* name = source->GetName();
    // Rewritten or replaced below: FeatureId marks exactly the landmarks,
    // the base arrays are the remesh's own.
    if (name &&
      (!std::strcmp(name, cmp::bridge::kFeatureIdArray) || !std::strcmp(name, kBaseTriangleArray) ||
        !std::strcmp(name, kBaseCoordinatesArray)))
      continue;
    auto array = vtk::TakeSmartPointer(source->NewInstance());
    array->SetName(name);
    array->SetNumberOfComponents(source->GetNumberOfComponents());
    array->CopyComponentNames(source);
    array->SetNumberOfTuples(vertices);
    const int components = source->GetNumberOfComponents();
    if (isFloating(source))
    {
      auto* from = vtkArrayDownCast<vtkDataArray>(source);
      auto* to = vtkArrayDownCast<vtkDataArray>(array);
      for (vtkIdType v = 0; v < vertices; ++v)
        for (int c = 0; c < components; ++c)
        {
          double value = 0.0;
          for (int k = 0; k < 3; ++k)
            if (samples[v].vertex[k] >= 0)
              value += samples[v].weight[k] * from->GetComponent(samples[v].vertex[k], c);
          to->SetComponent(v, c, value);
        }
    }
    else
    {
      // Labels, ids (vtkOriginalPointIds), masks and strings: averaging
      // them means nothing, so take the value of the input point the remesh
      // vertex is closest to in weight.
      for (vtkIdType v = 0; v < vertices; ++v)
      {
        const auto& w = samples[v].weight;
        const int nearest = static_cast<int>(std::max_element(w.begin(), w.end()) - w.begin());
        array->SetTuple(v, samples[v].vertex[nearest], source);
      }
    }
    const int attribute = input->IsArrayAnAttribute(i);
    const bool normals = attribute == vtkDataSetAttributes::NORMALS || (name && !std::strcmp(name, kNormalsArray));
    if (normals && isFloating(source) && components == 3)
    {
      auto* to = vtkArrayDownCast<vtkDataArray>(array);
      for (vtkIdType v = 0; v < vertices; ++v)
      {
        double n[3];
        to->GetTuple(v, n);
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length > 0.0)
          to->SetTuple3(v, n[0] / length, n[1] / length, n[2] / length);
      }
    }
    const int index = points->AddArray(array);
    // Global and pedigree ids must be unique: copied ids are not, so they
    // stay ordinary arrays.
    if (attribute >= 0 && attribute != vtkDataSetAttributes::GLOBALIDS &&
      attribute != vtkDataSetAttributes::PEDIGREEIDS)
      points->SetActiveAttribute(index, attribute);
  }

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
}

/// Unit normal of triangle (a, b, c); zero for a degenerate one.
cmp::Vec3 unitNormal(const cmp::Vec3& a, const cmp::Vec3& b, const cmp::Vec3& c)
{
  const cmp::Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0.0 ? cmp::Vec3(n / length) : cmp::Vec3::Zero();
}

/// Shape of the remesh and its orientation against the input surface.
struct RemeshQuality
{
  int flippedTriangles = 0;
  double minimumAngleDegrees = 0.0;
  double meanShapeQuality = 0.0;
};

RemeshQuality measureQuality(const cmp::SemiRegularMesh& remesh, const std::vector<cmp::Vec3>& positions,
  const std::vector<cmp::SurfaceSample>& samples, const cmp::EditableMesh& surface)
{
  RemeshQuality quality;
  double minimumAngle = M_PI, qualitySum = 0.0;
  for (const cmp::Triangle& tri : remesh.triangles)
  {
    const cmp::Vec3 &a = positions[tri[0]], &b = positions[tri[1]], &c = positions[tri[2]];
    for (int k = 0; k < 3; ++k)
    {
      const cmp::Vec3 e1 = positions[tri[(k + 1) % 3]] - positions[tri[k]];
      const cmp::Vec3 e2 = positions[tri[(k + 2) % 3]] - positions[tri[k]];
      minimumAngle = std::min(minimumAngle, std::atan2(e1.cross(e2).norm(), e1.dot(e2)));
    }
    qualitySum += cmp::triangleShapeQuality(a, b, c);
    // The input's normal under the triangle: the sum of the unit normals of
    // the input triangles its vertices lie in (landmarks record none).
    cmp::Vec3 under = cmp::Vec3::Zero();
    for (int v : tri)
    {
      const cmp::SurfaceSample& s = samples[v];
      if (s.vertex[1] >= 0)
        under += unitNormal(surface.point(s.vertex[0]), surface.point(s.vertex[1]), surface.point(s.vertex[2]));
    }
    quality.flippedTriangles += (b - a).cross(c - a).dot(under) < 0.0;
  }
  quality.minimumAngleDegrees = minimumAngle * 180.0 / M_PI;
  quality.meanShapeQuality = qualitySum / std::max<std::size_t>(1, remesh.triangles.size());
  return quality;
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
    : domain_(domain)
    , input_(input)
  {
  }
  ModelRemesher(const ModelRemesher&) = delete;
  ModelRemesher& operator=(const ModelRemesher&) = delete;

  const cmp::ParameterizedSurface& surface() const { return surface_; }

  cmp::Status prepare()
  {
    const Clock::time_point start = Clock::now();
    cmp::LandmarkList landmarks;
    std::vector<int> patchIds;
    cmp::Status status = toParameterizedSurface(input_, mesh_);
    if (status.ok())
      status = cmp::bridge::readLandmarks(input_, landmarks);
    if (status.ok())
      status = cmp::checkBaseDomain(domain_, static_cast<int>(landmarks.size()));
    if (status.ok())
      status = cmp::bridge::readPatchIds(input_, patchIds);
    if (status.ok())
      status = readParameterization(input_, domain_.mesh.triangleCount(), parameterization_);
    // The core only rebuilds a layout that is one; checking first names the
    // problem in the user's terms (for example L0 from another collection).
    if (status.ok())
      if (const std::string problem = layoutProblem(cmp::toLabelledSurface(mesh_, patchIds, landmarks), domain_);
          !problem.empty())
        status = cmp::Status::error("the input's PatchId layout is not equivalent to L0: " + problem);
    if (status.ok())
      status = cmp::layoutFromPatchIds(mesh_, patchIds, landmarks, domain_, net_);
    if (status.ok())
      if (cmp::Status built = surface_.build(net_, domain_, parameterization_); !built.ok())
        status = cmp::Status::error("cannot place the remesh on the input (BaseTriangle and BaseCoordinates do not "
                                    "fit its PatchId): " +
          built.message());
    rebuildSeconds_ = secondsSince(start);
    return status;
  }

  cmp::Status place(const SharedRemesh& shared, bool computeDistance, vtkPolyData* output,
    const std::function<void(double)>& progress)
  {
    const Clock::time_point placementStart = Clock::now();
    std::vector<cmp::SurfaceSample> samples;
    if (cmp::Status placed = cmp::placeOnSurface(shared.mesh, surface_, samples); !placed.ok())
      return cmp::Status::error("cannot place the remesh on the input (BaseTriangle and BaseCoordinates do not "
                                "fit its PatchId): " +
        placed.message());
    const std::vector<cmp::Vec3> positions = cmp::samplePositions(net_, samples);
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
    fillPointData(remesh->GetPointData(), input_->GetPointData(), samples, shared);
    remesh->GetCellData()->AddArray(shared.patchIds);
    remesh->GetCellData()->AddArray(shared.levels);
    const RemeshQuality quality = measureQuality(shared.mesh, positions, samples, net_.mesh);
    progress(0.7);

    vtkFieldData* field = remesh->GetFieldData();
    cmp::bridge::setFieldValue(field, "RemeshLevel", shared.mesh.level);
    cmp::bridge::setFieldValue(field, "VertexCount", shared.mesh.vertexCount());
    cmp::bridge::setFieldValue(field, "TriangleCount", static_cast<double>(shared.mesh.triangles.size()));
    cmp::bridge::setFieldValue(field, "FlippedTriangles", quality.flippedTriangles);
    cmp::bridge::setFieldValue(field, "MinimumAngle", quality.minimumAngleDegrees);
    cmp::bridge::setFieldValue(field, "MeanShapeQuality", quality.meanShapeQuality);
    cmp::bridge::setFieldValue(field, "RebuildSeconds", rebuildSeconds_);
    cmp::bridge::setFieldValue(field, "PlacementSeconds", placementSeconds);
    if (computeDistance)
    {
      // Sampled both ways: input to remesh catches features the remesh cuts
      // off, remesh to input catches triangles spanning concave regions.
      const Clock::time_point distanceStart = Clock::now();
      const cmp::SurfaceDistance distance =
        cmp::surfaceDistance(mesh_, cmp::TriangleMesh{ positions, shared.mesh.triangles });
      const double hausdorff = distance.hausdorff();
      const double diagonal = cmp::boundingBoxDiagonal(mesh_);
      cmp::bridge::setFieldValue(field, "HausdorffDistance", hausdorff);
      cmp::bridge::setFieldValue(field, "HausdorffDistanceRelative", diagonal > 0.0 ? hausdorff / diagonal : 0.0);
      cmp::bridge::setFieldValue(field, "MeanDistance", 0.5 * (distance.meanAToB + distance.meanBToA));
      cmp::bridge::setFieldValue(field, "DistanceSeconds", secondsSince(distanceStart));
    }
    cmp::bridge::setFieldValue(field, "TotalSeconds", rebuildSeconds_ + secondsSince(placementStart));
    output->ShallowCopy(remesh);
    progress(1.0);
    return {};
  }

private:
  const cmp::BaseDomain& domain_;
  vtkPolyData* input_ = nullptr;
  cmp::TriangleMesh mesh_;
  cmp::TracedNet net_;
  cmp::PatchParameterization parameterization_;
  cmp::ParameterizedSurface surface_;
  double rebuildSeconds_ = 0.0;
};

/// "block 2 ('387')" for messages about the surface at `index` (counting
/// the multiblock's surfaces from 0 in traversal order).
std::string blockName(vtkDataObjectTreeIterator* it, int index)
{
  std::string text = "block " + std::to_string(index);
  vtkInformation* meta = it->HasCurrentMetaData() ? it->GetCurrentMetaData() : nullptr;
  if (meta && meta->Has(vtkCompositeDataSet::NAME()))
    text += std::string(" ('") + meta->Get(vtkCompositeDataSet::NAME()) + "')";
  return text;
}

} // namespace

int vtkCMPSemiRegularRemesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* baseInput = vtkPolyData::GetData(inputVector[1]);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkPolyData* connectivityOutput = vtkPolyData::GetData(outputVector, 1);
  if (!baseInput)
  {
    vtkErrorMacro("no base domain: connect L0 (the one the surfaces were parameterized over) to the second input");
    return 0;
  }
  if (this->Level < 0 || this->Level > 8)
  {
    vtkErrorMacro("Level must be between 0 and 8 (it is " << this->Level << ")");
    return 0;
  }
  if (!(this->AdaptiveTolerance >= 0.0) || !std::isfinite(this->AdaptiveTolerance))
  {
    vtkErrorMacro("AdaptiveTolerance must be 0 (uniform) or a positive fraction of the bounding-box diagonal (it is "
      << this->AdaptiveTolerance << ")");
    return 0;
  }
  cmp::BaseDomain domain;
  if (cmp::Status status = cmp::bridge::toBaseDomain(baseInput, domain); !status.ok())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }

  // The surfaces to remesh: the input itself, or every leaf of a multiblock.
  auto* multiblockInput = vtkMultiBlockDataSet::SafeDownCast(input);
  auto* multiblockOutput = vtkMultiBlockDataSet::SafeDownCast(output);
  vtkSmartPointer<vtkDataObjectTreeIterator> leaves;
  std::vector<std::unique_ptr<ModelRemesher>> models;
  std::vector<std::string> names;
  if (multiblockInput)
  {
    if (!multiblockOutput)
    {
      vtkErrorMacro("internal error: the output for a multiblock input is not a multiblock");
      return 0;
    }
    leaves = vtk::TakeSmartPointer(multiblockInput->NewTreeIterator());
    leaves->SkipEmptyNodesOn();
    int index = 0;
    for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem(), ++index)
    {
      auto* surface = vtkPolyData::SafeDownCast(leaves->GetCurrentDataObject());
      if (!surface)
      {
        vtkErrorMacro(<< blockName(leaves, index) << ": is a " << leaves->GetCurrentDataObject()->GetClassName()
                      << ", not a vtkPolyData surface");
        multiblockOutput->Initialize();
        return 0;
      }
      models.push_back(std::make_unique<ModelRemesher>(domain, surface));
      names.push_back(blockName(leaves, index) + ": ");
    }
    if (models.empty())
    {
      vtkErrorMacro("the input multiblock holds no surfaces");
      return 0;
    }
  }
  else if (!vtkPolyData::SafeDownCast(input) || !vtkPolyData::SafeDownCast(output))
  {
    vtkErrorMacro("input 0 must be a vtkPolyData or a vtkMultiBlockDataSet of them");
    return 0;
  }
  else
  {
    models.push_back(std::make_unique<ModelRemesher>(domain, vtkPolyData::SafeDownCast(input)));
    names.emplace_back();
  }

  const auto fail = [&](const std::string& message)
  {
    vtkErrorMacro(<< message);
    output->Initialize();
    return 0;
  };
  const double modelCount = static_cast<double>(models.size());
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    if (cmp::Status status = models[m]->prepare(); !status.ok())
      return fail(names[m] + status.message());
    this->UpdateProgress(0.3 * (m + 1) / modelCount);
  }

  // One connectivity for the whole collection: with a tolerance, a triangle
  // is split when any model needs it.
  SharedRemesh shared;
  cmp::Status status;
  if (this->AdaptiveTolerance > 0.0)
  {
    std::vector<const cmp::ParameterizedSurface*> surfaces;
    for (const auto& model : models)
      surfaces.push_back(&model->surface());
    status = cmp::buildAdaptiveSemiRegularMesh(
      domain, this->Level, cmp::flatnessSplitRule(surfaces, this->AdaptiveTolerance), shared.mesh);
  }
  else
    status = cmp::buildSemiRegularMesh(domain, this->Level, shared.mesh);
  if (!status.ok())
    return fail(status.message());
  vtkSmartPointer<vtkPolyData> connectivity = shared.build(domain);
  this->UpdateProgress(0.4);

  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    results.push_back(vtkSmartPointer<vtkPolyData>::New());
    const auto progress = [this, m, modelCount](double f) { this->UpdateProgress(0.4 + 0.6 * (m + f) / modelCount); };
    if (cmp::Status placed = models[m]->place(shared, this->ComputeDistance, results.back(), progress); !placed.ok())
      return fail(names[m] + placed.message());
  }
  if (multiblockInput)
  {
    multiblockOutput->CopyStructure(multiblockInput); // same tree, names and other block metadata
    std::size_t m = 0;
    for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
      multiblockOutput->SetDataSet(leaves, results[m++]);
  }
  else
    output->ShallowCopy(results.front());
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
}
