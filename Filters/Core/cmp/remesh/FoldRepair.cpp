#include <cmp/remesh/FoldRepair.h>

#include <cmp/mesh/SurfaceDistance.h>
#include <cmp/mesh/SurfaceWalk.h>
#include <cmp/mesh/TriangleShape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cmp
{

namespace
{

/// Directions tried around a vertex, and the step lengths tried, as
/// fractions of its current shortest, mean and longest edge: in a band of
/// needles the shortest edge is a needle's width, while the move that
/// unfolds it runs along the needle.
constexpr int kDirections = 16;
constexpr double kStepFractions[] = { 0.05, 0.1, 0.2, 0.4, 0.8 };
/// Reaches are counted in this share of the remesh's median edge.
constexpr double kTypicalEdgeShare = 0.25;
/// Shape quality below which a triangle counts as bad while repairing, so
/// that unfolding never pays with a collapsed triangle.
constexpr double kLeastQuality = 1e-3;
/// Joint untangling of the regions around the folds, before single moves:
/// rings of vertices around each fold, gradient steps at most, halvings of
/// a step at most, and the shape quality above which a triangle no longer
/// pulls.
constexpr int kUntangledRings = 5;
constexpr int kUntangleIterations = 300;
constexpr int kBacktrackingSteps = 12;
constexpr double kFatEnough = 0.05;
/// Most widenings of the regions' reach accepted (each is one more pass).
constexpr int kMostRegionWidening = 64;

/// Shape quality of triangle (a, b, c) (1 when equilateral, 0 when flat),
/// negative when it faces against `under`; 1 when `under` is zero (all
/// corners are landmarks, which record no surface normal).
double signedQuality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& under)
{
  return under.isZero() ? 1.0 : signedTriangleShapeQuality(a, b, c, under.normalized());
}

/// Gradient of signedQuality(a, b, c, under) with respect to `a`, `under`
/// held fixed.
Vec3 signedQualityGradient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& under)
{
  const double squaredSides = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  if (under.isZero() || !(squaredSides > 0.0))
    return Vec3::Zero();
  const Vec3 u = under.normalized();
  const double n = (b - a).cross(c - a).dot(u);
  const Vec3 dn = (b - c).cross(u), dS = 2.0 * (2.0 * a - b - c);
  return 2.0 * std::sqrt(3.0) * (dn * squaredSides - n * dS) / (squaredSides * squaredSides);
}

/// Checks that `samples` fit `remesh` and `surface`: one per vertex, each a
/// landmark (triangle -1) or a convex combination of the vertices of a
/// live surface triangle.
Status checkSamples(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples)
{
  const int n = remesh.vertexCount();
  if (samples.size() != static_cast<std::size_t>(n))
    return Status::error("fold repair: " + std::to_string(samples.size()) + " samples for a remesh of " +
      std::to_string(n) + " vertices");
  for (std::size_t t = 0; t < remesh.triangles.size(); ++t)
    for (int v : remesh.triangles[t])
      if (v < 0 || v >= n)
        return Status::error("fold repair: remesh triangle " + std::to_string(t) + " has vertex " +
          std::to_string(v) + " of " + std::to_string(n));
  for (int v = 0; v < n; ++v)
  {
    const SurfacePoint& s = samples[v];
    const std::string which = "fold repair: sample " + std::to_string(v);
    if (s.triangle < -1 || s.triangle >= surface.triangleCount())
      return Status::error(which + " names surface triangle " + std::to_string(s.triangle) + " of " +
        std::to_string(surface.triangleCount()));
    if (s.triangle >= 0 && surface.isRemoved(s.triangle))
      return Status::error(which + " names removed surface triangle " + std::to_string(s.triangle));
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      if (s.vertex[k] >= surface.vertexCount() || (s.vertex[k] < 0 && s.weight[k] != 0.0))
        return Status::error(which + " names surface vertex " + std::to_string(s.vertex[k]));
      if (s.triangle >= 0 && s.weight[k] != 0.0)
      {
        const Triangle& tri = surface.triangle(s.triangle);
        if (std::find(tri.begin(), tri.end(), s.vertex[k]) == tri.end())
          return Status::error(which + ": its vertices are not those of its triangle " + std::to_string(s.triangle));
      }
      if (!(s.weight[k] >= 0.0))
        return Status::error(which + ": its weights are not barycentric (finite, >= 0, sum 1)");
      sum += s.weight[k];
    }
    if (!(std::abs(sum - 1.0) < 1e-9))
      return Status::error(which + ": its weights are not barycentric (finite, >= 0, sum 1)");
  }
  return {};
}

