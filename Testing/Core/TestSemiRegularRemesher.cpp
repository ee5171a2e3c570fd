#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/MeshFile.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/remesh/Remesh.h>
#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/mesh/SurfaceDistance.h>
#include "TestMeshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <cmath>

using namespace cmp;

using test::drawnOnDomain;
using test::IndexedModels;
using test::indexRealModels;
using test::octahedronDomain;

TEST(SemiRegularRemesher, ConnectivityIsAClosedQuadrisectionNumberedLevelByLevel)
{
  const BaseDomain domain = octahedronDomain();
  SemiRegularMesh previous;
  for (int level = 0; level <= 4; ++level)
  {
    SemiRegularMesh mesh;
    ASSERT_TRUE(buildSemiRegularMesh(domain, level, mesh).ok());
    const int triangles = 8 << (2 * level);
    EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(triangles));
    EXPECT_EQ(mesh.vertexCount(), 2 + triangles / 2); // genus 0
    // Drawn on the octahedron, the remesh is a closed, oriented manifold.
    const TriangleMesh drawn = drawnOnDomain(domain, mesh);
    const SurfaceCheckResult check = checkSurface(drawn);
    EXPECT_TRUE(check.ok()) << "level " << level << ": " << check.message;
    // Vertex f is base vertex of feature f.
    for (int bv = 0; bv < 6; ++bv)
      EXPECT_DOUBLE_EQ((drawn.points[domain.featureIds[bv]] - domain.mesh.points[bv]).norm(), 0.0);
    // Coarser levels are a prefix.
    for (int v = 0; v < previous.vertexCount(); ++v)
    {
      EXPECT_EQ(mesh.locations[v].triangle, previous.locations[v].triangle);
      EXPECT_EQ(mesh.locations[v].weight, previous.locations[v].weight);
    }
    previous = mesh;
  }
  SemiRegularMesh bad;
  EXPECT_FALSE(buildSemiRegularMesh(domain, 9, bad).ok());
  EXPECT_FALSE(buildSemiRegularMesh(domain, -1, bad).ok());
}

namespace
{

/// Remesh triangles whose normal points against the input surface under
/// them (the sum of the normals of the input triangles their corners lie in).
int trianglesAgainstSurface(const SemiRegularMesh& remesh, const TracedNet& net,
  const std::vector<SurfacePoint>& samples, const std::vector<Vec3>& positions)
{
  int flipped = 0;
  for (const Triangle& tri : remesh.triangles)
  {
    const Vec3 normal = (positions[tri[1]] - positions[tri[0]]).cross(positions[tri[2]] - positions[tri[0]]);
    Vec3 surfaceNormal = Vec3::Zero();
    for (int v : tri)
    {
      const SurfacePoint& s = samples[v];
      if (s.vertex[1] < 0)
        continue; // a landmark: no triangle recorded
      const Vec3 a = net.mesh.point(s.vertex[0]), b = net.mesh.point(s.vertex[1]), c = net.mesh.point(s.vertex[2]);
      surfaceNormal += (b - a).cross(c - a);
    }
    flipped += normal.dot(surfaceNormal) < 0.0;
  }
  return flipped;
}

TriangleMesh remeshSurface(const SemiRegularMesh& remesh, const std::vector<Vec3>& positions)
{
  TriangleMesh mesh;
  mesh.points = positions;
  mesh.triangles = remesh.triangles;
  return mesh;
}

} // namespace

