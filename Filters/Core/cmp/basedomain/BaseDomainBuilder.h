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
  /// \brief Called with the fraction of the work done, in [0, 1].
  std::function<void(double)> progress;
};

/// \brief What `buildBaseDomain()` did and how good the result is.
struct BaseDomainBuilderReport
{
  int collapses = 0;             ///< Half-edge collapses performed.
  int foldingCollapses = 0;      ///< Collapses that had to fold a triangle over.
  int flips = 0;                 ///< Edge flips used to unblock a vertex.
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
/// Fails (Status), naming the problem, on a surface that fails
/// `checkSurface()` (not a closed genus-0 manifold with sound geometry), on
/// invalid landmarks (`validateLandmarks()`), with fewer than 4 landmarks,
/// and when no remaining vertex can be removed without breaking the
/// topology (not expected: folding collapses and flips are tried first).
Status buildBaseDomain(const TriangleMesh& surface, const LandmarkList& landmarks, BaseDomain& domain,
  const BaseDomainBuilderOptions& options = {}, BaseDomainBuilderReport* report = nullptr);

} // namespace cmp
