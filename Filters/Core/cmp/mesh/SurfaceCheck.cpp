#include <cmp/mesh/SurfaceCheck.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace cmp
{
namespace
{

SurfaceCheckResult fail(SurfaceDefect defect, const std::string& message)
{
  return { defect, message };
}

std::string edgeName(int a, int b)
{
  std::ostringstream out;
  out << "(" << std::min(a, b) << ", " << std::max(a, b) << ")";
  return out.str();
}

SurfaceCheckResult checkIndices(const TriangleMesh& mesh)
{
  const int n = mesh.vertexCount();
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    for (int v : tri)
    {
      if (v < 0 || v >= n)
      {
        return fail(SurfaceDefect::IndexOutOfRange,
          "triangle " + std::to_string(t) + " refers to point " + std::to_string(v) + " but there are only " +
            std::to_string(n) + " points");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    {
      return fail(SurfaceDefect::RepeatedVertex,
        "triangle " + std::to_string(t) + " uses a point twice (" + std::to_string(tri[0]) + ", " +
          std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")");
    }
  }
  return {};
}

SurfaceCheckResult checkGeometry(const TriangleMesh& mesh, double degenerateAreaFraction)
{
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!mesh.points[v].allFinite())
    {
      return fail(SurfaceDefect::NonFiniteCoordinate, "point " + std::to_string(v) + " has a NaN or infinite coordinate");
    }
  }
  const double diagonal = boundingBoxDiagonal(mesh);
  const double minArea = degenerateAreaFraction * diagonal * diagonal;
  int degenerate = 0;
  int first = -1;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    if (!(triangleArea(mesh, t) > minArea))
    {
      degenerate += 1;
      first = first < 0 ? t : first;
    }
  }
  if (degenerate > 0)
  {
    const Triangle& tri = mesh.triangles[first];
    return fail(SurfaceDefect::DegenerateTriangle,
      std::to_string(degenerate) + " degenerate (zero-area) triangles, e.g. triangle " + std::to_string(first) +
        " with points (" + std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " + std::to_string(tri[2]) +
        ")");
  }
  return {};
}

SurfaceCheckResult checkUnusedVertices(const TriangleMesh& mesh)
{
  std::vector<char> used(mesh.vertexCount(), 0);
  for (const Triangle& tri : mesh.triangles)
  {
    for (int v : tri)
    {
      used[v] = 1;
    }
  }
  const auto unused = std::count(used.begin(), used.end(), 0);
  if (unused > 0)
  {
    const auto first = std::find(used.begin(), used.end(), 0) - used.begin();
    return fail(SurfaceDefect::UnusedVertex,
      std::to_string(unused) + " points belong to no triangle, e.g. point " + std::to_string(first));
  }
  return {};
}

/// Groups the halfedges by undirected edge (`order`, as `halfedgesByEdge()`
/// gives it) and reports open, non-manifold and inconsistently oriented
/// edges, each with a count and an example.
SurfaceCheckResult checkEdges(const TriangleMesh& mesh, const std::vector<int>& order)
{
  const auto from = [&](int h) { return mesh.triangles[h / 3][h % 3]; };
  const auto to = [&](int h) { return mesh.triangles[h / 3][(h % 3 + 1) % 3]; };
  const auto sameEdge = [&](int g, int h) {
    return std::min(from(g), to(g)) == std::min(from(h), to(h)) &&
      std::max(from(g), to(g)) == std::max(from(h), to(h));
  };
  int boundary = 0, nonManifold = 0, misoriented = 0;
  std::string boundaryExample, nonManifoldExample, misorientedExample;
  int nonManifoldCount = 0;
  for (std::size_t i = 0; i < order.size();)
  {
    std::size_t j = i;
    while (j < order.size() && sameEdge(order[j], order[i]))
    {
      ++j;
    }
    const int a = std::min(from(order[i]), to(order[i]));
    const int b = std::max(from(order[i]), to(order[i]));
    const std::size_t count = j - i;
    if (count == 1)
    {
      if (boundary++ == 0)
        boundaryExample = edgeName(a, b);
    }
    else if (count > 2)
    {
      if (nonManifold++ == 0)
      {
        nonManifoldExample = edgeName(a, b);
        nonManifoldCount = static_cast<int>(count);
      }
    }
    else if (from(order[i]) == from(order[i + 1]))
    {
      if (misoriented++ == 0)
        misorientedExample = edgeName(a, b);
    }
    i = j;
  }
  // Non-manifold edges first: a fin (a triangle hung on an edge of a closed
  // surface) also leaves boundary edges, but "open surface" alone would
  // send the user looking for a hole.
  if (nonManifold > 0)
  {
    return fail(SurfaceDefect::NonManifoldEdge,
      std::to_string(nonManifold) + " non-manifold edges, e.g. edge " + nonManifoldExample + " shared by " +
        std::to_string(nonManifoldCount) + " triangles" +
        (boundary > 0 ? " (and " + std::to_string(boundary) + " boundary edges, e.g. edge " + boundaryExample + ")"
                      : std::string()));
  }
  if (boundary > 0)
  {
    return fail(SurfaceDefect::BoundaryEdge,
      "open surface: " + std::to_string(boundary) + " boundary edges (edges with one triangle), e.g. edge " +
        boundaryExample);
  }
  if (misoriented > 0)
  {
    return fail(SurfaceDefect::InconsistentOrientation,
      "inconsistent orientation: " + std::to_string(misoriented) +
        " edges are traversed in the same direction by both their triangles, e.g. edge " + misorientedExample);
  }
  return {};
}

