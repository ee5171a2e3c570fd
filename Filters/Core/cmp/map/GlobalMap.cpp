#include <cmp/map/GlobalMap.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <string>
#include <map>
#include <unordered_map>

namespace cmp
{

namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();
using Mat2 = Eigen::Matrix2d;
/// A base triangle drawn in a plane: its corners in its vertex order.
using Drawing = std::array<Vec2, 3>;

/// Barycentric coordinates of `p` in the plane triangle `corners`.
std::array<double, 3> barycentricIn(const std::array<Vec2, 3>& corners, const Vec2& p)
{
  const Vec2 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0], d = p - corners[0];
  const double det = cross2(e1, e2);
  const double b1 = cross2(d, e2) / det, b2 = cross2(e1, d) / det;
  return { 1.0 - b1 - b2, b1, b2 };
}

/// The point left of the line from `p` to `q` at distance `dp` from `p`
/// and `dq` from `q`.
Vec2 apex(const Vec2& p, const Vec2& q, double dp, double dq)
{
  const Vec2 e = q - p;
  const double length = e.norm();
  const Vec2 u = e / length;
  const double x = (dp * dp - dq * dq + length * length) / (2.0 * length);
  const double h = std::sqrt(std::max(0.0, dp * dp - x * x));
  return p + x * u + h * Vec2(-u.y(), u.x());
}

/// The side of `triangles` equilateral triangles of `area` in all.
double equilateralSide(double area, int triangles)
{
  return std::sqrt(4.0 * area / (std::sqrt(3.0) * triangles));
}

/// The sides of L0's triangles drawn with `shapes` and `area` in all the
/// triangles not marked in `fixed` (empty: none):
/// `lengths[t][k]` the side between corners k and k + 1 of triangle t.
Status targetSides(const BaseDomain& domain, double area, GlobalMapOptions::TargetShapes shapes,
  const std::vector<char>& fixed, std::vector<std::array<double, 3>>& lengths)
{
  const int count = domain.mesh.triangleCount();
  const auto isFixed = [&](int t) { return !fixed.empty() && fixed[t]; };
  lengths.assign(count, { { 0.0, 0.0, 0.0 } });
  if (shapes == GlobalMapOptions::TargetShapes::Equilateral)
  {
    int free = 0;
    for (int t = 0; t < count; ++t)
      free += isFixed(t) ? 0 : 1;
    const double side = equilateralSide(area, free);
    for (auto& l : lengths)
      l = { { side, side, side } };
    return {};
  }
  double own = 0.0;
  for (int t = 0; t < count; ++t)
  {
    const Triangle& tri = domain.mesh.triangles[t];
    const Vec3 a = domain.mesh.points[tri[0]], b = domain.mesh.points[tri[1]], c = domain.mesh.points[tri[2]];
    const double twice = (b - a).cross(c - a).norm();
    const double longest = std::max({ (b - a).norm(), (c - b).norm(), (a - c).norm() });
    if (!(twice > 1e-6 * longest * longest))
      return Status::error("global map: triangle " + std::to_string(t) +
        " of L0 is too thin to draw its own shape (TargetShapes: use equilateral)");
    if (!isFixed(t))
      own += 0.5 * twice;
    for (int k = 0; k < 3; ++k)
      lengths[t][k] = (domain.mesh.points[tri[(k + 1) % 3]] - domain.mesh.points[tri[k]]).norm();
  }
  const double scale = std::sqrt(area / own);
  for (auto& l : lengths)
    for (double& side : l)
      side *= scale;
  return {};
}

/// L0 drawn flat triangle by triangle (`targetSides()`): each triangle
/// unfolded beside its neighbours, and straight walks across them.
class DomainGeometry
{
public:
  /// `lengths[t][k]`: the side of triangle t between its corners k and
  /// k + 1 (equal on both triangles of an edge).
  Status build(const BaseDomain& domain, std::vector<std::array<double, 3>> lengths)
  {
    length_ = std::move(lengths);
    const int count = domain.mesh.triangleCount();
    if (static_cast<int>(length_.size()) != count)
      return Status::error("global map: one length per side of L0's triangles is needed");
    const int vertices = domain.mesh.vertexCount();
    neighbour_.assign(count, { { -1, -1, -1 } });
    neighbourEdge_.assign(count, { { -1, -1, -1 } });
    std::unordered_map<long long, std::pair<int, int>> directed;
    for (int t = 0; t < count; ++t)
      for (int k = 0; k < 3; ++k)
      {
        const Triangle& tri = domain.mesh.triangles[t];
        directed[static_cast<long long>(tri[k]) * vertices + tri[(k + 1) % 3]] = { t, k };
      }
    for (int t = 0; t < count; ++t)
      for (int k = 0; k < 3; ++k)
      {
        const Triangle& tri = domain.mesh.triangles[t];
        const auto found = directed.find(static_cast<long long>(tri[(k + 1) % 3]) * vertices + tri[k]);
        if (found == directed.end())
          return Status::error("global map: L0 is not closed");
        neighbour_[t][k] = found->second.first;
        neighbourEdge_[t][k] = found->second.second;
      }
    return {};
  }

  /// Triangle `t` drawn on its own: corner 0 at the origin, corner 1 on the
  /// x axis.
  Drawing canonical(int t) const
  {
    const std::array<double, 3>& l = length_[t];
    return { Vec2(0.0, 0.0), Vec2(l[0], 0.0), apex(Vec2(0.0, 0.0), Vec2(l[0], 0.0), l[2], l[1]) };
  }

  /// The triangle across edge k (corners k, k + 1) of `t`, drawn `drawing`,
  /// drawn beside it; `result` gets its index.
  Drawing unfold(int t, const Drawing& drawing, int k, int& result) const
  {
    result = neighbour_[t][k];
    const int j = neighbourEdge_[t][k];
    Drawing out;
    out[j] = drawing[(k + 1) % 3];
    out[(j + 1) % 3] = drawing[k];
    out[(j + 2) % 3] = apex(out[j], out[(j + 1) % 3], length_[result][(j + 2) % 3], length_[result][(j + 1) % 3]);
    return out;
  }

  /// Walks the straight segment from `from` to `to` (points of the plane
  /// of `drawing`, `from` in triangle `t`) across L0's triangles, each
  /// unfolded beside the last; `t` and `drawing` end as the triangle that
  /// holds `to`. False if the walk does not end.
  bool walk(int& t, Drawing& drawing, const Vec2& from, const Vec2& to) const
  {
    int entry = -1; // local edge of `t` the walk came in by
    for (int step = 0; step < 10000; ++step)
    {
      const std::array<double, 3> end = barycentricIn(drawing, to);
      if (std::min({ end[0], end[1], end[2] }) >= -1e-12)
        return true;
      const std::array<double, 3> start = barycentricIn(drawing, from);
      // Corner c's coordinate falls below 0 across edge c + 1 (corners
      // c + 1, c + 2); of those the segment crosses, the first.
      int exit = -1;
      double first = kInfinity;
      for (int c = 0; c < 3; ++c)
      {
        const int edge = (c + 1) % 3;
        if (!(end[c] < 0.0) || edge == entry)
          continue;
        const double denominator = start[c] - end[c];
        const double at = denominator > 0.0 ? start[c] / denominator : 0.0;
        if (at < first)
        {
          first = at;
          exit = edge;
        }
      }
      if (exit < 0)
        return true; // only outside the edge it came in by: rounding
      int next = -1;
      drawing = unfold(t, drawing, exit, next);
      entry = neighbourEdge_[t][exit];
      t = next;
    }
    return false;
  }

private:
  std::vector<std::array<double, 3>> length_;
  std::vector<std::array<int, 3>> neighbour_;
  std::vector<std::array<int, 3>> neighbourEdge_;
};

/// A rigid motion of the plane: x -> rotation x + shift.
struct Motion
{
  Mat2 rotation = Mat2::Identity();
  Vec2 shift = Vec2::Zero();
  Vec2 operator()(const Vec2& x) const { return rotation * x + shift; }
};

/// The affine map taking the corners of `from` onto those of `to`.
Motion motionBetween(const Drawing& from, const Drawing& to)
{
  Mat2 a, b;
  a.col(0) = from[1] - from[0];
  a.col(1) = from[2] - from[0];
  b.col(0) = to[1] - to[0];
  b.col(1) = to[2] - to[0];
  Motion m;
  m.rotation = b * a.inverse();
  m.shift = to[0] - m.rotation * from[0];
  return m;
}

Vec2 atBarycentric(const Drawing& d, const std::array<double, 3>& b)
{
  return b[0] * d[0] + b[1] * d[1] + b[2] * d[2];
}

/// The symmetric Dirichlet energy density |F|^2 + |F^-1|^2 of a 2x2
/// Jacobian, infinite if it is flipped or flat.
double density(const Mat2& f)
{
  const double det = f.determinant();
  if (!(det > 0.0))
    return kInfinity;
  return f.squaredNorm() * (1.0 + 1.0 / (det * det));
}

/// d density / d F (column-major vec) and its Hessian projected onto its
/// positive part, from the singular values (Smith, De Goes, Kim 2019:
/// twist, flip and the two scalings are its eigenvectors).
void densityDerivatives(const Mat2& f, Eigen::Vector4d& gradient, Eigen::Matrix4d& hessian)
{
  Eigen::JacobiSVD<Mat2> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat2 u = svd.matrixU(), v = svd.matrixV();
  Eigen::Vector2d s = svd.singularValues();
  // Rotations, not reflections: det > 0, so flip the sign of both.
  if (u.determinant() < 0.0)
  {
    u.col(1) *= -1.0;
    v.col(1) *= -1.0;
  }
  const double s1 = s(0), s2 = s(1);
  const auto vec = [](const Mat2& m) { return Eigen::Vector4d(m(0, 0), m(1, 0), m(0, 1), m(1, 1)); };
  Mat2 diagonal = Mat2::Zero();
  diagonal(0, 0) = 2.0 * s1 - 2.0 / (s1 * s1 * s1);
  diagonal(1, 1) = 2.0 * s2 - 2.0 / (s2 * s2 * s2);
  gradient = vec(u * diagonal * v.transpose());
  const double p = s1 * s2, p3 = p * p * p;
  const double twist = std::max(0.0, 2.0 - 2.0 * (s1 * s1 - p + s2 * s2) / p3);
  const double flip = 2.0 + 2.0 * (s1 * s1 + p + s2 * s2) / p3;
  const double scale1 = 2.0 + 6.0 / (s1 * s1 * s1 * s1);
  const double scale2 = 2.0 + 6.0 / (s2 * s2 * s2 * s2);
  Mat2 twistMode, flipMode, scaleMode1, scaleMode2;
  twistMode << 0.0, -1.0, 1.0, 0.0;
  flipMode << 0.0, 1.0, 1.0, 0.0;
  scaleMode1 << 1.0, 0.0, 0.0, 0.0;
  scaleMode2 << 0.0, 0.0, 0.0, 1.0;
  const Eigen::Vector4d qt = vec(u * twistMode * v.transpose()) / std::sqrt(2.0);
  const Eigen::Vector4d qf = vec(u * flipMode * v.transpose()) / std::sqrt(2.0);
  const Eigen::Vector4d q1 = vec(u * scaleMode1 * v.transpose());
  const Eigen::Vector4d q2 = vec(u * scaleMode2 * v.transpose());
  hessian = twist * qt * qt.transpose() + flip * qf * qf.transpose() + scale1 * q1 * q1.transpose() +
    scale2 * q2 * q2.transpose();
}

