#pragma once
/// \file MultilevelSolver.h
/// \brief A coarse-to-fine solver for convex combination systems too large
///        for a sparse LU in good time (the F-vector parameterization of a
///        million-triangle surface).
///
/// The unknowns are grouped into aggregates (a vertex and its free
/// neighbours), level after level, until few remain. The coarse system sums
/// the weights between aggregates, which keeps it a convex combination system
/// on a coarser graph (the Galerkin operator of piecewise constant
/// interpolation). The coarsest one is solved exactly; each finer level
/// starts from the coarse values of its aggregates and is smoothed by
/// symmetric Gauss-Seidel sweeps. Every sweep replaces a value by a convex
/// combination of its neighbours, so the result keeps the maximum principle
/// of the exact solution: with unit vectors fixed, components lie in [0, 1]
/// and rows sum to one.
///
/// It is an approximation, not a converged multigrid solve: on model 387
/// subdivided once (58K vertices) the values differ from the exact solution
/// by 0.011 on average and up to 0.2 beside the fixed vertices, where the
/// coarse levels see a point constraint as larger than it is. That is what a
/// cost heuristic needs (the tracer's nets come out as long, see the core
/// tests), not what a bijective embedding needs.

#include "Status.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace cmp
{

/// \brief Tuning of `solveConvexCombinationMultilevel()`.
struct MultilevelOptions
{
  /// \brief Coarsen until at most this many unknowns remain, then solve
  ///        exactly.
  int coarsestUnknowns = 20000;
  /// \brief Symmetric Gauss-Seidel sweeps (one forward, one backward) on the
  ///        finest level after interpolation.
  int finestSweeps = 6;
  /// \brief Symmetric sweeps on each coarser level (they are cheap there).
  int coarseSweeps = 20;
};

/// \brief What `solveConvexCombinationMultilevel()` built.
struct MultilevelReport
{
  /// \brief Free unknowns of each level, finest first; the last one was
  ///        solved exactly.
  std::vector<int> unknownsPerLevel;
};

/// \brief Approximates the solution of `solveConvexCombinationSystem()`
///        (same arguments and meaning) coarse to fine, in time linear in the
///        number of weights apart from the small coarsest solve.
Status solveConvexCombinationMultilevel(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values, const MultilevelOptions& options = {},
  MultilevelReport* report = nullptr);

} // namespace cmp
