#pragma once
/// \file FeatureParameterization.h
/// \brief The paper's harmonic F-vector parameterization of a surface onto
///        its base domain (Section 2.2, "Parameterization").

#include <cmp/io/Landmarks.h>
#include <cmp/numerics/MultilevelSolver.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief Per-vertex F-vectors: `components[f][v]` is component f of
///        vertex v's parameter value pi_v.
///
/// One array per feature because a brush fire reads two components of many
/// neighbouring vertices: two arrays of a million doubles stay in cache where
/// rows of F values would not.
struct FeatureCoordinates
{
  int featureCount = 0;                         ///< F.
  std::vector<std::vector<double>> components;  ///< F arrays of one value per vertex.

  /// \brief Component f of vertex v.
  double at(int v, int f) const { return components[f][v]; }
  /// \brief Appends a vertex whose F-vector is `(1-t) pi_a + t pi_b`.
  void appendInterpolated(int a, int b, double t);
};

/// \brief How `computeFeatureCoordinates()` solves its system.
struct FeatureCoordinateOptions
{
  /// \brief Surfaces with more vertices than this are solved coarse to fine
  ///        by multigrid (`solveConvexCombinationMultilevel()`) instead of
  ///        by one sparse LU of the whole system: the LU's time grows faster
  ///        than the surface, the multigrid's about linearly, and the nets
  ///        come out the same (figures in Documentation/algorithm.md, "Net
  ///        tracing", and Documentation/filters/FeatureNetTracer.md).
  int directSolveLimit = 50000;
  /// \brief Tuning of the coarse-to-fine solve.
  MultilevelOptions multilevel;
};

/// \brief Solves pi_v = sum_j w_vj pi_j with Floater's mean value weights
///        w_vj from the 3D geometry, and pi = e_f at the landmark of feature f
///        (paper §2.2, "Parameterization"; a sparse LU where the paper uses
///        conjugate gradients).
///
/// The weights are a convex combination, so every component lies in [0, 1]
/// and each row sums to 1. One sparse LU factorization serves all F
/// right-hand sides (`ConvexCombinationFactorization::DiagonalPivots`). Surfaces above `options.directSolveLimit` vertices get
/// the multigrid approximation instead: rows still sum to 1, and components
/// may stray outside [0, 1] by the approximation's small error.
///
/// \pre `landmarks` are distinct vertices of `mesh` (`validateLandmarks()`),
///      and every part of `mesh` holds a landmark (a closed connected
///      surface, as `checkSurface()` ensures, and at least one landmark).
/// Fails (Status, "harmonic parameterization: ...") when the system cannot
/// be factorized or solved (degenerate geometry).
Status computeFeatureCoordinates(const TriangleMesh& mesh, const LandmarkList& landmarks, FeatureCoordinates& out,
  const FeatureCoordinateOptions& options = {});

} // namespace cmp