/// The smallest step in (0, 1] along (f1, f2) at which the triangle with
/// edges (e1, e2) flats, or 1 if none.
double flipBound(const Vec2& e1, const Vec2& e2, const Vec2& f1, const Vec2& f2)
{
  const double c = cross2(e1, e2);
  const double b = cross2(e1, f2) + cross2(f1, e2);
  const double a = cross2(f1, f2);
  double bound = kInfinity;
  const auto consider = [&](double t) {
    if (t > 0.0)
      bound = std::min(bound, t);
  };
  if (a == 0.0)
  {
    if (b != 0.0)
      consider(-c / b);
  }
  else
  {
    const double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0)
    {
      // The two roots, without cancellation.
      const double q = -0.5 * (b + (b >= 0.0 ? std::sqrt(disc) : -std::sqrt(disc)));
      if (q != 0.0)
      {
        consider(q / a);
        consider(c / q);
      }
    }
  }
  return bound;
}

/// Area of the part of triangle `p` inside triangle `q` (both
/// counter-clockwise), by clipping `p` against `q`'s sides.
double overlapArea(const std::array<Vec2, 3>& p, const Drawing& q)
{
  std::vector<Vec2> polygon(p.begin(), p.end()), next;
  for (int j = 0; j < 3 && !polygon.empty(); ++j)
  {
    const Vec2 a = q[j], d = q[(j + 1) % 3] - q[j];
    next.clear();
    const int m = static_cast<int>(polygon.size());
    for (int i = 0; i < m; ++i)
    {
      const Vec2& x = polygon[i];
      const Vec2& y = polygon[(i + 1) % m];
      const double fx = cross2(d, x - a), fy = cross2(d, y - a);
      if (fx >= 0.0)
        next.push_back(x);
      if ((fx >= 0.0) != (fy >= 0.0))
        next.push_back(x + fx / (fx - fy) * (y - x));
    }
    polygon.swap(next);
  }
  double area = 0.0;
  const int m = static_cast<int>(polygon.size());
  for (int i = 0; i < m; ++i)
    area += cross2(polygon[i], polygon[(i + 1) % m]);
  const double whole = cross2(p[1] - p[0], p[2] - p[0]);
  return 0.5 * area > 1e-10 * whole ? 0.5 * area : 0.0;
}

/// Whether the segment from `a` to `b` runs through the inside of
/// triangle `p` (counter-clockwise) for a length, not only touching it.
bool crossesInside(const std::array<Vec2, 3>& p, const Vec2& a, const Vec2& b)
{
  double low = 0.0, high = 1.0;
  const Vec2 d = b - a;
  const double scale = std::sqrt(std::abs(cross2(p[1] - p[0], p[2] - p[0])));
  for (int k = 0; k < 3; ++k)
  {
    const Vec2 e = p[(k + 1) % 3] - p[k];
    const double length = e.norm();
    // Signed distance inside the side's line, along the segment.
    const double at = cross2(e, a - p[k]) / length, slope = cross2(e, d) / length;
    if (std::abs(slope) < 1e-300)
    {
      if (at <= 1e-12 * scale)
        return false;
      continue;
    }
    const double zero = -at / slope;
    if (slope > 0.0)
      low = std::max(low, zero);
    else
      high = std::min(high, zero);
  }
  return (high - low) * d.norm() > 1e-9 * scale;
}

/// The smallest angle of the triangle (a, b, c).
double smallestAngle(const Vec2& a, const Vec2& b, const Vec2& c)
{
  const auto angle = [](const Vec2& at, const Vec2& x, const Vec2& y) {
    return std::abs(std::atan2(cross2(x - at, y - at), (x - at).dot(y - at)));
  };
  return std::min({ angle(a, b, c), angle(b, c, a), angle(c, a, b) });
}

