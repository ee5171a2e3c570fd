#include <cmp/remesh/SemiRegularRemesher.h>

#include <cmp/mesh/TriangleGrid.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>

namespace cmp
{
namespace
{

/// Base triangles around each base vertex, lowest first.
std::vector<std::vector<int>> trianglesAroundBaseVertices(const BaseDomain& domain)
{
  std::vector<std::vector<int>> around(domain.mesh.vertexCount());
  for (int t = 0; t < domain.mesh.triangleCount(); ++t)
    for (int v : domain.mesh.triangles[t])
      around[v].push_back(t);
  return around;
}

/// The same point expressed in the lowest-numbered base triangle that
/// contains it, so that every model and every level agree on it.
SurfacePoint canonical(const BaseDomain& domain, const std::vector<std::vector<int>>& around, const SurfacePoint& at)
{
  const Triangle& tri = domain.mesh.triangles[at.triangle];
  int support = -1, count = 0;
  for (int k = 0; k < 3; ++k)
    if (at.weight[k] != 0.0)
    {
      support = tri[k];
      ++count;
    }
  if (count == 3)
    return at;
  for (int candidate : around[support]) // increasing order
  {
    SurfacePoint moved = SurfacePoint::inTriangle(domain.mesh, candidate, {});
    if (coordinatesInTriangle(domain, at.triangle, at.weight, candidate, moved.weight))
      return moved;
  }
  return at;
}

std::uint64_t edgeKey(int a, int b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

/// The dyadic midpoint of two located vertices, computed in `patch` (exact,
/// so zeros stay zeros) and expressed canonically.
SurfacePoint midpointLocation(const BaseDomain& domain, const std::vector<std::vector<int>>& around,
  const SurfacePoint& a, const SurfacePoint& b, int patch)
{
  SurfacePoint at = SurfacePoint::inTriangle(domain.mesh, patch, {});
  std::array<double, 3> la{}, lb{};
  coordinatesInTriangle(domain, a.triangle, a.weight, patch, la);
  coordinatesInTriangle(domain, b.triangle, b.weight, patch, lb);
  for (int k = 0; k < 3; ++k)
    at.weight[k] = 0.5 * (la[k] + lb[k]);
  return canonical(domain, around, at);
}

/// Every base vertex at its lowest base triangle, stored at the remesh
/// vertex of its feature.
std::vector<SurfacePoint> baseVertexLocations(const BaseDomain& domain, const std::vector<std::vector<int>>& around)
{
  std::vector<SurfacePoint> locations(domain.mesh.vertexCount());
  for (int bv = 0; bv < domain.mesh.vertexCount(); ++bv)
  {
    const int t = around[bv].front();
    SurfacePoint at = SurfacePoint::inTriangle(domain.mesh, t, { 0.0, 0.0, 0.0 });
    const Triangle& tri = domain.mesh.triangles[t];
    at.weight[std::find(tri.begin(), tri.end(), bv) - tri.begin()] = 1.0;
    locations[domain.featureIds[bv]] = at;
  }
  return locations;
}

/// The base triangles with their corners renamed to remesh vertices.
std::vector<Triangle> baseTrianglesAsRemeshVertices(const BaseDomain& domain)
{
  std::vector<Triangle> triangles = domain.mesh.triangles;
  for (Triangle& tri : triangles)
    for (int& v : tri)
      v = domain.featureIds[v];
  return triangles;
}

} // namespace

bool locationInBaseTriangle(const BaseDomain& domain, const SurfacePoint& at, int triangle, Vec2& result)
{
  std::array<double, 3> c{};
  if (!coordinatesInTriangle(domain, at.triangle, at.weight, triangle, c))
    return false;
  result = Vec2(c[1], c[2]);
  return true;
}

Status removeHoleTriangles(const BaseDomain& domain, const std::vector<char>& holeTriangles, SemiRegularMesh& mesh)
{
  if (holeTriangles.empty())
    return {};
  if (holeTriangles.size() != static_cast<std::size_t>(domain.mesh.triangleCount()))
    return Status::error("holeTriangles has " + std::to_string(holeTriangles.size()) +
      " entries but the base domain has " + std::to_string(domain.mesh.triangleCount()) + " triangles");
  const int vertices = mesh.vertexCount();
  const auto hole = [&](int patch) { return patch >= 0 && patch < static_cast<int>(holeTriangles.size()) && holeTriangles[patch]; };
  std::vector<int> keptPatchOf(vertices, -1); // a kept base triangle each vertex lies in
  std::vector<int> keptTriangles;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    if (!hole(mesh.patchOfTriangle[t]))
    {
      keptTriangles.push_back(t);
      for (int v : mesh.triangles[t])
        if (keptPatchOf[v] < 0)
          keptPatchOf[v] = mesh.patchOfTriangle[t];
    }
  if (keptTriangles.empty())
    return Status::error("every base triangle is a hole: nothing is left to remesh");
  std::vector<int> newIndex(vertices, -1);
  SemiRegularMesh open;
  open.level = mesh.level;
  for (int v = 0; v < vertices; ++v)
  {
    if (keptPatchOf[v] < 0)
      continue;
    newIndex[v] = open.vertexCount();
    SurfacePoint at = mesh.locations[v];
    if (hole(at.triangle))
    {
      // On the edge (or corner) a hole shares with a kept base triangle:
      // the same place, named in the kept one.
      Vec2 q;
      if (!locationInBaseTriangle(domain, at, keptPatchOf[v], q))
        return Status::error("internal error: remesh vertex " + std::to_string(v) + " lies in a hole and outside it");
      std::array<double, 3> c{ { 1.0 - q.x() - q.y(), q.x(), q.y() } };
      for (double& w : c)
        if (std::abs(w) < 1e-15)
          w = 0.0;
      at = SurfacePoint::inTriangle(domain.mesh, keptPatchOf[v], c);
    }
    open.locations.push_back(at);
    open.levelOfVertex.push_back(mesh.levelOfVertex[v]);
  }
  for (int t : keptTriangles)
  {
    const Triangle& tri = mesh.triangles[t];
    open.triangles.push_back({ newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]] });
    open.patchOfTriangle.push_back(mesh.patchOfTriangle[t]);
    if (t < static_cast<int>(mesh.levelOfTriangle.size()))
      open.levelOfTriangle.push_back(mesh.levelOfTriangle[t]);
  }
  mesh = std::move(open);
  return {};
}

