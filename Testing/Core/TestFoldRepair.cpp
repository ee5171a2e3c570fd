#include <cmp/remesh/FoldRepair.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/map/Straighten.h>
#include <cmp/mesh/SurfaceDistance.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>

using namespace cmp;

namespace
{

/// The remesh vertices joined to `v` by an edge.
std::vector<int> neighboursOf(const SemiRegularMesh& remesh, int v)
{
  std::vector<int> around;
  for (const Triangle& tri : remesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (tri[k] == v)
        around.insert(around.end(), { tri[(k + 1) % 3], tri[(k + 2) % 3] });
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  return around;
}

/// The median length of the remesh's triangle sides at `positions` (an
/// inner edge counted once from each of its two triangles).
double medianEdgeLength(const SemiRegularMesh& remesh, const std::vector<Vec3>& positions)
{
  std::vector<double> lengths;
  for (const Triangle& tri : remesh.triangles)
    for (int k = 0; k < 3; ++k)
      lengths.push_back((positions[tri[(k + 1) % 3]] - positions[tri[k]]).norm());
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

/// Samples, positions and folds of a remesh placed on a parameterized model.
struct Placed
{
  std::vector<SurfacePoint> samples;
  std::vector<Vec3> positions;
};

Placed place(const SemiRegularMesh& remesh, const BaseDomain& domain, const test::ParameterizedModel& model)
{
  Placed placed;
  EXPECT_TRUE(placeOnSurface(remesh, model.net, domain, model.parameterization, placed.samples).ok());
  placed.positions = samplePositions(model.net, placed.samples);
  return placed;
}

/// Puts the last remesh vertex where the vertex beyond its first
/// neighbour is, so its triangles on that side fold over; returns it.
int tangleLastVertex(const SemiRegularMesh& remesh, const Placed& placed, std::vector<SurfacePoint>& samples)
{
  const int v = remesh.vertexCount() - 1, w = neighboursOf(remesh, v).front();
  const Vec3 away = (placed.positions[w] - placed.positions[v]).normalized();
  int beyond = -1;
  double straightest = -1.0;
  for (int u : neighboursOf(remesh, w))
  {
    const double straightness = (placed.positions[u] - placed.positions[w]).normalized().dot(away);
    if (u != v && straightness > straightest)
      straightest = straightness, beyond = u;
  }
  EXPECT_GT(straightest, 0.9);
  samples[v] = samples[beyond];
  return v;
}

} // namespace

TEST(FoldRepair, UnfoldsAVertexPushedAcrossItsNeighbourWithinReach)
{
  const BaseDomain domain = test::orderedOctahedronDomain();
  test::ParameterizedModel model;
  ASSERT_TRUE(test::parameterizedSphere(domain, 4, model).ok());
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 3, remesh).ok());
  Placed placed = place(remesh, domain, model);
  ASSERT_EQ(countFoldedTriangles(remesh, model.net.mesh, placed.samples), 0);

  std::vector<SurfacePoint> samples = placed.samples;
  const int v = tangleLastVertex(remesh, placed, samples);
  const std::vector<SurfacePoint> tangled = samples;
  const int folded = countFoldedTriangles(remesh, model.net.mesh, samples);
  ASSERT_GT(folded, 0);

  FoldRepairReport report;
  ASSERT_TRUE(repairFolds(remesh, model.net.mesh, samples, {}, &report).ok());
  EXPECT_EQ(report.foldedBefore, folded);
  EXPECT_EQ(report.foldedAfter, 0);
  EXPECT_EQ(countFoldedTriangles(remesh, model.net.mesh, samples), 0);
  // Every vertex stays on the sphere and within two median edges (as
  // given: the regions' widest reach, and single moves' one edge) of where
  // it was given; landmarks stay put.
  EXPECT_GE(report.movedVertices, 1);
  const std::vector<Vec3> given = samplePositions(model.net, tangled);
  const std::vector<Vec3> repaired = samplePositions(model.net, samples);
  EXPECT_NE(repaired[v], given[v]) << "the misplaced vertex stayed";
  const double medianEdge = medianEdgeLength(remesh, given);
  for (int u = 0; u < remesh.vertexCount(); ++u)
  {
    EXPECT_NEAR(repaired[u].norm(), 1.0, 0.01) << u;
    EXPECT_LE((repaired[u] - given[u]).norm(), 2.0 * medianEdge * (1.0 + 1e-9)) << u;
    if (u < domain.mesh.vertexCount())
      EXPECT_EQ(repaired[u], given[u]) << u;
  }
}

