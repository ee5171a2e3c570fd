#include <cmp/remesh/MissingLandmarks.h>

#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/EdgePaths.h>
#include <cmp/mesh/SurfaceDistance.h>
#include <cmp/numerics/Threads.h>
#include <cmp/remesh/Remesh.h>
#include <cmp/remesh/SemiRegularRemesher.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

namespace cmp
{
namespace
{

/// The geometric median of `points` weighted by `w` (Weiszfeld's iteration
/// from their weighted mean): one source whose map went astray moves it
/// little.
Vec3 geometricMedian(const std::vector<Vec3>& points, const std::vector<double>& w)
{
  Vec3 x = Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    x += w[i] * points[i];
    total += w[i];
  }
  x /= total;
  for (int iteration = 0; iteration < 50; ++iteration)
  {
    Vec3 sum = Vec3::Zero();
    double weights = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const Vec3& p = points[i];
      const double d = (p - x).norm();
      if (d < 1e-12)
        return p;
      sum += w[i] * p / d;
      weights += w[i] / d;
    }
    const Vec3 next = sum / weights;
    const bool settled = (next - x).norm() < 1e-9 * (1.0 + x.norm());
    x = next;
    if (settled)
      break;
  }
  return x;
}

/// How alike two placements of one remesh are: the RMS distance between
/// them after a similarity fit (both centred and scaled to unit RMS radius,
/// then the best rotation; Umeyama's method), 0 for the same shape.
double shapeDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  const Eigen::Index n = static_cast<Eigen::Index>(a.size());
  Eigen::Matrix3Xd A(3, n), B(3, n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    A.col(i) = a[i];
    B.col(i) = b[i];
  }
  A.colwise() -= A.rowwise().mean();
  B.colwise() -= B.rowwise().mean();
  const double sizeA = std::sqrt(A.squaredNorm() / n), sizeB = std::sqrt(B.squaredNorm() / n);
  if (!(sizeA > 0.0) || !(sizeB > 0.0))
    return 0.0;
  A /= sizeA;
  B /= sizeB;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(B * A.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d reflect = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0)
    reflect(2, 2) = -1.0;
  const Eigen::Matrix3d rotation = svd.matrixU() * reflect * svd.matrixV().transpose();
  return std::sqrt((rotation * A - B).squaredNorm() / n);
}

/// The vertex of `mesh` nearest to `p` that carries no feature
/// (`taken[v]`): a corner of the triangle `near` (the triangle of the
/// closest point) if one is free, else the nearest free vertex of all.
int nearestFreeVertex(const TriangleMesh& mesh, int near, const Vec3& p, const std::vector<char>& taken)
{
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  if (near >= 0)
    for (int v : mesh.triangles[near])
      if (!taken[v] && (mesh.points[v] - p).norm() < bestDistance)
      {
        best = v;
        bestDistance = (mesh.points[v] - p).norm();
      }
  if (best >= 0)
    return best;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (!taken[v] && (mesh.points[v] - p).norm() < bestDistance)
    {
      best = v;
      bestDistance = (mesh.points[v] - p).norm();
    }
  return best;
}

/// Climbs `height` from `from`: to the highest vertex within edge-path
/// distance `step` of the current one while that one is higher. Returns the
/// vertex where the climb stops (a peak at the scale of `step`), or -1 if
/// it would go farther than `reach` from `from`.
int climb(const EdgeGraph& graph, const std::vector<double>& height, int from, double step, double reach)
{
  // Only a finite reach needs the distances from the start.
  const std::vector<double> fromStart =
    std::isfinite(reach) ? edgePathDistances(graph, { from }, reach) : std::vector<double>{};
  int v = from;
  // The height rises at every move, so the climb ends.
  for (;;)
  {
    const std::vector<double> ball = edgePathDistances(graph, { v }, step);
    int best = v;
    for (std::size_t u = 0; u < ball.size(); ++u)
      if (std::isfinite(ball[u]) && height[u] > height[best])
        best = static_cast<int>(u);
    if (best == v)
      return v;
    if (!fromStart.empty() && !std::isfinite(fromStart[best]))
      return -1;
    v = best;
  }
}

