#pragma once
/// \file MeanValueSystem.h
/// \brief Floater's mean value weights and the sparse system they define:
///        every free vertex is the weighted mean of its neighbours. Used by
///        the F-vector parameterization, the straightener's star maps and the
///        per-patch parameterization.

#include <cmp/mesh/Status.h>
#include <cmp/numerics/SymmetricPatternLU.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <vector>

namespace cmp
{

/// \brief Floater's mean value weights from the 3D geometry: entry (i, j) is
///        (tan(alpha/2) + tan(beta/2)) / |p_j - p_i| for every edge, where
///        alpha and beta are the angles at i beside the edge. Not symmetric.
///        Paper §2.2: the "Floater scheme" of its F-vector parameterization
///        and edge straightening.
/// \pre Every triangle indexes vertices of `mesh`.
Eigen::SparseMatrix<double> meanValueWeights(const TriangleMesh& mesh);

/// \brief How a convex combination system is factorized. Its free
///        vertices' matrix is a nonsingular M-matrix, which needs no
///        pivoting; both give the same solution to rounding.
enum class ConvexCombinationFactorization
{
  /// Eigen's SparseLU (supernodal, column pivoting). For the maps that
  /// straightening and the patch parameterizations build: where a
  /// landmark-free protrusion crowds their values towards rounding, what
  /// the map later starts from depends on the rounding, and these maps were
  /// measured with this one.
  Pivoting,
  /// `SymmetricPatternLU` on the symmetric pattern of the mesh's edges:
  /// about three times faster on surface meshes (a third of the tracing
  /// time). For the tracer's F-vectors, whose nets it leaves unchanged.
  DiagonalPivots
};

/// \brief Solves x_v = sum_j W(v, j) x_j / sum_j W(v, j) for every vertex v
///        with `fixedRow[v] < 0`; a vertex with `fixedRow[v] >= 0` keeps
///        `fixedValues.row(fixedRow[v])`.
///
/// `values` becomes n x d (d = fixedValues.cols()). One sparse LU
/// factorization serves all d columns. With positive weights and a convex
/// boundary the result is a bijective embedding (Floater 1997). Paper §2.2
/// solves this system by conjugate gradients; the mean value system is not
/// symmetric, so here it is a sparse LU.
///
/// \pre `weights` is n x n with non-negative entries (row v: the weights of
///      v's neighbours); `fixedRow` has n entries, each -1 or a row of
///      `fixedValues`; every free vertex is joined to a fixed one through
///      positive weights (vertices without neighbours must be fixed).
/// Fails (Status) when the sparse LU cannot factorize the free vertices'
/// system (degenerate geometry) or its solution is not finite.
Status solveConvexCombinationSystem(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values,
  ConvexCombinationFactorization factorization = ConvexCombinationFactorization::Pivoting);

/// \brief The system of `solveConvexCombinationSystem()`, factorized once
///        and solved for any fixed values and right-hand sides (a multigrid
///        solver's coarsest level is solved again in every cycle).
class ConvexCombinationSolver
{
public:
  /// \brief Factorizes sum_j W(v, j) (x_v - x_j) = b_v for every vertex v
  ///        with `fixedRow[v] < 0`; the other vertices are known.
  /// \pre `weights` and `fixedRow` as for `solveConvexCombinationSystem()`.
  /// Fails (Status) when the sparse LU cannot factorize the system
  /// (degenerate geometry). A system without free vertices succeeds.
  Status factorize(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
    ConvexCombinationFactorization factorization = ConvexCombinationFactorization::Pivoting);

  /// \brief `values` becomes n x d: a fixed vertex v gets
  ///        `fixedValues.row(fixedRow[v])`, the free ones solve the system
  ///        with b = the matching rows of `rhs` (n x d, any values on fixed
  ///        rows), or b = 0 if `rhs` is null.
  /// \pre `factorize()` succeeded; `fixedValues` has a row for every
  ///      `fixedRow` value it was given; `rhs`, if set, has n rows and
  ///      `fixedValues.cols()` columns.
  /// Fails (Status) when the solve fails or its result is not finite.
  Status solve(const Eigen::MatrixXd& fixedValues, const Eigen::MatrixXd* rhs, Eigen::MatrixXd& values) const;

private:
  /// w_vj from free vertex v (as unknown `unknown`) to fixed vertex j (row
  /// `fixedRow` of the fixed values), in the order the weights list them.
  struct Coupling
  {
    int unknown;
    int fixedRow;
    double weight;
  };
  std::vector<int> fixedRow_;
  std::vector<int> unknown_; ///< Unknown of each free vertex, -1 for fixed ones.
  int unknowns_ = 0;
  std::vector<Coupling> couplings_;
  ConvexCombinationFactorization factorization_ = ConvexCombinationFactorization::Pivoting;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_; ///< Pivoting.
  SymmetricPatternLU diagonalLu_;                   ///< DiagonalPivots.
};

/// \brief `solveConvexCombinationSystem()` with `meanValueWeights(mesh)`:
///        same preconditions (n = `mesh.vertexCount()`) and failures.
Status solveMeanValueSystem(const TriangleMesh& mesh, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values,
  ConvexCombinationFactorization factorization = ConvexCombinationFactorization::Pivoting);

} // namespace cmp
