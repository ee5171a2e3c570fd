#pragma once
/// \file GlobalMap.h
/// \brief One map of the whole surface onto the base domain, its curves
///        free: only the landmarks stay at their base vertices, every other
///        surface vertex moves across patch boundaries to lower the map's
///        distortion against equilateral base triangles of equal area, and
///        no step folds a triangle. Beyond the paper, whose curves stay where
///        straightening put them (see Documentation/algorithm.md, "The map").

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/BaseCharts.h>
#include <cmp/map/NetStraightener.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/Status.h>

#include <string>
#include <vector>

namespace cmp
{

/// \brief Tuning of `optimizeGlobalMap()`.
struct GlobalMapOptions
{
  /// \brief Gauss-Seidel sweeps over the vertices at most.
  int maximumSweeps = 200;
  /// \brief A sweep that lowers the energy by less than this fraction ends
  ///        the optimization.
  double leastRelativeGain = 1e-4;
  /// \brief Rounds of star solves at most (before the sweeps); a round
  ///        that lowers the energy by less than `leastRelativeGain` ends
  ///        them.
  int starRounds = 4;
  /// \brief SLIM steps per star solve at most.
  int starIterations = 50;
  /// \brief Near the landmarks the sweeps ask the map to be closer to
  ///        isometric (the star solves before them are unweighted: weighted,
  ///        they denied a tail or an ear beside a landmark its room): each
  ///        triangle's energy is multiplied by 1 + min(cap, (R / r)^2),
  ///        r the distance of its centroid from the nearest landmark and R
  ///        this radius in sides of the drawn base triangles (0: every
  ///        weight 1). A landmark is pinned, so an unweighted map tends to
  ///        pinch there: the landmark's ring is squeezed to one side in the
  ///        chart and a remesh triangle at that corner spans most of a turn
  ///        round it, a fold the remesh cannot avoid.
  double landmarkWeightRadius = 0.125;
  /// \brief The largest extra weight, `cap` above: uncapped, the triangles
  ///        at a landmark would weigh so much that the sweeps crawl and a
  ///        protrusion beside the landmark is denied room.
  double landmarkWeightCap = 16.0;
};

/// \brief What `optimizeGlobalMap()` did.
struct GlobalMapReport
{
  int sweeps = 0;             ///< Sweeps made.
  int starRounds = 0;         ///< Rounds of star solves made.
  double distortionBefore = 0.0; ///< Area-weighted mean symmetric Dirichlet energy over its isometric value (1 best), before.
  double distortionAfter = 0.0;  ///< The same after.
  double maximumDistortion = 0.0; ///< The largest per-triangle value after.
  int crossingVertices = 0;   ///< Vertices that left their patch's base triangle.
};

/// \brief Lowers the symmetric Dirichlet energy of the map `map` (the
///        straightener's per-patch maps, as `parameterizePatches()` gives
///        them) of `net`'s surface onto `domain`, each base triangle drawn
///        equilateral with 1/F of the surface's area, letting vertices cross
///        the curves; returns every vertex's new place in `points`.
///
/// Energy: sum over surface triangles of area x (|J|^2 + |J^-1|^2), J the
/// map's differential, measured in a chart of the base triangles around
/// the triangle's corners (`BaseCharts`): infinite for a triangle flipped
/// or crushed. Every accepted move also keeps each triangle it touches
/// unflipped in every chart of its corners' base triangles, and no triangle
/// without a corner at a base vertex may reach more than half a turn round
/// it (the map would wrap round the landmark, which no cut can follow), so
/// the map stays bijective.
///
/// Moves, in two phases:
/// - star solves (Praun and Hoppe 2003, Schreiner et al. 2004, with SLIM
///   steps for each star): `starRounds` rounds over the base vertices;
///   each relaxes together every vertex whose ring lies in that vertex's
///   star, in the star unfolded flat round it (opened along one spoke,
///   another each round), the rest held. Global per star, so a squeezed
///   protrusion (a tail) gets room in one solve. A solve that leaves a
///   triangle flipped in one of its corners' charts is tried again with
///   those vertices held, then skipped;
/// - then Gauss-Seidel sweeps: each free vertex in turn, down its energy's
///   gradient with a Newton step length along it, halved until its
///   triangles' energy falls; each triangle's energy weighted by its
///   nearness to a landmark (`landmarkWeightRadius`), so that no landmark's
///   ring is pinched to one side of it.
///
/// \pre `map` is bijective on every patch (no flipped triangle).
/// Fails, naming the problem, if sizes disagree or a triangle of the
/// starting map is flipped. Cost: linear in the surface per sweep.
Status optimizeGlobalMap(const TracedNet& net, const BaseDomain& domain, const BaseCharts& charts,
  const PatchParameterization& map, std::vector<BasePoint>& points, const GlobalMapOptions& options = {},
  GlobalMapReport* report = nullptr);

/// \brief What `freeCurves()` did.
struct FreeCurvesReport
{
  GlobalMapReport map; ///< The global map's figures.
  bool applied = false; ///< Whether the net was cut anew (false: kept as straightened).
  std::string reason;   ///< Why not, when not applied.
};

/// \brief The straightened net with its curves moved where one
///        low-distortion map of the whole surface puts L0's edges:
///        `optimizeGlobalMap()` from the patch maps `map`, then
///        `cutAlongMap()`; the patch maps are the global map's own places,
///        with any triangle the cut's rounding flipped placed anew among
///        its neighbours (mean value weights a few rings round it, then a
///        symmetric Dirichlet relaxation of those vertices). Only if that
///        fails is every patch parameterized anew on its new curves
///        (`parameterizePatches()` with `options`). Where the cut
///        would not give an equivalent layout or a patch map flips, `out`
///        and `outMap` are `straight` and `map` unchanged and the report
///        says why (never an invalid layout).
Status freeCurves(const StraightenedNet& straight, const BaseDomain& domain, const PatchParameterization& map,
  const GlobalMapOptions& mapOptions, const PatchParameterizationOptions& options, StraightenedNet& out,
  PatchParameterization& outMap, FreeCurvesReport* report = nullptr);

} // namespace cmp
