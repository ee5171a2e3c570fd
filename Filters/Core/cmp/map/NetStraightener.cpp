#include <cmp/map/NetStraightener.h>

#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/TriangleShape.h>
#include <cmp/numerics/MeanValueSystem.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cmp
{
namespace
{

constexpr double kTwoPi = 6.283185307179586;
/// Cuts closer than this fraction of an edge to its ends are moved away.
constexpr double kSmallestCut = 1e-3;

/// True if every input vertex `inner` uses is used by `outer` too.
bool supportedBy(const SurfacePoint& inner, const SurfacePoint& outer)
{
  for (int v : inner.vertex)
    if (v >= 0 && std::find(outer.vertex.begin(), outer.vertex.end(), v) == outer.vertex.end())
      return false;
  return true;
}

/// One straight-line walk event: through an existing vertex, or across the
/// edge (u, v) at `t` from u.
struct WalkEvent
{
  int vertex = -1;
  int u = -1, v = -1;
  double t = 0.0;
};

class Straightener
{
public:
  Straightener(const BaseDomain& domain, const NetStraightenerOptions& options, StraightenedNet& out,
    NetStraightenerReport& report)
    : domain_(domain)
    , options_(options)
    , out_(out)
    , net_(out.net)
    , report_(report)
  {
    base_.build(domain);
  }

  Status run(const TracedNet& traced)
  {
    // Start from a fresh mesh so that triangle provenance refers to the
    // traced surface, not to whatever the tracer started from.
    if (Status s = net_.mesh.build(traced.mesh.toTriangleMesh()); !s.ok())
      return s;
    net_.baseEdges = traced.baseEdges;
    net_.leftTriangle = traced.leftTriangle;
    net_.rightTriangle = traced.rightTriangle;
    net_.curves = traced.curves;
    net_.landmarkVertex = traced.landmarkVertex;
    if (Status s = labelPatches(net_); !s.ok())
      return s;
    out_.inputPoint.resize(net_.mesh.vertexCount());
    for (int v = 0; v < net_.mesh.vertexCount(); ++v)
      out_.inputPoint[v] = SurfacePoint::at(v);
    // Between rebuilds this maps the triangles the mesh was built from (what
    // `mesh.inputTriangle()` returns) to the input's triangles.
    out_.inputTriangle.resize(net_.mesh.triangleCount());
    for (int t = 0; t < net_.mesh.triangleCount(); ++t)
      out_.inputTriangle[t] = t;
    const int patchCount = domain_.mesh.triangleCount();
    report_.netLengthBefore = netLength(net_);
    report_.areaVariationBefore = areaVariation(patchAreas(net_, patchCount));

    const int baseVertices = domain_.mesh.vertexCount();
    std::vector<char> kept(baseVertices, 0);
    for (int bv = 0; bv < baseVertices; ++bv)
      kept[bv] = std::find(options_.keptFeatures.begin(), options_.keptFeatures.end(), domain_.featureIds[bv]) !=
        options_.keptFeatures.end();
    double length = report_.netLengthBefore;
    for (int sweep = 0; sweep < options_.maxSweeps; ++sweep)
    {
      for (int bv = 0; bv < baseVertices; ++bv)
      {
        if (!kept[bv] && !straightenStar(bv, options_.snapTolerance) && !straightenStar(bv, 0.0))
          ++report_.skippedStars;
        if (options_.progress)
          options_.progress((sweep * baseVertices + bv + 1.0) / (options_.maxSweeps * baseVertices));
      }
      removeLeftovers();
      if (Status s = rebuild(); !s.ok())
        return s;
      ++report_.sweeps;
      const double newLength = netLength(net_);
      const bool settled = std::abs(newLength - length) <= options_.tolerance * length;
      length = newLength;
      if (settled)
        break;
    }
    makeRoomBetweenCurves();
    if (Status s = rebuild(); !s.ok())
      return s;
    report_.netLengthAfter = netLength(net_);
    report_.areaVariationAfter = areaVariation(patchAreas(net_, patchCount));
    if (options_.progress)
      options_.progress(1.0);
    return {};
  }

private:
  // ---- One landmark: map its star to the plane, cut straight curves -------

  /// Replaces the curves around base vertex `center`; false (and nothing
  /// changed) if the star map is degenerate or the new curves would not be a
  /// valid layout.
  bool straightenStar(int center, double snap)
  {
    const std::vector<int>& ring = base_.rotation[center];
    const int n = static_cast<int>(ring.size());
    std::vector<int> neighbour(n), linkEdge(n);
    for (int k = 0; k < n; ++k)
      neighbour[k] = base_.other(ring[k], center);
    for (int k = 0; k < n; ++k)
      linkEdge[k] = base_.edgeBetween(neighbour[k], neighbour[(k + 1) % n]);

    collectRegion(center);
    if (!mapRegionToPlane(neighbour, linkEdge))
      return false;

    const EditableMesh meshBefore = net_.mesh;
    const std::vector<SurfacePoint> pointsBefore = out_.inputPoint;
    const std::vector<int> patchBefore = net_.patchOfTriangle;
    const std::vector<std::vector<int>> curvesBefore = net_.curves;
    const auto restore = [&]
    {
      net_.mesh = meshBefore;
      out_.inputPoint = pointsBefore;
      net_.patchOfTriangle = patchBefore;
      net_.curves = curvesBefore;
      clearMarks();
      return false;
    };

    for (int e : ring)
      setCurveTags(net_.curves[e], -1);
    for (int e : linkEdge)
      for (int v : net_.curves[e])
        mark(v);
    mark(net_.landmarkVertex[center]);

    for (int k = 0; k < n; ++k)
    {
      std::vector<WalkEvent> events;
      const int from = net_.landmarkVertex[center], to = net_.landmarkVertex[neighbour[k]];
      std::vector<int> curve;
      if (!walk(from, to, snap, events) || !cut(from, events, curve))
        return restore();
      for (int v : curve)
        mark(v);
      if (!setCurveTags(curve, ring[k]))
        return restore();
      if (net_.baseEdges[ring[k]][0] != center)
        std::reverse(curve.begin(), curve.end());
      net_.curves[ring[k]] = std::move(curve);
    }
    if (!curvesLeaveInOrder(center) || !relabelRegion(ring))
      return restore();
    makeRoomAround(ring);
    clearMarks();
    return true;
  }

  /// Splits the non-curve edges from the new curves to other curve vertices
  /// (the marked ones), so no triangle has all its corners on curves and the
  /// next star map has no degenerate triangle.
  void makeRoomAround(const std::vector<int>& ring)
  {
    std::vector<int> curveVertices;
    for (int e : ring)
      curveVertices.insert(curveVertices.end(), net_.curves[e].begin(), net_.curves[e].end());
    marks_.resize(net_.mesh.vertexCount(), 0);
    splitEdgesBetweenCurves(net_.mesh, curveVertices, marks_, [this](int h) { split(h, 0.5); });
  }

  /// Triangles of the patches around `center`.
  void collectRegion(int center)
  {
    std::vector<char> inStar(domain_.mesh.triangleCount(), 0);
    for (int e : base_.rotation[center])
      inStar[net_.leftTriangle[e]] = inStar[net_.rightTriangle[e]] = 1;
    region_.clear();
    inRegion_.assign(net_.mesh.triangleCount(), 0);
    for (int t = 0; t < net_.mesh.triangleCount(); ++t)
      if (!net_.mesh.isRemoved(t) && inStar[net_.patchOfTriangle[t]])
      {
        region_.push_back(t);
        inRegion_[t] = 1;
      }
  }

  /// The paper's planar map of the star: neighbours on the unit circle at
  /// angles proportional to the lengths of the curves between them, those
  /// curves straight by arc length, the rest by mean value weights.
  bool mapRegionToPlane(const std::vector<int>& neighbour, const std::vector<int>& linkEdge)
  {
    const int n = static_cast<int>(neighbour.size());
    std::vector<std::vector<int>> link(n);
    std::vector<double> linkLength(n);
    double total = 0.0;
    for (int k = 0; k < n; ++k)
    {
      link[k] = net_.curves[linkEdge[k]];
      if (net_.baseEdges[linkEdge[k]][0] != neighbour[k])
        std::reverse(link[k].begin(), link[k].end());
      linkLength[k] = curveLength(net_.mesh, link[k]);
      total += linkLength[k];
    }
    if (!(total > 0.0))
      return false;

    // Local copy of the region; boundary rows are the polygon's points.
    local_.assign(net_.mesh.vertexCount(), -1);
    std::vector<int> global;
    const TriangleMesh star = extractTriangles(net_.mesh, region_, local_, global);
    std::vector<int> fixedRow(global.size(), -1);
    std::vector<Vec2> fixedPoints;
    double angle = 0.0;
    for (int k = 0; k < n; ++k)
    {
      const double nextAngle = angle + kTwoPi * linkLength[k] / total;
      const Vec2 a(std::cos(angle), std::sin(angle)), b(std::cos(nextAngle), std::sin(nextAngle));
      const std::vector<double> along = arcLengthParameters(net_.mesh, link[k]);
      for (std::size_t i = 0; i + 1 < link[k].size(); ++i) // the last point starts the next curve
      {
        const int v = local_[link[k][i]];
        if (v < 0)
          return false;
        fixedRow[v] = static_cast<int>(fixedPoints.size());
        fixedPoints.push_back((1.0 - along[i]) * a + along[i] * b);
      }
      angle = nextAngle;
    }
    Eigen::MatrixXd fixedValues(fixedPoints.size(), 2), values;
    for (std::size_t r = 0; r < fixedPoints.size(); ++r)
      fixedValues.row(r) = fixedPoints[r].transpose();
    if (!solveMeanValueSystem(star, fixedRow, fixedValues, values).ok())
      return false;
    uv_.resize(net_.mesh.vertexCount());
    for (std::size_t i = 0; i < global.size(); ++i)
      uv_[global[i]] = values.row(i).transpose();
    // The map is an embedding in exact arithmetic. Long protrusions without
    // a landmark shrink exponentially (crowding) and may round to zero area;
    // only a clearly folded triangle means the map is unusable. The walk and
    // the checks after it catch anything crowding could still confuse.
    for (const Triangle& tri : star.triangles)
      if (cross2(uv_[global[tri[1]]] - uv_[global[tri[0]]], uv_[global[tri[2]]] - uv_[global[tri[0]]]) < -1e-14)
        return false;
    return true;
  }

  /// A surface triangle's corners in the chart a walk reads it in, and the
  /// walk's goal there.
  struct TriangleChart
  {
    std::array<Vec2, 3> corners; ///< In the triangle's vertex order.
    Vec2 goal = Vec2::Zero();
    Vec2 at(const EditableMesh& mesh, int triangle, int vertex) const
    {
      const Triangle& tri = mesh.triangle(triangle);
      return corners[vertex == tri[0] ? 0 : vertex == tri[1] ? 1 : 2];
    }
  };

  /// Triangle `triangle` in the walk's chart (`uv_`, its region only, the
  /// goal at `goal`); false if the triangle is outside the region.
  bool chartOf(int triangle, const Vec2& goal, TriangleChart& chart) const
  {
    if (!inRegion_[triangle])
      return false;
    const Triangle& tri = net_.mesh.triangle(triangle);
    chart.corners = { uv_[tri[0]], uv_[tri[1]], uv_[tri[2]] };
    chart.goal = goal;
    return true;
  }

  /// Walks the straight segment from `source` to `target` in the planar map
  /// (each triangle as `chartOf()` draws it) and lists the vertices it
  /// passes and the edges it crosses; false if it leaves the map or meets
  /// another curve.
  bool walk(int source, int target, double snap, std::vector<WalkEvent>& events) const
  {
    const EditableMesh& mesh = net_.mesh;
    const Vec2 goal = uv_[target];
    int atVertex = source; // else: on halfedge `crossed` at `t`
    int crossed = -1;
    double t = 0.0;
    for (std::size_t step = 0; step <= region_.size() + 2; ++step)
    {
      int exit = -1;
      double exitT = 0.0;
      if (atVertex >= 0)
      {
        if (atVertex == target)
          return true;
        const int first = mesh.outgoing(atVertex);
        int h = first;
        do
        {
          const int triangle = EditableMesh::triangleOf(h);
          TriangleChart chart;
          if (!chartOf(triangle, goal, chart))
            return false;
          const Vec2 p = chart.at(mesh, triangle, atVertex), d = chart.goal - p;
          const Vec2 y = chart.at(mesh, triangle, mesh.to(h));
          const Vec2 z = chart.at(mesh, triangle, mesh.to(EditableMesh::next(h)));
          const double cy = cross2(y - p, d), cz = cross2(d, z - p);
          if (cy >= 0.0 && cz >= 0.0 && cy + cz > 0.0)
          {
            exit = EditableMesh::next(h);
            exitT = cy / (cy + cz);
            break;
          }
          h = mesh.nextAroundVertex(h);
        } while (h != first);
        if (exit < 0)
          return false;
      }
      else
      {
        const int entry = mesh.opposite(crossed); // b -> a in the next triangle (b, a, w)
        const int triangle = EditableMesh::triangleOf(entry);
        TriangleChart chart;
        if (!chartOf(triangle, goal, chart))
          return false;
        const int b = mesh.from(entry), a = mesh.to(entry), w = mesh.to(EditableMesh::next(entry));
        const Vec2 pa = chart.at(mesh, triangle, a), pb = chart.at(mesh, triangle, b), pw = chart.at(mesh, triangle, w);
        // `crossed` runs a -> b.
        const Vec2 p = (1.0 - t) * pa + t * pb;
        const Vec2 d = chart.goal - p;
        const double sa = cross2(d, pa - p), sb = cross2(d, pb - p), sw = cross2(d, pw - p);
        if ((sw > 0.0) == (sa > 0.0) && sw != 0.0)
        {
          exit = EditableMesh::prev(entry); // w -> b
          exitT = sw / (sw - sb);
        }
        else
        {
          exit = EditableMesh::next(entry); // a -> w
          exitT = sa / (sa - sw);
        }
      }
      // Leave through `exit` at `exitT`: onto a vertex, or across the edge.
      const int u = mesh.from(exit), v = mesh.to(exit);
      const bool uFree = u == target || !marked(u), vFree = v == target || !marked(v);
      if ((exitT <= snap || exitT <= 0.0 || (u == target && exitT < 0.5)) && uFree)
        atVertex = u;
      else if ((exitT >= 1.0 - snap || exitT >= 1.0 || (v == target && exitT > 0.5)) && vFree)
        atVertex = v;
      else if (exitT <= 0.0 || exitT >= 1.0)
        return false;
      else if (mesh.tag(exit) >= 0)
        return false;
      else
      {
        // Near a vertex it may not use, cross a little further away instead
        // of cutting a needle triangle.
        atVertex = -1;
        crossed = exit;
        t = std::clamp(exitT, kSmallestCut, 1.0 - kSmallestCut);
        events.push_back({ -1, u, v, t });
        continue;
      }
      if (atVertex != target && std::any_of(events.begin(), events.end(),
                                  [&](const WalkEvent& e) { return e.vertex == atVertex; }))
        return false;
      if (atVertex == source)
        return false;
      events.push_back({ atVertex, -1, -1, 0.0 });
    }
    return false;
  }

  /// Applies a walk: splits the crossed edges and returns the curve.
  bool cut(int source, const std::vector<WalkEvent>& events, std::vector<int>& curve)
  {
    curve.assign(1, source);
    for (const WalkEvent& event : events)
    {
      if (event.vertex >= 0)
      {
        curve.push_back(event.vertex);
        continue;
      }
      const int h = net_.mesh.findHalfedge(event.u, event.v);
      if (h < 0)
        return false;
      curve.push_back(split(h, event.t));
    }
    return true;
  }

  /// Splits the edge of `h` and keeps every per-vertex and per-triangle
  /// array in step.
  int split(int h, double t)
  {
    EditableMesh& mesh = net_.mesh;
    const int a = mesh.from(h), b = mesh.to(h);
    const int t1 = EditableMesh::triangleOf(h), t2 = EditableMesh::triangleOf(mesh.opposite(h));
    const int m = mesh.splitEdge(h, t);
    out_.inputPoint.push_back(interpolate(out_.inputPoint[a], out_.inputPoint[b], t));
    uv_.resize(mesh.vertexCount());
    uv_[m] = (1.0 - t) * uv_[a] + t * uv_[b];
    marks_.resize(mesh.vertexCount(), 0);
    for (int parent : { t1, t2 })
    {
      net_.patchOfTriangle.push_back(net_.patchOfTriangle[parent]);
      inRegion_.push_back(inRegion_[parent]);
      if (inRegion_[parent])
        region_.push_back(static_cast<int>(net_.patchOfTriangle.size()) - 1);
    }
    return m;
  }

  /// Tags the edges of `curve` (-1 clears); false if some step of it is not
  /// a mesh edge or already belongs to another curve.
  bool setCurveTags(const std::vector<int>& curve, int tag)
  {
    for (std::size_t i = 0; i + 1 < curve.size(); ++i)
    {
      const int h = net_.mesh.findHalfedge(curve[i], curve[i + 1]);
      if (h < 0 || (tag >= 0 && net_.mesh.tag(h) >= 0))
        return false;
      net_.mesh.setTag(h, tag);
      net_.mesh.setTag(net_.mesh.opposite(h), tag);
    }
    return true;
  }

  /// The new curves leave the centre in the base domain's cyclic order.
  bool curvesLeaveInOrder(int center) const
  {
    const EditableMesh& mesh = net_.mesh;
    const int v = net_.landmarkVertex[center];
    std::vector<int> order;
    const int first = mesh.outgoing(v);
    int h = first;
    do
    {
      if (mesh.tag(h) >= 0)
        order.push_back(mesh.tag(h));
      h = mesh.nextAroundVertex(h);
    } while (h != first);
    const std::vector<int>& ring = base_.rotation[center];
    if (order.size() != ring.size())
      return false;
    const auto start = std::find(order.begin(), order.end(), ring[0]);
    if (start == order.end())
      return false;
    std::rotate(order.begin(), start, order.end());
    return order == ring;
  }

  /// Flood-fills the region's patches from the new curves.
  bool relabelRegion(const std::vector<int>& ring)
  {
    for (int t : region_)
      net_.patchOfTriangle[t] = -1;
    return floodFillPatches(net_, ring, &inRegion_).ok() &&
      std::none_of(region_.begin(), region_.end(), [&](int t) { return net_.patchOfTriangle[t] < 0; });
  }

  void mark(int v)
  {
    marks_.resize(net_.mesh.vertexCount(), 0);
    if (!marks_[v])
    {
      marks_[v] = 1;
      marked_.push_back(v);
    }
  }
  bool marked(int v) const { return v < static_cast<int>(marks_.size()) && marks_[v]; }
  void clearMarks()
  {
    for (int v : marked_)
      if (v < static_cast<int>(marks_.size()))
        marks_[v] = 0;
    marked_.clear();
  }

  // ---- Cleaning up ---------------------------------------------------------

  /// Vertices on curves or at landmarks.
  std::vector<char> occupiedVertices() const
  {
    std::vector<char> occupied(net_.mesh.vertexCount(), 0);
    for (const auto& curve : net_.curves)
      for (int v : curve)
        occupied[v] = 1;
    return occupied;
  }

  /// Removes the vertices that cuts made and curves no longer use, by
  /// collapsing each into a neighbour on the same input edge or triangle,
  /// where that flips nothing, keeps the mesh manifold and adds no edge
  /// between two curve vertices.
  void removeLeftovers()
  {
    const std::vector<char> occupied = occupiedVertices();
    for (int v = 0; v < net_.mesh.vertexCount(); ++v)
    {
      if (occupied[v] || out_.inputPoint[v].supportSize() < 2 || net_.mesh.outgoing(v) < 0)
        continue;
      const int h = bestCollapse(v, occupied);
      if (h >= 0)
      {
        net_.mesh.collapseEdge(h);
        ++report_.removedVertices;
      }
    }
  }

  /// The halfedge v -> x whose collapse leaves the best triangles, or -1.
  int bestCollapse(int v, const std::vector<char>& occupied)
  {
    const EditableMesh& mesh = net_.mesh;
    ring_.clear();
    const int first = mesh.outgoing(v);
    int h = first;
    do
    {
      ring_.push_back(h);
      h = mesh.nextAroundVertex(h);
    } while (h != first);
    marks_.resize(mesh.vertexCount(), 0);
    for (int g : ring_)
      marks_[mesh.to(g)] = 1;

    int best = -1;
    double bestQuality = 1e-3; // never leave a sliver
    for (int g : ring_)
    {
      const int x = mesh.to(g);
      if (!supportedBy(out_.inputPoint[x], out_.inputPoint[v]) || !linkConditionHolds(g))
        continue;
      const int a = mesh.to(EditableMesh::next(g));
      const int b = mesh.to(EditableMesh::next(mesh.opposite(g)));
      double quality = 1.0;
      for (int k : ring_)
      {
        const int p = mesh.to(k), q = mesh.to(EditableMesh::next(k)); // triangle (v, p, q)
        if (p == x || q == x)
          continue;
        if (occupied[x] && ((occupied[p] && p != a && p != b) || (occupied[q] && q != a && q != b)))
        {
          quality = 0.0; // would join two curve vertices by a non-curve edge
          break;
        }
        const Vec3 before = (mesh.point(p) - mesh.point(v)).cross(mesh.point(q) - mesh.point(v));
        const Vec3 after = (mesh.point(p) - mesh.point(x)).cross(mesh.point(q) - mesh.point(x));
        if (before.dot(after) <= 0.0)
        {
          quality = 0.0;
          break;
        }
        quality = std::min(quality, triangleShapeQuality(mesh.point(x), mesh.point(p), mesh.point(q)));
      }
      if (quality > bestQuality)
      {
        bestQuality = quality;
        best = g;
      }
    }
    for (int g : ring_)
      marks_[mesh.to(g)] = 0;
    return best;
  }

  /// The ends of edge g = v -> x share exactly the two neighbours beside it
  /// (the neighbours of v are marked).
  bool linkConditionHolds(int g) const
  {
    const EditableMesh& mesh = net_.mesh;
    const int x = mesh.to(g);
    int shared = 0;
    const int first = mesh.outgoing(x);
    int h = first;
    do
    {
      shared += marks_[mesh.to(h)];
      h = mesh.nextAroundVertex(h);
    } while (h != first);
    return shared == 2;
  }

  /// Splits every non-curve edge between two curve vertices, so that every
  /// triangle of a patch has a vertex off the patch boundary or is the whole
  /// patch (what a bijective per-patch map needs).
  void makeRoomBetweenCurves()
  {
    const std::vector<char> occupied = occupiedVertices();
    std::vector<int> curveVertices;
    for (int v = 0; v < net_.mesh.vertexCount(); ++v)
      if (occupied[v])
        curveVertices.push_back(v);
    inRegion_.assign(net_.mesh.triangleCount(), 0);
    splitEdgesBetweenCurves(net_.mesh, curveVertices, occupied, [this](int h) { split(h, 0.5); });
  }

  /// Drops removed vertices and triangles, renumbers everything and
  /// rebuilds the mesh, keeping curves, patches and input locations.
  Status rebuild()
  {
    const EditableMesh& mesh = net_.mesh;
    std::vector<int> newIndex(mesh.vertexCount(), -1);
    TriangleMesh compact;
    std::vector<SurfacePoint> points;
    std::vector<int> patch, inputTriangle;
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      if (mesh.isRemoved(t))
        continue;
      Triangle tri = mesh.triangle(t);
      for (int& v : tri)
      {
        if (newIndex[v] < 0)
        {
          newIndex[v] = compact.vertexCount();
          compact.points.push_back(mesh.point(v));
          points.push_back(out_.inputPoint[v]);
        }
        v = newIndex[v];
      }
      compact.triangles.push_back(tri);
      patch.push_back(net_.patchOfTriangle[t]);
      inputTriangle.push_back(out_.inputTriangle[mesh.inputTriangle(t)]);
    }
    for (auto& curve : net_.curves)
      for (int& v : curve)
        v = newIndex[v];
    for (int& v : net_.landmarkVertex)
      v = newIndex[v];
    if (Status s = net_.mesh.build(compact); !s.ok())
      return Status::error("internal error after straightening: " + s.message());
    out_.inputPoint = std::move(points);
    out_.inputTriangle = std::move(inputTriangle);
    if (Status s = labelPatches(net_); !s.ok())
      return s;
    if (net_.patchOfTriangle != patch)
      return Status::error("internal error: straightening changed the patches");
    marks_.assign(net_.mesh.vertexCount(), 0);
    return {};
  }

  const BaseDomain& domain_;
  const NetStraightenerOptions& options_;
  StraightenedNet& out_;
  TracedNet& net_;
  NetStraightenerReport& report_;
  BaseTopology base_;
  std::vector<int> region_;        // triangles of the current star
  std::vector<char> inRegion_;
  std::vector<int> local_;
  std::vector<Vec2> uv_;           // planar map of the current star
  std::vector<char> marks_;        // vertices a new curve may not use
  std::vector<int> marked_;
  std::vector<int> ring_;
};

} // namespace

