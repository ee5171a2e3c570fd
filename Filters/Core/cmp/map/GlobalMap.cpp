#include <cmp/map/GlobalMap.h>

#include <cmp/numerics/MeanValueSystem.h>
#include <cmp/numerics/SymmetricDirichletRelaxation.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace cmp
{

namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Tries of one star solve, each holding more vertices, before it is skipped.
constexpr int kStarAttempts = 3;
/// Halvings of a vertex's step at most before it stays.
constexpr int kBacktrackingSteps = 10;
/// A vertex's step never exceeds this share of its shortest edge in the chart.
constexpr double kLongestStepShare = 0.5;

/// One surface triangle's metric: its area and the inverse of its edge
/// matrix in an isometric frame of its own.
struct Metric
{
  double area = 0.0;
  /// The energy's weight over the area (1 but near a landmark).
  double weight = 1.0;
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
    const Eigen::Matrix2d dJ =
      metric.weight * metric.area * (2.0 * (1.0 + inverse) * J - 2.0 * frobenius * inverse / d * cofactor);
    const Eigen::Matrix2d dE = side * dJ * metric.inverseEdges.transpose();
    if (corner == 1)
      *gradient += dE.col(0);
    else if (corner == 2)
      *gradient += dE.col(1);
    else
      *gradient -= dE.col(0) + dE.col(1);
  }
  return metric.weight * metric.area * frobenius * (1.0 + inverse);
}


/// The star of one base vertex unfolded: its k triangles drawn equilateral
/// (side `side`) one after the other round the vertex, from the spoke to
/// ring vertex `cut` on, so that the chart is isometric to L0's except
/// across that spoke, where it is open (a gap below valence 6, a second
/// sheet above). A point on the open spoke has no place in the chart.
class StarChart
{
public:
  /// False if the triangles round `center` do not close into one fan.
  bool build(const BaseDomain& domain, int center, int cut, double side)
  {
    center_ = center;
    triangles_ = &domain.mesh.triangles;
    ring_.clear();
    sector_.clear();
    std::vector<int> around;
    for (int t = 0; t < domain.mesh.triangleCount(); ++t)
      for (int k = 0; k < 3; ++k)
        if (domain.mesh.triangles[t][k] == center)
          around.push_back(t);
    if (around.size() < 3)
      return false;
    int t = around[0];
    for (std::size_t i = 0; i < around.size(); ++i)
    {
      const Triangle& tri = domain.mesh.triangles[t];
      const int k = static_cast<int>(std::find(tri.begin(), tri.end(), center) - tri.begin());
      ring_.push_back(tri[(k + 1) % 3]);
      sector_.push_back(t);
      const int next = tri[(k + 2) % 3];
      t = -1;
      for (int candidate : around)
      {
        const Triangle& c = domain.mesh.triangles[candidate];
        const int kc = static_cast<int>(std::find(c.begin(), c.end(), center) - c.begin());
        if (c[(kc + 1) % 3] == next)
          t = candidate;
      }
      if (t < 0)
        return false;
    }
    if (t != around[0])
      return false;
    const int k = valence();
    std::rotate(ring_.begin(), ring_.begin() + cut % k, ring_.end());
    std::rotate(sector_.begin(), sector_.begin() + cut % k, sector_.end());
    legs_.resize(k + 1);
    for (int i = 0; i <= k; ++i)
      legs_[i] = side * Vec2(std::cos(i * kPi / 3.0), std::sin(i * kPi / 3.0));
    return true;
  }

  int valence() const { return static_cast<int>(ring_.size()); }

