#include "vtkCMPPolyDataBridge.h"

#include "SurfaceCheck.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

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
    mesh.triangles.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  return {};
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

Status readIntegerPointArray(vtkDataSet* input, const char* name, std::vector<int>& values)
{
  vtkDataArray* array = input ? input->GetPointData()->GetArray(name) : nullptr;
  if (!array)
    return Status::error(std::string("missing point array '") + name +
      "' (set landmarks first, e.g. with the Landmarks From File filter)");
  if (array->GetNumberOfComponents() != 1)
    return Status::error(std::string("point array '") + name + "' must have one component");
  values.resize(array->GetNumberOfTuples());
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double value = array->GetComponent(i, 0);
    if (value != static_cast<int>(value))
      return Status::error(std::string("point array '") + name + "' has a non-integer value at point " +
        std::to_string(i));
    values[i] = static_cast<int>(value);
  }
  return {};
}

} // namespace

Status readLandmarks(vtkPolyData* input, LandmarkList& landmarks)
{
  std::vector<int> featureIds;
  if (Status s = readIntegerPointArray(input, kFeatureIdArray, featureIds); !s.ok())
    return s;
  return landmarksFromFeatureIds(featureIds, landmarks);
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

void setFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

void setFieldString(vtkFieldData* fieldData, const char* name, const std::string& value)
{
  auto array = vtkSmartPointer<vtkStringArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

} // namespace cmp::bridge
