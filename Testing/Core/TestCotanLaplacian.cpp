#include <cmp/numerics/CotanLaplacian.h>
#include "TestMeshes.h"

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace cmp;

TEST(CotanLaplacian, RightTriangleHasTheKnownEntries)
{
  // Right angle at 0, 45 degrees at 1 and 2: the edge 1-2 faces cot 90 = 0,
  // the edges 0-1 and 0-2 face cot 45 = 1, halved.
  TriangleMesh triangle;
  triangle.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
  triangle.triangles = { { 0, 1, 2 } };
  const Eigen::MatrixXd expected = (Eigen::MatrixXd(3, 3) << 1.0, -0.5, -0.5, -0.5, 0.5, 0.0, -0.5, 0.0, 0.5).finished();
  const Eigen::MatrixXd laplacian = Eigen::MatrixXd(cotanLaplacian(triangle));
  EXPECT_LT((laplacian - expected).cwiseAbs().maxCoeff(), 1e-14) << laplacian;
}

TEST(CotanLaplacian, EquilateralTriangleHasCot60)
{
  TriangleMesh triangle;
  triangle.points = { Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, std::sqrt(3.0), 0) };
  triangle.triangles = { { 0, 1, 2 } };
  const Eigen::MatrixXd laplacian = Eigen::MatrixXd(cotanLaplacian(triangle));
  const double cot60 = 1.0 / std::sqrt(3.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(laplacian(i, j), i == j ? cot60 : -0.5 * cot60, 1e-14) << i << "," << j;
}

TEST(CotanLaplacian, SymmetricRowsSumToZeroAndSemiDefinite)
{
  const TriangleMesh mesh = test::bumpySphere(2);
  const Eigen::SparseMatrix<double> laplacian = cotanLaplacian(mesh);
  ASSERT_EQ(laplacian.rows(), mesh.vertexCount());
  ASSERT_EQ(laplacian.cols(), mesh.vertexCount());
  const Eigen::MatrixXd dense = Eigen::MatrixXd(laplacian);
  const double scale = dense.cwiseAbs().maxCoeff();
  EXPECT_LT((dense - dense.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT(dense.rowwise().sum().cwiseAbs().maxCoeff(), 1e-12 * scale);
  // Off the diagonal, only edges: each vertex's neighbours.
  for (int i = 0; i < mesh.vertexCount(); ++i)
    for (int j = 0; j < mesh.vertexCount(); ++j)
      if (i != j && dense(i, j) != 0.0)
      {
        bool edge = false;
        for (const Triangle& t : mesh.triangles)
          edge = edge || (std::count(t.begin(), t.end(), i) && std::count(t.begin(), t.end(), j));
        EXPECT_TRUE(edge) << i << "," << j;
      }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(dense);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-10 * scale);
  // One closed surface: the constants alone are in the kernel.
  EXPECT_GT(eigen.eigenvalues()(1), 1e-6 * scale);
}

TEST(CotanLaplacian, LinearFunctionsAreHarmonicInsideAFlatGrid)
{
  constexpr int n = 4;
  const TriangleMesh grid = test::flatSquare(n);
  const Eigen::SparseMatrix<double> laplacian = cotanLaplacian(grid);
  Eigen::VectorXd f(grid.vertexCount());
  for (int v = 0; v < grid.vertexCount(); ++v)
    f(v) = 2.0 * grid.points[v].x() - 3.0 * grid.points[v].y() + 1.0;
  const Eigen::VectorXd lf = laplacian * f;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i)
      EXPECT_NEAR(lf(j * (n + 1) + i), 0.0, 1e-12) << i << "," << j;
  // f' L f is the Dirichlet energy: |grad f|^2 = 13 over the area 4.
  EXPECT_NEAR(f.dot(lf), 13.0 * 4.0, 1e-9);
}
