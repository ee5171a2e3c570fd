#include <cmp/mesh/SurfaceDistance.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace cmp
{
namespace
{

constexpr double infinity = std::numeric_limits<double>::infinity();

/// Few enough that a leaf is tested faster than it could be split further.
constexpr int leafSize = 4;

/// A point of a triangle as barycentric coordinates in its vertex order.
using Barycentric = std::array<double, 3>;

/// `num / den` clamped to [0, 1]; 0 when rounding left no positive `den`
/// (the edge is then too short relative to the query's distance to matter).
double edgeFraction(double num, double den)
{
  return den > 0.0 ? std::clamp(num / den, 0.0, 1.0) : 0.0;
}

/// Closest point of segment a-b to p as the fraction of the way to b.
double closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 d = b - a;
  return edgeFraction(d.dot(p - a), d.squaredNorm());
}

/// Closest point of a triangle with no usable normal: the best of its
/// three edges, which is where all of its points lie.
Barycentric closestOnFlatTriangle(const Vec3& p, const std::array<Vec3, 3>& x)
{
  Barycentric best{ { 1.0, 0.0, 0.0 } };
  double bestSquared = infinity;
  for (int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3;
    const double t = closestOnSegment(p, x[i], x[j]);
    const double squared = (x[i] + t * (x[j] - x[i]) - p).squaredNorm();
    if (squared < bestSquared)
    {
      bestSquared = squared;
      best = { { 0.0, 0.0, 0.0 } };
      best[i] = 1.0 - t;
      best[j] = t;
    }
  }
  return best;
}

/// Whether the triangle is too thin for its normal to be trusted: its
/// height is below 1e-12 of its longest edge, so its edges are as close to
/// every query as its interior (to that relative precision).
bool isFlat(const std::array<Vec3, 3>& x)
{
  const double longest = std::max({ (x[1] - x[0]).squaredNorm(), (x[2] - x[0]).squaredNorm(),
    (x[2] - x[1]).squaredNorm() });
  return (x[1] - x[0]).cross(x[2] - x[0]).norm() <= 1e-12 * longest;
}

/// Closest point of a triangle that is not flat (`isFlat`) to `p` by Voronoi
/// regions (Ericson, Real-Time Collision Detection, 5.1.5): the signs of a
/// few dot products decide whether a vertex, an edge or the interior is
/// nearest, without projecting first and clamping after, which fails near
/// obtuse corners.
Barycentric closestOnTriangle(const Vec3& p, const std::array<Vec3, 3>& x)
{
  const Vec3 ab = x[1] - x[0], ac = x[2] - x[0];
  const Vec3 ap = p - x[0], bp = p - x[1], cp = p - x[2];
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return { { 1.0, 0.0, 0.0 } };
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return { { 0.0, 1.0, 0.0 } };
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return { { 0.0, 0.0, 1.0 } };
  // va, vb, vc: the signed areas p's projection makes with each edge, in
  // units of the triangle's; a non-positive one puts p outside that edge.
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double t = edgeFraction(d1, d1 - d3);
    return { { 1.0 - t, t, 0.0 } };
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double t = edgeFraction(d2, d2 - d6);
    return { { 1.0 - t, 0.0, t } };
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    const double t = edgeFraction(d4 - d3, (d4 - d3) + (d5 - d6));
    return { { 0.0, 1.0 - t, t } };
  }
  const double area = va + vb + vc;
  if (!(area > 0.0)) // rounding on an almost flat triangle
    return closestOnFlatTriangle(p, x);
  const double v = vb / area, w = vc / area;
  return { { 1.0 - v - w, v, w } };
}

std::array<Vec3, 3> corners(const TriangleMesh& mesh, int t)
{
  const Triangle& tri = mesh.triangles[t];
  return { { mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]] } };
}