TEST(FoldRepair, RefusesSamplesThatDoNotFitTheRemesh)
{
  const BaseDomain domain = test::orderedOctahedronDomain();
  test::ParameterizedModel model;
  ASSERT_TRUE(test::parameterizedSphere(domain, 2, model).ok());
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 1, remesh).ok());
  Placed placed = place(remesh, domain, model);

  std::vector<SurfacePoint> fewer(placed.samples.begin(), placed.samples.end() - 1);
  EXPECT_NE(repairFolds(remesh, model.net.mesh, fewer).message().find("samples for a remesh of"), std::string::npos);
  std::vector<SurfacePoint> stray = placed.samples;
  stray.back().triangle = model.net.mesh.triangleCount();
  EXPECT_NE(repairFolds(remesh, model.net.mesh, stray).message().find("names surface triangle"), std::string::npos);
  FoldRepairOptions negative;
  negative.reach = -1.0;
  EXPECT_NE(repairFolds(remesh, model.net.mesh, placed.samples, negative).message().find("reach"), std::string::npos);
  FoldRepairOptions narrowing;
  narrowing.regionWidening = 0;
  EXPECT_NE(repairFolds(remesh, model.net.mesh, placed.samples, narrowing).message().find("region widening"),
    std::string::npos);
  narrowing.regionWidening = 65;
  EXPECT_NE(repairFolds(remesh, model.net.mesh, placed.samples, narrowing).message().find("between 1 and 64, not 65"),
    std::string::npos);
  FoldRepairOptions single;
  single.singleWidening = 0.5;
  EXPECT_NE(repairFolds(remesh, model.net.mesh, placed.samples, single).message().find("single moves' widening"),
    std::string::npos);
  single.singleWidening = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(repairFolds(remesh, model.net.mesh, placed.samples, single).message().find("single moves' widening"),
    std::string::npos);

  const int v = remesh.vertexCount() - 1;
  const auto refused = [&](std::vector<SurfacePoint> samples, const std::string& fragment)
  {
    const Status status = repairFolds(remesh, model.net.mesh, samples);
    EXPECT_NE(status.message().find(fragment), std::string::npos) << status.message();
  };
  std::vector<SurfacePoint> broken = placed.samples;
  broken[v].triangle = -2;
  refused(broken, "names surface triangle -2");
  broken = placed.samples;
  broken[v].vertex[0] = model.net.mesh.vertexCount();
  refused(broken, "names surface vertex");
  broken = placed.samples;
  broken[v].triangle = (broken[v].triangle + 1) % model.net.mesh.triangleCount();
  refused(broken, "its vertices are not those of its triangle");
  broken = placed.samples;
  broken[v].weight[0] += 0.5;
  refused(broken, "its weights are not barycentric");
  broken = placed.samples;
  broken[v].weight[1] = std::numeric_limits<double>::quiet_NaN();
  refused(broken, "its weights are not barycentric");
  // A triangle removed by a collapse (a straightened net can have some).
  EditableMesh collapsed = model.net.mesh;
  const int removedHalfedge = 3 * placed.samples[v].triangle;
  collapsed.collapseEdge(removedHalfedge);
  ASSERT_TRUE(collapsed.isRemoved(placed.samples[v].triangle));
  const Status removedStatus = repairFolds(remesh, collapsed, placed.samples);
  EXPECT_NE(removedStatus.message().find("names removed surface triangle"), std::string::npos)
    << removedStatus.message();
  SemiRegularMesh strayVertex = remesh;
  strayVertex.triangles[0][1] = remesh.vertexCount();
  const Status strayStatus = repairFolds(strayVertex, model.net.mesh, placed.samples);
  EXPECT_NE(strayStatus.message().find("remesh triangle 0 has vertex"), std::string::npos) << strayStatus.message();
}

