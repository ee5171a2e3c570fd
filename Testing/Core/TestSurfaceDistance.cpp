#include <cmp/mesh/SurfaceDistance.h>
#include "TestMeshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>

using namespace cmp;

namespace
{

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

/// A second, independent point-triangle distance (project onto the plane,
/// keep the foot if it is inside, else the nearest edge), so the brute
/// force does not share a bug with the code under test.
double referenceDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double edges = std::min({ segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a) });
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0.0))
    return edges;
  const Vec3 foot = p - n * (n.dot(p - a) / n2);
  const double u = n.dot((c - b).cross(foot - b)) / n2;
  const double v = n.dot((a - c).cross(foot - c)) / n2;
  if (u >= 0.0 && v >= 0.0 && 1.0 - u - v >= 0.0)
    return std::min(edges, (p - foot).norm());
  return edges;
}

double referenceDistance(const TriangleMesh& mesh, int t, const Vec3& p)
{
  const Triangle& tri = mesh.triangles[t];
  return referenceDistance(p, mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
}

double bruteForceDistance(const TriangleMesh& mesh, const Vec3& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (int t = 0; t < mesh.triangleCount(); ++t)
    best = std::min(best, referenceDistance(mesh, t, p));
  return best;
}

/// Number of `queries` whose answer differs from the brute force or is not
/// self-consistent; reports the first few.
int countMismatches(const TriangleMesh& mesh, const std::vector<Vec3>& queries)
{
  const ClosestPointQuery query(mesh);
  int mismatches = 0;
  for (const Vec3& p : queries)
  {
    const ClosestPointQuery::Result r = query.closest(p);
    const double expected = bruteForceDistance(mesh, p);
    bool ok = r.at.triangle >= 0 && r.at.triangle < mesh.triangleCount() && std::abs(r.distance - expected) < 1e-12;
    if (ok)
    {
      // The reported triangle, coordinates and point describe the same place.
      const Triangle& tri = mesh.triangles[r.at.triangle];
      ok = ok && r.at.vertex == tri;
      Vec3 fromWeights = Vec3::Zero();
      double sum = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        fromWeights += r.at.weight[k] * mesh.points[tri[k]];
        sum += r.at.weight[k];
        ok = ok && r.at.weight[k] >= -1e-12;
      }
      ok = ok && std::abs(sum - 1.0) < 1e-12 && (fromWeights - r.point).norm() < 1e-12 &&
        std::abs((p - r.point).norm() - r.distance) < 1e-12 &&
        std::abs(referenceDistance(mesh, r.at.triangle, p) - expected) < 1e-12;
    }
    if (!ok && ++mismatches <= 5)
      ADD_FAILURE() << "query (" << p.transpose() << "): distance " << r.distance << " in triangle " << r.at.triangle
                    << ", brute force " << expected;
  }
  return mismatches;
}

/// Points in a box around the unit sphere, plus points close to the sphere
/// where neighbouring triangles compete.
std::vector<Vec3> randomQueries(int count, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-1.6, 1.6), radius(0.9, 1.1);
  std::vector<Vec3> queries;
  for (int i = 0; i < count; ++i)
  {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    queries.push_back(i % 2 == 0 || p.norm() == 0.0 ? p : Vec3(p.normalized() * radius(random)));
  }
  return queries;
}

TriangleMesh scaled(TriangleMesh mesh, double factor)
{
  for (Vec3& p : mesh.points)
    p *= factor;
  return mesh;
}

double longestEdge(const TriangleMesh& mesh)
{
  double longest = 0.0;
  for (const Triangle& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (mesh.points[tri[k]] - mesh.points[tri[(k + 1) % 3]]).norm());
  return longest;
}

bool finite(const SurfaceDistance& d)
{
  return std::isfinite(d.aToB) && std::isfinite(d.bToA) && std::isfinite(d.meanAToB) && std::isfinite(d.meanBToA);
}

} // namespace

