#pragma once
/// \file GlobalMap.h
/// \brief One map of the whole surface onto the base domain, its curves
///        free: only the landmarks stay at their base vertices, every other
///        surface vertex moves across patch boundaries to lower the map's
///        distortion against equilateral base triangles of equal area, and
///        no step folds a triangle. The map is optimized in one piece, as a
///        seamless map of the surface cut open into a disk, and the surface
///        is then cut exactly along the map's own curves. Beyond the paper,
///        whose curves stay where straightening put them (see
///        Documentation/algorithm.md, "The map").

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
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
  /// \brief Newton steps at most.
  int maximumIterations = 100;
  /// \brief A full Newton step that lowers the energy by less than this
  ///        fraction ends the optimization (a step held back by a triangle
  ///        about to flatten does not: a crushed start gains little per step
  ///        at first).
  double leastRelativeGain = 1e-4;
  /// \brief Near the landmarks the map is asked to be closer to isometric:
  ///        each triangle's energy is multiplied by 1 + min(cap, (R / r)^2),
  ///        r the distance of its centroid from the nearest landmark and R
  ///        this radius in sides of the drawn base triangles (0: every
  ///        weight 1). A landmark is pinned, so an unweighted map tends to
  ///        pinch there: the landmark's ring is squeezed to one side and a
  ///        remesh triangle at that corner spans most of a turn round it, a
  ///        fold the remesh cannot avoid.
  double landmarkWeightRadius = 0.125;
  /// \brief The largest extra weight, `cap` above: uncapped, the triangles
  ///        at a landmark would weigh so much that a protrusion beside the
  ///        landmark is denied room.
  double landmarkWeightCap = 16.0;
  /// \brief Curved parts get more of L0: each surface triangle's metric is
  ///        inflated by s, s^2 = min(cap, 1 + c (kappa l)^2), c this value,
  ///        kappa the largest turn of the vertex normals along its sides per
  ///        length and l the side of a level-5 remesh triangle (0: the
  ///        surface as it is). Uniform remesh samples then reach into tips
  ///        of tails, ears and hooves, whose few flat-measured square
  ///        millimetres a low-distortion map would give little room.
  double curvatureDensity = 1.0;
  /// \brief The largest inflation s^2 above.
  double curvatureDensityCap = 16.0;
  /// \brief The shapes the map's base triangles are drawn with, the same
  ///        for every model of a collection, scaled to the surface's
  ///        (inflated) area: `Equilateral`, all alike; `BaseDomain`, L0's own
  ///        triangles (its vertex positions, the landmarks of the model it
  ///        was built from), so that each patch is asked for its model's
  ///        proportions.
  enum class TargetShapes
  {
    Equilateral,
    BaseDomain
  };
  TargetShapes targetShapes = TargetShapes::Equilateral;
  /// \brief Patches whose map is kept as it starts, so that their curves
  ///        stay where they are (the caps that close a surface's boundary
  ///        loops: the boundary must not move). Empty: none; else one entry
  ///        per base triangle, non-zero for a fixed patch. Every vertex
  ///        inside a fixed patch or on a curve between two fixed patches
  ///        keeps its starting place (on a cut curve, each of its places),
  ///        also through `freeCurves()`' cut, and so does every landmark.
  ///        A vertex on the curve of a base edge with a fixed patch on one
  ///        side only (a boundary stretch) slides along that edge instead:
  ///        one degree of freedom, its place a + t (b - a) in the free
  ///        patch's drawing (a, b the edge's ends), t optimized with the
  ///        rest. It stays on the edge to rounding (its place is reported in
  ///        the free patch, 0 at the opposite corner) and in its order along
  ///        it, so the curve keeps its vertices and `freeCurves()` cuts it as
  ///        it was; only their places along the edge move. Why: a boundary
  ///        pinned where the start put it (at arc length along the edge)
  ///        makes the map stretch unevenly along the boundary, and the
  ///        remesh folds there. The fixed patches' triangles have no say in
  ///        the energy, in the area the base triangles share (the other
  ///        patches' (inflated) area over the number of base triangles not
  ///        fixed) or in the report's figures; those with a sliding corner
  ///        are kept unflipped by the line search like every other (a cap's
  ///        triangle would flip where a sliding vertex passed its neighbour
  ///        along the edge). Having no say, they do not slow a sliding
  ///        vertex down as it nears them: one the Newton step would carry
  ///        past where a fixed triangle flattens is held to half that way,
  ///        the rest taking the Newton step given its, so that the line
  ///        search is not held to that one vertex's remaining way. Fails
  ///        (Status, naming `fixedPatches`) when it has neither 0 nor one
  ///        entry per base triangle, or fixes every patch.
  std::vector<char> fixedPatches;
};