TEST(FoldRepair, LeavesAnUnfoldedRemeshAndAReachOfZeroAlone)
{
  const BaseDomain domain = test::orderedOctahedronDomain();
  test::ParameterizedModel model;
  ASSERT_TRUE(test::parameterizedSphere(domain, 3, model).ok());
  for (int level : { 0, 3 })
  {
    SemiRegularMesh remesh;
    ASSERT_TRUE(buildSemiRegularMesh(domain, level, remesh).ok());
    Placed placed = place(remesh, domain, model);
    std::vector<SurfacePoint> samples = placed.samples;
    FoldRepairReport report;
    ASSERT_TRUE(repairFolds(remesh, model.net.mesh, samples, {}, &report).ok());
    EXPECT_EQ(report.foldedBefore, 0) << level;
    EXPECT_EQ(report.movedVertices, 0) << level;
    EXPECT_EQ(samplePositions(model.net, samples), placed.positions) << level;
  }

  // A tangle, but no reach: nothing may move.
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 3, remesh).ok());
  Placed placed = place(remesh, domain, model);
  std::vector<SurfacePoint> samples = placed.samples;
  tangleLastVertex(remesh, placed, samples);
  const std::vector<SurfacePoint> tangled = samples;
  FoldRepairOptions still;
  still.reach = 0.0;
  FoldRepairReport report;
  ASSERT_TRUE(repairFolds(remesh, model.net.mesh, samples, still, &report).ok());
  EXPECT_GT(report.foldedBefore, 0);
  EXPECT_EQ(report.movedVertices, 0);
  EXPECT_EQ(report.foldedAfter, report.foldedBefore);
  EXPECT_EQ(samplePositions(model.net, samples), samplePositions(model.net, tangled));
}

