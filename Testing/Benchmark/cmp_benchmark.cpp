/// \file cmp_benchmark.cpp
/// \brief Times each pipeline stage of the core on every landmarked model of
///        the shared data and on a surface of at least a million triangles,
///        with peak memory, and writes the results as Markdown and CSV.

#include "BenchmarkModels.h"
#include "BenchmarkReport.h"
#include "BenchmarkRunner.h"
#include "BenchmarkShapeAnalysis.h"
#include "BenchmarkStages.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#if defined(__GLIBC__) // defined by the C++ headers above
#include <malloc.h>    // malloc_trim
#endif

#ifndef CMP_SHARED_DATA_DIR
#define CMP_SHARED_DATA_DIR ""
#endif

namespace
{

using namespace cmp::bench;

/// \brief The model whose L0 every net is traced against: the issue asks for
///        the figures "with L0 from model 381".
const char* const sharedDomainModel = "381";

/// \brief Command-line settings.
struct Options
{
  std::string dataDir = CMP_SHARED_DATA_DIR;
  std::string output = "benchmark-results.md";
  int repetitions = 3;
  int largeRepetitions = 1;
  long minTriangles = 1000000;
  bool large = true;
  bool listOnly = false;
  bool pipelineOnly = false; ///< Only the stages in the total, and the yardstick.
  std::vector<std::string> only; ///< Model names to run; empty = all.
};

const char* const usage =
  R"(usage: cmp_benchmark [options]

Times each stage of the core pipeline on every landmarked model of the shared
data folder and on one model midpoint-subdivided to >= --min-triangles, each
model in its own process, and writes Markdown tables (time, memory, and the
stages' figures such as the net length per sqrt(area)) plus a CSV beside them.
`trace` uses one L0 built from model 381 before any model runs (untimed); if
381 is not in the data, each model is traced against its own L0.

  --data DIR            shared data folder (default: the configured CMP_SHARED_DATA_DIR)
  --output FILE         Markdown file to write (default: benchmark-results.md);
                        the CSV goes to the same path with extension .csv
  --repeat N            runs per stage, the best counts (default: 3)
  --large-repeat N      runs per stage on the large model (default: 1)
  --min-triangles N     triangle count of the large model (default: 1000000)
  --no-large            skip the large model
  --only NAME[,NAME]    run only these models ("381", "spot", "large" or its full name);
                        "pca" names the shape-analysis timing (100 models x 40,000
                        vertices, alignment + 10 principal components), which runs
                        after the models when --only is not given
  --pipeline-only       run only the stages counted in `total` and `yardstick`
                        (no measurement stages, no shape analysis unless --only pca)
  --list                print the models and exit
  --help                print this
)";

/// \brief Parses a positive integer option value; false if it is not one.
bool parseCount(const std::string& text, long& value)
{
  char* end = nullptr;
  value = std::strtol(text.c_str(), &end, 10);
  return !text.empty() && *end == '\0' && value > 0;
}

/// \brief Fills `options`; returns an exit code, or -1 to go on.
int parseArguments(int argc, char** argv, Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    long count = 0;
    if (arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      return 0;
    }
    else if (arg == "--no-large")
      options.large = false;
    else if (arg == "--list")
      options.listOnly = true;
    else if (arg == "--pipeline-only")
      options.pipelineOnly = true;
    else if (arg == "--data" && hasValue)
      options.dataDir = argv[++i];
    else if (arg == "--output" && hasValue)
      options.output = argv[++i];
    else if (arg == "--only" && hasValue)
      options.only = splitCommas(argv[++i]);
    else if (arg == "--repeat" && hasValue && parseCount(argv[++i], count))
      options.repetitions = static_cast<int>(count);
    else if (arg == "--large-repeat" && hasValue && parseCount(argv[++i], count))
      options.largeRepetitions = static_cast<int>(count);
    else if (arg == "--min-triangles" && hasValue && parseCount(argv[++i], count))
      options.minTriangles = count;
    else
    {
      std::cerr << "cmp_benchmark: bad or incomplete option '" << arg << "'\n\n" << usage;
      return 2;
    }
  }
  return -1;
}

