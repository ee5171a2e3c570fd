#include <cmp/layout/NetTracer.h>

#include <cmp/layout/FeatureParameterization.h>
#include <cmp/mesh/SurfaceCheck.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

namespace cmp
{

namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Position of `edge` in the counter-clockwise order around `vertex`.
int positionAt(const BaseTopology& base, int vertex, int edge)
{
  const auto& ring = base.rotation[vertex];
  return static_cast<int>(std::find(ring.begin(), ring.end(), edge) - ring.begin());
}

/// Third vertex of a base triangle, given two of its vertices.
int thirdVertex(const Triangle& tri, int a, int b)
{
  for (int v : tri)
    if (v != a && v != b)
      return v;
  return -1;
}

/// Dijkstra over free mesh vertices. Reused across runs: a stamp marks which
/// entries belong to the current run, so nothing is cleared per run.
class BrushFire
{
public:
  /// Grows from `source` through the halfedges `starts` and stops at
  /// `target`, which it may enter only from a vertex marked as a gate; or,
  /// with `target < 0`, at the first gate vertex it reaches. Fills `path`
  /// (source first) and returns its cost, or infinity if nothing was reached.
  /// `remaining(x)` is a lower bound of the cost from x to the target (with
  /// `target < 0`, to the nearest gate; 0 on the gates) that never drops by
  /// more than an edge's cost along the edge (A*): the path found is a
  /// cheapest one all the same, but the fire stays near the line to the
  /// target instead of flooding a disc.
  template <class Cost, class Remaining>
  double run(const EditableMesh& mesh, const std::vector<char>& blocked, int source, const std::vector<int>& starts,
    int target, const std::vector<int>& gates, Cost cost, Remaining remaining, std::vector<int>& path)
  {
    resize(mesh.vertexCount());
    ++stamp_;
    for (int g : gates)
      gate_[g] = stamp_;
    // A binary heap as std::priority_queue keeps one, in storage kept
    // across runs.
    std::vector<Entry>& heap = heap_;
    heap.clear();
    const auto relax = [&](int x, int from, double d)
    {
      if (closed_[x] == stamp_ || (seen_[x] == stamp_ && dist_[x] <= d))
        return;
      seen_[x] = stamp_;
      dist_[x] = d;
      parent_[x] = from;
      heap.push_back({ d + remaining(x), x });
      std::push_heap(heap.begin(), heap.end(), std::greater<Entry>());
    };
    for (int h : starts)
    {
      const int x = mesh.to(h);
      if (!blocked[x] || (target < 0 && gate_[x] == stamp_))
        relax(x, source, cost(source, x));
    }
    int reached = -1;
    while (!heap.empty())
    {
      std::pop_heap(heap.begin(), heap.end(), std::greater<Entry>());
      const int x = heap.back().second;
      heap.pop_back();
      if (closed_[x] == stamp_)
        continue; // a stale entry: x was settled through a cheaper one
      closed_[x] = stamp_;
      const double d = dist_[x];
      if (x == target || (target < 0 && gate_[x] == stamp_))
      {
        reached = x;
        break;
      }
      if (blocked[x])
        continue; // only the target may be blocked, and it ends the search
      const int first = mesh.outgoing(x);
      int h = first;
      do
      {
        const int y = mesh.to(h);
        const bool enterTarget = y == target && gate_[x] == stamp_;
        if (enterTarget || !blocked[y] || (target < 0 && gate_[y] == stamp_))
          relax(y, x, d + cost(x, y));
        h = mesh.nextAroundVertex(h);
      } while (h != first);
    }
    path.clear();
    if (reached < 0)
      return kInfinity;
    for (int v = reached; v != source; v = parent_[v])
      path.push_back(v);
    path.push_back(source);
    std::reverse(path.begin(), path.end());
    return dist_[reached];
  }

private:
  using Entry = std::pair<double, int>;

  void resize(int n)
  {
    if (static_cast<int>(dist_.size()) < n)
    {
      dist_.resize(n);
      parent_.resize(n);
      seen_.resize(n, 0);
      gate_.resize(n, 0);
      closed_.resize(n, 0);
    }
  }

  std::vector<double> dist_;
  std::vector<int> parent_;
  std::vector<unsigned> seen_, gate_, closed_;
  std::vector<Entry> heap_;
  unsigned stamp_ = 0;
};

class Tracer
{
public:
  Tracer(const BaseDomain& domain, const NetTracerOptions& options, TracedNet& net, NetTracerReport& report)
    : domain_(domain)
    , options_(options)
    , net_(net)
    , report_(report)
  {
    base_.build(domain);
  }