/// \brief Checks `options`; the messages name the fields.
Status checkGlobalMapOptions(const GlobalMapOptions& options);

/// \brief What `optimizeGlobalMap()` did.
struct GlobalMapReport
{
  int iterations = 0;             ///< Newton steps made.
  double distortionBefore = 0.0;  ///< Area-weighted mean symmetric Dirichlet energy over its isometric value (1 best), before (against the inflated surface; fixed patches left out, as below).
  double distortionAfter = 0.0;   ///< The same after.
  double maximumDistortion = 0.0; ///< The largest per-triangle value after.
  int crossingVertices = 0;       ///< Vertices that left their patch's base triangle.
};

/// \brief Lowers the symmetric Dirichlet energy of the map `start` (per-patch
///        maps, as `parameterizePatches()` gives them) of `net`'s surface,
///        its curved parts inflated (`curvatureDensity`), onto `domain`,
///        each base triangle drawn equilateral with 1/F of the surface's
///        (inflated) area; `result` gets every vertex's new place (a base
///        triangle holding it and its barycentric coordinates there; a
///        vertex's triangle need no longer be its patch).
///
/// The surface is cut along the curves of a spanning tree of L0's edges
/// into a disk, and L0 along the same edges is drawn flat. A vertex on a
/// cut curve has one place per side, the two tied by the rigid motion that
/// glues L0's two triangles across that edge, so the map is seamless and
/// its curves move freely (Khodakovsky, Litke and Schroder 2003 glue their
/// charts the same way). Energy: sum over surface triangles of area x
/// weight x (|J|^2 + |J^-1|^2), J the map's differential, infinite for a
/// flipped triangle. Each step is a Newton step with every triangle's
/// Hessian projected onto its positive part through its singular values
/// (Smith, De Goes and Kim 2019), one sparse Cholesky factorization, and a
/// line search that never lets a triangle flip (its largest step is where
/// the first triangle would flatten), so the map stays bijective: no
/// triangle flips and each vertex keeps its angle sum.
///
/// \pre `start` is bijective on every patch (no flipped triangle) and `net`
///      is a layout of `domain` (every curve along mesh edges).
/// Fails, naming the problem, on options out of range
/// (`checkGlobalMapOptions()`; `fixedPatches` of the wrong size or fixing
/// every patch), sizes that disagree, a flipped starting map or a layout
/// that does not cut into a disk.
Status optimizeGlobalMap(const TracedNet& net, const BaseDomain& domain, const PatchParameterization& start,
  PatchParameterization& result, const GlobalMapOptions& options = {}, GlobalMapReport* report = nullptr);

/// \brief What `freeCurves()` did.
struct FreeCurvesReport
{
  GlobalMapReport map; ///< The global map's figures.
  bool applied = false; ///< Whether the net was cut anew (false: kept as straightened).
  std::string reason;   ///< Why not, when not applied.
};

/// \brief The straightened net with its curves moved where one
///        low-distortion map of the whole surface puts L0's edges:
///        `optimizeGlobalMap()` from the patch maps `map`, then the surface
///        cut exactly along the map's curves, the preimages of L0's edges
///        (every mesh edge a curve crosses is split where it crosses, every
///        triangle cut along it). `out` is that layout, `outMap` the map
///        itself on it: every vertex keeps its place, a new vertex lies on
///        its base edge, and every triangle lies in one base triangle, so
///        the remesher samples exactly the optimized map. A vertex closer
///        than 1e-6 of a base triangle's side to a curve is put on it.
///        Should the cut not give a layout equivalent to L0 (never seen of
///        a bijective map), `out` and `outMap` are `straight` and `map`
///        unchanged and the report says why (never an invalid layout).
///
/// Fails, naming the problem, where `optimizeGlobalMap()` fails.
Status freeCurves(const StraightenedNet& straight, const BaseDomain& domain, const PatchParameterization& map,
  const GlobalMapOptions& options, StraightenedNet& out, PatchParameterization& outMap,
  FreeCurvesReport* report = nullptr);

} // namespace cmp