/// Per remesh triangle, its signed quality against the surface under it.
std::vector<double> triangleQualities(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples)
{
  std::vector<Vec3> positions(samples.size()), normals(samples.size(), Vec3::Zero());
  for (std::size_t v = 0; v < samples.size(); ++v)
  {
    positions[v] = samplePosition(surface, samples[v]);
    if (samples[v].triangle >= 0)
      normals[v] = surfaceTriangleNormal(surface, samples[v].triangle);
  }
  std::vector<double> qualities(remesh.triangles.size());
  for (std::size_t t = 0; t < qualities.size(); ++t)
  {
    const Triangle& tri = remesh.triangles[t];
    qualities[t] = signedQuality(positions[tri[0]], positions[tri[1]], positions[tri[2]],
      normals[tri[0]] + normals[tri[1]] + normals[tri[2]]);
  }
  return qualities;
}

/// What moving one vertex does to the triangles around it.
struct VertexScore
{
  int folds = 0;      ///< Triangles facing against the surface.
  int bad = 0;        ///< Folded or flatter than kLeastQuality.
  double worst = 1.0; ///< The smallest signed quality.

  /// Fewer bad triangles, then a fatter worst one: a sliver that agrees
  /// with the surface is one small tilt away from folding.
  bool betterThan(const VertexScore& other) const
  {
    return bad < other.bad || (bad == other.bad && worst > other.worst);
  }
};

