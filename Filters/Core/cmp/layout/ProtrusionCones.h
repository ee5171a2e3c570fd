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
  /// \brief Radius of the smallest ball round a tip whose area tells a
  ///        protrusion.
  double ballRadius = 0.075;
  /// \brief Balls of `ballRadius` times 1, 2, 4, ... (this many, 1 to 8)
  ///        are tried, the larger ones only up to half the tip's depth: a
  ///        tail thick at its tip (a tuft, a club) is thin against a larger
  ///        ball.
  int ballScales = 3;
  /// \brief A protrusion's ball holds less than this share of a flat disk
  ///        of its radius (a cylinder of girth c capped at the tip holds
  ///        about c r of pi r^2, so at every radius this asks for a girth
  ///        under about r) and caps the surface: the landmarks outside the
  ///        ball all lie in one piece of the surface outside it, which round
  ///        the middle of a thin leg or tail with a landmark at its end they
  ///        do not.
  ///        Measured on the SHREC'07 four-legged models and the CGAL
  ///        quadrupeds, at 0.075: long thin tails 0.11 to 0.28, ears 0.2 to
  ///        0.44, tufted or club tails 0.43 and 0.51 (the triceratops', the
  ///        bull's: 0.28 and 0.29 at 0.15), a thick tail (384) 0.6 (0.45 at
  ///        0.15, not found), flanks 0.7 and more, the middle of a camel's
  ///        leg 0.72 (0.43 at 0.15, beyond half its depth; its foot
  ///        landmark outside apart).
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
  double ballRadius = 0.0; ///< The radius of that ball (the first that told it), over sqrt(area).
};

/// \brief The landmark-free protrusions of `surface`: tips (vertices the
///        farthest from every landmark within `peakRadius`, at least
///        `leastDepth` away) with a ball of `ballRadius` x 1, 2, 4, ...
///        (`ballScales` of them, the larger up to half the tip's depth)
///        that holds less
///        than `largestBallShare` of a flat disk and caps the surface,
///        farthest first. A peak inside the ball of a deeper protrusion
///        (a second bump of a tufted tail) is that protrusion. On a surface
///        with boundaries no tip lies on a boundary loop (a landmark there
///        would be a boundary landmark, which L0 has only on its holes).
/// \pre `landmarks` are vertices of `surface`, none missing.
/// Fails (Status) on an empty surface, a missing or out-of-range landmark
/// or options out of range (lengths not positive, `ballScales` outside 1
/// to 8, `leastModels` < 1).
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
  /// \brief A protrusion that got no cone because the models disagree
  ///        where it leaves the body.
  struct Disagreement
  {
    int root = -1;          ///< The protrusion's root feature.
    int model = -1;         ///< A model whose tip lies elsewhere.
    int triangle = -1;      ///< The base triangle holding that tip.
    int splitTriangle = -1; ///< The triangle the cone would have split.
  };
  /// \brief Each such protrusion (the first model that disagreed).
  std::vector<Disagreement> disagreeing;
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
/// at the tip (Documentation/known-issues.md, the map's section). A cone
/// is added only where every model with the protrusion has its tip in the
/// split triangle or one sharing an edge with it; where the chosen triangle
/// leaves one apart, the triangle that every tip lies in or beside (the
/// one holding the most tips) is split instead, if there is one
/// (`disagreeing` lists the others: a tail raised where the others' hang
/// would have to be turned round its root across two curves by the map,
/// which did not settle). A protrusion nearest to a boundary landmark gets
/// no cone. Where two cones' tips lie in one base triangle only the one
/// more models have is added, and cones are added (the most shared first)
/// only while some model has every feature and every cone added, so that
/// the Missing Landmark Placer can place the rest from it. Without cones, `domain` is that L0 and `landmarks` are
/// unchanged.
///
/// Surfaces with boundaries (OpenSurface.h): L0 is then open, and each
/// model is traced over it closed (`closeBaseDomain()`, `closeSurface()`,
/// the caps' curves given), as every later stage runs it; a cone splits a
/// triangle of the open L0 (never a cap's), so `domain` is open with the
/// same holes. A tail is as landmark-free on a head cut open at the neck
/// as on a whole animal.
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
/// (`checkBaseDomain()`, or `closeBaseDomain()` for an open one), the landmark lists differ in length from F or
/// do not fit their surfaces, or the options are out of range.
Status addProtrusionCones(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const BaseDomain& given, BaseDomain& domain, const ProtrusionConeOptions& options = {},
  ProtrusionConeReport* report = nullptr);

} // namespace cmp