class SeamlessProblem
{
public:
  Status build(const TracedNet& net, const BaseDomain& domain, const PatchParameterization& map,
    const GlobalMapOptions& options)
  {
    const EditableMesh& mesh = net.mesh;
    mesh_ = &mesh;
    const int n = mesh.vertexCount();
    const int triangles = mesh.triangleCount();
    const int baseVertices = domain.mesh.vertexCount();
    const int baseTriangles = domain.mesh.triangleCount();
    const int baseEdges = static_cast<int>(net.baseEdges.size());
    if (static_cast<int>(map.baseTriangle.size()) != n || static_cast<int>(map.baseCoordinates.size()) != n ||
      static_cast<int>(net.patchOfTriangle.size()) != triangles ||
      static_cast<int>(net.landmarkVertex.size()) != baseVertices ||
      static_cast<int>(net.curves.size()) != baseEdges)
      return Status::error("global map: the layout and its parameterization do not belong together");
    const std::vector<char>& fixedPatches = options.fixedPatches;
    if (!fixedPatches.empty() && static_cast<int>(fixedPatches.size()) != baseTriangles)
      return Status::error("global map: fixedPatches has " + std::to_string(fixedPatches.size()) +
        " entries, but L0 has " + std::to_string(baseTriangles) + " triangles (give none or one per triangle)");
    int freeBaseTriangles = baseTriangles;
    for (char fixed : fixedPatches)
      freeBaseTriangles -= fixed ? 1 : 0;
    if (freeBaseTriangles == 0)
      return Status::error("global map: fixedPatches fixes every patch of L0, so nothing is left to map");
    fixedTriangle_.assign(triangles, 0);
    if (!fixedPatches.empty())
      for (int t = 0; t < triangles; ++t)
      {
        const int patch = net.patchOfTriangle[t];
        if (!mesh.isRemoved(t) && patch >= 0 && patch < baseTriangles)
          fixedTriangle_[t] = fixedPatches[patch] ? 1 : 0;
      }

    // The surface's metric: each triangle's area and inverse edge matrix
    // (none for a fixed patch's, which has no say in the energy or the area).
    area_.assign(triangles, 0.0);
    inverseEdges_.assign(triangles, Mat2::Zero());
    used_.assign(n, 0);
    totalArea_ = 0.0;
    for (int t = 0; t < triangles; ++t)
    {
      if (mesh.isRemoved(t))
        continue;
      const Triangle& tri = mesh.triangle(t);
      for (int v : tri)
        used_[v] = 1;
      if (fixedTriangle_[t])
        continue;
      const Vec3 e1 = mesh.point(tri[1]) - mesh.point(tri[0]), e2 = mesh.point(tri[2]) - mesh.point(tri[0]);
      const double twiceArea = e1.cross(e2).norm();
      const double length = e1.norm();
      if (!(twiceArea > 1e-14 * (e1.squaredNorm() + e2.squaredNorm())) || !(length > 0.0))
        continue; // degenerate: kept unflipped, but no say in the energy
      Mat2 edges;
      edges << length, e2.dot(e1) / length, 0.0, twiceArea / length;
      area_[t] = 0.5 * twiceArea;
      inverseEdges_[t] = edges.inverse();
      totalArea_ += area_[t];
    }
    if (!(totalArea_ > 0.0))
      return Status::error("global map: the surface has no area");
    side_ = equilateralSide(totalArea_, freeBaseTriangles);
    baseTriangles_ = freeBaseTriangles;
    if (options.curvatureDensity > 0.0)
      inflateCurvedParts(options.curvatureDensity, options.curvatureDensityCap);

    std::vector<std::array<double, 3>> lengths;
    if (Status s = targetSides(domain, totalArea_, options.targetShapes, fixedPatches, lengths); !s.ok())
      return s;
    if (Status s = geometry_.build(domain, std::move(lengths)); !s.ok())
      return s;

    // A spanning tree of L0's vertices: its curves cut the surface into a
    // disk, its edges L0 into one.
    std::vector<std::vector<int>> edgesAt(baseVertices);
    for (int e = 0; e < baseEdges; ++e)
      for (int end : net.baseEdges[e])
        edgesAt[end].push_back(e);
    std::vector<char> inTree(baseEdges, 0), reached(baseVertices, 0);
    std::vector<int> queue{ 0 };
    reached[0] = 1;
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (int e : edgesAt[queue[i]])
      {
        const int other = net.baseEdges[e][0] == queue[i] ? net.baseEdges[e][1] : net.baseEdges[e][0];
        if (!reached[other])
        {
          reached[other] = 1;
          inTree[e] = 1;
          queue.push_back(other);
        }
      }
    baseVertices_ = baseVertices;
    edgeOf_.clear();
    for (int e = 0; e < baseEdges; ++e)
    {
      const int a = net.baseEdges[e][0], b = net.baseEdges[e][1];
      edgeOf_[static_cast<long long>(std::min(a, b)) * baseVertices + std::max(a, b)] = e;
    }

    // L0 cut along the tree, drawn flat: across the other edges.
    drawing_.assign(baseTriangles, Drawing{});
    std::vector<char> drawn(baseTriangles, 0);
    drawn[0] = 1;
    drawing_[0] = geometry_.canonical(0);
    queue.assign(1, 0);
    for (std::size_t i = 0; i < queue.size(); ++i)
    {
      const int t = queue[i];
      for (int k = 0; k < 3; ++k)
      {
        const Triangle& tri = domain.mesh.triangles[t];
        const int e = baseEdge(tri[k], tri[(k + 1) % 3]);
        if (e < 0)
          return Status::error("global map: an edge of L0 has no curve");
        int next = -1;
        const Drawing beside = geometry_.unfold(t, drawing_[t], k, next);
        if (inTree[e] || drawn[next])
          continue;
        drawn[next] = 1;
        drawing_[next] = beside;
        queue.push_back(next);
      }
    }
    if (std::find(drawn.begin(), drawn.end(), 0) != drawn.end())
      return Status::error("global map: L0 cut along a spanning tree is not one disk");

    // The surface cut along the tree's curves.
    std::vector<char> cut(mesh.halfedgeCount(), 0);
    std::vector<int>& curveOf = curveOf_;
    curveOf.assign(n, -1);
    for (int e = 0; e < baseEdges; ++e)
    {
      const std::vector<int>& curve = net.curves[e];
      for (std::size_t i = 0; i + 1 < curve.size(); ++i)
      {
        const int h = mesh.findHalfedge(curve[i], curve[i + 1]);
        if (h < 0)
          return Status::error("global map: curve " + std::to_string(e) + " does not run along mesh edges");
        if (inTree[e])
          cut[h] = cut[mesh.opposite(h)] = 1;
      }
      for (std::size_t i = 1; i + 1 < curve.size(); ++i)
        curveOf[curve[i]] = e;
    }
    pinned_.assign(n, 0);
    for (int v : net.landmarkVertex)
      pinned_[v] = 1;
    // A fixed patch's vertices keep their start places (every copy of one
    // on a cut curve its own), so the curves round the patch stay.
    for (int t = 0; t < triangles; ++t)
      if (fixedTriangle_[t])
        for (int v : mesh.triangle(t))
          pinned_[v] = 1;
    // ... but for those on a curve between a fixed and a free patch: they
    // slide along its base edge, drawn in the free patch (one variable
    // each, its place along the edge), so the curve stays on the edge while
    // the map spreads its vertices there as it needs.
    sliding_.assign(n, 0);
    slideEdge_.assign(n, -1);
    slidePatch_.assign(n, -1);
    if (!fixedPatches.empty())
    {
      std::vector<char> landmark(n, 0);
      for (int v : net.landmarkVertex)
        landmark[v] = 1;
      for (int e = 0; e < baseEdges; ++e)
      {
        const int left = net.leftTriangle[e], right = net.rightTriangle[e];
        if ((fixedPatches[left] != 0) == (fixedPatches[right] != 0))
          continue;
        const std::vector<int>& curve = net.curves[e];
        for (std::size_t i = 1; i + 1 < curve.size(); ++i)
        {
          const int v = curve[i];
          if (landmark[v] || curveOf[v] != e)
            continue;
          sliding_[v] = 1;
          slideEdge_[v] = e;
          slidePatch_[v] = fixedPatches[left] ? right : left;
        }
      }
      // Only between its edge's two patches (a layout's curve vertex always
      // is): else it stays pinned.
      for (int t = 0; t < triangles; ++t)
        if (!mesh.isRemoved(t))
          for (int v : mesh.triangle(t))
            if (sliding_[v])
            {
              const int e = slideEdge_[v], patch = net.patchOfTriangle[t];
              if (patch != net.leftTriangle[e] && patch != net.rightTriangle[e])
                sliding_[v] = 0;
            }
      for (int v = 0; v < n; ++v)
      {
        if (sliding_[v])
          pinned_[v] = 0;
        else
          slideEdge_[v] = slidePatch_[v] = -1;
      }
    }
    // A fixed patch's triangle with a sliding corner is kept unflipped like
    // every free one (it still has no say in the energy).
    watched_.assign(triangles, 0);
    slideTriangles_.clear();
    for (int t = 0; t < triangles; ++t)
    {
      if (mesh.isRemoved(t))
        continue;
      watched_[t] = fixedTriangle_[t] ? 0 : 1;
      for (int v : mesh.triangle(t))
        watched_[t] = sliding_[v] ? 1 : watched_[t];
      if (fixedTriangle_[t] && watched_[t])
        slideTriangles_.push_back(t);
    }
    net_ = &net;
    domain_ = &domain;

    // One copy of a vertex per wedge between cut edges round it.
    copyOfCorner_.assign(mesh.halfedgeCount(), -1);
    copyPosition_.clear();
    copyVertex_.clear();
    copyPatch_.clear();
    firstCopy_.assign(n, -1);
    std::vector<int> ring;
    for (int v = 0; v < n; ++v)
    {
      if (!used_[v])
        continue;
      ring.clear();
      const int first = mesh.outgoing(v);
      int h = first;
      do
      {
        ring.push_back(h);
        h = mesh.nextAroundVertex(h);
      } while (h != first && ring.size() <= static_cast<std::size_t>(triangles));
      const int m = static_cast<int>(ring.size());
      int start = 0;
      for (int i = 0; i < m; ++i)
        if (cut[ring[i]])
        {
          start = i;
          break;
        }
      firstCopy_[v] = static_cast<int>(copyVertex_.size());
      for (int i = 0; i < m; ++i)
      {
        const int hh = ring[(start + i) % m];
        if (i == 0 || cut[hh])
        {
          copyVertex_.push_back(v);
          copyPatch_.push_back(net.patchOfTriangle[EditableMesh::triangleOf(hh)]);
          copyPosition_.push_back(Vec2::Zero());
        }
        copyOfCorner_[hh] = static_cast<int>(copyVertex_.size()) - 1;
      }
    }
    const int copies = static_cast<int>(copyVertex_.size());
    for (int c = 0; c < copies; ++c)
    {
      const int v = copyVertex_[c];
      std::array<double, 3> b;
      if (!coordinatesInTriangle(domain, map.baseTriangle[v], map.baseCoordinates[v], copyPatch_[c], b))
        return Status::error("global map: vertex " + std::to_string(v) + " is not on its patch's base triangle");
      copyPosition_[c] = atBarycentric(drawing_[copyPatch_[c]], b);
    }

    // Free vertices: one variable each, its first copy; another copy is
    // the first moved across its cut edge.
    variable_.assign(n, -1);
    variables_ = 0;
    for (int v = 0; v < n; ++v)
      if (used_[v] && !pinned_[v])
        variable_[v] = variables_++;
    motion_.assign(copies, Motion{});
    for (int c = 0; c < copies; ++c)
    {
      const int v = copyVertex_[c];
      if (pinned_[v] || c == firstCopy_[v])
        continue;
      const int master = firstCopy_[v];
      const int e = curveOf[v];
      if (e < 0 || !inTree[e] || c != master + 1 || (c + 1 < copies && copyVertex_[c + 1] == v))
        return Status::error("global map: vertex " + std::to_string(v) + " is cut but not on one cut curve");
      const int a = net.baseEdges[e][0], b = net.baseEdges[e][1];
      const int patch = copyPatch_[c];
      const Triangle& tri = domain.mesh.triangles[patch];
      int k = 0;
      while (k < 3 && !((tri[k] == a && tri[(k + 1) % 3] == b) || (tri[k] == b && tri[(k + 1) % 3] == a)))
        ++k;
      int other = -1;
      if (k == 3)
        return Status::error("global map: a cut curve's patch does not hold its edge");
      const Drawing beside = geometry_.unfold(patch, drawing_[patch], k, other);
      if (other != copyPatch_[master])
        return Status::error("global map: the two sides of a cut curve are not its edge's triangles");
      motion_[c] = motionBetween(drawing_[other], beside);
      if ((motion_[c](copyPosition_[master]) - copyPosition_[c]).norm() > 1e-6 * side_)
        return Status::error("global map: the two sides of vertex " + std::to_string(v) + " disagree");
    }
    // Every corner of a copy must be where the copy is (a wedge spans
    // patches only across curves that are not cut, drawn side by side).
    for (int h = 0; h < mesh.halfedgeCount(); ++h)
    {
      const int c = copyOfCorner_[h];
      if (c < 0)
        continue;
      const int v = copyVertex_[c];
      const int patch = net.patchOfTriangle[EditableMesh::triangleOf(h)];
      std::array<double, 3> b;
      if (!coordinatesInTriangle(domain, map.baseTriangle[v], map.baseCoordinates[v], patch, b) ||
        (atBarycentric(drawing_[patch], b) - copyPosition_[c]).norm() > 1e-6 * side_)
        return Status::error("global map: vertex " + std::to_string(v) + " lies apart in two patches");
    }

    x_.resize(2 * variables_);
    home_.assign(n, -1);
    homeDrawing_.assign(n, Drawing{});
    slideFrom_.assign(n, Vec2::Zero());
    slideAlong_.assign(n, Vec2::Zero());
    for (int v = 0; v < n; ++v)
      if (variable_[v] >= 0)
      {
        const int c = firstCopy_[v];
        x_.segment<2>(2 * variable_[v]) = copyPosition_[c];
        home_[v] = copyPatch_[c];
        homeDrawing_[v] = drawing_[copyPatch_[c]];
        if (!sliding_[v])
          continue;
        // A sliding vertex's home is its free patch, drawn in the plane of
        // its first copy (across its edge if that copy is on the fixed
        // side: the edge's ends are then the first copy's own); its
        // variable (t, 0), its place a + t (b - a), a and b its edge's ends.
        const int e = slideEdge_[v], patch = slidePatch_[v];
        if (copyPatch_[c] != patch)
        {
          const int k = baseEdgeCorner(domain, copyPatch_[c], e);
          int other = -1;
          if (k < 0)
            return Status::error("global map: vertex " + std::to_string(v) + " is not beside its curve's edge");
          homeDrawing_[v] = geometry_.unfold(copyPatch_[c], drawing_[copyPatch_[c]], k, other);
          if (other != patch)
            return Status::error("global map: vertex " + std::to_string(v) + " is not beside its curve's edge");
        }
        home_[v] = patch;
        const int ka = baseCorner(domain, patch, net.baseEdges[e][0]), kb = baseCorner(domain, patch, net.baseEdges[e][1]);
        if (ka < 0 || kb < 0)
          return Status::error("global map: vertex " + std::to_string(v) + " is not beside its curve's edge");
        slideFrom_[v] = homeDrawing_[v][ka];
        slideAlong_[v] = homeDrawing_[v][kb] - homeDrawing_[v][ka];
        const double t = (copyPosition_[c] - slideFrom_[v]).dot(slideAlong_[v]) / slideAlong_[v].squaredNorm();
        if (!(t > 0.0 && t < 1.0) ||
          std::abs(cross2(slideAlong_[v], copyPosition_[c] - slideFrom_[v])) > 1e-6 * side_ * slideAlong_[v].norm())
          return Status::error("global map: vertex " + std::to_string(v) + " of a fixed patch's curve is off its edge");
        x_.segment<2>(2 * variable_[v]) = Vec2(t, 0.0);
      }
    // Each triangle's share of the energy: its area, more near a landmark.
    weight_ = area_;
    if (options.landmarkWeightRadius > 0.0)
    {
      const double radius = options.landmarkWeightRadius * side_;
      for (int t = 0; t < triangles; ++t)
      {
        const Triangle& tri = mesh.triangle(t);
        const Vec3 c = (mesh.point(tri[0]) + mesh.point(tri[1]) + mesh.point(tri[2])) / 3.0;
        double nearest = kInfinity;
        for (int l : net.landmarkVertex)
          nearest = std::min(nearest, (mesh.point(l) - c).squaredNorm());
        weight_[t] *= 1.0 + (nearest > 0.0 ? std::min(options.landmarkWeightCap, radius * radius / nearest)
                                           : options.landmarkWeightCap);
      }
    }
    buildPattern();
    return {};
  }

