#include <cmp/layout/PatchLayout.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp
{

void BaseTopology::build(const BaseDomain& domain)
{
  CornerTable table;
  table.build(domain.mesh);
  std::vector<int> edgeOf(table.halfedgeCount(), -1);
  edges.clear();
  left.clear();
  right.clear();
  for (int h = 0; h < table.halfedgeCount(); ++h)
  {
    if (table.opposite(h) < h)
      continue;
    edgeOf[h] = edgeOf[table.opposite(h)] = static_cast<int>(edges.size());
    edges.push_back({ table.from(h), table.to(h) });
    left.push_back(CornerTable::triangleOf(h));
    right.push_back(CornerTable::triangleOf(table.opposite(h)));
  }
  rotation.assign(domain.mesh.vertexCount(), {});
  for (int v = 0; v < domain.mesh.vertexCount(); ++v)
  {
    const int start = table.outgoing(v);
    int h = start;
    do
    {
      rotation[v].push_back(edgeOf[h]);
      h = table.nextAroundVertex(h);
    } while (h != start);
  }
}

int BaseTopology::edgeBetween(int a, int b) const
{
  for (int e : rotation[a])
    if (other(e, a) == b)
      return e;
  return -1;
}

Status labelPatches(TracedNet& net)
{
  EditableMesh& mesh = net.mesh;
  std::vector<int> allEdges(net.curves.size());
  for (int e = 0; e < static_cast<int>(net.curves.size()); ++e)
  {
    allEdges[e] = e;
    const auto& curve = net.curves[e];
    for (std::size_t i = 0; i + 1 < curve.size(); ++i)
    {
      const int h = mesh.findHalfedge(curve[i], curve[i + 1]);
      if (h < 0)
        return Status::error("internal error: curve " + std::to_string(e) + " leaves the mesh edges");
      mesh.setTag(h, e);
      mesh.setTag(mesh.opposite(h), e);
    }
  }
  net.patchOfTriangle.assign(mesh.triangleCount(), -1);
  if (Status s = floodFillPatches(net, allEdges); !s.ok())
    return s;
  for (int t = 0; t < mesh.triangleCount(); ++t)
    if (net.patchOfTriangle[t] < 0 && !mesh.isRemoved(t))
      return Status::error("internal error: some triangles belong to no patch");
  return {};
}

Status floodFillPatches(TracedNet& net, const std::vector<int>& seedEdges, const std::vector<char>* allowed)
{
  const EditableMesh& mesh = net.mesh;
  auto& patch = net.patchOfTriangle;
  std::vector<int> stack;
  const auto label = [&](int t, int value)
  {
    if (patch[t] < 0)
    {
      patch[t] = value;
      stack.push_back(t);
    }
    return patch[t] == value;
  };
  const auto clash = [&](int t, int u)
  {
    return Status::error("internal error: patches " + std::to_string(patch[t]) + " and " + std::to_string(patch[u]) +
      " touch away from a curve");
  };
  for (int e : seedEdges)
  {
    const auto& curve = net.curves[e];
    for (std::size_t i = 0; i + 1 < curve.size(); ++i)
    {
      const int h = mesh.findHalfedge(curve[i], curve[i + 1]);
      const int left = EditableMesh::triangleOf(h), right = EditableMesh::triangleOf(mesh.opposite(h));
      if (!label(left, net.leftTriangle[e]) || !label(right, net.rightTriangle[e]))
        return Status::error("internal error: curve " + std::to_string(e) + " has the wrong patch beside it");
    }
  }
  while (!stack.empty())
  {
    const int t = stack.back();
    stack.pop_back();
    for (int h = 3 * t; h < 3 * t + 3; ++h)
    {
      if (mesh.tag(h) >= 0)
        continue;
      const int neighbour = EditableMesh::triangleOf(mesh.opposite(h));
      if (allowed && !(*allowed)[neighbour])
        return Status::error("internal error: patch " + std::to_string(patch[t]) + " leaves its region");
      if (!label(neighbour, patch[t]))
        return clash(t, neighbour);
    }
  }
  return {};
}

int splitEdgesBetweenCurves(const EditableMesh& mesh, const std::vector<int>& vertices,
  const std::vector<char>& occupied, const std::function<void(int)>& split)
{
  std::vector<std::pair<int, int>> crowded;
  for (int u : vertices)
  {
    const int first = mesh.outgoing(u);
    int h = first;
    do
    {
      if (occupied[mesh.to(h)] && mesh.tag(h) < 0)
        crowded.emplace_back(u, mesh.to(h));
      h = mesh.nextAroundVertex(h);
    } while (h != first);
  }
  int splits = 0;
  for (const auto& [u, x] : crowded)
  {
    const int h = mesh.findHalfedge(u, x); // gone if split from the other end
    if (h < 0 || mesh.tag(h) >= 0)
      continue;
    split(h);
    ++splits;
  }
  return splits;
}

TriangleMesh extractTriangles(const EditableMesh& mesh, const std::vector<int>& triangles,
  std::vector<int>& localIndex, std::vector<int>& global)
{
  TriangleMesh piece;
  global.clear();
  piece.triangles.reserve(triangles.size());
  for (int t : triangles)
  {
    Triangle tri = mesh.triangle(t);
    for (int& v : tri)
    {
      if (localIndex[v] < 0)
      {
        localIndex[v] = static_cast<int>(global.size());
        global.push_back(v);
        piece.points.push_back(mesh.point(v));
      }
      v = localIndex[v];
    }
    piece.triangles.push_back(tri);
  }
  return piece;
}

std::vector<double> arcLengthParameters(const EditableMesh& mesh, const std::vector<int>& curve)
{
  std::vector<double> parameters(curve.size(), 0.0);
  for (std::size_t i = 1; i < curve.size(); ++i)
    parameters[i] = parameters[i - 1] + (mesh.point(curve[i]) - mesh.point(curve[i - 1])).norm();
  const double length = parameters.empty() ? 0.0 : parameters.back();
  for (double& s : parameters)
    s = length > 0.0 ? s / length : 0.0;
  return parameters;
}

namespace
{

/// Follows the mesh edges between patches `left` and `right` from `start`
/// until `goal`; the edge's left triangle must be in `left`.
Status followCurve(const EditableMesh& mesh, const std::vector<int>& patchId, int left, int right, int start,
  int goal, std::vector<int>& curve)
{
  curve.assign(1, start);
  int u = start;
  while (u != goal)
  {
    const int first = mesh.outgoing(u);
    int h = first, next = -1;
    do
    {
      if (patchId[EditableMesh::triangleOf(h)] == left &&
        patchId[EditableMesh::triangleOf(mesh.opposite(h))] == right)
      {
        if (next >= 0)
          return Status::error("the boundary between patches " + std::to_string(left) + " and " +
            std::to_string(right) + " branches at point " + std::to_string(u));
        next = h;
      }
      h = mesh.nextAroundVertex(h);
    } while (h != first);
    if (next < 0 || curve.size() > static_cast<std::size_t>(mesh.vertexCount()))
      return Status::error("the boundary between patches " + std::to_string(left) + " and " +
        std::to_string(right) + " does not run from landmark to landmark");
    u = mesh.to(next);
    curve.push_back(u);
  }
  return {};
}

} // namespace

Status layoutFromPatchIds(const TriangleMesh& surface, const std::vector<int>& patchId,
  const LandmarkList& landmarks, const BaseDomain& domain, TracedNet& net)
{
  if (static_cast<int>(patchId.size()) != surface.triangleCount())
    return Status::error("PatchId has " + std::to_string(patchId.size()) + " values for " +
      std::to_string(surface.triangleCount()) + " triangles");
  if (Status s = validateLandmarks(landmarks, surface.vertexCount(), domain.mesh.vertexCount()); !s.ok())
    return s;
  const int patchCount = domain.mesh.triangleCount();
  for (int p : patchId)
    if (p < 0 || p >= patchCount)
      return Status::error("PatchId " + std::to_string(p) + " is not a base domain triangle (0.." +
        std::to_string(patchCount - 1) + ")");
  net = TracedNet{};
  if (Status s = net.mesh.build(surface); !s.ok())
    return s;
  BaseTopology base;
  base.build(domain);
  net.baseEdges = base.edges;
  net.leftTriangle = base.left;
  net.rightTriangle = base.right;
  net.landmarkVertex.resize(domain.mesh.vertexCount());
  for (int bv = 0; bv < domain.mesh.vertexCount(); ++bv)
    net.landmarkVertex[bv] = landmarks[domain.featureIds[bv]];
  net.curves.resize(base.edges.size());
  for (std::size_t e = 0; e < base.edges.size(); ++e)
    if (Status s = followCurve(net.mesh, patchId, base.left[e], base.right[e], net.landmarkVertex[base.edges[e][0]],
          net.landmarkVertex[base.edges[e][1]], net.curves[e]);
        !s.ok())
      return s;
  if (Status s = labelPatches(net); !s.ok())
    return s;
  if (net.patchOfTriangle != patchId)
    return Status::error("PatchId does not match the patches enclosed by the curves between patches");
  return {};
}

LabelledSurface toLabelledSurface(const TracedNet& net, const BaseDomain& domain)
{
  LandmarkList landmarks(domain.mesh.vertexCount());
  for (int bv = 0; bv < domain.mesh.vertexCount(); ++bv)
    landmarks[domain.featureIds[bv]] = net.landmarkVertex[bv];
  return toLabelledSurface(net.mesh.toTriangleMesh(), net.patchOfTriangle, landmarks);
}

LabelledSurface toLabelledSurface(
  const TriangleMesh& surface, const std::vector<int>& patchId, const LandmarkList& landmarks)
{
  LabelledSurface labelled;
  labelled.points.reserve(surface.points.size());
  for (const Vec3& p : surface.points)
    labelled.points.push_back({ p.x(), p.y(), p.z() });
  labelled.triangles = surface.triangles;
  labelled.patchId = patchId;
  labelled.featureId.assign(surface.points.size(), -1);
  for (std::size_t f = 0; f < landmarks.size(); ++f)
    labelled.featureId[landmarks[f]] = static_cast<int>(f);
  return labelled;
}

double curveLength(const EditableMesh& mesh, const std::vector<int>& curve)
{
  double length = 0.0;
  for (std::size_t i = 1; i < curve.size(); ++i)
    length += (mesh.point(curve[i]) - mesh.point(curve[i - 1])).norm();
  return length;
}

double netLength(const TracedNet& net)
{
  double length = 0.0;
  for (const auto& curve : net.curves)
    length += curveLength(net.mesh, curve);
  return length;
}

std::vector<double> patchAreas(const TracedNet& net, int patchCount)
{
  std::vector<double> areas(patchCount, 0.0);
  const EditableMesh& mesh = net.mesh;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    if (mesh.isRemoved(t))
      continue;
    const Triangle& tri = mesh.triangle(t);
    const Vec3 normal = (mesh.point(tri[1]) - mesh.point(tri[0])).cross(mesh.point(tri[2]) - mesh.point(tri[0]));
    areas[net.patchOfTriangle[t]] += 0.5 * normal.norm();
  }
  return areas;
}

double areaVariation(const std::vector<double>& areas)
{
  if (areas.empty())
    return 0.0;
  double mean = 0.0;
  for (double a : areas)
    mean += a;
  mean /= static_cast<double>(areas.size());
  double variance = 0.0;
  for (double a : areas)
    variance += (a - mean) * (a - mean);
  variance /= static_cast<double>(areas.size());
  return mean > 0.0 ? std::sqrt(variance) / mean : 0.0;
}

} // namespace cmp