  /// Traces the net. `coordinates` holds the harmonic parameterization of
  /// `surface`, or is empty (`featureCount` 0) and then gets it; the tracer works
  /// on a copy, which grows as edges are split. With `waiting`, a curve the
  /// swirl detector postpones waits until the net changes round it (see
  /// `NetTracerOptions::retraceWaiting`); without, it is requeued at a
  /// penalised priority, at most `maxPenalties` times.
  Status run(const TriangleMesh& surface, const LandmarkList& landmarks, FeatureCoordinates& coordinates, bool waiting)
  {
    waiting_ = waiting;
    if (Status s = net_.mesh.build(surface); !s.ok())
      return s;
    if (Status s = checkPresetCurves(landmarks); !s.ok())
      return s;
    if (coordinates.featureCount == 0)
      if (Status s = computeFeatureCoordinates(surface, landmarks, coordinates, options_.featureCoordinates); !s.ok())
        return s;
    coordinates_ = coordinates;
    const int baseVertices = domain_.mesh.vertexCount();
    net_.landmarkVertex.resize(baseVertices);
    featureOf_.resize(baseVertices);
    occupied_.assign(surface.vertexCount(), 0);
    for (int bv = 0; bv < baseVertices; ++bv)
    {
      featureOf_[bv] = domain_.featureIds[bv];
      net_.landmarkVertex[bv] = landmarks[featureOf_[bv]];
      occupied_[net_.landmarkVertex[bv]] = 1;
    }
    net_.baseEdges = base_.edges;
    net_.leftTriangle = base_.left;
    net_.rightTriangle = base_.right;
    const int edgeCount = static_cast<int>(base_.edges.size());
    net_.curves.assign(edgeCount, {});
    tentative_.assign(edgeCount, {});
    traced_.assign(edgeCount, 0);
    penalties_.assign(edgeCount, 0);
    // Preset curves first, all of them, then room round them all at once:
    // splitting round one before the next is in would split the next's edges.
    std::vector<int> crowded = net_.landmarkVertex;
    for (std::size_t i = 0; i < options_.presetCurves.size(); ++i)
    {
      const int e = presetEdge_[i];
      net_.curves[e] = options_.presetCurves[i].vertices;
      if (featureOf_[base_.edges[e][0]] != options_.presetCurves[i].from)
        std::reverse(net_.curves[e].begin(), net_.curves[e].end());
      occupy(e);
      crowded.insert(crowded.end(), net_.curves[e].begin(), net_.curves[e].end());
    }
    makeRoom(crowded);

    if (Status s = traceAll(); !s.ok())
      return s;
    for (const auto& curve : net_.curves)
      report_.netLength += curveLength(net_.mesh, curve);
    return labelPatches(net_);
  }

private:
  struct Candidate
  {
    double priority;
    int edge;
    bool operator>(const Candidate& other) const { return priority > other.priority; }
  };

