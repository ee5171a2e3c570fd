#pragma once
/// \file BenchmarkReport.h
/// \brief The benchmark's results as a Markdown table and a CSV file.

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
///        one column per stage) and a peak-memory table.
std::string markdownReport(const std::vector<ModelResult>& results, const RunInfo& info);

/// \brief One CSV row per model and stage:
///        `model,vertices,triangles,stage,status,seconds,runs,stage_peak_mb,process_peak_mb`.
std::string csvReport(const std::vector<ModelResult>& results);

/// \brief Writes `text` to `path`, creating its folder; false on failure.
bool writeTextFile(const std::string& path, const std::string& text);

} // namespace cmp::bench
