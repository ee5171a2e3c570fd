#include <cmp/remesh/SampleRelaxation.h>
#include <cmp/mesh/SurfaceDistance.h>
#include "TestMeshes.h"
#include "ThreadCommunicator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>

using namespace cmp;

namespace
{

/// Hausdorff distance of the remesh of `model` from it, over its diagonal.
double relativeHausdorff(const SemiRegularMesh& remesh, const ParameterizedSurface& surface, const TracedNet& net)
{
  std::vector<SurfacePoint> samples;
  EXPECT_TRUE(placeOnSurface(remesh, surface, samples).ok());
  const TriangleMesh drawn{ samplePositions(net, samples), remesh.triangles };
  return surfaceDistance(drawn, net.mesh.toTriangleMesh()).hausdorff() / surface.boundingBoxDiagonal();
}

bool strictlyInside(const SurfacePoint& at)
{
  return std::all_of(at.weight.begin(), at.weight.end(), [](double c) { return c > 0.0; });
}

/// Remesh triangles that are not counter-clockwise in their base triangle.
int clockwiseTriangles(const BaseDomain& domain, const SemiRegularMesh& remesh)
{
  int clockwise = 0;
  for (std::size_t t = 0; t < remesh.triangles.size(); ++t)
  {
    Vec2 corner[3];
    for (int k = 0; k < 3; ++k)
    {
      const SurfacePoint& at = remesh.locations[remesh.triangles[t][k]];
      std::array<double, 3> c{};
      EXPECT_TRUE(coordinatesInTriangle(domain, at.triangle, at.weight, remesh.patchOfTriangle[t], c));
      corner[k] = Vec2(c[1], c[2]);
    }
    clockwise += !(cross2(corner[1] - corner[0], corner[2] - corner[0]) > 0.0);
  }
  return clockwise;
}

/// Every vertex's base coordinates the same, bit for bit.
void expectSameLocations(const SemiRegularMesh& mesh, const SemiRegularMesh& expected)
{
  ASSERT_EQ(mesh.vertexCount(), expected.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
    ASSERT_EQ(mesh.locations[v].weight, expected.locations[v].weight) << "vertex " << v;
}

/// Model 387 parameterized on `L0` from 381, indexed once for the tests
/// that need a model but not a particular result, and a level-3 remesh.
class SampleRelaxationOn387 : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    if (test::sharedDataDir().empty())
      return; // each test skips
    domain_ = new BaseDomain(test::realBaseDomain("381"));
    indexed_ = new test::IndexedModels;
    const Status status = test::indexRealModels({ "387" }, *domain_, false, *indexed_);
    ASSERT_TRUE(status.ok()) << status.message();
  }
  static void TearDownTestSuite()
  {
    delete indexed_;
    delete domain_;
  }
  void SetUp() override
  {
    CMP_REQUIRE_SHARED_DATA();
    ASSERT_TRUE(buildSemiRegularMesh(*domain_, 3, mesh).ok());
  }

  const BaseDomain& domain() const { return *domain_; }
  const std::vector<const ParameterizedSurface*>& collection() const { return indexed_->collection; }

  SemiRegularMesh mesh; ///< Level 3, as built.

private:
  static BaseDomain* domain_;
  static test::IndexedModels* indexed_;
};

BaseDomain* SampleRelaxationOn387::domain_ = nullptr;
test::IndexedModels* SampleRelaxationOn387::indexed_ = nullptr;

} // namespace

TEST(SampleRelaxation, ReachesFurtherIntoATailAndKeepsAValidLayout)
{
  CMP_REQUIRE_SHARED_DATA();
  // 385's tail has no landmark at its tip: even with LowerStretch it takes
  // a sliver of a base triangle, which the level-5 grid samples sparsely
  // (measured: 0.046 -> 0.018 of the diagonal).
  const BaseDomain domain = test::realBaseDomain("381");
  test::IndexedModels indexed;
  const Status status = test::indexRealModels({ "385" }, domain, true, indexed);
  ASSERT_TRUE(status.ok()) << status.message();
  SemiRegularMesh uniform, relaxed;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, uniform).ok());
  relaxed = uniform;
  SampleRelaxationReport report;
  const Status relaxing = relaxSampleLocations(domain, indexed.collection, relaxed, {}, &report);
  ASSERT_TRUE(relaxing.ok()) << relaxing.message();
  EXPECT_EQ(report.iterations, 4);
  EXPECT_GT(report.movedVertices, relaxed.vertexCount() / 2);

  // Landmarks stay; a vertex inside a base triangle stays inside it, one on
  // a base edge slides along it (the same coordinate stays exactly 0).
  EXPECT_EQ(relaxed.triangles, uniform.triangles);
  EXPECT_EQ(relaxed.patchOfTriangle, uniform.patchOfTriangle);
  EXPECT_EQ(relaxed.levelOfVertex, uniform.levelOfVertex);
  int moved = 0, slid = 0;
  for (int v = 0; v < uniform.vertexCount(); ++v)
  {
    const SurfacePoint &before = uniform.locations[v], &after = relaxed.locations[v];
    ASSERT_EQ(after.triangle, before.triangle);
    if (v < domain.mesh.vertexCount())
      EXPECT_EQ(after.weight, before.weight) << "landmark " << v << " moved";
    else if (strictlyInside(before))
      EXPECT_TRUE(strictlyInside(after)) << "vertex " << v << " left its base triangle";
    else
    {
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(after.weight[k] == 0.0, before.weight[k] == 0.0) << "vertex " << v << " left its base edge";
        EXPECT_GE(after.weight[k], 0.0);
      }
      EXPECT_DOUBLE_EQ(after.weight[0] + after.weight[1] + after.weight[2], 1.0);
      slid += after.weight != before.weight;
    }
    moved += after.weight != before.weight;
  }
  EXPECT_GT(moved, uniform.vertexCount() / 2);
  EXPECT_GT(slid, 0);
  EXPECT_GT(report.largestMove, 0.0);
  EXPECT_EQ(clockwiseTriangles(domain, relaxed), 0);

  const TracedNet& net = indexed.parameterized[0].net;
  const double before = relativeHausdorff(uniform, indexed.surfaces[0], net);
  const double after = relativeHausdorff(relaxed, indexed.surfaces[0], net);
  std::cout << "385: Hausdorff distance / diagonal " << before << " -> " << after << "\n";
  EXPECT_LT(after, 0.75 * before);
}

