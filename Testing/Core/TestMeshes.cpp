#include "TestMeshes.h"

#include <cmp/basedomain/BaseDomainBuilder.h>

#include <cmp/map/NetStraightener.h>
#include <cmp/map/Straighten.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/mesh/EdgePaths.h>
#include <cmp/mesh/Subdivision.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>

namespace cmp::test
{

TriangleMesh octahedron()
{
  TriangleMesh mesh;
  mesh.points = { Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1) };
  mesh.triangles = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 },
    { 0, 3, 5 } };
  return mesh;
}

TriangleMesh tetrahedron(const Vec3& offset)
{
  TriangleMesh mesh;
  mesh.points = { Vec3(0, 0, 0) + offset, Vec3(1, 0, 0) + offset, Vec3(0, 1, 0) + offset, Vec3(0, 0, 1) + offset };
  mesh.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
  return mesh;
}

TriangleMesh sphere(int levels)
{
  TriangleMesh mesh = subdivideMidpoint(octahedron(), levels);
  for (Vec3& p : mesh.points)
    p.normalize();
  return mesh;
}

TriangleMesh disjointUnion(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh mesh = a;
  for (const Vec3& p : b.points)
    mesh.points.push_back(p);
  for (Triangle tri : b.triangles)
  {
    for (int& v : tri)
      v += a.vertexCount();
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

TriangleMesh flatSquare(int n)
{
  TriangleMesh square;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      square.points.emplace_back(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0);
  const auto at = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      square.triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      square.triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  return square;
}

TriangleMesh bumpySphere(int levels)
{
  TriangleMesh mesh = sphere(levels);
  for (Vec3& p : mesh.points)
    p *= 1.0 + 0.2 * std::sin(5 * p.x()) * std::sin(4 * p.y()) * std::sin(3 * p.z());
  return mesh;
}

BaseDomain octahedronDomain()
{
  return BaseDomain{ octahedron(), { 3, 0, 5, 1, 4, 2 } };
}

BaseDomain tetrahedronDomain()
{
  return BaseDomain{ tetrahedron(), { 0, 1, 2, 3 } };
}

BaseDomain mixedValenceDomain()
{
  TriangleMesh mesh = octahedron();
  const Triangle split = mesh.triangles[0];
  const int centre = mesh.vertexCount();
  mesh.points.push_back((mesh.points[split[0]] + mesh.points[split[1]] + mesh.points[split[2]]).normalized());
  mesh.triangles[0] = { split[0], split[1], centre };
  mesh.triangles.push_back({ split[1], split[2], centre });
  mesh.triangles.push_back({ split[2], split[0], centre });
  return BaseDomain{ mesh, { 6, 0, 5, 1, 4, 2, 3 } };
}

Eigen::MatrixXd toMatrix(const std::vector<Vec3>& points)
{
  Eigen::MatrixXd matrix(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    matrix.row(i) = points[i].transpose();
  return matrix;
}

TriangleMesh drawnOnDomain(const BaseDomain& domain, const SemiRegularMesh& mesh)
{
  TriangleMesh drawn;
  for (const SurfacePoint& at : mesh.locations)
  {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      p += at.weight[k] * domain.mesh.points[domain.mesh.triangles[at.triangle][k]];
    drawn.points.push_back(p);
  }
  drawn.triangles = mesh.triangles;
  return drawn;
}

int nearestVertex(const TriangleMesh& mesh, const Vec3& direction)
{
  int best = 0;
  for (int v = 1; v < mesh.vertexCount(); ++v)
    if (mesh.points[v].normalized().dot(direction.normalized()) >
      mesh.points[best].normalized().dot(direction.normalized()))
      best = v;
  return best;
}

namespace
{

/// Reads a model of the shared data; "spot" is the OBJ with SHREC landmarks.
Status loadRealModel(const std::string& name, LandmarkedModel& model)
{
  model = LandmarkedModel{ name, {}, {} };
  const std::string shrec = sharedDataDir() + "/shrec07-fourleg/" + name;
  Status status = name == "spot" ? readOBJ(sharedDataDir() + "/spot/spot.obj", model.data)
                                 : readOFF(shrec + ".off", model.data);
  if (status.ok())
    status = readLandmarkFile(name == "spot" ? sharedDataDir() + "/spot/spot_shrec07.pinned" : shrec + ".vts",
      model.data.mesh, model.data.fileToMeshPoint, model.landmarks);
  return status;
}

} // namespace

std::vector<LandmarkedModel> landmarkedRealModels()
{
  std::vector<std::string> names;
  for (const std::string& path : landmarkedFourLeggedModels())
    names.push_back(path.substr(path.find_last_of('/') + 1));
  names.push_back("spot");
  std::vector<LandmarkedModel> models;
  for (const std::string& name : names)
  {
    LandmarkedModel model;
    if (const Status status = loadRealModel(name, model); status.ok())
      models.push_back(std::move(model));
    else
      ADD_FAILURE() << name << ": " << status.message();
  }
  return models;
}

LandmarkedModel landmarkedRealModel(const std::string& name)
{
  LandmarkedModel model;
  if (const Status status = loadRealModel(name, model); !status.ok())
    ADD_FAILURE() << name << ": " << status.message();
  return model;
}

BaseDomain realBaseDomain(const std::string& name)
{
  const LandmarkedModel model = landmarkedRealModel(name);
  BaseDomain domain;
  if (const Status status = buildBaseDomain(model.data.mesh, model.landmarks, domain); !status.ok())
    ADD_FAILURE() << "L0 from " << name << ": " << status.message();
  return domain;
}

Status parameterizeOnDomain(
  const LandmarkedModel& model, const BaseDomain& domain, ParameterizedModel& out, const NetTracerOptions& tracing)
{
  TracedNet traced;
  if (Status s = traceFeatureNet(model.data.mesh, model.landmarks, domain, traced, tracing); !s.ok())
    return Status::error(model.name + ": tracing: " + s.message());
  StraightenOptions options;
  options.freeCurves = false; // the straightened curves, as the paper leaves them
  StraightenedNet straight;
  if (Status s = straighten(traced, domain, straight, out.parameterization, options); !s.ok())
    return Status::error(model.name + ": straightening and parameterizing: " + s.message());
  out.net = std::move(straight.net);
  return {};
}

BaseDomain orderedOctahedronDomain()
{
  return BaseDomain{ octahedron(), { 0, 1, 2, 3, 4, 5 } };
}

Status parameterizedSphere(const BaseDomain& domain, int levels, ParameterizedModel& model)
{
  LandmarkedModel sphere{ "sphere", {}, {} };
  sphere.data.mesh = test::sphere(levels);
  for (const Vec3& direction : domain.mesh.points)
    sphere.landmarks.push_back(nearestVertex(sphere.data.mesh, direction));
  return parameterizeOnDomain(sphere, domain, model);
}

std::vector<std::string> landmarkedFourLeggedModels()
{
  std::vector<std::string> models;
  const std::filesystem::path folder = std::filesystem::path(sharedDataDir()) / "shrec07-fourleg";
  if (sharedDataDir().empty() || !std::filesystem::is_directory(folder))
    return models;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    std::filesystem::path stem = entry.path();
    if (stem.extension() == ".vts" && std::filesystem::exists(stem.replace_extension(".off")))
      models.push_back(stem.replace_extension("").string());
  }
  std::sort(models.begin(), models.end());
  return models;
}

Status indexRealModels(
  const std::vector<std::string>& names, const BaseDomain& domain, bool lowerStretch, IndexedModels& out)
{
  out.parameterized.resize(names.size()); // sized once: the surfaces point into it
  out.surfaces.resize(names.size());
  PatchParameterizationOptions options;
  options.lowerStretch = lowerStretch;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    out.models.push_back(landmarkedRealModel(names[i]));
    ParameterizedModel& model = out.parameterized[i];
    if (Status s = parameterizeOnDomain(out.models[i], domain, model); !s.ok())
      return s;
    if (lowerStretch)
      if (Status s = parameterizePatches(model.net, domain, model.parameterization, options); !s.ok())
        return s;
    if (Status s = out.surfaces[i].build(model.net, domain, model.parameterization); !s.ok())
      return s;
    out.collection.push_back(&out.surfaces[i]);
  }
  return {};
}


namespace
{


} // namespace

Status cutAroundFeature(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  int feature, double radius, OpenModel& out)
{
  out = OpenModel{};
  const int baseVertices = domain.mesh.vertexCount();
  const int bx = static_cast<int>(std::find(domain.featureIds.begin(), domain.featureIds.end(), feature) -
    domain.featureIds.begin());
  if (bx >= baseVertices)
    return Status::error("no base vertex has feature " + std::to_string(feature));
  // The ring of X in L0, counter-clockwise.
  std::map<int, int> next;
  for (const Triangle& t : domain.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] == bx)
        next[t[(k + 1) % 3]] = t[(k + 2) % 3];
  std::vector<int> ring{ next.begin()->first };
  while (next.count(ring.back()) && next[ring.back()] != ring.front() && ring.size() <= next.size())
    ring.push_back(next[ring.back()]);
  if (ring.size() != next.size() || !next.count(ring.back()))
    return Status::error("feature " + std::to_string(feature) + " lies on L0's boundary: no disk around it to cut");
  const int x = landmarks[feature];
  const EdgeGraph graph = edgeGraph(surface);
  std::vector<int> parent;
  const std::vector<double> fromX = edgePathDistances(graph, { x }, std::numeric_limits<double>::infinity(), &parent);
  double nearest = std::numeric_limits<double>::infinity();
  for (int y : ring)
    nearest = std::min(nearest, fromX[landmarks[domain.featureIds[y]]]);
  const double cut = radius * nearest;
  std::vector<int> newIndex(surface.vertexCount(), -1);
  for (const Triangle& t : surface.triangles)
  {
    if (fromX[t[0]] < cut || fromX[t[1]] < cut || fromX[t[2]] < cut)
      continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k)
    {
      if (newIndex[t[k]] < 0)
      {
        newIndex[t[k]] = out.surface.vertexCount();
        out.surface.points.push_back(surface.points[t[k]]);
      }
      kept[k] = newIndex[t[k]];
    }
    out.surface.triangles.push_back(kept);
  }
  std::vector<std::vector<int>> before, loops;
  if (Status s = boundaryLoops(surface, before); !s.ok())
    return s;
  if (Status s = boundaryLoops(out.surface, loops); !s.ok())
    return s;
  if (loops.size() != before.size() + 1)
    return Status::error("the cut leaves " + std::to_string(loops.size()) + " boundary loops, not " +
      std::to_string(before.size() + 1));
  // The new loop is the one nearest to X.
  std::vector<int> oldIndex(out.surface.vertexCount());
  for (int v = 0; v < surface.vertexCount(); ++v)
    if (newIndex[v] >= 0)
      oldIndex[newIndex[v]] = v;
  std::sort(loops.begin(), loops.end(), [&](const std::vector<int>& a, const std::vector<int>& b) {
    return fromX[oldIndex[a.front()]] < fromX[oldIndex[b.front()]];
  });
  // The boundary landmarks: where the shortest way from X to each
  // neighbour leaves the cut (its last vertex outside it), as a place on the
  // loop. The loop runs clockwise round X (the surface on its left), so
  // the neighbours, counter-clockwise, meet it backwards; two that meet it
  // at one vertex are moved apart along it.
  const std::vector<int>& loop = loops[0];
  std::vector<int> onLoop(surface.vertexCount(), -1);
  for (std::size_t i = 0; i < loop.size(); ++i)
    for (int v = 0; v < surface.vertexCount(); ++v)
      if (newIndex[v] == loop[i])
        onLoop[v] = static_cast<int>(i);
  std::vector<int> boundary;
  std::vector<char> taken(loop.size(), 0);
  for (int y : ring)
  {
    const int landmark = landmarks[domain.featureIds[y]];
    if (newIndex[landmark] < 0)
      return Status::error("the cut removes the landmark of feature " + std::to_string(domain.featureIds[y]));
    int at = landmark, last = -1;
    for (; at != x && at >= 0; at = parent[at])
      if (fromX[at] >= cut && onLoop[at] >= 0)
        last = onLoop[at];
    if (last < 0)
      return Status::error("the way to feature " + std::to_string(domain.featureIds[y]) + " does not cross the cut");
    const int count = static_cast<int>(loop.size());
    for (int moved = 0; taken[last] && moved < count; ++moved)
      last = (last + count - 1) % count;
    taken[last] = 1;
    boundary.push_back(last);
  }
  // Ways that cross each other meet the loop out of order: the places, in
  // the loop's order backwards from the first neighbour's, go to the
  // neighbours in theirs.
  const int count = static_cast<int>(loop.size());
  const int start = boundary.front();
  std::vector<int> places(boundary);
  std::sort(places.begin(), places.end(),
    [&](int a, int b) { return (start - a + count) % count < (start - b + count) % count; });
  for (std::size_t i = 0; i < boundary.size(); ++i)
    boundary[i] = loop[places[i]];
  const auto newFeature = [&](int f) { return f < feature ? f : f - 1; };
  out.landmarks.assign(landmarks.size() - 1 + boundary.size(), kMissingLandmark);
  for (int f = 0; f < static_cast<int>(landmarks.size()); ++f)
  {
    if (f == feature)
      continue;
    if (newIndex[landmarks[f]] < 0)
      return Status::error("the cut removes the landmark of feature " + std::to_string(f));
    out.landmarks[newFeature(f)] = newIndex[landmarks[f]];
  }
  const int first = static_cast<int>(landmarks.size()) - 1;
  for (std::size_t i = 0; i < boundary.size(); ++i)
    out.landmarks[first + i] = boundary[i];
  // L0 without X's star, with the boundary landmarks.
  const auto newBase = [&](int v) { return v < bx ? v : v - 1; };
  for (int v = 0; v < baseVertices; ++v)
    if (v != bx)
    {
      out.domain.mesh.points.push_back(domain.mesh.points[v]);
      out.domain.featureIds.push_back(newFeature(domain.featureIds[v]));
    }
  std::map<int, int> boundaryBase;
  for (std::size_t i = 0; i < boundary.size(); ++i)
  {
    boundaryBase[ring[i]] = out.domain.mesh.vertexCount();
    out.domain.mesh.points.push_back(out.surface.points[boundary[i]]);
    out.domain.featureIds.push_back(first + static_cast<int>(i));
  }
  for (const Triangle& t : domain.mesh.triangles)
  {
    const int k = static_cast<int>(std::find(t.begin(), t.end(), bx) - t.begin());
    if (k == 3)
    {
      out.domain.mesh.triangles.push_back({ newBase(t[0]), newBase(t[1]), newBase(t[2]) });
      continue;
    }
    const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
    out.domain.mesh.triangles.push_back({ boundaryBase[a], newBase(a), newBase(b) });
    out.domain.mesh.triangles.push_back({ boundaryBase[a], newBase(b), boundaryBase[b] });
  }
  return {};
}

} // namespace cmp::test