  /// Checks the preset curves against the surface and the base domain and
  /// finds the base edge of each (`presetEdge_`).
  Status checkPresetCurves(const LandmarkList& landmarks)
  {
    const int features = static_cast<int>(landmarks.size());
    const int vertices = net_.mesh.vertexCount();
    std::vector<int> baseVertexOf(features, -1);
    for (int bv = 0; bv < domain_.mesh.vertexCount(); ++bv)
      if (domain_.featureIds[bv] >= 0 && domain_.featureIds[bv] < features)
        baseVertexOf[domain_.featureIds[bv]] = bv;
    std::vector<char> isLandmark(vertices, 0);
    for (int v : landmarks)
      if (v >= 0 && v < vertices)
        isLandmark[v] = 1;
    std::vector<int> owner(vertices, -1); // preset curve holding an inner vertex
    std::vector<int> seenIn(vertices, -1); // last preset curve through a vertex
    std::vector<int> presetOfEdge(base_.edges.size(), -1);
    presetEdge_.clear();
    for (std::size_t i = 0; i < options_.presetCurves.size(); ++i)
    {
      const PresetCurve& curve = options_.presetCurves[i];
      const std::string name = "preset curve " + std::to_string(i) + " (features " + std::to_string(curve.from) +
        " to " + std::to_string(curve.to) + ")";
      for (int f : { curve.from, curve.to })
      {
        if (f < 0 || f >= features)
          return Status::error(name + ": feature " + std::to_string(f) + " is out of range (0.." +
            std::to_string(features - 1) + ")");
        if (baseVertexOf[f] < 0)
          return Status::error(name + ": feature " + std::to_string(f) + " has no base vertex");
      }
      const int e = base_.edgeBetween(baseVertexOf[curve.from], baseVertexOf[curve.to]);
      if (e < 0)
        return Status::error(name + ": no edge of the base domain joins the two features");
      if (presetOfEdge[e] >= 0)
        return Status::error(name + ": preset curve " + std::to_string(presetOfEdge[e]) +
          " is already the curve of that base edge");
      presetOfEdge[e] = static_cast<int>(i);
      const std::vector<int>& path = curve.vertices;
      if (path.size() < 2)
        return Status::error(name + ": needs at least 2 vertices (it has " + std::to_string(path.size()) + ")");
      for (int v : path)
        if (v < 0 || v >= vertices)
          return Status::error(name + ": vertex " + std::to_string(v) + " is out of range (the surface has " +
            std::to_string(vertices) + ")");
      if (path.front() != landmarks[curve.from] || path.back() != landmarks[curve.to])
        return Status::error(name + ": does not run from the landmark of feature " + std::to_string(curve.from) +
          " (vertex " + std::to_string(landmarks[curve.from]) + ") to that of feature " + std::to_string(curve.to) +
          " (vertex " + std::to_string(landmarks[curve.to]) + ")");
      for (std::size_t k = 0; k + 1 < path.size(); ++k)
        if (net_.mesh.findHalfedge(path[k], path[k + 1]) < 0)
          return Status::error(name + ": vertices " + std::to_string(path[k]) + " and " +
            std::to_string(path[k + 1]) + " are not joined by a mesh edge");
      for (int v : path)
      {
        if (seenIn[v] == static_cast<int>(i))
          return Status::error(name + ": vertex " + std::to_string(v) + " repeats");
        seenIn[v] = static_cast<int>(i);
      }
      for (std::size_t k = 1; k + 1 < path.size(); ++k)
      {
        const int v = path[k];
        if (isLandmark[v])
          return Status::error(name + ": inner vertex " + std::to_string(v) + " is a landmark");
        if (owner[v] >= 0)
          return Status::error(name + ": inner vertex " + std::to_string(v) + " is on preset curve " +
            std::to_string(owner[v]) + " too");
        owner[v] = static_cast<int>(i);
      }
      presetEdge_.push_back(e);
    }
    return {};
  }