/// Places the features `dropped` on the models of missing set `set`
/// (`setOf[m] == set`): every model that has the other features is mapped
/// over a base domain built from `source` without `dropped`, the
/// collection remeshed, and each dropped feature carried from the models
/// that have it, never onto a vertex of `onBoundary` (per model).
Status placeOneSet(const std::vector<const TriangleMesh*>& surfaces, const std::vector<LandmarkList>& landmarks,
  const std::vector<std::vector<char>>& onBoundary, const std::vector<char>& dropped, const std::vector<int>& setOf, int set, int source,
  const MissingLandmarkOptions& options, MissingLandmarkReport& out, const std::function<void(double)>& progress)
{
  const int modelCount = static_cast<int>(surfaces.size());
  const int featureCount = static_cast<int>(dropped.size());
  std::vector<int> keptFeatures;
  for (int f = 0; f < featureCount; ++f)
    if (!dropped[f])
      keptFeatures.push_back(f);
  // Targets, and the models that have every kept feature (the targets and
  // the sources).
  std::vector<int> members;
  for (int m = 0; m < modelCount; ++m)
  {
    bool hasKept = true;
    for (int f : keptFeatures)
      hasKept = hasKept && landmarks[m][f] != kMissingLandmark;
    if (hasKept)
      members.push_back(m);
  }
  auto reduced = [&](int m) {
    LandmarkList list;
    for (int f : keptFeatures)
      list.push_back(landmarks[m][f]);
    return list;
  };
  // With many models, only the sources likest to a target (by their kept
  // landmarks' shape) are mapped: the likest weigh most anyway.
  if (options.maximumSources > 0)
  {
    auto positions = [&](int m) {
      std::vector<Vec3> points;
      for (int f : keptFeatures)
        points.push_back(surfaces[m]->points[landmarks[m][f]]);
      return points;
    };
    std::vector<char> keep(modelCount, 0);
    for (int target : members)
    {
      if (setOf[target] != set)
        continue;
      keep[target] = 1;
      std::vector<std::pair<double, int>> ranked;
      for (int c : members)
        if (setOf[c] != set)
          ranked.emplace_back(shapeDistance(positions(c), positions(target)), c);
      std::sort(ranked.begin(), ranked.end());
      for (std::size_t k = 0; k < ranked.size() && k < static_cast<std::size_t>(options.maximumSources); ++k)
        keep[ranked[k].second] = 1;
    }
    std::vector<int> chosen;
    for (int m : members)
      if (keep[m])
        chosen.push_back(m);
    members = chosen;
  }
  BaseDomain openDomain, domain;
  BaseDomainHoles holes;
  if (Status s = buildBaseDomain(*surfaces[source], reduced(source), openDomain); !s.ok())
    return Status::error("the base domain without the missing features: " + s.message());
  // Surfaces with boundaries: every stage runs on them closed, as the
  // filters run them (the reduced L0 is open when the models are).
  if (Status s = closeBaseDomain(openDomain, domain, holes); !s.ok())
    return Status::error("the base domain without the missing features: " + s.message());
  StraightenOptions straightening = options.straighten;
  straightening.net.keptFeatures = holes.keptFeatures();
  straightening.map.fixedPatches = holes.holeTriangle;

  struct Mapped
  {
    TracedNet traced;
    StraightenedNet straight;
    PatchParameterization map;
    ParameterizedSurface surface;
  };
  // Each model is mapped on its own, the models shared out over threads;
  // the calling thread alone reports progress.
  const int count = static_cast<int>(members.size());
  std::vector<std::unique_ptr<Mapped>> mapped(members.size());
  std::vector<Status> statuses(members.size());
  forEachOnThreads(
    count, options.threads,
    [&](int i) {
      const int m = members[i];
      auto one = std::make_unique<Mapped>();
      statuses[i] = traceSurfaceWithBoundaries(*surfaces[m], reduced(m), holes, domain, one->traced);
      if (statuses[i].ok())
        statuses[i] = straighten(one->traced, domain, one->straight, one->map, straightening);
      if (statuses[i].ok())
        statuses[i] = one->surface.build(one->straight.net, domain, one->map);
      if (statuses[i].ok())
        mapped[i] = std::move(one);
    },
    [&](int i, const char* message) { statuses[i] = Status::error(std::string("mapping failed: ") + message); },
    [&](int done) { progress(0.9 * done / count); });
  std::vector<RemeshModel> remeshModels;
  std::vector<int> remeshed; // the model of each one remeshed
  for (int i = 0; i < count; ++i)
  {
    const int m = members[i];
    if (!statuses[i].ok())
    {
      if (setOf[m] == set || out.modelErrors[m].empty())
        out.modelErrors[m] = statuses[i].message();
      continue;
    }
    remeshModels.push_back({ surfaces[m], &mapped[i]->surface });
    remeshed.push_back(m);
  }
  bool anyTarget = false;
  for (int m : remeshed)
    anyTarget = anyTarget || setOf[m] == set;
  if (!anyTarget)
    return {}; // each target's error says why

  RemeshOptions remeshOptions;
  remeshOptions.level = options.level;
  remeshOptions.sampleRelaxationIterations = options.sampleRelaxationIterations;
  remeshOptions.computeDistance = false;
  remeshOptions.holeTriangles = holes.holeTriangle;
  CollectionRemesh collection;
  if (Status s = remesh(domain, remeshModels, collection, remeshOptions); !s.ok())
    return Status::error("the remesh without the missing features: " + s.message());
  progress(0.95);

  // Where each source's landmark lies on its remesh.
  const std::vector<Triangle>& triangles = collection.mesh.triangles;
  std::vector<std::unique_ptr<ClosestPointQuery>> onRemesh(remeshed.size());
  for (std::size_t i = 0; i < remeshed.size(); ++i)
  {
    TriangleMesh placedRemesh;
    placedRemesh.points = collection.models[i].positions;
    placedRemesh.triangles = triangles;
    onRemesh[i] = std::make_unique<ClosestPointQuery>(placedRemesh);
  }
  // How far from each source's landmark of each dropped feature the climb
  // of the edge-path distance from its kept landmarks stops (over the
  // square root of its area): near 0 where it sits at a peak.
  std::vector<std::vector<double>> fromPeak(
    remeshed.size(), std::vector<double>(featureCount, std::numeric_limits<double>::infinity()));
  auto heightOf = [&](int m, const EdgeGraph& graph) {
    std::vector<int> kept;
    for (int f : keptFeatures)
      kept.push_back(landmarks[m][f]);
    return edgePathDistances(graph, kept);
  };
  if (options.climbToTips)
    for (std::size_t i = 0; i < remeshed.size(); ++i)
    {
      const int c = remeshed[i];
      if (setOf[c] == set)
        continue;
      const EdgeGraph graph = edgeGraph(*surfaces[c]);
      const std::vector<double> height = heightOf(c, graph);
      const double scale = std::sqrt(std::max(surfaceArea(*surfaces[c]), 1e-300));
      const std::vector<Vec3>& points = surfaces[c]->points;
      for (int f = 0; f < featureCount; ++f)
        if (dropped[f] && landmarks[c][f] != kMissingLandmark)
        {
          const int from = landmarks[c][f];
          const int peak = climb(graph, height, from, options.tipRadius * scale, std::numeric_limits<double>::infinity());
          fromPeak[i][f] = (points[peak] - points[from]).norm() / scale;
        }
    }
  for (std::size_t target = 0; target < remeshed.size(); ++target)
  {
    const int m = remeshed[target];
    if (setOf[m] != set)
      continue;
    std::unique_ptr<EdgeGraph> graph;
    std::vector<double> height;
    // The sources whose remesh is most like the target's weigh most: their
    // maps are the likeliest to agree with the target's.
    std::vector<double> unlikeness(remeshed.size(), 0.0);
    if (options.similarityWidth > 0.0)
      for (std::size_t i = 0; i < remeshed.size(); ++i)
        unlikeness[i] = shapeDistance(collection.models[i].positions, collection.models[target].positions) /
          options.similarityWidth;
    const TriangleMesh& surface = *surfaces[m];
    const ClosestPointQuery onSurface(surface);
    const double scale = std::sqrt(std::max(surfaceArea(surface), 1e-300));
    // An inner feature never goes on the boundary, whose landmarks are L0's.
    std::vector<char> taken = onBoundary[m];
    for (int v : landmarks[m])
      if (v != kMissingLandmark)
        taken[v] = 1;
    for (int f = 0; f < featureCount; ++f)
    {
      if (!dropped[f])
        continue;
      std::vector<Vec3> carried;
      std::vector<double> weight;
      std::vector<double> peakDistances;
      for (std::size_t i = 0; i < remeshed.size(); ++i)
      {
        const int c = remeshed[i];
        if (landmarks[c][f] == kMissingLandmark)
          continue;
        const ClosestPointQuery::Result at = onRemesh[i]->closest(surfaces[c]->points[landmarks[c][f]]);
        // The query's vertices are its triangle's corners: the same corners
        // and weights on the target's remesh.
        const std::vector<Vec3>& positions = collection.models[target].positions;
        Vec3 p = Vec3::Zero();
        for (int k = 0; k < 3; ++k)
          if (at.at.vertex[k] >= 0)
            p += at.at.weight[k] * positions[at.at.vertex[k]];
        if (at.at.triangle >= 0)
        {
          carried.push_back(p);
          weight.push_back(unlikeness[i]);
          peakDistances.push_back(fromPeak[i][f]);
        }
      }
      if (carried.empty())
        continue; // every model that has it failed: it stays missing
      // exp(-r^2) relative to the likest source's, which weighs 1.
      const double likest = *std::min_element(weight.begin(), weight.end());
      for (double& w : weight)
        w = std::exp(likest * likest - w * w);
      const ClosestPointQuery::Result onto = onSurface.closest(geometricMedian(carried, weight));
      int vertex = nearestFreeVertex(surface, onto.at.triangle, onto.point, taken);
      if (vertex < 0)
        continue;
      // A feature that most sources have at a peak (a tip) goes to the peak
      // the target's vertex climbs to, if it is near and the vertex is
      // farther from it than the sources' landmarks typically are from
      // theirs (hand-placed landmarks sit a little off the peak).
      const int mappedVertex = vertex;
      double climbed = 0.0;
      std::nth_element(peakDistances.begin(), peakDistances.begin() + peakDistances.size() / 2, peakDistances.end());
      const double offPeak = peakDistances[peakDistances.size() / 2];
      if (options.climbToTips && offPeak <= options.tipTolerance)
      {
        if (!graph)
        {
          graph = std::make_unique<EdgeGraph>(edgeGraph(surface));
          height = heightOf(m, *graph);
        }
        const int tip = climb(*graph, height, vertex, options.tipRadius * scale, options.tipReach * scale);
        const double toTip = tip >= 0 ? (surface.points[tip] - surface.points[vertex]).norm() / scale : 0.0;
        if (tip >= 0 && !taken[tip] && toTip > offPeak)
        {
          climbed = toTip;
          vertex = tip;
        }
      }
      taken[vertex] = 1;
      std::vector<double> distances;
      for (const Vec3& p : carried)
        distances.push_back((p - surface.points[vertex]).norm() / scale);
      std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
      PlacedLandmark placed;
      placed.model = m;
      placed.feature = f;
      placed.vertex = vertex;
      placed.mappedVertex = mappedVertex;
      placed.position = surface.points[vertex];
      placed.sources = static_cast<int>(carried.size());
      placed.spread = distances[distances.size() / 2];
      placed.climbed = climbed;
      out.placed.push_back(placed);
    }
  }
  return {};
}

