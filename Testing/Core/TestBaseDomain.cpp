#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/MeshFile.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/mesh/TriangleShape.h>
#include "TestMeshes.h"
#include "TestShapes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <set>
#include <tuple>

using namespace cmp;

namespace
{

void expectError(const Status& status, const std::string& fragment)
{
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find(fragment), std::string::npos) << "message: " << status.message();
}

BaseDomain octahedronDomain()
{
  BaseDomain domain;
  domain.mesh = test::octahedron();
  domain.featureIds = { 0, 1, 2, 3, 4, 5 };
  return domain;
}

/// `loop` rotated to start at its smallest element: cycles compare equal
/// when they are the same cyclic sequence.
std::vector<int> fromSmallest(std::vector<int> loop)
{
  if (!loop.empty())
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

/// Per boundary loop of `surface` (the surface on its left), the features of
/// the landmarks on it in the loop's order, each from its smallest; sorted.
std::vector<std::vector<int>> boundaryFeatures(const TriangleMesh& surface, const LandmarkList& landmarks)
{
  std::vector<std::vector<int>> loops, features;
  EXPECT_TRUE(boundaryLoops(surface, loops).ok());
  const std::vector<int> featureOf = featureIdsOf(landmarks, surface.vertexCount());
  for (const std::vector<int>& loop : loops)
  {
    std::vector<int> corners;
    for (int v : loop)
      if (featureOf[v] >= 0)
        corners.push_back(featureOf[v]);
    features.push_back(fromSmallest(corners));
  }
  std::sort(features.begin(), features.end());
  return features;
}

/// Checks the contract of surfaces with boundaries on an open L0 built from
/// `surface`: base vertex f is landmark f at its position; L0 has as many
/// boundary loops as the surface, each exactly the landmarks of one of the
/// surface's loops in its cyclic order (both with the surface on the left);
/// V - E + T = 2 - loops (a sphere with holes); closeBaseDomain() accepts
/// it; the report's angles are those of L0's own triangles.
void expectOpenL0FitsTheSurface(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& l0,
  const BaseDomainBuilderReport& report)
{
  const int featureCount = static_cast<int>(landmarks.size());
  ASSERT_EQ(l0.mesh.vertexCount(), featureCount);
  ASSERT_EQ(static_cast<int>(l0.featureIds.size()), featureCount);
  for (int f = 0; f < featureCount; ++f)
  {
    EXPECT_EQ(l0.featureIds[f], f);
    EXPECT_EQ(l0.mesh.points[f], surface.points[landmarks[f]]);
  }
  const std::vector<std::vector<int>> expected = boundaryFeatures(surface, landmarks);
  ASSERT_FALSE(expected.empty());
  std::vector<std::vector<int>> loops;
  ASSERT_TRUE(boundaryLoops(l0.mesh, loops).ok());
  for (std::vector<int>& loop : loops)
    loop = fromSmallest(loop);
  std::sort(loops.begin(), loops.end());
  EXPECT_EQ(loops, expected) << "L0's boundary loops are the surface's boundary landmarks in the same cyclic order";

  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : l0.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  EXPECT_EQ(l0.mesh.vertexCount() - static_cast<int>(edges.size()) + l0.mesh.triangleCount(),
    2 - static_cast<int>(expected.size()));

  BaseDomain closed;
  BaseDomainHoles holes;
  const Status close = closeBaseDomain(l0, closed, holes);
  ASSERT_TRUE(close.ok()) << close.message();
  std::vector<std::vector<int>> holeLoops = holes.loops;
  std::sort(holeLoops.begin(), holeLoops.end());
  EXPECT_EQ(holeLoops, expected);

  const TriangleShapeSummary shape = measureTriangleShapes(l0.mesh.points, l0.mesh.triangles);
  EXPECT_EQ(report.minAngleDegrees, shape.minimumAngleDegrees);
  EXPECT_EQ(report.meanShapeQuality, shape.meanShapeQuality);
  EXPECT_GT(report.minAngleDegrees, 0.0);
}

/// `mesh` without the triangles `drop` picks and the vertices only they
/// used; `newIndex` is each vertex's index in the result (-1: dropped).
TriangleMesh withoutTriangles(const TriangleMesh& mesh, const std::function<bool(const Triangle&)>& drop,
  std::vector<int>& newIndex)
{
  TriangleMesh open;
  newIndex.assign(mesh.vertexCount(), -1);
  for (const Triangle& t : mesh.triangles)
  {
    if (drop(t))
      continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k)
    {
      if (newIndex[t[k]] < 0)
      {
        newIndex[t[k]] = open.vertexCount();
        open.points.push_back(mesh.points[t[k]]);
      }
      kept[k] = newIndex[t[k]];
    }
    open.triangles.push_back(kept);
  }
  return open;
}

