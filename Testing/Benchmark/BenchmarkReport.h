#pragma once
/// \file BenchmarkReport.h
/// \brief The benchmark's results as Markdown tables and a CSV file.
///
/// Markdown: run facts, then "Time per stage (s)", "Peak memory per stage
/// (MB)" and "Figures per model" (one row per model, one column per figure
/// name in the order the names first appear; `-` where a model has none).
///
/// CSV: one row per model and stage, with the fixed columns
/// `model,vertices,triangles,stage,status,seconds,runs,stage_peak_mb,process_peak_mb`
/// followed by one column per figure name (same order as the Markdown).
/// Like `process_peak_mb`, figures belong to the model and repeat on each of
/// its rows; a cell is empty where the model has no such figure. Values are
/// written with full precision.

#include "BenchmarkRunner.h"

#include <string>
#include <vector>

namespace cmp::bench
{

/// \brief Facts about the run printed above the tables.
struct RunInfo
{
  std::string dataDir;               ///< Shared data folder.
  int repetitions = 1;               ///< Runs per stage (best is reported).
  int largeRepetitions = 1;          ///< Runs per stage on the large model.
  std::vector<std::string> notes;    ///< Extra lines (skipped models, large model choice).
};

/// \brief The Markdown report: run facts, a time table (one row per model,
///        one column per stage), a peak-memory table and a figures table.
std::string markdownReport(const std::vector<ModelResult>& results, const RunInfo& info);

/// \brief Sets each model's figure `pipeline_per_yardstick`: its pipeline
///        total (`ModelResult::totalSeconds()`) over its `yardstick_seconds`
///        (issue 24's speed reference), for a model that has both, and on
///        each of those `pipeline_per_yardstick_median`, the median ratio;
///        the same for the `trace` stage alone (`trace_per_yardstick` and
///        `trace_per_yardstick_median`, issue 28).
void addYardstickRatios(std::vector<ModelResult>& results);

/// \brief One CSV row per model and stage:
///        `model,vertices,triangles,stage,status,seconds,runs,stage_peak_mb,process_peak_mb`
///        then one column per figure name (see the file comment).
std::string csvReport(const std::vector<ModelResult>& results);

/// \brief Writes `text` to `path`, creating its folder; false on failure.
bool writeTextFile(const std::string& path, const std::string& text);

} // namespace cmp::bench
