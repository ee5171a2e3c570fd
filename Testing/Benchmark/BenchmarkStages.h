#pragma once
/// \file BenchmarkStages.h
/// \brief The pipeline stages the benchmark times, and the per-model context
///        they read from and write to.
///
/// To time a new stage (tracer, straightener, remesher, PCA, ...):
///  1. add the fields it produces to `ModelContext`;
///  2. append one `Stage` to the list in `pipelineStages()`
///     (BenchmarkStages.cpp).
/// The runner, the Markdown table and the CSV pick it up from that list.

#include "BaseDomain.h"
#include "BaseDomainBuilder.h"
#include "Landmarks.h"
#include "MeshFile.h"
#include "Status.h"
#include "SurfaceCheck.h"
#include "TriangleMesh.h"

#include <functional>
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

/// \brief Everything the stages of one model produce, in pipeline order.
///
/// Lives in the model's own child process, so nothing here leaks into the
/// memory measured for another model.
struct ModelContext
{
  ModelSpec spec;                         ///< Input files.
  MeshFileData file;                      ///< `read`: the welded file mesh.
  TriangleMesh subdivided;                ///< `subdivide`: the refined mesh (large model only).
  SurfaceCheckResult surfaceCheck;        ///< `check`: the surface's first defect, if any.
  LandmarkList landmarks;                 ///< `landmarks`: landmark vertex per feature.
  BaseDomain domain;                      ///< `base_domain`: L0.
  BaseDomainBuilderReport domainReport;   ///< `base_domain`: collapses, shape quality.
  // Later stages add their outputs here (patch nets, parameterization, ...).

  /// \brief The surface every stage after `read` works on: the subdivided
  ///        mesh when there is one, else the file's mesh.
  const TriangleMesh& surface() const
  {
    return spec.subdivisionLevels > 0 ? subdivided : file.mesh;
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
};

/// \brief The stages in pipeline order. Later stages append themselves here.
const std::vector<Stage>& pipelineStages();

/// \brief True if `stage` runs for `spec`.
bool stageApplies(const Stage& stage, const ModelSpec& spec);

} // namespace cmp::bench
