#include "vtkCMPFeatureNetTracer.h"

#include <cmp/layout/LayoutValidator.h>
#include <cmp/layout/NetTracer.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkCMPFeatureNetTracer);

vtkCMPFeatureNetTracer::vtkCMPFeatureNetTracer()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

int vtkCMPFeatureNetTracer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{

vtkSmartPointer<vtkIntArray> intArray(const char* name, vtkIdType size)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(size);
  return array;
}

/// The point `(1 - t) a + t b` as a blend of the input vertices of a and b.
/// A point needing more than three input vertices (never, since splits stay
/// inside input triangles) comes back without vertices.
cmp::SurfacePoint blend(const cmp::SurfacePoint& a, const cmp::SurfacePoint& b, double t)
{
  cmp::SurfacePoint result;
  int used = 0;
  for (const auto& [end, share] : { std::make_pair(&a, 1.0 - t), std::make_pair(&b, t) })
    for (int k = 0; k < 3; ++k)
    {
      if (end->vertex[k] < 0)
        continue;
      int slot = 0;
      while (slot < used && result.vertex[slot] != end->vertex[k])
        ++slot;
      if (slot == 3)
        return {};
      if (slot == used)
        result.vertex[used++] = end->vertex[k];
      result.weight[slot] += share * end->weight[k];
    }
  return result;
}

/// Where every vertex of the traced mesh lies on the input surface: input
/// vertices are themselves, a split vertex the blend of its edge's ends,
/// which come before it (one forward pass, as for the point data).
std::vector<cmp::SurfacePoint> inputPointsOf(const cmp::EditableMesh& mesh, int inputPoints)
{
  std::vector<cmp::SurfacePoint> points(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const cmp::VertexOrigin& origin = mesh.origin(v);
    points[v] = v < inputPoints ? cmp::SurfacePoint::at(v) : blend(points[origin.a], points[origin.b], origin.t);
  }
  return points;
}

/// The refined surface with the input's arrays carried through and PatchId:
/// the part of it outside the holes (`kept`; all of it for a closed L0).
vtkSmartPointer<vtkPolyData> refinedSurface(
  const cmp::TracedNet& net, vtkPolyData* input, const cmp::TriangleMesh& inputMesh, const cmp::OpenPart& kept)
{
  const cmp::EditableMesh& mesh = net.mesh;
  vtkSmartPointer<vtkPolyData> surface = cmp::bridge::toPolyData(kept.mesh);
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  const int vertices = kept.mesh.vertexCount();
  const int triangles = kept.mesh.triangleCount();
  vtkPointData* points = surface->GetPointData();
  points->CopyAllocate(input->GetPointData(), vertices);
  points->SetNumberOfTuples(vertices); // interpolation below reads and writes in place
  // A split vertex comes after the ends of its edge, which lie on the
  // surface (the caps' edges are never split into the surface's part).
  for (int v = 0; v < vertices; ++v)
  {
    const int old = kept.vertexOf[v];
    if (old < inputPoints)
      points->CopyData(input->GetPointData(), old, v);
    else
    {
      const cmp::VertexOrigin& origin = mesh.origin(old);
      points->InterpolateEdge(points, v, kept.newIndex[origin.a], kept.newIndex[origin.b], origin.t);
    }
  }
  if (vtkDataArray* featureIds = points->GetArray(cmp::bridge::kFeatureIdArray))
    for (int v = 0; v < vertices; ++v)
      if (kept.vertexOf[v] >= inputPoints)
        featureIds->SetComponent(v, 0, -1);

  vtkCellData* cells = surface->GetCellData();
  cells->CopyAllocate(input->GetCellData(), triangles);
  for (int t = 0; t < triangles; ++t)
    cells->CopyData(input->GetCellData(), mesh.inputTriangle(kept.triangleOf[t]), t);
  vtkDataArray* corners = cells->GetArray(cmp::bridge::kCornerTCoordsArray);
  vtkDataArray* inputCorners = input->GetCellData()->GetArray(cmp::bridge::kCornerTCoordsArray);
  if (corners && inputCorners && corners->GetNumberOfComponents() == 6)
  {
    const std::vector<cmp::SurfacePoint> onInput = inputPointsOf(mesh, static_cast<int>(inputPoints));
    cmp::bridge::interpolateCornerTCoords(corners, inputCorners, inputMesh, triangles,
      [&](int t) { return mesh.inputTriangle(kept.triangleOf[t]); },
      [&](int t, int c) { return onInput[mesh.triangle(kept.triangleOf[t])[c]]; });
  }
  auto patchIds = intArray(cmp::bridge::kPatchIdArray, triangles);
  for (int t = 0; t < triangles; ++t)
    patchIds->SetValue(t, net.patchOfTriangle[kept.triangleOf[t]]);
  cells->AddArray(patchIds);
  return surface;
}

