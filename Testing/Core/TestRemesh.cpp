#include <cmp/remesh/Remesh.h>
#include <cmp/mesh/SurfaceDistance.h>
#include <cmp/mesh/TriangleShape.h>
#include <cmp/remesh/SampleRelaxation.h>
#include "TestMeshes.h"
#include "ThreadCommunicator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>

using namespace cmp;

namespace
{

/// Two spheres of different tessellations parameterized on the ordered
/// octahedron, with their surfaces as given and their maps indexed.
class RemeshOfSpheres : public ::testing::Test
{
protected:
  void SetUp() override
  {
    for (int m = 0; m < 2; ++m)
    {
      ASSERT_TRUE(test::parameterizedSphere(domain_, 3 + m, parameterized_[m]).ok());
      surfaces_[m] = parameterized_[m].net.mesh.toTriangleMesh();
      ASSERT_TRUE(maps_[m].build(parameterized_[m].net, domain_, parameterized_[m].parameterization).ok());
    }
  }

  std::vector<RemeshModel> models(int count = 2) const
  {
    std::vector<RemeshModel> result;
    for (int m = 0; m < count; ++m)
      result.push_back({ &surfaces_[m], &maps_[m] });
    return result;
  }

  const BaseDomain domain_ = test::orderedOctahedronDomain();
  test::ParameterizedModel parameterized_[2];
  TriangleMesh surfaces_[2];
  ParameterizedSurface maps_[2];
};

} // namespace

TEST_F(RemeshOfSpheres, IsTheChainOfItsParts)
{
  // The stage is exactly: connectivity, placement, fold repair, positions,
  // folds, shape and distance, each as its own function gives it.
  RemeshOptions options;
  options.level = 3;
  CollectionRemesh remeshed;
  RemeshReport report;
  const Status status = remesh(domain_, models(), remeshed, options, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(remeshed.models.size(), 2u);
  ASSERT_EQ(report.models.size(), 2u);
  EXPECT_EQ(report.failedModel, -1);
  EXPECT_EQ(report.sampleRelaxationRounds, 0);

  SemiRegularMesh mesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain_, 3, mesh).ok());
  EXPECT_EQ(remeshed.mesh.triangles, mesh.triangles);
  const std::vector<int> nearest = nearestLandmarkOfTriangles(mesh, domain_.mesh.vertexCount());
  for (int m = 0; m < 2; ++m)
  {
    const TracedNet& net = parameterized_[m].net;
    std::vector<SurfacePoint> samples;
    ASSERT_TRUE(placeOnSurface(mesh, maps_[m], samples).ok());
    FoldRepairReport repair;
    ASSERT_TRUE(repairFolds(mesh, net.mesh, samples, {}, &repair).ok());
    const std::vector<Vec3> positions = samplePositions(net, samples);
    const RemeshedModel& placed = remeshed.models[m];
    const RemeshModelReport& figures = report.models[m];
    ASSERT_EQ(placed.samples.size(), samples.size());
    for (std::size_t v = 0; v < samples.size(); ++v)
    {
      EXPECT_EQ(placed.samples[v].vertex, samples[v].vertex) << "vertex " << v;
      EXPECT_EQ(placed.samples[v].weight, samples[v].weight) << "vertex " << v;
    }
    EXPECT_EQ(placed.positions, positions);
    const std::vector<char> folded = foldedTriangles(mesh, net.mesh, samples);
    EXPECT_EQ(placed.folded, folded);
    EXPECT_EQ(placed.foldsNearFeature, foldsNearLandmarks(nearest, domain_.mesh.vertexCount(), folded));
    EXPECT_EQ(figures.foldedBeforeRepair, repair.foldedBefore);
    EXPECT_EQ(figures.foldedAfterRepair, static_cast<int>(std::count(folded.begin(), folded.end(), 1)));
    const std::vector<char> centroidFlipped =
      centroidFlippedTriangles(surfaces_[m], TriangleMesh{ positions, mesh.triangles });
    EXPECT_EQ(placed.centroidFlipped, centroidFlipped);
    EXPECT_EQ(figures.centroidFlips, static_cast<int>(std::count(centroidFlipped.begin(), centroidFlipped.end(), 1)));
    EXPECT_EQ(figures.repair.movedVertices, repair.movedVertices);
    const TriangleShapeSummary shape = measureTriangleShapes(positions, mesh.triangles);
    EXPECT_EQ(figures.minimumAngleDegrees, shape.minimumAngleDegrees);
    EXPECT_EQ(figures.meanShapeQuality, shape.meanShapeQuality);
    EXPECT_GT(figures.minimumAngleDegrees, 10.0);
    EXPECT_LE(figures.meanShapeQuality, 1.0);

    ASSERT_TRUE(figures.distanceMeasured);
    const SurfaceDistance distance = surfaceDistance(surfaces_[m], TriangleMesh{ positions, mesh.triangles });
    EXPECT_EQ(figures.hausdorffDistance, distance.hausdorff());
    EXPECT_EQ(figures.hausdorffDistanceRelative, distance.hausdorff() / boundingBoxDiagonal(surfaces_[m]));
    EXPECT_EQ(figures.meanDistance, 0.5 * (distance.meanAToB + distance.meanBToA));
    EXPECT_EQ(figures.hausdorffPoint, distance.farthestPoint());
    EXPECT_GE(figures.hausdorffNearestFeature, 0);
    EXPECT_LT(figures.hausdorffNearestFeature, domain_.mesh.vertexCount());
    EXPECT_GE(figures.seconds, figures.placementSeconds);
  }
}