  /// Spanning tree of the base domain first, then the rest; shortest
  /// tentative curve first; invalid ones re-traced, swirling ones postponed.
  /// Preset curves are in already.
  Status traceAll()
  {
    const int edgeCount = static_cast<int>(base_.edges.size());
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue;
    for (int e = 0; e < edgeCount; ++e)
    {
      if (traced_[e])
        continue; // preset
      if (Status s = retrace(e); !s.ok())
        return s;
      queue.push({ curveLength(net_.mesh, tentative_[e]), e });
    }
    std::vector<int> component(domain_.mesh.vertexCount());
    std::iota(component.begin(), component.end(), 0);
    const auto root = [&](int v)
    {
      while (component[v] != v)
        v = component[v] = component[component[v]];
      return v;
    };
    int treeEdges = 0, inserted = 0;
    const int treeSize = domain_.mesh.vertexCount() - 1;
    for (int e : presetEdge_)
    {
      ++inserted;
      const int ra = root(base_.edges[e][0]), rb = root(base_.edges[e][1]);
      if (ra != rb)
      {
        component[ra] = rb;
        ++treeEdges;
      }
    }
    std::vector<int> deferred;
    // Curves the swirl detector postponed while waiting_: each waits until a
    // curve at a corner of its two base triangles is in (which of the
    // swirled configurations is fair shows only once more curves join those
    // landmarks; a curve elsewhere changes nothing the detector sees). When
    // only postponed curves are left, the cheapest goes in unchecked. Every
    // return to the queue follows an insertion, so the loop ends.
    std::vector<Candidate> postponed;
    while (!queue.empty() || !postponed.empty())
    {
      bool forced = false;
      if (queue.empty())
      {
        const auto cheapest = std::min_element(postponed.begin(), postponed.end(),
          [](const Candidate& x, const Candidate& y) { return x.priority < y.priority; });
        queue.push(*cheapest);
        postponed.erase(cheapest);
        forced = true;
      }
      const Candidate candidate = queue.top();
      queue.pop();
      const int e = candidate.edge;
      const int a = base_.edges[e][0], b = base_.edges[e][1];
      if (treeEdges < treeSize && root(a) == root(b))
      {
        deferred.push_back(e); // would close a cycle before the tree is complete
        continue;
      }
      if (!isValid(e))
      {
        ++report_.retraced;
        if (Status s = retrace(e); !s.ok())
          return s;
        queue.push({ curveLength(net_.mesh, tentative_[e]), e });
        continue;
      }
      const bool spent = !waiting_ && penalties_[e] >= options_.maxPenalties;
      if (options_.detectSwirls && !forced && !spent && swirls(e))
      {
        ++penalties_[e];
        ++report_.penalised;
        const Candidate later{ candidate.priority * options_.penaltyFactor, e };
        if (waiting_)
          postponed.push_back(later);
        else
          queue.push(later);
        continue;
      }
      // Checked once more for the report's forcedSwirls, which in the first
      // trace decides whether the net is traced again (only forced or spent
      // curves, a few per net).
      if (options_.detectSwirls && (forced || spent) && options_.retraceWaiting && swirls(e))
        ++report_.forcedSwirls;
      insert(e);
      ++inserted;
      for (std::size_t i = 0; i < postponed.size();)
      {
        const std::array<int, 4> corners = cornersOf(postponed[i].edge);
        if (std::find(corners.begin(), corners.end(), a) != corners.end() ||
          std::find(corners.begin(), corners.end(), b) != corners.end())
        {
          queue.push(postponed[i]);
          postponed[i] = postponed.back();
          postponed.pop_back();
        }
        else
          ++i;
      }
      if (options_.progress)
        options_.progress(static_cast<double>(inserted) / edgeCount);
      if (treeEdges < treeSize)
      {
        component[root(a)] = root(b);
        if (++treeEdges == treeSize)
        {
          for (int d : deferred)
            queue.push({ curveLength(net_.mesh, tentative_[d]), d });
          deferred.clear();
        }
      }
    }
    if (inserted != edgeCount)
      return Status::error("internal error: only " + std::to_string(inserted) + " of " + std::to_string(edgeCount) +
        " curves were traced");
    return {};
  }

  /// Outgoing mesh halfedges of base vertex bv's landmark that lie strictly
  /// between the curves of the traced edges found by searching the rotation
  /// backwards from position `before` and forwards from position `after`.
  std::vector<int> sector(int bv, int before, int after) const
  {
    const auto& ring = base_.rotation[bv];
    const int degree = static_cast<int>(ring.size());
    int predecessor = -1, successor = -1;
    for (int k = 0; k < degree && predecessor < 0; ++k)
    {
      const int e = ring[((before - k) % degree + degree) % degree];
      predecessor = traced_[e] ? e : -1;
    }
    for (int k = 0; k < degree && successor < 0; ++k)
    {
      const int e = ring[(after + k) % degree];
      successor = traced_[e] ? e : -1;
    }
    const int v = net_.landmarkVertex[bv];
    std::vector<int> halfedges;
    const int first = net_.mesh.outgoing(v);
    if (predecessor < 0)
    {
      int h = first;
      do
      {
        halfedges.push_back(h);
        h = net_.mesh.nextAroundVertex(h);
      } while (h != first);
      return halfedges;
    }
    const int from = curveHalfedgeAt(predecessor, bv);
    const int until = curveHalfedgeAt(successor, bv);
    for (int h = net_.mesh.nextAroundVertex(from); h != until; h = net_.mesh.nextAroundVertex(h))
      halfedges.push_back(h);
    return halfedges;
  }

  /// The mesh halfedge by which the curve of a traced edge leaves bv's landmark.
  int curveHalfedgeAt(int e, int bv) const
  {
    const auto& curve = net_.curves[e];
    const bool atStart = base_.edges[e][0] == bv;
    return net_.mesh.findHalfedge(net_.landmarkVertex[bv], atStart ? curve[1] : curve[curve.size() - 2]);
  }

  std::vector<int> edgeSector(int e, int bv) const
  {
    const int position = positionAt(base_, bv, e);
    return sector(bv, position - 1, position + 1);
  }