TEST(FoldRepair, UnfoldsMostNeedleFoldsOnRealModelsAndStaysOnTheSurface)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, remesh).ok());
  // Measured at level 5 with L0 from 381: 417 -> 5 on Spot (its two thin
  // wedge patches keep the rest; 6 with single moves within twice a
  // vertex's shortest edge, until December 2026), 59 -> 0 on 391; without
  // widening the regions' reach, 6 and 2; with single moves before the
  // regions' moves (the order until November 2026), 15 and 1.
  for (const std::string name : { "spot", "391" })
  {
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    test::ParameterizedModel parameterized;
    ASSERT_TRUE(test::parameterizeOnDomain(model, domain, parameterized).ok()) << name;
    Placed placed = place(remesh, domain, parameterized);
    std::vector<SurfacePoint> samples = placed.samples;
    FoldRepairReport report;
    ASSERT_TRUE(repairFolds(remesh, parameterized.net.mesh, samples, {}, &report).ok()) << name;
    EXPECT_EQ(report.foldedBefore, countFoldedTriangles(remesh, parameterized.net.mesh, placed.samples)) << name;
    EXPECT_EQ(report.foldedAfter, countFoldedTriangles(remesh, parameterized.net.mesh, samples)) << name;
    EXPECT_GT(report.foldedBefore, 50) << name;
    EXPECT_LT(report.foldedAfter, 0.03 * report.foldedBefore) << name;

    const std::vector<Vec3> repaired = samplePositions(parameterized.net, samples);
    const double diagonal = boundingBoxDiagonal(model.data.mesh);
    const ClosestPointQuery input(model.data.mesh);
    const double medianEdge = medianEdgeLength(remesh, placed.positions);
    int moved = 0;
    for (int v = 0; v < remesh.vertexCount(); ++v)
    {
      if (repaired[v] == placed.positions[v])
        continue;
      ++moved;
      EXPECT_GE(v, domain.mesh.vertexCount()) << name << ": landmark " << v << " moved";
      EXPECT_LT(input.closest(repaired[v]).distance, 1e-6 * diagonal) << name << " vertex " << v;
      // Within two median edges (FoldRepairOptions::reach 2 times a
      // quarter of it, widened up to 4 times), alone or with its region.
      EXPECT_LE((repaired[v] - placed.positions[v]).norm(), 2.0 * medianEdge * 1.01) << name << " vertex " << v;
    }
    EXPECT_EQ(moved, report.movedVertices) << name;
    // Every sample still names the surface triangle it lies in.
    double largest = 0.0;
    for (int v = 0; v < remesh.vertexCount(); ++v)
    {
      largest = std::max(largest, (repaired[v] - placed.positions[v]).norm());
      const SurfacePoint& sample = samples[v];
      if (sample.triangle < 0)
        continue;
      const Triangle& tri = parameterized.net.mesh.triangle(sample.triangle);
      double sum = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_TRUE(sample.weight[k] == 0.0 || std::find(tri.begin(), tri.end(), sample.vertex[k]) != tri.end())
          << name << " vertex " << v;
        EXPECT_GE(sample.weight[k], 0.0) << name << " vertex " << v;
        sum += sample.weight[k];
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << name << " vertex " << v;
    }
    EXPECT_NEAR(report.largestMove, largest, 1e-12 * diagonal) << name;

    const TriangleMesh before{ placed.positions, remesh.triangles }, after{ repaired, remesh.triangles };
    const double hausdorffBefore = surfaceDistance(before, model.data.mesh).hausdorff() / diagonal;
    const double hausdorffAfter = surfaceDistance(after, model.data.mesh).hausdorff() / diagonal;
    EXPECT_LT(hausdorffAfter, hausdorffBefore + 0.003) << name;

    // Then the centroid criterion's pass: its counts are the criterion's
    // own on the surface the samples lie on, and it leaves fewer flips
    // than repairing the folds alone (measured: Spot 12 -> 5, 391 49 -> 8).
    const TriangleMesh flat = parameterized.net.mesh.toTriangleMesh();
    const std::vector<char> flippedAfter = centroidFlippedTriangles(flat, after);
    EXPECT_EQ(report.centroidFlipsAfter, std::count(flippedAfter.begin(), flippedAfter.end(), 1)) << name;
    FoldRepairOptions foldsOnly;
    foldsOnly.centroidFlips = false;
    std::vector<SurfacePoint> foldsOnlySamples = placed.samples;
    FoldRepairReport foldsOnlyReport;
    ASSERT_TRUE(repairFolds(remesh, parameterized.net.mesh, foldsOnlySamples, foldsOnly, &foldsOnlyReport).ok());
    EXPECT_EQ(foldsOnlyReport.centroidFlipsBefore, 0) << name; // the pass did not run
    const std::vector<char> flippedFoldsOnly =
      centroidFlippedTriangles(flat, TriangleMesh{ samplePositions(parameterized.net, foldsOnlySamples), remesh.triangles });
    const auto foldsOnlyFlips = std::count(flippedFoldsOnly.begin(), flippedFoldsOnly.end(), 1);
    EXPECT_EQ(report.centroidFlipsBefore, foldsOnlyFlips) << name;
    EXPECT_LT(report.centroidFlipsAfter, 0.5 * static_cast<double>(foldsOnlyFlips)) << name;
    EXPECT_LE(report.foldedAfter, foldsOnlyReport.foldedAfter) << name;
    std::cout << name << ": centroid flips " << foldsOnlyFlips << " -> " << report.centroidFlipsAfter << "\n";

    // Without widening, regions stay within half the median edge and leave
    // more folds.
    FoldRepairOptions narrow;
    narrow.regionWidening = 1;
    narrow.singleWidening = 1.0;
    std::vector<SurfacePoint> narrowSamples = placed.samples;
    FoldRepairReport narrowReport;
    ASSERT_TRUE(repairFolds(remesh, parameterized.net.mesh, narrowSamples, narrow, &narrowReport).ok()) << name;
    EXPECT_GT(narrowReport.foldedAfter, report.foldedAfter) << name;
    EXPECT_LE(narrowReport.largestMove, 0.5 * medianEdge * 1.01) << name;
    EXPECT_GT(report.largestMove, 0.5 * medianEdge) << name; // the widening was used
    // Single moves kept to half a median edge, as the regions' first reach,
    // leave no fewer folds and flips than moves of a whole edge (on these
    // fixed-curve maps about as many: Spot 5 and 5 either way, 391 0 and 6
    // against 0 and 5; the free map's bands of needles are the test below).
    FoldRepairOptions shortSingles;
    shortSingles.singleWidening = 1.0;
    std::vector<SurfacePoint> shortSamples = placed.samples;
    FoldRepairReport shortReport;
    ASSERT_TRUE(repairFolds(remesh, parameterized.net.mesh, shortSamples, shortSingles, &shortReport).ok()) << name;
    EXPECT_LE(report.foldedAfter, shortReport.foldedAfter) << name;
    EXPECT_LE(report.foldedAfter + report.centroidFlipsAfter, shortReport.foldedAfter + shortReport.centroidFlipsAfter)
      << name;
    std::cout << name << ": single moves within half a median edge: " << shortReport.foldedAfter << " folds, "
              << shortReport.centroidFlipsAfter << " centroid flips; within one: " << report.foldedAfter << ", "
              << report.centroidFlipsAfter << "\n";
    std::cout << name << ": " << report.foldedBefore << " -> " << report.foldedAfter << " folded triangles ("
              << narrowReport.foldedAfter << " without widening), "
              << report.movedVertices << " vertices moved, at most " << report.largestMove / diagonal
              << " of the diagonal; Hausdorff distance " << hausdorffBefore << " -> " << hausdorffAfter << "\n";
  }
}

