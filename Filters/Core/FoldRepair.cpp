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
/// Joint untangling of what single moves leave: rings of vertices around
/// each remaining fold, gradient steps at most, halvings of a step at most,
/// and the shape quality above which a triangle no longer pulls.
constexpr int kUntangledRings = 3;
constexpr int kUntangleIterations = 300;
constexpr int kBacktrackingSteps = 12;
constexpr double kFatEnough = 0.05;

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
  const std::vector<int>& trianglesOf(int v) const { return trianglesOf_[v]; }
  int neighbourCount() const { return static_cast<int>(neighbours_.size()); }
  const Triangle& triangle(int t) const { return remesh_.triangles[t]; }
  int triangleCount() const { return static_cast<int>(remesh_.triangles.size()); }
  /// Gradient of signedQuality(t) with respect to corner k's position
  /// (the surface normals under the corners held fixed).
  Vec3 qualityGradient(int t, int k) const
  {
    const Triangle& tri = remesh_.triangles[t];
    const Vec3 &a = positions_[tri[k]], &b = positions_[tri[(k + 1) % 3]], &c = positions_[tri[(k + 2) % 3]];
    const Vec3 under = normals_[tri[0]] + normals_[tri[1]] + normals_[tri[2]];
    if (under.isZero())
      return Vec3::Zero();
    const Vec3 u = under.normalized();
    const double squaredSides = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    if (!(squaredSides > 0.0))
      return Vec3::Zero();
    const double n = (b - a).cross(c - a).dot(u);
    const Vec3 dn = (b - c).cross(u);
    const Vec3 dS = 2.0 * (2.0 * a - b - c);
    return 2.0 * std::sqrt(3.0) * (dn * squaredSides - n * dS) / (squaredSides * squaredSides);
  }

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

/// The vertices within `rings` edges of a folded triangle.
std::vector<int> regionAroundFolds(const FoldedRemesh& mesh, int rings)
{
  std::vector<char> inRegion(mesh.neighbourCount(), 0);
  std::vector<int> region;
  const auto add = [&](int v)
  {
    if (!inRegion[v])
      inRegion[v] = 1, region.push_back(v);
  };
  for (int t = 0; t < mesh.triangleCount(); ++t)
    if (mesh.signedQuality(t) < 0.0)
      for (int v : mesh.triangle(t))
        add(v);
  for (int ring = 0, begin = 0; ring < rings; ++ring)
  {
    const int end = static_cast<int>(region.size());
    for (int i = begin; i < end; ++i)
      for (int w : mesh.neighbours(region[i]))
        add(w);
    begin = end;
  }
  return region;
}

/// Penalty of a triangle of signed quality q: zero once it is fat enough,
/// so it pushes folded triangles and needles alike towards fatter shapes.
double penalty(double q)
{
  return q < kFatEnough ? (kFatEnough - q) * (kFatEnough - q) : 0.0;
}

/// Gradient of the penalty of the triangles around `v` with respect to its
/// position, in the tangent plane.
Vec3 penaltyGradient(const FoldedRemesh& mesh, int v)
{
  Vec3 gradient = Vec3::Zero();
  for (int t : mesh.trianglesOf(v))
  {
    const double q = mesh.signedQuality(t);
    if (q >= kFatEnough)
      continue;
    const Triangle& tri = mesh.triangle(t);
    const int corner = static_cast<int>(std::find(tri.begin(), tri.end(), v) - tri.begin());
    gradient += -2.0 * (kFatEnough - q) * mesh.qualityGradient(t, corner);
  }
  return gradient - mesh.normal(v) * mesh.normal(v).dot(gradient);
}