Status straightenNet(const TracedNet& traced, const BaseDomain& domain, StraightenedNet& out,
  const NetStraightenerOptions& options, NetStraightenerReport* report)
{
  if (Status s = checkBaseDomain(domain); !s.ok())
    return s;
  if (traced.curves.size() != static_cast<std::size_t>(edgeCount(domain.mesh)) ||
    traced.landmarkVertex.size() != static_cast<std::size_t>(domain.mesh.vertexCount()) ||
    traced.patchOfTriangle.size() != static_cast<std::size_t>(traced.mesh.triangleCount()))
    return Status::error("the net does not belong to this base domain");
  if (options.maxSweeps < 0 || !(options.tolerance >= 0.0) || !(options.snapTolerance >= 0.0) ||
    !(options.snapTolerance < 0.5))
    return Status::error("straightening options out of range (sweeps >= 0, tolerance >= 0, 0 <= snap < 0.5)");
  for (int f : options.keptFeatures)
    if (f < 0 || f >= domain.mesh.vertexCount())
      return Status::error("straightening options out of range: keptFeatures names feature " + std::to_string(f) +
        ", the base domain has features 0.." + std::to_string(domain.mesh.vertexCount() - 1));
  NetStraightenerReport localReport;
  NetStraightenerReport& figures = report ? *report : localReport;
  figures = NetStraightenerReport{};
  out = StraightenedNet{};
  Straightener straightener(domain, options, out, figures);
  return straightener.run(traced);
}

SurfacePoint interpolate(const SurfacePoint& a, const SurfacePoint& b, double t)
{
  SurfacePoint result;
  int used = 0;
  const auto add = [&](int v, double w)
  {
    if (v < 0 || w == 0.0)
      return;
    for (int k = 0; k < used; ++k)
      if (result.vertex[k] == v)
      {
        result.weight[k] += w;
        return;
      }
    if (used < 3)
    {
      result.vertex[used] = v;
      result.weight[used++] = w;
    }
  };
  for (int k = 0; k < 3; ++k)
  {
    add(a.vertex[k], (1.0 - t) * a.weight[k]);
    add(b.vertex[k], t * b.weight[k]);
  }
  return result;
}

} // namespace cmp