TEST(FoldRepair, SingleMovesAlongBandsOfNeedlesUnfoldWhatMovesWithinANeedlesWidthLeave)
{
  CMP_REQUIRE_SHARED_DATA();
  // The whole-surface map (free curves, the default) of legs and necks
  // onto long thin base triangles makes bands of needles; where a band
  // bends (a hoof's rim), needles fold, and unfolding them takes moves
  // along the needles, far longer than their width.
  const BaseDomain domain = test::realBaseDomain("385");
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, remesh).ok());
  int foldsNarrow = 0, foldsWide = 0, flipsNarrow = 0, flipsWide = 0;
  for (const std::string name : { "389", "391" })
  {
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    TracedNet traced;
    ASSERT_TRUE(traceFeatureNet(model.data.mesh, model.landmarks, domain, traced).ok()) << name;
    StraightenedNet straight;
    test::ParameterizedModel mapped;
    ASSERT_TRUE(straighten(traced, domain, straight, mapped.parameterization).ok()) << name;
    mapped.net = std::move(straight.net);
    const Placed placed = place(remesh, domain, mapped);
    FoldRepairOptions narrow;
    narrow.singleWidening = 1.0;
    std::vector<SurfacePoint> wideSamples = placed.samples, narrowSamples = placed.samples;
    FoldRepairReport wide, narrowReport;
    ASSERT_TRUE(repairFolds(remesh, mapped.net.mesh, wideSamples, {}, &wide).ok()) << name;
    ASSERT_TRUE(repairFolds(remesh, mapped.net.mesh, narrowSamples, narrow, &narrowReport).ok()) << name;
    foldsWide += wide.foldedAfter, flipsWide += wide.centroidFlipsAfter;
    foldsNarrow += narrowReport.foldedAfter, flipsNarrow += narrowReport.centroidFlipsAfter;
    std::cout << name << " on L0 from 385: " << wide.foldedBefore << " folds before repair; single moves within "
              << "half a median edge leave " << narrowReport.foldedAfter << " folds and "
              << narrowReport.centroidFlipsAfter << " centroid flips, within one " << wide.foldedAfter << " and "
              << wide.centroidFlipsAfter << "\n";
  }
  EXPECT_LT(foldsWide, foldsNarrow);
  EXPECT_LT(flipsWide, flipsNarrow);
}

