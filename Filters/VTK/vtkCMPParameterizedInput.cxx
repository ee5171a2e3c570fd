#include "vtkCMPParameterizedInput.h"

#include <cmp/layout/LayoutValidator.h>
#include <cmp/mesh/SurfaceCheck.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace cmp::bridge
{

namespace
{

/// Reads the surface and checks what sampling relies on: finite
/// coordinates and a closed genus-0 manifold. Zero-area triangles are
/// accepted: the straightener's cuts may leave some, and a point sampled in
/// one still lies on the surface.
Status toParameterizedSurface(vtkPolyData* input, TriangleMesh& mesh)
{
  if (Status s = toTriangleMesh(input, mesh); !s.ok())
    return s;
  SurfaceCheckOptions options;
  options.checkGeometry = false;
  const SurfaceCheckResult check = checkSurface(mesh, options);
  if (!check.ok())
    return Status::error(check.message);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (!mesh.points[v].allFinite())
      return Status::error("point " + std::to_string(v) + " has a NaN or infinite coordinate");
  return {};
}

bool isFloating(vtkAbstractArray* array)
{
  const int type = array->GetDataType();
  return vtkArrayDownCast<vtkDataArray>(array) && (type == VTK_FLOAT || type == VTK_DOUBLE);
}

void renormalize(vtkDataArray* vectors)
{
  for (vtkIdType v = 0; v < vectors->GetNumberOfTuples(); ++v)
  {
    double n[3];
    vectors->GetTuple(v, n);
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0.0)
      vectors->SetTuple3(v, n[0] / length, n[1] / length, n[2] / length);
  }
}

} // namespace

Status readParameterization(vtkPolyData* input, int baseTriangleCount, PatchParameterization& out)
{
  vtkPointData* points = input->GetPointData();
  const vtkIdType pointCount = input->GetNumberOfPoints();
  vtkDataArray* triangles = points->GetArray(kBaseTriangleArray);
  vtkDataArray* coordinates = points->GetArray(kBaseCoordinatesArray);
  for (const auto& [array, name] :
    { std::pair{ triangles, kBaseTriangleArray }, std::pair{ coordinates, kBaseCoordinatesArray } })
  {
    if (!array)
      return Status::error(std::string("input has no ") + name + " point array: run Net Straightener first");
    if (array->GetNumberOfTuples() != pointCount)
      return Status::error(std::string("point array '") + name + "' has " +
        std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(pointCount) + " points");
  }
  if (triangles->GetNumberOfComponents() != 1)
    return Status::error("point array 'BaseTriangle' must have one component (it has " +
      std::to_string(triangles->GetNumberOfComponents()) + ")");
  if (coordinates->GetNumberOfComponents() != 3)
    return Status::error("point array 'BaseCoordinates' must have 3 components (it has " +
      std::to_string(coordinates->GetNumberOfComponents()) + ")");
  out = PatchParameterization{};
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
      return Status::error(problem.str());
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
      return Status::error(problem.str());
    }
  }
  return {};
}

ParameterizedInput::ParameterizedInput(const BaseDomain& domain, vtkPolyData* input, const BaseDomainHoles* holes)
  : domain_(domain)
  , input_(input)
  , holes_(holes && !holes->empty() ? holes : nullptr)
{
}

Status ParameterizedInput::closeInput(const LandmarkList& landmarks, TriangleMesh& closed,
  LandmarkList& closedLandmarks, std::vector<int>& closedPatchIds)
{
  SurfaceCheckOptions topologyOnly;
  topologyOnly.checkGeometry = false;
  bridge::ClosedSurface surface;
  if (Status s = bridge::toClosedSurface(mesh_, landmarks, *holes_, surface, topologyOnly); !s.ok())
    return s;
  closed = std::move(surface.closed);
  closedLandmarks = std::move(surface.closedLandmarks);
  closedPatchIds = patchIds_;
  const std::vector<int> caps = capPatchIds(surface.holes, *holes_);
  closedPatchIds.insert(closedPatchIds.end(), caps.begin(), caps.end());
  // Each cap's centre is its hole's base vertex: corner 2 of the hole's
  // first triangle (closeBaseDomain() draws them (b, a, centre)).
  closedMap_ = parameterization_;
  int first = holes_->openTriangleCount;
  for (const std::vector<int>& loop : holes_->loops)
  {
    closedMap_.baseTriangle.push_back(first);
    closedMap_.baseCoordinates.push_back({ 0.0, 0.0, 1.0 });
    first += static_cast<int>(loop.size());
  }
  return {};
}

