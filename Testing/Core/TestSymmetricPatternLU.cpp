#include <cmp/numerics/MeanValueSystem.h>
#include <cmp/numerics/SymmetricPatternLU.h>
#include "TestMeshes.h"

#include <Eigen/SparseLU>
#include <gtest/gtest.h>

#include <random>

using namespace cmp;

namespace
{

/// The free vertices' matrix of the mean value system of `model` with its
/// landmarks fixed, and its right-hand sides for the unit F-vectors.
void meanValueSystem(const test::LandmarkedModel& model, Eigen::SparseMatrix<double>& matrix, Eigen::MatrixXd& rhs)
{
  const TriangleMesh& mesh = model.data.mesh;
  const int n = mesh.vertexCount();
  const int featureCount = static_cast<int>(model.landmarks.size());
  std::vector<int> fixed(n, -1), unknown(n, -1);
  for (int f = 0; f < featureCount; ++f)
    fixed[model.landmarks[f]] = f;
  int unknowns = 0;
  for (int v = 0; v < n; ++v)
    if (fixed[v] < 0)
      unknown[v] = unknowns++;
  const Eigen::SparseMatrix<double> weights = meanValueWeights(mesh);
  std::vector<Eigen::Triplet<double>> entries;
  rhs = Eigen::MatrixXd::Zero(unknowns, featureCount);
  for (int j = 0; j < weights.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(weights, j); it; ++it)
    {
      const int i = static_cast<int>(it.row());
      if (unknown[i] < 0)
        continue;
      entries.emplace_back(unknown[i], unknown[i], it.value());
      if (unknown[j] >= 0)
        entries.emplace_back(unknown[i], unknown[j], -it.value());
      else
        rhs(unknown[i], fixed[j]) += it.value();
    }
  matrix.resize(unknowns, unknowns);
  matrix.setFromTriplets(entries.begin(), entries.end());
}

} // namespace

TEST(SymmetricPatternLU, SolvesAMeanValueSystemAsAPivotingLUDoes)
{
  CMP_REQUIRE_SHARED_DATA();
  Eigen::SparseMatrix<double> matrix;
  Eigen::MatrixXd rhs;
  meanValueSystem(test::landmarkedRealModel("384"), matrix, rhs);

  Eigen::SparseLU<Eigen::SparseMatrix<double>> pivoting(matrix);
  ASSERT_EQ(pivoting.info(), Eigen::Success);
  const Eigen::MatrixXd expected = pivoting.solve(rhs);

  SymmetricPatternLU lu;
  ASSERT_TRUE(lu.compute(matrix));
  Eigen::MatrixXd x = rhs;
  lu.solveInPlace(x);
  EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((matrix * x - rhs).cwiseAbs().maxCoeff(), 1e-10 * rhs.cwiseAbs().maxCoeff());
  // The fill-reducing ordering matters: without it the factor of a surface
  // mesh of n vertices fills towards n^2 / 2; with it, a few dozen per row.
  EXPECT_LT(lu.factorNonZeros(), 40 * matrix.rows());
}

TEST(SymmetricPatternLU, TakesAnUnsymmetricPatternAndRefusesZeroPivots)
{
  // A diagonally dominant M-matrix whose couplings run one way only
  // (a(i, i+1) set, a(i+1, i) not) on a random sparse pattern.
  const int n = 60;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::uniform_real_distribution<double> weight(0.1, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> rowSum(n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
    {
      const int j = column(random);
      if (j == i)
        continue;
      const double w = weight(random);
      entries.emplace_back(i, j, -w);
      rowSum[i] += w;
    }
  for (int i = 0; i < n; ++i)
    entries.emplace_back(i, i, rowSum[i] + 0.5);
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 3);

  SymmetricPatternLU lu;
  ASSERT_TRUE(lu.compute(matrix));
  Eigen::MatrixXd x = rhs;
  lu.solveInPlace(x);
  EXPECT_LT((matrix * x - rhs).cwiseAbs().maxCoeff(), 1e-12);

  // [[0 1] [1 0]] is invertible but has no LU without pivoting.
  Eigen::SparseMatrix<double> swap(2, 2);
  swap.insert(0, 1) = 1.0;
  swap.insert(1, 0) = 1.0;
  EXPECT_FALSE(lu.compute(swap));
  // An empty system is solved by nothing.
  EXPECT_TRUE(lu.compute(Eigen::SparseMatrix<double>(0, 0)));
  Eigen::MatrixXd none(0, 2);
  lu.solveInPlace(none);
  EXPECT_EQ(none.rows(), 0);
}

TEST(SymmetricPatternLU, ConvexCombinationSolversAgree)
{
  CMP_REQUIRE_SHARED_DATA();
  const test::LandmarkedModel model = test::landmarkedRealModel("391");
  const int n = model.data.mesh.vertexCount();
  const int featureCount = static_cast<int>(model.landmarks.size());
  std::vector<int> fixedRow(n, -1);
  for (int f = 0; f < featureCount; ++f)
    fixedRow[model.landmarks[f]] = f;
  const Eigen::MatrixXd unitVectors = Eigen::MatrixXd::Identity(featureCount, featureCount);
  Eigen::MatrixXd pivoting, diagonal;
  ASSERT_TRUE(solveMeanValueSystem(model.data.mesh, fixedRow, unitVectors, pivoting).ok());
  ASSERT_TRUE(solveMeanValueSystem(model.data.mesh, fixedRow, unitVectors, diagonal,
    ConvexCombinationFactorization::DiagonalPivots).ok());
  EXPECT_LT((pivoting - diagonal).cwiseAbs().maxCoeff(), 1e-10);
  // Rows of F-vectors still sum to one.
  EXPECT_LT((diagonal.rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-10);
}