/// Runs the independent layout check on the traced net.
bool layoutIsValid(const cmp::TracedNet& net, const cmp::BaseDomain& domain, std::string& problem)
{
  problem = cmp::layoutProblem(cmp::toLabelledSurface(net, domain), domain);
  return problem.empty();
}

} // namespace

int vtkCMPFeatureNetTracer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* baseInput = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* surfaceOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* curvesOutput = vtkPolyData::GetData(outputVector, 1);
  const std::string model = cmp::bridge::modelPrefix(input);
  if (!baseInput)
  {
    vtkErrorMacro(<< model << "no base domain: connect L0 (for example from Base Domain Builder) to the second input");
    return 0;
  }
  cmp::LandmarkList landmarks;
  cmp::BaseDomain domain;
  cmp::BaseDomainHoles holes;
  cmp::bridge::ClosedSurface surface;
  // The surface's own defects first, then its landmarks, then L0.
  cmp::TriangleMesh asGiven;
  cmp::Status status = cmp::bridge::toCheckedSurfaceWithBoundaries(input, asGiven);
  if (status.ok())
    status = cmp::bridge::readLandmarks(input, landmarks);
  if (status.ok())
    status = cmp::bridge::toClosedBaseDomain(baseInput, domain, holes, static_cast<int>(landmarks.size()));
  if (status.ok())
    status = cmp::bridge::toClosedSurface(std::move(asGiven), landmarks, holes, surface);
  const cmp::TriangleMesh& mesh = surface.open;
  cmp::TracedNet net;
  cmp::NetTracerReport report;
  if (status.ok())
  {
    cmp::NetTracerOptions options;
    options.parameterizationWeight = this->ParameterizationWeight;
    options.detectSwirls = this->DetectSwirls;
    options.progress = [this](double fraction) { this->UpdateProgress(0.9 * fraction); };
    // An open surface's caps come traced: its boundary stretches and the spokes.
    status = cmp::traceClosedSurface(surface.closed, surface.closedLandmarks, surface.holes, domain, net, options, &report);
  }
  if (!status.ok())
  {
    vtkErrorMacro(<< model << status.message());
    return 0;
  }
  std::string problem;
  const bool valid = layoutIsValid(net, domain, problem);
  if (!valid)
    vtkWarningMacro(<< model << "the traced net failed the layout check: " << problem);
  const cmp::OpenPart kept = cmp::openPart(net.mesh.toTriangleMesh(), net.patchOfTriangle, holes.holeTriangle);
  surfaceOutput->ShallowCopy(refinedSurface(net, input, mesh, kept));
  curvesOutput->ShallowCopy(cmp::bridge::toPolyLines(net, domain, holes));
  const double lengthPerSqrtArea = report.netLength / std::sqrt(cmp::surfaceArea(mesh));
  for (vtkPolyData* output : { surfaceOutput, curvesOutput })
  {
    vtkFieldData* field = output->GetFieldData();
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetLengthField, report.netLength);
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetLengthPerSqrtAreaField, lengthPerSqrtArea);
    cmp::bridge::setFieldValue(field, cmp::bridge::kNetValidField, valid ? 1 : 0);
    cmp::bridge::setFieldValue(field, cmp::bridge::kRetracedCurvesField, report.retraced);
    cmp::bridge::setFieldValue(field, cmp::bridge::kPenalisedCurvesField, report.penalised);
    cmp::bridge::setFieldValue(field, cmp::bridge::kSplitEdgesField, report.splitEdges);
    // The outputs are built anew: keep the model's name for the next filters.
    cmp::bridge::copySourceFile(input, output);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPFeatureNetTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParameterizationWeight: " << this->ParameterizationWeight << "\n";
  os << indent << "DetectSwirls: " << this->DetectSwirls << "\n";
}