TEST_F(RemeshOfSpheres, OneModelGivenByItsLayoutIsTheCollectionOfOne)
{
  RemeshOptions options;
  options.level = 2;
  options.computeDistance = false;
  CollectionRemesh one, collection;
  RemeshReport report;
  ASSERT_TRUE(remesh(surfaces_[1], parameterized_[1].net, domain_, parameterized_[1].parameterization, one,
    options, &report).ok());
  ASSERT_TRUE(remesh(domain_, { models()[1] }, collection, options).ok());
  ASSERT_EQ(one.models.size(), 1u);
  EXPECT_EQ(one.models[0].positions, collection.models[0].positions);
  EXPECT_FALSE(report.models[0].distanceMeasured);
  EXPECT_EQ(report.models[0].hausdorffDistance, 0.0);
}

TEST_F(RemeshOfSpheres, RefinesAndRelaxesOverTheWholeCollection)
{
  RemeshOptions options;
  options.level = 4;
  options.adaptiveTolerance = 0.002;
  options.sampleRelaxationIterations = 2;
  options.repairFolds = false;
  options.computeDistance = false; // one pass: the tolerance is not checked on the placed remesh
  options.threads = 1;
  std::vector<double> progress;
  options.progress = [&](double f) { progress.push_back(f); };
  CollectionRemesh remeshed;
  RemeshReport report;
  ASSERT_TRUE(remesh(domain_, models(), remeshed, options, &report).ok());
  EXPECT_EQ(report.sampleRelaxationRounds, 2);
  EXPECT_EQ(report.adaptivePasses, 1);
  EXPECT_EQ(progress, (std::vector<double>{ 0.5, 1.0 }));

  std::vector<const ParameterizedSurface*> both{ &maps_[0], &maps_[1] };
  SemiRegularMesh mesh;
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(domain_, 4, flatnessSplitRule(both, 0.002), mesh).ok());
  SampleRelaxationOptions relaxation;
  relaxation.iterations = 2;
  ASSERT_TRUE(relaxSampleLocations(domain_, both, mesh, relaxation).ok());
  ASSERT_EQ(remeshed.mesh.vertexCount(), mesh.vertexCount());
  EXPECT_EQ(remeshed.mesh.triangles, mesh.triangles);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    ASSERT_EQ(remeshed.mesh.locations[v].weight, mesh.locations[v].weight) << "vertex " << v;
  // Without repair every vertex is where its parameterization puts it.
  for (int m = 0; m < 2; ++m)
  {
    EXPECT_EQ(report.models[m].repair.movedVertices, 0);
    EXPECT_EQ(report.models[m].foldedBeforeRepair, report.models[m].foldedAfterRepair);
  }
}

