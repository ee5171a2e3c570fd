#include "SampleRelaxation.h"

#include "PatchParameterization.h"
#include "TriangleGrid.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace cmp
{
namespace
{

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
      if (!std::isfinite(weight))
        return;
      mass[patch].push_back({ (image[0] + image[1] + image[2]) / 3.0, weight });
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
bool insideBaseTriangle(const BaseLocation& at)
{
  return at.coordinates[0] > 0.0 && at.coordinates[1] > 0.0 && at.coordinates[2] > 0.0;
}

/// One base triangle's part of the remesh, in its (c1, c2) coordinates.
class PatchSamples
{
public:
  PatchSamples(const BaseDomain& domain, SemiRegularMesh& remesh, const std::vector<int>& triangles, int patch)
    : domain_(domain), remesh_(remesh), triangles_(triangles), patch_(patch)
  {
    for (int t : triangles_)
      for (int v : remesh_.triangles[t])
        if (position_.find(v) == position_.end())
        {
          std::array<double, 3> c{};
          coordinatesInTriangle(domain_, remesh_.locations[v].triangle, remesh_.locations[v].coordinates, patch_, c);
          position_[v] = Vec2(c[1], c[2]);
        }
  }

  /// Each remesh triangle's share of `mass` (weight, weighted centroid).
  void bin(const std::vector<MassPoint>& mass, std::vector<double>& weight, std::vector<Vec2>& moment) const
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
      weight[triangles_[found]] += point.weight;
      moment[triangles_[found]] += point.weight * point.at;
    }
  }

  /// Moves `v` the fraction `step` towards `target`, halving the step while
  /// a triangle of `ring` would not stay counter-clockwise; the distance
  /// moved (0 if no step was safe).
  double moveTowards(int v, const Vec2& target, double step, const std::vector<int>& ring)
  {
    const Vec2 from = position_.at(v);
    for (double fraction = step; fraction > 1e-3; fraction *= 0.5)
    {
      const Vec2 to = from + fraction * (target - from);
      position_[v] = to;
      if (std::all_of(ring.begin(), ring.end(), [&](int t) { return counterClockwise(t); }))
      {
        remesh_.locations[v].coordinates = { 1.0 - to.x() - to.y(), to.x(), to.y() };
        return (to - from).norm();
      }
    }
    position_[v] = from;
    return 0.0;
  }

private:
  bool counterClockwise(int t) const
  {
    const Triangle& tri = remesh_.triangles[t];
    const Vec2 a = position_.at(tri[0]);
    return cross2(position_.at(tri[1]) - a, position_.at(tri[2]) - a) > 0.0;
  }

  const BaseDomain& domain_;
  SemiRegularMesh& remesh_;
  const std::vector<int>& triangles_;
  int patch_;
  std::unordered_map<int, Vec2> position_;
};

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
    std::any_of(remesh.locations.begin(), remesh.locations.end(), [&](const BaseLocation& at) { return outside(at.triangle); }))
    return Status::error("the remesh does not belong to this base domain (it names a base triangle it does not have)");
  for (const Triangle& tri : remesh.triangles)
    for (int v : tri)
      if (v < 0 || v >= remesh.vertexCount())
        return Status::error("the remesh has a triangle with a vertex it does not have");
  return {};
}

/// The collection's mass in each remesh triangle: weight and first moment,
/// summed over every process's models.
void binMass(const std::vector<std::vector<MassPoint>>& mass, const std::vector<PatchSamples>& patches,
  Communicator& communicator, std::vector<double>& weight, std::vector<Vec2>& moment)
{
  const std::size_t count = weight.size();
  std::fill(weight.begin(), weight.end(), 0.0);
  std::fill(moment.begin(), moment.end(), Vec2::Zero());
  for (std::size_t p = 0; p < patches.size(); ++p)
    patches[p].bin(mass[p], weight, moment);
  std::vector<double> packed(3 * count);
  for (std::size_t t = 0; t < count; ++t)
  {
    packed[3 * t] = weight[t];
    packed[3 * t + 1] = moment[t].x();
    packed[3 * t + 2] = moment[t].y();
  }
  communicator.allReduceSum(packed.data(), packed.size());
  for (std::size_t t = 0; t < count; ++t)
  {
    weight[t] = packed[3 * t];
    moment[t] = Vec2(packed[3 * t + 1], packed[3 * t + 2]);
  }
}

} // namespace

Status relaxSampleLocations(const BaseDomain& domain, const std::vector<const ParameterizedSurface*>& localModels,
  Communicator& communicator, SemiRegularMesh& remesh, const SampleRelaxationOptions& options,
  SampleRelaxationReport* report)
{
  if (Status s = agreeOnStatus(checkInput(domain, localModels, remesh, options), communicator); !s.ok())
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
  std::vector<double> weight(triangleCount);
  std::vector<Vec2> moment(triangleCount);
  SampleRelaxationReport done;
  for (; done.iterations < options.iterations; ++done.iterations)
  {
    std::vector<PatchSamples> patches;
    patches.reserve(patchCount);
    for (int p = 0; p < patchCount; ++p)
      patches.emplace_back(domain, remesh, trianglesOf[p], p);
    binMass(mass, patches, communicator, weight, moment);
    done.movedVertices = 0;
    done.largestMove = 0.0;
    std::vector<char> visited(remesh.vertexCount(), 0);
    for (int p = 0; p < patchCount; ++p)
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
            ringWeight += weight[r];
            ringMoment += moment[r];
          }
          if (!(ringWeight > 0.0))
            continue;
          const double moved = patches[p].moveTowards(v, ringMoment / ringWeight, options.step, ringOf[v]);
          done.movedVertices += moved > 0.0;
          done.largestMove = std::max(done.largestMove, moved);
        }
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