TEST(FoldRepair, CountsFoldsByTheirNearestLandmarkAlongRemeshEdges)
{
  const BaseDomain domain = test::orderedOctahedronDomain();
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 3, remesh).ok());
  const int landmarks = domain.mesh.vertexCount();
  std::vector<char> folded(remesh.triangles.size(), 0);
  // The fan around landmark 2 (valence 4), and one triangle two rings from
  // landmark 5 and farther from every other.
  int fan = 0;
  for (std::size_t t = 0; t < remesh.triangles.size(); ++t)
  {
    const Triangle& tri = remesh.triangles[t];
    if (std::find(tri.begin(), tri.end(), 2) != tri.end())
      folded[t] = 1, ++fan;
  }
  ASSERT_EQ(fan, 4);
  const std::vector<int> ringOne = neighboursOf(remesh, 5);
  int beyond = -1;
  for (std::size_t t = 0; t < remesh.triangles.size() && beyond < 0; ++t)
  {
    const Triangle& tri = remesh.triangles[t];
    const auto inRingOne = [&](int v) { return std::find(ringOne.begin(), ringOne.end(), v) != ringOne.end(); };
    if (std::find(tri.begin(), tri.end(), 5) == tri.end() && std::count_if(tri.begin(), tri.end(), inRingOne) == 1)
      beyond = static_cast<int>(t);
  }
  ASSERT_GE(beyond, 0);
  folded[beyond] = 1;

  const std::vector<int> counts = foldsNearLandmarks(remesh, landmarks, folded);
  ASSERT_EQ(counts.size(), static_cast<std::size_t>(landmarks));
  for (int f = 0; f < landmarks; ++f)
    EXPECT_EQ(counts[f], f == 2 ? 4 : f == 5 ? 1 : 0) << "landmark " << f;

  // The same in two steps, the first one shared by every model.
  const std::vector<int> nearest = nearestLandmarkOfTriangles(remesh, landmarks);
  ASSERT_EQ(nearest.size(), remesh.triangles.size());
  for (std::size_t t = 0; t < remesh.triangles.size(); ++t)
  {
    const Triangle& tri = remesh.triangles[t];
    if (std::find(tri.begin(), tri.end(), 2) != tri.end())
      EXPECT_EQ(nearest[t], 2) << "triangle " << t;
  }
  EXPECT_EQ(nearest[beyond], 5);
  EXPECT_EQ(foldsNearLandmarks(nearest, landmarks, folded), counts);
  EXPECT_TRUE(foldsNearLandmarks(nearest, landmarks, std::vector<char>(3, 1)).empty());
  EXPECT_TRUE(nearestLandmarkOfTriangles(remesh, remesh.vertexCount() + 1).empty());

  EXPECT_TRUE(foldsNearLandmarks(remesh, landmarks, std::vector<char>(3, 1)).empty());
  EXPECT_TRUE(foldsNearLandmarks(remesh, -1, folded).empty());
  EXPECT_EQ(foldsNearLandmarks(remesh, landmarks, std::vector<char>(remesh.triangles.size(), 0)),
    std::vector<int>(landmarks, 0));
}