std::string remeshLevelProblem(int level)
{
  return "level " + std::to_string(level) + " is out of range (0 to " + std::to_string(kMaximumRemeshLevel) + ")";
}

std::string remeshLevelProblem(const std::string& property, int level)
{
  return property + " must be between 0 and " + std::to_string(kMaximumRemeshLevel) + " (it is " +
    std::to_string(level) + ")";
}

Status buildSemiRegularMesh(const BaseDomain& domain, int level, SemiRegularMesh& out)
{
  if (!isRemeshLevel(level))
    return Status::error(remeshLevelProblem(level));
  if (Status s = checkBaseDomain(domain); !s.ok())
    return s;
  const auto around = trianglesAroundBaseVertices(domain);
  out = SemiRegularMesh{};
  out.level = level;
  const int featureCount = domain.mesh.vertexCount();
  out.locations = baseVertexLocations(domain, around);
  out.levelOfVertex.assign(featureCount, 0);
  out.triangles = baseTrianglesAsRemeshVertices(domain);
  for (int t = 0; t < domain.mesh.triangleCount(); ++t)
    out.patchOfTriangle.push_back(t);

  for (int l = 1; l <= level; ++l)
  {
    std::unordered_map<std::uint64_t, int> midpointOf;
    midpointOf.reserve(out.triangles.size() * 2);
    const auto midpoint = [&](int a, int b, int patch)
    {
      const auto [it, isNew] = midpointOf.emplace(edgeKey(a, b), out.vertexCount());
      if (isNew)
      {
        out.locations.push_back(midpointLocation(domain, around, out.locations[a], out.locations[b], patch));
        out.levelOfVertex.push_back(l);
      }
      return it->second;
    };
    std::vector<Triangle> triangles;
    std::vector<int> patches;
    triangles.reserve(4 * out.triangles.size());
    patches.reserve(4 * out.triangles.size());
    for (std::size_t t = 0; t < out.triangles.size(); ++t)
    {
      const auto [a, b, c] = out.triangles[t];
      const int patch = out.patchOfTriangle[t];
      const int ab = midpoint(a, b, patch), bc = midpoint(b, c, patch), ca = midpoint(c, a, patch);
      for (const Triangle& child : { Triangle{ a, ab, ca }, Triangle{ ab, b, bc }, Triangle{ ca, bc, c },
             Triangle{ ab, bc, ca } })
      {
        triangles.push_back(child);
        patches.push_back(patch);
      }
    }
    out.triangles = std::move(triangles);
    out.patchOfTriangle = std::move(patches);
  }
  out.levelOfTriangle.assign(out.triangles.size(), level);
  return {};
}