std::uint64_t edgeKey(int a, int b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

/// Distance of the samples of one mesh to another: the largest, the sum
/// of those in each triangle. With a limit, also where samples lie farther
/// than it: the triangles of `from` holding such a sample, and the
/// triangles of `to` nearest to one.
class SampleDistances
{
public:
  /// `farFrom` (per triangle of `from`) and `nearestToFar` (per triangle of
  /// `to`), when given, get 1 where a sample farther than `limit` lies, or
  /// is nearest; `farFrom` is filled by `triangleSum()`.
  SampleDistances(const TriangleMesh& from, const ClosestPointQuery& to, int steps, double limit = infinity,
    std::vector<char>* farFrom = nullptr, std::vector<char>* nearestToFar = nullptr)
    : from_(from)
    , to_(to)
    , steps_(steps)
    , limit_(limit)
    , farFrom_(farFrom)
    , nearestToFar_(nearestToFar)
  {
    measureVertices();
    measureEdges();
  }

  /// Sum of the distances of all grid points of triangle `t`.
  double triangleSum(int t)
  {
    const Triangle& tri = from_.triangles[t];
    double sum = 0.0, most = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      sum += vertexDistance_[tri[k]];
      most = std::max(most, vertexDistance_[tri[k]]);
      const auto edge = std::lower_bound(edges_.begin(), edges_.end(), edgeKey(tri[k], tri[(k + 1) % 3]));
      sum += edgeSum_[edge - edges_.begin()];
      most = std::max(most, edgeMost_[edge - edges_.begin()]);
    }
    const auto x = corners(from_, t);
    for (int i = 1; i < steps_; ++i)
      for (int j = 1; i + j < steps_; ++j)
      {
        const double d = measure((i * x[0] + j * x[1] + (steps_ - i - j) * x[2]) / steps_);
        sum += d;
        most = std::max(most, d);
      }
    if (farFrom_ && most > limit_)
      (*farFrom_)[t] = 1;
    return sum;
  }

  /// The largest distance measured so far.
  double largest() const { return largest_; }
  /// A sample at the largest distance (the first one measured there).
  const Vec3& farthest() const { return farthest_; }

private:
  double measure(const Vec3& p)
  {
    const ClosestPointQuery::Result nearest = to_.closest(p);
    const double d = nearest.distance;
    if (d > largest_)
    {
      largest_ = d;
      farthest_ = p;
    }
    if (nearestToFar_ && d > limit_ && nearest.at.triangle >= 0)
      (*nearestToFar_)[nearest.at.triangle] = 1;
    return d;
  }

  /// Vertices used by a triangle, each once however many triangles share it.
  void measureVertices()
  {
    vertexDistance_.assign(from_.vertexCount(), 0.0);
    std::vector<char> used(from_.vertexCount(), 0);
    for (const Triangle& tri : from_.triangles)
      for (int v : tri)
        used[v] = 1;
    for (int v = 0; v < from_.vertexCount(); ++v)
      if (used[v])
        vertexDistance_[v] = measure(from_.points[v]);
  }

  /// The inner grid points of each undirected edge, once per edge, walked
  /// from its lower vertex so both triangles would have seen the same points.
  void measureEdges()
  {
    edges_.reserve(3 * from_.triangles.size());
    for (const Triangle& tri : from_.triangles)
      for (int k = 0; k < 3; ++k)
        edges_.push_back(edgeKey(tri[k], tri[(k + 1) % 3]));
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    edgeSum_.assign(edges_.size(), 0.0);
    edgeMost_.assign(edges_.size(), 0.0);
    for (std::size_t e = 0; e < edges_.size(); ++e)
    {
      const Vec3& a = from_.points[edges_[e] >> 32];
      const Vec3& b = from_.points[edges_[e] & 0xffffffffu];
      for (int i = 1; i < steps_; ++i)
      {
        const double d = measure(((steps_ - i) * a + i * b) / steps_);
        edgeSum_[e] += d;
        edgeMost_[e] = std::max(edgeMost_[e], d);
      }
    }
  }

  const TriangleMesh& from_;
  const ClosestPointQuery& to_;
  const int steps_;
  const double limit_;
  std::vector<char>* farFrom_;
  std::vector<char>* nearestToFar_;
  double largest_ = -infinity; // so that the first sample is the farthest so far
  Vec3 farthest_ = Vec3::Zero();
  std::vector<double> vertexDistance_;
  std::vector<std::uint64_t> edges_; ///< Sorted undirected edges.
  std::vector<double> edgeSum_;      ///< Sum over each edge's inner points.
  std::vector<double> edgeMost_;     ///< Largest over each edge's inner points.
};