TEST(SemiRegularRemesher, EveryRealModelGetsTheSameConnectivity)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  ASSERT_GT(domain.mesh.vertexCount(), 0);
  const int level = 5;
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, level, remesh).ok());

  for (const test::LandmarkedModel& model : test::landmarkedRealModels())
  {
    const auto& [name, data, landmarks] = model;
    test::ParameterizedModel parameterized;
    const Status parameterizedStatus = test::parameterizeOnDomain(model, domain, parameterized);
    ASSERT_TRUE(parameterizedStatus.ok()) << parameterizedStatus.message();
    const TracedNet& net = parameterized.net;
    const auto start = std::chrono::steady_clock::now();
    std::vector<SurfacePoint> samples;
    const Status placed = placeOnSurface(remesh, net, domain, parameterized.parameterization, samples);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(placed.ok()) << name << ": " << placed.message();
    const std::vector<Vec3> positions = samplePositions(net, samples);
    for (int f = 0; f < domain.mesh.vertexCount(); ++f)
      EXPECT_EQ(positions[f], data.mesh.points[landmarks[f]]) << name << " landmark " << f;

    // On the input surface, checked against the input itself.
    const double diagonal = boundingBoxDiagonal(data.mesh);
    const ClosestPointQuery input(data.mesh);
    double farthest = 0.0;
    for (const Vec3& p : positions)
      farthest = std::max(farthest, input.closest(p).distance);
    EXPECT_LT(farthest, 1e-6 * diagonal) << name;

    // Known limit: landmark-free protrusions (tails, ears, horns) crowd in
    // the patch maps and get few samples, so the input's tips are far from
    // the remesh (issue 5 asks for 1% at level 5; see known-issues.md).
    // The remesh itself stays close to the input. 384's net is, since
    // 2026-12-07, the shorter one traced with waiting swirling curves
    // (18.8 per square root of area against 20.2); with its curves fixed,
    // the remesh is 2.9% of the diagonal off the input where it was under
    // 2.5%. The default map frees the curves: 384 0.62% there.
    const SurfaceDistance distance = surfaceDistance(remeshSurface(remesh, positions), data.mesh);
    EXPECT_LT(distance.aToB, (name == "384" ? 0.03 : 0.025) * diagonal) << name;
    EXPECT_LT(distance.hausdorff(), 0.1 * diagonal) << name;

    // Known limit: where a patch is a long thin band (the layout of 381 on
    // a model in another pose) the uniform samples make needle triangles,
    // some of which fold (Documentation/known-issues.md). Bounded here so
    // that it cannot grow unnoticed.
    const int flipped = trianglesAgainstSurface(remesh, net, samples, positions);
    EXPECT_LT(flipped, (name == "spot" ? 0.012 : 0.005) * remesh.triangles.size()) << name;
    std::cout << name << ": level " << level << ", " << remesh.vertexCount() << " vertices placed in " << seconds
              << " s, Hausdorff distance " << distance.hausdorff() / diagonal << " of the diagonal (" << distance.aToB / diagonal << " remesh to input, " << distance.bToA / diagonal << " input to remesh), " << flipped
              << " triangles against the surface normal\n";
  }
}

TEST(SemiRegularRemesher, LowerStretchReachesFurtherIntoLandmarkFreeProtrusions)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  ASSERT_GT(domain.mesh.vertexCount(), 0);
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, remesh).ok());
  // 381's ears, 385's long thin tail and Spot's horns carry no landmark;
  // measured at level 5: 0.051 -> 0.014, 0.091 -> 0.046 (the tail's patch
  // needs about 210 progressive steps: plain ones stall at 0.091) and
  // 0.026 -> 0.005 of the diagonal.
  for (const std::string name : { "381", "385", "spot" })
  {
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    test::ParameterizedModel parameterized;
    ASSERT_TRUE(test::parameterizeOnDomain(model, domain, parameterized).ok()) << name;
    PatchParameterizationOptions options;
    options.lowerStretch = true;
    PatchParameterization lowered;
    ASSERT_TRUE(parameterizePatches(parameterized.net, domain, lowered, options).ok()) << name;
    EXPECT_EQ(lowered.flippedTriangles, 0) << name;
    EXPECT_GT(lowered.smallestAreaRatio, parameterized.parameterization.smallestAreaRatio) << name;

    const double diagonal = boundingBoxDiagonal(model.data.mesh);
    double hausdorff[2] = { 0.0, 0.0 };
    int flipped = 0;
    for (int mode = 0; mode < 2; ++mode)
    {
      std::vector<SurfacePoint> samples;
      ASSERT_TRUE(placeOnSurface(remesh, parameterized.net, domain,
        mode == 0 ? parameterized.parameterization : lowered, samples).ok()) << name;
      const std::vector<Vec3> positions = samplePositions(parameterized.net, samples);
      hausdorff[mode] = surfaceDistance(remeshSurface(remesh, positions), model.data.mesh).hausdorff() / diagonal;
      if (mode == 1)
        flipped = trianglesAgainstSurface(remesh, parameterized.net, samples, positions);
    }
    EXPECT_LT(hausdorff[1], (name == "385" ? 0.6 : 0.4) * hausdorff[0]) << name;
    EXPECT_LT(hausdorff[1], name == "385" ? 0.055 : 0.02) << name;
    // The price (known-issues.md): more folds; bounded as for the default.
    EXPECT_LT(flipped, (name == "spot" ? 0.012 : 0.005) * remesh.triangles.size()) << name;
    std::cout << name << ": level 5 Hausdorff distance " << hausdorff[0] << " -> " << hausdorff[1]
              << " of the diagonal with lowered stretch, " << flipped << " triangles against the surface normal\n";
  }
}