namespace
{

/// The refinement tree of an adaptive remesh. Vertices here are numbered
/// in creation order; `numberLikeUniform()` renumbers them.
class RefinementTree
{
public:
  struct Node
  {
    Triangle corner;     ///< Tree vertices, counter-clockwise.
    int patch = -1;      ///< Base triangle.
    int level = 0;       ///< Depth.
    int firstChild = -1; ///< Children a, b, c, centre at firstChild..+3; -1 for a leaf.
  };

  RefinementTree(const BaseDomain& domain, const std::vector<std::vector<int>>& around)
    : domain_(domain)
    , around_(around)
    , locations_(baseVertexLocations(domain, around))
  {
    const std::vector<Triangle> roots = baseTrianglesAsRemeshVertices(domain);
    for (int t = 0; t < static_cast<int>(roots.size()); ++t)
      nodes_.push_back(Node{ roots[t], t, 0, -1 });
  }

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<SurfacePoint>& locations() const { return locations_; }
  int rootCount() const { return domain_.mesh.triangleCount(); }

  /// The corners of node n as locations in its base triangle.
  std::array<SurfacePoint, 3> cornerLocations(int n) const
  {
    std::array<SurfacePoint, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      const SurfacePoint& at = locations_[nodes_[n].corner[k]];
      corners[k].triangle = nodes_[n].patch;
      corners[k].vertex = domain_.mesh.triangles[nodes_[n].patch];
      coordinatesInTriangle(domain_, at.triangle, at.weight, nodes_[n].patch, corners[k].weight);
    }
    return corners;
  }

  /// The midpoint vertex of edge (a, b), or -1 if no triangle split it.
  int midpoint(int a, int b) const
  {
    const auto it = midpointOf_.find(edgeKey(a, b));
    return it == midpointOf_.end() ? -1 : it->second;
  }

  /// Quadrisects leaf n.
  void split(int n)
  {
    const Node node = nodes_[n];
    const auto [a, b, c] = node.corner;
    const int ab = makeMidpoint(a, b, node.patch), bc = makeMidpoint(b, c, node.patch),
              ca = makeMidpoint(c, a, node.patch);
    nodes_[n].firstChild = static_cast<int>(nodes_.size());
    for (const Triangle& child :
      { Triangle{ a, ab, ca }, Triangle{ ab, b, bc }, Triangle{ ca, bc, c }, Triangle{ ab, bc, ca } })
      nodes_.push_back(Node{ child, node.patch, node.level + 1, -1 });
  }

  /// True if a neighbour of leaf n across one of its edges is two or more
  /// levels finer.
  bool hasMuchFinerNeighbour(int n) const
  {
    const Triangle& tri = nodes_[n].corner;
    for (int k = 0; k < 3; ++k)
    {
      const int a = tri[k], b = tri[(k + 1) % 3], m = midpoint(a, b);
      if (m >= 0 && (midpoint(a, m) >= 0 || midpoint(m, b) >= 0))
        return true;
    }
    return false;
  }

  /// Number of edges of leaf n split by a finer neighbour.
  int hangingEdges(int n) const
  {
    const Triangle& tri = nodes_[n].corner;
    int count = 0;
    for (int k = 0; k < 3; ++k)
      count += midpoint(tri[k], tri[(k + 1) % 3]) >= 0;
    return count;
  }

private:
  int makeMidpoint(int a, int b, int patch)
  {
    const auto [it, isNew] = midpointOf_.emplace(edgeKey(a, b), static_cast<int>(locations_.size()));
    if (isNew)
      locations_.push_back(midpointLocation(domain_, around_, locations_[a], locations_[b], patch));
    return it->second;
  }