/// The remesh vertices joined to each vertex by an edge, sorted, without
/// repeats; edges with a corner outside the remesh are left out.
std::vector<std::vector<int>> vertexNeighbours(const SemiRegularMesh& remesh)
{
  const int n = remesh.vertexCount();
  std::vector<std::vector<int>> neighbours(n);
  for (const Triangle& tri : remesh.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = tri[k], b = tri[(k + 1) % 3];
      if (a >= 0 && a < n && b >= 0 && b < n)
      {
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
      }
    }
  for (std::vector<int>& around : neighbours)
  {
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
  return neighbours;
}

/// The remesh on the surface while it is repaired: where each vertex is,
/// the surface normal under it, and which triangles and vertices touch it.
/// The centroid criterion for one triangle (a, b, c): whether its normal
/// points against that of the `surface` triangle nearest to its centroid.
/// Zero area on either side gives a zero product: not flipped.
bool facesAgainstNearest(const Vec3& a, const Vec3& b, const Vec3& c, const ClosestPointQuery& query,
  const TriangleMesh& surface)
{
  const ClosestPointQuery::Result nearest = query.closest((a + b + c) / 3.0);
  if (nearest.at.triangle < 0)
    return false;
  const Triangle& under = surface.triangles[nearest.at.triangle];
  const Vec3 there =
    (surface.points[under[1]] - surface.points[under[0]]).cross(surface.points[under[2]] - surface.points[under[0]]);
  return (b - a).cross(c - a).dot(there) < 0.0;
}

class FoldedRemesh
{
public:
  /// Samples must have passed checkSamples().
  FoldedRemesh(const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples)
    : remesh_(remesh)
    , surface_(surface)
    , points_(samples.size())
    , positions_(samples.size())
    , normals_(samples.size(), Vec3::Zero())
    , trianglesOf_(samples.size())
    , neighbours_(vertexNeighbours(remesh))
  {
    for (std::size_t v = 0; v < samples.size(); ++v)
    {
      positions_[v] = samplePosition(surface, samples[v]);
      if (samples[v].triangle < 0)
        continue; // a landmark: pinned, and records no normal
      SurfacePoint& p = points_[v];
      p.triangle = samples[v].triangle;
      const Triangle& tri = surface.triangle(p.triangle);
      p.vertex = tri;
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          if (tri[k] == samples[v].vertex[j])
            p.weight[k] += samples[v].weight[j];
      normals_[v] = surfaceTriangleNormal(surface, p.triangle);
    }
    for (int t = 0; t < triangleCount(); ++t)
      for (int v : remesh.triangles[t])
        trianglesOf_[v].push_back(t);
    // A vertex of an open remesh's boundary (more neighbours than
    // triangles) stays on the surface's boundary: it never moves.
    boundary_.assign(samples.size(), 0);
    for (std::size_t v = 0; v < samples.size(); ++v)
      boundary_[v] = neighbours_[v].size() > trianglesOf_[v].size();
  }

  int vertexCount() const { return static_cast<int>(positions_.size()); }
  int triangleCount() const { return static_cast<int>(remesh_.triangles.size()); }
  const Triangle& triangle(int t) const { return remesh_.triangles[t]; }
  bool pinned(int v) const { return points_[v].triangle < 0 || boundary_[v]; }
  const Vec3& position(int v) const { return positions_[v]; }
  const Vec3& normal(int v) const { return normals_[v]; }
  const SurfacePoint& point(int v) const { return points_[v]; }
  const std::vector<int>& neighbours(int v) const { return neighbours_[v]; }
  const std::vector<int>& trianglesOf(int v) const { return trianglesOf_[v]; }

  void moveTo(int v, const SurfacePoint& p)
  {
    points_[v] = p;
    positions_[v] = surfacePosition(surface_, p);
    normals_[v] = surfaceTriangleNormal(surface_, p.triangle);
  }

  double signedQuality(int t) const
  {
    const Triangle& tri = remesh_.triangles[t];
    return cmp::signedQuality(positions_[tri[0]], positions_[tri[1]], positions_[tri[2]], under(t));
  }

  /// Gradient of signedQuality(t) with respect to the position of its
  /// corner `v`.
  Vec3 qualityGradient(int t, int v) const
  {
    const Triangle& tri = remesh_.triangles[t];
    const int k = static_cast<int>(std::find(tri.begin(), tri.end(), v) - tri.begin());
    return signedQualityGradient(
      positions_[tri[k]], positions_[tri[(k + 1) % 3]], positions_[tri[(k + 2) % 3]], under(t));
  }

  VertexScore aroundVertex(int v) const
  {
    VertexScore score;
    for (int t : trianglesOf_[v])
    {
      const double q = signedQuality(t);
      score.folds += q < 0.0;
      score.bad += q < kLeastQuality;
      score.worst = std::min(score.worst, q);
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
    for (int t = 0; t < triangleCount(); ++t)
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
    for (int t = 0; t < triangleCount(); ++t)
      folded += signedQuality(t) < 0.0;
    return folded;
  }

  /// Whether triangle `t` faces against the surface triangle nearest to
  /// its centroid (the centroid criterion, `centroidFlippedTriangles()`).
  bool centroidFlipped(int t, const ClosestPointQuery& query, const TriangleMesh& flat) const
  {
    const Triangle& tri = remesh_.triangles[t];
    return facesAgainstNearest(positions_[tri[0]], positions_[tri[1]], positions_[tri[2]], query, flat);
  }

private:
  /// The surface normal under triangle `t`: the sum of its corners'.
  Vec3 under(int t) const
  {
    const Triangle& tri = remesh_.triangles[t];
    return normals_[tri[0]] + normals_[tri[1]] + normals_[tri[2]];
  }

  const SemiRegularMesh& remesh_;
  const EditableMesh& surface_;
  std::vector<SurfacePoint> points_;
  std::vector<Vec3> positions_;
  std::vector<Vec3> normals_;
  std::vector<std::vector<int>> trianglesOf_;
  std::vector<std::vector<int>> neighbours_;
  std::vector<char> boundary_; ///< Per vertex: on the remesh's boundary (open surfaces), so pinned.
};

/// Tries short moves of `v` around its current place (16 directions of its
/// tangent plane, walked on the surface, within `reach` of `origin`) and
/// keeps the best-scored one that `keeps` accepts against the score where
/// it stands (`Score` has `betterThan()`); returns whether it moved.
template <class ScoreOf, class Keeps>
bool tryShortMoves(const EditableMesh& surface, FoldedRemesh& mesh, int v, const Vec3& origin, double reach,
  const ScoreOf& scoreOf, const Keeps& keeps)
{
  if (mesh.neighbours(v).empty())
    return false;
  const auto current = scoreOf(v);
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.0, sum = 0.0;
  for (int w : mesh.neighbours(v))
  {
    const double length = (mesh.position(w) - mesh.position(v)).norm();
    shortest = std::min(shortest, length), longest = std::max(longest, length), sum += length;
  }
  const double scales[] = { shortest, sum / static_cast<double>(mesh.neighbours(v).size()), longest };
  const Vec3 normal = mesh.normal(v);
  const Vec3 first = normal.unitOrthogonal(), second = normal.cross(first);
  const SurfacePoint start = mesh.point(v);
  SurfacePoint best = start;
  auto bestScore = current;
  bool moved = false;
  for (double scale : scales)
  for (double fraction : kStepFractions)
    for (int k = 0; k < kDirections; ++k)
    {
      const double angle = 2.0 * kPi * k / kDirections;
      const SurfacePoint tried =
        walkOnSurface(surface, start, fraction * scale * (std::cos(angle) * first + std::sin(angle) * second));
      mesh.moveTo(v, tried);
      if ((mesh.position(v) - origin).norm() > reach)
        continue;
      const auto score = scoreOf(v);
      if (keeps(score, current) && score.betterThan(bestScore))
        bestScore = score, best = tried, moved = true;
    }
  mesh.moveTo(v, best);
  return moved;
}

/// Tries short moves of `v` around its current place and keeps the best
/// one that folds no more triangles around it; returns whether it moved.
bool improveVertex(const EditableMesh& surface, FoldedRemesh& mesh, int v, const Vec3& origin, double reach)
{
  if (mesh.aroundVertex(v).folds == 0)
    return false;
  return tryShortMoves(surface, mesh, v, origin, reach, [&](int w) { return mesh.aroundVertex(w); },
    [](const VertexScore& score, const VertexScore& current) { return score.folds <= current.folds; });
}

/// What moving one vertex does to the centroid criterion around it, the
/// folds and shapes as in `VertexScore`.
struct FlipScore
{
  VertexScore shape;
  int flips = 0; ///< Triangles flipped by the centroid criterion.

  bool betterThan(const FlipScore& other) const
  {
    return shape.folds < other.shape.folds ||
      (shape.folds == other.shape.folds &&
        (flips < other.flips || (flips == other.flips && shape.betterThan(other.shape))));
  }
};

/// Tries short moves of `v`, a corner of a triangle flipped by the centroid
/// criterion, and keeps the best one that folds no more triangles and
/// flips fewer round it; returns whether it moved.
bool unflipVertex(const EditableMesh& surface, FoldedRemesh& mesh, int v, const Vec3& origin, double reach,
  const ClosestPointQuery& query, const TriangleMesh& flat)
{
  const auto scoreOf = [&](int w) {
    FlipScore score;
    score.shape = mesh.aroundVertex(w);
    for (int t : mesh.trianglesOf(w))
      score.flips += mesh.centroidFlipped(t, query, flat) ? 1 : 0;
    return score;
  };
  if (scoreOf(v).flips == 0)
    return false;
  return tryShortMoves(surface, mesh, v, origin, reach, scoreOf, [](const FlipScore& score, const FlipScore& current) {
    return score.shape.folds <= current.shape.folds && score.flips < current.flips;
  });
}

/// The movable vertices within `rings` edges of a folded triangle.
std::vector<int> regionAroundFolds(const FoldedRemesh& mesh, int rings)
{
  std::vector<char> inRegion(mesh.vertexCount(), 0);
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
  region.erase(std::remove_if(region.begin(), region.end(), [&](int v) { return mesh.pinned(v); }), region.end());
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
    if (q < kFatEnough)
      gradient += -2.0 * (kFatEnough - q) * mesh.qualityGradient(t, v);
  }
  return gradient - mesh.normal(v) * mesh.normal(v).dot(gradient);
}

/// The vertices near the remaining folds and the triangles they touch, for
/// moving them together.
class FoldRegion
{
public:
  FoldRegion(FoldedRemesh& mesh, std::vector<int> vertices)
    : mesh_(mesh)
    , vertices_(std::move(vertices))
  {
    for (int v : vertices_)
      triangles_.insert(triangles_.end(), mesh.trianglesOf(v).begin(), mesh.trianglesOf(v).end());
    std::sort(triangles_.begin(), triangles_.end());
    triangles_.erase(std::unique(triangles_.begin(), triangles_.end()), triangles_.end());
  }

  const std::vector<int>& vertices() const { return vertices_; }

  /// Total penalty of the region's triangles, and how many are folded.
  double penalty(int& folded) const
  {
    double total = 0.0;
    folded = 0;
    for (int t : triangles_)
    {
      const double q = mesh_.signedQuality(t);
      total += cmp::penalty(q);
      folded += q < 0.0;
    }
    return total;
  }

  std::vector<SurfacePoint> snapshot() const
  {
    std::vector<SurfacePoint> points;
    for (int v : vertices_)
      points.push_back(mesh_.point(v));
    return points;
  }

  void restore(const std::vector<SurfacePoint>& points)
  {
    for (std::size_t i = 0; i < vertices_.size(); ++i)
      mesh_.moveTo(vertices_[i], points[i]);
  }

private:
  FoldedRemesh& mesh_;
  std::vector<int> vertices_;
  std::vector<int> triangles_;
};

/// One backtracking gradient step of the whole region: the steepest vertex
/// moves `step` times `reach`, the others in proportion, each along the
/// surface and staying within `reach` of `origin`; the step halves until
/// the penalty falls. Returns the step taken (0 if none lowered it).
double descend(const EditableMesh& surface, FoldedRemesh& mesh, FoldRegion& region, const std::vector<Vec3>& origin,
  double reach, double step, double& energy, int& folded)
{
  const std::vector<int>& vertices = region.vertices();
  std::vector<Vec3> gradient(vertices.size());
  double steepest = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    steepest = std::max(steepest, (gradient[i] = penaltyGradient(mesh, vertices[i])).norm());
  if (!(steepest > 0.0))
    return 0.0;
  const std::vector<SurfacePoint> start = region.snapshot();
  for (int attempt = 0; attempt < kBacktrackingSteps; ++attempt, step *= 0.5)
  {
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
      const int v = vertices[i];
      mesh.moveTo(v, walkOnSurface(surface, start[i], -step * reach * gradient[i] / steepest));
      if ((mesh.position(v) - origin[v]).norm() > reach)
        mesh.moveTo(v, start[i]);
    }
    int trialFolded = 0;
    const double trial = region.penalty(trialFolded);
    if (trial < energy)
    {
      energy = trial;
      folded = trialFolded;
      return step;
    }
    region.restore(start);
  }
  return 0.0;
}