/// The distortion of `surface`'s map over the closed L0 `domain` (`holes`
/// its) with `list` as its landmarks (`GlobalMapReport::distortionAfter`):
/// infinite where it cannot be traced or mapped, NaN where the curves were
/// not freed (no whole-surface map to judge by).
double mapDistortion(const TriangleMesh& surface, const LandmarkList& list, const BaseDomain& domain,
  const BaseDomainHoles& holes, const StraightenOptions& straightening)
{
  TracedNet traced;
  if (!traceSurfaceWithBoundaries(surface, list, holes, domain, traced).ok())
    return std::numeric_limits<double>::infinity();
  StraightenedNet straight;
  PatchParameterization map;
  StraightenReport report;
  if (!straighten(traced, domain, straight, map, straightening, &report).ok())
    return std::numeric_limits<double>::infinity();
  if (!report.freeCurves.applied)
    return std::numeric_limits<double>::quiet_NaN();
  return report.freeCurves.map.distortionAfter;
}

/// `MissingLandmarkOptions::domain`: every placed feature that climbed is
/// judged by its model's map over the L0 the collection will be mapped
/// over, with the feature at the tip and at the vertex the maps gave (the
/// model's other placed features where they are); the climb is undone where
/// its map is more than `unsettledRatio` times as distorted (infinite: it
/// could not be made), and kept where neither can be judged.
void judgeClimbs(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const BaseDomain& domain, const BaseDomainHoles& holes, const MissingLandmarkOptions& options,
  std::vector<PlacedLandmark>& placed, const std::function<void(double)>& progress)
{
  StraightenOptions straightening = options.straighten;
  straightening.net.keptFeatures = holes.keptFeatures();
  straightening.map.fixedPatches = holes.holeTriangle;
  // Jobs: (model, placed index or -1 for the landmarks as placed).
  std::vector<std::pair<int, int>> jobs;
  std::vector<int> tipJob(placed.size(), -1), mappedJob(placed.size(), -1);
  std::vector<int> asPlaced(surfaces.size(), -1);
  for (std::size_t i = 0; i < placed.size(); ++i)
  {
    const PlacedLandmark& p = placed[i];
    const LandmarkList& list = landmarks[p.model];
    if (p.climbed <= 0.0 || p.mappedVertex < 0 || p.mappedVertex == p.vertex ||
      std::find(list.begin(), list.end(), p.mappedVertex) != list.end())
      continue;
    if (asPlaced[p.model] < 0)
    {
      asPlaced[p.model] = static_cast<int>(jobs.size());
      jobs.emplace_back(p.model, -1);
    }
    tipJob[i] = asPlaced[p.model];
    mappedJob[i] = static_cast<int>(jobs.size());
    jobs.emplace_back(p.model, static_cast<int>(i));
  }
  if (jobs.empty())
    return;
  std::vector<double> distortion(jobs.size(), std::numeric_limits<double>::infinity());
  forEachOnThreads(
    static_cast<int>(jobs.size()), options.threads,
    [&](int j) {
      const auto [m, i] = jobs[j];
      LandmarkList list = landmarks[m];
      if (i >= 0)
        list[placed[i].feature] = placed[i].mappedVertex;
      distortion[j] = mapDistortion(*surfaces[m], list, domain, holes, straightening);
    },
    [&](int j, const char*) { distortion[j] = std::numeric_limits<double>::infinity(); },
    [&](int done) { progress(static_cast<double>(done) / jobs.size()); });
  for (std::size_t i = 0; i < placed.size(); ++i)
  {
    if (tipJob[i] < 0)
      continue;
    PlacedLandmark& p = placed[i];
    p.tipDistortion = distortion[tipJob[i]];
    p.mappedDistortion = distortion[mappedJob[i]];
    // NaN (not judged) compares false: the tip stays.
    if (options.unsettledRatio * p.mappedDistortion < p.tipDistortion)
    {
      p.climbUndone = true;
      p.climbed = 0.0;
      p.vertex = p.mappedVertex;
      p.position = surfaces[p.model]->points[p.vertex];
      landmarks[p.model][p.feature] = p.vertex;
    }
  }
}

} // namespace

