#include <cmp/basedomain/BaseDomainBuilder.h>

#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/mesh/TriangleShape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace cmp
{

namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A triangle mesh that supports half-edge collapses and edge flips, with
/// per-vertex incident-triangle lists kept exact.
class CollapsibleMesh
{
public:
  CollapsibleMesh(const TriangleMesh& mesh)
    : points_(mesh.points)
    , triangles_(mesh.triangles)
    , alive_(mesh.triangles.size(), 1)
    , incident_(mesh.points.size())
  {
    for (int t = 0; t < static_cast<int>(triangles_.size()); ++t)
      for (int v : triangles_[t])
        incident_[v].push_back(t);
  }

  const Vec3& point(int v) const { return points_[v]; }
  const Triangle& triangle(int t) const { return triangles_[t]; }
  const std::vector<int>& incident(int v) const { return incident_[v]; }
  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  bool alive(int t) const { return alive_[t] != 0; }

  /// Sorted neighbours of `v`, written into `result` (reused, so the hot
  /// loop does not allocate).
  void neighbours(int v, std::vector<int>& result) const
  {
    result.clear();
    for (int t : incident_[v])
      for (int w : triangles_[t])
        if (w != v)
          result.push_back(w);
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
  }

  /// Sorted neighbours of `v`.
  std::vector<int> neighbours(int v) const
  {
    std::vector<int> result;
    neighbours(v, result);
    return result;
  }

  /// Collapsing u into v keeps a closed manifold iff they share exactly the
  /// two neighbours opposite their edge (the link condition). `uNeighbours`
  /// is `neighbours(u)`, computed once by the caller for all candidates v.
  bool linkConditionHolds(const std::vector<int>& uNeighbours, int v) const
  {
    neighbours(v, scratch_);
    int common = 0;
    auto a = uNeighbours.cbegin();
    auto b = scratch_.cbegin();
    while (a != uNeighbours.cend() && b != scratch_.cend())
    {
      if (*a < *b)
        ++a;
      else if (*b < *a)
        ++b;
      else
      {
        ++common, ++a, ++b;
      }
    }
    return common == 2;
  }

  /// Moves u onto v: the two triangles on edge uv die, the others of u are
  /// relabelled. Requires the link condition.
  void collapse(int u, int v)
  {
    for (int t : incident_[u])
    {
      Triangle& tri = triangles_[t];
      if (std::find(tri.begin(), tri.end(), v) != tri.end())
      {
        alive_[t] = 0;
        for (int w : tri)
          if (w != u)
            erase(incident_[w], t);
      }
      else
      {
        std::replace(tri.begin(), tri.end(), u, v);
        incident_[v].push_back(t);
      }
    }
    incident_[u].clear();
  }

  /// Flips edge (u, w) if the two opposite vertices are not yet adjacent.
  /// Lowers u's degree by one. Returns false if the flip is not allowed.
  bool flip(int u, int w)
  {
    int first = -1, second = -1; // (u, w, a) and (w, u, b) counter-clockwise
    for (int t : incident_[u])
    {
      const Triangle& tri = triangles_[t];
      for (int k = 0; k < 3; ++k)
      {
        if (tri[k] == u && tri[(k + 1) % 3] == w)
          first = t;
        if (tri[k] == w && tri[(k + 1) % 3] == u)
          second = t;
      }
    }
    if (first < 0 || second < 0)
      return false;
    const int a = opposite(first, u, w);
    const int b = opposite(second, u, w);
    const std::vector<int> na = neighbours(a);
    if (a == b || std::binary_search(na.begin(), na.end(), b))
      return false;
    // Quad u, b, w, a counter-clockwise; new diagonal a-b.
    triangles_[first] = { u, b, a };
    triangles_[second] = { b, w, a };
    erase(incident_[u], second);
    erase(incident_[w], first);
    incident_[a].push_back(second);
    incident_[b].push_back(first);
    return true;
  }

private:
  static void erase(std::vector<int>& list, int value)
  {
    const auto it = std::find(list.begin(), list.end(), value);
    if (it != list.end())
    {
      *it = list.back();
      list.pop_back();
    }
  }
  int opposite(int t, int u, int w) const
  {
    for (int x : triangles_[t])
      if (x != u && x != w)
        return x;
    return -1;
  }

  std::vector<Vec3> points_;
  std::vector<Triangle> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> incident_;
  mutable std::vector<int> scratch_;
};

/// Sum of squared distances to a set of planes, as a symmetric 4x4 matrix.
using Quadric = Eigen::Matrix4d;

std::vector<Quadric> initialQuadrics(const TriangleMesh& mesh)
{
  std::vector<Quadric> quadrics(mesh.points.size(), Quadric::Zero());
  for (const Triangle& tri : mesh.triangles)
  {
    const Vec3& a = mesh.points[tri[0]];
    const Vec3 normal = (mesh.points[tri[1]] - a).cross(mesh.points[tri[2]] - a);
    const double doubleArea = normal.norm();
    if (doubleArea <= 0.0)
      continue;
    Eigen::Vector4d plane;
    plane << normal / doubleArea, -normal.dot(a) / doubleArea;
    const Quadric q = 0.5 * doubleArea * plane * plane.transpose();
    for (int v : tri)
      quadrics[v] += q;
  }
  return quadrics;
}

struct Candidate
{
  double cost = kInfinity;
  int target = -1;
  bool folds = false;
};

struct QueueEntry
{
  double cost;
  int vertex;
  int version;
  Candidate candidate;
  bool operator>(const QueueEntry& other) const { return cost > other.cost; }
};

class Decimator
{
public:
  Decimator(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomainBuilderOptions& options)
    : mesh_(surface)
    , quadrics_(initialQuadrics(surface))
    , locked_(surface.points.size(), 0)
    , version_(surface.points.size(), 0)
    , options_(options)
    , diagonal_(boundingBoxDiagonal(surface))
  {
    for (int v : landmarks)
      locked_[v] = 1;
    remaining_ = surface.vertexCount() - static_cast<int>(landmarks.size());
  }

  Status run(BaseDomainBuilderReport& report)
  {
    const int total = remaining_;
    for (int v = 0; v < static_cast<int>(locked_.size()); ++v)
      schedule(v);
    while (remaining_ > 0)
    {
      if (queue_.empty())
      {
        if (Status s = unblock(report); !s.ok())
          return s;
        continue;
      }
      const QueueEntry entry = queue_.top();
      queue_.pop();
      // Any change near a vertex bumps its version (see collapse()), so a
      // current entry's candidate is still valid and still its best.
      if (entry.version != version_[entry.vertex])
        continue;
      collapse(entry.vertex, entry.candidate, report);
      if (options_.progress && total > 0 && remaining_ % 1024 == 0)
        options_.progress(1.0 - static_cast<double>(remaining_) / total);
    }
    return {};
  }

  const CollapsibleMesh& mesh() const { return mesh_; }

private:
  /// Best collapse of u: folding collapses only when nothing else is left.
  Candidate evaluate(int u) const
  {
    Candidate best;
    mesh_.neighbours(u, candidates_);
    for (int v : candidates_)
    {
      if (!mesh_.linkConditionHolds(candidates_, v))
        continue;
      Candidate c = cost(u, v);
      if (c.folds && !allowFolding_)
        continue;
      if (c.cost < best.cost)
        best = c;
    }
    return best;
  }

  Candidate cost(int u, int v) const
  {
    Candidate c;
    c.target = v;
    double worstQuality = 1.0;
    for (int t : mesh_.incident(u))
    {
      const Triangle& tri = mesh_.triangle(t);
      if (std::find(tri.begin(), tri.end(), v) != tri.end())
        continue;
      Vec3 corner[3], moved[3];
      for (int k = 0; k < 3; ++k)
      {
        corner[k] = mesh_.point(tri[k]);
        moved[k] = tri[k] == u ? mesh_.point(v) : corner[k];
      }
      const Vec3 before = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
      const Vec3 after = (moved[1] - moved[0]).cross(moved[2] - moved[0]);
      if (before.dot(after) <= 0.0)
        c.folds = true;
      worstQuality = std::min(worstQuality, triangleShapeQuality(moved[0], moved[1], moved[2]));
    }
    Eigen::Vector4d p;
    p << mesh_.point(v), 1.0;
    const double error = std::max(0.0, p.dot((quadrics_[u] + quadrics_[v]) * p));
    c.cost = std::sqrt(error) / diagonal_ + options_.shapeWeight * (1.0 - worstQuality);
    return c;
  }

  void schedule(int v)
  {
    ++version_[v];
    if (locked_[v] || mesh_.incident(v).empty())
      return;
    const Candidate c = evaluate(v);
    if (c.target >= 0)
      queue_.push({ c.cost, v, version_[v], c });
  }

  void collapse(int u, const Candidate& candidate, BaseDomainBuilderReport& report)
  {
    const int v = candidate.target;
    mesh_.collapse(u, v);
    quadrics_[v] += quadrics_[u];
    ++version_[u];
    --remaining_;
    ++report.collapses;
    report.foldingCollapses += candidate.folds ? 1 : 0;
    schedule(v);
    for (int w : mesh_.neighbours(v))
      schedule(w);
  }

  /// Nothing can be collapsed any more without folding, or at all: first
  /// allow folds, then flip edges around a blocked vertex until its degree
  /// is 3, which always makes a collapse valid on a closed surface.
  Status unblock(BaseDomainBuilderReport& report)
  {
    if (!allowFolding_)
    {
      allowFolding_ = true;
      for (int v = 0; v < static_cast<int>(locked_.size()); ++v)
        schedule(v);
      return {};
    }
    for (int u = 0; u < static_cast<int>(locked_.size()); ++u)
    {
      if (locked_[u] || mesh_.incident(u).empty())
        continue;
      bool flipped = true;
      while (flipped && evaluate(u).target < 0)
      {
        flipped = false;
        for (int w : mesh_.neighbours(u))
        {
          if (mesh_.flip(u, w))
          {
            ++report.flips;
            flipped = true;
            break;
          }
        }
      }
      if (evaluate(u).target >= 0)
      {
        for (int w : mesh_.neighbours(u))
          schedule(w);
        schedule(u);
        return {};
      }
    }
    return Status::error("base domain construction is stuck: no remaining vertex can be removed without "
                         "breaking the surface's topology");
  }

  CollapsibleMesh mesh_;
  std::vector<Quadric> quadrics_;
  std::vector<char> locked_;
  std::vector<int> version_;
  const BaseDomainBuilderOptions& options_;
  double diagonal_;
  int remaining_ = 0;
  bool allowFolding_ = false;
  mutable std::vector<int> candidates_;
  std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>> queue_;
};

void measureQuality(const BaseDomain& domain, BaseDomainBuilderReport& report)
{
  const TriangleShapeSummary shape = measureTriangleShapes(domain.mesh.points, domain.mesh.triangles);
  report.minAngleDegrees = shape.minimumAngleDegrees;
  report.meanShapeQuality = shape.meanShapeQuality;
}

} // namespace