TEST(SemiRegularRemesher, LowerStretchSettlesTheSameWayWhateverTheRounding)
{
  // 385's tail patch is relaxed until it settles, not until a step budget
  // runs out mid-way. With 150 steps, scaling the model by 1 + 1e-15 or
  // 1 + 1e-13 (another rounding, as on another machine) moved its remesh
  // from 0.066 to 0.017 or 0.020 of the diagonal from the tail's tip;
  // settled: 0.046, 0.043, 0.043.
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, remesh).ok());
  std::vector<double> hausdorff;
  for (double scale : { 0.0, 1e-15, 1e-13 })
  {
    test::LandmarkedModel model = test::landmarkedRealModel("385");
    for (Vec3& p : model.data.mesh.points)
      p *= 1.0 + scale;
    test::ParameterizedModel parameterized;
    ASSERT_TRUE(test::parameterizeOnDomain(model, domain, parameterized).ok());
    PatchParameterizationOptions options;
    options.lowerStretch = true;
    PatchParameterization lowered;
    ASSERT_TRUE(parameterizePatches(parameterized.net, domain, lowered, options).ok());
    std::vector<SurfacePoint> samples;
    ASSERT_TRUE(placeOnSurface(remesh, parameterized.net, domain, lowered, samples).ok());
    const std::vector<Vec3> positions = samplePositions(parameterized.net, samples);
    hausdorff.push_back(surfaceDistance(remeshSurface(remesh, positions), model.data.mesh).hausdorff() /
      boundingBoxDiagonal(model.data.mesh));
    std::cout << "385 scaled by 1 + " << scale << ", LowerStretch, level 5: Hausdorff distance " << hausdorff.back()
              << " of the diagonal\n";
  }
  const auto [least, most] = std::minmax_element(hausdorff.begin(), hausdorff.end());
  EXPECT_LT(*most - *least, 0.01);
}

TEST(SemiRegularRemesher, AdaptiveRemeshOfACollectionIsSharedAndCloserPerTriangle)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  ASSERT_GT(domain.mesh.vertexCount(), 0);
  const std::vector<std::string> names{ "381", "387", "spot" };
  IndexedModels indexed;
  const Status status = indexRealModels(names, domain, false, indexed);
  ASSERT_TRUE(status.ok()) << status.message();
  const auto& [models, parameterized, surfaces, collection] = indexed;
  const double tolerance = 0.002;
  SemiRegularMesh adaptive, uniform;
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(domain, 6, flatnessSplitRule(collection, tolerance), adaptive).ok());
  ASSERT_TRUE(buildSemiRegularMesh(domain, 6, uniform).ok());
  EXPECT_EQ(adaptive.level, 6);
  EXPECT_LT(adaptive.triangles.size() * 3, uniform.triangles.size());

  // The rule's contract: a triangle it leaves whole below the maximum level
  // is within the tolerance on every model at each of the 12 points of its
  // next two quadrisections, not only at its edge midpoints and centroid
  // (the rule once probed only those, and left triangles whose surface
  // bulged between them).
  int checked = 0, exceeded = 0, quarterPointsOnly = 0;
  for (std::size_t t = 0; t < adaptive.triangles.size(); ++t)
  {
    if (adaptive.levelOfTriangle[t] >= adaptive.level)
      continue;
    const int base = adaptive.patchOfTriangle[t];
    std::array<Vec2, 3> corner;
    for (int k = 0; k < 3; ++k)
      ASSERT_TRUE(locationInBaseTriangle(domain, adaptive.locations[adaptive.triangles[t][k]], base, corner[k]));
    // Only the rule's own triangles: not the halves of a bisection that
    // closes a finer neighbour.
    const double share = std::abs(cross2(corner[1] - corner[0], corner[2] - corner[0]));
    if (std::abs(share * std::pow(4.0, adaptive.levelOfTriangle[t]) - 1.0) > 1e-6)
      continue;
    for (std::size_t m = 0; m < collection.size(); ++m)
    {
      const ParameterizedSurface& surface = *collection[m];
      std::array<Vec3, 3> at;
      SurfacePoint sample;
      for (int k = 0; k < 3; ++k)
      {
        const SurfacePoint location = SurfacePoint::inTriangle(
          domain.mesh, base, { 1.0 - corner[k].x() - corner[k].y(), corner[k].x(), corner[k].y() });
        ASSERT_TRUE(surface.locate(location, sample).ok());
        at[k] = surface.position(sample);
      }
      bool beyond = false, beyondAtMidpointOrCentroid = false;
      for (int i = 0; i <= 4; ++i)
        for (int j = 0; i + j <= 4; ++j)
        {
          const double w[3] = { i / 4.0, j / 4.0, (4 - i - j) / 4.0 };
          if (w[0] == 1.0 || w[1] == 1.0 || w[2] == 1.0)
            continue;
          const Vec2 p = w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2];
          const SurfacePoint location = SurfacePoint::inTriangle(domain.mesh, base, { 1.0 - p.x() - p.y(), p.x(), p.y() });
          ASSERT_TRUE(surface.locate(location, sample).ok());
          const double off = (surface.position(sample) - (w[0] * at[0] + w[1] * at[1] + w[2] * at[2])).norm();
          const bool far = off > tolerance * surface.boundingBoxDiagonal() * (1.0 + 1e-9);
          beyond = beyond || far;
          const bool midpoint = (i % 2 == 0 && j % 2 == 0);
          beyondAtMidpointOrCentroid = beyondAtMidpointOrCentroid || (far && midpoint);
        }
      exceeded += beyond;
      quarterPointsOnly += beyond && !beyondAtMidpointOrCentroid;
      ++checked;
    }
  }
  std::cout << checked << " judged triangles and models, " << exceeded << " beyond the tolerance, "
            << quarterPointsOnly << " only between the edge midpoints and the centroid\n";
  EXPECT_GT(checked, 10000);
  // A few leaves come from splits that balance a finer neighbour, which the
  // rule did not ask for (4 of 47,886 here); with the midpoints and the
  // centroid only, 96 of 46,374 were beyond, 89 of them between those.
  EXPECT_LE(exceeded * 2000, checked);
  EXPECT_LE(quarterPointsOnly * 2000, checked);

  // Every leaf the rule left alone is flat enough on every model.
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    std::vector<SurfacePoint> samples;
    ASSERT_TRUE(
      placeOnSurface(adaptive, parameterized[i].net, domain, parameterized[i].parameterization, samples).ok());
    const std::vector<Vec3> positions = samplePositions(parameterized[i].net, samples);
    const TriangleMesh mesh = remeshSurface(adaptive, positions);
    EXPECT_TRUE(checkSurface(mesh).ok()) << names[i] << ": " << checkSurface(mesh).message;
    const double diagonal = boundingBoxDiagonal(models[i].data.mesh);
    const SurfaceDistance distance = surfaceDistance(mesh, models[i].data.mesh);
    EXPECT_LT(distance.aToB, 0.025 * diagonal) << names[i];
    std::cout << names[i] << ": adaptive to " << tolerance << " of the diagonal: " << adaptive.triangles.size()
              << " triangles (uniform level 6: " << uniform.triangles.size() << "), Hausdorff distance "
              << distance.hausdorff() / diagonal << " of the diagonal\n";
  }
}

