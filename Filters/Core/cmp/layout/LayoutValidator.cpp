#include <cmp/layout/LayoutValidator.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace cmp
{
namespace
{

using Edge = std::pair<int, int>;

Edge undirected(int a, int b)
{
  return { std::min(a, b), std::max(a, b) };
}

/// Rotates a cyclic sequence so it starts at its smallest element.
std::vector<int> canonicalCycle(std::vector<int> cycle)
{
  if (!cycle.empty())
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  return cycle;
}

std::string checkPatch(int patch, const std::vector<int>& triangles, const LabelledSurface& surface,
  const BaseTriangles& base)
{
  const std::string name = "patch " + std::to_string(patch) + ": ";
  if (triangles.empty())
    return name + "has no triangles";
  // Sorted arrays rather than maps: a million-triangle layout is checked in
  // a second, not ten.
  std::vector<Edge> directed;
  std::vector<int> vertices;
  directed.reserve(3 * triangles.size());
  vertices.reserve(3 * triangles.size());
  for (int t : triangles)
    for (int k = 0; k < 3; ++k)
    {
      directed.emplace_back(surface.triangles[t][k], surface.triangles[t][(k + 1) % 3]);
      vertices.push_back(surface.triangles[t][k]);
    }
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end())
    return name + "an edge is used twice in the same direction";
  // Boundary halfedges: those whose reverse is not in the patch, in order of
  // their first vertex.
  std::vector<Edge> boundary;
  for (const Edge& e : directed)
    if (!std::binary_search(directed.begin(), directed.end(), Edge{ e.second, e.first }))
      boundary.push_back(e);
  for (std::size_t i = 1; i < boundary.size(); ++i)
    if (boundary[i].first == boundary[i - 1].first)
      return name + "its boundary touches itself at vertex " + std::to_string(boundary[i].first);
  std::sort(vertices.begin(), vertices.end());
  const long vertexCount = std::unique(vertices.begin(), vertices.end()) - vertices.begin();
  // Each inner edge is two directed halfedges, each boundary edge one.
  const long edgeCount = static_cast<long>(directed.size() + boundary.size()) / 2;
  const long euler = vertexCount - edgeCount + static_cast<long>(triangles.size());
  if (euler != 1)
    return name + "is not a disk (Euler characteristic " + std::to_string(euler) + ")";
  if (boundary.empty())
    return name + "has no boundary";
  const auto nextOnBoundary = [&](int v)
  {
    const auto it = std::lower_bound(boundary.begin(), boundary.end(), Edge{ v, -1 });
    return it != boundary.end() && it->first == v ? it->second : -1;
  };
  // One boundary loop, walked in the patch's orientation.
  std::vector<int> landmarksOnLoop;
  const int start = boundary.front().first;
  int v = start;
  std::size_t steps = 0;
  do
  {
    if (surface.featureId[v] >= 0)
      landmarksOnLoop.push_back(surface.featureId[v]);
    v = nextOnBoundary(v);
  } while (v >= 0 && v != start && ++steps <= boundary.size());
  if (v < 0 || steps + 1 != boundary.size())
    return name + "its boundary is not one loop";
  const auto& expected = base.triangles[patch];
  if (canonicalCycle(landmarksOnLoop) != canonicalCycle({ expected[0], expected[1], expected[2] }))
  {
    std::string found;
    for (int f : landmarksOnLoop)
      found += std::to_string(f) + " ";
    return name + "its boundary passes landmarks " + found + "instead of " + std::to_string(expected[0]) + " " +
      std::to_string(expected[1]) + " " + std::to_string(expected[2]) + " in that order";
  }
  return "";
}

} // namespace

BaseTriangles toBaseTriangles(const BaseDomain& domain)
{
  BaseTriangles base;
  for (const Triangle& t : domain.mesh.triangles)
    base.triangles.push_back({ domain.featureIds[t[0]], domain.featureIds[t[1]], domain.featureIds[t[2]] });
  return base;
}

