#pragma once
/// \file BaseDomainBuilder.h
/// \brief Builds a base domain `L0` from one landmarked surface by
///        topology-preserving edge-collapse decimation.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/io/Landmarks.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <functional>

namespace cmp
{

/// \brief Tuning of `buildBaseDomain()`.
struct BaseDomainBuilderOptions
{
  /// \brief Weight of triangle shape against geometric error in the collapse
  ///        cost. Higher favours well-shaped base triangles.
  double shapeWeight = 1.0;
  /// \brief Open surfaces: each hole stands among the landmarks round it as
  ///        an inner landmark would (the surface decimated with its holes
  ///        capped and its boundary landmarks let go), then its loop is
  ///        joined to that ring by the shortest strip. false: the loops'
  ///        landmarks are kept through the decimation, and the band round
  ///        a hole is made anew only where it is a strip already.
  bool aroundRings = true;
  /// \brief Called with the fraction of the work done, in [0, 1].
  std::function<void(double)> progress;
};

/// \brief What `buildBaseDomain()` did and how good the result is.
struct BaseDomainBuilderReport
{
  int collapses = 0;             ///< Half-edge collapses performed.
  int foldingCollapses = 0;      ///< Collapses that had to fold a triangle over.
  int flips = 0;                 ///< Edge flips used to unblock a vertex, and those that make an open L0 Delaunay.
  int restripedBands = 0;        ///< Bands round the holes of an open L0 made anew as the shortest strip.
  int ringedHoles = 0;           ///< Holes of an open L0 joined to their ring of landmarks (`aroundRings`).
  double minAngleDegrees = 0.0;  ///< Smallest angle of the base triangles.
  double meanShapeQuality = 0.0; ///< Mean of 4*sqrt(3)*area/sum(edge^2), 1 = equilateral.
};

/// \brief Decimates `surface` until only the landmark vertices remain.
///
/// Every step is a half-edge collapse of a non-landmark vertex into a
/// neighbour that keeps the surface a closed manifold (link condition), so
/// the result is a genus-0 triangulation of the landmarks whose layout
/// follows the surface. Among valid collapses it prefers those that fold no
/// triangle over and leave well-shaped triangles close to the surface
/// (quadric error plus a shape term). Base vertex f is landmark f, placed at
/// its surface position. O(n log n). Paper §2 lets the base domain be given
/// or "found automatically"; this decimation is our own (beyond the paper).
///
/// Surfaces with boundaries (beyond the paper, whose future work lists
/// them; Documentation/algorithm.md, "Surfaces with boundaries"): each
/// boundary loop (`boundaryLoops()`) is closed by a fan from a new vertex
/// (`capLoop()`), which is kept like a landmark. With `aroundRings` (the
/// default), the boundary landmarks are let go: the capped surface is
/// decimated to its inner landmarks and the centres, so that each centre's
/// neighbours are the ring of landmarks round its hole, and each centre's
/// star is replaced by the strip between its loop's landmarks and that
/// ring that joins each boundary landmark to the ring in its own direction
/// round the hole (the least summed angle seen from the hole's centre in
/// the plane the loop spans; Fuchs, Kedem and Uselton's optimal
/// triangulation between two contours). Should that not give an `L0`
/// whose loops are the surface's (fewer than 4 inner landmarks and
/// centres, a ring through another hole's centre), or without
/// `aroundRings`: a non-landmark vertex of a loop only collapses into one
/// of its two neighbours along the loop, nothing collapses into a cap's
/// centre, no edge of a cap is flipped, the centres and their triangles
/// are removed at the end, and the band of triangles round each hole is
/// made anew where it is a strip between the loop and one ring of
/// landmarks (the shortest strip, on the landmarks' positions); a crowded
/// loop can then leave one boundary landmark joined to most of the ring,
/// and every other model's curves wind round the hole to reach it. Either
/// way `domain` is a triangulated sphere with as many holes as the
/// surface, whose boundary loops are exactly the landmarks on the
/// surface's loops, in the same cyclic order (both with the surface on the
/// left), and whose triangles are oriented like the surface's; every inner
/// edge is then flipped towards Delaunay's criterion on the landmarks'
/// positions (never a boundary edge, never into a chord between two
/// boundary landmarks or across a folded quadrilateral; counted in the
/// report's `flips`). `closeBaseDomain()` (layout) closes it again for the
/// later stages. The report's angles and shapes are those of `domain`'s
/// own triangles.
///
/// \pre `surface` is a closed genus-0 triangle surface, or a genus-0
///      surface with boundary loops each passing through at least 3
///      landmarks; `landmarks` are distinct vertices of it, none missing.
///
/// Fails (Status), naming the problem:
/// - on a closed surface that fails `checkSurface()` (not a closed genus-0
///   manifold with sound geometry), and with fewer than 4 landmarks;
/// - on an open surface (`checkSurface()` finds boundary edges): when
///   triangles disagree in orientation ("inconsistent orientation"), its
///   boundary is pinched or a loop encloses no area (`boundaryLoops()`,
///   `capLoop()`), the surface with its loops capped fails
///   `checkSurface()` (the message ends "(the surface with its boundary
///   loops capped)": e.g. several components, or handles), and when a loop
///   passes through fewer than 3 landmarks ("open surface: the boundary
///   loop through vertex V ... passes through N landmarks, but every
///   boundary loop needs at least 3");
/// - on invalid or missing landmarks (`validateLandmarks()`);
/// - when no remaining vertex can be removed without breaking the topology
///   (not expected: folding collapses and flips are tried first), and with
///   "internal error: ..." when the result does not fit the surface (not
///   expected either: for an open surface, a cap's centre whose triangles
///   are not a fan over its loop's landmarks in order, or boundary loops
///   of `domain` other than those).
Status buildBaseDomain(const TriangleMesh& surface, const LandmarkList& landmarks, BaseDomain& domain,
  const BaseDomainBuilderOptions& options = {}, BaseDomainBuilderReport* report = nullptr);

} // namespace cmp