  const BaseDomain& domain_;
  const std::vector<std::vector<int>>& around_;
  std::vector<SurfacePoint> locations_;
  std::vector<Node> nodes_;
  std::unordered_map<std::uint64_t, int> midpointOf_;
};

/// Splits leaves until neighbouring leaves differ by at most one level and
/// no leaf has more than one edge split by a finer neighbour.
void balanceAndClose(RefinementTree& tree)
{
  for (bool changed = true; changed;)
  {
    changed = false;
    for (int n = 0; n < static_cast<int>(tree.nodes().size()); ++n)
      if (tree.nodes()[n].firstChild < 0 && (tree.hasMuchFinerNeighbour(n) || tree.hangingEdges(n) >= 2))
      {
        tree.split(n);
        changed = true;
      }
  }
}

/// Writes the tree as a remesh numbered like uniform refinement.
void writeRemesh(const RefinementTree& tree, int featureCount, SemiRegularMesh& out)
{
  const auto& nodes = tree.nodes();
  std::vector<int> finalId(tree.locations().size(), -1);
  for (int v = 0; v < featureCount; ++v)
    finalId[v] = v;
  out.locations.assign(tree.locations().begin(), tree.locations().begin() + featureCount);
  out.levelOfVertex.assign(featureCount, 0);
  // Level by level: the split nodes of level l - 1 in tree order name
  // the midpoints of level l.
  std::vector<int> levelNodes(tree.rootCount());
  for (int t = 0; t < tree.rootCount(); ++t)
    levelNodes[t] = t;
  for (int l = 1; !levelNodes.empty(); ++l)
  {
    std::vector<int> next;
    for (int n : levelNodes)
    {
      if (nodes[n].firstChild < 0)
        continue;
      const Triangle& tri = nodes[n].corner;
      for (int k = 0; k < 3; ++k)
      {
        const int m = tree.midpoint(tri[k], tri[(k + 1) % 3]);
        if (finalId[m] < 0)
        {
          finalId[m] = out.vertexCount();
          out.locations.push_back(tree.locations()[m]);
          out.levelOfVertex.push_back(l);
        }
      }
      for (int c = 0; c < 4; ++c)
        next.push_back(nodes[n].firstChild + c);
    }
    levelNodes = std::move(next);
    if (!levelNodes.empty())
      out.level = l;
  }
  // Triangles depth first, a leaf with one split edge as two halves.
  std::vector<int> stack;
  for (int t = tree.rootCount() - 1; t >= 0; --t)
    stack.push_back(t);
  while (!stack.empty())
  {
    const int n = stack.back();
    stack.pop_back();
    const auto& node = nodes[n];
    if (node.firstChild >= 0)
    {
      for (int c = 3; c >= 0; --c)
        stack.push_back(node.firstChild + c);
      continue;
    }
    Triangle tri = node.corner;
    for (int& v : tri)
      v = finalId[v];
    int hanging = -1, m = -1;
    for (int k = 0; k < 3 && hanging < 0; ++k)
      if ((m = tree.midpoint(node.corner[k], node.corner[(k + 1) % 3])) >= 0)
        hanging = k;
    if (hanging < 0)
    {
      out.triangles.push_back(tri);
      out.patchOfTriangle.push_back(node.patch);
      out.levelOfTriangle.push_back(node.level);
      continue;
    }
    const int a = tri[hanging], b = tri[(hanging + 1) % 3], c = tri[(hanging + 2) % 3];
    for (const Triangle& half : { Triangle{ a, finalId[m], c }, Triangle{ finalId[m], b, c } })
    {
      out.triangles.push_back(half);
      out.patchOfTriangle.push_back(node.patch);
      out.levelOfTriangle.push_back(node.level);
    }
  }
}

} // namespace

