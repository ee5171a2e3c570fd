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
  ///        by one sparse LU of the whole system: 2.2 s instead of 19 s on a
  ///        million triangles, 3x faster already at 58K vertices, with the
  ///        same nets.
  int directSolveLimit = 50000;
  /// \brief Tuning of the coarse-to-fine solve.
  MultilevelOptions multilevel;
};

/// \brief Solves pi_v = sum_j w_vj pi_j with Floater's mean value weights
///        w_vj from the 3D geometry, and pi = e_f at the landmark of feature f.
///
/// The weights are a convex combination, so every component lies in [0, 1]
/// and each row sums to 1. One sparse LU factorization serves all F
/// right-hand sides. Surfaces above `options.directSolveLimit` vertices get
/// the multigrid approximation instead: rows still sum to 1, and components
/// may stray outside [0, 1] by a hair (1e-5 has been seen).
Status computeFeatureCoordinates(const TriangleMesh& mesh, const LandmarkList& landmarks, FeatureCoordinates& out,
  const FeatureCoordinateOptions& options = {});

} // namespace cmp
