/// \file cmp_map_study.cpp
/// \brief Measures the map issue's figures on a collection with the core's
///        default settings: every model traced against one L0 (built from
///        one of the models, or read from a file), straightened and mapped
///        (`straighten()`), then remeshed together (`remesh()`, with the
///        sample relaxation `consistent-remesh` uses by default), and per
///        model the two-sided Hausdorff distance, the folds by the corner
///        and the centroid criteria, the remesh's shape, the map's
///        distortion and the time of each stage.
///
///   cmp_map_study --data DIR [--l0 MODEL|FILE.obj] [--level 5]
///                 [--relax 4] [--models 381,382,...] [--fixed-curves]
///                 [--sweeps N] [--map-iterations N] [--map-gain G] [--density C] [--targets equilateral|l0]
///                 [--no-repair] [--details] [--write DIR]
///
/// One line per model, then the largest and median distance and the summed
/// folds: the table the map issue's notes give. `--sweeps` sets the
/// straightening sweeps, `--map-iterations` and `--map-gain` the map's
/// Newton steps at most and the least relative gain of one, `--density`
/// the curvature density, `--no-repair` counts the folds before any repair,
/// `--details` prints L0's valences and the folds left near each landmark,
/// `--write` each remesh as DIR/NAME.remesh.off with its folded triangles
/// (NAME.folds.txt: corner and centroid criterion per triangle) and where
/// its Hausdorff distance is reached (NAME.hausdorff.txt).

#include "BenchmarkModels.h"

#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/Landmarks.h>
#include <cmp/io/MeshFile.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/map/Straighten.h>
#include <cmp/remesh/Remesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <fstream>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#ifndef CMP_SHARED_DATA_DIR
#define CMP_SHARED_DATA_DIR ""
#endif

namespace
{

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Model
{
  std::string name;
  std::string meshPath;
  std::string landmarkPath;
  cmp::MeshFileData file;
  cmp::LandmarkList landmarks;
  cmp::TracedNet traced;
  cmp::StraightenedNet straight;
  cmp::PatchParameterization map;
  cmp::StraightenReport report;
  cmp::ParameterizedSurface surface;
  double traceSeconds = 0.0;
  std::string error;
};

/// The landmarked model `name` of the shared data (the benchmark's list).
bool locate(const std::string& data, const std::string& name, Model& model)
{
  std::vector<std::string> skipped;
  for (const cmp::bench::ModelSpec& spec : cmp::bench::discoverModels(data, skipped))
    if (spec.name == name)
    {
      model.name = name;
      model.meshPath = spec.meshPath;
      model.landmarkPath = spec.landmarkPath;
      return true;
    }
  return false;
}

cmp::Status read(Model& model)
{
  const cmp::Status status = cmp::fileExtension(model.meshPath) == "obj" ? cmp::readOBJ(model.meshPath, model.file)
                                                                          : cmp::readOFF(model.meshPath, model.file);
  if (!status.ok())
    return status;
  cmp::weldIdenticalPoints(model.file);
  return cmp::readLandmarkFile(model.landmarkPath, model.file.mesh, model.file.fileToMeshPoint, model.landmarks);
}

/// Writes `points` and `triangles` as an OFF file.
void writeOFF(const std::string& path, const std::vector<cmp::Vec3>& points, const std::vector<cmp::Triangle>& triangles)
{
  std::ofstream out(path);
  out << "OFF\n" << points.size() << " " << triangles.size() << " 0\n";
  out.precision(17);
  for (const cmp::Vec3& p : points)
    out << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const cmp::Triangle& t : triangles)
    out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

double median(std::vector<double> values)
{
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = CMP_SHARED_DATA_DIR;
  std::string l0 = "381";
  int level = 5;
  int relax = 4;
  bool fixedCurves = false;
  bool repair = true;
  bool details = false;
  int sweeps = -1;
  int mapIterations = -1;
  double mapGain = -1.0;
  double density = -1.0;
  std::string targets = "equilateral";
  std::string writeDir;
  std::vector<std::string> names{ "381", "382", "383", "384", "385", "387", "388", "389", "391", "392", "spot" };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc)
      {
        std::cerr << arg << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--data")
      data = value();
    else if (arg == "--l0")
      l0 = value();
    else if (arg == "--level")
      level = std::stoi(value());
    else if (arg == "--relax")
      relax = std::stoi(value());
    else if (arg == "--models")
      names = cmp::bench::splitCommas(value());
    else if (arg == "--write")
      writeDir = value();
    else if (arg == "--sweeps")
      sweeps = std::stoi(value());
    else if (arg == "--no-repair")
      repair = false;
    else if (arg == "--details")
      details = true;
    else if (arg == "--map-iterations")
      mapIterations = std::stoi(value());
    else if (arg == "--map-gain")
      mapGain = std::stod(value());
    else if (arg == "--density")
      density = std::stod(value());
    else if (arg == "--targets")
      targets = value();
    else if (arg == "--fixed-curves")
      fixedCurves = true;
    else
    {
      std::cerr << "usage: cmp_map_study --data DIR [--l0 MODEL|FILE.obj] [--level 5] [--relax 4] "
                   "[--models A,B,...] [--fixed-curves] [--sweeps N] [--map-iterations N] [--map-gain G] [--density C] [--targets equilateral|l0] "
                   "[--no-repair] [--details] [--write DIR]\n";
      return 2;
    }
  }