  double side() const { return side_; }

  /// Curved parts sampled finer: each triangle's metric is inflated by s,
  /// s^2 = min(cap, 1 + c (kappa l)^2), kappa the largest turn of the
  /// vertex normals along its sides per length (sides shorter than l / 4
  /// count as l / 4) and l the side of a level-5 remesh triangle. The
  /// energy then gives a curved part (a tail's tip, an ear's rim) the
  /// parameter area of a larger flat one, so uniform remesh samples reach
  /// into it. The base triangles keep 1/F of the inflated area each.
  void inflateCurvedParts(double c, double cap)
  {
    const EditableMesh& mesh = *mesh_;
    const double l = side_ / 32.0;
    std::vector<Vec3> normal(mesh.vertexCount(), Vec3::Zero());
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      if (mesh.isRemoved(t))
        continue;
      const Triangle& tri = mesh.triangle(t);
      const Vec3 face = (mesh.point(tri[1]) - mesh.point(tri[0])).cross(mesh.point(tri[2]) - mesh.point(tri[0]));
      if (!(face.norm() > 0.0))
        continue;
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 a = mesh.point(tri[(k + 1) % 3]) - mesh.point(tri[k]);
        const Vec3 b = mesh.point(tri[(k + 2) % 3]) - mesh.point(tri[k]);
        normal[tri[k]] += std::atan2(a.cross(b).norm(), a.dot(b)) * face.normalized();
      }
    }
    for (Vec3& v : normal)
      if (v.norm() > 0.0)
        v.normalize();
    totalArea_ = 0.0;
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      if (mesh.isRemoved(t) || !(area_[t] > 0.0))
        continue;
      const Triangle& tri = mesh.triangle(t);
      double kappa = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        const int a = tri[k], b = tri[(k + 1) % 3];
        const double turn = std::acos(std::clamp(normal[a].dot(normal[b]), -1.0, 1.0));
        kappa = std::max(kappa, turn / std::max((mesh.point(a) - mesh.point(b)).norm(), 0.25 * l));
      }
      const double inflation = std::min(cap, 1.0 + c * kappa * kappa * l * l);
      area_[t] *= inflation;
      inverseEdges_[t] /= std::sqrt(inflation);
      totalArea_ += area_[t];
    }
    side_ = equilateralSide(totalArea_, baseTriangles_);
  }

  /// The base edge between base vertices `a` and `b`, -1 if none.
  int baseEdge(int a, int b) const
  {
    const auto found = edgeOf_.find(static_cast<long long>(std::min(a, b)) * baseVertices_ + std::max(a, b));
    return found == edgeOf_.end() ? -1 : found->second;
  }
  /// The corner of base triangle `patch` at base vertex `vertex`, -1 if none.
  static int baseCorner(const BaseDomain& domain, int patch, int vertex)
  {
    const Triangle& tri = domain.mesh.triangles[patch];
    for (int k = 0; k < 3; ++k)
      if (tri[k] == vertex)
        return k;
    return -1;
  }
  /// The side k (corners k, k + 1) of base triangle `patch` that is base
  /// edge `e`, -1 if none.
  int baseEdgeCorner(const BaseDomain& domain, int patch, int e) const
  {
    const Triangle& tri = domain.mesh.triangles[patch];
    for (int k = 0; k < 3; ++k)
      if (baseEdge(tri[k], tri[(k + 1) % 3]) == e)
        return k;
    return -1;
  }
  double totalArea() const { return totalArea_; }
  const Eigen::VectorXd& x() const { return x_; }
  /// Whether some vertex slides along its edge beside a fixed triangle.
  bool slides() const { return !slideTriangles_.empty(); }

  /// Free vertex v's place in the plane of its first copy for the variables
  /// `x`, and its direction for the step `d`: the variable itself, or for a
  /// sliding vertex a + t (b - a), t its variable's first entry (the second
  /// has no say).
  Vec2 place(int v, const Eigen::VectorXd& x) const
  {
    const int i = 2 * variable_[v];
    if (!sliding_[v])
      return x.segment<2>(i);
    return slideFrom_[v] + x(i) * slideAlong_[v];
  }
  Vec2 placeStep(int v, const Eigen::VectorXd& d) const
  {
    const int i = 2 * variable_[v];
    if (!sliding_[v])
      return d.segment<2>(i);
    return d(i) * slideAlong_[v];
  }
  /// d place / d variable: the identity, or for a sliding vertex the edge
  /// (b - a) in its first column and zero in its second.
  Mat2 placeJacobian(int v) const
  {
    if (!sliding_[v])
      return Mat2::Identity();
    Mat2 j = Mat2::Zero();
    j.col(0) = slideAlong_[v];
    return j;
  }

  /// Corner h's place for the variables `x` (its copy moved), and its
  /// direction for the step `d` (zero for a pinned vertex).
  Vec2 corner(int h, const Eigen::VectorXd& x) const
  {
    const int c = copyOfCorner_[h];
    const int v = copyVertex_[c];
    if (pinned_[v])
      return copyPosition_[c];
    return motion_[c](place(v, x));
  }
  Vec2 cornerStep(int h, const Eigen::VectorXd& d) const
  {
    const int c = copyOfCorner_[h];
    const int v = copyVertex_[c];
    if (pinned_[v])
      return Vec2::Zero();
    return motion_[c].rotation * placeStep(v, d);
  }

  Mat2 jacobian(int t, const Eigen::VectorXd& x) const
  {
    const Vec2 p0 = corner(3 * t, x), p1 = corner(3 * t + 1, x), p2 = corner(3 * t + 2, x);
    Mat2 edges;
    edges.col(0) = p1 - p0;
    edges.col(1) = p2 - p0;
    return edges * inverseEdges_[t];
  }

  bool flipped(int t, const Eigen::VectorXd& x) const
  {
    const Vec2 p0 = corner(3 * t, x), p1 = corner(3 * t + 1, x), p2 = corner(3 * t + 2, x);
    return !(cross2(p1 - p0, p2 - p0) > 0.0);
  }

  double energy(const Eigen::VectorXd& x) const
  {
    double sum = 0.0;
    for (int t = 0; t < mesh_->triangleCount(); ++t)
    {
      if (mesh_->isRemoved(t))
        continue;
      if (area_[t] > 0.0)
        sum += weight_[t] * density(jacobian(t, x));
      else if (watched_[t] && flipped(t, x)) // a fixed patch's corners are pinned but for sliding ones
        return kInfinity;
      if (!std::isfinite(sum))
        return kInfinity;
    }
    // A sliding vertex between its edge's ends (its neighbours along the
    // edge keep it there already: they would flip first).
    for (std::size_t v = 0; v < sliding_.size(); ++v)
      if (sliding_[v] && !(x(2 * variable_[v]) > 0.0 && x(2 * variable_[v]) < 1.0))
        return kInfinity;
    return sum;
  }

  /// The energy without the landmark weights.
  double plainEnergy(const Eigen::VectorXd& x) const
  {
    double sum = 0.0;
    for (int t = 0; t < mesh_->triangleCount(); ++t)
      if (!mesh_->isRemoved(t) && area_[t] > 0.0)
        sum += area_[t] * density(jacobian(t, x));
    return sum;
  }

  double largestDensity(const Eigen::VectorXd& x) const
  {
    double largest = 0.0;
    for (int t = 0; t < mesh_->triangleCount(); ++t)
      if (!mesh_->isRemoved(t) && area_[t] > 0.0)
        largest = std::max(largest, density(jacobian(t, x)));
    return largest;
  }

  /// The largest step along `d` that keeps every triangle unflipped.
  double stepBound(const Eigen::VectorXd& d) const
  {
    double bound = kInfinity;
    for (int t = 0; t < mesh_->triangleCount(); ++t)
    {
      if (mesh_->isRemoved(t))
        continue;
      const Vec2 p0 = corner(3 * t, x_), p1 = corner(3 * t + 1, x_), p2 = corner(3 * t + 2, x_);
      const Vec2 d0 = cornerStep(3 * t, d), d1 = cornerStep(3 * t + 1, d), d2 = cornerStep(3 * t + 2, d);
      bound = std::min(bound, flipBound(p1 - p0, p2 - p0, d1 - d0, d2 - d0));
    }
    return bound;
  }

  /// The sliding vertices that the step `d` would carry past where one of
  /// their fixed triangles flattens (before the full step): per variable
  /// entry (a sliding vertex's t), the fraction of its step it may take,
  /// half the way to the first such triangle.
  void blockedSlides(const Eigen::VectorXd& d, std::map<int, double>& fraction) const
  {
    fraction.clear();
    for (int t : slideTriangles_)
    {
      const Vec2 p0 = corner(3 * t, x_), p1 = corner(3 * t + 1, x_), p2 = corner(3 * t + 2, x_);
      const Vec2 d0 = cornerStep(3 * t, d), d1 = cornerStep(3 * t + 1, d), d2 = cornerStep(3 * t + 2, d);
      const double bound = flipBound(p1 - p0, p2 - p0, d1 - d0, d2 - d0);
      if (!(bound < 1.0))
        continue;
      for (int v : mesh_->triangle(t))
        if (sliding_[v])
        {
          const auto [at, added] = fraction.insert({ 2 * variable_[v], 0.5 * bound });
          if (!added)
            at->second = std::min(at->second, 0.5 * bound);
        }
    }
  }

  /// Gradient and projected Hessian at the current variables.
  void assemble(Eigen::VectorXd& gradient)
  {
    gradient.setZero(2 * variables_);
    std::fill(hessian_.valuePtr(), hessian_.valuePtr() + hessian_.nonZeros(), 0.0);
    double* values = hessian_.valuePtr();
    Eigen::Vector4d g;
    Eigen::Matrix4d hf;
    for (int t = 0; t < mesh_->triangleCount(); ++t)
    {
      if (mesh_->isRemoved(t) || !(area_[t] > 0.0))
        continue;
      const Mat2 f = jacobian(t, x_);
      densityDerivatives(f, g, hf);
      // vec(F) = B p, p = (p0x, p0y, p1x, p1y, p2x, p2y).
      const Mat2& m = inverseEdges_[t];
      Eigen::Matrix<double, 4, 6> b = Eigen::Matrix<double, 4, 6>::Zero();
      for (int j = 0; j < 2; ++j)     // column of F
        for (int i = 0; i < 2; ++i)   // row of F
        {
          const int row = 2 * j + i;
          b(row, 2 + i) = m(0, j);
          b(row, 4 + i) = m(1, j);
          b(row, i) = -(m(0, j) + m(1, j));
        }
      const Eigen::Matrix<double, 6, 1> gp = weight_[t] * b.transpose() * g;
      const Eigen::Matrix<double, 6, 6> hp = weight_[t] * b.transpose() * hf * b;
      // d corner / d variable: the copy's rotation after the place's own
      // (J^T g and J^T H J reduce a sliding vertex to its edge).
      std::array<Mat2, 3> chain;
      std::array<int, 3> var{};
      for (int k = 0; k < 3; ++k)
      {
        const int h = 3 * t + k;
        const int c = copyOfCorner_[h];
        const int v = copyVertex_[c];
        var[k] = variable_[v];
        if (var[k] >= 0)
          chain[k] = motion_[c].rotation * placeJacobian(v);
      }
      for (int a = 0; a < 3; ++a)
      {
        if (var[a] < 0)
          continue;
        gradient.segment<2>(2 * var[a]) += chain[a].transpose() * gp.segment<2>(2 * a);
        for (int bb = 0; bb < 3; ++bb)
        {
          if (var[bb] < 0)
            continue;
          const Mat2 block = chain[a].transpose() * hp.block<2, 2>(2 * a, 2 * bb) * chain[bb];
          const int* slot = &slots_[36 * t + 12 * a + 4 * bb];
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
              if (slot[2 * i + j] >= 0)
                values[slot[2 * i + j]] += block(i, j);
        }
      }
    }
    // A vertex only on flat triangles has no say: keep the matrix definite.
    double trace = 0.0;
    for (int i = 0; i < 2 * variables_; ++i)
      trace += values[diagonal_[i]];
    const double shift = 1e-9 * trace / std::max(1, 2 * variables_) + 1e-300;
    for (int i = 0; i < 2 * variables_; ++i)
      values[diagonal_[i]] += shift;
    // A sliding vertex's second entry has no say (a zero row and column, a
    // zero gradient): a diagonal of the matrix's scale keeps its step 0.
    for (std::size_t v = 0; v < sliding_.size(); ++v)
      if (sliding_[v])
        values[diagonal_[2 * variable_[v] + 1]] = trace / std::max(1, 2 * variables_) + 1e-300;
  }

  const Eigen::SparseMatrix<double>& hessian() const { return hessian_; }

  /// Moves the variables to `next`, following every free vertex's place
  /// across L0's triangles.
  bool moveTo(const Eigen::VectorXd& next)
  {
    for (std::size_t v = 0; v < variable_.size(); ++v)
    {
      const int i = variable_[v];
      if (i < 0 || sliding_[v])
        continue; // a sliding vertex stays in its free patch, on its edge
      if (!geometry_.walk(home_[v], homeDrawing_[v], x_.segment<2>(2 * i), next.segment<2>(2 * i)))
        return false;
    }
    x_ = next;
    return true;
  }

  /// Cuts the surface along the map's curves, the preimages of L0's edges,
  /// exactly: every mesh edge a curve crosses is split where it crosses,
  /// every triangle a curve runs through is cut along it, so that each
  /// curve runs along mesh edges and each triangle lies in one base
  /// triangle. The map is unchanged: a new vertex lies on its base edge, a
  /// triangle's image is a piece of its old image.
  Status cut(const StraightenedNet& straight, StraightenedNet& out, PatchParameterization& outMap) const
  {
    const EditableMesh& mesh = *mesh_;
    const TracedNet& net = *net_;
    const BaseDomain& domain = *domain_;
    const int n = mesh.vertexCount();
    const int triangles = mesh.triangleCount();
    const int baseEdges = static_cast<int>(net.baseEdges.size());
    const int baseVertices = domain.mesh.vertexCount();
    // Closer than this to a curve, a vertex is put on it: a curve passing
    // nearer would cut slivers round it, whose patch rounding decides.
    const double snap = 1e-6 * side_;
    std::vector<int> landmarkOf(n, -1);
    for (int b = 0; b < baseVertices; ++b)
      landmarkOf[net.landmarkVertex[b]] = b;
    const auto incident = [&](int landmark, int e) {
      return net.baseEdges[e][0] == landmark || net.baseEdges[e][1] == landmark;
    };

    // Per surface triangle, the base triangles its image overlaps, drawn in
    // its own frame (found across the base edges that cross its inside,
    // so never round a landmark onto another sheet).
    std::vector<int> overlayStart(triangles + 1, 0), overlayBase;
    std::vector<Drawing> overlayDrawing;
    std::vector<std::array<Vec2, 3>> cornerAt(triangles);
    for (int t = 0; t < triangles; ++t)
    {
      overlayStart[t] = static_cast<int>(overlayBase.size());
      const Triangle& tri = mesh.triangle(t);
      std::array<Vec2, 3>& p = cornerAt[t];
      for (int k = 0; k < 3; ++k)
        p[k] = corner(3 * t + k, x_);
      int base = -1;
      Drawing drawing;
      int free = -1;
      for (int k = 0; k < 3 && base < 0; ++k)
        if (variable_[tri[k]] >= 0)
        {
          const Motion& m = motion_[copyOfCorner_[3 * t + k]];
          base = home_[tri[k]];
          for (int c = 0; c < 3; ++c)
            drawing[c] = m(homeDrawing_[tri[k]][c]);
          free = k;
        }
      if (base < 0)
      {
        base = net.patchOfTriangle[t];
        drawing = drawing_[base];
      }
      // Start from the base triangle that holds the image's centroid,
      // walked to from the free corner (so on the image's own sheet round a
      // landmark): the corner may lie on a side of its own base triangle or
      // at the tip of a needle whose body lies beyond it.
      const Vec2 centroid = (p[0] + p[1] + p[2]) / 3.0;
      if (free >= 0)
      {
        const std::array<double, 3> b = barycentricIn(drawing, centroid);
        if (std::min({ b[0], b[1], b[2] }) < 0.0 && !geometry_.walk(base, drawing, p[free], centroid))
          return Status::error("cutting along the map: triangle " + std::to_string(t) + " could not be followed across L0");
      }
      std::vector<int> queue{ base };
      std::vector<Drawing> drawings{ drawing };
      for (std::size_t i = 0; i < queue.size(); ++i)
      {
        if (overlapArea(p, drawings[i]) > 0.0)
        {
          overlayBase.push_back(queue[i]);
          overlayDrawing.push_back(drawings[i]);
        }
        for (int j = 0; j < 3; ++j)
        {
          if (!crossesInside(p, drawings[i][j], drawings[i][(j + 1) % 3]))
            continue;
          int next = -1;
          const Drawing beside = geometry_.unfold(queue[i], drawings[i], j, next);
          if (std::find(queue.begin(), queue.end(), next) != queue.end())
            continue;
          queue.push_back(next);
          drawings.push_back(beside);
        }
      }
      if (overlayStart[t] == static_cast<int>(overlayBase.size()))
      {
        // An image too small for the clipping to measure (a surface
        // triangle of no area, its corners within rounding of each other)
        // lies in the base triangle that holds its centroid.
        overlayBase.push_back(queue[0]);
        overlayDrawing.push_back(drawings[0]);
      }
    }
    overlayStart[triangles] = static_cast<int>(overlayBase.size());

    // Each base edge drawn in a triangle's frame, from its first end to its
    // second (net.baseEdges order).
    const auto edgeIn = [&](int t, int e, Vec2& a, Vec2& b) {
      for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
      {
        const Triangle& bt = domain.mesh.triangles[overlayBase[i]];
        for (int j = 0; j < 3; ++j)
          if (baseEdge(bt[j], bt[(j + 1) % 3]) == e)
          {
            const bool forward = bt[j] == net.baseEdges[e][0];
            a = overlayDrawing[i][forward ? j : (j + 1) % 3];
            b = overlayDrawing[i][forward ? (j + 1) % 3 : j];
            return true;
          }
      }
      return false;
    };

    // A vertex within `snap` of a base edge (in a triangle's drawing of one
    // of the base triangles it overlaps, so on the right sheet) lies on it.
    std::vector<int> onEdge(n, -1);
    std::vector<double> onEdgeAt(n, 0.0);
    std::vector<double> onEdgeOff(n, 0.0); // and its distance from that edge
    std::vector<int> newEdge;        // per new vertex: its base edge
    std::vector<double> newAlong;    // and its place along it
    for (int t = 0; t < triangles; ++t)
      for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
      {
        const Triangle& bt = domain.mesh.triangles[overlayBase[i]];
        for (int j = 0; j < 3; ++j)
        {
          const int e = baseEdge(bt[j], bt[(j + 1) % 3]);
          Vec2 a = Vec2::Zero(), b = Vec2::Zero();
          edgeIn(t, e, a, b); // an edge of one of t's own base triangles
          const Vec2 d = b - a;
          for (int k = 0; k < 3; ++k)
          {
            const int v = mesh.triangle(t)[k];
            if (landmarkOf[v] >= 0 || onEdge[v] >= 0)
              continue;
            if ((pinned_[v] || sliding_[v]) && curveOf_[v] != e)
              continue; // a fixed patch's vertex lies on its own curve only
            const double f = cross2(d, cornerAt[t][k] - a) / d.norm();
            const double along = (cornerAt[t][k] - a).dot(d) / d.squaredNorm();
            if (std::abs(f) < snap && along > 0.0 && along < 1.0)
            {
              onEdge[v] = e;
              onEdgeAt[v] = along;
              onEdgeOff[v] = std::abs(f);
            }
          }
        }
      }
    // A triangle never has its three corners on one curve (a sliver along
    // it, in no patch): of three within `snap` of one base edge, the
    // farthest from it stays off.
    for (int t = 0; t < triangles; ++t)
    {
      const Triangle& tri = mesh.triangle(t);
      for (int k = 0; k < 3; ++k)
      {
        const int e = onEdge[tri[k]];
        if (e < 0)
          continue;
        int on = 0, farthest = -1;
        for (int v : tri)
        {
          const bool lies = landmarkOf[v] >= 0 ? incident(landmarkOf[v], e) : onEdge[v] == e;
          on += lies ? 1 : 0;
          // A pinned or sliding vertex lies on its own curve: never the one
          // to leave off.
          const auto distance = [&](int u) { return pinned_[u] || sliding_[u] ? -1.0 : onEdgeOff[u]; };
          if (lies && landmarkOf[v] < 0 && (farthest < 0 || distance(v) > distance(farthest)))
            farthest = v;
        }
        if (on == 3)
          onEdge[farthest] = -1;
      }
    }
    const auto vertexOnEdge = [&](int v, int e) {
      if (v >= n)
        return newEdge[v - n] == e;
      if (landmarkOf[v] >= 0)
        return incident(landmarkOf[v], e);
      return onEdge[v] == e;
    };

    // Where curves cross mesh edges: one new vertex per crossing, keyed by
    // the mesh edge (lower vertex first) and the base edge.
    TriangleMesh cutMesh;
    cutMesh.points = mesh.points();
    std::vector<SurfacePoint> inputPoint = straight.inputPoint;
    std::map<std::pair<long long, int>, int> crossing; // (mesh edge, base edge) -> vertex
    const auto meshEdgeKey = [&](int u, int w) { return static_cast<long long>(std::min(u, w)) * n + std::max(u, w); };
    for (int h = 0; h < mesh.halfedgeCount(); ++h)
    {
      const int u = mesh.from(h), w = mesh.to(h);
      if (u > w)
        continue; // each edge once, from its lower end, in its triangle's frame
      const int t = EditableMesh::triangleOf(h);
      const Vec2 pu = cornerAt[t][h % 3], pw = cornerAt[t][(h % 3 + 1) % 3];
      for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
      {
        const Triangle& bt = domain.mesh.triangles[overlayBase[i]];
        for (int j = 0; j < 3; ++j)
        {
          const int e = baseEdge(bt[j], bt[(j + 1) % 3]);
          if (crossing.count({ meshEdgeKey(u, w), e }))
            continue;
          if (vertexOnEdge(u, e) || vertexOnEdge(w, e))
            continue;
          Vec2 a = Vec2::Zero(), b = Vec2::Zero();
          edgeIn(t, e, a, b); // an edge of one of t's own base triangles
          const Vec2 d = b - a;
          // Both ends' sides in this one drawing (a line's far part lies
          // elsewhere on another sheet round a landmark).
          double fu = cross2(d, pu - a) / d.norm(), fw = cross2(d, pw - a) / d.norm();
          if (std::abs(fu) < snap)
            fu = fu < 0.0 ? -snap : snap;
          if (std::abs(fw) < snap)
            fw = fw < 0.0 ? -snap : snap;
          if (!((fu < 0.0 && fw > 0.0) || (fu > 0.0 && fw < 0.0)))
            continue;
          const double at = fu / (fu - fw);
          const Vec2 x = pu + at * (pw - pu);
          const double along = (x - a).dot(b - a) / (b - a).squaredNorm();
          if (along < -1e-9 || along > 1.0 + 1e-9)
            continue; // the line's extension beyond a landmark
          const int v = cutMesh.vertexCount();
          cutMesh.points.push_back((1.0 - at) * mesh.point(u) + at * mesh.point(w));
          inputPoint.push_back(interpolate(straight.inputPoint[u], straight.inputPoint[w], at));
          newEdge.push_back(e);
          newAlong.push_back(std::clamp(along, 0.0, 1.0));
          crossing[{ meshEdgeKey(u, w), e }] = v;
        }
      }
    }
    const auto crossingOn = [&](int u, int w, int e) {
      const auto found = crossing.find({ meshEdgeKey(u, w), e });
      return found == crossing.end() ? -1 : found->second;
    };
    // Each triangle cut along the curves through it.
    std::vector<int> inputTriangle;
    std::vector<int> patchOf;
    // Per new triangle, 1 for a sliver, whose centre may fall either side of
    // its curve: its image of rounding area, or no higher than 3 `snap`. A
    // corner snapped onto a curve lies up to `snap` off it, so a piece with
    // two such corners on one side and its third less than 2 `snap` beyond
    // the curve on the other has its centre on the first side (the camel on
    // L0 from the bull had 4 such pieces, 0.004 to 0.85 `snap` high; Spot on
    // L0 from 383 with a tail-tip cone 3, 1.6 `snap` high).
    std::vector<char> sliver;
    std::vector<std::vector<std::pair<int, int>>> curveEdges(baseEdges);
    for (int t = 0; t < triangles; ++t)
    {
      const Triangle& tri = mesh.triangle(t);
      // The boundary, corners and crossings counter-clockwise.
      std::vector<int> ring;
      std::vector<Vec2> at;
      std::vector<int> sideOfPoint; // the triangle edge a point lies on (-1: a corner)
      std::vector<int> cornerOfPoint;
      for (int k = 0; k < 3; ++k)
      {
        const int u = tri[k], w = tri[(k + 1) % 3];
        ring.push_back(u);
        at.push_back(cornerAt[t][k]);
        sideOfPoint.push_back(-1);
        cornerOfPoint.push_back(k);
        std::vector<std::pair<double, int>> along;
        for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
        {
          const Triangle& bt = domain.mesh.triangles[overlayBase[i]];
          for (int j = 0; j < 3; ++j)
          {
            const int v = crossingOn(u, w, baseEdge(bt[j], bt[(j + 1) % 3]));
            if (v < 0)
              continue;
            const Vec3 d = mesh.point(w) - mesh.point(u);
            const double s = (cutMesh.points[v] - mesh.point(u)).dot(d) / d.squaredNorm();
            if (std::find_if(along.begin(), along.end(), [&](const auto& a) { return a.second == v; }) == along.end())
              along.push_back({ s, v });
          }
        }
        std::sort(along.begin(), along.end());
        for (const auto& [s, v] : along)
        {
          ring.push_back(v);
          at.push_back(cornerAt[t][k] + s * (cornerAt[t][(k + 1) % 3] - cornerAt[t][k]));
          sideOfPoint.push_back(k);
          cornerOfPoint.push_back(-1);
        }
      }
      const int m = static_cast<int>(ring.size());
      // Chords: the two boundary points of each base edge through it.
      std::vector<std::pair<int, int>> chords;
      std::vector<int> seen;
      for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
      {
        const Triangle& bt = domain.mesh.triangles[overlayBase[i]];
        for (int j = 0; j < 3; ++j)
        {
          const int e = baseEdge(bt[j], bt[(j + 1) % 3]);
          if (std::find(seen.begin(), seen.end(), e) != seen.end())
            continue;
          seen.push_back(e);
          std::vector<int> points;
          for (int r = 0; r < m; ++r)
            if (vertexOnEdge(ring[r], e))
              points.push_back(r);
          if (points.size() < 2)
          {
            if (points.size() == 1 && cornerOfPoint[points[0]] < 0)
              return Status::error("cutting along the map: the curve of L0's edge " + std::to_string(e) +
                " enters triangle " + std::to_string(t) + " but does not leave it");
            continue;
          }
          if (points.size() > 2)
            return Status::error("cutting along the map: the curve of L0's edge " + std::to_string(e) +
              " meets triangle " + std::to_string(t) + " " + std::to_string(points.size()) + " times");
          const int a = points[0], b = points[1];
          if (cornerOfPoint[a] >= 0 && cornerOfPoint[b] >= 0)
          {
            // Two corners: along the triangle's side between them (a straight
            // curve through two corners runs along that side).
            curveEdges[e].push_back({ ring[a], ring[b] });
            continue;
          }
          if ((sideOfPoint[a] >= 0 && sideOfPoint[a] == sideOfPoint[b]) ||
            (cornerOfPoint[a] >= 0 && (sideOfPoint[b] == cornerOfPoint[a] || sideOfPoint[b] == (cornerOfPoint[a] + 2) % 3)) ||
            (cornerOfPoint[b] >= 0 && (sideOfPoint[a] == cornerOfPoint[b] || sideOfPoint[a] == (cornerOfPoint[b] + 2) % 3)))
            return Status::error("cutting along the map: the curve of L0's edge " + std::to_string(e) +
              " runs along a side of triangle " + std::to_string(t) + " it crosses");
          chords.push_back({ a, b });
          curveEdges[e].push_back({ ring[a], ring[b] });
        }
      }
      // The pieces the chords cut, each triangulated.
      std::vector<std::vector<int>> pieces{ std::vector<int>(m) };
      for (int i = 0; i < m; ++i)
        pieces[0][i] = i;
      for (const auto& [a, b] : chords)
      {
        bool split = false;
        for (std::size_t q = 0; q < pieces.size() && !split; ++q)
        {
          std::vector<int>& piece = pieces[q];
          const auto ia = std::find(piece.begin(), piece.end(), a), ib = std::find(piece.begin(), piece.end(), b);
          if (ia == piece.end() || ib == piece.end())
            continue;
          std::size_t i = ia - piece.begin(), j = ib - piece.begin();
          if (i > j)
            std::swap(i, j);
          std::vector<int> first(piece.begin() + i, piece.begin() + j + 1);
          std::vector<int> second(piece.begin() + j, piece.end());
          second.insert(second.end(), piece.begin(), piece.begin() + i + 1);
          piece = std::move(first);
          pieces.push_back(std::move(second));
          split = true;
        }
        if (!split)
          return Status::error("cutting along the map: two curves cross in triangle " + std::to_string(t));
      }
      for (const std::vector<int>& piece : pieces)
      {
        Vec2 centre = Vec2::Zero();
        for (int r : piece)
          centre += at[r];
        centre /= static_cast<double>(piece.size());
        int patch = -1;
        double best = -kInfinity;
        for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
        {
          const std::array<double, 3> b = barycentricIn(overlayDrawing[i], centre);
          const double lowest = std::min({ b[0], b[1], b[2] });
          if (lowest > best)
          {
            best = lowest;
            patch = overlayBase[i];
          }
        }
        std::vector<int> polygon = piece;
        while (polygon.size() >= 3)
        {
          // The ear with the widest smallest angle, never a flat one.
          const int size = static_cast<int>(polygon.size());
          int ear = -1;
          double widest = -1.0;
          for (int r = 0; r < size; ++r)
          {
            const Vec2& p0 = at[polygon[(r + size - 1) % size]];
            const Vec2& p1 = at[polygon[r]];
            const Vec2& p2 = at[polygon[(r + 1) % size]];
            const double area = cross2(p1 - p0, p2 - p0);
            if (!(area > 1e-14 * ((p1 - p0).squaredNorm() + (p2 - p0).squaredNorm())) && size > 3)
              continue;
            const double angle = smallestAngle(p0, p1, p2);
            if (angle > widest)
            {
              widest = angle;
              ear = r;
            }
          }
          if (ear < 0)
            ear = 0;
          cutMesh.triangles.push_back({ ring[polygon[(ear + size - 1) % size]], ring[polygon[ear]],
            ring[polygon[(ear + 1) % size]] });
          inputTriangle.push_back(straight.inputTriangle[t]);
          patchOf.push_back(patch);
          {
            const Vec2& q0 = at[polygon[(ear + size - 1) % size]];
            const Vec2& q1 = at[polygon[ear]];
            const Vec2& q2 = at[polygon[(ear + 1) % size]];
            const double area = 0.5 * cross2(q1 - q0, q2 - q0);
            const double longest = std::max({ (q1 - q0).norm(), (q2 - q1).norm(), (q0 - q2).norm() });
            sliver.push_back(area <= 1e-12 * side_ * side_ || 2.0 * area <= 3.0 * snap * longest);
          }
          polygon.erase(polygon.begin() + ear);
        }
      }
    }

    // The new layout: its curves chained from landmark to landmark.
    out = StraightenedNet{};
    if (Status s = out.net.mesh.build(cutMesh); !s.ok())
      return Status::error("cutting along the map: " + s.message());
    out.net.baseEdges = net.baseEdges;
    out.net.leftTriangle = net.leftTriangle;
    out.net.rightTriangle = net.rightTriangle;
    out.net.landmarkVertex = net.landmarkVertex;
    out.net.curves.assign(baseEdges, {});
    for (int e = 0; e < baseEdges; ++e)
    {
      std::unordered_map<int, std::vector<int>> next;
      for (const auto& [a, b] : curveEdges[e])
      {
        std::vector<int>& na = next[a];
        if (std::find(na.begin(), na.end(), b) == na.end())
        {
          na.push_back(b);
          next[b].push_back(a);
        }
      }
      std::vector<int>& curve = out.net.curves[e];
      int v = net.landmarkVertex[net.baseEdges[e][0]], previous = -1;
      const int end = net.landmarkVertex[net.baseEdges[e][1]];
      // A spur, edges that end short of a landmark (a vertex snapped onto
      // the curve beside where it runs), is no part of the curve: pruned,
      // its triangles are checked below like every other's.
      std::vector<int> loose;
      for (const auto& [k, around] : next)
        if (around.size() == 1 && k != v && k != end)
          loose.push_back(k);
      while (!loose.empty())
      {
        const int k = loose.back();
        loose.pop_back();
        std::vector<int>& around = next[k];
        if (around.size() != 1)
          continue;
        const int other = around.front();
        around.clear();
        std::vector<int>& back = next[other];
        back.erase(std::remove(back.begin(), back.end(), k), back.end());
        if (back.size() == 1 && other != v && other != end)
          loose.push_back(other);
      }
      curve.push_back(v);
      while (v != end)
      {
        const std::vector<int>& around = next[v];
        int step = -1;
        for (int u : around)
          if (u != previous)
            step = u;
        if (step < 0 || around.size() > (v == curve.front() ? 1u : 2u) || curve.size() > next.size())
          return Status::error("cutting along the map: the curve of L0's edge " + std::to_string(e) +
            " does not run from landmark to landmark");
        previous = v;
        v = step;
        curve.push_back(v);
      }
    }
    if (Status s = labelPatches(out.net); !s.ok())
      return Status::error("cutting along the map: " + s.message());
    // The curves' patches and each piece's own image agree but for slivers.
    int disagree = 0;
    for (int t = 0; t < out.net.mesh.triangleCount(); ++t)
      if (out.net.patchOfTriangle[t] != patchOf[t] && !sliver[t])
        ++disagree;
    if (disagree > 0)
      return Status::error("cutting along the map: " + std::to_string(disagree) +
        " triangles lie in another patch than their curves say");
    out.inputPoint = std::move(inputPoint);
    out.inputTriangle = std::move(inputTriangle);

    // Every vertex's place in the lowest-numbered patch holding it.
    const EditableMesh& cutEditable = out.net.mesh;
    const int vertices = cutEditable.vertexCount();
    outMap = PatchParameterization{};
    outMap.baseTriangle.assign(vertices, -1);
    outMap.baseCoordinates.assign(vertices, { 0.0, 0.0, 0.0 });
    for (int t = 0; t < cutEditable.triangleCount(); ++t)
      for (int v : cutEditable.triangle(t))
        if (outMap.baseTriangle[v] < 0 || out.net.patchOfTriangle[t] < outMap.baseTriangle[v])
          outMap.baseTriangle[v] = out.net.patchOfTriangle[t];
    for (int v = 0; v < vertices; ++v)
    {
      const int patch = outMap.baseTriangle[v];
      std::array<double, 3>& c = outMap.baseCoordinates[v];
      int from = -1;
      std::array<double, 3> place{ 0.0, 0.0, 0.0 };
      if (v < n && landmarkOf[v] >= 0)
      {
        const Triangle& bt = domain.mesh.triangles[patch];
        c = { 0.0, 0.0, 0.0 };
        c[std::find(bt.begin(), bt.end(), landmarkOf[v]) - bt.begin()] = 1.0;
        continue;
      }
      const int e = v >= n ? newEdge[v - n] : onEdge[v];
      if (e < 0)
        continue; // off the curves: from the overlay below
      const double along = v >= n ? newAlong[v - n] : onEdgeAt[v];
      from = net.leftTriangle[e];
      const Triangle& bt = domain.mesh.triangles[from];
      for (int k = 0; k < 3; ++k)
        place[k] = bt[k] == net.baseEdges[e][0] ? 1.0 - along : bt[k] == net.baseEdges[e][1] ? along : 0.0;
      if (!coordinatesInTriangle(domain, from, place, patch, c))
        return Status::error("cutting along the map: point " + std::to_string(v) + " on L0's edge " +
          std::to_string(e) + " lies in patch " + std::to_string(patch) + ", away from that edge");
    }
    // A point off the curves: where its old triangle's image puts it in
    // its patch (within rounding of the patch even beside a curve).
    std::vector<char> placed(vertices, 0);
    for (int t = 0; t < triangles; ++t)
      for (int k = 0; k < 3; ++k)
      {
        const int v = mesh.triangle(t)[k];
        if (placed[v] || landmarkOf[v] >= 0 || onEdge[v] >= 0)
          continue;
        for (int i = overlayStart[t]; i < overlayStart[t + 1]; ++i)
          if (overlayBase[i] == outMap.baseTriangle[v])
          {
            outMap.baseCoordinates[v] = barycentricIn(overlayDrawing[i], cornerAt[t][k]);
            placed[v] = 1;
          }
      }
    for (int v = 0; v < vertices; ++v)
    {
      std::array<double, 3>& c = outMap.baseCoordinates[v];
      if (v < n && landmarkOf[v] < 0 && onEdge[v] < 0 && !placed[v])
        return Status::error("cutting along the map: point " + std::to_string(v) + " has no place in its patch");
      double sum = 0.0;
      for (double& x : c)
        sum += (x = std::max(x, 0.0));
      for (double& x : c)
        x /= sum;
    }
    return {};
  }

  /// Every vertex's place (the landmarks' from `start`) and how many left
  /// their first patch.
  void places(const PatchParameterization& start, PatchParameterization& result, int& crossing) const
  {
    const int n = mesh_->vertexCount();
    result = PatchParameterization{};
    result.baseTriangle = start.baseTriangle;
    result.baseCoordinates = start.baseCoordinates;
    crossing = 0;
    for (int v = 0; v < n; ++v)
    {
      if (variable_[v] < 0)
        continue;
      if (sliding_[v])
      {
        // On its edge exactly: (1 - t, t) at its ends, 0 at the third corner.
        const int e = slideEdge_[v], patch = slidePatch_[v];
        const double t = x_(2 * variable_[v]);
        std::array<double, 3> b{ 0.0, 0.0, 0.0 };
        b[baseCorner(*domain_, patch, net_->baseEdges[e][0])] = 1.0 - t;
        b[baseCorner(*domain_, patch, net_->baseEdges[e][1])] = t;
        result.baseTriangle[v] = patch;
        result.baseCoordinates[v] = b;
        continue;
      }
      std::array<double, 3> b = barycentricIn(homeDrawing_[v], x_.segment<2>(2 * variable_[v]));
      double sum = 0.0;
      for (double& c : b)
        sum += (c = std::max(c, 0.0));
      for (double& c : b)
        c /= sum;
      result.baseTriangle[v] = home_[v];
      result.baseCoordinates[v] = b;
      if (home_[v] != copyPatch_[firstCopy_[v]])
        ++crossing;
    }
  }

