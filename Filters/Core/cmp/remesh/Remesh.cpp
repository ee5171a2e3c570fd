#include <cmp/remesh/Remesh.h>

#include <cmp/mesh/SurfaceDistance.h>
#include <cmp/mesh/TriangleShape.h>
#include <cmp/remesh/SampleRelaxation.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <thread>

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
/// off, remesh to input catches triangles spanning concave regions.
void measureDistance(
  const BaseDomain& domain, const RemeshModel& model, const TriangleMesh& placed, RemeshModelReport& figures)
{
  const Clock::time_point start = Clock::now();
  const SurfaceDistance distance = surfaceDistance(*model.surface, placed);
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

/// The shared connectivity on one model: placed, repaired, measured.
Status placeModel(const BaseDomain& domain, const SemiRegularMesh& mesh, const std::vector<int>& nearestLandmarks,
  const RemeshModel& model, const RemeshOptions& options, RemeshedModel& placed, RemeshModelReport& figures)
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
    foldsNearLandmarks(nearestLandmarks, static_cast<int>(domain.featureIds.size()), placed.folded);
  if (options.computeDistance)
    measureDistance(domain, model, inSpace, figures);
  figures.seconds = secondsSince(start);
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
  // triangle is split when any model needs it.
  if (status.ok())
    status = options.adaptiveTolerance > 0.0
      ? buildAdaptiveSemiRegularMesh(
          domain, options.level, flatnessSplitRule(surfaces, options.adaptiveTolerance), result.mesh)
      : buildSemiRegularMesh(domain, options.level, result.mesh);
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

  const std::vector<int> nearestLandmarks = nearestLandmarkOfTriangles(result.mesh, domain.mesh.vertexCount());
  result.models.resize(localModels.size());
  // Each model is placed on its own: a thread takes the next model not yet
  // taken, and the calling thread (the only one to report progress) works
  // too. The first model that fails, in the order given, is reported.
  const int count = static_cast<int>(localModels.size());
  const int threadCount = std::clamp(
    options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency()), 1,
    std::max(1, count));
  std::vector<Status> placed(localModels.size());
  std::atomic<int> next{ 0 };
  std::atomic<int> done{ 0 };
  int reported = 0; // models done when the calling thread last reported progress
  const auto work = [&](bool reportProgress) {
    for (int m = next++; m < count; m = next++)
    {
      try
      {
        placed[m] = placeModel(domain, result.mesh, nearestLandmarks, localModels[m], options, result.models[m],
          local.models[m]);
      }
      catch (const std::exception& error)
      {
        placed[m] = Status::error(std::string("placing the remesh failed: ") + error.what());
      }
      const int finished = ++done;
      if (reportProgress && options.progress && finished > reported)
      {
        reported = finished;
        options.progress(static_cast<double>(finished) / count);
      }
    }
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threadCount; ++t)
    helpers.emplace_back(work, false);
  work(true);
  for (std::thread& helper : helpers)
    helper.join();
  for (int m = 0; m < count; ++m)
  {
    if (!placed[m].ok())
    {
      if (report)
      {
        *report = std::move(local);
        report->failedModel = m;
      }
      return placed[m];
    }
  }
  if (options.progress && reported < count)
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