Status placeMissingLandmarks(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const MissingLandmarkOptions& options, MissingLandmarkReport* report)
{
  const auto start = std::chrono::steady_clock::now();
  MissingLandmarkReport local;
  MissingLandmarkReport& out = report ? *report : local;
  out = MissingLandmarkReport();
  const int modelCount = static_cast<int>(surfaces.size());
  out.modelErrors.assign(modelCount, std::string());
  if (static_cast<int>(landmarks.size()) != modelCount)
    return Status::error(std::to_string(surfaces.size()) + " surfaces but " + std::to_string(landmarks.size()) +
      " landmark lists");
  if (options.level < 1 || options.level > kMaximumRemeshLevel)
    return Status::error("level " + std::to_string(options.level) + " is out of range (1 to " +
      std::to_string(kMaximumRemeshLevel) + ")");
  if (options.sampleRelaxationIterations < 0)
    return Status::error("sample relaxation rounds must not be negative");
  if (!std::isfinite(options.similarityWidth) || options.similarityWidth < 0.0)
    return Status::error("the similarity width must be 0 or positive");
  if (options.maximumSources < 0)
    return Status::error("the most sources must be 0 (every model) or positive");
  if (!(options.tipRadius > 0.0) || !(options.tipReach > 0.0) || !std::isfinite(options.tipRadius) ||
    !std::isfinite(options.tipReach) || !(options.tipTolerance >= 0.0) || !std::isfinite(options.tipTolerance))
    return Status::error("the tip radius and reach must be positive, the tip tolerance 0 or positive");
  if (!(options.unsettledRatio >= 1.0) || !std::isfinite(options.unsettledRatio))
    return Status::error("the unsettled ratio must be at least 1");
  if (modelCount == 0)
    return {};
  const int featureCount = static_cast<int>(landmarks[0].size());
  BaseDomain closedDomain;
  BaseDomainHoles domainHoles;
  if (options.domain)
  {
    if (Status s = closeBaseDomain(*options.domain, closedDomain, domainHoles); !s.ok())
      return Status::error("the base domain the climbs are judged over: " + s.message());
    if (domainHoles.openVertexCount != featureCount)
      return Status::error("the base domain the climbs are judged over has " +
        std::to_string(domainHoles.openVertexCount) + " vertices but the models " + std::to_string(featureCount) +
        " features");
  }
  for (int m = 0; m < modelCount; ++m)
  {
    if (!surfaces[m])
      return Status::error("model " + std::to_string(m) + " has no surface");
    if (static_cast<int>(landmarks[m].size()) != featureCount)
      return Status::error("model " + std::to_string(m) + " has " + std::to_string(landmarks[m].size()) +
        " features but model 0 has " + std::to_string(featureCount));
    if (Status s = validateLandmarks(landmarks[m], surfaces[m]->vertexCount(), -1, true); !s.ok())
      return Status::error("model " + std::to_string(m) + ": " + s.message());
  }

  // The features to place, and the models that have all the others.
  std::vector<char> missing(featureCount, 0);
  std::vector<int> sourcesOf(featureCount, 0);
  for (const LandmarkList& list : landmarks)
    for (int f = 0; f < featureCount; ++f)
    {
      if (list[f] == kMissingLandmark)
        missing[f] = 1;
      else
        ++sourcesOf[f];
    }
  for (int f = 0; f < featureCount; ++f)
    if (missing[f])
      out.missingFeatures.push_back(f);
  if (out.missingFeatures.empty())
    return {};
  for (int f : out.missingFeatures)
    if (sourcesOf[f] == 0)
      return Status::error("feature " + std::to_string(f) + " is missing on every model: nothing to place it from");
  // A boundary landmark marks where a surface was cut open: no map carries
  // it (the contract of surfaces with boundaries).
  std::vector<std::vector<char>> onBoundary(modelCount);
  for (int m = 0; m < modelCount; ++m)
  {
    if (Status s = boundaryVertices(*surfaces[m], onBoundary[m]); !s.ok())
      return Status::error("model " + std::to_string(m) + ": " + s.message());
    for (int f : out.missingFeatures)
      if (landmarks[m][f] != kMissingLandmark && onBoundary[m][landmarks[m][f]])
        return Status::error("feature " + std::to_string(f) + " lies on model " + std::to_string(m) +
          "'s boundary: a boundary landmark cannot be placed, only a feature inside the surfaces");
  }
  int source = options.baseDomainModel;
  if (source >= modelCount)
    return Status::error("the base domain's model " + std::to_string(source) + " is not in the collection");
  if (source < 0)
    for (int m = 0; m < modelCount && source < 0; ++m)
      if (missingLandmarkCount(landmarks[m]) == 0)
        source = m;
  if (source < 0)
    return Status::error("no model has every feature: the reduced base domain is built from one that does");
  if (missingLandmarkCount(landmarks[source]) > 0)
    return Status::error("model " + std::to_string(source) +
      ", which should give the base domain, misses features; a base domain is built from a model with every one");
  // The models that miss the same features are placed together, over a base
  // domain without just those: dropping every feature missing anywhere from
  // every model would leave the maps fewer landmarks than each model has.
  std::vector<std::vector<char>> missingSets;
  std::vector<int> setOf(modelCount, -1);
  for (int m = 0; m < modelCount; ++m)
  {
    if (missingLandmarkCount(landmarks[m]) == 0)
      continue;
    std::vector<char> set(featureCount, 0);
    for (int f = 0; f < featureCount; ++f)
      set[f] = landmarks[m][f] == kMissingLandmark;
    const auto found = std::find(missingSets.begin(), missingSets.end(), set);
    setOf[m] = static_cast<int>(found - missingSets.begin());
    if (found == missingSets.end())
      missingSets.push_back(set);
  }
  for (const std::vector<char>& set : missingSets)
  {
    const int kept = featureCount - static_cast<int>(std::count(set.begin(), set.end(), 1));
    if (kept < 4)
      return Status::error("a model has only " + std::to_string(kept) +
        " features; placing the missing ones needs a base domain of at least 4");
  }
  out.baseDomainModel = source;
  auto progress = [&](double fraction) {
    if (options.progress)
      options.progress(fraction);
  };
  // Sources are the landmarks as given: a placed feature is no source.
  const std::vector<LandmarkList> given = landmarks;
  // With climbs to judge, the last tenth of the progress is theirs.
  const double placing = options.domain ? 0.9 : 1.0;
  for (std::size_t set = 0; set < missingSets.size(); ++set)
  {
    const std::vector<char>& dropped = missingSets[set];
    const double done = placing * set / missingSets.size();
    const double share = placing / missingSets.size();
    if (Status s = placeOneSet(surfaces, given, onBoundary, dropped, setOf, static_cast<int>(set), source, options, out,
          [&](double fraction) { progress(done + share * fraction); });
        !s.ok())
      return s;
  }
  std::sort(out.placed.begin(), out.placed.end(), [](const PlacedLandmark& a, const PlacedLandmark& b) {
    return a.model != b.model ? a.model < b.model : a.feature < b.feature;
  });
  for (const PlacedLandmark& placed : out.placed)
    landmarks[placed.model][placed.feature] = placed.vertex;
  if (options.domain)
    judgeClimbs(surfaces, landmarks, closedDomain, domainHoles, options, out.placed,
      [&](double fraction) { progress(placing + (1.0 - placing) * fraction); });
  progress(1.0);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {};
}

} // namespace cmp
