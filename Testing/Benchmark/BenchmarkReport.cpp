#include "BenchmarkReport.h"

#include <sys/utsname.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

#ifndef CMP_BENCHMARK_BUILD_TYPE
#define CMP_BENCHMARK_BUILD_TYPE "unknown"
#endif

namespace cmp::bench
{
namespace
{

std::string format(const char* pattern, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// ---------------------------------------------------------------------------
// Facts about the machine and the build, so tables from different runs can
// be compared knowingly.

std::string utcNow()
{
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

std::string cpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
      return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

std::string hostDescription()
{
  utsname names{};
  ::uname(&names);
  return cpuModel() + ", " + std::to_string(std::thread::hardware_concurrency()) + " logical cores, " +
    names.sysname + " " + names.release;
}

std::string buildDescription()
{
  std::string text = std::string(CMP_BENCHMARK_BUILD_TYPE) + ", " +
#if defined(__clang__)
    "Clang " __clang_version__;
#elif defined(__GNUC__)
    "GCC " __VERSION__;
#else
    "unknown compiler";
#endif
#if defined(__SANITIZE_ADDRESS__)
  text += " **with sanitizers: times are not representative**";
#endif
  return text;
}

// ---------------------------------------------------------------------------
// Tables.

std::vector<std::string> stageNames(const std::vector<ModelResult>& results)
{
  std::vector<std::string> names;
  if (!results.empty())
  {
    for (const StageResult& stage : results.front().stages)
      names.push_back(stage.stage);
  }
  return names;
}

std::string cell(const StageResult& stage, double value, const char* pattern)
{
  switch (stage.state)
  {
    case StageState::Done:
      return format(pattern, value);
    case StageState::NotApplicable:
      return "-";
    case StageState::Failed:
      return "FAILED";
    case StageState::NotRun:
      break;
  }
  return "not run";
}

std::string tableRow(const std::vector<std::string>& cells)
{
  std::string row = "|";
  for (const std::string& c : cells)
    row += " " + c + " |";
  return row + "\n";
}

std::string tableHeader(const std::vector<std::string>& columns, std::size_t leftAligned)
{
  std::string rule = "|";
  for (std::size_t i = 0; i < columns.size(); ++i)
    rule += i < leftAligned ? " --- |" : " ---: |";
  return tableRow(columns) + rule + "\n";
}

std::string timeTable(const std::vector<ModelResult>& results)
{
  std::vector<std::string> columns = { "model", "vertices", "triangles" };
  for (const std::string& name : stageNames(results))
    columns.push_back(name);
  columns.push_back("total");
  columns.push_back("peak MB");
  std::string table = tableHeader(columns, 1);
  for (const ModelResult& result : results)
  {
    std::vector<std::string> cells = { result.model, std::to_string(result.vertices),
      std::to_string(result.triangles) };
    for (const StageResult& stage : result.stages)
      cells.push_back(cell(stage, stage.seconds, "%.3f"));
    cells.push_back(format("%.3f", result.totalSeconds()));
    cells.push_back(format("%.0f", result.peakMB));
    table += tableRow(cells);
  }
  return table;
}

std::string memoryTable(const std::vector<ModelResult>& results)
{
  std::vector<std::string> columns = { "model", "start" };
  for (const std::string& name : stageNames(results))
    columns.push_back(name);
  columns.push_back("process");
  std::string table = tableHeader(columns, 1);
  for (const ModelResult& result : results)
  {
    std::vector<std::string> cells = { result.model, format("%.1f", result.startMB) };
    for (const StageResult& stage : result.stages)
      cells.push_back(cell(stage, stage.peakMB, "%.1f"));
    cells.push_back(format("%.1f", result.peakMB));
    table += tableRow(cells);
  }
  return table;
}

/// \brief Every figure name of any model, in the order first seen.
std::vector<std::string> figureNames(const std::vector<ModelResult>& results)
{
  FigureList all;
  for (const ModelResult& result : results)
  {
    for (const Figure& figure : result.figures)
      setFigure(all, figure.name, 0.0);
  }
  std::vector<std::string> names;
  for (const Figure& figure : all)
    names.push_back(figure.name);
  return names;
}

const Figure* findFigure(const ModelResult& result, const std::string& name)
{
  for (const Figure& figure : result.figures)
  {
    if (figure.name == name)
      return &figure;
  }
  return nullptr;
}

/// \brief A figure for the table: counts as integers, the rest with three
///        decimals, or three significant digits below 1 so that small
///        ratios (a Hausdorff distance over the diagonal) do not all read
///        0.00x.
std::string figureCell(const Figure* figure)
{
  if (!figure)
    return "-";
  const double value = figure->value;
  if (value == std::floor(value) && std::abs(value) < 1e15)
    return format("%.0f", value);
  return format(std::abs(value) < 1.0 ? "%.3g" : "%.3f", value);
}

std::string figureTable(const std::vector<ModelResult>& results)
{
  const std::vector<std::string> names = figureNames(results);
  if (names.empty())
    return "No stage reported figures.\n";
  std::vector<std::string> columns = { "model" };
  columns.insert(columns.end(), names.begin(), names.end());
  std::string table = tableHeader(columns, 1);
  for (const ModelResult& result : results)
  {
    std::vector<std::string> cells = { result.model };
    for (const std::string& name : names)
      cells.push_back(figureCell(findFigure(result, name)));
    table += tableRow(cells);
  }
  return table;
}

std::string failures(const std::vector<ModelResult>& results)
{
  std::string text;
  for (const ModelResult& result : results)
  {
    if (!result.ok())
      text += "- " + result.model + ": " + result.error + "\n";
  }
  return text.empty() ? "" : "\n## Failures\n\n" + text;
}

bool allPerStage(const std::vector<ModelResult>& results)
{
  return std::all_of(
    results.begin(), results.end(), [](const ModelResult& result) { return result.perStagePeaks; });
}

std::string header(const std::vector<ModelResult>& results, const RunInfo& info)
{
  std::string text = "# cmp_benchmark\n\n";
  text += "- date: " + utcNow() + "\n";
  text += "- host: " + hostDescription() + "\n";
  text += "- build: " + buildDescription() + "\n";
  text += "- data: `" + info.dataDir + "`\n";
  text += "- time: wall clock in seconds, the best of " + std::to_string(info.repetitions) +
    " run(s) of each stage (large model: " + std::to_string(info.largeRepetitions) +
    "); `-` = the stage does not apply to the model\n";
  text += "- memory: peak resident set size of the model's own child process, in MB " +
    std::string(allPerStage(results) ? "(per stage: peak while that stage ran; the heap kept by earlier stages counts)"
                                     : "(per stage: peak since the process started)") +
    "; `start` is what the process holds before its first stage\n";
  for (const std::string& note : info.notes)
    text += "- " + note + "\n";
  return text;
}

std::string csvField(const std::string& text)
{
  if (text.find_first_of(",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

const char* stateName(StageState state)
{
  switch (state)
  {
    case StageState::Done:
      return "ok";
    case StageState::NotApplicable:
      return "n/a";
    case StageState::Failed:
      return "failed";
    case StageState::NotRun:
      break;
  }
  return "not-run";
}

/// The seconds of `stage` on `result`, or a negative number if it did not
/// run successfully.
double stageSeconds(const ModelResult& result, const std::string& stage)
{
  for (const StageResult& s : result.stages)
    if (s.stage == stage && s.state == StageState::Done)
      return s.seconds;
  return -1.0;
}

/// \brief The pipeline's speed against the yardstick: per model its
///        total, the yardstick and their ratio, and the median ratio.
std::string yardstickSection(const std::vector<ModelResult>& results)
{
  std::string table = tableHeader({ "model", "total", "yardstick", "ratio", "trace", "trace ratio" }, 1);
  int count = 0;
  double median = 0.0, traceMedian = -1.0;
  for (const ModelResult& result : results)
  {
    const Figure* ratio = findFigure(result, "pipeline_per_yardstick");
    const Figure* yardstick = findFigure(result, "yardstick_seconds");
    const Figure* middle = findFigure(result, "pipeline_per_yardstick_median");
    if (!ratio || !yardstick || !middle)
      continue;
    ++count;
    median = middle->value;
    const Figure* traceRatio = findFigure(result, "trace_per_yardstick");
    if (const Figure* traceMiddle = findFigure(result, "trace_per_yardstick_median"))
      traceMedian = traceMiddle->value;
    table += tableRow({ result.model, format("%.3f", result.totalSeconds()), format("%.4f", yardstick->value),
      format("%.1f", ratio->value), traceRatio ? format("%.3f", stageSeconds(result, "trace")) : "-",
      traceRatio ? format("%.1f", traceRatio->value) : "-" });
  }
  if (count == 0)
    return "";
  return "\n## Speed against the yardstick\n\n"
         "`total` = the pipeline's stages counted in the time table's total (`map` included); `yardstick` = one "
         "Eigen SimplicialLDLT factorization of the model's cotan Laplacian plus 21 solves (issue 24); ratio = "
         "total / yardstick, target: median <= 25; trace ratio = the `trace` stage / yardstick, target: median "
         "<= 3 (issue 28).\n\n" +
    table + "\nmedian ratio over " + std::to_string(count) + " models: " + format("%.1f", median) +
    (traceMedian >= 0.0 ? "; median trace ratio: " + format("%.1f", traceMedian) : std::string()) + "\n";
}

} // namespace

namespace
{

/// Sets figure `name` to seconds / yardstick on every model where `seconds`
/// gives a time, and `name`_median to the median of those ratios on each of
/// them (so that the CSV, one row per model and stage, carries it too).
void addRatio(std::vector<ModelResult>& results, const std::string& name,
  const std::function<double(const ModelResult&)>& seconds)
{
  std::vector<double> ratios;
  for (ModelResult& result : results)
  {
    const Figure* yardstick = findFigure(result, "yardstick_seconds");
    const double t = result.ok() ? seconds(result) : -1.0;
    if (t >= 0.0 && yardstick && yardstick->value > 0.0)
    {
      ratios.push_back(t / yardstick->value);
      setFigure(result.figures, name, ratios.back());
    }
  }
  if (ratios.empty())
    return;
  std::sort(ratios.begin(), ratios.end());
  const std::size_t half = ratios.size() / 2;
  const double median = ratios.size() % 2 ? ratios[half] : 0.5 * (ratios[half - 1] + ratios[half]);
  for (ModelResult& result : results)
    if (findFigure(result, name))
      setFigure(result.figures, name + "_median", median);
}

} // namespace

void addYardstickRatios(std::vector<ModelResult>& results)
{
  addRatio(results, "pipeline_per_yardstick", [](const ModelResult& r) { return r.totalSeconds(); });
  addRatio(results, "trace_per_yardstick", [](const ModelResult& r) { return stageSeconds(r, "trace"); });
}

std::string markdownReport(const std::vector<ModelResult>& results, const RunInfo& info)
{
  return header(results, info) + "\n## Time per stage (s)\n\n" + timeTable(results) +
    "\n## Peak memory per stage (MB)\n\n" + memoryTable(results) + "\n## Figures per model\n\n" +
    figureTable(results) + yardstickSection(results) + failures(results);
}

std::string csvReport(const std::vector<ModelResult>& results)
{
  const std::vector<std::string> names = figureNames(results);
  std::string text = "model,vertices,triangles,stage,status,seconds,runs,stage_peak_mb,process_peak_mb";
  for (const std::string& name : names)
    text += "," + csvField(name);
  text += "\n";
  for (const ModelResult& result : results)
  {
    // The model's figures, the same on each of its rows.
    std::string figures;
    for (const std::string& name : names)
    {
      const Figure* figure = findFigure(result, name);
      figures += "," + (figure ? format("%.17g", figure->value) : std::string());
    }
    for (const StageResult& stage : result.stages)
    {
      text += csvField(result.model) + "," + std::to_string(result.vertices) + "," +
        std::to_string(result.triangles) + "," + csvField(stage.stage) + "," + stateName(stage.state) + "," +
        format("%.6f", stage.seconds) + "," + std::to_string(stage.runs) + "," + format("%.1f", stage.peakMB) +
        "," + format("%.1f", result.peakMB) + figures + "\n";
    }
  }
  return text;
}

bool writeTextFile(const std::string& path, const std::string& text)
{
  const std::filesystem::path file(path);
  std::error_code ignored;
  if (file.has_parent_path())
    std::filesystem::create_directories(file.parent_path(), ignored);
  std::ofstream out(file, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

} // namespace cmp::bench
