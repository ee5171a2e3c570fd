#pragma once
/// \file BenchmarkStages.h
/// \brief The pipeline stages the benchmark times, and the per-model context
///        they read from and write to.
///
/// To time a new stage (straightener, remesher, PCA, ...):
///  1. add the fields it produces to `ModelContext`;
///  2. append one `Stage` to the list in `pipelineStages()`
///     (BenchmarkStages.cpp);
///  3. if it yields per-model numbers worth a column (a length, a count, an
///     error), `setFigure(ctx.figures, "name", value)` them in the stage.
/// The runner, the Markdown tables and the CSV pick both up by themselves.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/Landmarks.h>
#include <cmp/io/MeshFile.h>
#include <cmp/map/NetStraightener.h>
#include <cmp/map/Straighten.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/mesh/TriangleMesh.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmp::bench
{

/// \brief Where a model comes from: files and how much to refine it.
struct ModelSpec
{
  std::string name;           ///< Row name in the table ("381", "spot", "382-sub3").
  std::string meshPath;       ///< .off or .obj.
  std::string landmarkPath;   ///< .vts or .pinned.
  int subdivisionLevels = 0;  ///< Midpoint subdivisions after reading (0 = none).
};

/// \brief One named per-model number a stage produces (a net length, a
///        count, ...), reported in the "Figures per model" table.
struct Figure
{
  std::string name;   ///< Column name (lower case, no spaces, no tabs).
  double value = 0.0; ///< Its value for the model.
};

/// \brief A model's figures, in the order they were first set.
using FigureList = std::vector<Figure>;

/// \brief Sets figure `name` to `value`: replaces an earlier value of that
///        name (a repeated stage sets its figures again), else appends it.
void setFigure(FigureList& figures, const std::string& name, double value);

/// \brief Inputs every model shares, built once in the parent process before
///        any model's child is forked.
///
/// Each child sees them through fork's copy, so building them is neither
/// timed nor counted in any model's peak memory.
struct SharedInputs
{
  /// \brief The common base domain L0 that `trace` uses for every model;
  ///        empty when it could not be built (then `trace` falls back to the
  ///        model's own `base_domain`).
  std::optional<BaseDomain> domain;
  /// \brief Name of the model L0 was built from (e.g. "381").
  std::string domainModel;
};

/// \brief Everything the stages of one model produce, in pipeline order.
///
/// Lives in the model's own child process, so nothing here leaks into the
/// memory measured for another model.
struct ModelContext
{
  ModelSpec spec;                         ///< Input files.
  const SharedInputs* shared = nullptr;   ///< Inputs common to all models (not owned).
  MeshFileData file;                      ///< `read`: the welded file mesh.
  TriangleMesh subdivided;                ///< `subdivide`: the refined mesh (large model only).
  SurfaceCheckResult surfaceCheck;        ///< `check`: the surface's first defect, if any.
  LandmarkList landmarks;                 ///< `landmarks`: landmark vertex per feature.
  BaseDomain domain;                      ///< `base_domain`: L0.
  BaseDomainBuilderReport domainReport;   ///< `base_domain`: collapses, shape quality.
  TracedNet net;                          ///< `trace`: the net on the refined surface.
  NetTracerReport netReport;              ///< `trace`: length, retraces, splits.
  StraightenedNet straight;               ///< `straighten` to `map`: the final net (curves freed).
  StraightenReport straightReport;        ///< `straighten` to `map`: lengths, area variation, sweeps, the map's figures.
  PatchParameterization parameterization; ///< `straighten` to `map`: base-domain place of every vertex.
  SemiRegularMesh remesh;                 ///< `remesh`: the semi-regular connectivity.
  std::vector<SurfacePoint> remeshSamples; ///< `remesh`: where each remesh vertex lands on the surface.
  std::vector<Vec3> remeshPoints;         ///< `remesh`: the positions of those places.
  // Later stages add their outputs here (PCA, ...).
  FigureList figures;                     ///< Per-model numbers the stages report.
  /// \brief Set by a stage with `Stage::parts`: the seconds of each part
  ///        in its last run, in the order of `parts`.
  std::vector<double> partSeconds;

  /// \brief The surface every stage after `read` works on: the subdivided
  ///        mesh when there is one, else the file's mesh.
  const TriangleMesh& surface() const
  {
    return spec.subdivisionLevels > 0 ? subdivided : file.mesh;
  }

  /// \brief The base domain to trace against: the shared L0 when there is
  ///        one, else this model's own `base_domain` output.
  const BaseDomain& traceDomain() const
  {
    return shared && shared->domain ? *shared->domain : domain;
  }
};

/// \brief One timed step of the pipeline.
struct Stage
{
  /// \brief Column name in the table (lower case, no spaces).
  std::string name;
  /// \brief Does the work. Must be repeatable: it recomputes its outputs
  ///        from earlier stages' outputs (clearing them first, so a repeat
  ///        does not hold two copies and inflate the peak memory).
  std::function<Status(ModelContext&)> run;
  /// \brief Whether the stage runs for a model; empty means always.
  std::function<bool(const ModelSpec&)> appliesTo;
  /// \brief False for a stage that measures the pipeline's results instead
  ///        of producing them (`remesh_distance`): timed and shown like the
  ///        others, but left out of the model's total.
  bool inTotal = true;
  /// \brief Names of the parts the stage times itself (its `run` sets
  ///        `ModelContext::partSeconds`, one per part): the table then shows
  ///        one column per part, from the fastest run, and no column for the
  ///        stage. Empty: the stage is one column.
  std::vector<std::string> parts = {};
};

/// \brief The names the tables give `stage`: its parts, or its own name.
std::vector<std::string> stageColumns(const Stage& stage);

/// \brief The stages in pipeline order. Later stages append themselves here.
const std::vector<Stage>& pipelineStages();

/// \brief True if `stage` runs for `spec`.
bool stageApplies(const Stage& stage, const ModelSpec& spec);

/// \brief Builds `spec`'s base domain in the calling process by running the
///        pipeline's stages up to and including `base_domain`, untimed.
///
/// Used for the shared L0; running the same stages as the benchmark means L0
/// is exactly the `base_domain` output of that model's own row.
Status buildModelBaseDomain(const ModelSpec& spec, BaseDomain& domain);

} // namespace cmp::bench
