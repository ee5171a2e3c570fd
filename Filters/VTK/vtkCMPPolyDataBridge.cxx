#include "vtkCMPPolyDataBridge.h"

#include <cmath>

#include <cmp/mesh/SurfaceCheck.h>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <unordered_map>

namespace cmp::bridge
{

Status toTriangleMesh(vtkPolyData* input, TriangleMesh& mesh)
{
  mesh = TriangleMesh{};
  if (!input)
    return Status::error("no input surface");
  const vtkIdType others = input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfStrips();
  if (others > 0)
    return Status::error("the surface has " + std::to_string(others) +
      " vertex, line or strip cells; only triangles are accepted (apply Triangulate and Extract Surface first)");
  const vtkIdType pointCount = input->GetNumberOfPoints();
  mesh.points.resize(pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
    input->GetPoint(i, mesh.points[i].data());
  vtkCellArray* polys = input->GetPolys();
  mesh.triangles.reserve(polys->GetNumberOfCells());
  auto cells = ::vtk::TakeSmartPointer(polys->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    if (size != 3)
      return Status::error("cell " + std::to_string(cells->GetCurrentCellId()) + " is a polygon with " +
        std::to_string(size) + " points; only triangles are accepted (apply Triangulate first)");
    // VTK's readers take a file's connectivity as it is: an id out of range
    // would be read past the points by every stage after this one.
    for (int k = 0; k < 3; ++k)
      if (ids[k] < 0 || ids[k] >= pointCount)
        return Status::error("cell " + std::to_string(cells->GetCurrentCellId()) + " refers to point " +
          std::to_string(ids[k]) + ", but the surface has " + std::to_string(pointCount) + " points");
    mesh.triangles.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  return {};
}

Status toCheckedSurfaceWithBoundaries(vtkPolyData* input, TriangleMesh& mesh)
{
  if (Status s = toTriangleMesh(input, mesh); !s.ok())
    return s;
  return checkSurfaceWithBoundaries(mesh);
}

Status toCheckedSurface(vtkPolyData* input, TriangleMesh& mesh)
{
  if (Status s = toTriangleMesh(input, mesh); !s.ok())
    return s;
  const SurfaceCheckResult check = checkSurface(mesh);
  return check.ok() ? Status{} : Status::error(check.message);
}

namespace
{

/// Reads a one-component integer array; `kind` is "point" or "cell" and
/// `hint` says how to get the array when it is missing.
Status readIntegerArray(vtkDataArray* array, const std::string& kind, const char* name, const char* hint,
  std::vector<int>& values)
{
  if (!array)
    return Status::error("missing " + kind + " array '" + name + "' (" + hint + ")");
  if (array->GetNumberOfComponents() != 1)
    return Status::error(kind + " array '" + name + "' must have one component");
  values.resize(array->GetNumberOfTuples());
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double value = array->GetComponent(i, 0);
    if (value != static_cast<int>(value))
      return Status::error(kind + " array '" + name + "' has a non-integer value at " + kind + " " +
        std::to_string(i));
    values[i] = static_cast<int>(value);
  }
  return {};
}

Status readIntegerPointArray(vtkDataSet* input, const char* name, std::vector<int>& values)
{
  return readIntegerArray(input ? input->GetPointData()->GetArray(name) : nullptr, "point", name,
    "set landmarks first, e.g. with the Landmarks From File filter", values);
}

} // namespace

Status readLandmarks(vtkPolyData* input, LandmarkList& landmarks, bool allowMissing)
{
  std::vector<int> featureIds;
  if (Status s = readIntegerPointArray(input, kFeatureIdArray, featureIds); !s.ok())
    return s;
  return landmarksFromFeatureIds(featureIds, landmarks, featureCountOf(input), allowMissing);
}

int featureCountOf(vtkDataObject* data)
{
  vtkDataArray* count = data ? data->GetFieldData()->GetArray(kFeatureCountArray) : nullptr;
  if (!count || count->GetNumberOfTuples() != 1 || count->GetNumberOfComponents() != 1)
    return -1;
  const double value = count->GetTuple1(0);
  return std::isfinite(value) && value >= 0 && value <= 1e9 ? static_cast<int>(value) : -1;
}

Status readPatchIds(vtkPolyData* input, std::vector<int>& patchIds)
{
  if (Status s = readIntegerArray(input ? input->GetCellData()->GetArray(kPatchIdArray) : nullptr, "cell",
        kPatchIdArray, "connect the Surface output of Feature Net Tracer", patchIds);
      !s.ok())
    return s;
  if (static_cast<vtkIdType>(patchIds.size()) != input->GetNumberOfCells())
    return Status::error("cell array 'PatchId' has " + std::to_string(patchIds.size()) + " values for " +
      std::to_string(input->GetNumberOfCells()) + " triangles");
  return {};
}

Status toBaseDomain(vtkPolyData* input, BaseDomain& domain, int landmarkCount)
{
  domain = BaseDomain{};
  if (!input || input->GetNumberOfPoints() == 0)
    return Status::error("the base domain is empty");
  if (Status s = toTriangleMesh(input, domain.mesh); !s.ok())
    return Status::error("base domain: " + s.message());
  if (Status s = readIntegerPointArray(input, kFeatureIdArray, domain.featureIds); !s.ok())
    return Status::error("base domain: " + s.message());
  return checkBaseDomain(domain, landmarkCount);
}

Status toClosedBaseDomain(vtkPolyData* input, BaseDomain& domain, BaseDomainHoles& holes, int landmarkCount)
{
  domain = BaseDomain{};
  holes = BaseDomainHoles{};
  if (!input || input->GetNumberOfPoints() == 0)
    return Status::error("the base domain is empty");
  BaseDomain open;
  if (Status s = toTriangleMesh(input, open.mesh); !s.ok())
    return Status::error("base domain: " + s.message());
  if (Status s = readIntegerPointArray(input, kFeatureIdArray, open.featureIds); !s.ok())
    return Status::error("base domain: " + s.message());
  if (landmarkCount >= 0 && open.mesh.vertexCount() != landmarkCount)
    return Status::error("base domain has " + std::to_string(open.mesh.vertexCount()) +
      " vertices but the surface has " + std::to_string(landmarkCount) + " landmarks; they must match one to one");
  return closeBaseDomain(open, domain, holes);
}

Status toCheckedBaseDomain(vtkPolyData* input, BaseDomain& domain)
{
  BaseDomainHoles holes;
  if (Status s = toClosedBaseDomain(input, domain, holes); !s.ok())
    return s;
  // The closed L0 starts with the open one's vertices and triangles.
  domain.mesh.points.resize(holes.openVertexCount);
  domain.featureIds.resize(holes.openVertexCount);
  domain.mesh.triangles.resize(holes.openTriangleCount);
  return {};
}

Status toClosedSurface(TriangleMesh checked, const LandmarkList& landmarks, const BaseDomainHoles& holes,
  ClosedSurface& out, const SurfaceCheckOptions& capped)
{
  out = ClosedSurface{};
  out.open = std::move(checked);
  if (Status s = closeSurface(out.open, landmarks, holes, out.closed, out.closedLandmarks, out.holes); !s.ok())
    return s;
  if (holes.empty())
    return {}; // closed as given, and checked
  const SurfaceCheckResult check = checkSurface(out.closed, capped);
  if (!check.ok())
    return Status::error(check.message + " (the surface with its boundary loops capped)");
  return {};
}

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertexCount());
  for (int i = 0; i < mesh.vertexCount(); ++i)
    points->SetPoint(i, mesh.points[i].data());
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(mesh.triangleCount() + 1);
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(mesh.triangleCount()));
  for (int t = 0; t <= mesh.triangleCount(); ++t)
    offsets->SetValue(t, 3 * static_cast<vtkIdType>(t));
  for (int t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      connectivity->SetValue(3 * static_cast<vtkIdType>(t) + k, mesh.triangles[t][k]);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, connectivity);
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(points);
  output->SetPolys(polys);
  return output;
}

