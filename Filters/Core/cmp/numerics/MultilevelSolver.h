#pragma once
/// \file MultilevelSolver.h
/// \brief A multigrid solver for convex combination systems too large for
///        a sparse LU in good time (the F-vector parameterization of a
///        million-triangle surface).
///
/// The unknowns are put in breadth-first order (for cache locality), then
/// grouped into aggregates (a vertex and its free neighbours), level after
/// level, until few remain. The coarse system sums the weights between
/// aggregates, which keeps it a convex combination system on a coarser graph
/// (the Galerkin operator of piecewise constant interpolation). The coarsest
/// one is factorized once by sparse LU. The solve starts nested (coarsest
/// solution, interpolated and smoothed level by level), then runs V-cycles on
/// the finest level (symmetric Gauss-Seidel smoothing, over-corrected coarse
/// corrections, W-cycles below the finest level).
///
/// Every step is linear and keeps constants, so with unit vectors fixed the
/// rows still sum to one. The result is close to the exact solution but not
/// equal to it, least so beside the fixed vertices: good enough for a cost
/// heuristic (the tracer's ridge), not for a bijective embedding, which
/// needs the LU. Beyond the paper, which solves by conjugate gradients. Its
/// time and error against the LU are measured in Documentation/algorithm.md
/// ("Net tracing") and Documentation/filters/FeatureNetTracer.md.

#include <cmp/mesh/Status.h>

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
  int finestSweeps = 1;
  /// \brief Symmetric sweeps on each coarser level in the nested start.
  int coarseSweeps = 10;
  /// \brief V-cycles on the finest level after the nested start. They
  ///        remove most of the nested start's error, which is largest
  ///        beside the fixed vertices and there changes the tracer's nets
  ///        (measured in Documentation/algorithm.md, "Net tracing").
  int cycles = 4;
  /// \brief Factor on each coarse-level correction: piecewise constant
  ///        interpolation underestimates smooth corrections.
  double correctionScale = 1.5;
  /// \brief Cycles per visit of each level below the finest.
  int coarseCycles = 3;
};

/// \brief What `solveConvexCombinationMultilevel()` built.
struct MultilevelReport
{
  /// \brief Free unknowns of each level, finest first; the last one was
  ///        solved exactly.
  std::vector<int> unknownsPerLevel;
};

/// \brief Approximates the solution of `solveConvexCombinationSystem()`
///        (same arguments and meaning) by multigrid, in time linear in the
///        number of weights apart from the small coarsest factorization.
/// \pre As for `solveConvexCombinationSystem()`.
/// Fails (Status) when the coarsest system cannot be factorized or solved,
/// or the result is not finite.
Status solveConvexCombinationMultilevel(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values, const MultilevelOptions& options = {},
  MultilevelReport* report = nullptr);

} // namespace cmp