/// Moves one connected part of the vertices near the remaining folds
/// together down the gradient of their triangles' penalty. A step may fold
/// a triangle on the way as long as the penalty falls; the state with
/// fewest folds is kept, and nothing moves unless it has fewer folds than
/// the start.
void untanglePart(
  const EditableMesh& surface, FoldedRemesh& mesh, const std::vector<Vec3>& origin, double reach, std::vector<int> part)
{
  FoldRegion region(mesh, std::move(part));
  int folded = 0;
  double energy = region.penalty(folded);
  const int foldedAtStart = folded;
  const std::vector<SurfacePoint> atStart = region.snapshot();
  int fewestFolded = folded;
  std::vector<SurfacePoint> fewest = atStart;
  double step = 1.0;
  for (int iteration = 0; iteration < kUntangleIterations && folded > 0; ++iteration)
  {
    const double taken = descend(surface, mesh, region, origin, reach, step, energy, folded);
    if (!(taken > 0.0))
      break;
    step = std::min(1.0, 2.0 * taken);
    if (folded < fewestFolded)
      fewestFolded = folded, fewest = region.snapshot();
  }
  // Moving many vertices for fatter needles alone is not worth it.
  if (fewestFolded == foldedAtStart)
    region.restore(atStart);
  else if (folded > fewestFolded)
    region.restore(fewest);
}