/// Where single moves are stuck (a band of needles sheared at the scale of
/// several triangles, each move folding a neighbour), moves every vertex
/// near the remaining folds at once down the gradient of the penalty of
/// their triangles, along the surface and within `reach` of `origin`, with
/// a backtracking step. A step may fold a triangle on the way as long as
/// the penalty falls; the state with fewest folds is kept, and nothing
/// moves unless it has fewer folds than the start.
void untangle(const EditableMesh& surface, FoldedRemesh& mesh, const std::vector<Vec3>& origin, double reach)
{
  std::vector<int> region = regionAroundFolds(mesh, kUntangledRings);
  region.erase(std::remove_if(region.begin(), region.end(), [&](int v) { return mesh.pinned(v); }), region.end());
  std::vector<int> triangles;
  for (int v : region)
    triangles.insert(triangles.end(), mesh.trianglesOf(v).begin(), mesh.trianglesOf(v).end());
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  const auto measure = [&](int& folded)
  {
    double total = 0.0;
    folded = 0;
    for (int t : triangles)
    {
      const double q = mesh.signedQuality(t);
      total += penalty(q);
      folded += q < 0.0;
    }
    return total;
  };
  const auto snapshot = [&]
  {
    std::vector<SurfacePoint> points;
    for (int v : region)
      points.push_back(mesh.point(v));
    return points;
  };
  const auto restore = [&](const std::vector<SurfacePoint>& points)
  {
    for (std::size_t i = 0; i < region.size(); ++i)
      mesh.moveTo(region[i], points[i]);
  };

  int folded = 0;
  double energy = measure(folded);
  const int foldedAtStart = folded;
  const std::vector<SurfacePoint> atStart = snapshot();
  int fewestFolded = folded;
  std::vector<SurfacePoint> fewest = atStart;
  double step = 1.0; // of the reach, for the vertex with the steepest gradient
  for (int iteration = 0; iteration < kUntangleIterations && folded > 0; ++iteration)
  {
    std::vector<Vec3> gradient(region.size());
    double steepest = 0.0;
    for (std::size_t i = 0; i < region.size(); ++i)
      steepest = std::max(steepest, (gradient[i] = penaltyGradient(mesh, region[i])).norm());
    if (!(steepest > 0.0))
      break;
    const std::vector<SurfacePoint> start = snapshot();
    bool lowered = false;
    for (int attempt = 0; attempt < kBacktrackingSteps && !lowered; ++attempt, step *= 0.5)
    {
      for (std::size_t i = 0; i < region.size(); ++i)
      {
        const int v = region[i];
        mesh.moveTo(v, walk(surface, start[i], -step * reach * gradient[i] / steepest));
        if ((mesh.position(v) - origin[v]).norm() > reach)
          mesh.moveTo(v, start[i]);
      }
      int trialFolded = 0;
      const double trial = measure(trialFolded);
      if ((lowered = trial < energy))
        energy = trial, folded = trialFolded;
      else
        restore(start);
    }
    if (!lowered)
      break;
    step = std::min(1.0, 4.0 * step);
    if (folded < fewestFolded)
      fewestFolded = folded, fewest = snapshot();
  }
  // Moving many vertices for fatter needles alone is not worth it.
  if (fewestFolded == foldedAtStart)
    restore(atStart);
  else if (folded > fewestFolded)
    restore(fewest);
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
  std::vector<SurfacePoint> placed;
  for (int v = 0; v < n; ++v)
    placed.push_back(mesh.point(v));
  for (int sweep = 0; sweep < options.maximumSweeps; ++sweep)
  {
    bool any = false;
    for (int v : mesh.verticesOfFoldedTriangles())
      any = improveVertex(surface, mesh, v, origin[v], reach[v]) || any;
    if (!any)
      break;
  }
  if (mesh.foldedCount() > 0)
    untangle(surface, mesh, origin, options.reach * kTypicalEdgeShare * typicalEdge);
  result.foldedAfter = mesh.foldedCount();

  for (int v = 0; v < n; ++v)
  {
    const SurfacePoint& p = mesh.point(v);
    // A vertex put back, or walked onto the same point seen from the next
    // triangle, keeps its sample as placed.
    if (mesh.pinned(v) || (p.triangle == placed[v].triangle && p.coordinates == placed[v].coordinates) ||
        mesh.position(v) == origin[v])
      continue;
    ++result.movedVertices;
    result.largestMove = std::max(result.largestMove, (mesh.position(v) - origin[v]).norm());
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
