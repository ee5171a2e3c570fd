#include <cmp/basedomain/BaseDomainBuilder.h>

#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/mesh/TriangleShape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <string>
#include <utility>

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

/// Adds, for every edge of `loops` (the surface on its left), the plane
/// through the edge perpendicular to its triangle, weighted by the edge's
/// squared length (Garland and Heckbert's boundary constraint), so that a
/// collapse along a loop prefers its straight stretches.
void addBoundaryQuadrics(const TriangleMesh& mesh, const std::vector<std::vector<int>>& loops,
  std::vector<Quadric>& quadrics)
{
  std::map<std::pair<int, int>, int> triangleOfEdge;
  for (const std::vector<int>& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i)
      triangleOfEdge.emplace(std::make_pair(loop[i], loop[(i + 1) % loop.size()]), -1);
  for (int t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
    {
      const auto found = triangleOfEdge.find({ mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3] });
      if (found != triangleOfEdge.end())
        found->second = t;
    }
  for (const auto& [edge, t] : triangleOfEdge)
  {
    if (t < 0)
      continue;
    const Triangle& tri = mesh.triangles[t];
    const Vec3& a = mesh.points[edge.first];
    const Vec3 along = mesh.points[edge.second] - a;
    const Vec3 normal = (mesh.points[tri[1]] - mesh.points[tri[0]]).cross(mesh.points[tri[2]] - mesh.points[tri[0]]);
    const Vec3 side = along.cross(normal);
    if (!(side.norm() > 0.0))
      continue;
    Eigen::Vector4d plane;
    plane << side.normalized(), -side.normalized().dot(a);
    const Quadric q = along.squaredNorm() * plane * plane.transpose();
    quadrics[edge.first] += q;
    quadrics[edge.second] += q;
  }
}

