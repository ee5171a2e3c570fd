#include <cmp/remesh/SampleRelaxation.h>

#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/TriangleGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>

namespace cmp
{
namespace
{

/// Halvings of a move before a vertex is left where it is (a thousandth of
/// the step).
constexpr int kHalvings = 10;

/// The first fraction of step, step / 2, ... (`kHalvings` of them) for
/// which `tryMove(fraction)` succeeds; 0 if none does.
template <class TryMove>
double firstSafeFraction(double step, TryMove tryMove)
{
  double fraction = step;
  for (int halving = 0; halving < kHalvings; ++halving, fraction *= 0.5)
    if (tryMove(fraction))
      return fraction;
  return 0.0;
}

/// Per remesh triangle (column), the mass it holds: row 0 the weight, rows
/// 1 and 2 the first moment (weight x place); one block, so that one call
/// sums it over the processes.
using BinnedMass = Eigen::Matrix3Xd;

/// The weight in remesh triangle `t`.
double weightIn(const BinnedMass& binned, int t)
{
  return binned(0, t);
}

/// The first moment of the mass in remesh triangle `t`.
Vec2 momentIn(const BinnedMass& binned, int t)
{
  return binned.block<2, 1>(1, t);
}

/// A surface triangle's weight, at its image's centroid.
struct MassPoint
{
  Vec2 at;
  double weight = 0.0;
};

/// Per base triangle, every model's surface triangles as mass points, each
/// model's weights summing to 1 there.
std::vector<std::vector<MassPoint>> collectMass(const std::vector<const ParameterizedSurface*>& models, int patchCount)
{
  std::vector<std::vector<MassPoint>> mass(patchCount);
  for (const ParameterizedSurface* model : models)
  {
    std::vector<double> total(patchCount, 0.0);
    std::vector<std::size_t> first(patchCount);
    for (int p = 0; p < patchCount; ++p)
      first[p] = mass[p].size();
    model->forEachTriangleImage([&](int patch, const std::array<Vec2, 3>& image, double area) {
      const double imageArea = 0.5 * cross2(image[1] - image[0], image[2] - image[0]);
      if (!(imageArea > 0.0) || !(area > 0.0))
        return;
      const double weight = area * (area / imageArea); // area x density: see the header
      const Vec2 centroid = (image[0] + image[1] + image[2]) / 3.0;
      if (!(weight > 0.0) || !std::isfinite(weight) || !centroid.allFinite())
        return;
      mass[patch].push_back({ centroid, weight });
      total[patch] += weight;
    });
    for (int p = 0; p < patchCount; ++p)
      for (std::size_t i = first[p]; i < mass[p].size(); ++i)
        mass[p][i].weight /= total[p];
  }
  return mass;
}

/// True where every barycentric coordinate is positive: inside a base
/// triangle, free to move.
bool insideBaseTriangle(const SurfacePoint& at)
{
  return at.weight[0] > 0.0 && at.weight[1] > 0.0 && at.weight[2] > 0.0;
}

/// One base triangle's part of the remesh, in its (c1, c2) coordinates.
class PatchSamples
{
public:
  PatchSamples(const BaseDomain& domain, SemiRegularMesh& remesh, const std::vector<int>& triangles, int patch)
    : remesh_(remesh), triangles_(triangles), patch_(patch)
  {
    for (int t : triangles_)
      for (int v : remesh_.triangles[t])
        if (position_.find(v) == position_.end())
          locationInBaseTriangle(domain, remesh_.locations[v], patch_, position_[v]); // checked by checkInput
  }

  /// Each remesh triangle's share of `mass` (weight, weighted centroid).
  void bin(const std::vector<MassPoint>& mass, BinnedMass& binned) const
  {
    std::vector<std::array<Vec2, 3>> corners(triangles_.size());
    for (std::size_t i = 0; i < triangles_.size(); ++i)
      for (int k = 0; k < 3; ++k)
        corners[i][k] = position_.at(remesh_.triangles[triangles_[i]][k]);
    TriangleGrid grid;
    grid.build(corners);
    for (const MassPoint& point : mass)
    {
      int found = -1;
      std::array<double, 3> unused{};
      if (!grid.locate(point.at, found, unused))
        continue;
      binned(0, triangles_[found]) += point.weight;
      binned.block<2, 1>(1, triangles_[found]) += point.weight * point.at;
    }
  }