/// `vertices` split into parts connected by remesh edges.
std::vector<std::vector<int>> connectedParts(const FoldedRemesh& mesh, const std::vector<int>& vertices)
{
  std::vector<int> partOf(mesh.vertexCount(), -2); // -2: not given, -1: given, not yet reached
  for (int v : vertices)
    partOf[v] = -1;
  std::vector<std::vector<int>> parts;
  for (int seed : vertices)
  {
    if (partOf[seed] != -1)
      continue;
    parts.emplace_back();
    std::vector<int>& part = parts.back();
    partOf[seed] = static_cast<int>(parts.size()) - 1;
    part.push_back(seed);
    for (std::size_t i = 0; i < part.size(); ++i)
      for (int w : mesh.neighbours(part[i]))
        if (partOf[w] == -1)
          partOf[w] = partOf[seed], part.push_back(w);
  }
  return parts;
}

/// Untangles the vertices within a few rings of the folds (a band of needles
/// sheared at the scale of several triangles, where each single move would
/// fold a neighbour), each connected part on its own so that one stiff spot
/// does not hold back the step elsewhere.
void untangle(const EditableMesh& surface, FoldedRemesh& mesh, const std::vector<Vec3>& origin, double reach)
{
  for (std::vector<int>& part : connectedParts(mesh, regionAroundFolds(mesh, kUntangledRings)))
    untanglePart(surface, mesh, origin, reach, std::move(part));
}

