#include "vtkCMPAttributeTransfer.h"

#include <cmp/analysis/AttributeTransfer.h>
#include "vtkCMPCollection.h"
#include "vtkCMPParameterizedInput.h"
#include "vtkCMPPolyDataBridge.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCMPAttributeTransfer);

vtkCMPAttributeTransfer::vtkCMPAttributeTransfer()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(1);
}

int vtkCMPAttributeTransfer::FillInputPortInformation(int port, vtkInformation* info)
{
  // A multiblock target is taken whole: the source and L0 are prepared once.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  // Optional to the pipeline so that a missing source or L0 is reported
  // by RequestData in the user's terms.
  if (port > 0)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  if (port == 0)
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

int vtkCMPAttributeTransfer::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkCMPAttributeTransfer::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  cmp::bridge::matchOutputType(vtkDataObject::GetData(inputVector[0], 0), outputVector, 0);
  return 1;
}

namespace
{

using cmp::bridge::kTCoordsArray;
using cmp::bridge::kUnsplitPointIdArray;

/// Corners of one point whose texture coordinates differ by less (in u + v)
/// read the same texture: float storage and the corners' inset towards
/// their triangles leave differences near 1e-6, a seam jumps by a texel or more.
constexpr double kSameTextureCoordinates = 1e-5;

/// Texture coordinates of every target corner, read from the source
/// triangle each corner sample lies in (a corner sample at a landmark has
/// none: the landmark's first corner in the source is used then).
std::vector<std::array<double, 2>> cornerTextureCoordinates(
  const std::vector<cmp::SurfacePoint>& corners, vtkDataArray* sourceCorners, const cmp::TriangleMesh& source)
{
  std::vector<int> someTriangleOf(source.vertexCount(), -1);
  for (int t = 0; t < source.triangleCount(); ++t)
    for (int v : source.triangles[t])
      someTriangleOf[v] = t;
  std::vector<std::array<double, 2>> uv(corners.size(), { 0.0, 0.0 });
  for (std::size_t c = 0; c < corners.size(); ++c)
  {
    const cmp::SurfacePoint& s = corners[c];
    const int triangle = s.triangle >= 0 ? s.triangle : someTriangleOf[s.vertex[0]];
    for (int k = 0; k < 3; ++k)
    {
      if (s.vertex[k] < 0)
        continue;
      // The sample's vertices are its triangle's; find each one's corner.
      for (int corner = 0; corner < 3; ++corner)
        if (source.triangles[triangle][corner] == s.vertex[k])
          for (int i = 0; i < 2; ++i)
            uv[c][i] += s.weight[k] * sourceCorners->GetComponent(triangle, 2 * corner + i);
    }
  }
  return uv;
}

/// Appends a copy of point `copiedFrom[d]` (position and point data) as
/// point `n + d` and rebuilds the triangles with corner c at `pointOf(c)`;
/// `UnsplitPointId` gives every point's id before the split.
template <class PointOfCorner>
void splitPoints(vtkPolyData* output, const std::vector<vtkIdType>& copiedFrom, PointOfCorner pointOf)
{
  const vtkIdType pointCount = output->GetNumberOfPoints();
  const vtkIdType total = pointCount + static_cast<vtkIdType>(copiedFrom.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(output->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  vtkPointData* pointData = output->GetPointData();
  auto copied = vtkSmartPointer<vtkPointData>::New();
  copied->CopyAllocate(pointData, total);
  auto unsplit = vtkSmartPointer<vtkIdTypeArray>::New();
  unsplit->SetName(kUnsplitPointIdArray);
  unsplit->SetNumberOfTuples(total);
  for (vtkIdType p = 0; p < total; ++p)
  {
    const vtkIdType from = p < pointCount ? p : copiedFrom[p - pointCount];
    points->SetPoint(p, output->GetPoint(from));
    copied->CopyData(pointData, from, p);
    unsplit->SetValue(p, from);
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->AllocateExact(output->GetNumberOfPolys(), 3 * output->GetNumberOfPolys());
  for (vtkIdType t = 0; t < output->GetNumberOfPolys(); ++t)
  {
    const vtkIdType tri[3] = { pointOf(3 * t), pointOf(3 * t + 1), pointOf(3 * t + 2) };
    polys->InsertNextCell(3, tri);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->ShallowCopy(copied);
  output->GetPointData()->AddArray(unsplit);
}

/// Adds `CornerTCoords` (cells) and `TCoords` (points, active) to `output`.
/// With `split`, a point whose corners disagree is duplicated once per
/// further distinct value, and `UnsplitPointId` records each point's
/// target id. Returns the number of points added.
vtkIdType addTextureCoordinates(vtkPolyData* output, const std::vector<std::array<double, 2>>& uv, bool split)
{
  const vtkIdType triangleCount = output->GetNumberOfPolys();
  auto corners = vtkSmartPointer<vtkFloatArray>::New();
  corners->SetName(cmp::bridge::kCornerTCoordsArray);
  corners->SetNumberOfComponents(6);
  corners->SetNumberOfTuples(triangleCount);
  for (vtkIdType t = 0; t < triangleCount; ++t)
    for (int i = 0; i < 6; ++i)
      corners->SetComponent(t, i, uv[3 * t + i / 2][i % 2]);
  output->GetCellData()->AddArray(corners);

  // The distinct corner values at each point (the first one stays on the
  // point) and, for every corner, which of them it reads.
  const vtkIdType pointCount = output->GetNumberOfPoints();
  std::vector<std::vector<std::array<double, 2>>> valuesAt(pointCount);
  std::vector<vtkIdType> cornerPoint(3 * triangleCount);
  std::vector<int> cornerValue(3 * triangleCount, 0);
  vtkCellArray* polys = output->GetPolys();
  vtkIdType t = 0, n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids); ++t)
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t c = 3 * t + k;
      auto& values = valuesAt[ids[k]];
      std::size_t which = 0;
      while (which < values.size() &&
        std::abs(values[which][0] - uv[c][0]) + std::abs(values[which][1] - uv[c][1]) > kSameTextureCoordinates)
        ++which;
      if (which == values.size())
      {
        if (!values.empty() && !split)
          which = 0; // unsplit: a seam point keeps its first corner's value
        else
          values.push_back(uv[c]);
      }
      cornerPoint[c] = ids[k];
      cornerValue[c] = static_cast<int>(which);
    }

  // Duplicates are numbered after the target's points, point by point.
  std::vector<vtkIdType> firstDuplicate(pointCount, -1), copiedFrom;
  for (vtkIdType p = 0; p < pointCount; ++p)
    if (valuesAt[p].size() > 1)
    {
      firstDuplicate[p] = pointCount + static_cast<vtkIdType>(copiedFrom.size());
      copiedFrom.insert(copiedFrom.end(), valuesAt[p].size() - 1, p);
    }
  const auto added = static_cast<vtkIdType>(copiedFrom.size());
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetName(kTCoordsArray);
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(pointCount + added);
  for (vtkIdType p = 0; p < pointCount; ++p)
    for (std::size_t d = 0; d < valuesAt[p].size(); ++d)
      tcoords->SetTuple2(d == 0 ? p : firstDuplicate[p] + static_cast<vtkIdType>(d) - 1, valuesAt[p][d][0],
        valuesAt[p][d][1]);
  if (added > 0)
    splitPoints(output, copiedFrom, [&](std::size_t c)
      { return cornerValue[c] == 0 ? cornerPoint[c] : firstDuplicate[cornerPoint[c]] + cornerValue[c] - 1; });
  output->GetPointData()->SetTCoords(tcoords);
  return added;
}

} // namespace

namespace
{

/// Target arrays that must stay the target's own: its correspondence and
/// its geometry.
std::vector<std::string> arraysKeptFromTarget(vtkPointData* source)
{
  std::vector<std::string> kept{ cmp::bridge::kFeatureIdArray, cmp::bridge::kBaseTriangleArray,
    cmp::bridge::kBaseCoordinatesArray, cmp::bridge::kNormalsArray, kUnsplitPointIdArray };
  if (vtkDataArray* normals = source->GetNormals(); normals && normals->GetName())
    kept.emplace_back(normals->GetName());
  return kept;
}

/// One target with the source's attributes, and the field arrays saying
/// what was carried and how many points texture seams added.
cmp::Status transferTo(vtkPolyData* target, const cmp::BaseDomain& domain, const cmp::BaseDomainHoles& holes,
  const cmp::bridge::ParameterizedInput& source, bool splitSeams, vtkPolyData* result)
{
  const auto start = std::chrono::steady_clock::now();
  cmp::bridge::ParameterizedInput mapped(domain, target, &holes);
  if (cmp::Status s = mapped.prepare(); !s.ok())
    return s;
  const cmp::BaseDomainMesh where = cmp::bridge::toBaseDomainMesh(mapped);
  std::vector<cmp::SurfacePoint> samples;
  if (cmp::Status s = cmp::locateVertices(source.surface(), where, samples); !s.ok())
    return s;
  result->ShallowCopy(target);
  // New point data, so that the target's arrays are not modified upstream.
  auto points = vtkSmartPointer<vtkPointData>::New();
  points->ShallowCopy(target->GetPointData());
  vtkPointData* sourcePoints = source.input()->GetPointData();
  const std::vector<std::string> kept = arraysKeptFromTarget(sourcePoints);
  cmp::bridge::sampleArrays(points, sourcePoints, samples, kept);
  result->GetPointData()->ShallowCopy(points);
  auto cells = vtkSmartPointer<vtkCellData>::New();
  cells->ShallowCopy(target->GetCellData());
  result->GetCellData()->ShallowCopy(cells);

  int transferred = 0;
  for (int i = 0; i < sourcePoints->GetNumberOfArrays(); ++i)
  {
    const char* name = sourcePoints->GetArrayName(i);
    transferred += !(name && std::find(kept.begin(), kept.end(), name) != kept.end());
  }
  vtkIdType seamPoints = 0;
  vtkDataArray* sourceCorners = source.input()->GetCellData()->GetArray(cmp::bridge::kCornerTCoordsArray);
  if (sourceCorners && sourceCorners->GetNumberOfComponents() == 6)
  {
    std::vector<cmp::SurfacePoint> corners;
    if (cmp::Status s = cmp::locateCorners(source.surface(), domain, where, corners); !s.ok())
      return s;
    seamPoints = addTextureCoordinates(
      result, cornerTextureCoordinates(corners, sourceCorners, source.mesh()), splitSeams);
    ++transferred;
  }
  vtkFieldData* field = result->GetFieldData();
  cmp::bridge::setFieldValue(field, cmp::bridge::kTransferredArraysField, transferred);
  cmp::bridge::setFieldValue(field, cmp::bridge::kSeamPointsAddedField, static_cast<double>(seamPoints));
  cmp::bridge::setFieldValue(field, cmp::bridge::kTransferSecondsField,
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return {};
}

} // namespace

int vtkCMPAttributeTransfer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* sourceInput = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* baseInput = vtkPolyData::GetData(inputVector[2], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  const auto fail = [&](const std::string& message)
  {
    vtkErrorMacro(<< message);
    if (output)
      output->Initialize();
    return 0;
  };
  if (!sourceInput)
    return fail("no source: connect the model whose attributes are carried over to the second input");
  if (!baseInput)
    return fail("no base domain: connect L0 (the one source and targets were parameterized over) to the third input");
  cmp::BaseDomain domain;
  cmp::BaseDomainHoles holes; // an open L0's caps: source and targets are closed anew
  if (cmp::Status s = cmp::bridge::toClosedBaseDomain(baseInput, domain, holes); !s.ok())
    return fail(s.message());
  cmp::bridge::SurfaceCollection targets;
  if (cmp::Status s = cmp::bridge::collectSurfaces(input, targets); !s.ok())
    return fail(s.message());

  cmp::bridge::ParameterizedInput source(domain, sourceInput, &holes);
  if (cmp::Status s = source.prepare(); !s.ok())
    return fail("source: " + s.message());
  this->UpdateProgress(0.2);
  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (std::size_t m = 0; m < targets.surfaces.size(); ++m)
  {
    results.push_back(vtkSmartPointer<vtkPolyData>::New());
    if (cmp::Status s = transferTo(targets.surfaces[m], domain, holes, source, this->SplitTextureSeams, results.back());
        !s.ok())
      return fail((targets.multiblock ? targets.labels[m] : std::string("target: ")) + s.message());
    this->UpdateProgress(0.2 + 0.8 * static_cast<double>(m + 1) / targets.surfaces.size());
  }
  cmp::bridge::assembleOutput(input, output, results);
  return 1;
}

void vtkCMPAttributeTransfer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SplitTextureSeams: " << this->SplitTextureSeams << "\n";
}
