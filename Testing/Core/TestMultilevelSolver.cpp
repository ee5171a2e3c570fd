#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/layout/LayoutValidator.h>
#include <cmp/numerics/MeanValueSystem.h>
#include <cmp/numerics/MultilevelSolver.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/mesh/Subdivision.h>
#include "TestMeshes.h"
#include "TestShapes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cmp;

namespace
{

/// Model 387 subdivided once (58,714 vertices): big enough for three levels
/// with the default coarsest size, the landmarks still at their vertices.
struct SubdividedModel
{
  TriangleMesh mesh;
  LandmarkList landmarks;
};

SubdividedModel subdivided387()
{
  const test::LandmarkedModel model = test::landmarkedRealModel("387");
  return { subdivideMidpoint(model.data.mesh, 1), model.landmarks };
}

std::vector<int> fixedRowsOf(const SubdividedModel& model)
{
  std::vector<int> fixedRow(model.mesh.vertexCount(), -1);
  for (std::size_t f = 0; f < model.landmarks.size(); ++f)
    fixedRow[model.landmarks[f]] = static_cast<int>(f);
  return fixedRow;
}

} // namespace

TEST(MultilevelSolver, StaysNearTheExactSolutionAndItsCyclesMatter)
{
  CMP_REQUIRE_SHARED_DATA();
  const SubdividedModel model = subdivided387();
  const std::vector<int> fixedRow = fixedRowsOf(model);
  const int featureCount = static_cast<int>(model.landmarks.size());
  const Eigen::MatrixXd unitVectors = Eigen::MatrixXd::Identity(featureCount, featureCount);
  const Eigen::SparseMatrix<double> weights = meanValueWeights(model.mesh);

  Eigen::MatrixXd exact, approximate, nestedOnly;
  ASSERT_TRUE(solveConvexCombinationSystem(weights, fixedRow, unitVectors, exact).ok());
  MultilevelReport report;
  MultilevelOptions options;
  options.coarsestUnknowns = 3000;
  ASSERT_TRUE(solveConvexCombinationMultilevel(weights, fixedRow, unitVectors, approximate, options, &report).ok());
  MultilevelOptions withoutCycles = options;
  withoutCycles.cycles = 0;
  ASSERT_TRUE(solveConvexCombinationMultilevel(weights, fixedRow, unitVectors, nestedOnly, withoutCycles).ok());

  ASSERT_GE(report.unknownsPerLevel.size(), 3u) << "the test must exercise more than one coarse level";
  EXPECT_EQ(report.unknownsPerLevel.front(), model.mesh.vertexCount() - featureCount);
  EXPECT_LE(report.unknownsPerLevel.back(), options.coarsestUnknowns);
  for (std::size_t l = 1; l < report.unknownsPerLevel.size(); ++l)
    EXPECT_LT(report.unknownsPerLevel[l], report.unknownsPerLevel[l - 1] / 3) << "level " << l;

  ASSERT_EQ(approximate.rows(), exact.rows());
  ASSERT_EQ(approximate.cols(), exact.cols());
  EXPECT_GE(approximate.minCoeff(), -1e-3);
  EXPECT_LE(approximate.maxCoeff(), 1.0 + 1e-3);
  EXPECT_LT((approximate.rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-12);
  for (int f = 0; f < featureCount; ++f)
    EXPECT_EQ(approximate.row(model.landmarks[f]), unitVectors.row(f)) << "landmark " << f;
  const double meanDeviation = (approximate - exact).cwiseAbs().mean();
  const double largestDeviation = (approximate - exact).cwiseAbs().maxCoeff();
  const double nestedDeviation = (nestedOnly - exact).cwiseAbs().mean();
  std::cout << "levels " << report.unknownsPerLevel.size() << ", mean deviation " << meanDeviation << ", largest "
            << largestDeviation << "; without cycles " << nestedDeviation << "\n";
  EXPECT_LT(meanDeviation, 0.003);
  EXPECT_LT(largestDeviation, 0.05);
  EXPECT_LT(meanDeviation, 0.2 * nestedDeviation) << "the V-cycles should remove most of the nested start's error";
}

TEST(MultilevelSolver, SmallSystemsAreSolvedExactly)
{
  const TriangleMesh sphere = test::bumpySphere(3);
  std::vector<int> fixedRow(sphere.vertexCount(), -1);
  fixedRow[0] = 0;
  fixedRow[sphere.vertexCount() / 2] = 1;
  const Eigen::MatrixXd ends = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::SparseMatrix<double> weights = meanValueWeights(sphere);
  Eigen::MatrixXd exact, multilevel;
  ASSERT_TRUE(solveConvexCombinationSystem(weights, fixedRow, ends, exact).ok());
  MultilevelReport report;
  ASSERT_TRUE(solveConvexCombinationMultilevel(weights, fixedRow, ends, multilevel, {}, &report).ok());
  EXPECT_EQ(report.unknownsPerLevel.size(), 1u);
  EXPECT_LT((multilevel - exact).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(MultilevelSolver, StopsCoarseningAGraphThatDoesNotShrink)
{
  // A star: every leaf's only neighbour is the hub, so aggregation cannot
  // halve it; the solver must stop coarsening and still solve.
  const int leaves = 50;
  std::vector<Eigen::Triplet<double>> entries;
  for (int leaf = 1; leaf <= leaves; ++leaf)
  {
    entries.emplace_back(0, leaf, 1.0);
    entries.emplace_back(leaf, 0, 1.0);
  }
  Eigen::SparseMatrix<double> weights(leaves + 1, leaves + 1);
  weights.setFromTriplets(entries.begin(), entries.end());
  std::vector<int> fixedRow(leaves + 1, -1);
  fixedRow[0] = 0;
  Eigen::MatrixXd values;
  MultilevelOptions options;
  options.coarsestUnknowns = 1;
  ASSERT_TRUE(solveConvexCombinationMultilevel(weights, fixedRow, Eigen::MatrixXd::Constant(1, 1, 0.25), values,
    options).ok());
  EXPECT_LT((values.array() - 0.25).abs().maxCoeff(), 1e-12);
}

TEST(NetTracer, CoarseToFineParameterizationGivesAValidNetAsShort)
{
  CMP_REQUIRE_SHARED_DATA();
  const SubdividedModel model = subdivided387();
  const BaseDomain domain = test::realBaseDomain("381");
  ASSERT_GT(domain.mesh.vertexCount(), 0);
  double lengths[2] = { 0.0, 0.0 };
  for (const bool multilevel : { false, true })
  {
    NetTracerOptions options;
    options.featureCoordinates.directSolveLimit = multilevel ? 0 : model.mesh.vertexCount();
    options.featureCoordinates.multilevel.coarsestUnknowns = 3000;
    TracedNet net;
    NetTracerReport report;
    ASSERT_TRUE(traceFeatureNet(model.mesh, model.landmarks, domain, net, options, &report).ok());
    for (const std::string& problem : validateLayout(toLabelledSurface(net, domain), toBaseTriangles(domain)))
      ADD_FAILURE() << (multilevel ? "coarse to fine: " : "direct: ") << problem;
    lengths[multilevel] = report.netLength;
  }
  std::cout << "net length direct " << lengths[0] << ", coarse to fine " << lengths[1] << "\n";
  EXPECT_LT(lengths[1], 1.02 * lengths[0]);
}
