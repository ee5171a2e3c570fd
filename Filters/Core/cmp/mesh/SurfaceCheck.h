#pragma once
/// \file SurfaceCheck.h
/// \brief The input check every stage runs: is this a closed, oriented,
///        genus-0 triangle surface without degenerate or NaN geometry?

#include <cmp/mesh/TriangleMesh.h>

#include <string>

namespace cmp
{

/// \brief The first defect `checkSurface()` found, in the order it checks.
enum class SurfaceDefect
{
  None,                    ///< The surface is usable.
  Empty,                   ///< No points or no triangles.
  NonFiniteCoordinate,     ///< A coordinate is NaN or infinite.
  IndexOutOfRange,         ///< A triangle names a vertex that does not exist.
  RepeatedVertex,          ///< A triangle uses the same vertex twice.
  DegenerateTriangle,      ///< A triangle has (near) zero area.
  UnusedVertex,            ///< A point belongs to no triangle.
  BoundaryEdge,            ///< An edge has one triangle: the surface is open.
  NonManifoldEdge,         ///< An edge has more than two triangles.
  InconsistentOrientation, ///< Two triangles traverse an edge the same way.
  NonManifoldVertex,       ///< The triangles around a vertex form several fans.
  SeveralComponents,       ///< The surface is not connected.
  WrongGenus               ///< The surface has handles (genus > 0).
};

/// \brief Outcome of `checkSurface()`.
struct SurfaceCheckResult
{
  SurfaceDefect defect = SurfaceDefect::None; ///< What is wrong, if anything.
  std::string message;                        ///< Human readable, names where.
  /// \brief True when the surface passed every check.
  bool ok() const { return defect == SurfaceDefect::None; }
};

/// \brief What `checkSurface()` looks at.
struct SurfaceCheckOptions
{
  /// \brief Check coordinates (NaN, degenerate triangles). Off for a base
  ///        domain, whose geometry is only a picture.
  bool checkGeometry = true;
  /// \brief A triangle whose area is below this fraction of the squared
  ///        bounding-box diagonal counts as degenerate.
  double degenerateAreaFraction = 1e-14;
  /// \brief Required genus (the paper handles genus 0).
  int requiredGenus = 0;
};

/// \brief Checks that `mesh` is a closed, edge- and vertex-manifold,
///        consistently oriented, connected surface of the required genus with
///        finite, non-degenerate geometry.
///
/// Runs in O(n log n). Reports the first failing check with a message that
/// names the offending element and how many there are, for example
/// "open surface: 12 boundary edges, e.g. edge (3, 17)".
SurfaceCheckResult checkSurface(const TriangleMesh& mesh, const SurfaceCheckOptions& options = {});

/// \brief Short, stable name of a defect ("boundary-edge", ...), for reports.
const char* defectName(SurfaceDefect defect);

} // namespace cmp