  Status retrace(int e)
  {
    const int a = base_.edges[e][0], b = base_.edges[e][1];
    const std::vector<int> starts = edgeSector(e, a);
    std::vector<int> gates;
    for (int h : edgeSector(e, b))
      gates.push_back(net_.mesh.to(h));
    const int fa = featureOf_[a], fb = featureOf_[b];
    const double weight = options_.parameterizationWeight;
    const auto cost = [&](int x, int y)
    {
      const double k = 0.5 * (coordinates_.at(x, fa) + coordinates_.at(x, fb) + coordinates_.at(y, fa) +
                         coordinates_.at(y, fb));
      return (net_.mesh.point(x) - net_.mesh.point(y)).norm() * (1.0 + weight * (1.0 - k));
    };
    // Every edge costs at least its length (pi[f] + pi[f'] <= 1), so the
    // straight distance to the target bounds what is left.
    const Vec3 target = net_.mesh.point(net_.landmarkVertex[b]);
    const auto remaining = [&](int x) { return weight >= 0.0 ? (net_.mesh.point(x) - target).norm() : 0.0; };
    ++report_.traces;
    const double found = fire_.run(net_.mesh, occupied_, net_.landmarkVertex[a], starts, net_.landmarkVertex[b],
      gates, cost, remaining, tentative_[e]);
    if (found == kInfinity)
      return Status::error("internal error: no curve found between features " + std::to_string(featureOf_[a]) +
        " and " + std::to_string(featureOf_[b]));
    return {};
  }

  /// Is the tentative curve still free, still made of mesh edges, and does
  /// it still leave both landmarks in the right sector?
  bool isValid(int e) const
  {
    const auto& path = tentative_[e];
    for (std::size_t i = 1; i + 1 < path.size(); ++i)
      if (occupied_[path[i]])
        return false;
    for (std::size_t i = 1; i < path.size(); ++i)
      if (net_.mesh.findHalfedge(path[i - 1], path[i]) < 0)
        return false;
    const auto inSector = [&](int bv, int neighbour)
    {
      const int h = net_.mesh.findHalfedge(net_.landmarkVertex[bv], neighbour);
      const std::vector<int> allowed = edgeSector(e, bv);
      return std::find(allowed.begin(), allowed.end(), h) != allowed.end();
    };
    return inSector(base_.edges[e][0], path[1]) && inSector(base_.edges[e][1], path[path.size() - 2]);
  }

  /// The four base vertices of the two base triangles beside edge `e`.
  std::array<int, 4> cornersOf(int e) const
  {
    const int a = base_.edges[e][0], b = base_.edges[e][1];
    return { a, b, thirdVertex(domain_.mesh.triangles[base_.left[e]], a, b),
      thirdVertex(domain_.mesh.triangles[base_.right[e]], a, b) };
  }

  /// The paper's swirl detector: from the third vertex of each base triangle
  /// beside the edge, the closest point of the tentative curve must be
  /// reached from that triangle's side.
  bool swirls(int e)
  {
    const int a = base_.edges[e][0], b = base_.edges[e][1];
    const int c = thirdVertex(domain_.mesh.triangles[base_.left[e]], a, b);
    const int d = thirdVertex(domain_.mesh.triangles[base_.right[e]], a, b);
    // Corner of (a, b, c) at c lies after edge (c, a); of (b, a, d) at d after (d, b).
    const int ca = base_.edgeBetween(c, a), cb = base_.edgeBetween(c, b), db = base_.edgeBetween(d, b), da = base_.edgeBetween(d, a);
    return reachesSide(e, c, positionAt(base_, c, ca), positionAt(base_, c, cb)) == Side::Right ||
      reachesSide(e, d, positionAt(base_, d, db), positionAt(base_, d, da)) == Side::Left;
  }

  enum class Side
  {
    Left,
    Right,
    Unknown
  };