TEST(SurfaceDistance, ClosestPointOfOneTriangleInEachRegion)
{
  // Obtuse at a, where projecting and clamping barycentric coordinates
  // picks the wrong edge.
  TriangleMesh mesh;
  mesh.points = { Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(-1, 1, 0) };
  mesh.triangles = { { 0, 1, 2 } };
  const ClosestPointQuery query(mesh);
  struct Case
  {
    Vec3 p, expected;
  };
  const Vec3 bc = Vec3(4, 0, 0) + 7.0 / 26.0 * Vec3(-5, 1, 0);
  const std::vector<Case> cases = {
    { Vec3(2, 0.25, 3), Vec3(2, 0.25, 0) },     // interior
    { Vec3(2, -1, 0.5), Vec3(2, 0, 0) },        // edge ab
    { Vec3(-2, -1, 0), Vec3(-0.5, 0.5, 0) },    // edge ca, beside the obtuse corner
    { Vec3(3, 2, -1), bc },                     // edge bc
    { Vec3(-0.2, -1, 0), Vec3(0, 0, 0) },       // vertex a
    { Vec3(5, -1, 0), Vec3(4, 0, 0) },          // vertex b
    { Vec3(-2, 3, 1), Vec3(-1, 1, 0) },         // vertex c
  };
  for (const Case& c : cases)
  {
    const ClosestPointQuery::Result r = query.closest(c.p);
    EXPECT_EQ(r.at.triangle, 0);
    EXPECT_LT((r.point - c.expected).norm(), 1e-12) << "query " << c.p.transpose() << " gave " << r.point.transpose();
    EXPECT_NEAR(r.distance, (c.p - c.expected).norm(), 1e-12);
  }
  const ClosestPointQuery::Result onEdge = query.closest(Vec3(2, -1, 0.5));
  EXPECT_NEAR(onEdge.at.weight[0], 0.5, 1e-12);
  EXPECT_NEAR(onEdge.at.weight[1], 0.5, 1e-12);
  EXPECT_NEAR(onEdge.at.weight[2], 0.0, 1e-12);
}

TEST(SurfaceDistance, ClosestPointMatchesBruteForceOnSpheres)
{
  const TriangleMesh sphere = test::sphere(4);
  const TriangleMesh bumpy = test::bumpySphere(3);
  ASSERT_EQ(sphere.triangleCount(), 2048);
  EXPECT_EQ(countMismatches(sphere, randomQueries(3000, 1)), 0);
  EXPECT_EQ(countMismatches(bumpy, randomQueries(3000, 2)), 0);
  // The vertices themselves: ties between every triangle around them.
  EXPECT_EQ(countMismatches(bumpy, bumpy.points), 0);
}

