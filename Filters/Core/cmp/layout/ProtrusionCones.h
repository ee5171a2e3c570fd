#pragma once
/// \file ProtrusionCones.h
/// \brief Cones at the tips of landmark-free protrusions (tails): an extra
///        vertex of L0 where the collection has such a protrusion, so that
///        the map does not have to squeeze a long cylinder into the inside
///        of one base triangle (beyond the paper).

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/io/Landmarks.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief How protrusions are found and when they get a cone. Lengths are
///        in square roots of the surface's area, along mesh edges.
struct ProtrusionConeOptions
{
  /// \brief A tip lies at least this far from every landmark.
  double leastDepth = 0.05;
  /// \brief A tip is the farthest from the landmarks within this distance.
  double peakRadius = 0.02;
  /// \brief Radius of the ball round a tip whose area tells a protrusion.
  double ballRadius = 0.075;
  /// \brief A protrusion's ball holds less than this share of a flat disk
  ///        of that radius (a cylinder of girth c holds about c r of pi
  ///        r^2). Measured on the SHREC'07 four-legged models: long thin
  ///        tails 0.14 to 0.28, ears 0.2 to 0.44 (nearest to the head's
  ///        landmark, two of them), a thick tail (384) 0.6, flanks and legs
  ///        0.6 and more.
  double largestBallShare = 0.32;
  /// \brief A cone where at least this many models have exactly one
  ///        protrusion nearest to the same landmark (1 or more).
  int leastModels = 2;
};

/// \brief A landmark-free protrusion of one surface.
struct Protrusion
{
  int vertex = -1;         ///< Its tip.
  int nearestFeature = -1; ///< The feature whose landmark is nearest to the tip (its root).
  double depth = 0.0;      ///< The tip's distance from the nearest landmark, over sqrt(area).
  double ballShare = 0.0;  ///< Its ball's area over the flat disk's.
};

/// \brief The landmark-free protrusions of `surface`: tips (vertices the
///        farthest from every landmark within `peakRadius`, at least
///        `leastDepth` away) whose ball of `ballRadius` holds less than
///        `largestBallShare` of a flat disk, farthest first.
/// \pre `landmarks` are vertices of `surface`, none missing.
/// Fails (Status) on an empty surface, a missing or out-of-range landmark
/// or options out of range (lengths not positive, `leastModels` < 1).
Status findProtrusions(const TriangleMesh& surface, const LandmarkList& landmarks,
  std::vector<Protrusion>& protrusions, const ProtrusionConeOptions& options = {});

/// \brief What `addProtrusionCones()` did.
struct ProtrusionConeReport
{
  /// \brief Per model, the protrusions found (none on a model that misses
  ///        landmarks: it is not searched).
  std::vector<std::vector<Protrusion>> protrusions;
  /// \brief Per cone (features F, F + 1, ... after the files' F): the
  ///        feature whose landmark is its root.
  std::vector<int> roots;
  /// \brief Per cone, the model whose tip chose the base triangle split.
  std::vector<int> tipModels;
  /// \brief Per cone, that triangle, in the L0 built from the files'
  ///        landmarks.
  std::vector<int> splitTriangles;
};

/// \brief Builds L0 from model `baseDomainModel` with a cone at the tip of
///        each landmark-free protrusion the collection shares, and adds the
///        cones to every model's landmarks.
///
/// Each model with every landmark is searched (`findProtrusions()`). A cone
/// is added for each feature f whose landmark is nearest to exactly one
/// protrusion on at least `leastModels` models; on those models the tip is
/// the cone's landmark, on the others it is `kMissingLandmark` (the
/// Missing Landmark Placer places it from the models that have it). L0 is
/// built from `baseDomainModel`'s own landmarks (`buildBaseDomain()`), and
/// each cone splits in three the base triangle whose patch holds its tip
/// when the tip's model is traced over that L0 (`traceFeatureNet()`; the
/// tip of `baseDomainModel` when it has one, else of the first model that
/// has one and traces over it), so its star is a thin fan up the protrusion to the landmarks
/// round its root. Joined by decimation instead, a tail curled back to
/// the hind legs got a cone joined across the body, and the maps folded
/// at the tip (Documentation/known-issues.md, the map's section). Where
/// two cones' tips lie in one base triangle only the one more models have
/// is added. Without cones, `domain` is that L0 and `landmarks` are
/// unchanged.
/// \pre Every model has the same number of features; `baseDomainModel`
///      has all of them.
/// Fails (Status) when the landmark lists differ in length or do not fit
/// their surfaces, `baseDomainModel` is out of range or misses landmarks,
/// the options are out of range, or L0 cannot be built or the tip's
/// model cannot be traced over it.
Status addProtrusionCones(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  int baseDomainModel, BaseDomain& domain, const ProtrusionConeOptions& options = {},
  ProtrusionConeReport* report = nullptr);

/// \brief The same on a given L0 (a template, or one built earlier): the
///        cones split triangles of `given`, which keeps its vertices, edges
///        and other triangles, so a remesh over `domain` still has `given`'s
///        landmarks at the same vertices.
///
/// Each cone's base triangle is the one whose patch holds the tip on most
/// of the models that have it, each traced over `given` (a tie goes to the
/// triangle of the earliest model; a model that cannot be traced over
/// `given` has no say, and a cone no model with it can be traced for is
/// not added). `report.tipModels` names the first model in the chosen
/// triangle. Without cones, `domain` is `given` and `landmarks` are
/// unchanged. Why a given L0 needs cones as much: the published template
/// of the shared data has no tail vertex either, and its maps fold at the
/// tails' roots as a built L0's do (Documentation/filters/ProtrusionCones.md).
/// \pre Every model has one entry per vertex of `given`.
/// Fails (Status) when `given` is not a base domain of F features
/// (`checkBaseDomain()`), the landmark lists differ in length from F or
/// do not fit their surfaces, or the options are out of range.
Status addProtrusionCones(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const BaseDomain& given, BaseDomain& domain, const ProtrusionConeOptions& options = {},
  ProtrusionConeReport* report = nullptr);

} // namespace cmp
