#pragma once
/// \file OpenSurface.h
/// \brief Surfaces with boundaries (beyond the paper, whose future work
///        lists them): every boundary loop of a surface and of `L0` is
///        closed by a cap, so that every stage runs on closed surfaces, and
///        the caps are dropped again from the remesh.
///
/// The contract (Documentation/algorithm.md, "Surfaces with boundaries"):
/// - each boundary loop of a surface passes through at least 3 landmarks;
/// - `L0` is then a triangulated surface with as many boundary loops, whose
///   boundary vertices are exactly those landmarks, in the same cyclic
///   order along each loop, both traversed with the surface on the left;
/// - each boundary edge of `L0` maps to the stretch of the surface's
///   boundary between its two landmarks.
///
/// How it is kept: hole j of `L0` is closed by a new base vertex, feature
/// F + j (F the features of the open `L0`), joined to every landmark of
/// the loop; the matching loop of each surface by a fan of triangles from
/// a new vertex, that feature's landmark. The curves of the cap (the
/// boundary stretches and the spokes to the cap's centre) are given to the
/// tracer instead of traced, the stars of the boundary landmarks are not
/// straightened, the map keeps every vertex of the caps where it starts,
/// and the remesh leaves the caps' triangles out: its boundary vertices
/// lie on the surface's boundary, the landmarks exact.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/io/Landmarks.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief What `closeBaseDomain()` added to an open `L0`.
struct BaseDomainHoles
{
  int openVertexCount = 0;   ///< F: base vertices (and features) of the open L0.
  int openTriangleCount = 0; ///< Its triangles; the caps' come after them.
  /// \brief Per hole, the features of its boundary in order, the open L0 on
  ///        the left, starting at the smallest; hole j's cap is base vertex
  ///        and feature F + j. Holes are ordered by their smallest feature.
  std::vector<std::vector<int>> loops;
  /// \brief Per triangle of the closed L0: 1 for a cap's (a hole's).
  std::vector<char> holeTriangle;

  /// \brief Whether L0 had no hole (then the closed L0 is the open one).
  bool empty() const { return loops.empty(); }
  /// \brief Features of the closed L0: F plus one per hole.
  int closedFeatureCount() const { return openVertexCount + static_cast<int>(loops.size()); }
  /// \brief Whether feature `f` lies on a hole's boundary.
  bool onBoundary(int f) const;
  /// \brief The boundary features and the caps' centres: the features whose
  ///        stars are not straightened (`NetStraightenerOptions::keptFeatures`),
  ///        so that the caps' curves stay where `closeSurface()` put them.
  std::vector<int> keptFeatures() const;
};

/// \brief Closes every boundary loop of `domain` by a new base vertex (feature
///        F + j for hole j, at the centroid of the loop's vertices) joined to
///        the loop's vertices. A closed `domain` is copied unchanged, with
///        `holes` empty.
/// Fails (Status), naming the problem, when `domain`'s FeatureIds are not
/// 0..F-1 once each, a loop has fewer than 3 vertices ("a boundary loop of
/// L0 needs at least 3 landmarks"), a vertex lies on a loop twice, or the
/// closed L0 fails `checkBaseDomain()` (not manifold, not oriented, not
/// connected, or with handles: L0 must be a sphere with holes).
Status closeBaseDomain(const BaseDomain& domain, BaseDomain& closed, BaseDomainHoles& holes);

/// \brief What `closeSurface()` added to an open surface.
struct SurfaceHoles
{
  int openVertexCount = 0;   ///< Vertices of the open surface; cap centres follow.
  int openTriangleCount = 0; ///< Its triangles; the caps' follow.
  /// \brief Per hole of L0 (`BaseDomainHoles::loops` order), the surface's
  ///        boundary vertices in order, starting at the first feature's
  ///        landmark.
  std::vector<std::vector<int>> loops;
  /// \brief Per hole, the landmarks of its features (`BaseDomainHoles::loops`), in order.
  std::vector<std::vector<int>> boundaryLandmarks;
  /// \brief The curves of the caps, for `NetTracerOptions::presetCurves`: each boundary stretch between two
  ///        consecutive boundary landmarks (along the boundary), and each
  ///        spoke from a cap's centre to a boundary landmark (one edge).
  std::vector<PresetCurve> curves;

  /// \brief Whether the surface had no boundary.
  bool empty() const { return loops.empty(); }
};