/// The median length of the remesh's edges.
double medianEdgeLength(const FoldedRemesh& mesh)
{
  std::vector<double> lengths;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    for (int w : mesh.neighbours(v))
      if (v < w)
        lengths.push_back((mesh.position(w) - mesh.position(v)).norm());
  if (lengths.empty())
    return 0.0;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

/// Writes every vertex that left its sample's point back into `samples`,
/// and counts those whose position changed.
void writeBack(const FoldedRemesh& mesh, const std::vector<SurfacePoint>& placed,
  const std::vector<Vec3>& origin, std::vector<SurfacePoint>& samples, FoldRepairReport& report)
{
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const SurfacePoint& p = mesh.point(v);
    if (mesh.pinned(v) || (p.triangle == placed[v].triangle && p.weight == placed[v].weight))
      continue;
    samples[v] = p; // in the order of its triangle's corners
    // The same point seen from the next triangle is not a move.
    const double moved = (mesh.position(v) - origin[v]).norm();
    if (moved > 0.0)
    {
      ++report.movedVertices;
      report.largestMove = std::max(report.largestMove, moved);
    }
  }
}

} // namespace

int countFoldedTriangles(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples)
{
  const std::vector<double> qualities = triangleQualities(remesh, surface, samples);
  return static_cast<int>(std::count_if(qualities.begin(), qualities.end(), [](double q) { return q < 0.0; }));
}

