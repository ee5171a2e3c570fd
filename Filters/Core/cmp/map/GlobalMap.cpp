#include <cmp/map/GlobalMap.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cmp
{

namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Halvings of a vertex's step at most before it stays.
constexpr int kBacktrackingSteps = 10;
/// A vertex's step never exceeds this share of its shortest edge in the chart.
constexpr double kLongestStepShare = 0.5;

/// One surface triangle's metric: its area and the inverse of its edge
/// matrix in an isometric frame of its own.
struct Metric
{
  double area = 0.0;
  Eigen::Matrix2d inverseEdges = Eigen::Matrix2d::Zero();
};

/// Symmetric Dirichlet energy of a triangle whose corners sit at `p` in a
/// chart (unit frame, scaled by `side`); with `gradient`, adds d energy /
/// d p[corner] (in unit coordinates).
double triangleEnergy(const Metric& metric, const std::array<Vec2, 3>& p, double side, int corner = -1,
  Vec2* gradient = nullptr)
{
  if (!(metric.area > 0.0))
    return 0.0;
  Eigen::Matrix2d edges;
  edges.col(0) = side * (p[1] - p[0]);
  edges.col(1) = side * (p[2] - p[0]);
  const Eigen::Matrix2d J = edges * metric.inverseEdges;
  const double d = J.determinant();
  if (!(d > 0.0))
    return kInfinity;
  const double frobenius = J.squaredNorm(), inverse = 1.0 / (d * d);
  if (gradient)
  {
    Eigen::Matrix2d cofactor;
    cofactor << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
    const Eigen::Matrix2d dJ = metric.area * (2.0 * (1.0 + inverse) * J - 2.0 * frobenius * inverse / d * cofactor);
    const Eigen::Matrix2d dE = side * dJ * metric.inverseEdges.transpose();
    if (corner == 1)
      *gradient += dE.col(0);
    else if (corner == 2)
      *gradient += dE.col(1);
    else
      *gradient -= dE.col(0) + dE.col(1);
  }
  return metric.area * frobenius * (1.0 + inverse);
}

class Optimizer
{
public:
  Optimizer(const TracedNet& net, const BaseCharts& charts, std::vector<BasePoint>& points)
    : mesh_(net.mesh)
    , charts_(charts)
    , points_(points)
    , pinned_(net.mesh.vertexCount(), 0)
    , metrics_(net.mesh.triangleCount())
  {
    for (int v : net.landmarkVertex)
      pinned_[v] = 1;
    for (int t = 0; t < mesh_.triangleCount(); ++t)
    {
      const Triangle& tri = mesh_.triangle(t);
      const Vec3 e1 = mesh_.point(tri[1]) - mesh_.point(tri[0]), e2 = mesh_.point(tri[2]) - mesh_.point(tri[0]);
      const double twiceArea = e1.cross(e2).norm();
      const double length = e1.norm();
      if (!(twiceArea > 1e-14 * (e1.squaredNorm() + e2.squaredNorm())) || !(length > 0.0))
        continue; // degenerate: no say, as in the patch maps' relaxation
      Eigen::Matrix2d edges;
      const double along = e2.dot(e1) / length;
      edges << length, along, 0.0, twiceArea / length;
      metrics_[t].area = 0.5 * twiceArea;
      metrics_[t].inverseEdges = edges.inverse();
    }
  }

  /// The corners `q` in one chart: of the triangles of the corners that are
  /// not at a base vertex, the one that lays them closest together (a chart
  /// cut across near a base vertex spreads them round it); false if none
  /// charts all three.
  bool chart(const std::array<BasePoint, 3>& q, const std::array<bool, 3>& atBaseVertex, std::array<Vec2, 3>& p) const
  {
    double best = kInfinity;
    std::array<Vec2, 3> trial;
    for (int a = 0; a < 3; ++a)
    {
      // A landmark's own triangle is any of those round its base vertex:
      // no guide to which way round the others lie.
      if (atBaseVertex[a])
        continue;
      const int anchor = q[a].triangle;
      if ((a > 0 && !atBaseVertex[0] && anchor == q[0].triangle) ||
        (a > 1 && !atBaseVertex[1] && anchor == q[1].triangle))
        continue;
      bool charted = true;
      for (int k = 0; k < 3 && charted; ++k)
        charted = charts_.inFrame(anchor, q[k], trial[k]);
      if (!charted)
        continue;
      const double perimeter = (trial[1] - trial[0]).norm() + (trial[2] - trial[1]).norm() + (trial[0] - trial[2]).norm();
      if (perimeter < best)
      {
        best = perimeter;
        p = trial;
      }
    }
    return best < kInfinity;
  }

  /// Energy of triangle t, infinite if its corners have no common chart.
  double energy(int t) const
  {
    const Triangle& tri = mesh_.triangle(t);
    std::array<Vec2, 3> p;
    if (!chart({ points_[tri[0]], points_[tri[1]], points_[tri[2]] },
          { pinned_[tri[0]] != 0, pinned_[tri[1]] != 0, pinned_[tri[2]] != 0 }, p))
      return kInfinity;
    return triangleEnergy(metrics_[t], p, side_);
  }

  double totalEnergy() const
  {
    double sum = 0.0;
    for (int t = 0; t < mesh_.triangleCount(); ++t)
      sum += energy(t);
    return sum;
  }

  double totalArea() const
  {
    double sum = 0.0;
    for (const Metric& m : metrics_)
      sum += m.area;
    return sum;
  }

  double largestDistortion() const
  {
    double largest = 0.0;
    for (int t = 0; t < mesh_.triangleCount(); ++t)
      if (metrics_[t].area > 0.0)
        largest = std::max(largest, energy(t) / (4.0 * metrics_[t].area));
    return largest;
  }

  bool pinned(int v) const { return pinned_[v] != 0; }

  /// The side of every base triangle, drawn equilateral.
  void setSide(double side) { side_ = side; }

  /// One move of free vertex v; true if it moved.
  bool relax(int v)
  {
    // The ring in one chart: of the triangles of v and its neighbours, the
    // one that lays the ring most tightly.
    candidates_.assign(1, points_[v].triangle);
    const int first = mesh_.outgoing(v);
    int h = first;
    do
    {
      const int u = mesh_.to(h);
      if (!pinned_[u] && std::find(candidates_.begin(), candidates_.end(), points_[u].triangle) == candidates_.end())
        candidates_.push_back(points_[u].triangle);
      h = mesh_.nextAroundVertex(h);
    } while (h != first);
    int anchor = -1;
    double best = kInfinity;
    for (int candidate : candidates_)
    {
      Vec2 at;
      if (!charts_.inFrame(candidate, points_[v], at))
        continue;
      double length = 0.0;
      bool charted = true;
      h = first;
      do
      {
        Vec2 p;
        charted = charts_.inFrame(candidate, points_[mesh_.to(h)], p);
        length += (p - at).norm();
        h = mesh_.nextAroundVertex(h);
      } while (charted && h != first);
      if (charted && length < best)
      {
        best = length;
        anchor = candidate;
      }
    }
    if (anchor < 0)
      return false;

    ring_.clear();
    Vec2 at;
    charts_.inFrame(anchor, points_[v], at);
    double shortest = kInfinity;
    h = first;
    do
    {
      const int t = EditableMesh::triangleOf(h);
      const Triangle& tri = mesh_.triangle(t);
      Around around;
      around.triangle = t;
      for (int k = 0; k < 3; ++k)
      {
        if (tri[k] == v)
        {
          around.corner = k;
          continue;
        }
        charts_.inFrame(anchor, points_[tri[k]], around.p[k]);
        shortest = std::min(shortest, (around.p[k] - at).norm());
      }
      ring_.push_back(around);
      h = mesh_.nextAroundVertex(h);
    } while (h != first);
    if (!(shortest > 0.0) || !std::isfinite(shortest))
      return false;

    Vec2 gradient = Vec2::Zero();
    const double e0 = ringEnergy(at, &gradient);
    const double slope = gradient.norm();
    if (!std::isfinite(e0) || !(slope > 0.0) || !std::isfinite(slope))
      return false;
    const Vec2 direction = -gradient / slope;
    const double probe = 1e-4 * shortest;
    Vec2 probeGradient = Vec2::Zero();
    ringEnergy(at + probe * direction, &probeGradient);
    const double curvature = (probeGradient.dot(direction) + slope) / probe;
    double step = kLongestStepShare * shortest;
    if (curvature > 0.0 && std::isfinite(curvature))
      step = std::min(step, slope / curvature);
    const BasePoint before = points_[v];
    for (int attempt = 0; attempt <= kBacktrackingSteps; ++attempt, step *= 0.5)
    {
      const Vec2 candidate = at + step * direction;
      if (!(ringEnergy(candidate, nullptr) < e0))
        continue;
      BasePoint moved;
      if (!charts_.locate(anchor, candidate, moved))
        continue;
      // Every triangle of the ring must keep a chart of its own corners,
      // with the energy this chart gave it.
      points_[v] = moved;
      double check = 0.0;
      for (const Around& around : ring_)
        check += energy(around.triangle);
      if (check < e0)
        return true;
      points_[v] = before;
    }
    return false;
  }

private:
  struct Around
  {
    int triangle = -1;
    int corner = -1;
    std::array<Vec2, 3> p;
  };

  double ringEnergy(const Vec2& at, Vec2* gradient)
  {
    double sum = 0.0;
    for (Around& around : ring_)
    {
      around.p[around.corner] = at;
      sum += triangleEnergy(metrics_[around.triangle], around.p, side_, around.corner, gradient);
    }
    return sum;
  }

  const EditableMesh& mesh_;
  const BaseCharts& charts_;
  std::vector<BasePoint>& points_;
  double side_ = 1.0;
  std::vector<char> pinned_;
  std::vector<Metric> metrics_;
  std::vector<Around> ring_;
  std::vector<int> candidates_;
};

} // namespace