TEST(SemiRegularRemesher, AdaptiveRemeshWithLowerStretchIsWithinOnePercentOfEveryModel)
{
  // The way to 1% of the diagonal on models whose tails and ears carry no
  // landmark: LowerStretch gives those parts room in the base domain, and
  // adaptive refinement spends the triangles there. Measured on 381, 385
  // and Spot (tolerance 0.005, levels up to 8): 9298 triangles, a quarter
  // of uniform level 5, and 0.0056, 0.0065, 0.0055 of the diagonal, where
  // uniform level 5 gives 0.014, 0.046 and 0.005 with LowerStretch (385:
  // 0.091 without).
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  ASSERT_GT(domain.mesh.vertexCount(), 0);
  const std::vector<std::string> names{ "381", "385", "spot" };
  IndexedModels indexed;
  const Status status = indexRealModels(names, domain, true, indexed);
  ASSERT_TRUE(status.ok()) << status.message();
  const auto& [models, parameterized, surfaces, collection] = indexed;
  // The whole remesh stage, as the filter runs it (without fold repair).
  std::vector<RemeshModel> given;
  for (std::size_t i = 0; i < names.size(); ++i)
    given.push_back({ &models[i].data.mesh, &surfaces[i] });
  RemeshOptions options;
  options.level = 8;
  options.adaptiveTolerance = 0.005;
  options.repairFolds = false;
  CollectionRemesh remeshed;
  RemeshReport report;
  const Status remeshing = remesh(domain, given, remeshed, options, &report);
  ASSERT_TRUE(remeshing.ok()) << remeshing.message();
  const SemiRegularMesh& adaptive = remeshed.mesh;
  SemiRegularMesh uniform;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 5, uniform).ok());
  EXPECT_LT(adaptive.triangles.size(), 0.3 * uniform.triangles.size());
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const double hausdorff = report.models[i].hausdorffDistanceRelative;
    EXPECT_LT(hausdorff, 0.01) << names[i];
    std::cout << names[i] << ": LowerStretch, adaptive to 0.005 up to level 8: " << adaptive.triangles.size()
              << " triangles (uniform level 5: " << uniform.triangles.size() << "), Hausdorff distance " << hausdorff
              << " of the diagonal\n";
  }
}

