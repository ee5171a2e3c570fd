#include "BenchmarkStages.h"

#include <cmp/analysis/LoopWavelet.h>
#include <cmp/map/Straighten.h>
#include <cmp/numerics/CotanLaplacian.h>
#include <cmp/remesh/Remesh.h>
#include <cmp/remesh/SampleRelaxation.h>
#include <cmp/mesh/Subdivision.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

namespace cmp::bench
{
namespace
{

/// \brief `read`: parse the file and weld coincident points, as every
///        consumer of a file does before anything else.
Status readStage(ModelContext& ctx)
{
  ctx.file = MeshFileData{};
  const Status status = fileExtension(ctx.spec.meshPath) == "obj" ? readOBJ(ctx.spec.meshPath, ctx.file)
                                                                   : readOFF(ctx.spec.meshPath, ctx.file);
  if (status.ok())
    weldIdenticalPoints(ctx.file);
  return status;
}

/// \brief `subdivide`: refine the file mesh for the large model. Original
///        vertices keep their ids, so the model's landmark file still applies.
Status subdivideStage(ModelContext& ctx)
{
  ctx.subdivided = TriangleMesh{};
  ctx.subdivided = subdivideMidpoint(ctx.file.mesh, ctx.spec.subdivisionLevels);
  return {};
}

/// \brief `check`: the input check every stage of the pipeline runs first.
Status checkStage(ModelContext& ctx)
{
  ctx.surfaceCheck = checkSurface(ctx.surface());
  if (!ctx.surfaceCheck.ok())
    return Status::error("surface check: " + ctx.surfaceCheck.message);
  return {};
}

/// \brief `landmarks`: read the landmark file and map it to welded vertex ids.
Status landmarksStage(ModelContext& ctx)
{
  ctx.landmarks.clear();
  return readLandmarkFile(ctx.spec.landmarkPath, ctx.surface(), ctx.file.fileToMeshPoint, ctx.landmarks);
}

/// \brief `base_domain`: decimate the surface down to its landmarks (L0).
Status baseDomainStage(ModelContext& ctx)
{
  ctx.domain = BaseDomain{};
  ctx.domainReport = BaseDomainBuilderReport{};
  return buildBaseDomain(ctx.surface(), ctx.landmarks, ctx.domain, {}, &ctx.domainReport);
}

/// \brief `trace`: trace the feature net against the shared L0 (the issue's
///        figures are "with L0 from model 381"), or against the model's own
///        L0 when there is no shared one. Landmark ids stay valid on the
///        subdivided surface because subdivision keeps original vertex ids.
Status traceStage(ModelContext& ctx)
{
  ctx.net = TracedNet{};
  ctx.netReport = NetTracerReport{};
  const Status status = traceFeatureNet(ctx.surface(), ctx.landmarks, ctx.traceDomain(), ctx.net, {}, &ctx.netReport);
  if (!status.ok())
    return status;
  // Dividing by sqrt(area) makes the length independent of the model's
  // scale, so models (and the published 15.9-36.9 range) compare directly.
  setFigure(ctx.figures, "net_length_per_sqrt_area", ctx.netReport.netLength / std::sqrt(surfaceArea(ctx.surface())));
  setFigure(ctx.figures, "retraced", ctx.netReport.retraced);
  setFigure(ctx.figures, "penalised", ctx.netReport.penalised);
  setFigure(ctx.figures, "split_edges", ctx.netReport.splitEdges);
  return status;
}

/// \brief `straighten`, `parameterize` and `map`: the map stage as the Net
///        Straightener runs it by default (`straighten()`: edge
///        straightening, the per-patch maps, then the curves freed by the
///        whole-surface map), one column per part.
Status straightenStage(ModelContext& ctx)
{
  ctx.straight = StraightenedNet{};
  ctx.parameterization = PatchParameterization{};
  ctx.straightReport = StraightenReport{};
  const Status status = straighten(ctx.net, ctx.traceDomain(), ctx.straight, ctx.parameterization, {}, &ctx.straightReport);
  if (!status.ok())
    return status;
  const StraightenReport& report = ctx.straightReport;
  ctx.partSeconds = { report.straightenSeconds, report.parameterizeSeconds, report.mapSeconds };
  const double root = std::sqrt(surfaceArea(ctx.surface()));
  setFigure(ctx.figures, "straight_length_per_sqrt_area", report.net.netLengthAfter / root);
  setFigure(ctx.figures, "area_variation_traced", report.net.areaVariationBefore);
  setFigure(ctx.figures, "area_variation_straight", report.net.areaVariationAfter);
  setFigure(ctx.figures, "sweeps", report.net.sweeps);
  setFigure(ctx.figures, "flipped_triangles", ctx.parameterization.flippedTriangles);
  setFigure(ctx.figures, "smallest_area_ratio", ctx.parameterization.smallestAreaRatio);
  setFigure(ctx.figures, "map_applied", report.freeCurves.applied ? 1.0 : 0.0);
  setFigure(ctx.figures, "map_distortion_before", report.freeCurves.map.distortionBefore);
  setFigure(ctx.figures, "map_distortion_after", report.freeCurves.map.distortionAfter);
  setFigure(ctx.figures, "map_iterations", report.freeCurves.map.iterations);
  return status;
}

/// \brief `yardstick`: the reference for the pipeline's speed, one
///        sparse Cholesky factorization (Eigen `SimplicialLDLT`) of the
///        model's cotan Laplacian plus 21 solves. A measurement, not in the
///        total; yardstick_seconds is the factorization and the solves alone
///        (the fastest run), without building the matrix. The Laplacian is
///        shifted by 1e-8 of its mean diagonal so that it is definite.
Status yardstickStage(ModelContext& ctx)
{
  using Clock = std::chrono::steady_clock;
  Eigen::SparseMatrix<double> laplacian = cotanLaplacian(ctx.surface());
  const Eigen::Index n = laplacian.rows();
  const double shift = 1e-8 * laplacian.diagonal().sum() / static_cast<double>(std::max<Eigen::Index>(1, n));
  for (Eigen::Index v = 0; v < n; ++v)
    laplacian.coeffRef(v, v) += shift;
  constexpr int solves = 21;
  Eigen::MatrixXd right(n, solves);
  for (Eigen::Index v = 0; v < n; ++v)
    for (int k = 0; k < solves; ++k)
      right(v, k) = std::sin(0.37 * static_cast<double>(v) + 1.3 * k);
  Eigen::VectorXd solution;
  const Clock::time_point start = Clock::now();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factorization(laplacian);
  if (factorization.info() != Eigen::Success)
    return Status::error("the cotan Laplacian's LDLT factorization failed");
  double check = 0.0;
  for (int k = 0; k < solves; ++k)
  {
    solution = factorization.solve(right.col(k));
    check += solution(0);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!std::isfinite(check))
    return Status::error("the cotan Laplacian's solves are not finite");
  double best = seconds;
  for (const Figure& figure : ctx.figures)
    if (figure.name == "yardstick_seconds" && figure.value > 0.0)
      best = std::min(best, figure.value);
  setFigure(ctx.figures, "yardstick_seconds", best);
  return {};
}

bool isSubdivided(const ModelSpec& spec)
{
  return spec.subdivisionLevels > 0;
}

bool isNotSubdivided(const ModelSpec& spec)
{
  return !isSubdivided(spec);
}

/// \brief The level `remesh` times, after the targets: level 5 on a
///        SHREC model (< 0.3 s), level 6 on the large surface (< 5 s).
int remeshLevel(const ModelSpec& spec)
{
  return isSubdivided(spec) ? 6 : 5;
}

/// \brief The remesh stage's options for the measurements below: `level`,
///        with or without the fold repair and the distance, no relaxation.
RemeshOptions remeshOptions(int level, bool repairFolds, bool computeDistance)
{
  RemeshOptions options;
  options.level = level;
  options.repairFolds = repairFolds;
  options.computeDistance = computeDistance;
  return options;
}

/// \brief The remesh stage (`remesh()`) on the model's surface, laid out by
///        `net` and mapped by `parameterization`; its figures in `figures`.
Status remeshAt(const ModelContext& ctx, const TracedNet& net, const PatchParameterization& parameterization,
  const RemeshOptions& options, CollectionRemesh& out, RemeshModelReport& figures, RemeshReport* report = nullptr)
{
  RemeshReport local;
  const Status status = remesh(ctx.surface(), net, ctx.traceDomain(), parameterization, out, options, &local);
  if (status.ok())
    figures = local.models.front();
  if (report)
    *report = std::move(local);
  return status;
}

/// \brief `remesh`: the semi-regular remesh at `remeshLevel()`, folds
///        repaired as the filter does by default (timed on its own too).
Status remeshStage(ModelContext& ctx)
{
  ctx.remesh = SemiRegularMesh{};
  ctx.remeshSamples = std::vector<SurfacePoint>();
  ctx.remeshPoints = std::vector<Vec3>();
  const int level = remeshLevel(ctx.spec);
  CollectionRemesh result;
  RemeshModelReport figures;
  if (Status status = remeshAt(ctx, ctx.straight.net, ctx.parameterization,
        remeshOptions(level, /*repairFolds=*/true, /*computeDistance=*/false), result, figures);
      !status.ok())
    return status;
  ctx.remesh = std::move(result.mesh);
  ctx.remeshSamples = std::move(result.models.front().samples);
  ctx.remeshPoints = std::move(result.models.front().positions);
  setFigure(ctx.figures, "fold_repair_seconds", figures.foldRepairSeconds);
  setFigure(ctx.figures, "remesh_level", level);
  setFigure(ctx.figures, "remesh_triangles", static_cast<double>(ctx.remesh.triangles.size()));
  setFigure(ctx.figures, "remesh_folded_before_repair", figures.repair.foldedBefore);
  setFigure(ctx.figures, "remesh_folded_after_repair", figures.repair.foldedAfter);
  return {};
}

/// \brief `remesh_distance`: how closely the remeshes of levels 3 to 6
///        follow the surface, as the two-sided Hausdorff distance over the
///        surface's bounding-box diagonal. A measurement, not a pipeline
///        step: it builds its own remeshes (so the stage's time includes
///        them), and each distance computation is also timed on its own.
Status remeshDistanceStage(ModelContext& ctx)
{
  for (int level = 3; level <= 6; ++level)
  {
    CollectionRemesh result;
    RemeshModelReport figures;
    if (Status status = remeshAt(ctx, ctx.straight.net, ctx.parameterization,
          remeshOptions(level, /*repairFolds=*/false, /*computeDistance=*/true), result, figures);
        !status.ok())
      return Status::error("level " + std::to_string(level) + ": " + status.message());
    const std::string suffix = "_l" + std::to_string(level);
    setFigure(ctx.figures, "hausdorff_per_diagonal" + suffix, figures.hausdorffDistanceRelative);
    setFigure(ctx.figures, "distance_seconds" + suffix, figures.distanceSeconds);
  }
  return {};
}

/// \brief `lower_stretch`: straightening and the parameterization again
///        with `PatchParameterizationOptions::lowerStretch` and the curves
///        kept (Net Straightener's LowerStretch, FreeCurves off). A measurement, not a pipeline step: the stage's
///        time includes a level-5 remesh with its distance and one with its
///        fold repair on the SHREC models; lower_stretch_seconds is the
///        parameterization alone.
Status lowerStretchStage(ModelContext& ctx)
{
  StraightenOptions options;
  options.patches.lowerStretch = true;
  options.freeCurves = false;
  StraightenedNet straight;
  PatchParameterization lowered;
  StraightenReport report;
  if (Status status = straighten(ctx.net, ctx.traceDomain(), straight, lowered, options, &report); !status.ok())
    return status;
  setFigure(ctx.figures, "lower_stretch_seconds", report.parameterizeSeconds);
  setFigure(ctx.figures, "lower_stretch_flipped_triangles", lowered.flippedTriangles);
  setFigure(ctx.figures, "lower_stretch_smallest_area_ratio", lowered.smallestAreaRatio);
  if (isSubdivided(ctx.spec))
    return {};
  constexpr int level = 5;
  // The distance as placed (comparable with remesh_distance's), then its
  // price in folds, before and after the default fold repair.
  CollectionRemesh result;
  RemeshModelReport placed, repaired;
  if (Status status = remeshAt(ctx, straight.net, lowered,
        remeshOptions(level, /*repairFolds=*/false, /*computeDistance=*/true), result, placed);
      !status.ok())
    return status;
  setFigure(ctx.figures, "lower_stretch_hausdorff_per_diagonal_l5", placed.hausdorffDistanceRelative);
  if (Status status = remeshAt(ctx, straight.net, lowered,
        remeshOptions(level, /*repairFolds=*/true, /*computeDistance=*/false), result, repaired);
      !status.ok())
    return status;
  setFigure(ctx.figures, "lower_stretch_folded_before_repair_l5", repaired.repair.foldedBefore);
  setFigure(ctx.figures, "lower_stretch_folded_after_repair_l5", repaired.repair.foldedAfter);
  return {};
}

/// \brief `free_curves`: the map stage again with LowerStretch
///        (`straighten()` with `lowerStretch`: the patches parameterized
///        with it, then the whole-surface map and the cut along it), then a level-5 remesh with its
///        distance and folds. A measurement, not a pipeline step; not on the
///        subdivided surface. free_curves_seconds is the map (`freeCurves()`) alone.
Status freeCurvesStage(ModelContext& ctx)
{
  StraightenOptions options;
  options.patches.lowerStretch = true;
  StraightenedNet moved;
  PatchParameterization map;
  StraightenReport report;
  if (Status status = straighten(ctx.net, ctx.traceDomain(), moved, map, options, &report); !status.ok())
    return status;
  setFigure(ctx.figures, "free_curves_seconds", report.mapSeconds);
  setFigure(ctx.figures, "free_curves_applied", report.freeCurves.applied ? 1.0 : 0.0);
  setFigure(ctx.figures, "free_curves_map_distortion_before", report.freeCurves.map.distortionBefore);
  setFigure(ctx.figures, "free_curves_map_distortion_after", report.freeCurves.map.distortionAfter);
  constexpr int level = 5;
  CollectionRemesh result;
  RemeshModelReport figures;
  if (Status status = remeshAt(
        ctx, moved.net, map, remeshOptions(level, /*repairFolds=*/true, /*computeDistance=*/true), result, figures);
      !status.ok())
    return status;
  setFigure(ctx.figures, "free_curves_hausdorff_per_diagonal_l5", figures.hausdorffDistanceRelative);
  setFigure(ctx.figures, "free_curves_folded_after_repair_l5", figures.repair.foldedAfter);
  return {};
}

/// \brief `sample_relaxation`: the Semi-Regular Remesher's sample
///        relaxation (4 rounds, the model alone) on the remesh of
///        `remeshLevel()`. A measurement: the stage's time includes indexing
///        the parameterization, the remesh, its placement and, on the SHREC
///        models, the remesh's distance; sample_relaxation_seconds is the
///        relaxation alone.
Status sampleRelaxationStage(ModelContext& ctx)
{
  const int level = remeshLevel(ctx.spec);
  RemeshOptions options = remeshOptions(level, /*repairFolds=*/false, /*computeDistance=*/!isSubdivided(ctx.spec));
  options.sampleRelaxationIterations = SampleRelaxationOptions{}.iterations;
  CollectionRemesh result;
  RemeshModelReport figures;
  RemeshReport report;
  if (Status status = remeshAt(ctx, ctx.straight.net, ctx.parameterization, options, result, figures, &report);
      !status.ok())
    return status;
  setFigure(ctx.figures, "sample_relaxation_seconds", report.sampleRelaxationSeconds);
  if (isSubdivided(ctx.spec))
    return {};
  setFigure(ctx.figures, "sample_relaxation_hausdorff_per_diagonal_l" + std::to_string(level),
    figures.hausdorffDistanceRelative);
  return {};
}

/// \brief `wavelet`: one Loop wavelet analysis plus synthesis (local
///        frames, as detail transfer uses them) of the model's level-6
///        remesh. A measurement: it builds that remesh itself unless the
///        `remesh` stage already did (the large model), so the stage's time
///        includes it; `wavelet_seconds` is the analysis plus synthesis
///        alone (best of three), `wavelet_build_seconds` the transform's
///        set-up, `wavelet_error` the largest reconstruction error over the
///        bounding-box diagonal.
Status waveletStage(ModelContext& ctx)
{
  using Clock = std::chrono::steady_clock;
  constexpr int level = 6;
  CollectionRemesh result;
  RemeshModelReport figures;
  const bool reuse = ctx.remesh.level == level && !ctx.remeshPoints.empty();
  if (!reuse)
  {
    if (Status status = remeshAt(ctx, ctx.straight.net, ctx.parameterization,
          remeshOptions(level, /*repairFolds=*/false, /*computeDistance=*/false), result, figures);
        !status.ok())
      return status;
  }
  const SemiRegularMesh& mesh = reuse ? ctx.remesh : result.mesh;
  const std::vector<Vec3>& positions = reuse ? ctx.remeshPoints : result.models.front().positions;
  Eigen::MatrixXd values(positions.size(), 3);
  for (std::size_t v = 0; v < positions.size(); ++v)
    values.row(static_cast<Eigen::Index>(v)) = positions[v].transpose();

  Clock::time_point start = Clock::now();
  LoopWaveletTransform transform;
  if (Status status = transform.build(mesh); !status.ok())
    return status;
  setFigure(ctx.figures, "wavelet_build_seconds", std::chrono::duration<double>(Clock::now() - start).count());
  double best = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd rebuilt;
  for (int run = 0; run < 3; ++run)
  {
    start = Clock::now();
    WaveletCoefficients coefficients;
    Status status = transform.analyze(values, DetailFrame::Local, coefficients);
    if (status.ok())
      status = transform.synthesize(coefficients, rebuilt);
    if (!status.ok())
      return status;
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  setFigure(ctx.figures, "wavelet_level", level);
  setFigure(ctx.figures, "wavelet_seconds", best);
  setFigure(ctx.figures, "wavelet_error", (rebuilt - values).cwiseAbs().maxCoeff() / boundingBoxDiagonal(ctx.surface()));
  return {};
}

} // namespace

const std::vector<Stage>& pipelineStages()
{
  // Pipeline order. A later stage appends one line here, e.g.
  //   { "pca", pcaStage, {} },
  static const std::vector<Stage> stages = {
    { "read", readStage, {} },
    { "subdivide", subdivideStage, isSubdivided },
    { "check", checkStage, {} },
    { "landmarks", landmarksStage, {} },
    { "base_domain", baseDomainStage, {} },
    { "trace", traceStage, {} },
    { "straighten", straightenStage, {}, true, { "straighten", "parameterize", "map" } },
    { "remesh", remeshStage, {} },
    // The speed reference, per model: the pipeline's total over it.
    { "yardstick", yardstickStage, {}, false },
    // Not on the large surface: sampling its million triangles at four
    // levels would dwarf the pipeline, and the issue asks only for the
    // level-6 remesh time there.
    { "remesh_distance", remeshDistanceStage, isNotSubdivided, false },
    { "lower_stretch", lowerStretchStage, {}, false },
    { "free_curves", freeCurvesStage, isNotSubdivided, false },
    { "sample_relaxation", sampleRelaxationStage, {}, false },
    { "wavelet", waveletStage, {}, false },
  };
  return stages;
}

std::vector<std::string> stageColumns(const Stage& stage)
{
  return stage.parts.empty() ? std::vector<std::string>{ stage.name } : stage.parts;
}

bool stageApplies(const Stage& stage, const ModelSpec& spec)
{
  return !stage.appliesTo || stage.appliesTo(spec);
}

void setFigure(FigureList& figures, const std::string& name, double value)
{
  for (Figure& figure : figures)
  {
    if (figure.name == name)
    {
      figure.value = value;
      return;
    }
  }
  figures.push_back({ name, value });
}

Status buildModelBaseDomain(const ModelSpec& spec, BaseDomain& domain)
{
  ModelContext ctx;
  ctx.spec = spec;
  for (const Stage& stage : pipelineStages())
  {
    if (!stageApplies(stage, spec))
      continue;
    if (Status status = stage.run(ctx); !status.ok())
      return Status::error(stage.name + ": " + status.message());
    if (stage.name == "base_domain")
    {
      domain = std::move(ctx.domain);
      return {};
    }
  }
  return Status::error("the pipeline has no base_domain stage");
}

} // namespace cmp::bench