Status optimizeGlobalMap(const TracedNet& net, const BaseDomain& domain, const BaseCharts& charts,
  const PatchParameterization& map, std::vector<BasePoint>& points, const GlobalMapOptions& options,
  GlobalMapReport* report)
{
  const EditableMesh& mesh = net.mesh;
  const int n = mesh.vertexCount();
  if (static_cast<int>(map.baseTriangle.size()) != n || static_cast<int>(map.baseCoordinates.size()) != n)
    return Status::error("global map: the parameterization does not belong to this surface");
  if (options.maximumSweeps < 0 || !(options.leastRelativeGain >= 0.0))
    return Status::error("global map: sweeps must be >= 0 and the least relative gain >= 0");
  const int baseTriangles = domain.mesh.triangleCount();
  std::vector<BasePoint> start(n);
  for (int v = 0; v < n; ++v)
  {
    if (map.baseTriangle[v] < 0 || map.baseTriangle[v] >= baseTriangles)
      return Status::error("global map: point " + std::to_string(v) + " has no base triangle");
    start[v] = BaseCharts::fromBarycentric(map.baseTriangle[v], map.baseCoordinates[v]);
  }

  GlobalMapReport result;
  Optimizer optimizer(net, charts, start);
  const double area = optimizer.totalArea();
  if (!(area > 0.0) || baseTriangles <= 0)
    return Status::error("global map: the surface has no area");
  // Each base triangle equilateral, with 1/F of the surface's area.
  optimizer.setSide(std::sqrt(4.0 * area / (std::sqrt(3.0) * baseTriangles)));
  double energy = optimizer.totalEnergy();
  if (!std::isfinite(energy))
    return Status::error("global map: the starting map has a flipped or crushed triangle");
  result.distortionBefore = energy / (4.0 * area);
  for (int sweep = 0; sweep < options.maximumSweeps; ++sweep)
  {
    int moved = 0;
    for (int v = 0; v < n; ++v)
      if (!optimizer.pinned(v))
        moved += optimizer.relax(v) ? 1 : 0;
    ++result.sweeps;
    const double next = optimizer.totalEnergy();
    const bool settled = !(energy - next > options.leastRelativeGain * energy);
    energy = next;
    if (moved == 0 || settled)
      break;
  }
  result.distortionAfter = energy / (4.0 * area);
  result.maximumDistortion = optimizer.largestDistortion();
  for (int v = 0; v < n; ++v)
  {
    const int patch = net.patchOfTriangle[EditableMesh::triangleOf(mesh.outgoing(v))];
    Vec2 inPatch;
    if (!charts.inFrame(patch, start[v], inPatch))
    {
      ++result.crossingVertices;
      continue;
    }
    const std::array<double, 3> b = BaseCharts::barycentric({ patch, inPatch });
    if (std::min({ b[0], b[1], b[2] }) < -1e-9)
      ++result.crossingVertices;
  }
  points = std::move(start);
  if (report)
    *report = result;
  return {};
}

Status freeCurves(const StraightenedNet& straight, const BaseDomain& domain, const PatchParameterization& map,
  const GlobalMapOptions& mapOptions, const PatchParameterizationOptions& options, StraightenedNet& out,
  PatchParameterization& outMap, FreeCurvesReport* report)
{
  FreeCurvesReport result;
  BaseCharts charts;
  charts.build(domain);
  std::vector<BasePoint> points;
  if (Status s = optimizeGlobalMap(straight.net, domain, charts, map, points, mapOptions, &result.map); !s.ok())
    return s;
  StraightenedNet cut;
  PatchParameterization cutMap;
  Status s = cutAlongMap(straight, domain, charts, points, cut, cutMap);
  if (s.ok())
    s = parameterizePatches(cut.net, domain, cutMap, options);
  if (s.ok() && cutMap.flippedTriangles > 0)
    s = Status::error(std::to_string(cutMap.flippedTriangles) + " triangles flip in the new patch maps");
  result.applied = s.ok();
  if (result.applied)
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
