#include "vtkCMPConsistentCollection.h"

#include "vtkCMPPolyDataBridge.h"

#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cstdint>

namespace cmp::bridge
{

namespace
{

/// Where two triangle lists first differ, in words ("" if they do not).
std::string firstDifference(const std::vector<Triangle>& a, const std::vector<Triangle>& b)
{
  if (a.size() != b.size())
    return std::to_string(b.size()) + " triangles instead of " + std::to_string(a.size());
  for (std::size_t t = 0; t < a.size(); ++t)
    if (a[t] != b[t])
      return "triangle " + std::to_string(t) + " is (" + std::to_string(b[t][0]) + ", " + std::to_string(b[t][1]) +
        ", " + std::to_string(b[t][2]) + ") instead of (" + std::to_string(a[t][0]) + ", " + std::to_string(a[t][1]) +
        ", " + std::to_string(a[t][2]) + ")";
  return "";
}

/// A 31-bit fingerprint of the connectivity, to compare across ranks
/// without sending it.
int fingerprint(const std::vector<Triangle>& triangles, int pointCount)
{
  std::uint64_t h = 1469598103934665603ull ^ static_cast<std::uint64_t>(pointCount);
  for (const Triangle& t : triangles)
    for (int v : t)
      h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
  return static_cast<int>(h & 0x7fffffffu);
}

constexpr const char* kRemeshAdvice = "; remesh the whole collection in one Semi-Regular Remesher run";

Status readLocal(ConsistentCollection& out)
{
  for (std::size_t m = 0; m < out.surfaces.surfaces.size(); ++m)
  {
    TriangleMesh mesh;
    if (Status s = toTriangleMesh(out.surfaces.surfaces[m], mesh); !s.ok())
      return Status::error(out.surfaces.labels[m] + s.message());
    if (mesh.triangles.empty())
      return Status::error(out.surfaces.labels[m] + "the surface has no triangles");
    for (int v = 0; v < mesh.vertexCount(); ++v)
      if (!mesh.points[v].allFinite())
        return Status::error(
          out.surfaces.labels[m] + "point " + std::to_string(v) + " has a NaN or infinite coordinate");
    if (m == 0)
    {
      out.triangles = std::move(mesh.triangles);
      out.pointCount = mesh.vertexCount();
    }
    else if (mesh.vertexCount() != out.pointCount)
      return Status::error(out.surfaces.labels[m] + "its connectivity differs from " + out.surfaces.labels[0] +
        std::to_string(mesh.vertexCount()) + " points instead of " + std::to_string(out.pointCount) + kRemeshAdvice);
    else if (const std::string difference = firstDifference(out.triangles, mesh.triangles); !difference.empty())
      return Status::error(
        out.surfaces.labels[m] + "its connectivity differs from " + out.surfaces.labels[0] + difference + kRemeshAdvice);
    out.positions.push_back(std::move(mesh.points));
  }
  return {};
}

/// Sends the triangles of rank `owner` to every rank (as doubles: the
/// communicator moves doubles only; ids below 2^53 are exact).
void shareTriangles(Communicator& communicator, int owner, ConsistentCollection& out)
{
  double counts[2] = { static_cast<double>(out.triangles.size()), static_cast<double>(out.pointCount) };
  communicator.broadcast(counts, 2, owner);
  std::vector<double> flat(3 * static_cast<std::size_t>(counts[0]));
  if (communicator.rank() == owner)
    for (std::size_t t = 0; t < out.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k)
        flat[3 * t + k] = out.triangles[t][k];
  communicator.broadcast(flat.data(), flat.size(), owner);
  out.pointCount = static_cast<int>(counts[1]);
  out.triangles.resize(static_cast<std::size_t>(counts[0]));
  for (std::size_t t = 0; t < out.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      out.triangles[t][k] = static_cast<int>(flat[3 * t + k]);
}

/// Every rank's block names, in global model order, on every rank.
void shareNames(Communicator& communicator, ConsistentCollection& out)
{
  for (int r = 0; r < communicator.size(); ++r)
  {
    std::string joined;
    if (communicator.rank() == r)
      for (const std::string& name : out.surfaces.names)
        joined += name + '\0';
    double length = static_cast<double>(joined.size());
    communicator.broadcast(&length, 1, r);
    std::vector<double> characters(static_cast<std::size_t>(length));
    for (std::size_t i = 0; i < joined.size(); ++i)
      characters[i] = static_cast<unsigned char>(joined[i]);
    communicator.broadcast(characters.data(), characters.size(), r);
    std::string name;
    for (double c : characters)
      if (c == 0.0)
      {
        out.globalNames.push_back(name);
        name.clear();
      }
      else
        name += static_cast<char>(static_cast<unsigned char>(c));
  }
}

} // namespace

Status readConsistentCollection(vtkDataObject* input, Communicator& communicator, ConsistentCollection& out)
{
  out = ConsistentCollection{};
  Status local = collectSurfaces(input, out.surfaces, /*allowEmpty=*/communicator.size() > 1);
  if (local.ok())
    local = readLocal(out);
  if (Status all = agreeOnStatus(local, communicator); !all.ok())
    return all;

  const std::vector<int> counts = communicator.allGather(static_cast<int>(out.positions.size()));
  const auto owner = std::find_if(counts.begin(), counts.end(), [](int c) { return c > 0; }) - counts.begin();
  if (owner == static_cast<long>(counts.size()))
    return Status::error("the input holds no surfaces");
  for (int r = 0; r < communicator.rank(); ++r)
    out.firstGlobalIndex += counts[r];
  for (int c : counts)
    out.globalModelCount += c;
  // Every rank's connectivity against the owner's.
  const int mine = out.positions.empty() ? -1 : fingerprint(out.triangles, out.pointCount);
  const std::vector<int> prints = communicator.allGather(mine);
  for (std::size_t r = 0; r < prints.size(); ++r)
    if (prints[r] >= 0 && prints[r] != prints[owner])
      return Status::error("the surfaces of process " + std::to_string(r) +
        " have another connectivity than those of process " + std::to_string(owner) + kRemeshAdvice);
  shareTriangles(communicator, static_cast<int>(owner), out);
  shareNames(communicator, out);
  return {};
}

Status alignCollection(const ConsistentCollection& collection, CollectionAlignment mode, Communicator& communicator,
  ShapeList& aligned, ShapeAlignment* details)
{
  if (mode == CollectionAlignment::None)
  {
    aligned = collection.positions;
    return {};
  }
  AlignmentOptions options;
  options.scaling = mode == CollectionAlignment::RigidEqualVolume ? AlignmentScaling::EqualVolume
    : mode == CollectionAlignment::RigidUnitCentroidSize        ? AlignmentScaling::UnitCentroidSize
                                                                : AlignmentScaling::None;
  ShapeAlignment alignment;
  if (Status s = alignShapes(collection.positions, collection.triangles, options, communicator, alignment); !s.ok())
    return s;
  aligned = alignment.alignedModels;
  if (details)
    *details = std::move(alignment);
  return {};
}

void copyCorrespondenceArrays(vtkPolyData* model, vtkPolyData* shape)
{
  if (!model)
    return;
  for (const char* name : { kFeatureIdArray, kBaseTriangleArray, kBaseCoordinatesArray, kVertexLevelArray })
    if (vtkAbstractArray* array = model->GetPointData()->GetAbstractArray(name))
      shape->GetPointData()->AddArray(array);
  shape->GetCellData()->ShallowCopy(model->GetCellData());
}

vtkSmartPointer<vtkPolyData> toPolyData(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
{
  return toPolyData(TriangleMesh{ points, triangles });
}

} // namespace cmp::bridge
