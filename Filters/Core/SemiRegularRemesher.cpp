#include "SemiRegularRemesher.h"

#include <Eigen/Core>

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
BaseLocation canonical(const BaseDomain& domain, const std::vector<std::vector<int>>& around, const BaseLocation& at)
{
  const Triangle& tri = domain.mesh.triangles[at.triangle];
  int support = -1, count = 0;
  for (int k = 0; k < 3; ++k)
    if (at.coordinates[k] != 0.0)
    {
      support = tri[k];
      ++count;
    }
  if (count == 3)
    return at;
  for (int candidate : around[support]) // increasing order
  {
    BaseLocation moved{ candidate, {} };
    if (coordinatesInTriangle(domain, at.triangle, at.coordinates, candidate, moved.coordinates))
      return moved;
  }
  return at;
}

std::uint64_t edgeKey(int a, int b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

} // namespace

Status buildSemiRegularMesh(const BaseDomain& domain, int level, SemiRegularMesh& out)
{
  if (level < 0 || level > 8)
    return Status::error("level " + std::to_string(level) + " is out of range (0 to 8)");
  if (Status s = checkBaseDomain(domain); !s.ok())
    return s;
  const auto around = trianglesAroundBaseVertices(domain);
  out = SemiRegularMesh{};
  out.level = level;
  const int featureCount = domain.mesh.vertexCount();
  out.locations.resize(featureCount);
  out.levelOfVertex.assign(featureCount, 0);
  for (int bv = 0; bv < featureCount; ++bv)
  {
    const int t = around[bv].front();
    BaseLocation at{ t, { 0.0, 0.0, 0.0 } };
    at.coordinates[std::find(domain.mesh.triangles[t].begin(), domain.mesh.triangles[t].end(), bv) -
      domain.mesh.triangles[t].begin()] = 1.0;
    out.locations[domain.featureIds[bv]] = at;
  }
  for (int t = 0; t < domain.mesh.triangleCount(); ++t)
  {
    Triangle tri = domain.mesh.triangles[t];
    for (int& v : tri)
      v = domain.featureIds[v];
    out.triangles.push_back(tri);
    out.patchOfTriangle.push_back(t);
  }

  for (int l = 1; l <= level; ++l)
  {
    std::unordered_map<std::uint64_t, int> midpointOf;
    midpointOf.reserve(out.triangles.size() * 2);
    const auto midpoint = [&](int a, int b, int patch)
    {
      const auto [it, isNew] = midpointOf.emplace(edgeKey(a, b), out.vertexCount());
      if (isNew)
      {
        BaseLocation at{ patch, {} }, la, lb;
        coordinatesInTriangle(domain, out.locations[a].triangle, out.locations[a].coordinates, patch, la.coordinates);
        coordinatesInTriangle(domain, out.locations[b].triangle, out.locations[b].coordinates, patch, lb.coordinates);
        for (int k = 0; k < 3; ++k) // dyadic: exact, so zeros stay zeros
          at.coordinates[k] = 0.5 * (la.coordinates[k] + lb.coordinates[k]);
        out.locations.push_back(canonical(domain, around, at));
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
  return {};
}

namespace
{

using Vec2 = Eigen::Vector2d;

/// Point location in one patch's parameter triangle: a uniform grid of
/// cells, each listing the surface triangles whose image's box meets it.
class PatchGrid
{
public:
  void build(const std::vector<int>& triangles, const std::vector<std::array<Vec2, 3>>& corners)
  {
    triangles_ = &triangles;
    corners_ = &corners;
    size_ = std::max(1, static_cast<int>(std::sqrt(0.5 * static_cast<double>(triangles.size()))));
    start_.assign(static_cast<std::size_t>(size_) * size_ + 1, 0);
    forEachCell([&](int, int cell) { ++start_[cell + 1]; });
    for (std::size_t i = 1; i < start_.size(); ++i)
      start_[i] += start_[i - 1];
    entries_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    forEachCell([&](int i, int cell) { entries_[fill[cell]++] = i; });
  }

  /// The triangle (index into the patch list) whose image contains `q`
  /// best (largest smallest barycentric coordinate), with its coordinates.
  bool locate(const Vec2& q, int& best, std::array<double, 3>& weights) const
  {
    double bestScore = -std::numeric_limits<double>::infinity();
    const int cx = cellOf(q.x()), cy = cellOf(q.y());
    for (int radius = 0; radius < size_; ++radius)
    {
      for (int x = std::max(0, cx - radius); x <= std::min(size_ - 1, cx + radius); ++x)
        for (int y = std::max(0, cy - radius); y <= std::min(size_ - 1, cy + radius); ++y)
        {
          if (std::max(std::abs(x - cx), std::abs(y - cy)) != radius)
            continue;
          const int cell = x * size_ + y;
          for (int e = start_[cell]; e < start_[cell + 1]; ++e)
            score(entries_[e], q, bestScore, best, weights);
        }
      if (bestScore > -1e-9)
        return true;
    }
    return best >= 0;
  }

private:
  int cellOf(double u) const { return std::clamp(static_cast<int>(u * size_), 0, size_ - 1); }

  template <class Visit>
  void forEachCell(Visit visit) const
  {
    for (int i = 0; i < static_cast<int>(triangles_->size()); ++i)
    {
      const auto& c = (*corners_)[i];
      const int x0 = cellOf(std::min({ c[0].x(), c[1].x(), c[2].x() }));
      const int x1 = cellOf(std::max({ c[0].x(), c[1].x(), c[2].x() }));
      const int y0 = cellOf(std::min({ c[0].y(), c[1].y(), c[2].y() }));
      const int y1 = cellOf(std::max({ c[0].y(), c[1].y(), c[2].y() }));
      for (int x = x0; x <= x1; ++x)
        for (int y = y0; y <= y1; ++y)
          visit(i, x * size_ + y);
    }
  }

  void score(int i, const Vec2& q, double& bestScore, int& best, std::array<double, 3>& weights) const
  {
    const auto& c = (*corners_)[i];
    const Vec2 e1 = c[1] - c[0], e2 = c[2] - c[0], d = q - c[0];
    const double area = e1.x() * e2.y() - e1.y() * e2.x();
    if (!(area > 0.0))
      return; // crowded to nothing: its neighbours cover the point too
    const double w1 = (d.x() * e2.y() - d.y() * e2.x()) / area;
    const double w2 = (e1.x() * d.y() - e1.y() * d.x()) / area;
    const double w0 = 1.0 - w1 - w2;
    const double s = std::min({ w0, w1, w2 });
    if (s > bestScore)
    {
      bestScore = s;
      best = i;
      weights = { w0, w1, w2 };
    }
  }

  const std::vector<int>* triangles_ = nullptr;
  const std::vector<std::array<Vec2, 3>>* corners_ = nullptr;
  int size_ = 1;
  std::vector<int> start_, entries_;
};

} // namespace

Status placeOnSurface(const SemiRegularMesh& remesh, const TracedNet& net, const BaseDomain& domain,
  const PatchParameterization& parameterization, std::vector<SurfaceSample>& samples)
{
  const EditableMesh& mesh = net.mesh;
  const int patchCount = domain.mesh.triangleCount();
  if (static_cast<int>(parameterization.baseTriangle.size()) != mesh.vertexCount())
    return Status::error("the parameterization does not belong to this surface");
  std::vector<std::vector<int>> trianglesOf(patchCount);
  std::vector<std::vector<std::array<Vec2, 3>>> cornersOf(patchCount);
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
    trianglesOf[patch].push_back(t);
    cornersOf[patch].push_back(corners);
  }
  std::vector<PatchGrid> grids(patchCount);
  for (int p = 0; p < patchCount; ++p)
    grids[p].build(trianglesOf[p], cornersOf[p]);

  samples.assign(remesh.vertexCount(), SurfaceSample{});
  const int featureCount = domain.mesh.vertexCount();
  for (int bv = 0; bv < featureCount; ++bv) // landmarks exactly
    samples[domain.featureIds[bv]] = { { net.landmarkVertex[bv], -1, -1 }, { 1.0, 0.0, 0.0 } };
  for (int v = featureCount; v < remesh.vertexCount(); ++v)
  {
    const BaseLocation& at = remesh.locations[v];
    int found = -1;
    std::array<double, 3> w{};
    if (!grids[at.triangle].locate(Vec2(at.coordinates[1], at.coordinates[2]), found, w))
      return Status::error("remesh vertex " + std::to_string(v) + " lies in no triangle of patch " +
        std::to_string(at.triangle));
    double sum = 0.0;
    for (double& x : w)
      sum += (x = std::max(x, 0.0));
    const Triangle& tri = mesh.triangle(trianglesOf[at.triangle][found]);
    samples[v] = { { tri[0], tri[1], tri[2] }, { w[0] / sum, w[1] / sum, w[2] / sum } };
  }
  return {};
}

std::vector<Vec3> samplePositions(const TracedNet& net, const std::vector<SurfaceSample>& samples)
{
  std::vector<Vec3> positions;
  positions.reserve(samples.size());
  for (const SurfaceSample& s : samples)
  {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      if (s.vertex[k] >= 0)
        p += s.weight[k] * net.mesh.point(s.vertex[k]);
    positions.push_back(p);
  }
  return positions;
}

} // namespace cmp