std::vector<char> foldedTriangles(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples)
{
  const std::vector<double> qualities = triangleQualities(remesh, surface, samples);
  std::vector<char> folded(qualities.size());
  std::transform(qualities.begin(), qualities.end(), folded.begin(), [](double q) { return q < 0.0; });
  return folded;
}

std::vector<char> centroidFlippedTriangles(const TriangleMesh& surface, const TriangleMesh& placed)
{
  std::vector<char> flipped(placed.triangles.size(), 0);
  const ClosestPointQuery query(surface);
  for (std::size_t t = 0; t < placed.triangles.size(); ++t)
  {
    const Triangle& triangle = placed.triangles[t];
    flipped[t] = facesAgainstNearest(
      placed.points[triangle[0]], placed.points[triangle[1]], placed.points[triangle[2]], query, surface);
  }
  return flipped;
}

std::vector<int> nearestLandmarkOfTriangles(const SemiRegularMesh& remesh, int landmarkCount)
{
  const int vertexCount = remesh.vertexCount();
  if (landmarkCount < 0 || landmarkCount > vertexCount)
    return {};
  const std::vector<std::vector<int>> neighbours = vertexNeighbours(remesh);
  // Breadth first from all landmarks at once: every vertex keeps the
  // landmark that reaches it first.
  std::vector<int> distance(vertexCount, -1), nearest(vertexCount, -1), queue;
  for (int f = 0; f < landmarkCount; ++f)
  {
    distance[f] = 0;
    nearest[f] = f;
    queue.push_back(f);
  }
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (int w : neighbours[queue[i]])
      if (distance[w] < 0)
      {
        distance[w] = distance[queue[i]] + 1;
        nearest[w] = nearest[queue[i]];
        queue.push_back(w);
      }
  std::vector<int> result(remesh.triangles.size(), -1);
  for (std::size_t t = 0; t < remesh.triangles.size(); ++t)
  {
    int closest = -1;
    for (int v : remesh.triangles[t])
      if (v >= 0 && v < vertexCount && nearest[v] >= 0 &&
        (closest < 0 || distance[v] < distance[closest] ||
          (distance[v] == distance[closest] && nearest[v] < nearest[closest])))
        closest = v;
    if (closest >= 0)
      result[t] = nearest[closest];
  }
  return result;
}

std::vector<int> foldsNearLandmarks(
  const std::vector<int>& nearestLandmark, int landmarkCount, const std::vector<char>& folded)
{
  if (folded.size() != nearestLandmark.size() || landmarkCount < 0)
    return {};
  std::vector<int> counts(landmarkCount, 0);
  for (std::size_t t = 0; t < folded.size(); ++t)
    if (folded[t] && nearestLandmark[t] >= 0 && nearestLandmark[t] < landmarkCount)
      ++counts[nearestLandmark[t]];
  return counts;
}

std::vector<int> foldsNearLandmarks(
  const SemiRegularMesh& remesh, int landmarkCount, const std::vector<char>& folded)
{
  if (folded.size() != remesh.triangles.size() || landmarkCount < 0 || landmarkCount > remesh.vertexCount())
    return {};
  return foldsNearLandmarks(nearestLandmarkOfTriangles(remesh, landmarkCount), landmarkCount, folded);
}