TEST(SurfaceDistance, PointsOnTheSurfaceAreAtDistanceZero)
{
  const TriangleMesh mesh = test::bumpySphere(3);
  const ClosestPointQuery query(mesh);
  std::mt19937 random(3);
  std::uniform_int_distribution<int> triangle(0, mesh.triangleCount() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    const Triangle& tri = mesh.triangles[triangle(random)];
    double u = unit(random), v = unit(random);
    if (u + v > 1.0)
      u = 1.0 - u, v = 1.0 - v;
    const Vec3 p = (1.0 - u - v) * mesh.points[tri[0]] + u * mesh.points[tri[1]] + v * mesh.points[tri[2]];
    const ClosestPointQuery::Result r = query.closest(p);
    worst = std::max({ worst, r.distance, (r.point - p).norm() });
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(SurfaceDistance, SphereScaledByOnePointOneIsOneTenthAway)
{
  const TriangleMesh unit = test::sphere(5);
  const TriangleMesh larger = scaled(unit, 1.1);
  // Vertices lie on the spheres and no point of a flat triangle is further
  // inside than its circumradius^2 / (2 r) <= longest edge^2 / 2.
  const double tessellation = 0.5 * std::pow(longestEdge(larger), 2);
  ASSERT_LT(tessellation, 0.005);
  const SurfaceDistance d = surfaceDistance(unit, larger);
  EXPECT_NEAR(d.hausdorff(), 0.1, tessellation);
  EXPECT_NEAR(d.aToB, 0.1, tessellation);
  EXPECT_NEAR(d.bToA, 0.1, tessellation);
  EXPECT_NEAR(d.meanAToB, 0.1, tessellation);
  EXPECT_NEAR(d.meanBToA, 0.1, tessellation);
  EXPECT_LE(d.meanAToB, d.aToB);
  EXPECT_LE(d.meanBToA, d.bToA);
  std::cout << std::setprecision(10) << "unit vs 1.1 sphere: hausdorff " << d.hausdorff() << ", means "
            << d.meanAToB << " and " << d.meanBToA << " (tessellation bound " << tessellation << ")\n";
}

TEST(SurfaceDistance, SaysWhereTheHausdorffDistanceIsReached)
{
  // A spike the sphere misses: the distance is reached at its tip, on a.
  const TriangleMesh sphere = test::sphere(4);
  TriangleMesh spiked = sphere;
  const int tip = 7;
  spiked.points[tip] *= 1.5;
  const SurfaceDistance d = surfaceDistance(spiked, sphere);
  EXPECT_TRUE(d.reachedOnA());
  EXPECT_EQ(d.farthestOfA, spiked.points[tip]);
  EXPECT_EQ(d.farthestPoint(), spiked.points[tip]);
  EXPECT_NEAR(d.aToB, 0.5, 0.01);
  // Each farthest sample is as far from the other surface as its side says.
  EXPECT_DOUBLE_EQ(ClosestPointQuery(sphere).closest(d.farthestOfA).distance, d.aToB);
  EXPECT_DOUBLE_EQ(ClosestPointQuery(spiked).closest(d.farthestOfB).distance, d.bToA);
  // The other way round the spike is a part of b that a misses.
  const SurfaceDistance back = surfaceDistance(sphere, spiked);
  EXPECT_FALSE(back.reachedOnA());
  EXPECT_EQ(back.farthestPoint(), spiked.points[tip]);
}

TEST(SurfaceDistance, MarksTheRemeshTrianglesWhereTheDistanceIsAboveALimit)
{
  const TriangleMesh sphere = test::sphere(4);
  const int tip = 7;
  std::vector<int> aroundTip;
  for (int t = 0; t < sphere.triangleCount(); ++t)
    if (std::find(sphere.triangles[t].begin(), sphere.triangles[t].end(), tip) != sphere.triangles[t].end())
      aroundTip.push_back(t);
  TriangleMesh spiked = sphere;
  spiked.points[tip] *= 1.5;
  const auto marked = [](const std::vector<char>& far) {
    std::vector<int> result;
    for (int t = 0; t < static_cast<int>(far.size()); ++t)
      if (far[t])
        result.push_back(t);
    return result;
  };
  // A remesh spike off the surface: its own triangles, sampled, are far.
  EXPECT_EQ(marked(trianglesFartherThan(sphere, spiked, 0.1)), aroundTip);
  // A surface spike the remesh misses: the remesh triangles nearest to its
  // far samples are marked, and no triangle far from the spike is.
  const std::vector<int> missing = marked(trianglesFartherThan(spiked, sphere, 0.1));
  ASSERT_FALSE(missing.empty());
  for (int t : missing)
    EXPECT_LT((sphere.points[sphere.triangles[t][0]] - sphere.points[tip]).norm(), 0.5) << "triangle " << t;
  // Within the limit nothing is marked; the same surface never is.
  EXPECT_TRUE(marked(trianglesFartherThan(spiked, sphere, 0.6)).empty());
  EXPECT_TRUE(marked(trianglesFartherThan(sphere, sphere, 1e-12)).empty());
}

TEST(SurfaceDistance, MeshAgainstItselfIsZero)
{
  const TriangleMesh mesh = test::bumpySphere(3);
  const SurfaceDistance d = surfaceDistance(mesh, mesh, 4);
  EXPECT_LT(d.hausdorff(), 1e-12);
  EXPECT_LT(d.meanAToB, 1e-12);
  EXPECT_LT(d.meanBToA, 1e-12);
}

TEST(SurfaceDistance, OneSubdivisionSamplesTheVertices)
{
  const TriangleMesh a = test::bumpySphere(2), b = test::sphere(3);
  const ClosestPointQuery toB(b);
  std::vector<double> distance;
  double largest = 0.0;
  for (const Vec3& p : a.points)
  {
    distance.push_back(toB.closest(p).distance);
    largest = std::max(largest, distance.back());
  }
  double weighted = 0.0;
  for (int t = 0; t < a.triangleCount(); ++t)
  {
    const Triangle& tri = a.triangles[t];
    weighted += triangleArea(a, t) * (distance[tri[0]] + distance[tri[1]] + distance[tri[2]]) / 3.0;
  }
  const SurfaceDistance d = surfaceDistance(a, b, 1);
  EXPECT_EQ(d.aToB, largest);
  EXPECT_NEAR(d.meanAToB, weighted / surfaceArea(a), 1e-14);
  EXPECT_EQ(surfaceDistance(a, b, 0).aToB, largest); // below 1 counts as 1
  // Finer grids keep the vertices and add points, so the maximum cannot drop.
  EXPECT_GE(surfaceDistance(a, b, 3).aToB, largest);
  EXPECT_GT(largest, 0.01); // the bumps are far from the sphere: not trivially 0
}

TEST(SurfaceDistance, GridHasVerticesEdgePointsAndInteriorPoints)
{
  // The octahedron's vertices lie on the sphere; its edge midpoints are at
  // radius 1/sqrt(2) and its face centres at 1/sqrt(3), so each grid size
  // reaches a different farthest sample.
  const TriangleMesh octahedron = test::octahedron(), sphere = test::sphere(5);
  const double tessellation = 0.5 * std::pow(longestEdge(sphere), 2);
  EXPECT_LT(surfaceDistance(octahedron, sphere, 1).aToB, 1e-12);
  EXPECT_NEAR(surfaceDistance(octahedron, sphere, 2).aToB, 1.0 - std::sqrt(0.5), tessellation);
  EXPECT_NEAR(surfaceDistance(octahedron, sphere, 3).aToB, 1.0 - std::sqrt(1.0 / 3.0), tessellation);
}

TEST(SurfaceDistance, DegenerateTrianglesGiveNoNaN)
{
  TriangleMesh mesh;
  mesh.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(3, 3, 3), Vec3(0.5, 1e-20, 0),
    Vec3(0, 0, 0) };
  mesh.triangles = {
    { 0, 1, 2 }, // collinear
    { 0, 6, 3 }, // two coincident corners
    { 4, 4, 4 }, // a single point
    { 0, 1, 5 }, // a sliver
  };
  std::vector<Vec3> queries = randomQueries(500, 4);
  for (const Vec3& p : mesh.points)
    queries.push_back(p);
  queries.push_back(Vec3(0.5, 0.0, 0.0));
  const ClosestPointQuery query(mesh);
  int bad = 0;
  for (const Vec3& p : queries)
  {
    const ClosestPointQuery::Result r = query.closest(p);
    const bool finite = std::isfinite(r.distance) && r.point.allFinite() &&
      std::all_of(r.at.weight.begin(), r.at.weight.end(), [](double w) { return std::isfinite(w); });
    if (!finite || std::abs(r.distance - bruteForceDistance(mesh, p)) > 1e-9)
      ++bad;
  }
  EXPECT_EQ(bad, 0);
  // Zero total area: the mean falls back to a plain one instead of 0 / 0.
  const SurfaceDistance d = surfaceDistance(mesh, test::sphere(2));
  EXPECT_TRUE(finite(d));
  EXPECT_GT(d.hausdorff(), 0.0);
}

TEST(SurfaceDistance, EmptyMeshes)
{
  const TriangleMesh empty, sphere = test::sphere(1);
  const ClosestPointQuery query(empty);
  const ClosestPointQuery::Result r = query.closest(Vec3(1, 2, 3));
  EXPECT_EQ(r.at.triangle, -1);
  EXPECT_TRUE(std::isinf(r.distance));
  const SurfaceDistance d = surfaceDistance(sphere, empty);
  EXPECT_TRUE(std::isinf(d.aToB));
  EXPECT_EQ(d.bToA, 0.0);
  EXPECT_EQ(surfaceDistance(empty, empty).hausdorff(), 0.0);
}

// The tree's speed is measured by the benchmark (remesh_distance stage,
// distance_seconds), not asserted here; a brute-force scan would take
// minutes and hit the test's timeout.
TEST(SurfaceDistance, HundredThousandQueriesOnALargeSphere)
{
  const TriangleMesh mesh = test::sphere(7);
  ASSERT_EQ(mesh.triangleCount(), 131072);
  const std::vector<Vec3> queries = randomQueries(100000, 5);
  const ClosestPointQuery query(mesh);
  double total = 0.0;
  for (const Vec3& p : queries)
    total += query.closest(p).distance;
  EXPECT_TRUE(std::isfinite(total));
  // Spot-check the large tree against the brute force.
  const std::vector<Vec3> few(queries.begin(), queries.begin() + 20);
  EXPECT_EQ(countMismatches(mesh, few), 0);
}
