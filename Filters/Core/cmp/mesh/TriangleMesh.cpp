#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>

namespace cmp
{

double boundingBoxDiagonal(const std::vector<Vec3>& points)
{
  if (points.empty())
  {
    return 0.0;
  }
  Vec3 lo = points.front();
  Vec3 hi = lo;
  for (const Vec3& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

double boundingBoxDiagonal(const TriangleMesh& mesh)
{
  return boundingBoxDiagonal(mesh.points);
}

double triangleArea(const TriangleMesh& mesh, int t)
{
  const Triangle& tri = mesh.triangles[t];
  const Vec3& a = mesh.points[tri[0]];
  return 0.5 * (mesh.points[tri[1]] - a).cross(mesh.points[tri[2]] - a).norm();
}

double surfaceArea(const TriangleMesh& mesh)
{
  double area = 0.0;
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    area += triangleArea(mesh, t);
  }
  return area;
}

std::vector<int> halfedgesByEdge(const TriangleMesh& mesh)
{
  const int halfedges = 3 * mesh.triangleCount();
  std::vector<int> smaller(halfedges), larger(halfedges);
  for (int t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
    {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      smaller[3 * t + k] = std::min(a, b);
      larger[3 * t + k] = std::max(a, b);
    }
  std::vector<int> start(mesh.vertexCount() + 1, 0);
  for (int h = 0; h < halfedges; ++h)
    ++start[smaller[h] + 1];
  for (int v = 0; v < mesh.vertexCount(); ++v)
    start[v + 1] += start[v];
  std::vector<int> order(halfedges);
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int h = 0; h < halfedges; ++h)
    order[next[smaller[h]]++] = h;
  const auto before = [&](int g, int h) { return larger[g] < larger[h] || (larger[g] == larger[h] && g < h); };
  for (int v = 0; v < mesh.vertexCount(); ++v)
    std::sort(order.begin() + start[v], order.begin() + start[v + 1], before);
  return order;
}

bool CornerTable::build(const TriangleMesh& mesh)
{
  return build(mesh, halfedgesByEdge(mesh));
}

bool CornerTable::build(const TriangleMesh& mesh, const std::vector<int>& order)
{
  triangles_ = &mesh.triangles;
  const int halfedges = 3 * mesh.triangleCount();
  if (static_cast<int>(order.size()) != halfedges)
    return false;
  const auto edge = [&](int h) { return std::make_pair(std::min(from(h), to(h)), std::max(from(h), to(h))); };

  opposite_.assign(halfedges, -1);
  for (int i = 0; i < halfedges; i += 2)
  {
    if (i + 1 >= halfedges || edge(order[i]) != edge(order[i + 1]) ||
      (i + 2 < halfedges && edge(order[i + 2]) == edge(order[i])))
    {
      return false;
    }
    const int h = order[i];
    const int g = order[i + 1];
    if (from(h) != to(g))
    {
      return false;
    }
    opposite_[h] = g;
    opposite_[g] = h;
  }
  outgoing_.assign(mesh.vertexCount(), -1);
  for (int h = 0; h < halfedges; ++h)
  {
    outgoing_[from(h)] = h;
  }
  return true;
}

} // namespace cmp