  std::vector<std::unique_ptr<Model>> models;
  for (const std::string& name : names)
  {
    auto model = std::make_unique<Model>();
    if (!locate(data, name, *model))
    {
      std::cerr << name << ": no mesh and landmark file in " << data << "\n";
      return 1;
    }
    if (cmp::Status s = read(*model); !s.ok())
    {
      std::cerr << name << ": " << s.message() << "\n";
      return 1;
    }
    models.push_back(std::move(model));
  }

  cmp::BaseDomain domain;
  if (cmp::fileExtension(l0) == "obj")
  {
    cmp::MeshFileData file;
    if (cmp::Status s = cmp::readOBJ(l0, file); !s.ok())
    {
      std::cerr << l0 << ": " << s.message() << "\n";
      return 1;
    }
    domain.mesh = file.mesh;
    for (int f = 0; f < domain.mesh.vertexCount(); ++f)
      domain.featureIds.push_back(f);
  }
  else
  {
    Model source;
    if (!locate(data, l0, source) || !read(source).ok())
    {
      std::cerr << l0 << ": cannot read the model to build L0 from\n";
      return 1;
    }
    if (cmp::Status s = cmp::buildBaseDomain(source.file.mesh, source.landmarks, domain); !s.ok())
    {
      std::cerr << "L0 from " << l0 << ": " << s.message() << "\n";
      return 1;
    }
  }

  if (details)
  {
    std::vector<int> valence(domain.mesh.vertexCount(), 0);
    std::vector<double> angle(domain.mesh.vertexCount(), 0.0);
    for (const cmp::Triangle& t : domain.mesh.triangles)
      for (int k = 0; k < 3; ++k)
      {
        ++valence[t[k]];
        const cmp::Vec3 a = domain.mesh.points[t[(k + 1) % 3]] - domain.mesh.points[t[k]];
        const cmp::Vec3 b = domain.mesh.points[t[(k + 2) % 3]] - domain.mesh.points[t[k]];
        angle[t[k]] += std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
      }
    for (int v = 0; v < domain.mesh.vertexCount(); ++v)
      std::fprintf(stderr, "L0 vertex %d (feature %d): valence %d, angle %.0f deg (equilateral %d)\n", v,
        domain.featureIds[v], valence[v], angle[v] * 180.0 / cmp::kPi, 60 * valence[v]);
  }
  cmp::StraightenOptions options;
  options.freeCurves = !fixedCurves;
  if (sweeps >= 0)
    options.net.maxSweeps = sweeps;
  if (mapIterations >= 0)
    options.map.maximumIterations = mapIterations;
  if (mapGain >= 0.0)
    options.map.leastRelativeGain = mapGain;
  if (density >= 0.0)
    options.map.curvatureDensity = density;
  if (targets == "l0")
    options.map.targetShapes = cmp::GlobalMapOptions::TargetShapes::BaseDomain;
  std::vector<cmp::RemeshModel> remeshModels;
  std::vector<Model*> placed;
  for (auto& model : models)
  {
    Clock::time_point start = Clock::now();
    cmp::Status s = cmp::traceFeatureNet(model->file.mesh, model->landmarks, domain, model->traced);
    model->traceSeconds = since(start);
    if (s.ok())
      s = cmp::straighten(model->traced, domain, model->straight, model->map, options, &model->report);
    if (s.ok())
      s = model->surface.build(model->straight.net, domain, model->map);
    if (!s.ok())
    {
      model->error = s.message();
      std::cerr << model->name << ": " << s.message() << "\n";
      continue;
    }
    std::fprintf(stderr, "%s: %d vertices, traced %d, mapped on %d; trace %.2f s, straighten %.2f s, map %.2f s, applied %d %s, flipped %d\n",
      model->name.c_str(), model->file.mesh.vertexCount(), model->traced.mesh.vertexCount(),
      model->straight.net.mesh.vertexCount(), model->traceSeconds,
      model->report.straightenSeconds + model->report.parameterizeSeconds,
      model->report.mapSeconds, model->report.freeCurves.applied ? 1 : 0, model->report.freeCurves.reason.c_str(),
      model->map.flippedTriangles);
    remeshModels.push_back({ &model->file.mesh, &model->surface });
    placed.push_back(model.get());
  }