/// The largest and the area-weighted mean sample distance from `from` to
/// `to`, and a sample at the largest.
struct OneSided
{
  double largest = 0.0;
  double mean = 0.0;
  Vec3 farthest = Vec3::Zero();
};

OneSided oneSidedDistance(const TriangleMesh& from, const TriangleMesh& to, int steps, double limit = infinity,
  std::vector<char>* farFrom = nullptr, std::vector<char>* nearestToFar = nullptr)
{
  if (from.triangles.empty())
    return {};
  if (to.triangles.empty()) // nothing to be close to; avoids 0 * inf below
    return { infinity, infinity, from.points[from.triangles[0][0]] };
  const ClosestPointQuery query(to);
  SampleDistances samples(from, query, steps, limit, farFrom, nearestToFar);
  const double perTriangle = (steps + 1) * (steps + 2) / 2.0;
  double weighted = 0.0, area = 0.0, plain = 0.0;
  for (int t = 0; t < from.triangleCount(); ++t)
  {
    const double mean = samples.triangleSum(t) / perTriangle;
    const double a = triangleArea(from, t);
    weighted += a * mean;
    area += a;
    plain += mean;
  }
  return { samples.largest(), area > 0.0 ? weighted / area : plain / from.triangleCount(), samples.farthest() };
}

} // namespace

ClosestPointQuery::ClosestPointQuery(const TriangleMesh& mesh)
  : triangles_(mesh.triangles)
{
  const int n = mesh.triangleCount();
  if (n == 0)
    return;
  std::vector<Vec3> centroids(n);
  for (int t = 0; t < n; ++t)
  {
    const auto x = corners(mesh, t);
    centroids[t] = (x[0] + x[1] + x[2]) / 3.0;
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.reserve(4 * (n / leafSize + 1));
  nodes_.emplace_back();
  build(mesh, 0, 0, n, centroids);
  corners_.resize(n);
  flat_.resize(n);
  for (int i = 0; i < n; ++i)
  {
    corners_[i] = corners(mesh, order_[i]);
    flat_[i] = isFlat(corners_[i]);
  }
}

void ClosestPointQuery::build(
  const TriangleMesh& mesh, int node, int begin, int end, const std::vector<Vec3>& centroids)
{
  Vec3 lo = Vec3::Constant(infinity), hi = Vec3::Constant(-infinity);
  Vec3 centreLo = lo, centreHi = hi;
  for (int i = begin; i < end; ++i)
  {
    for (int v : mesh.triangles[order_[i]])
    {
      lo = lo.cwiseMin(mesh.points[v]);
      hi = hi.cwiseMax(mesh.points[v]);
    }
    centreLo = centreLo.cwiseMin(centroids[order_[i]]);
    centreHi = centreHi.cwiseMax(centroids[order_[i]]);
  }
  nodes_[node].lo = lo;
  nodes_[node].hi = hi;
  nodes_[node].begin = begin;
  nodes_[node].end = end;
  if (end - begin <= leafSize)
    return;
  // Splitting at the median by count (not at the middle of the box) keeps the
  // tree balanced, so its depth stays below 32 and the query's stack fits.
  int axis = 0;
  (centreHi - centreLo).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
    [&](int s, int t) { return centroids[s][axis] < centroids[t][axis]; });
  const int left = static_cast<int>(nodes_.size());
  nodes_[node].left = left;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(mesh, left, begin, middle, centroids);
  build(mesh, left + 1, middle, end, centroids);
}