  /// `p` in the chart, with its angle round the centre (0 to k pi / 3);
  /// false if it lies outside the closed star or on the open spoke. With
  /// `inside`, whether it lies in the open star (off its rim).
  bool position(const BasePoint& p, Vec2& q, double& angle, bool* inside = nullptr) const
  {
    const std::array<double, 3> c = BaseCharts::barycentric(p);
    const Triangle& tri = (*triangles_)[p.triangle];
    const int k = valence();
    int found = -1;
    double weights[3] = { 0.0, 0.0, 0.0 }; // centre, ring i, ring i + 1
    for (int i = 0; i < k; ++i)
    {
      const int a = ring_[i], b = ring_[(i + 1) % k];
      double w[3] = { 0.0, 0.0, 0.0 };
      bool holds = true;
      for (int j = 0; j < 3 && holds; ++j)
      {
        const double x = std::max(c[j], 0.0);
        if (x < kOffStar)
          continue;
        if (tri[j] == center_)
          w[0] += x;
        else if (tri[j] == a)
          w[1] += x;
        else if (tri[j] == b)
          w[2] += x;
        else
          holds = false;
      }
      if (!holds)
        continue;
      if (found >= 0 && !(w[1] == 0.0 && w[2] == 0.0))
      {
        // On the spoke between sector k - 1 and sector 0: open there.
        if (found == 0 && i == k - 1)
          return false;
      }
      if (found < 0)
      {
        found = i;
        std::copy(w, w + 3, weights);
      }
    }
    const double sum = weights[0] + weights[1] + weights[2];
    if (found < 0 || !(sum > 0.0))
      return false;
    q = (weights[1] * legs_[found] + weights[2] * legs_[found + 1]) / sum;
    angle = (found + (weights[1] + weights[2] > 0.0 ? weights[2] / (weights[1] + weights[2]) : 0.5)) * kPi / 3.0;
    if (inside)
      *inside = weights[0] / sum > kOffStar;
    return true;
  }

  /// The base point at chart point `q`, on the sheet nearest to `angle`.
  BasePoint point(const Vec2& q, double angle) const
  {
    const int k = valence();
    double theta = std::atan2(q.y(), q.x());
    theta += 2.0 * kPi * std::round((angle - theta) / (2.0 * kPi));
    const int i = std::clamp(static_cast<int>(std::floor(theta / (kPi / 3.0))), 0, k - 1);
    Eigen::Matrix2d legs;
    legs.col(0) = legs_[i];
    legs.col(1) = legs_[i + 1];
    const Vec2 ab = legs.inverse() * q;
    const double a = std::max(ab.x(), 0.0), b = std::max(ab.y(), 0.0);
    const double centre = std::max(1.0 - a - b, 0.0), sum = centre + a + b;
    const Triangle& tri = (*triangles_)[sector_[i]];
    std::array<double, 3> c{ 0.0, 0.0, 0.0 };
    for (int j = 0; j < 3; ++j)
      c[j] = tri[j] == center_ ? centre / sum : tri[j] == ring_[i] ? a / sum : b / sum;
    return BaseCharts::fromBarycentric(sector_[i], c);
  }

private:
  /// Barycentric weights below this count as none (a point on the rim).
  static constexpr double kOffStar = 1e-10;
  int center_ = -1;
  const std::vector<Triangle>* triangles_ = nullptr;
  std::vector<int> ring_;   ///< Base vertices round the centre, counter-clockwise from the cut.
  std::vector<int> sector_; ///< Base triangle (centre, ring i, ring i + 1).
  std::vector<Vec2> legs_;  ///< Chart place of ring vertex i (k + 1 of them: the cut's twice).
};

/// Per surface triangle, 1 + min(cap, (radius / r)^2), r the distance of
/// its centroid from the nearest landmark (see
/// `GlobalMapOptions::landmarkWeightRadius`); empty if `radius` is 0.
std::vector<double> landmarkWeights(const EditableMesh& mesh, const std::vector<int>& landmarks, double radius, double cap)
{
  if (!(radius > 0.0) || !(cap > 0.0))
    return {};
  std::vector<double> weights(mesh.triangleCount(), 1.0);
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const Triangle& tri = mesh.triangle(t);
    const Vec3 c = (mesh.point(tri[0]) + mesh.point(tri[1]) + mesh.point(tri[2])) / 3.0;
    double nearest = kInfinity;
    for (int l : landmarks)
      nearest = std::min(nearest, (mesh.point(l) - c).squaredNorm());
    weights[t] = 1.0 + (nearest > 0.0 ? std::min(cap, radius * radius / nearest) : cap);
  }
  return weights;
}

