#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/SurfaceCheck.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace cmp
{

namespace
{

/// The directed edges of the triangles, sorted.
std::vector<std::pair<int, int>> directedEdges(const TriangleMesh& mesh)
{
  std::vector<std::pair<int, int>> directed;
  directed.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      directed.emplace_back(t[k], t[(k + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  return directed;
}

} // namespace

Status boundaryLoops(const TriangleMesh& mesh, std::vector<std::vector<int>>& loops)
{
  loops.clear();
  // A boundary edge's reverse is no triangle's.
  const std::vector<std::pair<int, int>> directed = directedEdges(mesh);
  const auto has = [&](int a, int b) { return std::binary_search(directed.begin(), directed.end(), std::make_pair(a, b)); };
  std::map<int, int> next;
  for (const auto& [a, b] : directed)
  {
    if (has(b, a))
      continue;
    if (!next.emplace(a, b).second)
      return Status::error("the surface's boundary is pinched at vertex " + std::to_string(a) +
        ": two boundary edges leave it (each vertex may lie on one boundary loop once)");
  }
  std::map<int, char> visited;
  for (const auto& [start, unused] : next)
  {
    (void)unused;
    if (visited[start])
      continue;
    std::vector<int> loop;
    int v = start;
    while (!visited[v])
    {
      visited[v] = 1;
      loop.push_back(v);
      const auto found = next.find(v);
      if (found == next.end())
        return Status::error("the surface's boundary does not close at vertex " + std::to_string(v));
      v = found->second;
    }
    if (v != start)
      return Status::error("the surface's boundary is pinched at vertex " + std::to_string(v) +
        ": two boundary edges enter it");
    loops.push_back(loop);
  }
  // `next` is ordered by vertex, so each loop starts at its smallest vertex
  // and the loops come in the order of their smallest vertices.
  return {};
}

Status boundaryVertices(const TriangleMesh& mesh, std::vector<char>& onBoundary)
{
  onBoundary.assign(mesh.vertexCount(), 0);
  std::vector<std::vector<int>> loops;
  if (Status s = boundaryLoops(mesh, loops); !s.ok())
    return s;
  for (const std::vector<int>& loop : loops)
    for (int v : loop)
      onBoundary[v] = 1;
  return {};
}

Status capLoop(TriangleMesh& mesh, const std::vector<int>& loop, int& centre)
{
  const int count = static_cast<int>(loop.size());
  if (count < 3)
    return Status::error("a boundary loop of " + std::to_string(count) + " edges cannot be closed");
  Vec3 centroid = Vec3::Zero(), area = Vec3::Zero();
  for (int v : loop)
    centroid += mesh.points[v];
  centroid /= count;
  double radius = 0.0, perimeter = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const Vec3 a = mesh.points[loop[i]] - centroid, b = mesh.points[loop[(i + 1) % count]] - centroid;
    area += 0.5 * a.cross(b);
    radius += a.norm() / count;
    perimeter += (b - a).norm();
  }
  if (!(area.norm() > 1e-6 * perimeter * perimeter) || !std::isfinite(area.norm()))
    return Status::error("the boundary loop through vertex " + std::to_string(loop.front()) +
      " encloses no area: it cannot be closed");
  // The surface's vector area is its boundary's; the cap faces the other way.
  centre = mesh.vertexCount();
  mesh.points.push_back(centroid - 0.5 * radius * area.normalized());
  for (int i = 0; i < count; ++i)
    mesh.triangles.push_back({ loop[(i + 1) % count], loop[i], centre });
  return {};
}

std::string tooFewBoundaryLandmarks(const std::vector<int>& loop, int count)
{
  return "the boundary loop through vertex " + std::to_string(loop.front()) + " (" + std::to_string(loop.size()) +
    " boundary vertices) passes through " + std::to_string(count) + " landmark" + (count == 1 ? "" : "s") +
    ", but every boundary loop needs at least 3: they become the corners of the base domain's boundary";
}

Status checkSurfaceWithBoundaries(const TriangleMesh& surface, const std::vector<int>* landmarks, CappedSurface* capped)
{
  // Any defect but boundary edges is the surface's as it is (a fin, not a hole).
  const SurfaceCheckResult asGiven = checkSurface(surface);
  if (asGiven.defect != SurfaceDefect::BoundaryEdge)
  {
    if (capped && asGiven.ok())
      *capped = CappedSurface{ surface, {}, {} };
    return asGiven.ok() ? Status{} : Status::error(asGiven.message);
  }
  // Two triangles that run along an edge the same way would look like a
  // pinched boundary: name them for what they are.
  const std::vector<std::pair<int, int>> directed = directedEdges(surface);
  int misoriented = 0;
  std::pair<int, int> example;
  for (std::size_t i = 1; i < directed.size(); ++i)
    if (directed[i] == directed[i - 1] && misoriented++ == 0)
      example = std::minmax(directed[i].first, directed[i].second);
  if (misoriented > 0)
    return Status::error("inconsistent orientation: " + std::to_string(misoriented) +
      " edges are traversed in the same direction by both their triangles, e.g. edge (" +
      std::to_string(example.first) + ", " + std::to_string(example.second) + ") (on a surface with boundary loops)");
  CappedSurface closed{ surface, {}, {} };
  if (Status s = boundaryLoops(surface, closed.loops); !s.ok())
    return s;
  for (const std::vector<int>& loop : closed.loops)
  {
    int centre = -1;
    if (Status s = capLoop(closed.mesh, loop, centre); !s.ok())
      return s;
    closed.centres.push_back(centre);
  }
  if (const SurfaceCheckResult check = checkSurface(closed.mesh); !check.ok())
    return Status::error(check.message + " (the surface with its boundary loops capped)");
  if (landmarks)
  {
    std::vector<char> isLandmark(surface.vertexCount(), 0);
    for (int v : *landmarks)
      if (v >= 0 && v < surface.vertexCount())
        isLandmark[v] = 1;
    for (const std::vector<int>& loop : closed.loops)
    {
      const auto count = static_cast<int>(std::count_if(loop.begin(), loop.end(), [&](int v) { return isLandmark[v]; }));
      if (count < 3)
        return Status::error(tooFewBoundaryLandmarks(loop, count));
    }
  }
  if (capped)
    *capped = std::move(closed);
  return {};
}

} // namespace cmp