TEST(SampleRelaxation, BringsACollectionCloserWithOneSetOfLocations)
{
  CMP_REQUIRE_SHARED_DATA();
  // Without LowerStretch (the default parameterization), on three models
  // whose protrusions crowd in different base triangles.
  const BaseDomain domain = test::realBaseDomain("381");
  test::IndexedModels indexed;
  const std::vector<std::string> names{ "381", "389", "spot" };
  const Status status = test::indexRealModels(names, domain, false, indexed);
  ASSERT_TRUE(status.ok()) << status.message();
  SemiRegularMesh uniform, relaxed;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, uniform).ok());
  relaxed = uniform;
  ASSERT_TRUE(relaxSampleLocations(domain, indexed.collection, relaxed).ok());
  EXPECT_EQ(clockwiseTriangles(domain, relaxed), 0);
  double sumBefore = 0.0, sumAfter = 0.0;
  for (std::size_t m = 0; m < names.size(); ++m)
  {
    const double before = relativeHausdorff(uniform, indexed.surfaces[m], indexed.parameterized[m].net);
    const double after = relativeHausdorff(relaxed, indexed.surfaces[m], indexed.parameterized[m].net);
    std::cout << names[m] << ": Hausdorff distance / diagonal " << before << " -> " << after << "\n";
    EXPECT_LT(after, 1.05 * before) << names[m];
    sumBefore += before;
    sumAfter += after;
  }
  EXPECT_LT(sumAfter, 0.8 * sumBefore);
}

TEST(SampleRelaxation, ModelsSpreadOverRanksMoveTheLocationsAsOneProcessDoes)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  test::IndexedModels indexed;
  ASSERT_TRUE(test::indexRealModels({ "381", "385", "spot" }, domain, false, indexed).ok());
  SemiRegularMesh serial;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 4, serial).ok());
  const SemiRegularMesh start = serial;
  ASSERT_TRUE(relaxSampleLocations(domain, indexed.collection, serial).ok());

  // Rank 0 holds two models, rank 1 one; then rank 1 holds none.
  for (const std::vector<std::vector<int>>& split :
    { std::vector<std::vector<int>>{ { 0, 1 }, { 2 } }, std::vector<std::vector<int>>{ { 0, 1, 2 }, {} } })
  {
    std::vector<SemiRegularMesh> results(split.size(), start);
    std::mutex mutex;
    test::runOnRanks(static_cast<int>(split.size()), [&](Communicator& communicator) {
      std::vector<const ParameterizedSurface*> local;
      for (int m : split[communicator.rank()])
        local.push_back(indexed.collection[m]);
      const Status status = relaxSampleLocations(domain, local, communicator, results[communicator.rank()]);
      const std::lock_guard<std::mutex> lock(mutex);
      EXPECT_TRUE(status.ok()) << status.message();
    });
    double largest = 0.0;
    for (int v = 0; v < serial.vertexCount(); ++v)
    {
      // The ranks agree bit for bit; with one process, up to the order of the sums.
      EXPECT_EQ(results[0].locations[v].weight, results[1].locations[v].weight) << "vertex " << v;
      for (int k = 0; k < 3; ++k)
        largest = std::max(largest,
          std::abs(results[0].locations[v].weight[k] - serial.locations[v].weight[k]));
    }
    EXPECT_LT(largest, 1e-9);
  }
}

