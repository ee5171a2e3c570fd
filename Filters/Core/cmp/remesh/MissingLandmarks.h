#pragma once
/// \file MissingLandmarks.h
/// \brief Places the features a model of a collection misses where the
///        collection's consistent maps carry them from the models that have
///        them, so that every model then gets the full L0 and the same
///        connectivity. Beyond the paper, whose future work lists missing
///        feature points.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/io/Landmarks.h>
#include <cmp/map/Straighten.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <functional>
#include <string>
#include <vector>

namespace cmp
{

/// \brief Tuning of `placeMissingLandmarks()`.
struct MissingLandmarkOptions
{
  /// \brief The model the reduced base domain is built from (an index into
  ///        the collection; it must have every feature), or -1 for the first
  ///        model that has every feature.
  int baseDomainModel = -1;
  /// \brief Level of the reduced collection's remesh through which the
  ///        features are carried (1 to `kMaximumRemeshLevel`).
  int level = 4;
  /// \brief Rounds of sample relaxation of that remesh.
  int sampleRelaxationIterations = 4;
  /// \brief How much a source's likeness to the target counts: a model that
  ///        has a feature weighs exp(-(r / w)^2) in the feature's place on a
  ///        model that misses it, r the RMS distance between the two models'
  ///        remeshes after a similarity fit (each scaled to unit RMS radius)
  ///        and w this width; 0: every source weighs the same. The most
  ///        alike models' maps agree best (Documentation/filters/
  ///        MissingLandmarkPlacer.md, "Measured").
  double similarityWidth = 0.1;
  /// \brief The most models each target is carried from (0: every model
  ///        that has the features): the likest to it by the shape of the
  ///        landmarks both have (similarity fit). Each set of missing
  ///        features maps its targets and their sources, so this bounds the
  ///        cost in a large collection; with up to 8 sources it changes
  ///        nothing, and 3 or 5 placed about as well as 7 (Documentation/
  ///        filters/MissingLandmarkPlacer.md, "Measured").
  int maximumSources = 8;
  /// \brief Whether a feature that the sources have at the tip of a
  ///        protrusion (a foot, a nose, a horn) is moved from where the
  ///        maps carry it to the tip nearby. On each source, the edge-path
  ///        distance from its other landmarks (the ones the target has too)
  ///        is climbed from f's vertex, in steps of `tipRadius` (to the
  ///        farthest vertex within that distance while it is farther), to
  ///        the peak where it stops. If that peak is within `tipTolerance`
  ///        of the landmark on at least half the sources (the median), the
  ///        target's vertex climbs the same distance on the target, at most
  ///        `tipReach` away, and takes the peak it stops at, unless it
  ///        is already as near it as the sources' landmarks are to theirs
  ///        (that median). Hand-placed
  ///        landmarks sit a little off the peak on some models; features
  ///        inside smooth surface are far from any peak on most sources and
  ///        stay where the maps carry them (Documentation/filters/
  ///        MissingLandmarkPlacer.md, "Measured").
  bool climbToTips = true;
  /// \brief The climb's step: the radius (edge-path distance over the
  ///        square root of the area) within which it goes to the farthest
  ///        vertex from the landmarks.
  double tipRadius = 0.04;
  /// \brief How far from their peaks (over the square root of the area,
  ///        the median over the sources) the sources' landmarks may be for
  ///        the feature to be at a tip: half a step. On the SHREC'07
  ///        animals the hooves (about 1% off) climb; the nose tip and the
  ///        other landmarks of the head (2 to 10% off, as hands placed
  ///        them) do not (Documentation/filters/MissingLandmarkPlacer.md).
  double tipTolerance = 0.02;
  /// \brief How far the target's placed vertex may climb to its tip
  ///        (edge-path distance over the square root of its area); a climb
  ///        that would go farther keeps the vertex the maps gave.
  double tipReach = 0.2;
  /// \brief The base domain the collection will then be mapped over (open
  ///        for surfaces with boundaries), if known; null: none. With it,
  ///        each model with a feature that climbed to a tip is traced,
  ///        straightened and mapped over this L0 (curves freed as
  ///        `straighten` says) with the feature at the tip and at the vertex
  ///        the maps gave, and the climb is undone where its map is more
  ///        than `unsettledRatio` times as distorted
  ///        (`GlobalMapReport::distortionAfter`) or cannot be made. Why: on
  ///        a model without the protrusion (a protrusion cone, a tail the
  ///        model lacks) the climb stops on a rump or a hip, and the map can
  ///        then not settle (Spot cut open round its back, `L0` from 381: 28
  ///        times its isometric energy and 2.18% of its diagonal from its
  ///        remesh, against 1.64 and 1.05% unclimbed). Costs two mappings
  ///        of each model with a climbed feature, one more per further
  ///        climbed feature (Documentation/filters/MissingLandmarkPlacer.md,
  ///        "Measured"). Must outlive the call.
  const BaseDomain* domain = nullptr;
  /// \brief How many times as distorted the map with a climb must be, over
  ///        `domain`, for the climb to be undone: a map that did not settle.
  ///        Measured: climbed and unclimbed maps that both settle differ by
  ///        at most 2.6% (a hoof's climb, right by 3% of the square root of
  ///        the area, was a 0.1% tie); of the two that did not settle, one
  ///        was 17 times as distorted as the other, the other could not be
  ///        made.
  double unsettledRatio = 2.0;
  /// \brief How each model of the reduced collection is straightened and
  ///        mapped (the defaults: curves freed).
  StraightenOptions straighten;
  /// \brief Threads that map the models at once (0: one per hardware
  ///        thread). The result does not depend on it.
  int threads = 0;
  /// \brief Called with the fraction (0 to 1) of the work done, if set,
  ///        always on the calling thread.
  std::function<void(double)> progress;
};

/// \brief One feature placed on one model.
struct PlacedLandmark
{
  int model = -1;   ///< Index of the model in the collection.
  int feature = -1; ///< The feature placed.
  int vertex = -1;  ///< The vertex that now carries it.
  /// \brief The vertex the maps carried it to: `vertex` unless it climbed
  ///        to a tip from there (`climbed`).
  int mappedVertex = -1;
  Vec3 position = Vec3::Zero(); ///< That vertex's position.
  int sources = 0;  ///< Models it was carried from.
  /// \brief Median distance from the vertex to the points the sources carry
  ///        it to, over the square root of the model's area: how far the
  ///        collection's maps disagree.
  double spread = 0.0;
  /// \brief How far the vertex the maps gave climbed to the tip the
  ///        sources have the feature at (`MissingLandmarkOptions::climbToTips`),
  ///        over the square root of the model's area; 0 if it did not climb.
  double climbed = 0.0;
  /// \brief With `MissingLandmarkOptions::domain`, for a feature that
  ///        climbed: its model's map distortion over that L0 with the
  ///        feature at the tip (`tipDistortion`) and at the vertex the maps
  ///        gave (`mappedDistortion`); infinite where the model could not be
  ///        mapped, 0 where it was not judged. `climbed` is 0 and `vertex`
  ///        `mappedVertex` when the climb was undone (`climbUndone`).
  double tipDistortion = 0.0;
  double mappedDistortion = 0.0; ///< See `tipDistortion`.
  bool climbUndone = false;      ///< Whether the climb was undone by the maps' distortion.
};

/// \brief What `placeMissingLandmarks()` did.
struct MissingLandmarkReport
{
  std::vector<int> missingFeatures; ///< Every feature missing on some model, increasing.
  int baseDomainModel = -1;         ///< The model the reduced base domains were built from (-1: nothing to place).
  std::vector<PlacedLandmark> placed; ///< By model, then feature.
  /// \brief Per model, why it could not be mapped over a reduced base
  ///        domain (empty if it was). A model that has every feature and
  ///        fails is not a source; a model that misses one and fails keeps
  ///        it missing.
  std::vector<std::string> modelErrors;
  double seconds = 0.0; ///< The whole call.
};

/// \brief Places every missing feature (`kMissingLandmark`) of `landmarks`,
///        one list per model of `surfaces`, on a vertex of its model.
///
/// Method: the models that miss the same set S of features are placed
/// together. A base domain without S is built from `baseDomainModel`
/// (`buildBaseDomain()`); every model that has the features outside S is
/// traced, straightened and mapped over it (`traceFeatureNet()`,
/// `straighten()`, `threads` at once) and they are remeshed with one
/// connectivity (`remesh()`). A feature f missing on model m is then
/// carried from each model c that has it: the point of c's remesh nearest
/// to c's landmark (a remesh triangle and barycentric coordinates) is the
/// same triangle and coordinates of m's remesh. The carried points'
/// geometric median, each weighted by how alike c's remesh is to m's
/// (`similarityWidth`), is projected onto m, and f goes to the nearest
/// corner of that triangle that carries no other feature. A feature that
/// the sources have at the tip of a protrusion then climbs to the tip near
/// that vertex (`climbToTips`), unless its model's map over `domain`, when
/// given, does not settle with the climb and does without. Measured in
/// Documentation/filters/MissingLandmarkPlacer.md.
///
/// On success `landmarks` has every feature placed on every model that
/// could be mapped; a model that could not keeps its missing features and
/// `report->modelErrors` says why. Nothing to place (no feature missing) is
/// a success that does nothing.
///
/// Surfaces with boundaries (beyond the paper) are placed the same way:
/// the reduced base domain is then open, every model closed against it
/// (`closeBaseDomain()`, `closeSurface()`, the stages' options that keep
/// the caps) and the remesh open; a feature is never placed on a boundary
/// vertex, and a feature that lies on a model's boundary cannot be placed.
///
/// \pre Every surface is closed, genus 0 and manifold (`checkSurface()`),
///      or a sphere with holes (`checkSurfaceWithBoundaries()`).
/// Fails (Status), naming the problem, on options out of range (a level
/// outside 1 to `kMaximumRemeshLevel`, negative relaxation rounds or
/// similarity width, a tip radius or reach that is not positive, a negative
/// tip tolerance, an unsettled ratio below 1, a `domain` that cannot be
/// closed or whose vertices are not one per feature), lists of different lengths or invalid
/// (`validateLandmarks()` with missing features allowed), a missing feature that lies on some model's boundary, a
/// feature missing on every model, fewer than 4 features left, no model
/// with every feature (or a `baseDomainModel` that misses some), a reduced
/// base domain that cannot be built, no model that has a missing feature
/// mapped, and a failed remesh.
Status placeMissingLandmarks(const std::vector<const TriangleMesh*>& surfaces, std::vector<LandmarkList>& landmarks,
  const MissingLandmarkOptions& options = {}, MissingLandmarkReport* report = nullptr);

} // namespace cmp
