#include <cmp/numerics/MultilevelSolver.h>

#include <cmp/numerics/MeanValueSystem.h>

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

/// sum_j w_ij x_j over the neighbours j of row i, added to `sum`.
void addWeightedNeighbours(const Level& level, int i, const RowMatrix& x, Eigen::RowVectorXd& sum)
{
  for (RowSparse::InnerIterator it(level.weights, i); it; ++it)
    if (it.col() != i)
      sum.noalias() += it.value() * x.row(it.col());
}

/// Solves row i of totals_i x_i - sum_j w_ij x_j = b_i for x_i, all columns
/// at once (`rhs` null: b = 0, x_i becomes a convex combination).
void relaxRow(const Level& level, int i, RowMatrix& x, const RowMatrix* rhs, Eigen::RowVectorXd& sum)
{
  if (level.fixedRow[i] >= 0 || level.totals[i] <= 0.0)
    return;
  if (rhs)
    sum = rhs->row(i);
  else
    sum.setZero();
  addWeightedNeighbours(level, i, x, sum);
  x.row(i) = sum * (1.0 / level.totals[i]);
}

/// Symmetric Gauss-Seidel: a forward then a backward sweep, so no direction
/// of the vertex order is favoured.
void smooth(const Level& level, RowMatrix& x, const RowMatrix* rhs, int sweeps)
{
  Eigen::RowVectorXd sum(x.cols());
  const int n = static_cast<int>(x.rows());
  for (int s = 0; s < sweeps; ++s)
  {
    for (int i = 0; i < n; ++i)
      relaxRow(level, i, x, rhs, sum);
    for (int i = n - 1; i >= 0; --i)
      relaxRow(level, i, x, rhs, sum);
  }
}

/// b - A x on the free rows, summed over each aggregate: the right-hand side
/// of the next coarser level's correction.
RowMatrix restrictedResidual(const Level& level, const RowMatrix& x, const RowMatrix* rhs, int coarseCount)
{
  RowMatrix coarse = RowMatrix::Zero(coarseCount, x.cols());
  Eigen::RowVectorXd residual(x.cols());
  for (int i = 0; i < x.rows(); ++i)
  {
    if (level.fixedRow[i] >= 0)
      continue;
    residual = -level.totals[i] * x.row(i);
    if (rhs)
      residual += rhs->row(i);
    addWeightedNeighbours(level, i, x, residual);
    coarse.row(level.aggregate[i]) += residual;
  }
  return coarse;
}

/// Starts a finer level from the values of its aggregates.
RowMatrix interpolate(const Level& fine, const RowMatrix& coarse, const Eigen::MatrixXd& fixedValues)
{
  RowMatrix x(fine.aggregate.size(), coarse.cols());
  for (std::size_t i = 0; i < fine.aggregate.size(); ++i)
    x.row(i) = fine.fixedRow[i] >= 0 ? RowMatrix(fixedValues.row(fine.fixedRow[i])) : coarse.row(fine.aggregate[i]);
  return x;
}

/// The levels, finest first, and the coarsest one's factorization.
struct Hierarchy
{
  std::vector<Level> levels;
  ConvexCombinationSolver coarsest;
  Eigen::MatrixXd zeroFixedValues; ///< A correction is 0 on the fixed rows.
};