/// One star's solve: the surface vertices whose whole ring lies in the
/// star of base vertex `center` (the landmarks aside, and away from the
/// spoke to ring vertex `cut`) relaxed together in its chart, the rest
/// held; returns the number of vertices moved.
int relaxStar(const TracedNet& net, const BaseDomain& domain, int center, int cut, double side,
  const std::vector<char>& pinned, const SymmetricDirichletOptions& options, const std::function<bool(int)>& valid,
  std::vector<BasePoint>& points)
{
  StarChart chart;
  if (!chart.build(domain, center, cut, side))
    return 0;
  const EditableMesh& mesh = net.mesh;
  const int n = mesh.vertexCount();
  std::vector<Vec2> q(n);
  std::vector<double> angle(n, 0.0);
  std::vector<char> inStar(n, 0), inside(n, 0), free(n, 0);
  for (int v = 0; v < n; ++v)
  {
    bool open = false;
    inStar[v] = chart.position(points[v], q[v], angle[v], &open) ? 1 : 0;
    inside[v] = open ? 1 : 0;
  }
  std::vector<char> held(n, 0);
  std::vector<int> triangles;
  for (int attempt = 0; attempt < kStarAttempts; ++attempt)
  {
    for (int v = 0; v < n; ++v)
    {
      free[v] = 0;
      if (pinned[v] || !inside[v] || held[v])
        continue;
      bool ring = true;
      const int first = mesh.outgoing(v);
      int h = first;
      do
      {
        ring = inStar[mesh.to(h)] != 0;
        h = mesh.nextAroundVertex(h);
      } while (ring && h != first);
      free[v] = ring ? 1 : 0;
    }
    // A triangle across the open spoke (its corners more than half a turn
    // apart round the centre), or one the chart shows flipped or flat, holds
    // its corners.
    triangles.clear();
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      const Triangle& tri = mesh.triangle(t);
      if (!free[tri[0]] && !free[tri[1]] && !free[tri[2]])
        continue;
      double lowest = kInfinity, highest = -kInfinity;
      for (int v : tri)
        if (q[v].squaredNorm() > 0.0) // the centre has no angle
        {
          lowest = std::min(lowest, angle[v]);
          highest = std::max(highest, angle[v]);
        }
      if (highest - lowest > kPi || !(cross2(q[tri[1]] - q[tri[0]], q[tri[2]] - q[tri[0]]) > 0.0))
        for (int v : tri)
          free[v] = 0;
    }
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      const Triangle& tri = mesh.triangle(t);
      if (free[tri[0]] || free[tri[1]] || free[tri[2]])
        triangles.push_back(t);
    }
    if (triangles.empty())
      return 0;
    std::vector<int> local(n, -1), global;
    const TriangleMesh piece = extractTriangles(mesh, triangles, local, global);
    Eigen::MatrixXd plane(piece.vertexCount(), 2);
    std::vector<char> fixed(piece.vertexCount(), 1);
    for (int i = 0; i < piece.vertexCount(); ++i)
    {
      plane.row(i) = q[global[i]].transpose();
      fixed[i] = free[global[i]] ? 0 : 1;
    }
    if (!relaxSymmetricDirichlet(piece, fixed, plane, options).ok())
      return 0;
    int moved = 0;
    std::vector<BasePoint> before(piece.vertexCount());
    for (int i = 0; i < piece.vertexCount(); ++i)
      if (!fixed[i])
      {
        before[i] = points[global[i]];
        points[global[i]] = chart.point(plane.row(i).transpose(), angle[global[i]]);
        ++moved;
      }
    // The chart is L0's own but for the open spoke and a triangle round the
    // centre may end wider than L0's charts take: such triangles, checked in
    // L0's charts, hold their corners and their corners' rings for another
    // try.
    std::vector<int> bad;
    for (int t : triangles)
      if (!valid(t))
        bad.push_back(t);
    if (bad.empty())
      return moved;
    for (int i = 0; i < piece.vertexCount(); ++i)
      if (!fixed[i])
        points[global[i]] = before[i];
    for (int t : bad)
      for (int v : mesh.triangle(t))
      {
        held[v] = 1;
        const int first = mesh.outgoing(v);
        int h = first;
        do
        {
          held[mesh.to(h)] = 1;
          h = mesh.nextAroundVertex(h);
        } while (h != first);
      }
  }
  return 0;
}