private:
  /// Calls `visit(t, slot, row, col)` for every entry on or below the
  /// Hessian's diagonal that a triangle couples, `slot` its place among the
  /// triangle's 36 (corner a, corner b, coordinate i, coordinate j).
  template <class Visit>
  void forEachEntry(const Visit& visit) const
  {
    const EditableMesh& mesh = *mesh_;
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      if (mesh.isRemoved(t) || !(area_[t] > 0.0))
        continue;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
        {
          const int va = variable_[mesh.triangle(t)[a]], vb = variable_[mesh.triangle(t)[b]];
          if (va < 0 || vb < 0)
            continue;
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
              if (2 * va + i >= 2 * vb + j)
                visit(t, 12 * a + 4 * b + 2 * i + j, 2 * va + i, 2 * vb + j);
        }
    }
  }

  void buildPattern()
  {
    const EditableMesh& mesh = *mesh_;
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < 2 * variables_; ++i)
      entries.emplace_back(i, i, 0.0);
    forEachEntry([&](int, int, int row, int col) { entries.emplace_back(row, col, 0.0); });
    hessian_.resize(2 * variables_, 2 * variables_);
    hessian_.setFromTriplets(entries.begin(), entries.end());
    hessian_.makeCompressed();
    const auto slotOf = [&](int row, int col) {
      const int* begin = hessian_.innerIndexPtr() + hessian_.outerIndexPtr()[col];
      const int* end = hessian_.innerIndexPtr() + hessian_.outerIndexPtr()[col + 1];
      const int* found = std::lower_bound(begin, end, row);
      return static_cast<int>(found - hessian_.innerIndexPtr());
    };
    diagonal_.resize(2 * variables_);
    for (int i = 0; i < 2 * variables_; ++i)
      diagonal_[i] = slotOf(i, i);
    slots_.assign(36 * static_cast<std::size_t>(mesh.triangleCount()), -1);
    forEachEntry([&](int t, int slot, int row, int col) { slots_[36 * t + slot] = slotOf(row, col); });
  }

  const EditableMesh* mesh_ = nullptr;
  const TracedNet* net_ = nullptr;
  const BaseDomain* domain_ = nullptr;
  int baseVertices_ = 0;
  std::unordered_map<long long, int> edgeOf_; ///< Base edge of a sorted pair of base vertices.
  DomainGeometry geometry_;
  double side_ = 1.0;
  int baseTriangles_ = 0;
  double totalArea_ = 0.0;
  std::vector<double> area_;
  std::vector<double> weight_;        ///< Per triangle: its energy's factor (area x landmark weight).
  std::vector<Mat2> inverseEdges_;
  std::vector<char> used_;
  std::vector<char> pinned_;
  std::vector<char> fixedTriangle_;   ///< Per triangle: in a fixed patch (its corners pinned or sliding).
  std::vector<char> watched_;         ///< Per triangle: kept unflipped (not fixed, or with a sliding corner).
  std::vector<int> slideTriangles_;   ///< The fixed triangles with a sliding corner.
  std::vector<char> sliding_;         ///< Per vertex: on a curve between a fixed and a free patch, sliding along its edge.
  std::vector<int> slideEdge_;        ///< Per sliding vertex: its curve's base edge...
  std::vector<int> slidePatch_;       ///< ... the free patch beside it, its home...
  std::vector<Vec2> slideFrom_;       ///< ... the edge's first end (net.baseEdges order) in its home drawing...
  std::vector<Vec2> slideAlong_;      ///< ... and the edge from there to its second end.
  std::vector<int> curveOf_;          ///< Per vertex: the curve it lies inside, -1 if none.
  std::vector<Drawing> drawing_;      ///< Per base triangle, in the cut L0's plane.
  std::vector<int> copyOfCorner_;     ///< Per halfedge: the copy of its start vertex in its triangle.
  std::vector<int> copyVertex_;
  std::vector<int> copyPatch_;
  std::vector<Vec2> copyPosition_;    ///< Start place (kept by a pinned vertex's copies).
  std::vector<int> firstCopy_;
  std::vector<Motion> motion_;        ///< Per copy: from its vertex's first copy.
  std::vector<int> variable_;
  int variables_ = 0;
  Eigen::VectorXd x_;
  std::vector<int> home_;             ///< Per free vertex: the L0 triangle it lies in...
  std::vector<Drawing> homeDrawing_;  ///< ... drawn in the plane of its first copy.
  Eigen::SparseMatrix<double> hessian_;
  std::vector<int> slots_;
  std::vector<int> diagonal_;
};

} // namespace