TEST(FoldRepair, NamesTheLandmarksWhereTheFoldsStayOnModel384)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, remesh).ok());
  // Traced with requeued swirling curves only, whose net leaves landmark 8
  // bunched; the default tracer's shorter net does not, and its remesh
  // keeps no fold (TestCurveSpread.cpp).
  NetTracerOptions requeueOnly;
  requeueOnly.retraceWaiting = false;
  test::ParameterizedModel model;
  ASSERT_TRUE(test::parameterizeOnDomain(test::landmarkedRealModel("384"), domain, model, requeueOnly).ok());
  std::vector<SurfacePoint> samples = place(remesh, domain, model).samples;
  FoldRepairReport report;
  ASSERT_TRUE(repairFolds(remesh, model.net.mesh, samples, {}, &report).ok());
  const std::vector<int> counts =
    foldsNearLandmarks(remesh, domain.mesh.vertexCount(), foldedTriangles(remesh, model.net.mesh, samples));
  ASSERT_EQ(counts.size(), static_cast<std::size_t>(domain.mesh.vertexCount()));
  int total = 0;
  for (int count : counts) // indexed by feature, like the remesh's first vertices
    total += count;
  // Measured: 3 folds, all nearest landmark 8 (the outside of the left
  // hind leg's top, where the curves leave bunched). Its neighbour 20 lies
  // beside it, so with other rounding some may count there; the old repair
  // left 10 at 8 and 8 at 20.
  EXPECT_EQ(total, report.foldedAfter);
  if (report.foldedAfter == 0)
    GTEST_SKIP() << "no fold left on 384 to attribute to a landmark";
  EXPECT_EQ(counts[8] + counts[20], total);
}

TEST(FoldRepair, TheCentroidCriterionAsksTheSurfaceNearestToEachTriangleMiddle)
{
  // A remesh that is its surface faces with it everywhere; turning one
  // triangle round flips that one alone.
  const TriangleMesh surface = test::sphere(2);
  TriangleMesh placed = surface;
  std::vector<char> flipped = centroidFlippedTriangles(surface, placed);
  ASSERT_EQ(flipped.size(), placed.triangles.size());
  EXPECT_EQ(std::count(flipped.begin(), flipped.end(), 1), 0);
  std::swap(placed.triangles[7][1], placed.triangles[7][2]);
  flipped = centroidFlippedTriangles(surface, placed);
  EXPECT_EQ(std::count(flipped.begin(), flipped.end(), 1), 1);
  EXPECT_EQ(flipped[7], 1);

  // A thin slab, 1 wide and 0.05 thick, faces up on top and down below.
  // An upward triangle whose middle is nearer the top faces with it; the
  // same triangle nearer the bottom hangs over the wrong side and is
  // flipped, as a remesh triangle cutting across a thin tail would be.
  TriangleMesh slab;
  const double h = 0.05;
  for (double z : { 0.0, h })
    for (double y : { 0.0, 1.0 })
      for (double x : { 0.0, 1.0 })
        slab.points.push_back(Vec3(x, y, z));
  // Outward (counter-clockwise seen from outside) faces of the box.
  slab.triangles = { { 0, 2, 1 }, { 1, 2, 3 }, { 4, 5, 6 }, { 5, 7, 6 }, { 0, 1, 5 }, { 0, 5, 4 },
    { 2, 6, 7 }, { 2, 7, 3 }, { 0, 4, 6 }, { 0, 6, 2 }, { 1, 3, 7 }, { 1, 7, 5 } };
  const auto upward = [](double z) {
    return TriangleMesh{ { Vec3(0.3, 0.3, z), Vec3(0.7, 0.3, z), Vec3(0.5, 0.7, z) }, { { 0, 1, 2 } } };
  };
  EXPECT_EQ(centroidFlippedTriangles(slab, upward(0.9 * h))[0], 0);
  EXPECT_EQ(centroidFlippedTriangles(slab, upward(0.1 * h))[0], 1);
  // A triangle with no area has no normal to disagree with.
  const TriangleMesh flat{ { Vec3(0.3, 0.3, 0.01), Vec3(0.5, 0.3, 0.01), Vec3(0.7, 0.3, 0.01) }, { { 0, 1, 2 } } };
  EXPECT_EQ(centroidFlippedTriangles(slab, flat)[0], 0);
}