  Side reachesSide(int e, int bv, int before, int after)
  {
    const auto& path = tentative_[e];
    if (path.size() < 3)
      return Side::Unknown;
    const std::vector<int> interior(path.begin() + 1, path.end() - 1);
    const auto length = [&](int x, int y) { return (net_.mesh.point(x) - net_.mesh.point(y)).norm(); };
    // The straight distance to the interior's bounding box bounds the
    // distance to its nearest vertex, and changes by at most an edge's
    // length along an edge.
    Eigen::AlignedBox<double, 3> box;
    for (int v : interior)
      box.extend(net_.mesh.point(v));
    const auto toBox = [&](int x) { return std::sqrt(box.squaredExteriorDistance(net_.mesh.point(x))); };
    std::vector<int> reach;
    ++report_.traces;
    if (fire_.run(net_.mesh, occupied_, net_.landmarkVertex[bv], sector(bv, before, after), -1, interior, length,
          toBox, reach) == kInfinity)
      return Side::Unknown;
    const int hit = reach.back();
    const int from = reach[reach.size() - 2];
    const std::size_t i = std::find(path.begin(), path.end(), hit) - path.begin();
    // Counter-clockwise from the forward direction sweeps the left side.
    const int forward = net_.mesh.findHalfedge(hit, path[i + 1]);
    for (int h = net_.mesh.nextAroundVertex(forward);; h = net_.mesh.nextAroundVertex(h))
    {
      if (net_.mesh.to(h) == from)
        return Side::Left;
      if (net_.mesh.to(h) == path[i - 1])
        return Side::Right;
    }
  }

  void insert(int e)
  {
    net_.curves[e] = tentative_[e];
    occupy(e);
    makeRoom(net_.curves[e]);
  }

  /// Marks the curve of `e` traced: its vertices occupied, its edges tagged.
  void occupy(int e)
  {
    traced_[e] = 1;
    const auto& curve = net_.curves[e];
    for (std::size_t i = 0; i < curve.size(); ++i)
    {
      occupied_[curve[i]] = 1;
      if (i + 1 < curve.size())
      {
        const int h = net_.mesh.findHalfedge(curve[i], curve[i + 1]);
        net_.mesh.setTag(h, e);
        net_.mesh.setTag(net_.mesh.opposite(h), e);
      }
    }
  }

  /// Splits every non-curve edge between two occupied vertices around
  /// `vertices`, so that every gap between curves holds a free vertex.
  void makeRoom(const std::vector<int>& vertices)
  {
    report_.splitEdges += splitEdgesBetweenCurves(net_.mesh, vertices, occupied_,
      [this](int h)
      {
        coordinates_.appendInterpolated(net_.mesh.from(h), net_.mesh.to(h), 0.5);
        net_.mesh.splitEdge(h);
        occupied_.push_back(0);
      });
  }

  const BaseDomain& domain_;
  const NetTracerOptions& options_;
  TracedNet& net_;
  NetTracerReport& report_;
  BaseTopology base_;
  FeatureCoordinates coordinates_;
  std::vector<int> featureOf_;
  std::vector<char> occupied_;
  std::vector<std::vector<int>> tentative_;
  std::vector<char> traced_;
  std::vector<int> penalties_;
  std::vector<int> presetEdge_; // base edge of each preset curve
  BrushFire fire_;
  bool waiting_ = false; // postponed curves wait for the net to change round them
};

} // namespace

Status traceFeatureNet(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  TracedNet& net, const NetTracerOptions& options, NetTracerReport* report)
{
  if (const SurfaceCheckResult check = checkSurface(surface); !check.ok())
    return Status::error(check.message);
  if (Status s = validateLandmarks(landmarks, surface.vertexCount(), domain.mesh.vertexCount()); !s.ok())
    return s;
  if (Status s = checkBaseDomain(domain, static_cast<int>(landmarks.size())); !s.ok())
    return s;
  NetTracerReport localReport;
  NetTracerReport& out = report ? *report : localReport;
  out = NetTracerReport{};
  net = TracedNet{};
  FeatureCoordinates coordinates;
  if (Status s = Tracer(domain, options, net, out).run(surface, landmarks, coordinates, false); !s.ok())
    return s;
  if (!options.retraceWaiting || !options.detectSwirls || out.forcedSwirls == 0)
    return {};
  // Both nets are valid; the paper's greedy tracing aims at the shortest
  // net, so the shorter one is kept.
  // Progress was reported to the end already; the second trace is quiet.
  NetTracerOptions waiting = options;
  waiting.progress = nullptr;
  TracedNet waitingNet;
  NetTracerReport waitingReport;
  const Status waited = Tracer(domain, waiting, waitingNet, waitingReport).run(surface, landmarks, coordinates, true);
  const int traces = out.traces + waitingReport.traces;
  if (waited.ok() && waitingReport.netLength < out.netLength)
  {
    waitingReport.alternativeNetLength = out.netLength;
    waitingReport.waited = true;
    net = std::move(waitingNet);
    out = waitingReport;
  }
  else
    out.alternativeNetLength = waited.ok() ? waitingReport.netLength : 0.0;
  out.traces = traces;
  return {};
}

} // namespace cmp