class Optimizer
{
public:
  Optimizer(const TracedNet& net, const BaseDomain& domain, const BaseCharts& charts, std::vector<BasePoint>& points)
    : mesh_(net.mesh)
    , domain_(domain)
    , charts_(charts)
    , points_(points)
    , pinned_(net.mesh.vertexCount(), 0)
    , metrics_(net.mesh.triangleCount())
  {
    for (int v : net.landmarkVertex)
      pinned_[v] = 1;
    stars_.resize(domain.mesh.vertexCount());
    for (int t = 0; t < domain.mesh.triangleCount(); ++t)
      for (int k = 0; k < 3; ++k)
      {
        const int b = domain.mesh.triangles[t][k];
        if (!stars_[b].built)
          stars_[b].built = stars_[b].star.build(domain, t, b, domain.mesh.triangles[t][(k + 1) % 3]);
      }
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

  /// Whether triangle t keeps its orientation in every chart of its
  /// corners' base triangles that holds all three (so that every later
  /// step, which may read it in any of them, sees it unflipped), and has
  /// a finite energy.
  bool consistent(int t) const
  {
    if (!std::isfinite(energy(t)))
      return false;
    const Triangle& tri = mesh_.triangle(t);
    const int home = points_[tri[0]].triangle;
    if (!pinned_[tri[0]] && !pinned_[tri[1]] && !pinned_[tri[2]] && points_[tri[1]].triangle == home &&
      points_[tri[2]].triangle == home)
      return true; // inside one base triangle: one shape in every chart
    // The chart of each corner's triangle: the cut reads the triangle in
    // one of them.
    for (int v : tri)
    {
      const int anchor = points_[v].triangle;
      std::array<Vec2, 3> p;
      bool charted = true;
      for (int k = 0; k < 3 && charted; ++k)
        charted = charts_.inFrame(anchor, points_[tri[k]], p[k]);
      if (charted && !(cross2(p[1] - p[0], p[2] - p[0]) > 0.0))
        return false;
    }
    return !wrapsBaseVertex(tri);
  }

  /// Whether a triangle with no corner at a base vertex reaches more than
  /// half a turn round it, its corners all in that vertex's star: drawn in
  /// the star, it would hold the vertex, so the map would wrap round the
  /// landmark there, which no chart of its corners' triangles shows (each
  /// draws it unflipped) and along which no curve can be cut.
  bool wrapsBaseVertex(const Triangle& tri) const
  {
    for (int b : domain_.mesh.triangles[points_[tri[0]].triangle])
    {
      const Star& around = stars_[b];
      if (!around.built)
        continue;
      std::array<double, 3> angle{};
      bool inStar = true;
      for (int k = 0; k < 3 && inStar; ++k)
      {
        double radius = 0.0;
        inStar = around.star.polar(points_[tri[k]], radius, angle[k]) && radius > 0.0;
      }
      if (!inStar)
        continue;
      std::sort(angle.begin(), angle.end());
      const double turn = around.star.turn();
      const double widest = std::max({ angle[1] - angle[0], angle[2] - angle[1], angle[0] + turn - angle[2] });
      if (turn - widest > kPi)
        return true;
    }
    return false;
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
        largest = std::max(largest, energy(t) / (4.0 * metrics_[t].weight * metrics_[t].area));
    return largest;
  }

  bool pinned(int v) const { return pinned_[v] != 0; }

  /// The side of every base triangle, drawn equilateral.
  void setSide(double side) { side_ = side; }

  /// Weighs each triangle's energy (one factor per triangle, or none: 1).
  void setWeights(const std::vector<double>& weights)
  {
    for (int t = 0; t < mesh_.triangleCount(); ++t)
      metrics_[t].weight = weights.empty() ? 1.0 : weights[t];
  }

  /// The unweighted energy.
  double totalPlainEnergy() const
  {
    double sum = 0.0;
    for (int t = 0; t < mesh_.triangleCount(); ++t)
      sum += energy(t) / metrics_[t].weight;
    return sum;
  }

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
      // with the energy this chart gave it, stay unflipped in every chart
      // of its corners' triangles and not wrap round a base vertex.
      points_[v] = moved;
      double check = 0.0;
      for (const Around& around : ring_)
        check += energy(around.triangle);
      if (check < e0 &&
        std::all_of(ring_.begin(), ring_.end(), [&](const Around& around) { return consistent(around.triangle); }))
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

  /// A base vertex's star, unfolded (`built` false if it is not one fan).
  struct Star
  {
    StarUnfolding star;
    bool built = false;
  };

  const EditableMesh& mesh_;
  const BaseDomain& domain_;
  const BaseCharts& charts_;
  std::vector<BasePoint>& points_;
  std::vector<Star> stars_;
  double side_ = 1.0;
  std::vector<char> pinned_;
  std::vector<Metric> metrics_;
  std::vector<Around> ring_;
  std::vector<int> candidates_;
};


/// Unflips the triangles the cut's rounding left flipped in the map
/// `map` of the cut net `net`: in each patch that has some, the vertices off
/// the curves within a few rings of them are placed anew by mean value
/// weights, the rest held, the rings widened until no triangle of the patch
/// is flipped (the whole patch at worst: a convex boundary, so Floater's
/// map is bijective). Returns false if a patch cannot be solved.
bool unflipPatches(const TracedNet& net, const BaseDomain& domain, PatchParameterization& map)
{
  if (map.flippedTriangles == 0)
    return true;
  const EditableMesh& mesh = net.mesh;
  const int patchCount = domain.mesh.triangleCount();
  std::vector<std::vector<int>> trianglesOf(patchCount);
  for (int t = 0; t < mesh.triangleCount(); ++t)
    trianglesOf[net.patchOfTriangle[t]].push_back(t);
  std::vector<char> onCurve(mesh.vertexCount(), 0);
  for (const auto& curve : net.curves)
    for (int v : curve)
      onCurve[v] = 1;
  std::vector<int> local(mesh.vertexCount(), -1);
  for (int patch = 0; patch < patchCount; ++patch)
  {
    std::vector<int> global;
    const TriangleMesh piece = extractTriangles(mesh, trianglesOf[patch], local, global);
    const int m = piece.vertexCount();
    Eigen::MatrixXd values(m, 2);
    for (int i = 0; i < m; ++i)
    {
      std::array<double, 3> c;
      if (!coordinatesInTriangle(domain, map.baseTriangle[global[i]], map.baseCoordinates[global[i]], patch, c))
        return false;
      values.row(i) << c[1], c[2];
    }
    for (int v : global)
      local[v] = -1;
    const auto flipped = [&](const Eigen::MatrixXd& x) {
      std::vector<int> result;
      for (int t = 0; t < piece.triangleCount(); ++t)
      {
        const Triangle& tri = piece.triangles[t];
        const Vec2 a = x.row(tri[1]) - x.row(tri[0]), b = x.row(tri[2]) - x.row(tri[0]);
        if (!(cross2(a, b) > 0.0))
          result.push_back(t);
      }
      return result;
    };
    const std::vector<int> bad = flipped(values);
    if (bad.empty())
      continue;
    std::vector<std::vector<int>> neighbours(m);
    for (const Triangle& tri : piece.triangles)
      for (int k = 0; k < 3; ++k)
        neighbours[tri[k]].push_back(tri[(k + 1) % 3]);
    std::vector<int> distance(m, -1), queue;
    for (int t : bad)
      for (int v : piece.triangles[t])
        if (distance[v] < 0)
        {
          distance[v] = 0;
          queue.push_back(v);
        }
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (int u : neighbours[queue[i]])
        if (distance[u] < 0)
        {
          distance[u] = distance[queue[i]] + 1;
          queue.push_back(u);
        }
    const Eigen::SparseMatrix<double> weights = meanValueWeights(piece);
    bool solved = false;
    for (int rings = 2; !solved; rings *= 2)
    {
      const bool whole = rings > m;
      std::vector<int> fixedRow(m, -1);
      Eigen::MatrixXd fixedValues(m, 2);
      int fixedCount = 0;
      for (int i = 0; i < m; ++i)
        if (onCurve[global[i]] || (!whole && (distance[i] < 0 || distance[i] > rings)))
        {
          fixedRow[i] = fixedCount;
          fixedValues.row(fixedCount++) = values.row(i);
        }
      Eigen::MatrixXd solution;
      if (!solveConvexCombinationSystem(weights, fixedRow, fixedValues.topRows(fixedCount), solution).ok())
      {
        if (whole)
          return false;
        continue;
      }
      if (flipped(solution).empty() || whole)
      {
        if (!flipped(solution).empty())
          return false;
        // The freed vertices relaxed towards an isometry from there (the
        // mean value map crowds a protrusion the map had given room).
        double area = 0.0;
        for (int t = 0; t < piece.triangleCount(); ++t)
          area += triangleArea(piece, t);
        if (area > 0.0)
        {
          const double side = std::sqrt(4.0 * area / std::sqrt(3.0));
          Eigen::Matrix2d frame;
          frame << side, 0.5 * side, 0.0, 0.5 * std::sqrt(3.0) * side;
          Eigen::MatrixXd plane = solution * frame.transpose();
          std::vector<char> fixed(m, 0);
          for (int i = 0; i < m; ++i)
            fixed[i] = fixedRow[i] >= 0 ? 1 : 0;
          if (relaxSymmetricDirichlet(piece, fixed, plane).ok())
          {
            Eigen::MatrixXd relaxed = plane * frame.transpose().inverse();
            for (int i = 0; i < m; ++i)
              if (fixedRow[i] >= 0)
                relaxed.row(i) = solution.row(i);
            if (relaxed.allFinite() && flipped(relaxed).empty())
              solution.swap(relaxed);
          }
        }
        for (int i = 0; i < m; ++i)
          if (fixedRow[i] < 0)
          {
            const int v = global[i];
            map.baseTriangle[v] = patch; // off the curves: in this patch alone
            map.baseCoordinates[v] = { 1.0 - solution(i, 0) - solution(i, 1), solution(i, 0), solution(i, 1) };
          }
        solved = true;
      }
    }
  }
  map.flippedTriangles = 0;
  return true;
}
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
  if (!(options.landmarkWeightRadius >= 0.0) || !std::isfinite(options.landmarkWeightRadius) ||
    !(options.landmarkWeightCap > 0.0) || !std::isfinite(options.landmarkWeightCap))
    return Status::error("global map: the landmark weight radius must be finite and >= 0, its cap finite and > 0");
  const int baseTriangles = domain.mesh.triangleCount();
  std::vector<BasePoint> start(n);
  for (int v = 0; v < n; ++v)
  {
    if (map.baseTriangle[v] < 0 || map.baseTriangle[v] >= baseTriangles)
      return Status::error("global map: point " + std::to_string(v) + " has no base triangle");
    start[v] = BaseCharts::fromBarycentric(map.baseTriangle[v], map.baseCoordinates[v]);
  }