/// `count` vertices of `loop` spread evenly along it, in its order.
std::vector<int> spreadAlong(const std::vector<int>& loop, int count)
{
  std::vector<int> picked;
  for (int i = 0; i < count; ++i)
    picked.push_back(loop[i * loop.size() / count]);
  return picked;
}

} // namespace

TEST(BaseDomain, AcceptsAValidDomainInAnyFeatureOrder)
{
  BaseDomain domain = octahedronDomain();
  EXPECT_TRUE(checkBaseDomain(domain, 6).ok());
  domain.featureIds = { 3, 5, 0, 1, 4, 2 };
  EXPECT_TRUE(checkBaseDomain(domain, 6).ok());
  EXPECT_EQ(edgeCount(domain.mesh), 12);
}

TEST(BaseDomain, ReportsEveryWayItCanBeWrong)
{
  BaseDomain domain = octahedronDomain();
  expectError(checkBaseDomain(domain, 21), "base domain has 6 vertices but the surface has 21 landmarks");
  domain.featureIds = { 0, 1, 2, 3, 4, 4 };
  expectError(checkBaseDomain(domain), "FeatureId 4 is on vertices 4 and 5");
  domain.featureIds = { 0, 1, 2, 3, 4, 6 };
  expectError(checkBaseDomain(domain), "vertex 5 has FeatureId 6, outside 0..5");
  domain.featureIds = { 0, 1, 2 };
  expectError(checkBaseDomain(domain), "6 points but 3 FeatureId values");
  domain = octahedronDomain();
  domain.mesh.triangles.pop_back();
  expectError(checkBaseDomain(domain), "base domain: open surface");
  domain.mesh = test::torus(4, 3);
  domain.featureIds.resize(12);
  for (int i = 0; i < 12; ++i)
    domain.featureIds[i] = i;
  expectError(checkBaseDomain(domain), "base domain: the surface has genus 1");
  domain = octahedronDomain();
  domain.mesh.points[0] = domain.mesh.points[1]; // a base domain's geometry is only a picture
  EXPECT_TRUE(checkBaseDomain(domain).ok());
}

TEST(BaseDomainBuilder, SphereWithOctahedronLandmarksGivesTheOctahedron)
{
  const TriangleMesh sphere = test::sphere(4);
  const LandmarkList landmarks = { 0, 1, 2, 3, 4, 5 }; // the octahedron's vertices
  BaseDomain domain;
  BaseDomainBuilderReport report;
  ASSERT_TRUE(buildBaseDomain(sphere, landmarks, domain, {}, &report).ok());
  EXPECT_EQ(domain.mesh.vertexCount(), 6);
  EXPECT_EQ(domain.mesh.triangleCount(), 8);
  EXPECT_EQ(report.collapses, sphere.vertexCount() - 6);
  EXPECT_EQ(report.foldingCollapses, 0);
  EXPECT_NEAR(report.minAngleDegrees, 60.0, 1e-9);
  // Same triangles as the octahedron, with the same orientation.
  std::vector<Triangle> expected = test::octahedron().triangles, actual = domain.mesh.triangles;
  for (auto* list : { &expected, &actual })
  {
    for (Triangle& tri : *list)
      std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    std::sort(list->begin(), list->end());
  }
  EXPECT_EQ(actual, expected);
}

TEST(BaseDomainBuilder, RefusesTooFewLandmarksAndBadInput)
{
  BaseDomain domain;
  expectError(buildBaseDomain(test::sphere(2), { 0, 1, 2 }, domain), "too few landmarks: 3 given");
  expectError(buildBaseDomain(test::sphere(2), { 0, 1, 2, 2 }, domain), "duplicate landmark");
  expectError(buildBaseDomain(test::torus(8, 6), { 0, 1, 2, 3 }, domain), "genus 1");
  TriangleMesh open = test::sphere(2);
  open.triangles.pop_back();
  expectError(buildBaseDomain(open, { 0, 1, 2, 3 }, domain), "open surface");
}

