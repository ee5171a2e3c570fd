#include "BenchmarkModels.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace cmp::bench
{
namespace
{

namespace fs = std::filesystem;

/// \brief Every `*.off` in `folder` with a `.vts` beside it.
void addFourLegged(const fs::path& folder, std::vector<ModelSpec>& models, std::vector<std::string>& skipped)
{
  if (!fs::is_directory(folder))
  {
    skipped.push_back(folder.string() + ": folder not found");
    return;
  }
  std::vector<fs::path> meshes;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
  {
    if (entry.path().extension() == ".off")
      meshes.push_back(entry.path());
  }
  std::sort(meshes.begin(), meshes.end());
  for (const fs::path& mesh : meshes)
  {
    fs::path landmarks = mesh;
    landmarks.replace_extension(".vts");
    if (fs::exists(landmarks))
      models.push_back({ mesh.stem().string(), mesh.string(), landmarks.string(), 0 });
    else
      skipped.push_back(mesh.stem().string() + ": no landmark file");
  }
}

void addSpot(const fs::path& folder, std::vector<ModelSpec>& models, std::vector<std::string>& skipped)
{
  const fs::path mesh = folder / "spot.obj";
  const fs::path landmarks = folder / "spot_shrec07.pinned";
  if (fs::exists(mesh) && fs::exists(landmarks))
    models.push_back({ "spot", mesh.string(), landmarks.string(), 0 });
  else
    skipped.push_back("spot: spot.obj or spot_shrec07.pinned not found");
}

long triangleCountAfter(long triangles, int levels)
{
  for (int i = 0; i < levels; ++i)
    triangles *= 4;
  return triangles;
}

} // namespace

std::vector<ModelSpec> discoverModels(const std::string& dataDir, std::vector<std::string>& skipped)
{
  std::vector<ModelSpec> models;
  addFourLegged(fs::path(dataDir) / "shrec07-fourleg", models, skipped);
  addSpot(fs::path(dataDir) / "spot", models, skipped);
  return models;
}

std::vector<std::string> splitCommas(const std::string& text)
{
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, ','))
  {
    if (!part.empty())
      parts.push_back(part);
  }
  return parts;
}

int levelsToReach(long triangles, long minTriangles)
{
  int levels = 0;
  while (triangles > 0 && triangleCountAfter(triangles, levels) < minTriangles)
    ++levels;
  return levels;
}

std::optional<ModelSpec> chooseLargeModel(const std::vector<ModelSpec>& models, const std::vector<int>& triangleCounts,
  long minTriangles)
{
  std::optional<ModelSpec> best;
  long bestTriangles = 0;
  for (std::size_t i = 0; i < models.size() && i < triangleCounts.size(); ++i)
  {
    if (triangleCounts[i] <= 0)
      continue;
    const int levels = levelsToReach(triangleCounts[i], minTriangles);
    const long triangles = triangleCountAfter(triangleCounts[i], levels);
    // Fewest levels first (a shallower refinement is closer to a real
    // scan's mesh), then the smallest surface above the target.
    if (best && (levels > best->subdivisionLevels ||
                  (levels == best->subdivisionLevels && triangles >= bestTriangles)))
      continue;
    best = models[i];
    best->subdivisionLevels = levels;
    best->name = models[i].name + "-sub" + std::to_string(levels);
    bestTriangles = triangles;
  }
  return best;
}

} // namespace cmp::bench
