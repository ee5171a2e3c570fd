#include "FoldRepair.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace cmp
{

namespace
{

/// Directions tried around a vertex, and the fractions of its reach.
constexpr int kDirections = 16;
constexpr double kStepFractions[] = { 0.05, 0.1, 0.2, 0.4, 0.8 };
/// Surface triangles crossed by one walk at most (a walk is shorter than a
/// remesh edge, so this only stops a walk circling a degenerate spot).
constexpr int kMaximumCrossings = 2000;
/// A vertex's reach is counted in its shortest edge, but never in more than
/// this share of the remesh's median edge.
constexpr double kTypicalEdgeShare = 0.25;
/// Shape quality below which a triangle counts as bad while repairing, so
/// that unfolding never pays with a collapsed triangle.
constexpr double kLeastQuality = 1e-3;

/// A point of the surface: a triangle and barycentric coordinates in the
/// order of its vertices.
struct SurfacePoint
{
  int triangle = -1;
  Eigen::Vector3d coordinates = Eigen::Vector3d::Zero();
};

Vec3 unitNormal(const EditableMesh& surface, int t)
{
  const Triangle& tri = surface.triangle(t);
  const Vec3 n = (surface.point(tri[1]) - surface.point(tri[0])).cross(surface.point(tri[2]) - surface.point(tri[0]));
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

Vec3 positionOf(const EditableMesh& surface, const SurfacePoint& p)
{
  const Triangle& tri = surface.triangle(p.triangle);
  return p.coordinates[0] * surface.point(tri[0]) + p.coordinates[1] * surface.point(tri[1]) +
    p.coordinates[2] * surface.point(tri[2]);
}

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

/// Moves `p` by `step` along the surface: straight within a triangle, and
/// across an edge the rest of the step is turned about that edge into the
/// next triangle's plane (the surface unfolded locally). Stops early at a
/// degenerate triangle.
SurfacePoint walk(const EditableMesh& surface, SurfacePoint p, Vec3 step)
{
  for (int crossing = 0; crossing < kMaximumCrossings; ++crossing)
  {
    const Vec3 normal = unitNormal(surface, p.triangle);
    step -= normal * normal.dot(step);
    Eigen::Vector3d target;
    if (normal.isZero() || !planeCoordinates(surface, p.triangle, positionOf(surface, p) + step, target))
      return p;
    if (target.minCoeff() >= 0.0)
    {
      p.coordinates = target;
      return p;
    }
    // The side left first: the corner whose coordinate reaches zero first.
    int corner = -1;
    double fraction = 1.0;
    for (int k = 0; k < 3; ++k)
      if (target[k] < 0.0)
      {
        const double at = p.coordinates[k] / (p.coordinates[k] - target[k]);
        if (corner < 0 || at < fraction)
          corner = k, fraction = at;
      }
    fraction = std::clamp(fraction, 0.0, 1.0);
    Eigen::Vector3d exit = (p.coordinates + fraction * (target - p.coordinates)).cwiseMax(0.0);
    exit[corner] = 0.0;
    exit /= exit.sum();

    const int h = 3 * p.triangle + (corner + 1) % 3; // runs along the side left
    const int across = surface.opposite(h);
    if (across < 0)
    {
      p.coordinates = exit;
      return p;
    }
    const int u = surface.from(h), v = surface.to(h);
    const Vec3 along = (surface.point(v) - surface.point(u)).normalized();
    const Vec3 rest = (1.0 - fraction) * step;
    const double alongLength = rest.dot(along);
    const double acrossLength = (rest - alongLength * along).norm();
    const int next = EditableMesh::triangleOf(across);
    const int apex = surface.from(EditableMesh::prev(across));
    Vec3 inward = surface.point(apex) - surface.point(u);
    inward -= along * along.dot(inward);
    if (inward.norm() > 0.0)
      inward.normalize();
    step = alongLength * along + acrossLength * inward;

    SurfacePoint entered;
    entered.triangle = next;
    const Triangle& tri = surface.triangle(next);
    for (int k = 0; k < 3; ++k)
      entered.coordinates[k] = tri[k] == u ? exit[(corner + 1) % 3] : tri[k] == v ? exit[(corner + 2) % 3] : 0.0;
    p = entered;
    if (step.squaredNorm() == 0.0)
      return p;
  }
  return p;
}

/// The remesh around the samples: positions, surface normals under each
/// vertex, and which triangles touch which vertex.
class FoldedRemesh
{
public:
  FoldedRemesh(const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfaceSample>& samples)
    : remesh_(remesh)
    , surface_(surface)
    , points_(samples.size())
    , positions_(samples.size())
    , normals_(samples.size(), Vec3::Zero())
    , trianglesOf_(samples.size())
    , neighbours_(samples.size())
  {
    for (std::size_t v = 0; v < samples.size(); ++v)
    {
      positions_[v] = Vec3::Zero();
      for (int k = 0; k < 3; ++k)
        if (samples[v].vertex[k] >= 0)
          positions_[v] += samples[v].weight[k] * surface.point(samples[v].vertex[k]);
      if (samples[v].triangle < 0)
        continue; // a landmark: pinned, and records no normal
      SurfacePoint& p = points_[v];
      p.triangle = samples[v].triangle;
      const Triangle& tri = surface.triangle(p.triangle);
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          if (tri[k] == samples[v].vertex[j])
            p.coordinates[k] += samples[v].weight[j];
      normals_[v] = unitNormal(surface, p.triangle);
    }
    for (int t = 0; t < static_cast<int>(remesh.triangles.size()); ++t)
      for (int k = 0; k < 3; ++k)
      {
        const int a = remesh.triangles[t][k], b = remesh.triangles[t][(k + 1) % 3];
        trianglesOf_[a].push_back(t);
        neighbours_[a].push_back(b);
        neighbours_[b].push_back(a);
      }
    for (std::vector<int>& around : neighbours_)
    {
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
    }
  }

  bool pinned(int v) const { return points_[v].triangle < 0; }
  const Vec3& position(int v) const { return positions_[v]; }
  const Vec3& normal(int v) const { return normals_[v]; }
  const SurfacePoint& point(int v) const { return points_[v]; }
  const std::vector<int>& neighbours(int v) const { return neighbours_[v]; }

  void moveTo(int v, const SurfacePoint& p)
  {
    points_[v] = p;
    positions_[v] = positionOf(surface_, p);
    normals_[v] = unitNormal(surface_, p.triangle);
  }

  /// Shape quality of triangle `t` (1 when equilateral, 0 when flat),
  /// negative when it faces against the surface under it; 1 when all its
  /// corners are landmarks, which record no surface normal.
  double signedQuality(int t) const
  {
    const Triangle& tri = remesh_.triangles[t];
    const Vec3 &a = positions_[tri[0]], &b = positions_[tri[1]], &c = positions_[tri[2]];
    const Vec3 under = normals_[tri[0]] + normals_[tri[1]] + normals_[tri[2]];
    const double squaredSides = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    if (under.isZero())
      return 1.0;
    if (!(squaredSides > 0.0))
      return 0.0;
    return 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).dot(under.normalized()) / squaredSides;
  }

  /// Bad triangles around `v` (folded, or so flat that a fold was traded
  /// for a collapse), and the worst signed quality among them.
  std::pair<int, double> aroundVertex(int v) const
  {
    std::pair<int, double> score{ 0, 1.0 };
    for (int t : trianglesOf_[v])
    {
      const double a = signedQuality(t);
      score.first += a < kLeastQuality;
      score.second = std::min(score.second, a);
    }
    return score;
  }

  /// Movable vertices of folded triangles, those with most folds around
  /// them first: a vertex pushed across its neighbours folds all its own
  /// triangles, and moving it back beats moving each neighbour.
  std::vector<int> verticesOfFoldedTriangles() const
  {
    std::vector<int> folds(positions_.size(), 0);
    std::vector<int> vertices;
    for (int t = 0; t < static_cast<int>(remesh_.triangles.size()); ++t)
      if (signedQuality(t) < 0.0)
        for (int v : remesh_.triangles[t])
          if (!pinned(v) && folds[v]++ == 0)
            vertices.push_back(v);
    std::stable_sort(vertices.begin(), vertices.end(), [&](int a, int b) { return folds[a] > folds[b]; });
    return vertices;
  }

  int foldedCount() const
  {
    int folded = 0;
    for (int t = 0; t < static_cast<int>(remesh_.triangles.size()); ++t)
      folded += signedQuality(t) < 0.0;
    return folded;
  }

private:
  const SemiRegularMesh& remesh_;
  const EditableMesh& surface_;
  std::vector<SurfacePoint> points_;
  std::vector<Vec3> positions_;
  std::vector<Vec3> normals_;
  std::vector<std::vector<int>> trianglesOf_;
  std::vector<std::vector<int>> neighbours_;
};

/// Tries short moves of `v` around its current place and keeps the best;
/// returns whether it moved.
bool improveVertex(const EditableMesh& surface, FoldedRemesh& mesh, int v, const Vec3& origin, double reach)
{
  const std::pair<int, double> current = mesh.aroundVertex(v);
  if (current.first == 0)
    return false;
  double shortest = std::numeric_limits<double>::infinity();
  for (int w : mesh.neighbours(v))
    shortest = std::min(shortest, (mesh.position(w) - mesh.position(v)).norm());
  const Vec3 normal = mesh.normal(v);
  const Vec3 first = normal.unitOrthogonal(), second = normal.cross(first);
  const SurfacePoint start = mesh.point(v);
  SurfacePoint best = start;
  std::pair<int, double> bestScore = current;
  for (double fraction : kStepFractions)
    for (int k = 0; k < kDirections; ++k)
    {
      const double angle = 2.0 * M_PI * k / kDirections;
      const SurfacePoint tried =
        walk(surface, start, fraction * shortest * (std::cos(angle) * first + std::sin(angle) * second));
      mesh.moveTo(v, tried);
      if ((mesh.position(v) - origin).norm() > reach)
        continue;
      const std::pair<int, double> score = mesh.aroundVertex(v);
      // Fewer folds first, then a fatter worst triangle: a sliver that
      // agrees with the surface is one small tilt away from folding.
      if (score.first < bestScore.first || (score.first == bestScore.first && score.second > bestScore.second))
      {
        bestScore = score;
        best = tried;
      }
    }
  mesh.moveTo(v, best);
  return bestScore != current; // only a better score replaces the start
}

} // namespace

int countFoldedTriangles(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfaceSample>& samples)
{
  return FoldedRemesh(remesh, surface, samples).foldedCount();
}

std::vector<char> foldedTriangles(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfaceSample>& samples)
{
  const FoldedRemesh mesh(remesh, surface, samples);
  std::vector<char> folded(remesh.triangles.size(), 0);
  for (std::size_t t = 0; t < folded.size(); ++t)
    folded[t] = mesh.signedQuality(static_cast<int>(t)) < 0.0;
  return folded;
}

Status repairFolds(const SemiRegularMesh& remesh, const EditableMesh& surface, std::vector<SurfaceSample>& samples,
  const FoldRepairOptions& options, FoldRepairReport* report)
{
  if (samples.size() != static_cast<std::size_t>(remesh.vertexCount()))
    return Status::error("fold repair: " + std::to_string(samples.size()) + " samples for a remesh of " +
      std::to_string(remesh.vertexCount()) + " vertices");
  for (const SurfaceSample& s : samples)
    if (s.triangle >= surface.triangleCount())
      return Status::error("fold repair: a sample names surface triangle " + std::to_string(s.triangle) +
        " of " + std::to_string(surface.triangleCount()));
  if (!(options.reach >= 0.0) || options.maximumSweeps < 0)
    return Status::error("fold repair: the reach must be >= 0 and the sweeps >= 0");

  FoldedRemesh mesh(remesh, surface, samples);
  const int n = remesh.vertexCount();
  std::vector<Vec3> origin(n);
  std::vector<double> shortest(n, std::numeric_limits<double>::infinity()), lengths;
  for (int v = 0; v < n; ++v)
  {
    origin[v] = mesh.position(v);
    for (int w : mesh.neighbours(v))
    {
      const double length = (mesh.position(w) - origin[v]).norm();
      shortest[v] = std::min(shortest[v], length);
      if (v < w)
        lengths.push_back(length);
    }
  }
  // Long edges mean a coarsely sampled part (a tip, a ridge), where moving
  // a vertex by its own edge length would cut into the shape: there the
  // reach is counted in typical edges instead.
  double typicalEdge = 0.0;
  if (!lengths.empty())
  {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    typicalEdge = lengths[lengths.size() / 2];
  }
  std::vector<double> reach(n, 0.0);
  for (int v = 0; v < n; ++v)
    if (std::isfinite(shortest[v]))
      reach[v] = options.reach * std::min(shortest[v], kTypicalEdgeShare * typicalEdge);
  FoldRepairReport result;
  result.foldedBefore = mesh.foldedCount();
  std::vector<char> moved(n, 0);
  for (int sweep = 0; sweep < options.maximumSweeps; ++sweep)
  {
    bool any = false;
    for (int v : mesh.verticesOfFoldedTriangles())
      if (improveVertex(surface, mesh, v, origin[v], reach[v]))
        any = true, moved[v] = 1;
    if (!any)
      break;
  }
  result.foldedAfter = mesh.foldedCount();

  for (int v = 0; v < n; ++v)
  {
    if (!moved[v])
      continue;
    ++result.movedVertices;
    result.largestMove = std::max(result.largestMove, (mesh.position(v) - origin[v]).norm());
    const SurfacePoint& p = mesh.point(v);
    SurfaceSample& s = samples[v];
    s.triangle = p.triangle;
    for (int k = 0; k < 3; ++k)
    {
      s.vertex[k] = surface.triangle(p.triangle)[k];
      s.weight[k] = p.coordinates[k];
    }
  }
  if (report)
    *report = result;
  return {};
}

} // namespace cmp