Status buildAdaptiveSemiRegularMesh(
  const BaseDomain& domain, int maximumLevel, const SplitRule& needsSplit, SemiRegularMesh& out)
{
  if (!isRemeshLevel(maximumLevel))
    return Status::error(remeshLevelProblem(maximumLevel));
  if (Status s = checkBaseDomain(domain); !s.ok())
    return s;
  const auto around = trianglesAroundBaseVertices(domain);
  RefinementTree tree(domain, around);
  // Nodes are appended level by level, so one pass visits every level in turn.
  for (int n = 0; n < static_cast<int>(tree.nodes().size()); ++n)
    if (tree.nodes()[n].level < maximumLevel && needsSplit(tree.cornerLocations(n), tree.nodes()[n].level))
      tree.split(n);
  balanceAndClose(tree);
  out = SemiRegularMesh{};
  writeRemesh(tree, domain.mesh.vertexCount(), out);
  return {};
}

struct ParameterizedSurface::Index
{
  std::vector<std::vector<int>> trianglesOf;
  std::vector<std::vector<std::array<Vec2, 3>>> cornersOf;
  std::vector<TriangleGrid> grids;
};

ParameterizedSurface::ParameterizedSurface() = default;
ParameterizedSurface::~ParameterizedSurface() = default;
ParameterizedSurface::ParameterizedSurface(ParameterizedSurface&&) noexcept = default;
ParameterizedSurface& ParameterizedSurface::operator=(ParameterizedSurface&&) noexcept = default;

Status ParameterizedSurface::build(
  const TracedNet& net, const BaseDomain& domain, const PatchParameterization& parameterization)
{
  const EditableMesh& mesh = net.mesh;
  const int patchCount = domain.mesh.triangleCount();
  if (static_cast<int>(parameterization.baseTriangle.size()) != mesh.vertexCount())
    return Status::error("the parameterization does not belong to this surface");
  if (static_cast<int>(net.landmarkVertex.size()) != domain.mesh.vertexCount())
    return Status::error("the surface has " + std::to_string(net.landmarkVertex.size()) +
      " landmarks but the base domain has " + std::to_string(domain.mesh.vertexCount()) + " vertices");
  auto index = std::make_unique<Index>();
  index->trianglesOf.resize(patchCount);
  index->cornersOf.resize(patchCount);
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const int patch = net.patchOfTriangle[t];
    std::array<Vec2, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      const int v = mesh.triangle(t)[k];
      std::array<double, 3> c;
      if (!coordinatesInTriangle(domain, parameterization.baseTriangle[v], parameterization.baseCoordinates[v], patch, c))
        return Status::error("point " + std::to_string(v) + " has no coordinates in patch " + std::to_string(patch));
      corners[k] = Vec2(c[1], c[2]);
    }
    index->trianglesOf[patch].push_back(t);
    index->cornersOf[patch].push_back(corners);
  }
  index->grids.resize(patchCount);
  for (int p = 0; p < patchCount; ++p)
    index->grids[p].build(index->cornersOf[p]);

  diagonal_ = cmp::boundingBoxDiagonal(mesh.points());
  index_ = std::move(index);
  net_ = &net;
  domain_ = &domain;
  return {};
}

Status ParameterizedSurface::locate(const SurfacePoint& at, SurfacePoint& sample) const
{
  if (!index_)
    return Status::error("the parameterized surface was not built");
  const Triangle& base = domain_->mesh.triangles[at.triangle];
  for (int k = 0; k < 3; ++k)
    if (at.weight[k] == 1.0) // a base vertex: its landmark exactly
    {
      sample = { { net_->landmarkVertex[base[k]], -1, -1 }, { 1.0, 0.0, 0.0 } };
      return {};
    }
  int found = -1;
  std::array<double, 3> w{};
  if (!index_->grids[at.triangle].locate(Vec2(at.weight[1], at.weight[2]), found, w))
    return Status::error("a base location lies in no triangle of patch " + std::to_string(at.triangle));
  double sum = 0.0;
  for (double& x : w)
    sum += (x = std::max(x, 0.0));
  const int triangle = index_->trianglesOf[at.triangle][found];
  const Triangle& tri = net_->mesh.triangle(triangle);
  sample = { { tri[0], tri[1], tri[2] }, { w[0] / sum, w[1] / sum, w[2] / sum }, triangle };
  return {};
}