TEST_F(RemeshOfSpheres, AnAdaptiveRemeshFartherThanTheToleranceIsMadeAgain)
{
  // The split rule's probes see the maps before relaxation and repair move
  // the samples, so the first adaptive remesh ends farther than the
  // tolerance from a model; the triangles there are split once more and the
  // remesh made again, until every model is within the tolerance.
  RemeshOptions options;
  options.level = 6;
  options.adaptiveTolerance = 0.002;
  options.sampleRelaxationIterations = 2;
  std::vector<double> progress;
  options.progress = [&](double f) { progress.push_back(f); };

  RemeshOptions once = options;
  once.computeDistance = false; // no check: one pass
  CollectionRemesh first;
  RemeshReport firstReport;
  ASSERT_TRUE(remesh(domain_, models(), first, once, &firstReport).ok());
  EXPECT_EQ(firstReport.adaptivePasses, 1);
  int farAtFirst = 0;
  for (int m = 0; m < 2; ++m)
  {
    const std::vector<char> far = trianglesFartherThan(surfaces_[m], { first.models[m].positions, first.mesh.triangles },
      options.adaptiveTolerance * boundingBoxDiagonal(surfaces_[m]));
    farAtFirst += static_cast<int>(std::count(far.begin(), far.end(), 1));
  }
  ASSERT_GT(farAtFirst, 0) << "the first remesh is within the tolerance: the test no longer tests the passes";

  progress.clear();
  CollectionRemesh remeshed;
  RemeshReport report;
  ASSERT_TRUE(remesh(domain_, models(), remeshed, options, &report).ok());
  EXPECT_GE(report.adaptivePasses, 2);
  ASSERT_EQ(report.adaptiveTriangles.size(), static_cast<std::size_t>(report.adaptivePasses));
  EXPECT_EQ(report.adaptiveTriangles.front(), static_cast<int>(first.mesh.triangles.size()));
  EXPECT_EQ(report.adaptiveTriangles.back(), static_cast<int>(remeshed.mesh.triangles.size()));
  EXPECT_TRUE(std::is_sorted(report.adaptiveTriangles.begin(), report.adaptiveTriangles.end()));
  // Only where it was far: well below the uniform remesh of that level.
  EXPECT_LT(remeshed.mesh.triangles.size(), 8u * 4096u / 2u);
  for (int m = 0; m < 2; ++m)
  {
    EXPECT_LE(report.models[m].hausdorffDistanceRelative, options.adaptiveTolerance) << "model " << m;
    const std::vector<char> far = trianglesFartherThan(surfaces_[m],
      { remeshed.models[m].positions, remeshed.mesh.triangles },
      options.adaptiveTolerance * boundingBoxDiagonal(surfaces_[m]));
    EXPECT_EQ(std::count(far.begin(), far.end(), 1), 0) << "model " << m;
  }
  ASSERT_FALSE(progress.empty());
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(progress.back(), 1.0);
}

TEST_F(RemeshOfSpheres, PlacesTheModelsOnSeveralThreadsWithTheSameResult)
{
  // Six models (the two spheres three times), so that each of three threads
  // gets some; every figure but the times is the same as on one thread.
  std::vector<RemeshModel> six;
  for (int copy = 0; copy < 3; ++copy)
    for (const RemeshModel& model : models())
      six.push_back(model);
  RemeshOptions options;
  options.level = 4;
  options.sampleRelaxationIterations = 1;
  CollectionRemesh alone;
  RemeshReport aloneReport;
  options.threads = 1;
  ASSERT_TRUE(remesh(domain_, six, alone, options, &aloneReport).ok());
  for (int threads : { 3, 0 })
  {
    options.threads = threads;
    std::vector<double> progress;
    options.progress = [&](double f) { progress.push_back(f); };
    CollectionRemesh together;
    RemeshReport report;
    ASSERT_TRUE(remesh(domain_, six, together, options, &report).ok()) << threads << " threads";
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
    ASSERT_EQ(together.models.size(), six.size());
    for (std::size_t m = 0; m < six.size(); ++m)
    {
      EXPECT_EQ(together.models[m].positions, alone.models[m].positions) << "model " << m << ", " << threads;
      EXPECT_EQ(together.models[m].folded, alone.models[m].folded) << "model " << m;
      EXPECT_EQ(together.models[m].centroidFlipped, alone.models[m].centroidFlipped) << "model " << m;
      EXPECT_EQ(report.models[m].hausdorffDistance, aloneReport.models[m].hausdorffDistance) << "model " << m;
      EXPECT_EQ(report.models[m].foldedBeforeRepair, aloneReport.models[m].foldedBeforeRepair) << "model " << m;
    }
  }
}