TEST(BaseDomainBuilder, FourLandmarksGiveATetrahedron)
{
  BaseDomain domain;
  ASSERT_TRUE(buildBaseDomain(test::sphere(3), { 0, 2, 4, 5 }, domain).ok());
  EXPECT_EQ(domain.mesh.triangleCount(), 4);
  EXPECT_TRUE(checkBaseDomain(domain, 4).ok());
}

TEST(BaseDomainBuilder, EveryLandmarkedRealModelGives38TrianglesAnd57Edges)
{
  CMP_REQUIRE_SHARED_DATA();
  std::vector<std::pair<std::string, std::string>> inputs;
  for (const std::string& model : test::landmarkedFourLeggedModels())
    inputs.emplace_back(model + ".off", model + ".vts");
  inputs.emplace_back(test::sharedDataDir() + "/spot/spot.obj", test::sharedDataDir() + "/spot/spot_shrec07.pinned");
  ASSERT_GE(inputs.size(), 11u);
  for (const auto& [meshPath, landmarkPath] : inputs)
  {
    MeshFileData data;
    ASSERT_TRUE((fileExtension(meshPath) == "obj" ? readOBJ(meshPath, data) : readOFF(meshPath, data)).ok());
    LandmarkList landmarks;
    ASSERT_TRUE(readLandmarkFile(landmarkPath, data.mesh, data.fileToMeshPoint, landmarks).ok());
    BaseDomain domain;
    BaseDomainBuilderReport report;
    const auto start = std::chrono::steady_clock::now();
    const Status status = buildBaseDomain(data.mesh, landmarks, domain, {}, &report);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(status.ok()) << meshPath << ": " << status.message();
    EXPECT_EQ(domain.mesh.vertexCount(), 21);
    EXPECT_EQ(domain.mesh.triangleCount(), 38);
    EXPECT_EQ(edgeCount(domain.mesh), 57);
    EXPECT_TRUE(checkBaseDomain(domain, 21).ok());
    for (int f = 0; f < 21; ++f)
      EXPECT_EQ(domain.mesh.points[f], data.mesh.points[landmarks[f]]);
    std::cout << meshPath.substr(meshPath.find_last_of('/') + 1) << ": " << seconds << " s, min angle "
              << report.minAngleDegrees << " deg, mean quality " << report.meanShapeQuality << ", folding collapses "
              << report.foldingCollapses << ", flips " << report.flips << "\n";
  }
}

// Surfaces with boundaries (issue 27 B, beyond the paper): the open L0's
// boundary loops are the surface's boundary landmarks, in order.