bool contains(const std::vector<std::string>& names, const std::string& name)
{
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool selected(const Options& options, const std::string& name)
{
  return options.only.empty() || contains(options.only, name);
}

/// \brief Whether the large model may be wanted: by default, or if `--only`
///        names "large" or something that is not a base model.
bool largeWanted(const Options& options, const std::vector<ModelSpec>& models)
{
  if (!options.large)
    return false;
  return options.only.empty() || std::any_of(options.only.begin(), options.only.end(), [&](const std::string& name) {
    return name != "pca" &&
      std::none_of(models.begin(), models.end(), [&](const ModelSpec& m) { return m.name == name; });
  });
}

/// \brief Runs one model, reporting progress on stderr.
ModelResult runAndReport(
  const ModelSpec& spec, const SharedInputs& shared, const std::vector<Stage>& stages, int repetitions)
{
  std::cerr << "cmp_benchmark: " << spec.name << " (" << spec.meshPath
            << (spec.subdivisionLevels ? ", " + std::to_string(spec.subdivisionLevels) + " subdivisions" : "")
            << ")\n";
  return runModel(
    spec, shared, stages, repetitions, [](const std::string& line) { std::cerr << "  " << line << "\n"; });
}

/// \brief Builds the shared L0 from `sharedDomainModel`, in this process so
///        that every child gets it through fork, and says in `notes` which
///        L0 `trace` used.
SharedInputs buildSharedInputs(const std::vector<ModelSpec>& models, std::vector<std::string>& notes)
{
  SharedInputs shared;
  const auto spec = std::find_if(
    models.begin(), models.end(), [](const ModelSpec& m) { return m.name == sharedDomainModel; });
  std::string reason = std::string("model ") + sharedDomainModel + " is not in the data";
  if (spec != models.end())
  {
    std::cerr << "cmp_benchmark: building the shared L0 from " << spec->meshPath << "\n";
    cmp::BaseDomain domain;
    const cmp::Status status = buildModelBaseDomain(*spec, domain);
    if (status.ok())
    {
      shared.domainModel = spec->name;
      notes.push_back("trace: every net is traced against one L0 built from model " + spec->name + " (" +
        std::to_string(domain.mesh.vertexCount()) + " vertices, " + std::to_string(domain.mesh.triangleCount()) +
        " triangles) before the models ran; building it is not timed and not in any model's memory");
      shared.domain = std::move(domain);
    }
    else
      reason = "L0 from model " + spec->name + " failed: " + status.message();
  }
  if (!shared.domain)
    notes.push_back("trace: " + reason + "; **each model is traced against its own base_domain**, "
      "so the figures are not the issue's \"with L0 from model " + sharedDomainModel + "\"");
#if defined(__GLIBC__)
  // Hand the decimation's freed heap back to the system: a child inherits
  // the parent's resident pages, and they would inflate every `start`.
  ::malloc_trim(0);
#endif
  return shared;
}

/// \brief Says what the figures of the `trace` stage mean.
std::string traceFiguresNote()
{
  return "figures of `trace`: net_length_per_sqrt_area = total curve length / sqrt(surface area); retraced = "
         "tentative curves found invalid and traced again; penalised = curves postponed by the swirl "
         "detector; split_edges = mesh edges split to make room between curves";
}

/// \brief Says what `remesh` and `remesh_distance` time and report.
std::string remeshFiguresNote()
{
  return "`remesh` = semi-regular connectivity + placement on the surface + fold repair (as the filter's default "
         "RepairFolds) + positions, at level remesh_level (5, or 6 on the large model); fold_repair_seconds = the "
         "repair alone, remesh_folded_before_repair and remesh_folded_after_repair = remesh triangles facing against "
         "the surface before and after it; `remesh_distance` (not on the large model) is a measurement, not counted "
         "in `total`: for levels 3 to 6 it builds the remesh (unrepaired) and compares it with the input surface, "
         "hausdorff_per_diagonal_lN = two-sided Hausdorff distance (both surfaces sampled at the points of a "
         "3-step barycentric grid per triangle) / bounding-box diagonal of the input, distance_seconds_lN = time of "
         "that distance computation alone (last run)";
}

/// \brief Says what the map stage's columns and the yardstick are.
std::string mapFiguresNote()
{
  return "`straighten`, `parameterize` and `map` are the parts of one `straighten()` call, the Net Straightener's "
         "default (edge straightening, the per-patch maps, then `freeCurves()`: the whole-surface map and the cut "
         "along it), each timed inside that call (the fastest call's); `remesh` and the measurements after it work on "
         "the map's result; map_applied = 1 where the curves were freed, map_distortion_before/_after = the global "
         "map's mean symmetric Dirichlet energy over its isometric value, map_iterations = its Newton steps; "
         "`yardstick` (not counted in `total`) = one Eigen SimplicialLDLT factorization of the model's cotan "
         "Laplacian (shifted by 1e-8 of its mean diagonal) plus 21 solves, yardstick_seconds = those alone (without "
         "building the matrix), pipeline_per_yardstick = `total` / yardstick_seconds (issue 24: median <= 25), trace_per_yardstick = `trace` / yardstick_seconds (issue 28: median <= 3)";
}

/// \brief Says what the `lower_stretch` measurement reports.
std::string lowerStretchFiguresNote()
{
  return "`lower_stretch` (a measurement, not counted in `total`) straightens and parameterizes again with Net "
         "Straightener's LowerStretch and FreeCurves off: lower_stretch_seconds = that parameterization alone, lower_stretch_smallest_area_ratio and "
         "lower_stretch_flipped_triangles as `parameterize` reports them, lower_stretch_hausdorff_per_diagonal_l5 "
         "(not on the large model) = the level-5 remesh's two-sided Hausdorff distance, to compare with "
         "hausdorff_per_diagonal_l5, lower_stretch_folded_before_repair_l5 and _after_repair_l5 = its folded "
         "triangles before and after the default fold repair, to compare with remesh_folded_before_repair and "
         "remesh_folded_after_repair";
}

std::string waveletFiguresNote()
{
  return "`wavelet` (a measurement, not counted in `total`) builds the level-6 remesh unless `remesh` did, then "
         "wavelet_seconds = one Loop wavelet analysis + synthesis of its positions with local detail frames (best "
         "of 3; target < 0.2 s), wavelet_build_seconds = setting up the transform, wavelet_error = largest "
         "reconstruction error / bounding-box diagonal";
}

/// \brief Triangle count of `spec`'s file, from a result already measured or
///        else by running only the `read` stage in a child process; 0 for a
///        model that failed (its refinement would fail the same way).
int triangleCount(const ModelSpec& spec, const SharedInputs& shared, const std::vector<ModelResult>& results)
{
  for (const ModelResult& result : results)
  {
    if (result.model == spec.name)
      return result.ok() ? result.triangles : 0;
  }
  std::vector<Stage> readOnly;
  for (const Stage& stage : pipelineStages())
  {
    if (stage.name == "read")
      readOnly.push_back(stage);
  }
  return runModel(spec, shared, readOnly, 1).triangles;
}

std::optional<ModelSpec> largeModel(const std::vector<ModelSpec>& models, const SharedInputs& shared,
  const std::vector<ModelResult>& results, long minTriangles)
{
  std::vector<int> counts;
  for (const ModelSpec& spec : models)
    counts.push_back(triangleCount(spec, shared, results));
  return chooseLargeModel(models, counts, minTriangles);
}

std::string largeNote(const ModelSpec& large, const std::vector<ModelResult>& results, long minTriangles)
{
  for (const ModelResult& result : results)
  {
    if (result.model == large.name)
      return "large model: " + large.name + " = " + large.meshPath + " midpoint-subdivided " +
        std::to_string(large.subdivisionLevels) + " times, " + std::to_string(result.triangles) +
        " triangles (fewest levels to reach " + std::to_string(minTriangles) + ")";
  }
  return "";
}

std::string csvPathFor(const std::string& markdownPath)
{
  std::filesystem::path path(markdownPath);
  path.replace_extension(".csv");
  return path.string() == markdownPath ? markdownPath + ".csv" : path.string();
}

void listModels(const std::vector<ModelSpec>& models, const std::optional<ModelSpec>& large)
{
  for (const ModelSpec& spec : models)
    std::cout << spec.name << "\t" << spec.meshPath << "\t" << spec.landmarkPath << "\n";
  if (large)
    std::cout << large->name << "\t" << large->meshPath << " x" << large->subdivisionLevels << " subdivisions\t"
              << large->landmarkPath << "\n";
}

/// \brief Writes and prints the report; returns the process exit code.
int writeReport(const Options& options, std::vector<ModelResult> results, const RunInfo& info)
{
  addYardstickRatios(results);
  const std::string markdown = markdownReport(results, info);
  std::cout << markdown;
  const std::string csvPath = csvPathFor(options.output);
  if (!writeTextFile(options.output, markdown) || !writeTextFile(csvPath, csvReport(results)))
  {
    std::cerr << "cmp_benchmark: cannot write " << options.output << " or " << csvPath << "\n";
    return 2;
  }
  std::cerr << "cmp_benchmark: wrote " << options.output << " and " << csvPath << "\n";
  const bool ok = std::all_of(results.begin(), results.end(), [](const ModelResult& r) { return r.ok(); });
  return ok ? 0 : 1;
}

int run(const Options& options)
{
  if (options.dataDir.empty() || !std::filesystem::is_directory(options.dataDir))
  {
    std::cerr << "cmp_benchmark: shared data folder '" << options.dataDir
              << "' not found; pass --data DIR (or configure CMP_SHARED_DATA_DIR)\n";
    return 2;
  }
  RunInfo info{ options.dataDir, options.repetitions, options.largeRepetitions, {} };
  std::vector<std::string> skipped;
  const std::vector<ModelSpec> models = discoverModels(options.dataDir, skipped);
  for (const std::string& reason : skipped)
    info.notes.push_back("not benchmarked: " + reason);

  const SharedInputs shared = options.listOnly ? SharedInputs{} : buildSharedInputs(models, info.notes);
  info.notes.push_back(traceFiguresNote());
  info.notes.push_back(mapFiguresNote());
  info.notes.push_back(remeshFiguresNote());

  info.notes.push_back(lowerStretchFiguresNote());
  info.notes.push_back(waveletFiguresNote());

  std::vector<Stage> stages;
  for (const Stage& stage : pipelineStages())
  {
    if (!options.pipelineOnly || stage.inTotal || stage.name == "yardstick")
      stages.push_back(stage);
  }
  std::vector<ModelResult> results;
  for (const ModelSpec& spec : models)
  {
    if (selected(options, spec.name) && !options.listOnly)
      results.push_back(runAndReport(spec, shared, stages, options.repetitions));
  }
  const std::optional<ModelSpec> large =
    largeWanted(options, models) ? largeModel(models, shared, results, options.minTriangles) : std::nullopt;
  if (options.listOnly)
  {
    listModels(models, large);
    return 0;
  }
  if (large && (selected(options, large->name) || contains(options.only, "large")))
  {
    results.push_back(runAndReport(*large, shared, stages, options.largeRepetitions));
    info.notes.push_back(largeNote(*large, results, options.minTriangles));
  }
  const bool shapeAnalysis = options.pipelineOnly ? contains(options.only, "pca") : selected(options, "pca");
  if (shapeAnalysis)
  {
    std::cerr << "shape analysis: 100 models x 40,000 vertices\n";
    ShapeAnalysisTiming timing;
    if (cmp::Status status = timeShapeAnalysis(100, 200, 10, options.repetitions, timing); !status.ok())
    {
      std::cerr << "cmp_benchmark: shape analysis failed: " << status.message() << "\n";
      return 1;
    }
    info.notes.push_back(describe(timing));
  }
  if (results.empty() && !shapeAnalysis)
  {
    std::cerr << "cmp_benchmark: no model selected (see --list)\n";
    return 2;
  }
  return writeReport(options, results, info);
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  const int code = parseArguments(argc, argv, options);
  return code >= 0 ? code : run(options);
}