std::string layoutProblem(const LabelledSurface& surface, const BaseDomain& domain)
{
  const std::vector<std::string> problems = validateLayout(surface, toBaseTriangles(domain));
  return problems.empty() ? "" : problems.front();
}

std::vector<std::string> validateLayout(const LabelledSurface& surface, const BaseTriangles& base)
{
  std::vector<std::string> problems;
  const int patches = static_cast<int>(base.triangles.size());
  std::vector<std::vector<int>> trianglesOf(patches);
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t)
  {
    const int p = surface.patchId[t];
    if (p < 0 || p >= patches)
    {
      problems.push_back("triangle " + std::to_string(t) + " has PatchId " + std::to_string(p));
      return problems;
    }
    trianglesOf[p].push_back(t);
  }
  for (int p = 0; p < patches; ++p)
  {
    const std::string problem = checkPatch(p, trianglesOf[p], surface, base);
    if (!problem.empty())
      problems.push_back(problem);
  }
  // Adjacency: which patches meet along mesh edges, and along which
  // vertices. Every (edge, patch) pair, sorted, so an edge's owners are
  // neighbours in the array.
  std::vector<std::pair<Edge, int>> edgeOwners;
  edgeOwners.reserve(3 * surface.triangles.size());
  for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      edgeOwners.emplace_back(undirected(surface.triangles[t][k], surface.triangles[t][(k + 1) % 3]),
        surface.patchId[t]);
  std::sort(edgeOwners.begin(), edgeOwners.end());
  std::map<Edge, std::set<int>> sharedVertices; // patch pair -> vertices on their common boundary
  for (std::size_t first = 0, last; first < edgeOwners.size(); first = last)
  {
    last = first + 1;
    while (last < edgeOwners.size() && edgeOwners[last].first == edgeOwners[first].first)
      ++last;
    const int a = edgeOwners[first].second, b = edgeOwners[last - 1].second;
    if (last - first == 2 && a != b)
    {
      auto& shared = sharedVertices[undirected(a, b)];
      shared.insert(edgeOwners[first].first.first);
      shared.insert(edgeOwners[first].first.second);
    }
  }
  std::map<Edge, std::set<int>> baseEdges; // base triangle pair -> the two shared features
  std::map<Edge, std::vector<int>> trianglesOfBaseEdge;
  for (int p = 0; p < patches; ++p)
    for (int k = 0; k < 3; ++k)
      trianglesOfBaseEdge[undirected(base.triangles[p][k], base.triangles[p][(k + 1) % 3])].push_back(p);
  for (const auto& [e, owners] : trianglesOfBaseEdge)
    if (owners.size() == 2)
      baseEdges[undirected(owners[0], owners[1])] = { e.first, e.second };
  for (const auto& [pair, vertices] : sharedVertices)
  {
    const auto expected = baseEdges.find(pair);
    if (expected == baseEdges.end())
    {
      problems.push_back("patches " + std::to_string(pair.first) + " and " + std::to_string(pair.second) +
        " share a boundary but their base triangles share no edge");
      continue;
    }
    std::set<int> landmarks;
    for (int v : vertices)
      if (surface.featureId[v] >= 0)
        landmarks.insert(surface.featureId[v]);
    if (landmarks != expected->second)
      problems.push_back("patches " + std::to_string(pair.first) + " and " + std::to_string(pair.second) +
        " share a boundary whose landmarks are not their base edge's two features");
  }
  for (const auto& [pair, features] : baseEdges)
    if (!sharedVertices.count(pair))
      problems.push_back("patches " + std::to_string(pair.first) + " and " + std::to_string(pair.second) +
        " should share a curve but do not touch");
  return problems;
}

double totalArea(const LabelledSurface& surface)
{
  double area = 0.0;
  for (const auto& tri : surface.triangles)
  {
    const auto& a = surface.points[tri[0]];
    const auto& b = surface.points[tri[1]];
    const auto& c = surface.points[tri[2]];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

} // namespace cmp