void ParameterizedSurface::forEachTriangleImage(
  const std::function<void(int, const std::array<Vec2, 3>&, double)>& visit) const
{
  if (!index_)
    return;
  for (std::size_t patch = 0; patch < index_->trianglesOf.size(); ++patch)
    for (std::size_t i = 0; i < index_->trianglesOf[patch].size(); ++i)
    {
      const Triangle& tri = net_->mesh.triangle(index_->trianglesOf[patch][i]);
      const Vec3 a = net_->mesh.point(tri[1]) - net_->mesh.point(tri[0]);
      const Vec3 b = net_->mesh.point(tri[2]) - net_->mesh.point(tri[0]);
      visit(static_cast<int>(patch), index_->cornersOf[patch][i], 0.5 * a.cross(b).norm());
    }
}

Vec3 ParameterizedSurface::position(const SurfacePoint& sample) const
{
  return samplePosition(net_->mesh, sample);
}

SplitRule flatnessSplitRule(const std::vector<const ParameterizedSurface*>& models, double tolerance)
{
  return [models, tolerance](const std::array<SurfacePoint, 3>& corners, int)
  {
    // The points of the triangle's next two 1-to-4 refinements (its
    // barycentric lattice of order 4 without the corners), in the corners'
    // base triangle: a bump between the edge midpoints and the centroid
    // (the rim of an ear, a hoof's edge) shows there.
    constexpr int kOrder = 4;
    constexpr int kProbes = (kOrder + 1) * (kOrder + 2) / 2 - 3;
    std::array<std::array<double, 3>, kProbes> mix{};
    int made = 0;
    for (int i = 0; i <= kOrder; ++i)
      for (int j = 0; i + j <= kOrder; ++j)
      {
        const int k = kOrder - i - j;
        if (i == kOrder || j == kOrder || k == kOrder)
          continue;
        mix[made++] = { static_cast<double>(i) / kOrder, static_cast<double>(j) / kOrder,
          static_cast<double>(k) / kOrder };
      }
    std::array<SurfacePoint, kProbes> probes;
    for (int i = 0; i < kProbes; ++i)
    {
      probes[i].triangle = corners[0].triangle;
      probes[i].vertex = corners[0].vertex;
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
          probes[i].weight[k] += mix[i][c] * corners[c].weight[k];
    }
    for (const ParameterizedSurface* model : models)
    {
      std::array<Vec3, 3> at;
      SurfacePoint sample;
      for (int c = 0; c < 3; ++c)
      {
        if (!model->locate(corners[c], sample).ok())
          return true; // cannot judge: refining never hurts consistency
        at[c] = model->position(sample);
      }
      const double limit = tolerance * model->boundingBoxDiagonal();
      for (int i = 0; i < kProbes; ++i)
      {
        if (!model->locate(probes[i], sample).ok())
          return true;
        const Vec3 flat = mix[i][0] * at[0] + mix[i][1] * at[1] + mix[i][2] * at[2];
        if ((model->position(sample) - flat).norm() > limit)
          return true;
      }
    }
    return false;
  };
}

Status placeOnSurface(const SemiRegularMesh& remesh, const TracedNet& net, const BaseDomain& domain,
  const PatchParameterization& parameterization, std::vector<SurfacePoint>& samples)
{
  ParameterizedSurface surface;
  if (Status s = surface.build(net, domain, parameterization); !s.ok())
    return s;
  return placeOnSurface(remesh, surface, samples);
}

Status placeOnSurface(
  const SemiRegularMesh& remesh, const ParameterizedSurface& surface, std::vector<SurfacePoint>& samples)
{
  samples.assign(remesh.vertexCount(), SurfacePoint{});
  for (int v = 0; v < remesh.vertexCount(); ++v)
    if (Status s = surface.locate(remesh.locations[v], samples[v]); !s.ok())
      return Status::error("remesh vertex " + std::to_string(v) + ": " + s.message());
  return {};
}

Vec3 samplePosition(const EditableMesh& mesh, const SurfacePoint& sample)
{
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    if (sample.vertex[k] >= 0)
      p += sample.weight[k] * mesh.point(sample.vertex[k]);
  return p;
}

std::vector<Vec3> samplePositions(const TracedNet& net, const std::vector<SurfacePoint>& samples)
{
  std::vector<Vec3> positions;
  positions.reserve(samples.size());
  for (const SurfacePoint& s : samples)
    positions.push_back(samplePosition(net.mesh, s));
  return positions;
}

} // namespace cmp