  GlobalMapReport result;
  Optimizer optimizer(net, domain, charts, start);
  const double area = optimizer.totalArea();
  if (!(area > 0.0) || baseTriangles <= 0)
    return Status::error("global map: the surface has no area");
  // Each base triangle equilateral, with 1/F of the surface's area.
  optimizer.setSide(std::sqrt(4.0 * area / (std::sqrt(3.0) * baseTriangles)));
  double energy = optimizer.totalEnergy();
  if (!std::isfinite(energy))
    return Status::error("global map: the starting map has a flipped or crushed triangle");
  result.distortionBefore = energy / (4.0 * area);
  const double side = std::sqrt(4.0 * area / (std::sqrt(3.0) * baseTriangles));
  {
    std::vector<char> pinned(n, 0);
    for (int v : net.landmarkVertex)
      pinned[v] = 1;
    SymmetricDirichletOptions relax;
    relax.maximumIterations = options.starIterations;
    for (int round = 0; round < options.starRounds; ++round)
    {
      for (int b = 0; b < domain.mesh.vertexCount(); ++b)
        relaxStar(net, domain, b, round, side, pinned, relax,
          [&](int t) { return optimizer.consistent(t); }, start);
      const double next = optimizer.totalEnergy();
      ++result.starRounds;
      const bool settled = !(energy - next > options.leastRelativeGain * energy);
      energy = next;
      if (settled)
        break;
    }
  }
  // The star solves spread the map unweighted: weighted, they denied tails
  // and ears beside a landmark their room. The sweeps then polish it with
  // the landmarks' rings weighted.
  const std::vector<double> weights =
    landmarkWeights(mesh, net.landmarkVertex, options.landmarkWeightRadius * side, options.landmarkWeightCap);
  if (!weights.empty())
  {
    optimizer.setWeights(weights);
    energy = optimizer.totalEnergy();
  }
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
  result.distortionAfter = optimizer.totalPlainEnergy() / (4.0 * area);
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
  // The map's own places, the cut's rounding unflipped; where that fails,
  // every patch parameterized anew on the new curves.
  if (s.ok() && !unflipPatches(cut.net, domain, cutMap))
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
