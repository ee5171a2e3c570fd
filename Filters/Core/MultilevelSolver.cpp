#include "MultilevelSolver.h"

#include "MeanValueSystem.h"

#include <algorithm>

namespace cmp
{
namespace
{

using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// One level of the hierarchy: a convex combination system on a graph.
struct Level
{
  RowSparse weights;          ///< w_ij >= 0, no diagonal; rows are the equations.
  std::vector<double> totals; ///< sum_j w_ij per row.
  std::vector<int> fixedRow;  ///< As in solveConvexCombinationSystem().
  std::vector<int> aggregate; ///< This level's unknown -> next coarser level's.
  int unknowns = 0;           ///< Rows that are not fixed.
};

Level makeLevel(RowSparse weights, std::vector<int> fixedRow)
{
  Level level;
  level.weights = std::move(weights);
  level.fixedRow = std::move(fixedRow);
  level.totals.assign(level.weights.rows(), 0.0);
  for (int i = 0; i < level.weights.outerSize(); ++i)
    for (RowSparse::InnerIterator it(level.weights, i); it; ++it)
      if (it.col() != i)
        level.totals[i] += it.value();
  level.unknowns = static_cast<int>(std::count(level.fixedRow.begin(), level.fixedRow.end(), -1));
  return level;
}

/// Greedy aggregation: a fixed row stays alone; a free row whose free
/// neighbours are all still unassigned takes them as its aggregate; leftovers
/// join the neighbouring aggregate they are most strongly tied to. Returns the
/// number of aggregates.
int aggregate(Level& level)
{
  const int n = static_cast<int>(level.weights.rows());
  std::vector<int>& group = level.aggregate;
  group.assign(n, -1);
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (level.fixedRow[i] >= 0)
      group[i] = count++;
  const int firstFree = count;
  for (int i = 0; i < n; ++i)
  {
    if (group[i] >= 0)
      continue;
    bool neighboursFree = true;
    for (RowSparse::InnerIterator it(level.weights, i); it && neighboursFree; ++it)
      neighboursFree = group[it.col()] < 0 || level.fixedRow[it.col()] >= 0;
    if (!neighboursFree)
      continue;
    group[i] = count;
    for (RowSparse::InnerIterator it(level.weights, i); it; ++it)
      if (level.fixedRow[it.col()] < 0)
        group[it.col()] = count;
    ++count;
  }
  // Leftovers join only first-pass aggregates, so no chain of joins forms.
  const std::vector<int> firstPass = group;
  for (int i = 0; i < n; ++i)
  {
    if (group[i] >= 0)
      continue;
    int best = -1;
    double strongest = -1.0;
    for (RowSparse::InnerIterator it(level.weights, i); it; ++it)
      if (firstPass[it.col()] >= firstFree && it.value() > strongest)
      {
        strongest = it.value();
        best = firstPass[it.col()];
      }
    group[i] = best >= 0 ? best : count++;
  }
  return count;
}

/// The Galerkin operator of piecewise constant interpolation: the weight
/// between two aggregates is the sum of the weights between their members.
Level coarsen(Level& fine)
{
  const int coarseCount = aggregate(fine);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(fine.weights.nonZeros());
  for (int i = 0; i < fine.weights.outerSize(); ++i)
    for (RowSparse::InnerIterator it(fine.weights, i); it; ++it)
    {
      const int a = fine.aggregate[i], b = fine.aggregate[it.col()];
      if (a != b)
        entries.emplace_back(a, b, it.value());
    }
  RowSparse weights(coarseCount, coarseCount);
  weights.setFromTriplets(entries.begin(), entries.end());
  std::vector<int> fixedRow(coarseCount, -1);
  for (std::size_t i = 0; i < fine.fixedRow.size(); ++i)
    if (fine.fixedRow[i] >= 0)
      fixedRow[fine.aggregate[i]] = fine.fixedRow[i];
  return makeLevel(std::move(weights), std::move(fixedRow));
}

/// x_i = sum_j w_ij x_j / sum_j w_ij for one free row, all columns at once.
void relaxRow(const Level& level, int i, RowMatrix& x, std::vector<double>& sum)
{
  if (level.fixedRow[i] >= 0 || level.totals[i] <= 0.0)
    return;
  const int d = static_cast<int>(x.cols());
  std::fill(sum.begin(), sum.end(), 0.0);
  for (RowSparse::InnerIterator it(level.weights, i); it; ++it)
  {
    if (it.col() == i)
      continue;
    const double w = it.value();
    const double* neighbour = x.data() + static_cast<std::size_t>(it.col()) * d;
    for (int k = 0; k < d; ++k)
      sum[k] += w * neighbour[k];
  }
  double* row = x.data() + static_cast<std::size_t>(i) * d;
  const double scale = 1.0 / level.totals[i];
  for (int k = 0; k < d; ++k)
    row[k] = sum[k] * scale;
}

/// Symmetric Gauss-Seidel: a forward then a backward sweep, so no direction
/// of the vertex order is favoured.
void smooth(const Level& level, RowMatrix& x, int sweeps)
{
  std::vector<double> sum(x.cols());
  const int n = static_cast<int>(x.rows());
  for (int s = 0; s < sweeps; ++s)
  {
    for (int i = 0; i < n; ++i)
      relaxRow(level, i, x, sum);
    for (int i = n - 1; i >= 0; --i)
      relaxRow(level, i, x, sum);
  }
}

/// Starts a finer level from the values of its aggregates.
RowMatrix interpolate(const Level& fine, const RowMatrix& coarse, const Eigen::MatrixXd& fixedValues)
{
  RowMatrix x(fine.aggregate.size(), coarse.cols());
  for (std::size_t i = 0; i < fine.aggregate.size(); ++i)
    x.row(i) = fine.fixedRow[i] >= 0 ? RowMatrix(fixedValues.row(fine.fixedRow[i])) : coarse.row(fine.aggregate[i]);
  return x;
}

} // namespace

Status solveConvexCombinationMultilevel(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values, const MultilevelOptions& options,
  MultilevelReport* report)
{
  std::vector<Level> levels;
  levels.push_back(makeLevel(RowSparse(weights), fixedRow));
  while (levels.back().unknowns > options.coarsestUnknowns)
  {
    Level coarse = coarsen(levels.back());
    // A graph that no longer shrinks (a star, a clique) would loop forever.
    if (coarse.weights.rows() > 0.8 * levels.back().weights.rows())
      break;
    levels.push_back(std::move(coarse));
  }
  if (report)
  {
    report->unknownsPerLevel.clear();
    for (const Level& level : levels)
      report->unknownsPerLevel.push_back(level.unknowns);
  }
  Eigen::MatrixXd coarsest;
  if (Status s = solveConvexCombinationSystem(Eigen::SparseMatrix<double>(levels.back().weights),
        levels.back().fixedRow, fixedValues, coarsest);
      !s.ok())
    return s;
  RowMatrix x = coarsest;
  for (int l = static_cast<int>(levels.size()) - 2; l >= 0; --l)
  {
    x = interpolate(levels[l], x, fixedValues);
    smooth(levels[l], x, l == 0 ? options.finestSweeps : options.coarseSweeps);
  }
  if (!x.allFinite())
    return Status::error("the mean value system could not be solved");
  values = x;
  return {};
}

} // namespace cmp
