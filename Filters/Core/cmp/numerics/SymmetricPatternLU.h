#pragma once
/// \file SymmetricPatternLU.h
/// \brief A sparse LU without pivoting for matrices whose pivots need none,
///        such as the convex combination systems of the paper's harmonic
///        parameterizations (Section 2.2).

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace cmp
{

/// \brief Factorizes P A P^T = L D U (L unit lower, D diagonal, U unit upper
///        triangular) with a fill-reducing ordering P of the symmetric
///        pattern of A + A^T, and solves A x = b for many right-hand sides.
///
/// L and U share one sparsity pattern, the Cholesky pattern of A + A^T, so
/// the symbolic work is that of a sparse Cholesky factorization (elimination
/// tree and column counts) and the numeric work about twice its own. It
/// pivots only on the diagonal: it suits matrices whose every symmetric
/// permutation has nonzero pivots, such as nonsingular M-matrices (the
/// systems sum_j w_vj (x_v - x_j) = b_v with positive weights w and every
/// free vertex joined to a fixed one, which `ConvexCombinationSolver`
/// solves), where it is as accurate as partial pivoting would be. On such
/// systems it replaces Eigen's SparseLU (supernodal, column pivoting, about
/// twice as slow on surface meshes).
class SymmetricPatternLU
{
public:
  /// \brief Factorizes `matrix` (square; any nonzero pattern, taken with its
  ///        transpose's).
  /// \return false when a pivot is zero or not finite; the factorization
  ///         is then unusable.
  bool compute(const Eigen::SparseMatrix<double>& matrix);

  /// \brief Replaces `rhs` (n x d) by the solution of A x = rhs.
  /// \pre `compute()` returned true for an n x n matrix.
  void solveInPlace(Eigen::MatrixXd& rhs) const;

  /// \brief Entries of L below its diagonal (as many are above U's).
  Eigen::Index factorNonZeros() const { return static_cast<Eigen::Index>(lowerRows_.size()); }

private:
  int n_ = 0;
  std::vector<int> newIndex_; ///< Position in P A P^T of each row of A.
  std::vector<int> start_;    ///< Column j of L (row j of U) is [start_[j], start_[j + 1]).
  /// \brief L(i, j) and U(j, i), side by side: the factorization and the
  ///        solves read both at once.
  struct Entry
  {
    double lower;
    double upper;
  };
  std::vector<int> lowerRows_; ///< Row i of each entry of L (column j): the column of U's entry beside it.
  std::vector<Entry> entries_; ///< At the same positions.
  std::vector<double> pivot_;  ///< D.
};

} // namespace cmp