/// \brief Closes every boundary loop of `surface` by a fan of triangles from
///        a new vertex (the cap's centre), matched to the holes of L0 by the
///        landmarks on it: `closed` has the surface's vertices and triangles
///        first, then one centre per hole of L0 and the caps' triangles;
///        `closedLandmarks` the landmarks, then each centre as the landmark
///        of feature F + j. A cap's centre lies off the loop's centroid, on
///        the side away from the surface (the loop's vector area), by half
///        the loop's mean radius. A closed surface with a closed L0 is
///        copied unchanged.
///
/// Fails (Status), naming the problem in the user's terms, when: the
/// surface is open and L0 closed or the other way round; a boundary loop
/// has fewer than 3 landmarks; a feature lies on the surface's boundary but
/// inside L0, or on L0's boundary but inside the surface; a boundary
/// landmark is missing (`kMissingLandmark`); the landmarks of a loop are
/// those of no hole of L0 or in another cyclic order than L0's; a boundary
/// is pinched (`boundaryLoops()`); or a loop is degenerate (no area).
/// \pre `landmarks` pass `validateLandmarks(landmarks, surface.vertexCount(),
///      holes.openVertexCount, true)`; `holes` is `closeBaseDomain()`'s.
Status closeSurface(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomainHoles& holes,
  TriangleMesh& closed, LandmarkList& closedLandmarks, SurfaceHoles& surfaceHoles);

/// \brief Traces `closed` (`closeSurface()`'s, with `closedLandmarks` and
///        `surfaceHoles`) over the closed L0 `closedDomain`, the caps' curves
///        given: `traceFeatureNet()` with `NetTracerOptions::presetCurves` set
///        to `surfaceHoles.curves` (whatever `options` had there).
/// Fails where `traceFeatureNet()` fails.
Status traceClosedSurface(const TriangleMesh& closed, const LandmarkList& closedLandmarks,
  const SurfaceHoles& surfaceHoles, const BaseDomain& closedDomain, TracedNet& net, NetTracerOptions options = {},
  NetTracerReport* report = nullptr);

/// \brief Traces a surface that may have boundary loops over the closed L0
///        (`closeBaseDomain()`'s `closedDomain` and `holes`), as every stage
///        runs such a surface: `closeSurface()`, then `traceClosedSurface()`.
///        A closed surface with a closed L0 is traced as it is. `net` is the
///        closed surface's net; its first vertices and triangles are the
///        surface's.
/// Fails where `closeSurface()` or `traceFeatureNet()` fails.
Status traceSurfaceWithBoundaries(const TriangleMesh& surface, const LandmarkList& landmarks,
  const BaseDomainHoles& holes, const BaseDomain& closedDomain, TracedNet& net, const NetTracerOptions& options = {},
  NetTracerReport* report = nullptr);

/// \brief Per cap triangle of `closeSurface()`'s closed surface (those after
///        the open surface's), the hole's base triangle it lies in: the cap
///        triangle on the boundary stretch between the i-th and (i+1)-th
///        features of hole j lies in the j-th hole's i-th triangle of the
///        closed L0, so a labelled open surface (`PatchId`) closes into a
///        labelled closed one.
std::vector<int> capPatchIds(const SurfaceHoles& surfaceHoles, const BaseDomainHoles& holes);

/// \brief The part of a closed surface outside its holes: the triangles
///        whose patch is not a hole, in their order, and the vertices they
///        use, in theirs.
struct OpenPart
{
  TriangleMesh mesh;               ///< The kept triangles, renumbered.
  std::vector<int> vertexOf;       ///< Per vertex of `mesh`, its vertex in the closed surface.
  std::vector<int> triangleOf;     ///< Per triangle of `mesh`, its triangle in the closed surface.
  std::vector<int> newIndex;       ///< Per vertex of the closed surface, its vertex in `mesh` (-1: only the caps use it).
};

/// \brief `OpenPart` of `closed` with `patchOfTriangle` its patches and
///        `holeTriangle` `closeBaseDomain()`'s. All of it without holes.
OpenPart openPart(const TriangleMesh& closed, const std::vector<int>& patchOfTriangle,
  const std::vector<char>& holeTriangle);

/// \brief The open surface back from a closed one: its first
///        `openVertexCount` vertices and `openTriangleCount` triangles.
TriangleMesh openSurface(const TriangleMesh& closed, const SurfaceHoles& holes);

} // namespace cmp