namespace
{

/// The Newton step `step` (`solver` holding the factorized Hessian, at
/// `gradient`) with the sliding vertices it would carry past where a fixed
/// triangle flattens held to half that way, the rest the Newton step given
/// theirs (its multipliers from the same factorization: H d = -g + E l,
/// E the held entries, l so that they take their share). A fixed triangle
/// has no say in the energy, so nothing in the Newton step keeps a sliding
/// vertex from it; unheld, the line search (whose largest step is where
/// the first triangle would flatten) would crawl, every vertex held to that
/// one vertex's remaining way. Left as it is should the held step not go
/// downhill.
template <class Solver>
void limitSlides(const SeamlessProblem& problem, const Solver& solver, const Eigen::VectorXd& gradient,
  Eigen::VectorXd& step)
{
  const Eigen::VectorXd newton = step;
  std::vector<int> rows;
  std::vector<double> target;
  std::vector<Eigen::VectorXd> columns; // H^-1 e_row
  std::map<int, double> fraction;
  for (int round = 0; round < 8; ++round)
  {
    problem.blockedSlides(step, fraction);
    if (fraction.empty())
      break;
    for (const auto& [row, share] : fraction)
    {
      const auto at = std::find(rows.begin(), rows.end(), row);
      if (at != rows.end())
      {
        target[at - rows.begin()] = share * step(row);
        continue;
      }
      rows.push_back(row);
      target.push_back(share * step(row));
      Eigen::VectorXd unit = Eigen::VectorXd::Zero(step.size());
      unit(row) = 1.0;
      columns.push_back(solver.solve(unit));
    }
    const int m = static_cast<int>(rows.size());
    Eigen::MatrixXd inverse(m, m);
    Eigen::VectorXd missing(m);
    for (int i = 0; i < m; ++i)
    {
      for (int j = 0; j < m; ++j)
        inverse(i, j) = columns[j](rows[i]);
      missing(i) = target[i] - newton(rows[i]);
    }
    const Eigen::VectorXd multipliers = inverse.ldlt().solve(missing);
    if (!multipliers.allFinite())
    {
      step = newton;
      return;
    }
    step = newton;
    for (int j = 0; j < m; ++j)
      step += multipliers(j) * columns[j];
    for (int i = 0; i < m; ++i)
      step(rows[i]) = target[i];
  }
  if (!(gradient.dot(step) < 0.0) || !step.allFinite())
    step = newton;
}

/// Projected Newton steps on `problem` until a step gains little.
Status optimize(SeamlessProblem& problem, const GlobalMapOptions& options, GlobalMapReport& result)
{
  double energy = problem.energy(problem.x());
  if (!std::isfinite(energy))
    return Status::error("global map: the starting map has a flipped or crushed triangle");
  const double isometric = 4.0 * problem.totalArea();
  result.distortionBefore = problem.plainEnergy(problem.x()) / isometric;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool analyzed = false;
  Eigen::VectorXd gradient, step, trial;
  for (int iteration = 0; iteration < options.maximumIterations; ++iteration)
  {
    problem.assemble(gradient);
    if (!analyzed)
    {
      solver.analyzePattern(problem.hessian());
      analyzed = true;
    }
    solver.factorize(problem.hessian());
    if (solver.info() != Eigen::Success)
      break;
    step = solver.solve(-gradient);
    if (problem.slides())
      limitSlides(problem, solver, gradient, step);
    const double slope = gradient.dot(step);
    if (!(slope < 0.0) || !step.allFinite())
      break;
    // Never as far as a triangle flattening, then back until the energy
    // falls enough (Armijo).
    double alpha = std::min(1.0, 0.9 * problem.stepBound(step));
    double next = kInfinity;
    for (int tries = 0; tries < 40; ++tries)
    {
      trial = problem.x() + alpha * step;
      next = problem.energy(trial);
      if (next <= energy + 1e-4 * alpha * slope)
        break;
      alpha *= 0.5;
      next = kInfinity;
    }
    if (!std::isfinite(next) || !(next < energy))
      break;
    if (!problem.moveTo(trial))
      return Status::error("global map: a vertex's place could not be followed across L0");
    ++result.iterations;
    // Only a full step that gains little has settled. A step held back by a
    // triangle about to flatten gains little because it is short: a crushed
    // start (Spot on L0 from 383 with a tail-tip cone: the first step 7e-5
    // of its way, gaining 9e-5) then gains more with every step.
    const bool settled = alpha == 1.0 && energy - next < options.leastRelativeGain * energy;
    energy = next;
    if (settled)
      break;
  }
  result.distortionAfter = problem.plainEnergy(problem.x()) / isometric;
  result.maximumDistortion = problem.largestDensity(problem.x()) / 4.0;
  return {};
}

} // namespace

