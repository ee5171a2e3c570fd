#include <cmp/numerics/SymmetricPatternLU.h>

#include <Eigen/OrderingMethods>

#include <cmath>

namespace cmp
{
namespace
{

/// Entries of one triangle of the permuted matrix, grouped by the index
/// they share with the diagonal (compressed, as CSR or CSC).
struct Half
{
  std::vector<int> start;
  std::vector<int> index;
  std::vector<double> value;
};

void compress(Half& half, int n)
{
  for (int k = 0; k < n; ++k)
    half.start[k + 1] += half.start[k];
  half.index.resize(half.start[n]);
  half.value.resize(half.start[n]);
}

} // namespace

bool SymmetricPatternLU::compute(const Eigen::SparseMatrix<double>& matrix)
{
  const int n = static_cast<int>(matrix.rows());
  n_ = n;
  newIndex_.clear();
  start_.assign(1, 0);
  lowerRows_.clear();
  entries_.clear();
  pivot_.clear();
  if (n == 0)
    return true;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(matrix, order); // of A + A^T; order(new) = old
  newIndex_.assign(n, 0);
  for (int k = 0; k < n; ++k)
    newIndex_[order.indices()[k]] = k;

  // C = P A P^T by halves: `above` holds column k's entries C(i, k), i < k;
  // `left` row k's entries C(k, i), i < k.
  Half above, left;
  above.start.assign(n + 1, 0);
  left.start.assign(n + 1, 0);
  std::vector<double> diagonal(n, 0.0);
  for (int pass = 0; pass < 2; ++pass)
  {
    std::vector<int> aboveNext, leftNext;
    if (pass == 1)
    {
      compress(above, n);
      compress(left, n);
      aboveNext.assign(above.start.begin(), above.start.end() - 1);
      leftNext.assign(left.start.begin(), left.start.end() - 1);
    }
    for (int j = 0; j < matrix.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, j); it; ++it)
      {
        const int r = newIndex_[it.row()], c = newIndex_[it.col()];
        if (pass == 0)
        {
          if (r < c)
            ++above.start[c + 1];
          else if (r > c)
            ++left.start[r + 1];
          else
            diagonal[r] += it.value();
        }
        else if (r < c)
        {
          above.index[aboveNext[c]] = r;
          above.value[aboveNext[c]++] = it.value();
        }
        else if (r > c)
        {
          left.index[leftNext[r]] = c;
          left.value[leftNext[r]++] = it.value();
        }
      }
  }

  // Symbolic: the elimination tree of A + A^T and the entries of each
  // column of L, row k's entries being the tree paths from its nonzeros up
  // to k.
  std::vector<int> parent(n, -1), flag(n, -1), count(n, 0);
  for (int k = 0; k < n; ++k)
  {
    flag[k] = k;
    const auto visit = [&](int i) {
      for (; flag[i] != k; i = parent[i])
      {
        if (parent[i] < 0)
          parent[i] = k;
        ++count[i];
        flag[i] = k;
      }
    };
    for (int p = above.start[k]; p < above.start[k + 1]; ++p)
      visit(above.index[p]);
    for (int p = left.start[k]; p < left.start[k + 1]; ++p)
      visit(left.index[p]);
  }
  start_.assign(n + 1, 0);
  for (int j = 0; j < n; ++j)
    start_[j + 1] = start_[j] + count[j];
  lowerRows_.resize(start_[n]);
  entries_.resize(start_[n]);
  pivot_.assign(n, 0.0);

  // Numeric, row by row of L and column by column of U: with the leading
  // block L11 D11 U11 known, L11 y = C(0:k-1, k) gives U's column
  // (D11^-1 y), U11^T z = C(k, 0:k-1)^T gives L's row (z^T D11^-1), and the
  // pivot is C(k, k) - z^T D11^-1 y. Both solves run over row k's pattern
  // in topological order.
  // y (column k of U, scaled) and z (row k of L, scaled) side by side.
  std::vector<Entry> work(n, Entry{ 0.0, 0.0 });
  std::vector<int> pattern(n), path(n), filled(n, 0);
  std::fill(flag.begin(), flag.end(), -1);
  for (int k = 0; k < n; ++k)
  {
    flag[k] = k;
    int top = n;
    const auto reach = [&](int i) {
      int length = 0;
      for (; flag[i] != k; i = parent[i])
      {
        path[length++] = i;
        flag[i] = k;
      }
      while (length > 0)
        pattern[--top] = path[--length];
    };
    for (int p = above.start[k]; p < above.start[k + 1]; ++p)
    {
      work[above.index[p]].upper += above.value[p];
      reach(above.index[p]);
    }
    for (int p = left.start[k]; p < left.start[k + 1]; ++p)
    {
      work[left.index[p]].lower += left.value[p];
      reach(left.index[p]);
    }
    double pivot = diagonal[k];
    for (int t = top; t < n; ++t)
    {
      const int j = pattern[t];
      const double y = work[j].upper, z = work[j].lower;
      work[j] = Entry{ 0.0, 0.0 };
      const int end = start_[j] + filled[j];
      for (int p = start_[j]; p < end; ++p)
      {
        Entry& w = work[lowerRows_[p]];
        w.upper -= entries_[p].lower * y;
        w.lower -= entries_[p].upper * z;
      }
      const double l = z / pivot_[j];
      pivot -= l * y;
      lowerRows_[end] = k;
      entries_[end] = Entry{ l, y / pivot_[j] };
      ++filled[j];
    }
    if (pivot == 0.0 || !std::isfinite(pivot))
      return false;
    pivot_[k] = pivot;
  }
  return true;
}

void SymmetricPatternLU::solveInPlace(Eigen::MatrixXd& rhs) const
{
  const int d = static_cast<int>(rhs.cols());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> x(n_, d);
  for (int i = 0; i < n_; ++i)
    x.row(newIndex_[i]) = rhs.row(i);
  double* data = x.data();
  for (int j = 0; j < n_; ++j) // L
  {
    const double* xj = data + static_cast<std::ptrdiff_t>(j) * d;
    for (int p = start_[j]; p < start_[j + 1]; ++p)
    {
      double* xi = data + static_cast<std::ptrdiff_t>(lowerRows_[p]) * d;
      const double l = entries_[p].lower;
      for (int c = 0; c < d; ++c)
        xi[c] -= l * xj[c];
    }
  }
  for (int j = 0; j < n_; ++j) // D
    x.row(j) /= pivot_[j];
  for (int j = n_ - 1; j >= 0; --j) // U, by rows
  {
    double* xj = data + static_cast<std::ptrdiff_t>(j) * d;
    for (int p = start_[j]; p < start_[j + 1]; ++p)
    {
      const double* xi = data + static_cast<std::ptrdiff_t>(lowerRows_[p]) * d;
      const double u = entries_[p].upper;
      for (int c = 0; c < d; ++c)
        xj[c] -= u * xi[c];
    }
  }
  for (int i = 0; i < n_; ++i)
    rhs.row(i) = x.row(newIndex_[i]);
}

} // namespace cmp