TEST(SemiRegularRemesher, AdaptiveWithEverySplitIsTheUniformRemesh)
{
  const BaseDomain domain = octahedronDomain();
  for (int level = 0; level <= 4; ++level)
  {
    SemiRegularMesh uniform, adaptive;
    ASSERT_TRUE(buildSemiRegularMesh(domain, level, uniform).ok());
    ASSERT_TRUE(
      buildAdaptiveSemiRegularMesh(domain, level, [](const auto&, int) { return true; }, adaptive).ok());
    EXPECT_EQ(adaptive.level, level);
    EXPECT_EQ(adaptive.triangles, uniform.triangles) << "level " << level;
    EXPECT_EQ(adaptive.patchOfTriangle, uniform.patchOfTriangle);
    EXPECT_EQ(adaptive.levelOfVertex, uniform.levelOfVertex);
    EXPECT_EQ(adaptive.levelOfTriangle, uniform.levelOfTriangle);
    ASSERT_EQ(adaptive.vertexCount(), uniform.vertexCount());
    for (int v = 0; v < uniform.vertexCount(); ++v)
    {
      EXPECT_EQ(adaptive.locations[v].triangle, uniform.locations[v].triangle);
      EXPECT_EQ(adaptive.locations[v].weight, uniform.locations[v].weight);
    }
  }
  SemiRegularMesh none;
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(domain, 5, [](const auto&, int) { return false; }, none).ok());
  EXPECT_EQ(none.triangles.size(), 8u);
  EXPECT_EQ(none.level, 0);
  EXPECT_FALSE(buildAdaptiveSemiRegularMesh(domain, 9, [](const auto&, int) { return true; }, none).ok());
}

TEST(SemiRegularRemesher, AdaptiveRefinementIsClosedBalancedAndDeterministic)
{
  const BaseDomain domain = octahedronDomain();
  // Refine towards one base vertex only: the rest must be closed off.
  const int corner = 0;
  const auto nearCorner = [&](const std::array<SurfacePoint, 3>& corners, int)
  {
    const Triangle& base = domain.mesh.triangles[corners[0].triangle];
    const auto k = std::find(base.begin(), base.end(), corner) - base.begin();
    if (k == 3)
      return false;
    for (const SurfacePoint& at : corners)
      if (at.weight[k] > 0.9)
        return true;
    return false;
  };
  SemiRegularMesh mesh, again;
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(domain, 6, nearCorner, mesh).ok());
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(domain, 6, nearCorner, again).ok());
  EXPECT_EQ(mesh.triangles, again.triangles);
  EXPECT_EQ(mesh.level, 6);
  SemiRegularMesh full;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 6, full).ok());
  EXPECT_LT(mesh.triangles.size() * 20, full.triangles.size());

  const TriangleMesh drawn = drawnOnDomain(domain, mesh);
  const SurfaceCheckResult check = checkSurface(drawn); // a T-junction would open the surface
  EXPECT_TRUE(check.ok()) << check.message;
  // Flat pieces: the drawn remesh covers the octahedron exactly once.
  double area = 0.0;
  for (int t = 0; t < drawn.triangleCount(); ++t)
  {
    const Triangle& tri = drawn.triangles[t];
    const Vec3 n = (drawn.points[tri[1]] - drawn.points[tri[0]]).cross(drawn.points[tri[2]] - drawn.points[tri[0]]);
    EXPECT_GT(n.dot(drawn.points[tri[0]] + drawn.points[tri[1]] + drawn.points[tri[2]]), 0.0) << "inverted " << t;
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 8.0 * std::sqrt(3.0) / 2.0, 1e-12);
  // Levels of triangles sharing an edge differ by at most one.
  std::map<std::pair<int, int>, int> levelAcross;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
    {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      const auto it = levelAcross.find({ b, a });
      if (it != levelAcross.end())
        EXPECT_LE(std::abs(it->second - mesh.levelOfTriangle[t]), 1);
      levelAcross[{ a, b }] = mesh.levelOfTriangle[t];
    }
  // Vertex f is still feature f, and a vertex's level is that of its first split.
  for (int bv = 0; bv < 6; ++bv)
    EXPECT_EQ(drawn.points[domain.featureIds[bv]], domain.mesh.points[bv]);
  EXPECT_TRUE(std::is_sorted(mesh.levelOfVertex.begin(), mesh.levelOfVertex.end()));
}