  cmp::RemeshOptions remeshOptions;
  remeshOptions.level = level;
  remeshOptions.sampleRelaxationIterations = relax;
  remeshOptions.repairFolds = repair;
  cmp::CollectionRemesh out;
  cmp::RemeshReport report;
  const Clock::time_point start = Clock::now();
  if (cmp::Status s = cmp::remesh(domain, remeshModels, out, remeshOptions, &report); !s.ok())
  {
    std::cerr << "remesh: " << s.message() << "\n";
    return 1;
  }
  const double remeshSeconds = since(start);
  if (!writeDir.empty())
  {
    fs::create_directories(writeDir);
    for (std::size_t i = 0; i < placed.size(); ++i)
    {
      writeOFF((fs::path(writeDir) / (placed[i]->name + ".remesh.off")).string(), out.models[i].positions,
        out.mesh.triangles);
      std::ofstream folds((fs::path(writeDir) / (placed[i]->name + ".folds.txt")).string());
      for (std::size_t t = 0; t < out.models[i].folded.size(); ++t)
        folds << int(out.models[i].folded[t]) << " " << int(out.models[i].centroidFlipped[t]) << "\n";
      std::ofstream hp((fs::path(writeDir) / (placed[i]->name + ".hausdorff.txt")).string());
      hp << report.models[i].hausdorffPoint.transpose() << "\n";
    }
  }

  std::printf("%-6s %7s %6s %6s %6s %6s %6s %7s %7s %7s %5s %7s %7s %6s %4s %6s\n", "model", "haus%", "folds", "cflip",
    "before", "minang", "qual", "distB", "distA", "distMax", "iter", "mapS", "totS", "net%", "near", "len");
  std::vector<double> distances;
  int folds = 0, flips = 0, worstFlips = 0, foldFree = 0, fewFlips = 0;
  double worstNet = 0.0;
  for (std::size_t i = 0; i < placed.size(); ++i)
  {
    const Model& m = *placed[i];
    const cmp::RemeshModelReport& r = report.models[i];
    const cmp::StraightenReport& s = m.report;
    const double net = 100.0 * (s.net.netLengthAfter / s.net.netLengthBefore - 1.0);
    worstNet = std::max(worstNet, net);
    std::printf("%-6s %7.3f %6d %6d %6d %6.2f %6.3f %7.3f %7.3f %7.1f %5d %7.2f %7.2f %6.1f %3d%s %6.2f\n", m.name.c_str(),
      100.0 * r.hausdorffDistanceRelative, r.foldedAfterRepair, r.centroidFlips, r.foldedBeforeRepair,
      r.minimumAngleDegrees, r.meanShapeQuality, s.freeCurves.map.distortionBefore, s.freeCurves.map.distortionAfter,
      s.freeCurves.map.maximumDistortion, s.freeCurves.map.iterations, s.mapSeconds, m.traceSeconds + s.seconds + r.seconds,
      net, r.hausdorffNearestFeature, r.hausdorffPointOnInput ? "i" : "r",
      s.net.netLengthAfter / std::sqrt(cmp::surfaceArea(m.file.mesh)));
    if (details)
    {
      std::fprintf(stderr, "%s folds near landmark:", m.name.c_str());
      for (std::size_t f = 0; f < out.models[i].foldsNearFeature.size(); ++f)
        if (out.models[i].foldsNearFeature[f] > 0)
          std::fprintf(stderr, " %zu:%d", f, out.models[i].foldsNearFeature[f]);
      std::fprintf(stderr, "\n");
    }
    distances.push_back(100.0 * r.hausdorffDistanceRelative);
    folds += r.foldedAfterRepair;
    flips += r.centroidFlips;
    worstFlips = std::max(worstFlips, r.centroidFlips);
    foldFree += r.foldedAfterRepair == 0 ? 1 : 0;
    fewFlips += r.centroidFlips <= 10 ? 1 : 0;
  }
  std::printf("L0 %s level %d: largest %.2f%%, median %.2f%%, under 1%%: %d of %zu; corner folds %d (%d models "
              "without), centroid flips %d (worst %d, %d models <= 10); net +%.1f%% at most; remesh %.1f s\n",
    l0.c_str(), level, distances.empty() ? 0.0 : *std::max_element(distances.begin(), distances.end()),
    median(distances), static_cast<int>(std::count_if(distances.begin(), distances.end(), [](double d) { return d < 1.0; })),
    distances.size(), folds, foldFree, flips, worstFlips, fewFlips, worstNet, remeshSeconds);
  return 0;
}
