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

bool CornerTable::build(const TriangleMesh& mesh)
{
  triangles_ = &mesh.triangles;
  const int halfedges = 3 * mesh.triangleCount();
  // Sort halfedges by their undirected edge so the two sides of every edge
  // end up next to each other.
  struct Key
  {
    std::uint64_t edge;
    int halfedge;
  };
  std::vector<Key> keys(halfedges);
  for (int h = 0; h < halfedges; ++h)
  {
    const auto a = static_cast<std::uint64_t>(from(h));
    const auto b = static_cast<std::uint64_t>(to(h));
    keys[h] = { (std::min(a, b) << 32) | std::max(a, b), h };
  }
  std::sort(keys.begin(), keys.end(),
    [](const Key& x, const Key& y) { return x.edge < y.edge || (x.edge == y.edge && x.halfedge < y.halfedge); });

  opposite_.assign(halfedges, -1);
  for (int i = 0; i < halfedges; i += 2)
  {
    if (i + 1 >= halfedges || keys[i].edge != keys[i + 1].edge ||
      (i + 2 < halfedges && keys[i + 2].edge == keys[i].edge))
    {
      return false;
    }
    const int h = keys[i].halfedge;
    const int g = keys[i + 1].halfedge;
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