TEST_F(RemeshOfSpheres, RefusesOptionsOutOfRangeAndMissingModels)
{
  const auto expectError = [&](const RemeshOptions& options, const std::vector<RemeshModel>& given,
                             const std::string& expected)
  {
    CollectionRemesh out;
    RemeshReport report;
    report.failedModel = 7;
    const Status status = remesh(domain_, given, out, options, &report);
    EXPECT_FALSE(status.ok()) << expected;
    EXPECT_EQ(report.failedModel, -1) << "no model was placed";
    EXPECT_NE(status.message().find(expected), std::string::npos) << status.message();
  };
  RemeshOptions options;
  options.level = kMaximumRemeshLevel + 1;
  expectError(options, models(), "Level must be between 0 and 8 (it is 9)");
  options.level = -1;
  expectError(options, models(), "Level must be between 0 and 8 (it is -1)");
  options = {};
  options.adaptiveTolerance = -0.1;
  expectError(options, models(), "AdaptiveTolerance must be 0 (uniform)");
  options.adaptiveTolerance = std::nan("");
  expectError(options, models(), "AdaptiveTolerance must be 0 (uniform)");
  options = {};
  options.sampleRelaxationIterations = -1;
  expectError(options, models(), "SampleRelaxationIterations must be 0 (none)");
  options = {};
  expectError(options, { RemeshModel{ &surfaces_[0], nullptr } }, "model 0 is missing");
  const ParameterizedSurface unbuilt;
  expectError(options, { models()[0], RemeshModel{ &surfaces_[1], &unbuilt } }, "model 1 is not parameterized");
  EXPECT_TRUE(checkRemeshOptions({}).ok());
}

TEST_F(RemeshOfSpheres, ARankThatFailsBeforeRelaxingStopsEveryRank)
{
  // With relaxation the call is collective: rank 1's missing model must
  // not leave rank 0 waiting in the relaxation's sums.
  RemeshOptions options;
  options.level = 2;
  options.sampleRelaxationIterations = 1;
  std::mutex mutex;
  test::runOnRanks(2, [&](Communicator& communicator) {
    std::vector<RemeshModel> mine = { communicator.rank() == 0 ? models()[0] : RemeshModel{} };
    CollectionRemesh out;
    const Status status = remesh(domain_, mine, communicator, out, options);
    const std::lock_guard<std::mutex> lock(mutex);
    EXPECT_FALSE(status.ok()) << "rank " << communicator.rank();
    EXPECT_NE(status.message().find("model 0 is missing"), std::string::npos) << status.message();
  });
}

TEST_F(RemeshOfSpheres, RanksMakeTheSamePassesOfAnAdaptiveRemesh)
{
  // Every rank holds both spheres (the same connectivity, which relaxation
  // checks): the passes that split far triangles share the far triangles
  // over the ranks and must end alike on every rank, in the same number of
  // passes as one process.
  RemeshOptions options;
  options.level = 6;
  options.adaptiveTolerance = 0.002;
  options.sampleRelaxationIterations = 2;
  options.threads = 1;
  CollectionRemesh alone;
  RemeshReport aloneReport;
  ASSERT_TRUE(remesh(domain_, models(), alone, options, &aloneReport).ok());
  ASSERT_GE(aloneReport.adaptivePasses, 2);
  std::mutex mutex;
  test::runOnRanks(2, [&](Communicator& communicator) {
    CollectionRemesh out;
    RemeshReport report;
    const Status status = remesh(domain_, models(), communicator, out, options, &report);
    const std::lock_guard<std::mutex> lock(mutex);
    ASSERT_TRUE(status.ok()) << "rank " << communicator.rank() << ": " << status.message();
    EXPECT_EQ(report.adaptivePasses, aloneReport.adaptivePasses) << "rank " << communicator.rank();
    EXPECT_EQ(out.mesh.triangles, alone.mesh.triangles) << "rank " << communicator.rank();
  });
}