TEST_F(SampleRelaxationOn387, RanksWithDifferentRemeshesAllFail)
{
  // An adaptive remesh refined on each rank's own models differs between
  // ranks: the per-triangle sums would not match, so every rank refuses.
  for (bool sameLevelOtherStep : { false, true })
  {
    std::mutex mutex;
    test::runOnRanks(2, [&](Communicator& communicator) {
      SemiRegularMesh mine;
      const int level = sameLevelOtherStep ? 3 : 2 + communicator.rank();
      ASSERT_TRUE(buildSemiRegularMesh(domain(), level, mine).ok());
      const SemiRegularMesh untouched = mine;
      SampleRelaxationOptions options;
      if (sameLevelOtherStep && communicator.rank() == 1)
        options.step = 0.25;
      const Status status = relaxSampleLocations(domain(), collection(), communicator, mine, options);
      const std::lock_guard<std::mutex> lock(mutex);
      EXPECT_FALSE(status.ok());
      EXPECT_NE(status.message().find("different remeshes or with different options"), std::string::npos)
        << status.message();
      expectSameLocations(mine, untouched);
    });
  }
}

TEST_F(SampleRelaxationOn387, ASmallStepStillMoves)
{
  SampleRelaxationOptions options;
  options.iterations = 1;
  options.step = 1e-4;
  SampleRelaxationReport report;
  ASSERT_TRUE(relaxSampleLocations(domain(), collection(), mesh, options, &report).ok());
  EXPECT_GT(report.movedVertices, 0);
  EXPECT_GT(report.largestMove, 0.0);
  EXPECT_LT(report.largestMove, 1e-4);
}

TEST_F(SampleRelaxationOn387, ZeroRoundsLeaveTheLocationsAlone)
{
  const SemiRegularMesh untouched = mesh;
  SampleRelaxationOptions none;
  none.iterations = 0;
  SampleRelaxationReport report;
  ASSERT_TRUE(relaxSampleLocations(domain(), collection(), mesh, none, &report).ok());
  EXPECT_EQ(report.iterations, 0);
  expectSameLocations(mesh, untouched);
}

TEST_F(SampleRelaxationOn387, BadInputIsNamedAndLeavesTheRemeshAlone)
{
  const SemiRegularMesh untouched = mesh;
  const BaseDomain& domain = this->domain();
  const auto expectError = [&](const Status& status, const std::string& words) {
    ASSERT_FALSE(status.ok()) << "expected an error mentioning '" << words << "'";
    EXPECT_NE(status.message().find(words), std::string::npos) << status.message();
    expectSameLocations(mesh, untouched);
  };
  expectError(relaxSampleLocations(domain, {}, mesh), "no model");
  const ParameterizedSurface unbuilt;
  expectError(relaxSampleLocations(domain, { &unbuilt }, mesh), "not parameterized");
  expectError(relaxSampleLocations(domain, { nullptr }, mesh), "missing");
  SampleRelaxationOptions options;
  options.iterations = -1;
  expectError(relaxSampleLocations(domain, collection(), mesh, options), "negative");
  for (double step : { 0.0, 1.5, std::nan("") })
  {
    options = {};
    options.step = step;
    expectError(relaxSampleLocations(domain, collection(), mesh, options), "step");
  }
  // A vertex whose base location is not in the base triangle of its triangle.
  SemiRegularMesh misplaced = mesh;
  const int inside = mesh.vertexCount() - 1; // the last midpoint of level 3 lies inside a base triangle
  ASSERT_TRUE(std::all_of(mesh.locations[inside].weight.begin(), mesh.locations[inside].weight.end(),
    [](double c) { return c > 0.0; }));
  misplaced.locations[inside].triangle = (mesh.locations[inside].triangle + 1) % domain.mesh.triangleCount();
  const Status outside = relaxSampleLocations(domain, collection(), misplaced);
  EXPECT_FALSE(outside.ok());
  EXPECT_NE(outside.message().find("does not lie in the base triangle of its triangle"), std::string::npos)
    << outside.message();

  // A remesh of a larger base domain names base triangles this one lacks.
  SemiRegularMesh foreign = mesh;
  foreign.patchOfTriangle.back() = domain.mesh.triangleCount();
  ASSERT_FALSE(relaxSampleLocations(domain, collection(), foreign).ok());
  EXPECT_EQ(foreign.locations[mesh.vertexCount() - 1].weight, untouched.locations[mesh.vertexCount() - 1].weight);

  // Over ranks: no rank has a model, or one rank's input is bad; every rank says so.
  for (bool badOnRankOne : { false, true })
  {
    std::mutex mutex;
    test::runOnRanks(2, [&](Communicator& communicator) {
      SemiRegularMesh copy = untouched;
      SampleRelaxationOptions mine;
      if (badOnRankOne && communicator.rank() == 1)
        mine.iterations = -3;
      const std::vector<const ParameterizedSurface*> local =
        badOnRankOne ? collection() : std::vector<const ParameterizedSurface*>{};
      const Status status = relaxSampleLocations(domain, local, communicator, copy, mine);
      const std::lock_guard<std::mutex> lock(mutex);
      EXPECT_FALSE(status.ok());
      EXPECT_NE(status.message().find(badOnRankOne ? "negative" : "no model"), std::string::npos) << status.message();
    });
  }
}