  /// Moves `v` the fraction `step` towards `target`, halving the step while
  /// a triangle of `ring` would not stay counter-clockwise; the distance
  /// moved (0 if no step was safe).
  double moveTowards(int v, const Vec2& target, double step, const std::vector<int>& ring)
  {
    const Vec2 from = position_.at(v);
    const double fraction =
      firstSafeFraction(step, [&](double f) { return placeIfValid(v, from + f * (target - from), ring); });
    if (!(fraction > 0.0))
      return 0.0;
    const Vec2 to = position_.at(v);
    remesh_.locations[v].weight = { 1.0 - to.x() - to.y(), to.x(), to.y() };
    return (to - from).norm();
  }

  /// Puts `v` at `q`, unchecked (to undo a move).
  void put(int v, const Vec2& q) { position_[v] = q; }

  /// Puts `v` at `q` if the triangles of `ring` that lie in this base
  /// triangle stay counter-clockwise; true if it did.
  bool placeIfValid(int v, const Vec2& q, const std::vector<int>& ring)
  {
    const Vec2 from = position_.at(v);
    position_[v] = q;
    for (int t : ring)
      if (remesh_.patchOfTriangle[t] == patch_ && !counterClockwise(t))
      {
        position_[v] = from;
        return false;
      }
    return true;
  }

private:
  bool counterClockwise(int t) const
  {
    const Triangle& tri = remesh_.triangles[t];
    const Vec2 a = position_.at(tri[0]);
    return cross2(position_.at(tri[1]) - a, position_.at(tri[2]) - a) > 0.0;
  }

