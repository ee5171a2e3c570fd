#include <cmp/remesh/Remesh.h>

#include <cmp/mesh/SurfaceDistance.h>
#include <cmp/mesh/TriangleMesh.h>
#include <cmp/mesh/TriangleShape.h>
#include <cmp/numerics/Threads.h>
#include <cmp/remesh/SampleRelaxation.h>

#include <algorithm>
#include <exception>
#include <functional>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace cmp
{

namespace
{

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The base vertex whose landmark lies nearest to `point` (straight-line
/// distance in `distance`), -1 if the net has none.
int nearestLandmark(const TracedNet& net, const Vec3& point, double& distance)
{
  int nearest = -1;
  distance = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < net.landmarkVertex.size(); ++b)
  {
    if (net.landmarkVertex[b] < 0)
      continue;
    const double d = (net.mesh.point(net.landmarkVertex[b]) - point).norm();
    if (d < distance)
    {
      distance = d;
      nearest = static_cast<int>(b);
    }
  }
  return nearest;
}

/// Sampled both ways: input to remesh catches features the remesh cuts
/// off, remesh to input catches triangles spanning concave regions. With
/// `far`, the same samples also mark the remesh triangles farther from the
/// model than `limit`.
void measureDistance(const BaseDomain& domain, const RemeshModel& model, const TriangleMesh& placed,
  RemeshModelReport& figures, double limit = 0.0, std::vector<char>* far = nullptr)
{
  const Clock::time_point start = Clock::now();
  const SurfaceDistance distance = surfaceDistance(*model.surface, placed, 3, limit, far);
  const double diagonal = boundingBoxDiagonal(*model.surface);
  figures.distanceMeasured = true;
  figures.hausdorffDistance = distance.hausdorff();
  figures.hausdorffDistanceRelative = diagonal > 0.0 ? figures.hausdorffDistance / diagonal : 0.0;
  figures.meanDistance = 0.5 * (distance.meanAToB + distance.meanBToA);
  // Where the Hausdorff distance is reached, and the landmark nearest to
  // it: a part without a landmark that the remesh misses (a tail's tip)
  // shows up here, and a landmark there is the cure.
  figures.hausdorffPoint = distance.farthestPoint();
  figures.hausdorffPointOnInput = distance.reachedOnA();
  double landmarkDistance = 0.0;
  const int base = nearestLandmark(model.map->net(), figures.hausdorffPoint, landmarkDistance);
  figures.hausdorffNearestFeature = base >= 0 ? domain.featureIds[base] : -1;
  figures.hausdorffFeatureDistanceRelative = base >= 0 && diagonal > 0.0 ? landmarkDistance / diagonal : 0.0;
  figures.distanceSeconds = secondsSince(start);
}

/// The remesh's landmarks: its base vertices (vertices 0..F-1; an open
/// L0's caps, whose features come last, are left out).
int landmarkCount(const SemiRegularMesh& mesh)
{
  int count = 0;
  while (count < mesh.vertexCount() && mesh.levelOfVertex[count] == 0)
    ++count;
  return count;
}

/// `rule`, which never splits a hole's triangle (they are left out).
SplitRule outsideHoles(SplitRule rule, const std::vector<char>& holeTriangles)
{
  if (holeTriangles.empty())
    return rule;
  return [rule = std::move(rule), &holeTriangles](const std::array<SurfacePoint, 3>& corners, int level) {
    const int patch = corners[0].triangle;
    if (patch >= 0 && patch < static_cast<int>(holeTriangles.size()) && holeTriangles[patch])
      return false;
    return rule(corners, level);
  };
}

/// The shared connectivity on one model: placed, repaired, measured.
/// With `far`, also marks the triangles where the placed remesh lies
/// farther from the model than the adaptive tolerance.
Status placeModel(const BaseDomain& domain, const SemiRegularMesh& mesh, const std::vector<int>& nearestLandmarks,
  const RemeshModel& model, const RemeshOptions& options, RemeshedModel& placed, RemeshModelReport& figures,
  std::vector<char>* far)
{
  const Clock::time_point start = Clock::now();
  const TracedNet& net = model.map->net();
  if (Status status = placeOnSurface(mesh, *model.map, placed.samples); !status.ok())
    return Status::error(
      "cannot place the remesh on the model (its parameterization does not fit its layout): " + status.message());
  if (options.repairFolds)
  {
    const Clock::time_point repairStart = Clock::now();
    if (Status status = repairFolds(mesh, net.mesh, placed.samples, options.foldRepair, &figures.repair);
        !status.ok())
      return status;
    figures.foldRepairSeconds = secondsSince(repairStart);
  }
  placed.positions = samplePositions(net, placed.samples);
  figures.placementSeconds = secondsSince(start);

  placed.folded = foldedTriangles(mesh, net.mesh, placed.samples);
  figures.foldedAfterRepair = static_cast<int>(std::count(placed.folded.begin(), placed.folded.end(), 1));
  figures.foldedBeforeRepair = options.repairFolds ? figures.repair.foldedBefore : figures.foldedAfterRepair;
  // The remesh as placed in space, for the centroid criterion and the distance.
  const TriangleMesh inSpace{ placed.positions, mesh.triangles };
  placed.centroidFlipped = centroidFlippedTriangles(*model.surface, inSpace);
  figures.centroidFlips = static_cast<int>(std::count(placed.centroidFlipped.begin(), placed.centroidFlipped.end(), 1));
  const TriangleShapeSummary shape = measureTriangleShapes(placed.positions, mesh.triangles);
  figures.minimumAngleDegrees = shape.minimumAngleDegrees;
  figures.meanShapeQuality = shape.meanShapeQuality;
  placed.foldsNearFeature =
    foldsNearLandmarks(nearestLandmarks, landmarkCount(mesh), placed.folded);
  // An adaptive pass's far triangles come from the distance's own samples.
  if (options.computeDistance || far)
    measureDistance(domain, model, inSpace, figures,
      options.adaptiveTolerance * boundingBoxDiagonal(*model.surface), far);
  figures.seconds = secondsSince(start);
  return {};
}

/// Adaptive remeshing makes the connectivity at most this many times
/// (`remesh()`): the first, then again while a placed remesh is farther
/// from a model than the tolerance.
constexpr int kAdaptivePasses = 3;

/// A place of the base domain where a placed adaptive remesh missed a
/// model: the leaf triangle there, of level `level`, is to be split.
struct RefineMark
{
  int patch = -1; ///< Base triangle.
  Vec2 at;        ///< The leaf's centroid, (c1, c2) in `patch`.
  int level = 0;  ///< The leaf's level: nodes down to it that hold `at` split.
};

/// The marks of the triangles `far` marks of `mesh` (the connectivity as
/// built, before its samples were relaxed: its corners are the tree's).
void addRefineMarks(
  const BaseDomain& domain, const SemiRegularMesh& mesh, const std::vector<char>& far, std::vector<RefineMark>& marks)
{
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
  {
    if (!far[t])
      continue;
    RefineMark mark;
    mark.patch = mesh.patchOfTriangle[t];
    std::array<Vec2, 3> corner;
    bool located = true;
    for (int k = 0; k < 3; ++k)
      located = located && locationInBaseTriangle(domain, mesh.locations[mesh.triangles[t][k]], mark.patch, corner[k]);
    if (!located)
      continue;
    mark.at = (corner[0] + corner[1] + corner[2]) / 3.0;
    mark.level = mesh.levelOfTriangle[t]; // a bisected leaf's halves keep its level
    marks.push_back(mark);
  }
}

/// Whether the plane triangle `corners` holds `p` (on its sides too).
bool holds(const std::array<Vec2, 3>& corners, const Vec2& p)
{
  const double tolerance = 1e-12;
  const double area = cross2(corners[1] - corners[0], corners[2] - corners[0]);
  for (int k = 0; k < 3; ++k)
    if (cross2(corners[(k + 1) % 3] - corners[k], p - corners[k]) * (area < 0.0 ? -1.0 : 1.0) < -tolerance)
      return false;
  return true;
}

/// `flatness`, and a split of every node down to a mark's level that holds
/// the mark.
SplitRule refinedSplitRule(SplitRule flatness, const std::vector<RefineMark>& marks)
{
  std::vector<std::vector<RefineMark>> byPatch; // the marks of each base triangle
  for (const RefineMark& mark : marks)
  {
    if (mark.patch >= static_cast<int>(byPatch.size()))
      byPatch.resize(mark.patch + 1);
    byPatch[mark.patch].push_back(mark);
  }
  return [flatness = std::move(flatness), byPatch = std::move(byPatch)](
           const std::array<SurfacePoint, 3>& corners, int level) {
    const int patch = corners[0].triangle;
    if (patch >= 0 && patch < static_cast<int>(byPatch.size()))
    {
      std::array<Vec2, 3> at;
      for (int k = 0; k < 3; ++k)
        at[k] = Vec2(corners[k].weight[1], corners[k].weight[2]);
      for (const RefineMark& mark : byPatch[patch])
        if (level <= mark.level && holds(at, mark.at))
          return true;
    }
    return flatness(corners, level);
  };
}

/// Per triangle of the shared connectivity, 1 where the remesh as placed on
/// any model of any rank lies farther from it than the tolerance (`far`:
/// this rank's models' marks).
std::vector<char> farTrianglesOverRanks(
  const std::vector<std::vector<char>>& far, std::size_t triangles, Communicator& communicator)
{
  std::vector<double> count(triangles, 0.0);
  for (const std::vector<char>& model : far)
    for (std::size_t t = 0; t < triangles && t < model.size(); ++t)
      count[t] += model[t];
  communicator.allReduceSum(count.data(), count.size());
  std::vector<char> marked(triangles, 0);
  for (std::size_t t = 0; t < triangles; ++t)
    marked[t] = count[t] > 0.0;
  return marked;
}

/// Relaxes `result.mesh`'s samples over every model (collective, with
/// relaxation) and places it on each of this rank's models; `progress`
/// gets the fraction of the models placed. `status` is the caller's so far.
/// With `far`, each model's far triangles (`placeModel()`) go there.
Status placeCollection(const BaseDomain& domain, const std::vector<RemeshModel>& localModels,
  const std::vector<const ParameterizedSurface*>& surfaces, Communicator& communicator, const RemeshOptions& options,
  Status status, const std::function<void(double)>& progress, CollectionRemesh& result, RemeshReport& local,
  std::vector<std::vector<char>>* far)
{
  if (far)
    far->assign(localModels.size(), {});
  const bool relax = options.sampleRelaxationIterations > 0;
  if (relax)
    status = agreeOnStatus(status, communicator);
  if (!status.ok())
    return status;
  if (relax)
  {
    const Clock::time_point start = Clock::now();
    SampleRelaxationOptions relaxation;
    relaxation.iterations = options.sampleRelaxationIterations;
    SampleRelaxationReport relaxed;
    if (Status s = relaxSampleLocations(domain, surfaces, communicator, result.mesh, relaxation, &relaxed); !s.ok())
      return Status::error("sample relaxation: " + s.message());
    local.sampleRelaxationRounds = relaxed.iterations;
    local.sampleRelaxationSeconds = secondsSince(start);
  }

  const std::vector<int> nearestLandmarks = nearestLandmarkOfTriangles(result.mesh, landmarkCount(result.mesh));
  result.models.assign(localModels.size(), RemeshedModel{});
  local.models.assign(localModels.size(), RemeshModelReport{});
  // Each model is placed on its own, the models shared out over threads;
  // the calling thread alone reports progress. The first model that fails,
  // in the order given, is reported.
  const int count = static_cast<int>(localModels.size());
  std::vector<Status> placed(localModels.size());
  forEachOnThreads(
    count, options.threads,
    [&](int m) {
      placed[m] = placeModel(domain, result.mesh, nearestLandmarks, localModels[m], options, result.models[m],
        local.models[m], far ? &(*far)[m] : nullptr);
    },
    [&](int m, const char* message) { placed[m] = Status::error(std::string("placing the remesh failed: ") + message); },
    [&](int done) {
      if (progress)
        progress(static_cast<double>(done) / count);
    });
  for (int m = 0; m < count; ++m)
    if (!placed[m].ok())
    {
      local.failedModel = m;
      return placed[m];
    }
  return {};
}

} // namespace

Status checkRemeshOptions(const RemeshOptions& options)
{
  if (!isRemeshLevel(options.level))
    return Status::error(remeshLevelProblem("Level", options.level));
  if (!(options.adaptiveTolerance >= 0.0) || !std::isfinite(options.adaptiveTolerance))
  {
    std::ostringstream message;
    message << "AdaptiveTolerance must be 0 (uniform) or a positive fraction of the bounding-box diagonal (it is "
            << options.adaptiveTolerance << ")";
    return Status::error(message.str());
  }
  if (options.sampleRelaxationIterations < 0)
    return Status::error("SampleRelaxationIterations must be 0 (none) or a positive number of rounds (it is " +
      std::to_string(options.sampleRelaxationIterations) + ")");
  return {};
}

Status remesh(const BaseDomain& domain, const std::vector<RemeshModel>& localModels, Communicator& communicator,
  CollectionRemesh& out, const RemeshOptions& options, RemeshReport* report)
{
  if (report)
    *report = RemeshReport{};
  RemeshReport local;
  local.models.resize(localModels.size());
  CollectionRemesh result;
  Status status = checkRemeshOptions(options);
  std::vector<const ParameterizedSurface*> surfaces;
  for (std::size_t m = 0; m < localModels.size() && status.ok(); ++m)
  {
    const RemeshModel& model = localModels[m];
    if (!model.surface || !model.map)
      status = Status::error("model " + std::to_string(m) + " is missing");
    else if (!model.map->built())
      status = Status::error("model " + std::to_string(m) + " is not parameterized (its map was not built)");
    else
      surfaces.push_back(model.map);
  }

  // One connectivity for the whole collection: with a tolerance, a
  // triangle is split when any model needs it. The split rule probes the
  // models' maps before the samples are relaxed, placed and repaired, which
  // moves them; so where the remesh as placed on some model is still
  // farther from it than the tolerance, the connectivity is made again with
  // the triangles there split once more.
  const bool adaptive = options.adaptiveTolerance > 0.0;
  // Over several processes the passes need sample relaxation, which makes
  // sure that every process has the same connectivity; the processes then
  // agree on each placement before they share the far triangles.
  const bool shared = communicator.size() > 1;
  const bool checked =
    adaptive && options.computeDistance && (!shared || options.sampleRelaxationIterations > 0);
  std::vector<RefineMark> marks;
  double lastProgress = 0.0;
  for (int pass = 1;; ++pass)
  {
    SemiRegularMesh connectivity;
    if (status.ok())
      status = !adaptive ? buildSemiRegularMesh(domain, options.level, connectivity)
        : buildAdaptiveSemiRegularMesh(domain, options.level,
            outsideHoles(refinedSplitRule(flatnessSplitRule(surfaces, options.adaptiveTolerance), marks),
              options.holeTriangles),
            connectivity);
    if (status.ok())
      status = removeHoleTriangles(domain, options.holeTriangles, connectivity);
    if (status.ok() && pass > 1 && connectivity.triangles.size() == result.mesh.triangles.size())
      break; // the far triangles are at the maximum level: the last pass stands
    const SemiRegularMesh built = checked ? connectivity : SemiRegularMesh{};
    // Progress runs once over all the passes there may be.
    const std::function<void(double)> progress = !options.progress ? std::function<void(double)>()
      : [&, pass](double fraction) {
          lastProgress = checked ? (pass - 1 + fraction) / kAdaptivePasses : fraction;
          options.progress(lastProgress);
        };
    CollectionRemesh attempt;
    attempt.mesh = std::move(connectivity);
    RemeshReport figures = local;
    // The last pass that may be followed by another marks far triangles.
    const bool mayRefine = checked && pass < kAdaptivePasses;
    std::vector<std::vector<char>> farOnModels;
    Status s = placeCollection(domain, localModels, surfaces, communicator, options, status, progress, attempt,
      figures, mayRefine ? &farOnModels : nullptr);
    if (checked && shared)
      s = agreeOnStatus(s, communicator);
    if (!s.ok())
    {
      if (pass > 1)
        break; // the last pass that succeeded stands
      if (report && figures.failedModel >= 0)
        *report = std::move(figures);
      return s;
    }
    result = std::move(attempt);
    local = std::move(figures);
    if (adaptive)
    {
      local.adaptivePasses = pass;
      local.adaptiveTriangles.push_back(static_cast<int>(result.mesh.triangles.size()));
    }
    if (!mayRefine)
      break;
    const std::vector<char> far = farTrianglesOverRanks(farOnModels, result.mesh.triangles.size(), communicator);
    if (std::find(far.begin(), far.end(), 1) == far.end())
      break;
    addRefineMarks(domain, built, far, marks);
  }
  if (options.progress && lastProgress < 1.0)
    options.progress(1.0);
  out = std::move(result);
  if (report)
    *report = std::move(local);
  return {};
}

Status remesh(const BaseDomain& domain, const std::vector<RemeshModel>& models, CollectionRemesh& out,
  const RemeshOptions& options, RemeshReport* report)
{
  SingleProcess alone;
  return remesh(domain, models, alone, out, options, report);
}

Status remesh(const TriangleMesh& surface, const TracedNet& net, const BaseDomain& domain,
  const PatchParameterization& parameterization, CollectionRemesh& out, const RemeshOptions& options,
  RemeshReport* report)
{
  ParameterizedSurface map;
  if (Status status = map.build(net, domain, parameterization); !status.ok())
    return status;
  return remesh(domain, { RemeshModel{ &surface, &map } }, out, options, report);
}

} // namespace cmp