Status buildBaseDomain(const TriangleMesh& surface, const LandmarkList& landmarks, BaseDomain& domain,
  const BaseDomainBuilderOptions& options, BaseDomainBuilderReport* report)
{
  const SurfaceCheckResult check = checkSurface(surface);
  if (!check.ok())
    return Status::error(check.message);
  if (Status s = validateLandmarks(landmarks, surface.vertexCount()); !s.ok())
    return s;
  if (landmarks.size() < 4)
    return Status::error("too few landmarks: " + std::to_string(landmarks.size()) +
      " given, but a closed base domain needs at least 4 (a tetrahedron)");

  BaseDomainBuilderReport localReport;
  BaseDomainBuilderReport& out = report ? *report : localReport;
  out = BaseDomainBuilderReport{};
  Decimator decimator(surface, landmarks, options);
  if (Status s = decimator.run(out); !s.ok())
    return s;

  const std::vector<int> featureOfVertex = featureIdsOf(landmarks, surface.vertexCount());
  domain = BaseDomain{};
  for (int v : landmarks)
    domain.mesh.points.push_back(surface.points[v]);
  for (int f = 0; f < static_cast<int>(landmarks.size()); ++f)
    domain.featureIds.push_back(f);
  const CollapsibleMesh& mesh = decimator.mesh();
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    if (!mesh.alive(t))
      continue;
    const Triangle& tri = mesh.triangle(t);
    domain.mesh.triangles.push_back({ featureOfVertex[tri[0]], featureOfVertex[tri[1]], featureOfVertex[tri[2]] });
  }
  if (Status s = checkBaseDomain(domain, static_cast<int>(landmarks.size())); !s.ok())
    return Status::error("internal error, the decimated base domain is invalid: " + s.message());
  measureQuality(domain, out);
  if (options.progress)
    options.progress(1.0);
  return {};
}

} // namespace cmp