  SemiRegularMesh& remesh_;
  const std::vector<int>& triangles_;
  int patch_;
  std::unordered_map<int, Vec2> position_;
};

/// A vertex on a base edge: the edge's base vertices and the vertex's
/// place along it (0 at `a`, 1 at `b`), with their indices in the vertex's
/// own base triangle.
struct EdgePlace
{
  int a = -1, b = -1;
  int indexA = -1, indexB = -1;
  double along = 0.0;
};

/// True, with `place`, for a vertex strictly inside a base edge.
bool onBaseEdge(const BaseDomain& domain, const SurfacePoint& at, EdgePlace& place)
{
  const auto& c = at.weight;
  if (std::count(c.begin(), c.end(), 0.0) != 1)
    return false;
  const Triangle& corners = domain.mesh.triangles[at.triangle];
  place.indexA = c[0] != 0.0 ? 0 : 1;
  place.indexB = c[2] != 0.0 ? 2 : 1;
  place.a = corners[place.indexA];
  place.b = corners[place.indexB];
  place.along = c[place.indexB] / (c[place.indexA] + c[place.indexB]);
  return true;
}

/// The weights of base vertices `a` and `b` in point `q` of base triangle
/// `patch` (0 for one the triangle lacks).
std::pair<double, double> edgeWeights(const BaseDomain& domain, int patch, const Vec2& q, int a, int b)
{
  const Triangle& corners = domain.mesh.triangles[patch];
  const double c[3] = { 1.0 - q.x() - q.y(), q.x(), q.y() };
  std::pair<double, double> weights{ 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
  {
    if (corners[k] == a)
      weights.first = c[k];
    if (corners[k] == b)
      weights.second = c[k];
  }
  return weights;
}

/// The place `along` the base edge of `place`, as a location in the
/// vertex's own base triangle, that of `home`.
SurfacePoint alongEdge(const SurfacePoint& home, const EdgePlace& place, double along)
{
  SurfacePoint at;
  at.triangle = home.triangle;
  at.vertex = home.vertex;
  at.weight[place.indexA] = 1.0 - along;
  at.weight[place.indexB] = along;
  return at;
}

Status checkInput(const BaseDomain& domain, const std::vector<const ParameterizedSurface*>& models,
  const SemiRegularMesh& remesh, const SampleRelaxationOptions& options)
{
  if (std::any_of(models.begin(), models.end(), [](const ParameterizedSurface* m) { return !m || !m->built(); }))
    return Status::error("a model is missing or was not parameterized (built)");
  if (options.iterations < 0)
    return Status::error(
      "the number of sample relaxation rounds is negative (" + std::to_string(options.iterations) + ")");
  if (!(options.step > 0.0 && options.step <= 1.0))
    return Status::error("the sample relaxation step must be in (0, 1] (it is " + std::to_string(options.step) + ")");
  if (remesh.patchOfTriangle.size() != remesh.triangles.size())
    return Status::error("the remesh has no base triangle for some of its triangles");
  const int patchCount = domain.mesh.triangleCount();
  const auto outside = [&](int p) { return p < 0 || p >= patchCount; };
  if (std::any_of(remesh.patchOfTriangle.begin(), remesh.patchOfTriangle.end(), outside) ||
    std::any_of(remesh.locations.begin(), remesh.locations.end(), [&](const SurfacePoint& at) { return outside(at.triangle); }))
    return Status::error("the remesh does not belong to this base domain (it names a base triangle it does not have)");
  for (std::size_t t = 0; t < remesh.triangles.size(); ++t)
    for (int v : remesh.triangles[t])
    {
      Vec2 unused;
      if (v < 0 || v >= remesh.vertexCount())
        return Status::error("the remesh has a triangle with a vertex it does not have");
      if (!locationInBaseTriangle(domain, remesh.locations[v], remesh.patchOfTriangle[t], unused) ||
        (insideBaseTriangle(remesh.locations[v]) && remesh.locations[v].triangle != remesh.patchOfTriangle[t]))
        return Status::error("remesh vertex " + std::to_string(v) + " does not lie in the base triangle of its triangle " +
          std::to_string(t));
    }
  return {};
}

/// A fingerprint of the remesh and the options: equal on every process
/// that relaxes the same remesh the same way.
std::uint64_t fingerprint(const SemiRegularMesh& remesh, const SampleRelaxationOptions& options)
{
  std::uint64_t hash = 1469598103934665603ull; // FNV-1a
  const auto add = [&hash](const void* data, std::size_t bytes) {
    const auto* byte = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i)
      hash = (hash ^ byte[i]) * 1099511628211ull;
  };
  add(remesh.triangles.data(), remesh.triangles.size() * sizeof(Triangle));
  add(remesh.patchOfTriangle.data(), remesh.patchOfTriangle.size() * sizeof(int));
  for (const SurfacePoint& at : remesh.locations)
  {
    add(&at.triangle, sizeof at.triangle);
    add(at.weight.data(), sizeof at.weight);
  }
  add(&options.iterations, sizeof options.iterations);
  add(&options.step, sizeof options.step);
  return hash;
}

/// Fails on every process unless all pass the same remesh and options: the
/// sums over processes are taken per remesh triangle.
Status agreeOnRemesh(const SemiRegularMesh& remesh, const SampleRelaxationOptions& options, Communicator& communicator)
{
  const std::uint64_t hash = fingerprint(remesh, options);
  for (int shift : { 0, 31, 62 })
  {
    const std::vector<int> parts = communicator.allGather(static_cast<int>((hash >> shift) & 0x7fffffffu));
    if (std::adjacent_find(parts.begin(), parts.end(), std::not_equal_to<int>()) != parts.end())
      return Status::error("the processes relax different remeshes or with different options (an adaptive remesh "
                           "refined on each process's own models, for one): remesh one connectivity for all");
  }
  return {};
}

/// The collection's mass in each remesh triangle, summed over every
/// process's models.
void binMass(const std::vector<std::vector<MassPoint>>& mass, const std::vector<PatchSamples>& patches,
  Communicator& communicator, BinnedMass& binned)
{
  binned.setZero();
  for (std::size_t p = 0; p < patches.size(); ++p)
    patches[p].bin(mass[p], binned);
  communicator.allReduceSum(binned.data(), static_cast<std::size_t>(binned.size()));
}

/// Counts one move in the report.
void record(double moved, SampleRelaxationReport& done)
{
  done.movedVertices += moved > 0.0;
  done.largestMove = std::max(done.largestMove, moved);
}

/// Moves every vertex inside a base triangle towards the mass centroid of
/// its ring of remesh triangles.
void moveInsideBaseTriangles(SemiRegularMesh& remesh, const std::vector<std::vector<int>>& trianglesOf,
  const std::vector<std::vector<int>>& ringOf, const BinnedMass& binned,
  double step, std::vector<PatchSamples>& patches, SampleRelaxationReport& done)
{
  std::vector<char> visited(remesh.vertexCount(), 0);
  for (std::size_t p = 0; p < trianglesOf.size(); ++p)
    for (int t : trianglesOf[p])
      for (int v : remesh.triangles[t])
      {
        if (visited[v] || !insideBaseTriangle(remesh.locations[v]))
          continue;
        visited[v] = 1;
        double ringWeight = 0.0;
        Vec2 ringMoment = Vec2::Zero();
        for (int r : ringOf[v])
        {
          ringWeight += weightIn(binned, r);
          ringMoment += momentIn(binned, r);
        }
        if (ringWeight > 0.0)
          record(patches[p].moveTowards(v, ringMoment / ringWeight, step, ringOf[v]), done);
      }
}

/// Slides every vertex on a base edge along it, towards the mean place
/// along the edge of its ring's mass centroids (in both base triangles),
/// halving the step while a ring triangle would turn clockwise in either.
/// The landmarks, at the edges' ends, stay.
void slideAlongBaseEdges(const BaseDomain& domain, SemiRegularMesh& remesh,
  const std::vector<std::vector<int>>& ringOf, const BinnedMass& binned,
  double step, std::vector<PatchSamples>& patches, SampleRelaxationReport& done)
{
  for (int v = 0; v < remesh.vertexCount(); ++v)
  {
    EdgePlace place;
    if (!onBaseEdge(domain, remesh.locations[v], place))
      continue;
    double ringWeight = 0.0, ringAlong = 0.0;
    for (int r : ringOf[v])
    {
      const double weight = weightIn(binned, r);
      if (!(weight > 0.0))
        continue;
      const auto [wa, wb] = edgeWeights(domain, remesh.patchOfTriangle[r], momentIn(binned, r) / weight, place.a, place.b);
      if (wa + wb > 0.0)
      {
        ringWeight += weight;
        ringAlong += weight * wb / (wa + wb);
      }
    }
    if (!(ringWeight > 0.0))
      continue;
    const double target = ringAlong / ringWeight;
    SurfacePoint& at = remesh.locations[v];
    // Placed in each base triangle of its ring, or back where it was in all.
    const auto placeEverywhere = [&](const SurfacePoint& where, bool check) {
      std::vector<int> placedIn;
      for (int r : ringOf[v])
      {
        const int p = remesh.patchOfTriangle[r];
        if (std::find(placedIn.begin(), placedIn.end(), p) != placedIn.end())
          continue;
        Vec2 q;
        locationInBaseTriangle(domain, where, p, q); // an edge vertex lies on both its base triangles
        if (!patches[p].placeIfValid(v, q, check ? ringOf[v] : std::vector<int>{}))
          return false;
        placedIn.push_back(p);
      }
      return true;
    };
    const double fraction = firstSafeFraction(step, [&](double f) {
      const double along = place.along + f * (target - place.along);
      if (along > 0.0 && along < 1.0 && placeEverywhere(alongEdge(at, place, along), true))
        return true;
      placeEverywhere(at, false);
      return false;
    });
    if (fraction > 0.0)
    {
      const double along = place.along + fraction * (target - place.along);
      at = alongEdge(at, place, along);
      record(std::abs(along - place.along), done);
    }
  }
}

} // namespace

Status relaxSampleLocations(const BaseDomain& domain, const std::vector<const ParameterizedSurface*>& localModels,
  Communicator& communicator, SemiRegularMesh& remesh, const SampleRelaxationOptions& options,
  SampleRelaxationReport* report)
{
  if (Status s = agreeOnStatus(checkInput(domain, localModels, remesh, options), communicator); !s.ok())
    return s;
  if (Status s = agreeOnRemesh(remesh, options, communicator); !s.ok())
    return s;
  const std::vector<int> modelCounts = communicator.allGather(static_cast<int>(localModels.size()));
  if (std::all_of(modelCounts.begin(), modelCounts.end(), [](int n) { return n == 0; }))
    return Status::error("no model to relax the samples for");
  const int patchCount = domain.mesh.triangleCount();
  const int triangleCount = static_cast<int>(remesh.triangles.size());
  std::vector<std::vector<int>> trianglesOf(patchCount), ringOf(remesh.vertexCount());
  for (int t = 0; t < triangleCount; ++t)
  {
    trianglesOf[remesh.patchOfTriangle[t]].push_back(t);
    for (int v : remesh.triangles[t])
      ringOf[v].push_back(t);
  }
  const std::vector<std::vector<MassPoint>> mass = collectMass(localModels, patchCount);
  BinnedMass binned(3, triangleCount);
  SampleRelaxationReport done;
  for (; done.iterations < options.iterations; ++done.iterations)
  {
    std::vector<PatchSamples> patches;
    patches.reserve(patchCount);
    for (int p = 0; p < patchCount; ++p)
      patches.emplace_back(domain, remesh, trianglesOf[p], p);
    binMass(mass, patches, communicator, binned);
    done.movedVertices = 0;
    done.largestMove = 0.0;
    moveInsideBaseTriangles(remesh, trianglesOf, ringOf, binned, options.step, patches, done);
    slideAlongBaseEdges(domain, remesh, ringOf, binned, options.step, patches, done);
  }
  if (report)
    *report = done;
  return {};
}

Status relaxSampleLocations(const BaseDomain& domain, const std::vector<const ParameterizedSurface*>& models,
  SemiRegularMesh& remesh, const SampleRelaxationOptions& options, SampleRelaxationReport* report)
{
  SingleProcess alone;
  return relaxSampleLocations(domain, models, alone, remesh, options, report);
}

} // namespace cmp
