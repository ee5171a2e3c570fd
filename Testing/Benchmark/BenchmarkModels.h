#pragma once
/// \file BenchmarkModels.h
/// \brief Which models the benchmark runs: the landmarked models of the
///        shared data folder and one of them refined to a large surface.

#include "BenchmarkStages.h"

#include <optional>
#include <string>
#include <vector>

namespace cmp::bench
{

/// \brief The landmarked models of the shared data folder: every
///        `shrec07-fourleg/NNN.off` with a matching `.vts`, by name, then
///        `spot/spot.obj` with `spot_shrec07.pinned`.
///
/// Models left out (no landmark file) are described in `skipped`.
std::vector<ModelSpec> discoverModels(const std::string& dataDir, std::vector<std::string>& skipped);

/// \brief The names in a comma-separated option value ("381,spot"), empty
///        ones dropped.
std::vector<std::string> splitCommas(const std::string& text);

/// \brief Number of 1-to-4 subdivisions that take `triangles` to at least
///        `minTriangles`.
int levelsToReach(long triangles, long minTriangles);

/// \brief The large model: the base model that reaches `minTriangles` with
///        the fewest subdivision levels and, among those, the fewest
///        triangles (the one closest above the target).
///
/// `triangleCounts[i]` is the triangle count of `models[i]` (<= 0 when
/// unknown, which excludes it). The result is named "<base>-sub<levels>".
std::optional<ModelSpec> chooseLargeModel(const std::vector<ModelSpec>& models, const std::vector<int>& triangleCounts,
  long minTriangles);

} // namespace cmp::bench