Status ParameterizedInput::prepare()
{
  LandmarkList landmarks;
  Status status;
  if (holes_)
  {
    status = toTriangleMesh(input_, mesh_);
    for (int v = 0; v < mesh_.vertexCount() && status.ok(); ++v)
      if (!mesh_.points[v].allFinite())
        status = Status::error("point " + std::to_string(v) + " has a NaN or infinite coordinate");
  }
  else
    status = toParameterizedSurface(input_, mesh_);
  if (status.ok())
    status = readLandmarks(input_, landmarks);
  if (status.ok())
    status = holes_ ? (static_cast<int>(landmarks.size()) == holes_->openVertexCount
                          ? Status{}
                          : Status::error("the surface has " + std::to_string(landmarks.size()) +
                              " landmarks but L0 has " + std::to_string(holes_->openVertexCount) + " vertices"))
                    : checkBaseDomain(domain_, static_cast<int>(landmarks.size()));
  if (status.ok())
    status = readPatchIds(input_, patchIds_);
  if (status.ok())
    status = readParameterization(input_, domain_.mesh.triangleCount(), parameterization_);
  TriangleMesh closed = mesh_;
  LandmarkList closedLandmarks = landmarks;
  std::vector<int> closedPatchIds = patchIds_;
  if (status.ok() && holes_)
    status = closeInput(landmarks, closed, closedLandmarks, closedPatchIds);
  // The core only rebuilds a layout that is one; checking first names the
  // problem in the user's terms (for example L0 from another collection).
  if (status.ok())
    if (const std::string problem = layoutProblem(toLabelledSurface(closed, closedPatchIds, closedLandmarks), domain_);
        !problem.empty())
      status = Status::error("the input's PatchId layout is not equivalent to L0: " + problem);
  if (status.ok())
    status = layoutFromPatchIds(closed, closedPatchIds, closedLandmarks, domain_, net_);
  if (status.ok())
    if (Status built = surface_.build(net_, domain_, holes_ ? closedMap_ : parameterization_); !built.ok())
      status = Status::error(
        "BaseTriangle and BaseCoordinates do not fit the input's PatchId: " + built.message());
  return status;
}

BaseDomainMesh toBaseDomainMesh(const ParameterizedInput& input)
{
  BaseDomainMesh target;
  const PatchParameterization& map = input.parameterization();
  target.locations.resize(map.baseTriangle.size());
  for (std::size_t v = 0; v < map.baseTriangle.size(); ++v)
    target.locations[v] = SurfacePoint::inTriangle(input.domain().mesh, map.baseTriangle[v], map.baseCoordinates[v]);
  target.triangles = input.mesh().triangles;
  target.patchOfTriangle = input.patchIds();
  return target;
}

void sampleArrays(vtkDataSetAttributes* output, vtkDataSetAttributes* input, const std::vector<SurfacePoint>& samples,
  const std::vector<std::string>& skip)
{
  const auto count = static_cast<vtkIdType>(samples.size());
  for (int i = 0; i < input->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* source = input->GetAbstractArray(i);
    const char* name = source->GetName();
    if (name && std::find(skip.begin(), skip.end(), name) != skip.end())
      continue;
    auto array = vtk::TakeSmartPointer(source->NewInstance());
    array->SetName(name);
    array->SetNumberOfComponents(source->GetNumberOfComponents());
    array->CopyComponentNames(source);
    array->SetNumberOfTuples(count);
    const int components = source->GetNumberOfComponents();
    if (isFloating(source))
    {
      auto* from = vtkArrayDownCast<vtkDataArray>(source);
      auto* to = vtkArrayDownCast<vtkDataArray>(array);
      for (vtkIdType v = 0; v < count; ++v)
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
      // them means nothing, so take the value of the vertex the sample is
      // closest to in weight.
      for (vtkIdType v = 0; v < count; ++v)
      {
        const auto& w = samples[v].weight;
        const int nearest = static_cast<int>(std::max_element(w.begin(), w.end()) - w.begin());
        array->SetTuple(v, samples[v].vertex[nearest], source);
      }
    }
    const int attribute = input->IsArrayAnAttribute(i);
    const bool normals = attribute == vtkDataSetAttributes::NORMALS || (name && !std::strcmp(name, kNormalsArray));
    if (normals && isFloating(source) && components == 3)
      renormalize(vtkArrayDownCast<vtkDataArray>(array));
    const int index = output->AddArray(array);
    if (attribute >= 0 && attribute != vtkDataSetAttributes::GLOBALIDS &&
      attribute != vtkDataSetAttributes::PEDIGREEIDS)
      output->SetActiveAttribute(index, attribute);
  }
}

} // namespace cmp::bridge