TEST(BaseDomainBuilder, OpenSphereGivesL0WithOneHoleBoundedByItsBoundaryLandmarks)
{
  const TriangleMesh sphere = test::sphere(4);
  const LandmarkList landmarks = { 0, 1, 2, 3, 4, 5 };
  BaseDomain closedL0;
  ASSERT_TRUE(buildBaseDomain(sphere, landmarks, closedL0).ok());
  test::OpenModel open;
  const Status cut = test::cutAroundFeature(sphere, landmarks, closedL0, 4, 0.5, open);
  ASSERT_TRUE(cut.ok()) << cut.message();
  ASSERT_EQ(open.landmarks.size(), 9u); // the pole's four neighbours stay, four boundary landmarks come
  BaseDomain l0;
  BaseDomainBuilderReport report;
  const Status status = buildBaseDomain(open.surface, open.landmarks, l0, {}, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  expectOpenL0FitsTheSurface(open.surface, open.landmarks, l0, report);
  // One loop, through the four new landmarks (features 5..8) alone.
  const std::vector<std::vector<int>> boundary = boundaryFeatures(open.surface, open.landmarks);
  ASSERT_EQ(boundary.size(), 1u);
  EXPECT_EQ(std::set<int>(boundary[0].begin(), boundary[0].end()), (std::set<int>{ 5, 6, 7, 8 }));
  EXPECT_EQ(report.collapses, open.surface.vertexCount() - 9);
}

TEST(BaseDomainBuilder, OpenRealModelsGiveL0WhoseBoundaryIsTheirBoundaryLandmarksInOrder)
{
  CMP_REQUIRE_SHARED_DATA();
  // 381 as the other open-surface tests cut it; 384 and 389 cut so that the
  // decimation joins the two loop neighbours of a boundary vertex by an
  // inner edge, which only flipping that edge undoes.
  for (const auto& [name, feature, radius] :
    { std::make_tuple("381", 14, 0.4), std::make_tuple("384", 5, 0.7), std::make_tuple("389", 9, 0.4) })
  {
    SCOPED_TRACE(std::string(name) + " cut round feature " + std::to_string(feature));
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    BaseDomain closedL0;
    ASSERT_TRUE(buildBaseDomain(model.data.mesh, model.landmarks, closedL0).ok());
    test::OpenModel open;
    const Status cut = test::cutAroundFeature(model.data.mesh, model.landmarks, closedL0, feature, radius, open);
    ASSERT_TRUE(cut.ok()) << cut.message();
    BaseDomain l0;
    BaseDomainBuilderReport report;
    const Status status = buildBaseDomain(open.surface, open.landmarks, l0, {}, &report);
    ASSERT_TRUE(status.ok()) << status.message();
    expectOpenL0FitsTheSurface(open.surface, open.landmarks, l0, report);
    EXPECT_GE(boundaryFeatures(open.surface, open.landmarks)[0].size(), 3u);
  }
}

TEST(BaseDomainBuilder, FlatSquareGivesL0OfItsLandmarksEvenWhenAllAreOnTheBoundary)
{
  const int n = 6;
  const TriangleMesh square = test::flatSquare(n);
  const int a = 0, b = n, c = n * (n + 2), d = n * (n + 1), middle = (n / 2) * (n + 1) + n / 2;
  struct Case
  {
    LandmarkList landmarks;
    int triangles;
  };
  for (const Case& test : { Case{ { a, b, c, d, middle }, 4 }, Case{ { c, a, b, d }, 2 }, Case{ { a, b, c }, 1 } })
  {
    BaseDomain l0;
    BaseDomainBuilderReport report;
    const Status status = buildBaseDomain(square, test.landmarks, l0, {}, &report);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_EQ(l0.mesh.triangleCount(), test.triangles);
    expectOpenL0FitsTheSurface(square, test.landmarks, l0, report);
    for (const Triangle& t : l0.mesh.triangles) // facing +z, like the square
    {
      const Vec3 normal = (l0.mesh.points[t[1]] - l0.mesh.points[t[0]]).cross(l0.mesh.points[t[2]] - l0.mesh.points[t[0]]);
      EXPECT_GT(normal.z(), 0.0);
    }
  }
}

TEST(BaseDomainBuilder, SphereWithTwoHolesGivesL0WithTwoHoles)
{
  const TriangleMesh sphere = test::sphere(3);
  std::vector<int> newIndex;
  const TriangleMesh open = withoutTriangles(
    sphere,
    [&](const Triangle& t) {
      for (int v : t)
        if (std::abs(sphere.points[v].z()) > 0.8)
          return true;
      return false;
    },
    newIndex);
  std::vector<std::vector<int>> loops;
  ASSERT_TRUE(boundaryLoops(open, loops).ok());
  ASSERT_EQ(loops.size(), 2u);
  LandmarkList landmarks = { newIndex[0], newIndex[1], newIndex[2], newIndex[3] }; // the equator's
  for (const std::vector<int>& loop : loops)
    for (int v : spreadAlong(loop, 3 + static_cast<int>(&loop - loops.data())))
      landmarks.push_back(v);
  BaseDomain l0;
  BaseDomainBuilderReport report;
  const Status status = buildBaseDomain(open, landmarks, l0, {}, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  expectOpenL0FitsTheSurface(open, landmarks, l0, report);
}

TEST(BaseDomainBuilder, RefusesABoundaryLoopWithFewerThanThreeLandmarks)
{
  const TriangleMesh sphere = test::sphere(3);
  std::vector<int> newIndex;
  const TriangleMesh open = withoutTriangles( // the north pole's star
    sphere, [](const Triangle& t) { return std::find(t.begin(), t.end(), 4) != t.end(); }, newIndex);
  std::vector<std::vector<int>> loops;
  ASSERT_TRUE(boundaryLoops(open, loops).ok());
  ASSERT_EQ(loops.size(), 1u);
  const std::vector<int>& loop = loops[0];
  ASSERT_EQ(loop.size(), 4u);
  const LandmarkList others = { newIndex[0], newIndex[1], newIndex[2], newIndex[3], newIndex[5] };
  const std::string through = "open surface: the boundary loop through vertex " + std::to_string(loop.front());
  BaseDomain domain;
  for (int onLoop = 0; onLoop < 3; ++onLoop)
  {
    LandmarkList landmarks = others;
    for (int i = 0; i < onLoop; ++i)
      landmarks.push_back(loop[2 * i]);
    const Status status = buildBaseDomain(open, landmarks, domain);
    expectError(status, through);
    expectError(status, "passes through " + std::to_string(onLoop) + " landmark");
    expectError(status, "needs at least 3");
  }
  // With a third one on the loop it builds.
  LandmarkList landmarks = others;
  for (int i : { 0, 1, 2 })
    landmarks.push_back(loop[i]);
  BaseDomainBuilderReport report;
  ASSERT_TRUE(buildBaseDomain(open, landmarks, domain, {}, &report).ok());
  expectOpenL0FitsTheSurface(open, landmarks, domain, report);
}

TEST(BaseDomainBuilder, RefusesABadOpenSurfaceInTheUsersTerms)
{
  const TriangleMesh sphere = test::sphere(2);
  std::vector<int> newIndex;
  const TriangleMesh open = withoutTriangles(
    sphere, [](const Triangle& t) { return std::find(t.begin(), t.end(), 4) != t.end(); }, newIndex);
  std::vector<std::vector<int>> loops;
  ASSERT_TRUE(boundaryLoops(open, loops).ok());
  ASSERT_EQ(loops.size(), 1u);
  LandmarkList landmarks = { newIndex[0], newIndex[1], newIndex[2], newIndex[3], newIndex[5] };
  for (int v : spreadAlong(loops[0], 3))
    landmarks.push_back(v);
  BaseDomain domain;
  const Status fine = buildBaseDomain(open, landmarks, domain);
  ASSERT_TRUE(fine.ok()) << fine.message();

  // Two components: the capped surface fails the surface check.
  const TriangleMesh twoParts = test::disjointUnion(open, test::tetrahedron(Vec3(3, 0, 0)));
  Status status = buildBaseDomain(twoParts, landmarks, domain);
  expectError(status, "2 connected components");
  expectError(status, "(the surface with its boundary loops capped)");

  // A torus with a hole.
  TriangleMesh torus = test::torus(8, 6);
  torus.triangles.pop_back();
  status = buildBaseDomain(torus, { 0, 1, 2, 3 }, domain);
  expectError(status, "genus 1");
  expectError(status, "(the surface with its boundary loops capped)");

  // One triangle turned over.
  TriangleMesh turned = open;
  std::swap(turned.triangles[0][1], turned.triangles[0][2]);
  expectError(buildBaseDomain(turned, landmarks, domain), "inconsistent orientation");

  // Two holes that touch at a vertex: two triangles at vertex 0 that share
  // no edge.
  std::vector<int> atZero;
  for (int t = 0; t < sphere.triangleCount(); ++t)
    if (std::find(sphere.triangles[t].begin(), sphere.triangles[t].end(), 0) != sphere.triangles[t].end())
      atZero.push_back(t);
  int first = -1, second = -1;
  for (int i : atZero)
    for (int j : atZero)
    {
      int shared = 0;
      for (int v : sphere.triangles[i])
        shared += std::count(sphere.triangles[j].begin(), sphere.triangles[j].end(), v);
      if (i < j && shared == 1)
        first = i, second = j;
    }
  ASSERT_GE(first, 0);
  TriangleMesh pinched = sphere;
  pinched.triangles.erase(pinched.triangles.begin() + second);
  pinched.triangles.erase(pinched.triangles.begin() + first);
  expectError(buildBaseDomain(pinched, { 0, 1, 2, 3, 4, 5 }, domain), "boundary is pinched at vertex 0");

  // A missing landmark is refused as on a closed surface.
  landmarks.push_back(kMissingLandmark);
  expectError(buildBaseDomain(open, landmarks, domain), "is missing");
}
