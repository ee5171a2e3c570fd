#pragma once
/// \file FeatureParameterization.h
/// \brief The paper's harmonic F-vector parameterization of a surface onto
///        its base domain (Section 2.2, "Parameterization").

#include "Landmarks.h"
#include "Status.h"
#include "TriangleMesh.h"

#include <vector>

namespace cmp
{

/// \brief Per-vertex F-vectors: `values[v * F + f]` is component f of
///        vertex v's parameter value pi_v.
struct FeatureCoordinates
{
  int featureCount = 0;       ///< F.
  std::vector<double> values; ///< Row-major, one row of F values per vertex.

  /// \brief Component f of vertex v.
  double at(int v, int f) const { return values[static_cast<std::size_t>(v) * featureCount + f]; }
  /// \brief Appends a vertex whose F-vector is `(1-t) pi_a + t pi_b`.
  void appendInterpolated(int a, int b, double t);
};

/// \brief Solves pi_v = sum_j w_vj pi_j with Floater's mean value weights
///        w_vj from the 3D geometry, and pi = e_f at the landmark of feature f.
///
/// The weights are a convex combination, so every component lies in [0, 1]
/// and each row sums to 1. One sparse LU factorization serves all F
/// right-hand sides.
Status computeFeatureCoordinates(const TriangleMesh& mesh, const LandmarkList& landmarks, FeatureCoordinates& out);

} // namespace cmp