Status checkGlobalMapOptions(const GlobalMapOptions& options)
{
  if (options.maximumIterations < 0)
    return Status::error("global map: maximumIterations must be 0 or more (it is " +
      std::to_string(options.maximumIterations) + ")");
  if (!(options.leastRelativeGain >= 0.0) || !std::isfinite(options.leastRelativeGain))
    return Status::error("global map: leastRelativeGain must be a finite number >= 0");
  if (!(options.curvatureDensity >= 0.0) || !std::isfinite(options.curvatureDensity) ||
    !(options.curvatureDensityCap >= 1.0) || !std::isfinite(options.curvatureDensityCap))
    return Status::error("global map: curvatureDensity must be finite and >= 0, curvatureDensityCap finite and >= 1");
  if (!(options.landmarkWeightRadius >= 0.0) || !std::isfinite(options.landmarkWeightRadius) ||
    !(options.landmarkWeightCap > 0.0) || !std::isfinite(options.landmarkWeightCap))
    return Status::error("global map: landmarkWeightRadius must be finite and >= 0, landmarkWeightCap finite and > 0");
  return {};
}

namespace
{

/// The map of `net`'s surface from `start` optimized in `problem`.
Status solve(const TracedNet& net, const BaseDomain& domain, const PatchParameterization& start,
  const GlobalMapOptions& options, SeamlessProblem& problem, GlobalMapReport& report)
{
  if (Status s = checkGlobalMapOptions(options); !s.ok())
    return s;
  if (Status s = problem.build(net, domain, start, options); !s.ok())
    return s;
  return optimize(problem, options, report);
}

} // namespace

