#include <cmp/mesh/TriangleShape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cmp
{

double triangleShapeQuality(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double squaredEdges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return squaredEdges > 0.0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / squaredEdges : 0.0;
}

double signedTriangleShapeQuality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& unitDirection)
{
  const double squaredEdges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return squaredEdges > 0.0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).dot(unitDirection) / squaredEdges : 0.0;
}

TriangleShapeSummary measureTriangleShapes(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
{
  // No triangle has an angle above pi, so pi stands for "none yet".
  double minimumAngle = kPi, qualitySum = 0.0;
  for (const Triangle& tri : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 e1 = points[tri[(k + 1) % 3]] - points[tri[k]];
      const Vec3 e2 = points[tri[(k + 2) % 3]] - points[tri[k]];
      minimumAngle = std::min(minimumAngle, std::atan2(e1.cross(e2).norm(), e1.dot(e2)));
    }
    qualitySum += triangleShapeQuality(points[tri[0]], points[tri[1]], points[tri[2]]);
  }
  TriangleShapeSummary summary;
  summary.minimumAngleDegrees = minimumAngle * 180.0 / kPi;
  summary.meanShapeQuality = qualitySum / std::max<std::size_t>(1, triangles.size());
  return summary;
}

} // namespace cmp
