#include <cmp/mesh/SurfaceWalk.h>

#include <Eigen/Geometry>

#include <algorithm>

namespace cmp
{

namespace
{

/// Crossings of one walk at most (a walk shorter than a remesh edge
/// crosses a few triangles; this only stops one circling a degenerate spot).
constexpr int kMaximumCrossings = 2000;

/// Barycentric coordinates of `q` projected into the plane of triangle `t`;
/// false for a triangle too thin to have a plane.
bool planeCoordinates(const EditableMesh& surface, int t, const Vec3& q, Eigen::Vector3d& coordinates)
{
  const Triangle& tri = surface.triangle(t);
  const Vec3 a = surface.point(tri[0]);
  const Vec3 e1 = surface.point(tri[1]) - a, e2 = surface.point(tri[2]) - a, d = q - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double determinant = d11 * d22 - d12 * d12;
  if (!(determinant > 1e-24 * d11 * d22))
    return false;
  const double v = (d22 * d.dot(e1) - d12 * d.dot(e2)) / determinant;
  const double w = (d11 * d.dot(e2) - d12 * d.dot(e1)) / determinant;
  coordinates = { 1.0 - v - w, v, w };
  return true;
}

/// The rest of a step that leaves a triangle across the edge u -> v, turned
/// about that edge into the plane of the triangle beyond it (apex `apex`).
Vec3 turnAcross(const EditableMesh& surface, int u, int v, int apex, const Vec3& rest)
{
  const Vec3 along = (surface.point(v) - surface.point(u)).normalized();
  const double alongLength = rest.dot(along);
  const double acrossLength = (rest - alongLength * along).norm();
  Vec3 inward = surface.point(apex) - surface.point(u);
  inward -= along * along.dot(inward);
  if (inward.norm() > 0.0)
    inward.normalize();
  return alongLength * along + acrossLength * inward;
}

} // namespace

Vec3 surfacePosition(const EditableMesh& surface, const SurfacePoint& p)
{
  const Triangle& tri = surface.triangle(p.triangle);
  return p.weight[0] * surface.point(tri[0]) + p.weight[1] * surface.point(tri[1]) +
    p.weight[2] * surface.point(tri[2]);
}

Vec3 surfaceTriangleNormal(const EditableMesh& surface, int t)
{
  const Triangle& tri = surface.triangle(t);
  const Vec3 n = (surface.point(tri[1]) - surface.point(tri[0])).cross(surface.point(tri[2]) - surface.point(tri[0]));
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

SurfacePoint walkOnSurface(const EditableMesh& surface, SurfacePoint p, Vec3 step)
{
  const auto coordinates = [&p]() { return Eigen::Map<const Eigen::Vector3d>(p.weight.data()); };
  const auto setCoordinates = [&p](const Eigen::Vector3d& c) { p.weight = { c[0], c[1], c[2] }; };
  for (int crossing = 0; crossing < kMaximumCrossings; ++crossing)
  {
    const Vec3 normal = surfaceTriangleNormal(surface, p.triangle);
    step -= normal * normal.dot(step);
    if (step.squaredNorm() == 0.0)
      return p; // exactly where it was, not recomputed
    Eigen::Vector3d target;
    if (normal.isZero() || !planeCoordinates(surface, p.triangle, surfacePosition(surface, p) + step, target))
      return p;
    if (target.minCoeff() >= 0.0)
    {
      setCoordinates(target);
      return p;
    }
    // The side left first: the corner whose coordinate reaches zero first.
    int corner = -1;
    double fraction = 1.0;
    for (int k = 0; k < 3; ++k)
      if (target[k] < 0.0)
      {
        const double at = p.weight[k] / (p.weight[k] - target[k]);
        if (corner < 0 || at < fraction)
          corner = k, fraction = at;
      }
    fraction = std::clamp(fraction, 0.0, 1.0);
    Eigen::Vector3d exit = (coordinates() + fraction * (target - coordinates())).cwiseMax(0.0);
    exit[corner] = 0.0;
    exit /= exit.sum();

    const int h = 3 * p.triangle + (corner + 1) % 3; // runs along the side left
    const int across = surface.opposite(h);
    if (across < 0)
    {
      setCoordinates(exit);
      return p;
    }
    const int u = surface.from(h), v = surface.to(h);
    step = turnAcross(surface, u, v, surface.from(EditableMesh::prev(across)), (1.0 - fraction) * step);
    p.triangle = EditableMesh::triangleOf(across);
    const Triangle& tri = surface.triangle(p.triangle);
    p.vertex = tri;
    for (int k = 0; k < 3; ++k)
      p.weight[k] = tri[k] == u ? exit[(corner + 1) % 3] : tri[k] == v ? exit[(corner + 2) % 3] : 0.0;
  }
  return p;
}

} // namespace cmp