Status repairFolds(const SemiRegularMesh& remesh, const EditableMesh& surface, std::vector<SurfacePoint>& samples,
  const FoldRepairOptions& options, FoldRepairReport* report)
{
  if (Status status = checkSamples(remesh, surface, samples); !status.ok())
    return status;
  if (!(options.reach >= 0.0) || options.maximumSweeps < 0)
    return Status::error("fold repair: the reach must be >= 0 and the sweeps >= 0");
  if (options.regionWidening < 1 || options.regionWidening > kMostRegionWidening)
    return Status::error("fold repair: the region widening must be between 1 and " +
      std::to_string(kMostRegionWidening) + ", not " + std::to_string(options.regionWidening));
  if (!(options.singleWidening >= 1.0 && options.singleWidening <= kMostRegionWidening))
    return Status::error("fold repair: the single moves' widening must be between 1 and " +
      std::to_string(kMostRegionWidening) + ", not " + std::to_string(options.singleWidening));
  FoldRepairReport result;
  result.foldedBefore = result.foldedAfter = countFoldedTriangles(remesh, surface, samples);
  FoldedRemesh mesh(remesh, surface, samples);
  std::vector<Vec3> origin;
  std::vector<SurfacePoint> placed;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    origin.push_back(mesh.position(v)), placed.push_back(mesh.point(v));
  const double typicalEdge = kTypicalEdgeShare * medianEdgeLength(mesh);
  // How far a vertex may go alone: a fixed share of the median edge, not
  // of its own edges (in a band of needles its shortest edge is a needle's
  // width, and no move within that unfolds the band; a long edge is a
  // coarsely sampled tip, where a move that long would cut into the shape).
  const double singleReach = options.singleWidening * options.reach * typicalEdge;
  if (result.foldedBefore > 0)
  {
    // Regions first: single moves made first settle into a state where a
    // fan of needles is locked (each vertex's best move folds a neighbour)
    // and the regions' descent then often stalls there; after the regions,
    // single moves only clean up isolated folds.
    const double regionReach = options.reach * typicalEdge;
    for (int widening = 1; widening <= options.regionWidening && mesh.foldedCount() > 0; ++widening)
      untangle(surface, mesh, origin, widening * regionReach);
    for (int sweep = 0; sweep < options.maximumSweeps && mesh.foldedCount() > 0; ++sweep)
    {
      bool any = false;
      for (int v : mesh.verticesOfFoldedTriangles())
        any = improveVertex(surface, mesh, v, origin[v], singleReach) || any;
      if (!any)
        break;
    }
  }
  if (options.centroidFlips)
  {
    // Then the centroid criterion: a triangle whose corners lie on one side
    // of a thin part while its middle hangs over the other, by single moves
    // that fold nothing more.
    const TriangleMesh flat = surface.toTriangleMesh();
    const ClosestPointQuery query(flat);
    std::vector<int> flips, vertices;
    // The flipped triangles' movable corners, those in most flips first.
    const auto collect = [&]() {
      flips.assign(mesh.vertexCount(), 0);
      vertices.clear();
      int count = 0;
      for (int t = 0; t < mesh.triangleCount(); ++t)
        if (mesh.centroidFlipped(t, query, flat))
        {
          ++count;
          for (int v : mesh.triangle(t))
            if (!mesh.pinned(v) && flips[v]++ == 0)
              vertices.push_back(v);
        }
      std::stable_sort(vertices.begin(), vertices.end(), [&](int a, int b) { return flips[a] > flips[b]; });
      return count;
    };
    result.centroidFlipsBefore = result.centroidFlipsAfter = collect();
    for (int sweep = 0; sweep < options.maximumSweeps && result.centroidFlipsAfter > 0; ++sweep)
    {
      bool any = false;
      for (int v : vertices)
        any = unflipVertex(surface, mesh, v, origin[v], singleReach, query, flat) || any;
      result.centroidFlipsAfter = collect();
      if (!any)
        break;
    }
  }
  writeBack(mesh, placed, origin, samples, result);
  result.foldedAfter = countFoldedTriangles(remesh, surface, samples);
  if (report)
    *report = result;
  return {};
}

} // namespace cmp
