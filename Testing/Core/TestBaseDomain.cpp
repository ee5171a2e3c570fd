#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/MeshFile.h>
#include <cmp/mesh/SurfaceCheck.h>
#include "TestMeshes.h"
#include "TestShapes.h"

#include <gtest/gtest.h>

#include <chrono>

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