/// One V-cycle on level `l` for A x = b (fixed rows of `x` untouched): smooth,
/// correct by the coarser level's solution for the residual, smooth.
Status cycle(const Hierarchy& hierarchy, std::size_t l, RowMatrix& x, const RowMatrix* rhs,
  const MultilevelOptions& options)
{
  const std::vector<Level>& levels = hierarchy.levels;
  const Level& level = levels[l];
  if (l + 1 == levels.size())
  {
    // Only corrections come here: zero on the fixed rows.
    const Eigen::MatrixXd b = *rhs;
    Eigen::MatrixXd solution;
    if (Status s = hierarchy.coarsest.solve(hierarchy.zeroFixedValues, &b, solution); !s.ok())
      return s;
    x = solution;
    return {};
  }
  // The finest level is the expensive one: one cycle there; coarser levels
  // repeat theirs (a W-cycle), since an inexact coarse correction is what
  // slows aggregation multigrid down.
  const int repeats = l == 0 ? 1 : options.coarseCycles;
  for (int r = 0; r < repeats; ++r)
  {
    smooth(level, x, rhs, 1);
    const int coarseCount = static_cast<int>(levels[l + 1].weights.rows());
    const RowMatrix coarseRhs = restrictedResidual(level, x, rhs, coarseCount);
    RowMatrix correction = RowMatrix::Zero(coarseCount, x.cols());
    if (Status s = cycle(hierarchy, l + 1, correction, &coarseRhs, options); !s.ok())
      return s;
    for (int i = 0; i < x.rows(); ++i)
      if (level.fixedRow[i] < 0)
        x.row(i) += options.correctionScale * correction.row(level.aggregate[i]);
    smooth(level, x, rhs, 1);
  }
  return {};
}

/// Breadth-first order of the graph (component after component): rows that
/// are neighbours get nearby numbers, so a sweep reads neighbour rows that are
/// still in cache. `order[k]` is the old index of new row k.
std::vector<int> breadthFirstOrder(const RowSparse& weights)
{
  const int n = static_cast<int>(weights.rows());
  std::vector<int> order;
  order.reserve(n);
  std::vector<char> visited(n, 0);
  for (int seed = 0; seed < n; ++seed)
  {
    if (visited[seed])
      continue;
    visited[seed] = 1;
    order.push_back(seed);
    for (std::size_t head = order.size() - 1; head < order.size(); ++head)
      for (RowSparse::InnerIterator it(weights, order[head]); it; ++it)
        if (!visited[it.col()])
        {
          visited[it.col()] = 1;
          order.push_back(static_cast<int>(it.col()));
        }
  }
  return order;
}

} // namespace

Status solveConvexCombinationMultilevel(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values, const MultilevelOptions& options,
  MultilevelReport* report)
{
  // Work in breadth-first order: the input's order (a subdivided mesh puts
  // new vertices last) can scatter neighbours over the whole array.
  const int n = static_cast<int>(weights.rows());
  const std::vector<int> order = breadthFirstOrder(RowSparse(weights));
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> toNew(n);
  std::vector<int> orderedFixedRow(n);
  for (int k = 0; k < n; ++k)
  {
    toNew.indices()[order[k]] = k;
    orderedFixedRow[k] = fixedRow[order[k]];
  }
  Hierarchy hierarchy;
  std::vector<Level>& levels = hierarchy.levels;
  const Eigen::SparseMatrix<double> ordered = toNew * weights * toNew.inverse();
  levels.push_back(makeLevel(RowSparse(ordered), std::move(orderedFixedRow)));
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
  if (Status s = hierarchy.coarsest.factorize(Eigen::SparseMatrix<double>(levels.back().weights), levels.back().fixedRow,
        ConvexCombinationFactorization::DiagonalPivots);
      !s.ok())
    return s;
  hierarchy.zeroFixedValues = Eigen::MatrixXd::Zero(fixedValues.rows(), fixedValues.cols());
  // Nested start: the coarsest solution, interpolated and smoothed level by
  // level; then V-cycles on the finest level remove what the coarse levels
  // got wrong (mostly near the fixed rows).
  Eigen::MatrixXd coarsest;
  if (Status s = hierarchy.coarsest.solve(fixedValues, nullptr, coarsest); !s.ok())
    return s;
  RowMatrix x = coarsest;
  for (int l = static_cast<int>(levels.size()) - 2; l >= 0; --l)
  {
    x = interpolate(levels[l], x, fixedValues);
    smooth(levels[l], x, nullptr, l == 0 ? options.finestSweeps : options.coarseSweeps);
  }
  for (int c = 0; c < options.cycles && levels.size() > 1; ++c)
    if (Status s = cycle(hierarchy, 0, x, nullptr, options); !s.ok())
      return s;
  if (!x.allFinite())
    return Status::error("the mean value system could not be solved");
  values.resize(n, x.cols());
  for (int k = 0; k < n; ++k)
    values.row(order[k]) = x.row(k);
  return {};
}

} // namespace cmp
