#include "MeanValueSystem.h"

#include <Eigen/Geometry>
#include <Eigen/SparseLU>

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

Status solveConvexCombinationSystem(const Eigen::SparseMatrix<double>& weights, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values)
{
  const int n = static_cast<int>(weights.rows());
  const int d = static_cast<int>(fixedValues.cols());
  std::vector<int> unknown(n, -1);
  int unknowns = 0;
  for (int v = 0; v < n; ++v)
    if (fixedRow[v] < 0)
      unknown[v] = unknowns++;

  // Row i: sum_j w_ij (x_i - x_j) = 0; known x_j go to the right-hand side.
  // Column-major storage: iterate columns j, entries (i, j).
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(2 * static_cast<std::size_t>(weights.nonZeros()));
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, d);
  for (int j = 0; j < weights.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(weights, j); it; ++it)
    {
      const int i = static_cast<int>(it.row());
      if (unknown[i] < 0)
        continue;
      const double w = it.value();
      entries.emplace_back(unknown[i], unknown[i], w);
      if (unknown[j] >= 0)
        entries.emplace_back(unknown[i], unknown[j], -w);
      else
        rhs.row(unknown[i]) += w * fixedValues.row(fixedRow[j]);
    }
  Eigen::MatrixXd solution;
  if (unknowns > 0) // Eigen's SparseLU divides by zero on an empty system
  {
    Eigen::SparseMatrix<double> system(unknowns, unknowns);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    solver.compute(system);
    if (solver.info() != Eigen::Success)
      return Status::error("the mean value system could not be factorized (degenerate geometry?)");
    solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite())
      return Status::error("the mean value system could not be solved");
  }
  values.resize(n, d);
  for (int v = 0; v < n; ++v)
    if (unknown[v] >= 0)
      values.row(v) = solution.row(unknown[v]);
    else
      values.row(v) = fixedValues.row(fixedRow[v]);
  return {};
}

Status solveMeanValueSystem(const TriangleMesh& mesh, const std::vector<int>& fixedRow,
  const Eigen::MatrixXd& fixedValues, Eigen::MatrixXd& values)
{
  return solveConvexCombinationSystem(meanValueWeights(mesh), fixedRow, fixedValues, values);
}

} // namespace cmp
