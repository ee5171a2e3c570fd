#include <cmp/numerics/MeanValueSystem.h>

#include <Eigen/Geometry>

namespace cmp
{
namespace
{

/// tan(theta/2) of the angle between e1 and e2, computed without acos.
double halfAngleTangent(const Vec3& e1, const Vec3& e2)
{
  const double sine = e1.cross(e2).norm();
  const double cosineScaled = e1.norm() * e2.norm() + e1.dot(e2);
  return cosineScaled > 0.0 ? sine / cosineScaled : 1e12;
}

} // namespace

Eigen::SparseMatrix<double> meanValueWeights(const TriangleMesh& mesh)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(6 * mesh.triangles.size());
  for (const Triangle& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int i = tri[k], j1 = tri[(k + 1) % 3], j2 = tri[(k + 2) % 3];
      const Vec3 e1 = mesh.points[j1] - mesh.points[i];
      const Vec3 e2 = mesh.points[j2] - mesh.points[i];
      const double tangent = halfAngleTangent(e1, e2);
      entries.emplace_back(i, j1, tangent / std::max(e1.norm(), 1e-300));
      entries.emplace_back(i, j2, tangent / std::max(e2.norm(), 1e-300));
    }
  Eigen::SparseMatrix<double> weights(mesh.vertexCount(), mesh.vertexCount());
  weights.setFromTriplets(entries.begin(), entries.end());
  return weights;
}

Status ConvexCombinationSolver::factorize(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  ConvexCombinationFactorization factorization)
{
  factorization_ = factorization;
  const int n = static_cast<int>(weights.rows());
  fixedRow_ = fixedRow;
  unknown_.assign(n, -1);
  unknowns_ = 0;
  for (int v = 0; v < n; ++v)
    if (fixedRow[v] < 0)
      unknown_[v] = unknowns_++;

  // Row i: sum_j w_ij (x_i - x_j) = b_i; known x_j go to the right-hand side.
  // Column-major storage: iterate columns j, entries (i, j).
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(2 * static_cast<std::size_t>(weights.nonZeros()));
  couplings_.clear();
  for (int j = 0; j < weights.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(weights, j); it; ++it)
    {
      const int i = static_cast<int>(it.row());
      if (unknown_[i] < 0)
        continue;
      const double w = it.value();
      entries.emplace_back(unknown_[i], unknown_[i], w);
      if (unknown_[j] >= 0)
        entries.emplace_back(unknown_[i], unknown_[j], -w);
      else
        couplings_.push_back({ unknown_[i], fixedRow[j], w });
    }
  if (unknowns_ == 0) // Eigen's SparseLU divides by zero on an empty system
    return {};
  Eigen::SparseMatrix<double> system(unknowns_, unknowns_);
  system.setFromTriplets(entries.begin(), entries.end());
  const bool factorized = factorization == ConvexCombinationFactorization::DiagonalPivots
    ? diagonalLu_.compute(system)
    : (lu_.compute(system), lu_.info() == Eigen::Success);
  if (!factorized)
    return Status::error("the mean value system could not be factorized (degenerate geometry?)");
  return {};
}

Status ConvexCombinationSolver::solve(
  const Eigen::MatrixXd& fixedValues, const Eigen::MatrixXd* rhs, Eigen::MatrixXd& values) const
{
  const int n = static_cast<int>(unknown_.size());
  const int d = static_cast<int>(fixedValues.cols());
  Eigen::MatrixXd solution;
  if (unknowns_ > 0)
  {
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(unknowns_, d);
    if (rhs)
      for (int v = 0; v < n; ++v)
        if (unknown_[v] >= 0)
          b.row(unknown_[v]) = rhs->row(v);
    for (const Coupling& c : couplings_)
      b.row(c.unknown) += c.weight * fixedValues.row(c.fixedRow);
    bool solved = true;
    if (factorization_ == ConvexCombinationFactorization::DiagonalPivots)
    {
      diagonalLu_.solveInPlace(b);
      solution = std::move(b);
    }
    else
    {
      solution = lu_.solve(b);
      solved = lu_.info() == Eigen::Success;
    }
    if (!solved || !solution.allFinite())
      return Status::error("the mean value system could not be solved");
  }
  values.resize(n, d);
  for (int v = 0; v < n; ++v)
    if (unknown_[v] >= 0)
      values.row(v) = solution.row(unknown_[v]);
    else
      values.row(v) = fixedValues.row(fixedRow_[v]);
  return {};
}

Status solveConvexCombinationSystem(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values, ConvexCombinationFactorization factorization)
{
  ConvexCombinationSolver solver;
  if (Status s = solver.factorize(weights, fixedRow, factorization); !s.ok())
    return s;
  return solver.solve(fixedValues, nullptr, values);
}

Status solveMeanValueSystem(const TriangleMesh& mesh, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values, ConvexCombinationFactorization factorization)
{
  return solveConvexCombinationSystem(meanValueWeights(mesh), fixedRow, fixedValues, values, factorization);
}

} // namespace cmp
