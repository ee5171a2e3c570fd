#pragma once
/// \file BenchmarkRunner.h
/// \brief Runs the pipeline stages on one model in its own child process and
///        measures wall time and peak memory of each stage.

#include "BenchmarkStages.h"

#include <functional>
#include <string>
#include <vector>

namespace cmp::bench
{

/// \brief What happened to one stage on one model.
enum class StageState
{
  NotRun,        ///< An earlier stage failed, or the process died first.
  NotApplicable, ///< The stage does not apply to this model (e.g. `subdivide`).
  Done,          ///< Ran successfully.
  Failed         ///< Returned an error.
};

/// \brief Timing and memory of one stage on one model.
struct StageResult
{
  std::string stage;                    ///< Stage name.
  StageState state = StageState::NotRun; ///< Outcome.
  double seconds = 0.0;                 ///< Best wall time over `runs` runs.
  int runs = 0;                         ///< Number of timed runs.
  double peakMB = 0.0;                  ///< Peak resident memory while the stage ran.
  bool inTotal = true;                  ///< Counted in `ModelResult::totalSeconds()` (see `Stage::inTotal`).
};

/// \brief All stages of one model.
struct ModelResult
{
  std::string model;               ///< Model name.
  int vertices = 0;                ///< Vertices of the surface the stages worked on.
  int triangles = 0;               ///< Triangles of that surface.
  std::vector<StageResult> stages; ///< One per pipeline stage, in order.
  FigureList figures;              ///< What the stages that finished reported, in first-set order.
  double startMB = 0.0;            ///< Resident memory of the child before its first stage.
  double peakMB = 0.0;             ///< Peak resident memory of the child process.
  bool perStagePeaks = false;      ///< True if each stage's peak was measured on its own
                                   ///< (else peaks are cumulative since the child started).
  std::string error;               ///< First failure or crash; empty on success.

  /// \brief True if every applicable stage ran successfully.
  bool ok() const { return error.empty(); }
  /// \brief Sum of the best times of the stages counted in the total.
  double totalSeconds() const;
};

/// \brief Receives one line of progress per finished stage.
using ProgressFunction = std::function<void(const std::string&)>;

/// \brief Runs `stages` on `spec` in a forked child process and collects
///        their best-of-`repetitions` times, peak memory and figures.
///
/// A child per model means each model's peak memory is its own (not the
/// high-water mark of the models before it), and a crash or an
/// out-of-memory kill ends one row instead of the benchmark. The child
/// reads `shared` from its copy of the parent's memory.
ModelResult runModel(const ModelSpec& spec, const SharedInputs& shared, const std::vector<Stage>& stages,
  int repetitions, const ProgressFunction& progress = {});

} // namespace cmp::bench