/// The surface the decimation runs on: the input with every boundary loop
/// closed by a cap (`capLoop()`), whose centre is one more locked vertex.
/// For a closed surface, the surface itself.
struct LandmarkedCaps
{
  TriangleMesh mesh;                   ///< The surface, then the centres and the caps' triangles.
  LandmarkList landmarks;              ///< The landmarks, then the centres (never collapsed).
  std::vector<std::vector<int>> loops; ///< The surface's boundary loops (`boundaryLoops()`).
  std::vector<int> centres;            ///< Per loop, its cap's centre.
};

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
  /// `surface` is the input (its triangles give the quadrics and the scale),
  /// `capped` what the decimation runs on.
  Decimator(const TriangleMesh& surface, const LandmarkedCaps& capped, const BaseDomainBuilderOptions& options)
    : mesh_(capped.mesh)
    , quadrics_(initialQuadrics(surface))
    , locked_(capped.mesh.points.size(), 0)
    , version_(capped.mesh.points.size(), 0)
    , centre_(capped.mesh.points.size(), 0)
    , loopOf_(capped.mesh.points.size(), -1)
    , centres_(capped.centres)
    , options_(options)
    , diagonal_(boundingBoxDiagonal(surface))
  {
    for (int v : capped.landmarks)
      locked_[v] = 1;
    remaining_ = capped.mesh.vertexCount() - static_cast<int>(capped.landmarks.size());
    // The caps' triangles are no part of the surface: they add no plane.
    quadrics_.resize(capped.mesh.points.size(), Quadric::Zero());
    addBoundaryQuadrics(surface, capped.loops, quadrics_);
    for (std::size_t j = 0; j < capped.loops.size(); ++j)
    {
      centre_[capped.centres[j]] = 1;
      for (int v : capped.loops[j])
        loopOf_[v] = static_cast<int>(j);
    }
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
  /// Nothing collapses into a cap's centre, and a vertex of a boundary loop
  /// only along its loop, so the loop stays a chain of boundary vertices
  /// between its landmarks and the cap a fan over it.
  Candidate evaluate(int u) const
  {
    Candidate best;
    mesh_.neighbours(u, candidates_);
    const int loop = loopOf_[u];
    for (int v : candidates_)
    {
      if (centre_[v] || (loop >= 0 && !inCapTriangle(u, v, centres_[loop])))
        continue;
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
      // A cap's triangles are no part of the surface: neither their folds
      // nor their shapes count.
      if (centre_[tri[0]] || centre_[tri[1]] || centre_[tri[2]])
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

  /// Whether some triangle has corners u, v and `c` (with c a cap's centre:
  /// whether u and v are neighbours along c's loop).
  bool inCapTriangle(int u, int v, int c) const
  {
    for (int t : mesh_.incident(u))
    {
      const Triangle& tri = mesh_.triangle(t);
      if (std::find(tri.begin(), tri.end(), v) != tri.end() && std::find(tri.begin(), tri.end(), c) != tri.end())
        return true;
    }
    return false;
  }

  /// Whether edge (u, w) is a cap's: a spoke to its centre or an edge of a
  /// boundary loop (a triangle on it has a centre). Never flipped, so that
  /// every cap stays the fan of its centre over its loop.
  bool capEdge(int u, int w) const
  {
    if (centre_[u] || centre_[w])
      return true;
    const int loop = loopOf_[u];
    return loop >= 0 && loop == loopOf_[w] && inCapTriangle(u, w, centres_[loop]);
  }

  /// Flips the edge between the two loop neighbours p and n of `u` (a
  /// vertex of a boundary loop), if there is one. Such a chord blocks u for
  /// good once u's other neighbour is a landmark: u cannot collapse along
  /// its loop (p and n would be joined twice) and flipping its edge to that
  /// neighbour would join them again. The chord, the spokes to p and n and
  /// the centre make a 3-cycle with u on one side, so the two vertices
  /// opposite the chord lie on either side of it and the flip is valid.
  bool flipChordAcross(int u)
  {
    const int c = centres_[loopOf_[u]];
    int ends[2] = { -1, -1 };
    for (int t : mesh_.incident(u))
    {
      const Triangle& tri = mesh_.triangle(t);
      if (std::find(tri.begin(), tri.end(), c) == tri.end())
        continue;
      for (int w : tri)
        if (w != u && w != c)
          (ends[0] < 0 ? ends[0] : ends[1]) = w;
    }
    if (ends[0] < 0 || ends[1] < 0 || capEdge(ends[0], ends[1]))
      return false;
    const std::vector<int> around = mesh_.neighbours(ends[0]);
    return std::binary_search(around.begin(), around.end(), ends[1]) && mesh_.flip(ends[0], ends[1]);
  }

  /// Nothing can be collapsed any more without folding, or at all: first
  /// allow folds, then flip edges around a blocked vertex until its degree
  /// is 3, which always makes a collapse valid on a closed surface (for a
  /// vertex of a boundary loop: its two loop neighbours and the centre,
  /// flipping no cap edge).
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
          if (capEdge(u, w))
            continue;
          if (mesh_.flip(u, w))
          {
            ++report.flips;
            flipped = true;
            break;
          }
        }
        if (!flipped && loopOf_[u] >= 0 && flipChordAcross(u))
        {
          ++report.flips;
          flipped = true;
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
  std::vector<char> centre_;  ///< Per vertex: 1 for a cap's centre.
  std::vector<int> loopOf_;   ///< Per vertex: its boundary loop, -1 for none.
  std::vector<int> centres_;  ///< Per boundary loop: its cap's centre.
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

/// Closes every boundary loop of an open `surface` (one that failed
/// `checkSurface()` with boundary edges) and checks the contract
/// (`checkSurfaceWithBoundaries()`): the capped surface passes
/// `checkSurface()`, the landmarks are valid and every loop carries at least
/// 3 of them.
Status capSurface(const TriangleMesh& surface, const LandmarkList& landmarks, LandmarkedCaps& capped)
{
  CappedSurface closed;
  if (Status s = checkSurfaceWithBoundaries(surface, nullptr, &closed); !s.ok())
    return s;
  if (Status s = validateLandmarks(landmarks, surface.vertexCount()); !s.ok())
    return s;
  if (Status s = checkSurfaceWithBoundaries(surface, &landmarks); !s.ok())
    return Status::error("open surface: " + s.message());
  capped.mesh = std::move(closed.mesh);
  capped.loops = std::move(closed.loops);
  capped.centres = std::move(closed.centres);
  capped.landmarks = landmarks;
  capped.landmarks.insert(capped.landmarks.end(), capped.centres.begin(), capped.centres.end());
  return {};
}

/// `loop` rotated to start at its smallest element, for comparing cycles.
std::vector<int> fromSmallest(std::vector<int> loop)
{
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

/// The open L0 from the decimated capped one (`closed`, whose base vertices
/// F + j are the caps' centres): every centre and its triangles removed.
/// Checks that each centre's star is a fan over its loop's landmarks, in
/// the loop's order, and that the open L0's boundary loops are those.
Status removeCaps(const BaseDomain& closed, const LandmarkedCaps& capped, const std::vector<int>& featureOfVertex,
  int featureCount, BaseDomain& domain)
{
  const auto internal = [](const std::string& what) {
    return Status::error("internal error: the decimated base domain does not fit the surface's boundary: " + what);
  };
  std::vector<std::vector<int>> expected;
  for (std::size_t j = 0; j < capped.loops.size(); ++j)
  {
    std::vector<int> corners; // the loop's landmarks, as features, in its order
    for (int v : capped.loops[j])
      if (featureOfVertex[v] >= 0)
        corners.push_back(featureOfVertex[v]);
    // The cap (q, p, c), c the centre, crosses loop edge p -> q.
    const int c = featureCount + static_cast<int>(j);
    std::map<int, int> next;
    for (const Triangle& t : closed.mesh.triangles)
      for (int k = 0; k < 3; ++k)
        if (t[k] == c && !next.emplace(t[(k + 2) % 3], t[(k + 1) % 3]).second)
          return internal("the cap of the boundary loop through vertex " + std::to_string(capped.loops[j].front()) +
            " is not a fan");
    bool fan = next.size() == corners.size();
    for (std::size_t i = 0; fan && i < corners.size(); ++i)
    {
      const auto found = next.find(corners[i]);
      fan = found != next.end() && found->second == corners[(i + 1) % corners.size()];
    }
    if (!fan)
      return internal("the cap of the boundary loop through vertex " + std::to_string(capped.loops[j].front()) +
        " is not a fan over the loop's landmarks in order");
    expected.push_back(fromSmallest(corners));
  }
  domain = BaseDomain{};
  domain.mesh.points.assign(closed.mesh.points.begin(), closed.mesh.points.begin() + featureCount);
  domain.featureIds.assign(closed.featureIds.begin(), closed.featureIds.begin() + featureCount);
  std::vector<char> used(featureCount, 0);
  for (const Triangle& t : closed.mesh.triangles)
    if (t[0] < featureCount && t[1] < featureCount && t[2] < featureCount)
    {
      domain.mesh.triangles.push_back(t);
      used[t[0]] = used[t[1]] = used[t[2]] = 1;
    }
  if (std::find(used.begin(), used.end(), 0) != used.end())
    return internal("a landmark is on no triangle once the caps are removed");
  std::vector<std::vector<int>> loops;
  if (Status s = boundaryLoops(domain.mesh, loops); !s.ok())
    return internal(s.message());
  for (std::vector<int>& loop : loops)
    loop = fromSmallest(loop);
  std::sort(loops.begin(), loops.end());
  std::sort(expected.begin(), expected.end());
  if (loops != expected)
    return internal("its boundary loops are not the boundary landmarks in the surface's order");
  return {};
}

/// The ring `ringNext` (each ring vertex -> the next, the strip on the
/// left) walked against its direction, as `shortestStrip()` takes it:
/// z[k + 1] -> z[k] is a ring edge. Empty unless the ring is one cycle of
/// at least 3 vertices.
std::vector<int> ringAgainstItsDirection(const std::map<int, int>& ringNext)
{
  const int n = static_cast<int>(ringNext.size());
  std::map<int, int> ringPrevious;
  for (const auto& [a, b] : ringNext)
    ringPrevious[b] = a;
  if (n < 3 || static_cast<int>(ringPrevious.size()) != n)
    return {};
  std::vector<int> z{ ringNext.begin()->first };
  while (static_cast<int>(z.size()) < n)
  {
    const auto found = ringPrevious.find(z.back());
    if (found == ringPrevious.end() || found->second == z.front())
      return {};
    z.push_back(found->second);
  }
  const auto closing = ringPrevious.find(z.back());
  if (closing == ringPrevious.end() || closing->second != z.front())
    return {};
  return z;
}

/// The shortest strip of triangles between `loop` (m vertices) and the ring
/// `z` (n vertices, run the loop's way round the hole: z[k + 1] -> z[k] is
/// a ring edge with the strip on its left): m + n triangles, each joining
/// edge from a loop vertex to a ring vertex, their summed `distance` least
/// over every first edge (Fuchs, Kedem and Uselton's optimal triangulation
/// between two contours, by dynamic programming).
std::vector<Triangle> shortestStrip(
  const std::vector<int>& loop, const std::vector<int>& z, const std::function<double(int, int)>& distance)
{
  const int m = static_cast<int>(loop.size()), n = static_cast<int>(z.size());
  // The shortest strip, from each possible first edge (loop[0], z[k0]).
  const double infinity = std::numeric_limits<double>::infinity();
  double bestCost = infinity;
  std::vector<Triangle> bestStrip;
  for (int k0 = 0; k0 < n; ++k0)
  {
    const auto ring = [&](int k) { return z[(k0 + k) % n]; };
    // cost[i][k]: the joining edges so far, the strip at edge (loop[i % m], ring(k)).
    std::vector<std::vector<double>> cost(m + 1, std::vector<double>(n + 1, infinity));
    std::vector<std::vector<char>> fromLoop(m + 1, std::vector<char>(n + 1, 0));
    cost[0][0] = distance(loop[0], ring(0));
    for (int i = 0; i <= m; ++i)
      for (int k = 0; k <= n; ++k)
      {
        if (i < m && cost[i][k] + distance(loop[(i + 1) % m], ring(k)) < cost[i + 1][k])
        {
          cost[i + 1][k] = cost[i][k] + distance(loop[(i + 1) % m], ring(k));
          fromLoop[i + 1][k] = 1;
        }
        if (k < n && cost[i][k] + distance(loop[i % m], ring(k + 1)) < cost[i][k + 1])
        {
          cost[i][k + 1] = cost[i][k] + distance(loop[i % m], ring(k + 1));
          fromLoop[i][k + 1] = 0;
        }
      }
    if (!(cost[m][n] < bestCost))
      continue;
    bestCost = cost[m][n];
    bestStrip.clear();
    for (int i = m, k = n; i > 0 || k > 0;)
    {
      if (fromLoop[i][k])
      {
        bestStrip.push_back({ { loop[i - 1], loop[i % m], ring(k) } });
        --i;
      }
      else
      {
        bestStrip.push_back({ { loop[i % m], ring(k), ring(k - 1) } });
        --k;
      }
    }
  }
  return bestStrip;
}

/// The open L0 made round rings (`buildBaseDomain()`): the capped surface
/// decimated to its inner landmarks and the caps' centres alone, so that
/// each centre stands for its hole among the landmarks round it as an inner
/// landmark would; then each centre's star is replaced by the shortest
/// strip between its loop's landmarks and its ring (the centre's
/// neighbours). Why: every boundary landmark then joins the ring landmarks
/// in its own direction, as on every model of the collection, where a loop
/// decimated with its landmarks kept can leave one of them joined to most
/// of the ring (a belly cut open round a landmark of 12 neighbours: one of
/// its 12 boundary landmarks joined to 9 landmarks). False, `domain`
/// unchanged, where that does not give an L0 whose boundary loops are the
/// surface's (too few inner landmarks, a centre whose ring touches another
/// hole, a strip that would repeat an edge, an L0 that is not a sphere
/// with holes).
bool buildAroundRings(const TriangleMesh& surface, const LandmarkList& landmarks, const LandmarkedCaps& capped,
  const BaseDomainBuilderOptions& options, BaseDomain& domain)
{
  const int featureCount = static_cast<int>(landmarks.size());
  std::vector<char> onLoop(capped.mesh.vertexCount(), 0);
  for (const std::vector<int>& loop : capped.loops)
    for (int v : loop)
      onLoop[v] = 1;
  LandmarkedCaps inner;
  inner.mesh = capped.mesh;
  std::vector<int> featureOfKept; // per landmark of `inner`: its feature (a centre's: F + j)
  for (int f = 0; f < featureCount; ++f)
    if (!onLoop[landmarks[f]])
    {
      inner.landmarks.push_back(landmarks[f]);
      featureOfKept.push_back(f);
    }
  for (std::size_t j = 0; j < capped.centres.size(); ++j)
  {
    inner.landmarks.push_back(capped.centres[j]);
    featureOfKept.push_back(featureCount + static_cast<int>(j));
  }
  if (inner.landmarks.size() < 4)
    return false;
  BaseDomainBuilderOptions quiet = options;
  quiet.progress = nullptr;
  BaseDomainBuilderReport ignored;
  Decimator decimator(surface, inner, quiet);
  if (!decimator.run(ignored).ok())
    return false;
  const std::vector<int> keptOfVertex = featureIdsOf(inner.landmarks, inner.mesh.vertexCount());
  std::vector<Triangle> triangles;
  const CollapsibleMesh& mesh = decimator.mesh();
  for (int t = 0; t < mesh.triangleCount(); ++t)
    if (mesh.alive(t))
    {
      const Triangle& tri = mesh.triangle(t);
      Triangle out;
      for (int k = 0; k < 3; ++k)
      {
        if (keptOfVertex[tri[k]] < 0)
          return false;
        out[k] = featureOfKept[keptOfVertex[tri[k]]];
      }
      triangles.push_back(out);
    }
  const auto distance = [&](int a, int b) {
    return (surface.points[landmarks[a]] - surface.points[landmarks[b]]).norm();
  };
  const std::vector<int> featureOfVertex = featureIdsOf(landmarks, capped.mesh.vertexCount());
  std::vector<std::vector<int>> expected;
  for (std::size_t j = 0; j < capped.loops.size(); ++j)
  {
    const int centre = featureCount + static_cast<int>(j);
    std::vector<int> loop; // the loop's landmarks, as features, in its order
    for (int v : capped.loops[j])
      if (featureOfVertex[v] >= 0)
        loop.push_back(featureOfVertex[v]);
    // The ring: (a, b, centre) runs a -> b round the centre.
    std::map<int, int> ringNext;
    std::vector<Triangle> rest;
    for (const Triangle& tri : triangles)
    {
      int k = 0;
      while (k < 3 && tri[k] != centre)
        ++k;
      if (k == 3)
      {
        rest.push_back(tri);
        continue;
      }
      const int a = tri[(k + 1) % 3], b = tri[(k + 2) % 3];
      if (a >= featureCount || b >= featureCount || !ringNext.emplace(a, b).second)
        return false; // another centre on the ring, or not a fan
    }
    const std::vector<int> z = ringAgainstItsDirection(ringNext);
    if (z.empty())
      return false;
    // Joined by direction round the hole: the angle between a boundary
    // landmark and a ring landmark seen from the hole's centre, in the
    // plane the loop spans (the loop is small beside its ring, so that
    // distances alone join one boundary landmark to most of the ring).
    const Vec3 centrePoint = capped.mesh.points[capped.centres[j]];
    Vec3 normal = Vec3::Zero();
    const std::vector<int>& rim = capped.loops[j];
    for (std::size_t i = 0; i < rim.size(); ++i)
      normal += (capped.mesh.points[rim[i]] - centrePoint).cross(capped.mesh.points[rim[(i + 1) % rim.size()]] - centrePoint);
    if (!(normal.norm() > 0.0))
      return false;
    normal.normalize();
    const Vec3 first = (surface.points[landmarks[loop.front()]] - centrePoint);
    const Vec3 e1 = (first - first.dot(normal) * normal).normalized();
    const Vec3 e2 = normal.cross(e1);
    if (!e1.allFinite())
      return false;
    const auto angleOf = [&](int f) {
      const Vec3 d = surface.points[landmarks[f]] - centrePoint;
      return std::atan2(d.dot(e2), d.dot(e1));
    };
    double scale = 0.0;
    for (int a : loop)
      for (int b : z)
        scale = std::max(scale, distance(a, b));
    const auto byDirection = [&](int a, int b) {
      const double turn = std::abs(std::remainder(angleOf(a) - angleOf(b), 2.0 * kPi));
      return turn + 1e-2 * distance(a, b) / scale;
    };
    const std::vector<Triangle> strip = shortestStrip(loop, z, byDirection);
    if (strip.size() != loop.size() + z.size())
      return false;
    rest.insert(rest.end(), strip.begin(), strip.end());
    triangles = std::move(rest);
    expected.push_back(fromSmallest(loop));
  }
  BaseDomain built;
  for (int f = 0; f < featureCount; ++f)
  {
    built.mesh.points.push_back(surface.points[landmarks[f]]);
    built.featureIds.push_back(f);
  }
  built.mesh.triangles = std::move(triangles);
  // Each directed edge once (oriented, no edge repeated), every landmark on
  // a triangle, the boundary loops the surface's, and closed again a valid
  // L0.
  std::set<std::pair<int, int>> runs;
  std::vector<char> used(featureCount, 0);
  for (const Triangle& tri : built.mesh.triangles)
    for (int k = 0; k < 3; ++k)
    {
      used[tri[k]] = 1;
      if (!runs.insert({ tri[k], tri[(k + 1) % 3] }).second)
        return false;
    }
  if (std::find(used.begin(), used.end(), 0) != used.end())
    return false;
  std::vector<std::vector<int>> loops;
  if (!boundaryLoops(built.mesh, loops).ok())
    return false;
  for (std::vector<int>& loop : loops)
    loop = fromSmallest(loop);
  std::sort(loops.begin(), loops.end());
  std::sort(expected.begin(), expected.end());
  // A sphere with as many holes as loops: V - E + F = 2 - loops.
  std::set<std::pair<int, int>> edges;
  for (const auto& [a, b] : runs)
    edges.insert(std::minmax(a, b));
  const long euler = static_cast<long>(featureCount) - static_cast<long>(edges.size()) +
    static_cast<long>(built.mesh.triangles.size());
  if (loops != expected || euler != 2 - static_cast<long>(loops.size()))
    return false;
  domain = std::move(built);
  return true;
}

/// Re-triangulates the band of an open L0 round each boundary loop (the
/// triangles with a corner on the loop) as the shortest strip between the
/// loop and the ring of landmarks round it: each boundary landmark is
/// joined to the landmarks of the ring nearest to it in the order of both
/// (Fuchs, Kedem and Uselton's optimal strip between two contours, by
/// dynamic programming over the joining edges' summed lengths). Why: a
/// boundary landmark only collapses along its loop, so the decimation can
/// leave one boundary landmark of a crowded loop joined to most of the
/// ring and its neighbours on the loop to one landmark each, and every
/// other model's curves then wind round the hole to reach them. A band
/// that is not such a strip (a chord between boundary landmarks, a ring
/// that touches itself or the loop) is left as it is. Returns the bands
/// made anew.
int restripBoundaryBands(BaseDomain& domain)
{
  std::vector<std::vector<int>> loops;
  if (!boundaryLoops(domain.mesh, loops).ok())
    return 0;
  std::vector<Triangle>& triangles = domain.mesh.triangles;
  const auto distance = [&](int a, int b) { return (domain.mesh.points[a] - domain.mesh.points[b]).norm(); };
  int made = 0;
  for (const std::vector<int>& loop : loops)
  {
    const int m = static_cast<int>(loop.size());
    std::map<int, int> place; // loop vertex -> its index on the loop
    for (int i = 0; i < m; ++i)
      place[loop[i]] = i;
    // The band, and its edges on the ring: a ring edge (y, y') runs along
    // its band triangle with the band on the left, and its other side is
    // outside the band.
    std::vector<int> band;
    std::set<std::pair<int, int>> directed;
    bool strip = true;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    {
      const Triangle& tri = triangles[t];
      int onLoop = 0;
      for (int v : tri)
        onLoop += place.count(v) ? 1 : 0;
      if (onLoop == 0)
        continue;
      band.push_back(t);
      if (onLoop == 3)
        strip = false;
      for (int k = 0; k < 3; ++k)
      {
        const int a = tri[k], b = tri[(k + 1) % 3];
        directed.insert({ a, b });
        // Two loop corners must be a loop edge, run the loop's way.
        if (onLoop == 2 && place.count(a) && place.count(b) && loop[(place[a] + 1) % m] != b)
          strip = false;
      }
    }
    std::map<int, int> ringNext; // ring vertex -> the next one, the band on the left
    for (const auto& [a, b] : directed)
      if (!place.count(a) && !place.count(b) && !directed.count({ b, a }))
        strip = strip && ringNext.emplace(a, b).second;
    const int n = static_cast<int>(ringNext.size());
    if (!strip || n < 3 || static_cast<int>(band.size()) != m + n)
      continue;
    // The ring in order, walked against its direction so that it runs the
    // loop's way round the hole.
    const std::vector<int> z = ringAgainstItsDirection(ringNext);
    if (z.empty())
      continue; // the ring is not one cycle
    const std::vector<Triangle> bestStrip = shortestStrip(loop, z, distance);
    // The new joining edges must not be edges already (outside the band).
    std::set<std::pair<int, int>> outside;
    std::vector<char> inBand(triangles.size(), 0);
    for (int t : band)
      inBand[t] = 1;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
      if (!inBand[t])
        for (int k = 0; k < 3; ++k)
          outside.insert(std::minmax(triangles[t][k], triangles[t][(k + 1) % 3]));
    bool fits = static_cast<int>(bestStrip.size()) == m + n;
    for (const Triangle& tri : bestStrip)
      for (int k = 0; k < 3 && fits; ++k)
      {
        const int a = tri[k], b = tri[(k + 1) % 3];
        fits = !(place.count(a) != place.count(b) && outside.count(std::minmax(a, b)));
      }
    if (!fits)
      continue;
    const std::vector<Triangle> before = triangles;
    for (std::size_t i = 0; i < band.size(); ++i)
      triangles[band[i]] = bestStrip[i];
    // Oriented as before: each directed edge once, each edge of two
    // triangles run both ways.
    std::set<std::pair<int, int>> runs;
    bool oriented = true;
    for (const Triangle& tri : triangles)
      for (int k = 0; k < 3; ++k)
        oriented = oriented && runs.insert({ tri[k], tri[(k + 1) % 3] }).second;
    std::vector<std::vector<int>> after;
    if (!oriented || !boundaryLoops(domain.mesh, after).ok() || after.size() != loops.size())
    {
      triangles = before;
      continue;
    }
    ++made;
  }
  return made;
}

/// The corner angle at `c` of triangle (a, b, c), from the base vertices'
/// positions.
double angleAt(const BaseDomain& domain, int a, int b, int c)
{
  const Vec3 u = domain.mesh.points[a] - domain.mesh.points[c], w = domain.mesh.points[b] - domain.mesh.points[c];
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

/// Flips the inner edges of an open L0 whose two opposite corners sum to
/// more than a half turn (Delaunay's criterion on the landmarks'
/// positions) while the two triangles, flipped, still face the way they
/// did (the quadrilateral is not folded), no vertex is left on fewer than
/// two triangles, and the new edge is not one already or a chord between
/// two boundary landmarks. Why: a boundary landmark only collapses along
/// its loop, so the decimation leaves one boundary landmark of a crowded
/// loop joined to most of the landmarks round it (a belly cut open round
/// a landmark of 12 neighbours: one of its 12 boundary landmarks joined to
/// 9 of them), and every other model's curves then wind round the hole to
/// reach them. Returns the flips made.
int flipToDelaunay(BaseDomain& domain)
{
  std::vector<Triangle>& triangles = domain.mesh.triangles;
  const int vertices = domain.mesh.vertexCount();
  std::vector<char> onBoundary;
  if (!boundaryVertices(domain.mesh, onBoundary).ok())
    return 0;
  const auto normal = [&](int a, int b, int c) {
    const Vec3 &p = domain.mesh.points[a], &q = domain.mesh.points[b], &r = domain.mesh.points[c];
    return Vec3((q - p).cross(r - p));
  };
  int flips = 0;
  const int most = 10 * static_cast<int>(triangles.size());
  for (bool changed = true; changed && flips < most;)
  {
    changed = false;
    std::map<std::pair<int, int>, int> triangleOf; // directed edge -> its triangle
    std::vector<int> trianglesAt(vertices, 0);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
      for (int k = 0; k < 3; ++k)
      {
        triangleOf[{ triangles[t][k], triangles[t][(k + 1) % 3] }] = t;
        ++trianglesAt[triangles[t][k]];
      }
    // The edge that most breaks the criterion goes first.
    double worst = kPi + 1e-9;
    int best = -1, bestOther = -1, a = -1, b = -1, c = -1, d = -1;
    for (const auto& [edge, t] : triangleOf)
    {
      const auto [u, w] = edge;
      if (u > w)
        continue;
      const auto across = triangleOf.find({ w, u });
      if (across == triangleOf.end())
        continue; // a boundary edge
      const int o = across->second;
      const auto third = [&](int tri) {
        for (int v : triangles[tri])
          if (v != u && v != w)
            return v;
        return -1;
      };
      const int x = third(t), y = third(o);
      if (x == y || triangleOf.count({ x, y }) || triangleOf.count({ y, x }) || (onBoundary[x] && onBoundary[y]))
        continue;
      if (trianglesAt[u] < 3 || trianglesAt[w] < 3)
        continue;
      const double opposite = angleAt(domain, u, w, x) + angleAt(domain, w, u, y);
      if (!(opposite > worst))
        continue;
      // (u, w, x) and (w, u, y) become (u, y, x) and (w, x, y).
      const Vec3 before = normal(u, w, x).normalized() + normal(w, u, y).normalized();
      if (!(normal(u, y, x).dot(before) > 0.0 && normal(w, x, y).dot(before) > 0.0))
        continue;
      worst = opposite;
      best = t;
      bestOther = o;
      a = u;
      b = w;
      c = x;
      d = y;
    }
    if (best < 0)
      break;
    triangles[best] = { { a, d, c } };
    triangles[bestOther] = { { b, c, d } };
    ++flips;
    changed = true;
  }
  return flips;
}

} // namespace

Status buildBaseDomain(const TriangleMesh& surface, const LandmarkList& landmarks, BaseDomain& domain,
  const BaseDomainBuilderOptions& options, BaseDomainBuilderReport* report)
{
  const SurfaceCheckResult check = checkSurface(surface);
  LandmarkedCaps capped;
  if (check.ok())
  {
    if (Status s = validateLandmarks(landmarks, surface.vertexCount()); !s.ok())
      return s;
    if (landmarks.size() < 4)
      return Status::error("too few landmarks: " + std::to_string(landmarks.size()) +
        " given, but a closed base domain needs at least 4 (a tetrahedron)");
    capped.mesh = surface;
    capped.landmarks = landmarks;
  }
  else if (check.defect != SurfaceDefect::BoundaryEdge)
    return Status::error(check.message);
  else if (Status s = capSurface(surface, landmarks, capped); !s.ok())
    return s;

  BaseDomainBuilderReport localReport;
  BaseDomainBuilderReport& out = report ? *report : localReport;
  out = BaseDomainBuilderReport{};
  Decimator decimator(surface, capped, options);
  if (Status s = decimator.run(out); !s.ok())
    return s;

  // The decimated surface (capped), base vertex f at landmark f; the caps'
  // centres follow the landmarks.
  const int featureCount = static_cast<int>(landmarks.size());
  const int cappedCount = static_cast<int>(capped.landmarks.size());
  const std::vector<int> featureOfVertex = featureIdsOf(capped.landmarks, capped.mesh.vertexCount());
  BaseDomain decimated;
  for (int v : capped.landmarks)
    decimated.mesh.points.push_back(capped.mesh.points[v]);
  for (int f = 0; f < cappedCount; ++f)
    decimated.featureIds.push_back(f);
  const CollapsibleMesh& mesh = decimator.mesh();
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    if (!mesh.alive(t))
      continue;
    const Triangle& tri = mesh.triangle(t);
    decimated.mesh.triangles.push_back({ featureOfVertex[tri[0]], featureOfVertex[tri[1]], featureOfVertex[tri[2]] });
  }
  if (capped.loops.empty())
  {
    domain = std::move(decimated);
    if (Status s = checkBaseDomain(domain, featureCount); !s.ok())
      return Status::error("internal error, the decimated base domain is invalid: " + s.message());
  }
  else
  {
    if (Status s = checkBaseDomain(decimated, cappedCount); !s.ok())
      return Status::error("internal error: the decimated base domain (its holes capped) is invalid: " + s.message());
    if (Status s = removeCaps(decimated, capped, featureOfVertex, featureCount, domain); !s.ok())
      return s;
    // Made round rings where that works; else the band round each hole
    // made anew where it is a strip. Then every inner edge towards
    // Delaunay's criterion.
    if (options.aroundRings && buildAroundRings(surface, landmarks, capped, options, domain))
      out.ringedHoles = static_cast<int>(capped.loops.size());
    else
      out.restripedBands = restripBoundaryBands(domain);
    out.flips += flipToDelaunay(domain);
  }
  measureQuality(domain, out);
  if (options.progress)
    options.progress(1.0);
  return {};
}

} // namespace cmp
