#include <cmp/layout/CurveSpread.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cmp
{
namespace
{

/// The area-weighted normal of the triangles around mesh vertex `v`.
Vec3 vertexNormal(const EditableMesh& mesh, int v)
{
  Vec3 normal = Vec3::Zero();
  const int first = mesh.outgoing(v);
  if (first < 0)
    return normal;
  int h = first;
  do
  {
    const Vec3 a = mesh.point(mesh.to(h)) - mesh.point(v);
    const Vec3 b = mesh.point(mesh.to(EditableMesh::next(h))) - mesh.point(v);
    normal += a.cross(b);
    h = mesh.nextAroundVertex(h);
  } while (h != first && h >= 0);
  return normal;
}

/// The first vertex of `curve` (mesh vertices, starting at the landmark) at
/// least `reach` along it, or at least half-way if the curve is shorter
/// than twice that.
Vec3 pointAlong(const EditableMesh& mesh, const std::vector<int>& curve, double reach)
{
  const double wanted = std::min(reach, 0.5 * curveLength(mesh, curve));
  double travelled = 0.0;
  for (std::size_t k = 1; k < curve.size(); ++k)
  {
    travelled += (mesh.point(curve[k]) - mesh.point(curve[k - 1])).norm();
    if (travelled >= wanted)
      return mesh.point(curve[k]);
  }
  return mesh.point(curve.back());
}

} // namespace

std::vector<double> largestCurveGaps(const TracedNet& net, double reach)
{
  const double distance = reach * boundingBoxDiagonal(net.mesh.points());
  std::vector<std::vector<Vec3>> chords(net.landmarkVertex.size());
  for (std::size_t e = 0; e < net.curves.size() && e < net.baseEdges.size(); ++e)
  {
    const std::vector<int>& curve = net.curves[e];
    if (curve.size() < 2)
      continue;
    for (int end = 0; end < 2; ++end)
    {
      const int base = net.baseEdges[e][end];
      if (base < 0 || base >= static_cast<int>(chords.size()))
        continue;
      std::vector<int> outwards = curve;
      if (end == 1)
        std::reverse(outwards.begin(), outwards.end());
      chords[base].push_back(pointAlong(net.mesh, outwards, distance) - net.mesh.point(outwards.front()));
    }
  }
  std::vector<double> gaps(net.landmarkVertex.size(), 0.0);
  for (std::size_t base = 0; base < chords.size(); ++base)
  {
    if (chords[base].empty() || net.landmarkVertex[base] < 0)
      continue;
    const Vec3 areaNormal = vertexNormal(net.mesh, net.landmarkVertex[base]);
    if (!(areaNormal.squaredNorm() > 0.0) || !areaNormal.allFinite())
      continue; // no tangent plane to read the angles in
    const Vec3 normal = areaNormal.normalized();
    const Vec3 u = normal.unitOrthogonal(), w = normal.cross(u);
    std::vector<double> angles;
    for (const Vec3& chord : chords[base])
    {
      const Vec3 tangential = chord - chord.dot(normal) * normal;
      if (tangential.norm() > 1e-9 * chord.norm()) // a chord along the normal has no direction
        angles.push_back(std::atan2(chord.dot(w), chord.dot(u)));
    }
    if (angles.empty())
      continue;
    std::sort(angles.begin(), angles.end());
    double largest = 2.0 * kPi - (angles.back() - angles.front()); // across the cut at +-pi
    for (std::size_t k = 1; k < angles.size(); ++k)
      largest = std::max(largest, angles[k] - angles[k - 1]);
    gaps[base] = largest * 180.0 / kPi;
  }
  return gaps;
}

CurveGap widestCurveGap(const TracedNet& net, double reach)
{
  const std::vector<double> gaps = largestCurveGaps(net, reach);
  CurveGap widest;
  for (std::size_t base = 0; base < gaps.size(); ++base)
    if (widest.baseVertex < 0 || gaps[base] > widest.degrees)
      widest = { static_cast<int>(base), gaps[base] };
  return widest;
}

} // namespace cmp