double ClosestPointQuery::boxDistanceSquared(const Node& node, const Vec3& p)
{
  return (node.lo - p).cwiseMax(p - node.hi).cwiseMax(0.0).squaredNorm();
}

void ClosestPointQuery::testLeaf(const Node& node, const Vec3& p, Result& best, double& bestSquared) const
{
  for (int i = node.begin; i < node.end; ++i)
  {
    const auto& x = corners_[i];
    const Barycentric w = flat_[i] ? closestOnFlatTriangle(p, x) : closestOnTriangle(p, x);
    const Vec3 q = w[0] * x[0] + w[1] * x[1] + w[2] * x[2];
    const double squared = (q - p).squaredNorm();
    if (squared < bestSquared)
    {
      bestSquared = squared;
      best.at.triangle = order_[i];
      best.point = q;
      best.at.weight = w;
    }
  }
}

ClosestPointQuery::Result ClosestPointQuery::closest(const Vec3& p) const
{
  Result best;
  best.distance = infinity;
  if (nodes_.empty())
    return best;
  struct Pending
  {
    int node;
    double squared; ///< Distance to its box when it was pushed.
  };
  std::array<Pending, 64> stack;
  int size = 0;
  double bestSquared = infinity;
  stack[size++] = { 0, boxDistanceSquared(nodes_[0], p) };
  while (size > 0)
  {
    const Pending top = stack[--size];
    if (top.squared >= bestSquared) // the bound may have tightened since the push
      continue;
    const Node& node = nodes_[top.node];
    if (node.left < 0)
    {
      testLeaf(node, p, best, bestSquared);
      continue;
    }
    Pending nearer{ node.left, boxDistanceSquared(nodes_[node.left], p) };
    Pending farther{ node.left + 1, boxDistanceSquared(nodes_[node.left + 1], p) };
    if (farther.squared < nearer.squared)
      std::swap(nearer, farther);
    // The nearer child goes on top: searched first, it tightens the bound
    // that may then prune the farther one.
    if (farther.squared < bestSquared)
      stack[size++] = farther;
    if (nearer.squared < bestSquared)
      stack[size++] = nearer;
  }
  if (best.at.triangle >= 0)
    best.at.vertex = triangles_[best.at.triangle];
  best.distance = std::sqrt(bestSquared);
  return best;
}

std::vector<char> trianglesFartherThan(
  const TriangleMesh& surface, const TriangleMesh& remesh, double limit, int subdivisions)
{
  std::vector<char> far;
  surfaceDistance(surface, remesh, subdivisions, limit, &far);
  return far;
}

SurfaceDistance surfaceDistance(const TriangleMesh& a, const TriangleMesh& b, int subdivisions)
{
  return surfaceDistance(a, b, subdivisions, infinity, nullptr);
}

SurfaceDistance surfaceDistance(
  const TriangleMesh& a, const TriangleMesh& b, int subdivisions, double limit, std::vector<char>* farOfB)
{
  const int steps = std::max(1, subdivisions);
  if (farOfB)
    farOfB->assign(b.triangles.size(), 0);
  // Marking needs both meshes to have triangles (a's samples are then near
  // some triangle of b, and b's samples are measured against a).
  std::vector<char>* marks = farOfB && !a.triangles.empty() && !b.triangles.empty() ? farOfB : nullptr;
  const OneSided ab = oneSidedDistance(a, b, steps, limit, nullptr, marks);
  const OneSided ba = oneSidedDistance(b, a, steps, limit, marks, nullptr);
  SurfaceDistance result;
  result.aToB = ab.largest;
  result.meanAToB = ab.mean;
  result.farthestOfA = ab.farthest;
  result.bToA = ba.largest;
  result.meanBToA = ba.mean;
  result.farthestOfB = ba.farthest;
  return result;
}

} // namespace cmp
