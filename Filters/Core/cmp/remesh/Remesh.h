#pragma once
/// \file Remesh.h
/// \brief The remesh stage in one call (paper Section 2): one semi-regular
///        connectivity for a collection of parameterized models, placed on
///        each of them, with its folds repaired and its shape and distance
///        to each model measured.
///
/// `remesh()` does the whole stage: build the connectivity (uniform, or
/// adaptive over every model), relax its samples over every model, place it
/// on each model, repair folds, and measure quality and distance. Its parts
/// (`buildSemiRegularMesh()`, `relaxSampleLocations()`, `placeOnSurface()`,
/// `repairFolds()`, ...) stay available for a caller who needs one alone.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>
#include <cmp/numerics/Communicator.h>
#include <cmp/remesh/FoldRepair.h>
#include <cmp/remesh/SemiRegularRemesher.h>

#include <functional>
#include <vector>

namespace cmp
{

/// \brief What `remesh()` builds and measures.
struct RemeshOptions
{
  /// \brief Quadrisections of L0, 0 to `kMaximumRemeshLevel`; with
  ///        `adaptiveTolerance`, the maximum level.
  int level = 4;
  /// \brief 0: uniform refinement. t > 0: adaptive, a triangle is split
  ///        while on any model the surface at one of its edge midpoints or
  ///        its centroid is farther than t times that model's bounding-box
  ///        diagonal from the flat triangle (`flatnessSplitRule()`). With
  ///        `computeDistance`, the tolerance holds for the remesh as placed
  ///        (relaxed and repaired), as far as `level` allows: where on some
  ///        model it lies farther than t times the diagonal
  ///        (`trianglesFartherThan()`), the triangles there are split once
  ///        more and the connectivity made again, three times at most in all
  ///        (`RemeshReport::adaptivePasses`).
  double adaptiveTolerance = 0.0;
  /// \brief Rounds of `relaxSampleLocations()` over every model (0: none;
  ///        its other options at their defaults).
  int sampleRelaxationIterations = 0;
  /// \brief Unfold triangles that face against their model
  ///        (`repairFolds()` with `foldRepair`).
  bool repairFolds = true;
  /// \brief The fold repair's own options.
  FoldRepairOptions foldRepair;
  /// \brief Measure each remesh's sampled two-sided distance to its model.
  bool computeDistance = true;
  /// \brief Threads that place the models at once (0: one per hardware
  ///        thread), at most one per model. The result does not depend on
  ///        it; the threads have ended when `remesh()` returns.
  int threads = 0;
  /// \brief Per base triangle of the domain, 1 for a hole's (a cap that
  ///        `closeBaseDomain()` added to an open L0): the remesh leaves
  ///        those triangles out (`removeHoleTriangles()`), so its boundary
  ///        vertices lie on the models' boundaries. Empty: none.
  std::vector<char> holeTriangles;
  /// \brief Called with the fraction (0 to 1) of the models placed, if set,
  ///        always on the calling thread.
  std::function<void(double)> progress;
};

/// \brief Checks the options `remesh()` checks first. The messages name the
///        options as the Semi-Regular Remesher's properties do (`Level`,
///        `AdaptiveTolerance`, `SampleRelaxationIterations`), so that a
///        filter can pass them on as they are. Fails (Status) on a level
///        outside 0 to `kMaximumRemeshLevel`, a negative or non-finite
///        tolerance, or negative relaxation rounds; the fold repair's
///        options are checked by `repairFolds()`.
Status checkRemeshOptions(const RemeshOptions& options);

/// \brief One model to remesh.
struct RemeshModel
{
  /// \brief The model's surface as given: distances are measured to it.
  const TriangleMesh* surface = nullptr;
  /// \brief Its layout and parameterization, indexed (built on the layout
  ///        of `surface`, over the domain given to `remesh()`).
  const ParameterizedSurface* map = nullptr;
};

/// \brief The shared remesh placed on one model.
struct RemeshedModel
{
  std::vector<SurfacePoint> samples; ///< Where each remesh vertex lies on the model's layout.
  std::vector<Vec3> positions;        ///< Their positions.
  std::vector<char> folded;           ///< Per triangle: 1 if it faces against the model (after repair).
  /// \brief Per triangle: 1 if it faces against the model by the centroid
  ///        criterion (`centroidFlippedTriangles()`, after repair).
  std::vector<char> centroidFlipped;
  /// \brief Per landmark (FeatureId order), the folded triangles nearest to
  ///        it in remesh edges (`foldsNearLandmarks()`): which landmark to
  ///        move, or to add one beside.
  std::vector<int> foldsNearFeature;
};

/// \brief What `remesh()` makes: one connectivity, placed on every model.
struct CollectionRemesh
{
  SemiRegularMesh mesh;               ///< The connectivity and base locations shared by every model.
  std::vector<RemeshedModel> models;  ///< Per model, in the order given.
};

/// \brief What `remesh()` measured on one model.
struct RemeshModelReport
{
  int foldedBeforeRepair = 0;     ///< Folded triangles before repair (`foldedAfterRepair` without repair).
  int foldedAfterRepair = 0;      ///< Folded triangles left, the ones `RemeshedModel::folded` marks.
  /// \brief Triangles flipped by the centroid criterion after repair, the
  ///        ones `RemeshedModel::centroidFlipped` marks.
  int centroidFlips = 0;
  FoldRepairReport repair;        ///< The fold repair's own report (zero without repair).
  double minimumAngleDegrees = 0.0; ///< Smallest corner angle of the placed remesh.
  double meanShapeQuality = 0.0;  ///< Mean `triangleShapeQuality()` of the placed remesh.
  bool distanceMeasured = false;  ///< Whether the figures below were measured (`computeDistance`).
  double hausdorffDistance = 0.0; ///< Sampled two-sided Hausdorff distance to the model.
  double hausdorffDistanceRelative = 0.0; ///< The same over the model's bounding-box diagonal (0 if it is 0).
  double meanDistance = 0.0;      ///< Mean of the two one-sided mean distances.
  Vec3 hausdorffPoint = Vec3::Zero(); ///< Where the Hausdorff distance is reached.
  bool hausdorffPointOnInput = false; ///< Whether that point is on the model (a part the remesh misses).
  /// \brief The landmark (FeatureId) nearest to `hausdorffPoint` in
  ///        straight-line distance, -1 if the layout has none: a part the
  ///        remesh misses (a tail's tip) wants a landmark there.
  int hausdorffNearestFeature = -1;
  double hausdorffFeatureDistanceRelative = 0.0; ///< Its distance over the diagonal.
  double placementSeconds = 0.0;  ///< Placement, fold repair and positions.
  double foldRepairSeconds = 0.0; ///< The fold repair alone.
  double distanceSeconds = 0.0;   ///< The distance alone.
  double seconds = 0.0;           ///< All of this model's work.
};

/// \brief What `remesh()` did.
struct RemeshReport
{
  int sampleRelaxationRounds = 0;       ///< Rounds of sample relaxation made (in the last pass).
  /// \brief Adaptive remeshing: how many times the connectivity was made
  ///        (1 when the first placed remesh is within the tolerance on every
  ///        model; 0 for a uniform remesh).
  int adaptivePasses = 0;
  /// \brief Adaptive remeshing: the connectivity's triangles after each
  ///        pass (the last one is the result's).
  std::vector<int> adaptiveTriangles;
  double sampleRelaxationSeconds = 0.0; ///< Their time (the whole collection's).
  /// \brief The model whose placement or fold repair failed, -1 if none
  ///        did (the message then is that model's).
  int failedModel = -1;
  std::vector<RemeshModelReport> models; ///< Per model, in the order given.
};

/// \brief Remeshes a collection with one connectivity (paper Section 2):
///        `domain` refined `options.level` times (uniformly, or adaptively
///        where any model needs it), its samples relaxed over every model,
///        then placed on each model through its parameterization, folds
///        repaired, shape and distance measured.
///
/// \pre `domain` is the L0 every model was parameterized over; each model's
///      `map` was built on the layout of its `surface` over `domain`.
///
/// The models may be spread over the processes of `communicator`, each
/// passing its own (possibly none) and the same options: with sample
/// relaxation the call is collective, and a process that fails before the
/// relaxation (options, a missing model, adaptive refinement) makes every
/// process fail with its message, so that none waits for the others.
/// Without relaxation no process waits for another. An adaptive remesh
/// made again where it is far from a model (`adaptiveTolerance` with
/// `computeDistance`) is made again only with relaxation when there are
/// several processes; they then agree on each pass's placement, and a pass
/// after the first that fails anywhere leaves the previous one standing.
///
/// Fails (Status), naming the problem, on options out of range
/// (`checkRemeshOptions()`), a model that is missing or not built, a
/// `domain` that fails `checkBaseDomain()`, a failed sample relaxation
/// ("sample relaxation: ...", `relaxSampleLocations()`), and when a model's
/// placement or fold repair fails (`report->failedModel` says which). `out`
/// is complete only on success. The connectivity by quadrisection, uniform
/// or adaptive, is the paper's (§2); sample relaxation, fold repair and the
/// distances are beyond it.
Status remesh(const BaseDomain& domain, const std::vector<RemeshModel>& localModels, Communicator& communicator,
  CollectionRemesh& out, const RemeshOptions& options = {}, RemeshReport* report = nullptr);

/// \brief `remesh()` for a collection held by one process: same
///        preconditions and failures.
Status remesh(const BaseDomain& domain, const std::vector<RemeshModel>& models, CollectionRemesh& out,
  const RemeshOptions& options = {}, RemeshReport* report = nullptr);

/// \brief `remesh()` for one model given by its layout `net` (the
///        straightener's) and `parameterization` (the per-patch map's);
///        `surface` is the model as given, for the distances. Fails as
///        `remesh()` does, and where `ParameterizedSurface::build()` fails.
Status remesh(const TriangleMesh& surface, const TracedNet& net, const BaseDomain& domain,
  const PatchParameterization& parameterization, CollectionRemesh& out, const RemeshOptions& options = {},
  RemeshReport* report = nullptr);

} // namespace cmp
