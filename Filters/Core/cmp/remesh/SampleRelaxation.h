#pragma once
/// \file SampleRelaxation.h
/// \brief Moves the base-domain locations of a semi-regular remesh's
///        vertices towards where the surface area of a collection's models
///        lies, so that uniform refinement reaches into protrusions its
///        regular samples miss; one set of locations for every model, so the
///        connectivity and the correspondence stay shared.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/numerics/Communicator.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/Status.h>

#include <vector>

namespace cmp
{

/// \brief Tuning of `relaxSampleLocations()`.
struct SampleRelaxationOptions
{
  /// \brief Rounds of moves; 0 leaves the locations as built. What more
  ///        rounds gain is measured in
  ///        Documentation/filters/SemiRegularRemesher.md, "Sample relaxation".
  int iterations = 4;
  /// \brief Fraction of the way to its target a vertex moves in one round,
  ///        in (0, 1]; halved, up to 10 times, while one of its triangles
  ///        would turn clockwise (then the vertex stays).
  double step = 0.5;
};

/// \brief What `relaxSampleLocations()` did.
struct SampleRelaxationReport
{
  int iterations = 0;       ///< Rounds made.
  int movedVertices = 0;    ///< Vertices moved in the last round.
  double largestMove = 0.0; ///< Largest move in the last round, in barycentric units of its base triangle.
};

/// \brief Moves every vertex inside a base triangle towards the centroid of
///        the surface area its triangles cover, summed over `models`, each
///        model weighing the same in each base triangle, and slides every
///        vertex inside a base edge along it, towards the mean place along
///        the edge of that area; the landmarks stay.
///
/// Each surface triangle counts as its area times its area density (surface
/// area over the area of its image in the base domain), at its image's
/// centroid: a Lloyd-like step whose fixed point gives every remesh
/// triangle about the same surface area, where a plain area weight would
/// give it the square root. A move that would turn one of the vertex's
/// triangles clockwise in the base domain is shortened, so the remesh stays
/// a valid layout of every base triangle. Connectivity and numbering are
/// unchanged, and every vertex stays in its base triangle or on its base
/// edge; only `remesh.locations` moves.
///
/// The models may be spread over the processes of `communicator` (each
/// passing its own, possibly none, and the same remesh and options); the
/// area is summed over all of them, so every process moves the locations
/// the same way, bit for bit (equal to one process holding every model up
/// to the rounding of the sums). Collective.
///
/// Beyond the paper, whose remesh keeps the quadrisection's places.
///
/// \pre `remesh` was built on `domain` (`buildSemiRegularMesh()` or
///      `buildAdaptiveSemiRegularMesh()`) and every model was built over
///      `domain` (`ParameterizedSurface::build()`).
/// Fails (Status), naming the problem, on every process and without touching
/// `remesh`, if no process has a model, if a model was not built, if the
/// remesh does not belong to `domain` (a vertex outside the base triangle
/// of one of its triangles), if an option is out of range or if the
/// processes pass different remeshes or options (an adaptive remesh
/// refined on each process's own models).
/// Cost per round: linear in the models' triangles and the remesh's, plus
/// one sum over processes of three numbers per remesh triangle.
Status relaxSampleLocations(const BaseDomain& domain, const std::vector<const ParameterizedSurface*>& localModels,
  Communicator& communicator, SemiRegularMesh& remesh, const SampleRelaxationOptions& options = {},
  SampleRelaxationReport* report = nullptr);

/// \brief `relaxSampleLocations()` for a collection held by one process:
///        same preconditions and failures.
Status relaxSampleLocations(const BaseDomain& domain, const std::vector<const ParameterizedSurface*>& models,
  SemiRegularMesh& remesh, const SampleRelaxationOptions& options = {}, SampleRelaxationReport* report = nullptr);

} // namespace cmp