SurfaceCheckResult checkVertexFans(const TriangleMesh& mesh, const CornerTable& table)
{
  std::vector<int> valence(mesh.vertexCount(), 0);
  for (const Triangle& tri : mesh.triangles)
  {
    for (int v : tri)
    {
      ++valence[v];
    }
  }
  int bad = 0, first = -1;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    int fan = 0;
    const int start = table.outgoing(v);
    int h = start;
    do
    {
      ++fan;
      h = table.nextAroundVertex(h);
    } while (h != start && fan <= valence[v]);
    if (fan != valence[v])
    {
      first = bad++ == 0 ? v : first;
    }
  }
  if (bad > 0)
  {
    return fail(SurfaceDefect::NonManifoldVertex,
      std::to_string(bad) + " non-manifold vertices (their triangles form more than one fan), e.g. point " +
        std::to_string(first));
  }
  return {};
}

int findRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

SurfaceCheckResult checkConnected(const TriangleMesh& mesh, const CornerTable& table)
{
  std::vector<int> parent(mesh.triangleCount());
  std::iota(parent.begin(), parent.end(), 0);
  for (int h = 0; h < table.halfedgeCount(); ++h)
  {
    const int a = findRoot(parent, CornerTable::triangleOf(h));
    const int b = findRoot(parent, CornerTable::triangleOf(table.opposite(h)));
    if (a != b)
    {
      parent[a] = b;
    }
  }
  std::vector<int> size(mesh.triangleCount(), 0);
  int components = 0;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    if (size[findRoot(parent, t)]++ == 0)
    {
      ++components;
    }
  }
  if (components > 1)
  {
    std::vector<int> sizes;
    for (int s : size)
    {
      if (s > 0)
        sizes.push_back(s);
    }
    std::sort(sizes.rbegin(), sizes.rend());
    std::string list;
    for (std::size_t i = 0; i < sizes.size() && i < 5; ++i)
    {
      list += (i ? ", " : "") + std::to_string(sizes[i]);
    }
    return fail(SurfaceDefect::SeveralComponents,
      "the surface has " + std::to_string(components) + " connected components (triangles per component: " + list +
        (sizes.size() > 5 ? ", ..." : "") + "); keep one, e.g. with Connectivity (largest region)");
  }
  return {};
}

} // namespace

SurfaceCheckResult checkSurface(const TriangleMesh& mesh, const SurfaceCheckOptions& options)
{
  if (mesh.points.empty() || mesh.triangles.empty())
  {
    return fail(SurfaceDefect::Empty,
      "empty surface: " + std::to_string(mesh.vertexCount()) + " points and " + std::to_string(mesh.triangleCount()) +
        " triangles");
  }
  SurfaceCheckResult result = checkIndices(mesh);
  if (result.ok() && options.checkGeometry)
    result = checkGeometry(mesh, options.degenerateAreaFraction);
  if (result.ok())
    result = checkUnusedVertices(mesh);
  if (!result.ok())
    return result;
  const std::vector<int> order = halfedgesByEdge(mesh);
  result = checkEdges(mesh, order);
  if (!result.ok())
    return result;
  CornerTable table;
  table.build(mesh, order); // cannot fail once checkEdges passed
  result = checkVertexFans(mesh, table);
  if (result.ok())
  {
    result = checkConnected(mesh, table);
  }
  if (!result.ok())
  {
    return result;
  }
  const int edges = 3 * mesh.triangleCount() / 2;
  const int euler = mesh.vertexCount() - edges + mesh.triangleCount();
  const int genus = (2 - euler) / 2;
  if (genus != options.requiredGenus)
  {
    return fail(SurfaceDefect::WrongGenus,
      "the surface has genus " + std::to_string(genus) + " (Euler characteristic " + std::to_string(euler) +
        "); genus " + std::to_string(options.requiredGenus) + " is required");
  }
  return {};
}

const char* defectName(SurfaceDefect defect)
{
  switch (defect)
  {
    case SurfaceDefect::None: return "none";
    case SurfaceDefect::Empty: return "empty";
    case SurfaceDefect::NonFiniteCoordinate: return "non-finite-coordinate";
    case SurfaceDefect::IndexOutOfRange: return "index-out-of-range";
    case SurfaceDefect::RepeatedVertex: return "repeated-vertex";
    case SurfaceDefect::DegenerateTriangle: return "degenerate-triangle";
    case SurfaceDefect::UnusedVertex: return "unused-vertex";
    case SurfaceDefect::BoundaryEdge: return "boundary-edge";
    case SurfaceDefect::NonManifoldEdge: return "non-manifold-edge";
    case SurfaceDefect::InconsistentOrientation: return "inconsistent-orientation";
    case SurfaceDefect::NonManifoldVertex: return "non-manifold-vertex";
    case SurfaceDefect::SeveralComponents: return "several-components";
    case SurfaceDefect::WrongGenus: return "wrong-genus";
  }
  return "unknown";
}

} // namespace cmp
