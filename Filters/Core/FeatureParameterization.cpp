#include "FeatureParameterization.h"

#include <Eigen/Geometry>
#include <Eigen/SparseLU>

namespace cmp
{

void FeatureCoordinates::appendInterpolated(int a, int b, double t)
{
  const std::size_t rowA = static_cast<std::size_t>(a) * featureCount;
  const std::size_t rowB = static_cast<std::size_t>(b) * featureCount;
  for (int f = 0; f < featureCount; ++f)
    values.push_back((1.0 - t) * values[rowA + f] + t * values[rowB + f]);
}

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

Status computeFeatureCoordinates(const TriangleMesh& mesh, const LandmarkList& landmarks, FeatureCoordinates& out)
{
  const int n = mesh.vertexCount();
  const int featureCount = static_cast<int>(landmarks.size());
  std::vector<int> featureAt(n, -1), unknown(n, -1);
  for (int f = 0; f < featureCount; ++f)
    featureAt[landmarks[f]] = f;
  int unknowns = 0;
  for (int v = 0; v < n; ++v)
    if (featureAt[v] < 0)
      unknown[v] = unknowns++;

  // Mean value weight of edge (i, j) from triangle (i, j, k): tan(angle at i / 2) / |pj - pi|.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(7 * static_cast<std::size_t>(unknowns));
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, featureCount);
  for (const Triangle& tri : mesh.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int i = tri[k];
      if (unknown[i] < 0)
        continue;
      const Vec3 e1 = mesh.points[tri[(k + 1) % 3]] - mesh.points[i];
      const Vec3 e2 = mesh.points[tri[(k + 2) % 3]] - mesh.points[i];
      const double tangent = halfAngleTangent(e1, e2);
      for (const auto& [j, edge] : { std::pair<int, Vec3>{ tri[(k + 1) % 3], e1 }, { tri[(k + 2) % 3], e2 } })
      {
        const double w = tangent / std::max(edge.norm(), 1e-300);
        entries.emplace_back(unknown[i], unknown[i], w);
        if (unknown[j] >= 0)
          entries.emplace_back(unknown[i], unknown[j], -w);
        else
          rhs(unknown[i], featureAt[j]) += w;
      }
    }
  }
  Eigen::MatrixXd solution;
  if (unknowns > 0) // every vertex may be a landmark; Eigen's SparseLU divides by zero on an empty system
  {
    Eigen::SparseMatrix<double> system(unknowns, unknowns);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    solver.compute(system);
    if (solver.info() != Eigen::Success)
      return Status::error("the harmonic parameterization could not be factorized (degenerate geometry?)");
    solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite())
      return Status::error("the harmonic parameterization could not be solved");
  }

  out.featureCount = featureCount;
  out.values.assign(static_cast<std::size_t>(n) * featureCount, 0.0);
  for (int v = 0; v < n; ++v)
  {
    double* row = out.values.data() + static_cast<std::size_t>(v) * featureCount;
    if (featureAt[v] >= 0)
      row[featureAt[v]] = 1.0;
    else
      for (int f = 0; f < featureCount; ++f)
        row[f] = solution(unknown[v], f);
  }
  return {};
}

} // namespace cmp