Status optimizeGlobalMap(const TracedNet& net, const BaseDomain& domain, const PatchParameterization& start,
  PatchParameterization& result, const GlobalMapOptions& options, GlobalMapReport* report)
{
  SeamlessProblem problem;
  GlobalMapReport figures;
  if (Status s = solve(net, domain, start, options, problem, figures); !s.ok())
    return s;
  problem.places(start, result, figures.crossingVertices);
  if (report)
    *report = figures;
  return {};
}

Status freeCurves(const StraightenedNet& straight, const BaseDomain& domain, const PatchParameterization& map,
  const GlobalMapOptions& options, StraightenedNet& out, PatchParameterization& outMap, FreeCurvesReport* report)
{
  FreeCurvesReport result;
  SeamlessProblem problem;
  if (Status s = solve(straight.net, domain, map, options, problem, result.map); !s.ok())
    return s;
  PatchParameterization places;
  problem.places(map, places, result.map.crossingVertices);
  StraightenedNet cut;
  PatchParameterization cutMap;
  const Status s = problem.cut(straight, cut, cutMap);
  result.applied = s.ok();
  if (s.ok())
  {
    out = std::move(cut);
    outMap = std::move(cutMap);
  }
  else
  {
    result.reason = s.message();
    out = straight;
    outMap = map;
  }
  if (report)
    *report = result;
  return {};
}

} // namespace cmp