vtkSmartPointer<vtkPolyData> toPolyData(const BaseDomain& domain)
{
  vtkSmartPointer<vtkPolyData> output = toPolyData(domain.mesh);
  auto featureIds = vtkSmartPointer<vtkIntArray>::New();
  featureIds->SetName(kFeatureIdArray);
  featureIds->SetNumberOfValues(static_cast<vtkIdType>(domain.featureIds.size()));
  for (std::size_t i = 0; i < domain.featureIds.size(); ++i)
    featureIds->SetValue(static_cast<vtkIdType>(i), domain.featureIds[i]);
  output->GetPointData()->AddArray(featureIds);
  return output;
}

vtkSmartPointer<vtkPolyData> toPolyLines(const TracedNet& net, const BaseDomain& domain)
{
  return toPolyLines(net, domain, BaseDomainHoles{});
}

vtkSmartPointer<vtkPolyData> toPolyLines(const TracedNet& net, const BaseDomain& domain, const BaseDomainHoles& holes)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  std::unordered_map<int, vtkIdType> pointOf; // curves share their landmarks
  const auto onCap = [&](int e) {
    return !holes.empty() && (domain.featureIds[net.baseEdges[e][0]] >= holes.openVertexCount ||
                               domain.featureIds[net.baseEdges[e][1]] >= holes.openVertexCount);
  };
  vtkIdType edges = 0;
  for (std::size_t e = 0; e < net.curves.size(); ++e)
    edges += onCap(static_cast<int>(e)) ? 0 : 1;
  const auto intArray = [edges](const char* name)
  {
    auto array = vtkSmartPointer<vtkIntArray>::New();
    array->SetName(name);
    array->SetNumberOfValues(edges);
    return array;
  };
  auto baseEdgeIds = intArray(kBaseEdgeIdArray);
  auto featureA = intArray(kFeatureIdAArray);
  auto featureB = intArray(kFeatureIdBArray);
  vtkIdType cell = 0;
  for (int edge = 0; edge < static_cast<int>(net.curves.size()); ++edge)
  {
    if (onCap(edge))
      continue;
    const vtkIdType e = cell++;
    const auto& curve = net.curves[edge];
    lines->InsertNextCell(static_cast<vtkIdType>(curve.size()));
    for (int v : curve)
    {
      auto [it, inserted] = pointOf.emplace(v, points->GetNumberOfPoints());
      if (inserted)
        points->InsertNextPoint(net.mesh.point(v).data());
      lines->InsertCellPoint(it->second);
    }
    baseEdgeIds->SetValue(e, edge);
    featureA->SetValue(e, domain.featureIds[net.baseEdges[edge][0]]);
    featureB->SetValue(e, domain.featureIds[net.baseEdges[edge][1]]);
  }
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(baseEdgeIds);
  output->GetCellData()->AddArray(featureA);
  output->GetCellData()->AddArray(featureB);
  return output;
}

vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

void setFeatureIds(vtkPolyData* surface, const LandmarkList& landmarks)
{
  surface->GetPointData()->AddArray(
    intArray(kFeatureIdArray, featureIdsOf(landmarks, static_cast<int>(surface->GetNumberOfPoints()))));
  surface->GetFieldData()->AddArray(intArray(kFeatureCountArray, { static_cast<int>(landmarks.size()) }));
}

std::vector<int> fileToMeshPointMap(vtkPolyData* surface)
{
  std::vector<int> map;
  if (vtkDataArray* array = surface->GetFieldData()->GetArray(kFileToMeshPointArray))
  {
    map.resize(array->GetNumberOfTuples());
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      map[i] = static_cast<int>(array->GetComponent(i, 0));
  }
  return map;
}

void setFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

void setFieldTuple(vtkFieldData* fieldData, const char* name, const Vec3& value)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->InsertNextTuple(value.data());
  fieldData->AddArray(array);
}

void setFieldString(vtkFieldData* fieldData, const char* name, const std::string& value)
{
  auto array = vtkSmartPointer<vtkStringArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

namespace
{

/// The value of `data`'s SourceFile field array, "" if it has none.
std::string sourceFileOf(vtkDataObject* data)
{
  vtkFieldData* field = data ? data->GetFieldData() : nullptr;
  auto* name = vtkStringArray::SafeDownCast(field ? field->GetAbstractArray(kSourceFileArray) : nullptr);
  return name && name->GetNumberOfValues() > 0 ? name->GetValue(0) : std::string();
}

} // namespace

std::string modelPrefix(vtkDataObject* data)
{
  const std::string name = sourceFileOf(data);
  return name.empty() ? name : name + ": ";
}

void copySourceFile(vtkDataObject* from, vtkDataObject* to)
{
  // A new array rather than the input's, so that nothing done to the output
  // reaches upstream data.
  if (const std::string name = sourceFileOf(from); !name.empty() && to)
    setFieldString(to->GetFieldData(), kSourceFileArray, name);
}

void interpolateCornerTCoords(vtkDataArray* corners, vtkDataArray* inputCorners, const TriangleMesh& input,
  int pieces, const std::function<int(int)>& homeOf, const std::function<SurfacePoint(int, int)>& cornerPoint)
{
  for (int t = 0; t < pieces; ++t)
  {
    const int home = homeOf(t);
    const Triangle& homeCorners = input.triangles[home];
    double values[6] = { 0, 0, 0, 0, 0, 0 };
    bool inside = true;
    for (int c = 0; c < 3 && inside; ++c)
    {
      const SurfacePoint at = cornerPoint(t, c);
      inside = at.supportSize() > 0;
      for (int k = 0; k < 3 && inside; ++k)
      {
        if (at.vertex[k] < 0)
          continue;
        const auto corner = std::find(homeCorners.begin(), homeCorners.end(), at.vertex[k]);
        inside = corner != homeCorners.end();
        if (inside)
          for (int uv = 0; uv < 2; ++uv)
            values[2 * c + uv] +=
              at.weight[k] * inputCorners->GetComponent(home, 2 * static_cast<int>(corner - homeCorners.begin()) + uv);
      }
    }
    // A corner outside its home triangle would break the caller's contract;
    // the copied values are then kept rather than extrapolated.
    if (inside)
      for (int i = 0; i < 6; ++i)
        corners->SetComponent(t, i, values[i]);
  }
}

} // namespace cmp::bridge
