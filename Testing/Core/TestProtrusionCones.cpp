#include <cmp/basedomain/BaseDomain.h>
#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/MeshFile.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/layout/ProtrusionCones.h>
#include <cmp/mesh/BoundaryLoops.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace cmp;

namespace
{

/// The base vertices joined to base vertex `v`, as features.
std::set<int> neighbourFeatures(const BaseDomain& domain, int v)
{
  std::set<int> result;
  for (const Triangle& t : domain.mesh.triangles)
    if (std::find(t.begin(), t.end(), v) != t.end())
      for (int u : t)
        if (u != v)
          result.insert(domain.featureIds[u]);
  return result;
}

/// The surface of revolution about the x axis of `profile` (x, radius),
/// from one pole (radius 0) to the other, `around` vertices per ring.
TriangleMesh revolved(const std::vector<std::pair<double, double>>& profile, int around)
{
  TriangleMesh mesh;
  const int rings = static_cast<int>(profile.size()) - 2;
  mesh.points.push_back(Vec3(profile.front().first, 0.0, 0.0));
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < around; ++j)
    {
      const double phi = 2.0 * kPi * j / around;
      mesh.points.push_back(Vec3(profile[i].first, profile[i].second * std::cos(phi), profile[i].second * std::sin(phi)));
    }
  mesh.points.push_back(Vec3(profile.back().first, 0.0, 0.0));
  const int last = mesh.vertexCount() - 1;
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * around + (j % around); };
  for (int j = 0; j < around; ++j)
  {
    mesh.triangles.push_back({ 0, at(1, j + 1), at(1, j) });
    for (int i = 1; i < rings; ++i)
    {
      mesh.triangles.push_back({ at(i, j), at(i, j + 1), at(i + 1, j + 1) });
      mesh.triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i + 1, j) });
    }
    mesh.triangles.push_back({ last, at(rings, j), at(rings, j + 1) });
  }
  return mesh;
}

/// A unit sphere with a spike `length` long and `radius` thick along +x,
/// joined to it by a flat collar at x = 0.7; the +x pole is the spike's
/// tip. With `club` > 0 the last 0.2 of the spike is a club of that
/// radius, ending in a half sphere.
TriangleMesh spikedSphere(double radius, double length, double club = 0.0)
{
  std::vector<std::pair<double, double>> profile;
  const double collar = std::acos(-0.7); // the sphere's angle from the -x pole at x = 0.7
  for (int i = 0; i <= 40; ++i)
  {
    const double a = collar * i / 40.0;
    profile.push_back({ -std::cos(a), std::sin(a) });
  }
  const double top = std::sin(collar);
  for (int i = 1; i <= 10; ++i)
    profile.push_back({ 0.7 + 0.005 * i, top + (radius - top) * i / 10.0 });
  const int along = static_cast<int>(length / 0.03);
  for (int i = 1; i <= along; ++i)
  {
    const double x = 0.75 + length * i / along;
    profile.push_back({ x, club > 0.0 && x > 0.75 + length - 0.2 ? club : radius });
  }
  const double end = club > 0.0 ? club : radius;
  for (int i = 1; i < 8; ++i)
  {
    const double a = 0.5 * kPi * i / 8.0;
    profile.push_back({ 0.75 + length + end * std::sin(a), end * std::cos(a) });
  }
  profile.push_back({ 0.75 + length + end, 0.0 });
  return revolved(profile, 32);
}

/// Models with their surfaces and landmark lists side by side, as the
/// collection entries take them (the surfaces point into `models`).
struct Collection
{
  std::vector<test::LandmarkedModel> models;
  std::vector<const TriangleMesh*> surfaces;
  std::vector<LandmarkList> landmarks;
};

Collection collectionOf(std::vector<test::LandmarkedModel> models)
{
  Collection c;
  c.models = std::move(models);
  for (const test::LandmarkedModel& model : c.models)
  {
    c.surfaces.push_back(&model.data.mesh);
    c.landmarks.push_back(model.landmarks);
  }
  return c;
}

Collection namedCollection(std::initializer_list<const char*> names)
{
  std::vector<test::LandmarkedModel> models;
  for (const char* name : names)
    models.push_back(test::landmarkedRealModel(name));
  return collectionOf(std::move(models));
}

/// Real models cut open round `feature` (the core tests' cut, 0.4 of the
/// way to its nearest neighbour in `closedL0`), side by side as the
/// collection entries take them.
struct OpenCollection
{
  std::vector<test::OpenModel> models;
  std::vector<const TriangleMesh*> surfaces;
  std::vector<LandmarkList> landmarks;
};

void cutOpen(std::initializer_list<const char*> names, const BaseDomain& closedL0, int feature, OpenCollection& out)
{
  out = OpenCollection{};
  for (const char* name : names)
  {
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    out.models.emplace_back();
    const Status cut = test::cutAroundFeature(model.data.mesh, model.landmarks, closedL0, feature, 0.4, out.models.back());
    ASSERT_TRUE(cut.ok()) << name << ": " << cut.message();
  }
  for (const test::OpenModel& model : out.models)
  {
    out.surfaces.push_back(&model.surface);
    out.landmarks.push_back(model.landmarks);
  }
}

} // namespace

TEST(ProtrusionCones, ASpikeIsAProtrusionAtItsTipNotInItsMiddleAndAClubbedOneWithinALargerBall)
{
  const TriangleMesh spiked = spikedSphere(0.02, 3.0);
  const int tip = spiked.vertexCount() - 1;
  // Landmarks: the -x pole and four round the equator (ring 20).
  LandmarkList body{ 0 };
  for (int j : { 0, 8, 16, 24 })
    body.push_back(1 + 19 * 32 + j);
  std::vector<Protrusion> found;
  ASSERT_TRUE(findProtrusions(spiked, body, found).ok());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].vertex, tip);
  EXPECT_LT(found[0].ballShare, 0.32);
  // With a landmark at the tip, the spike's middle is the deepest point:
  // its balls hold little (a thin band), but round a band the tip's side
  // is left apart, so it is no protrusion.
  LandmarkList withTip = body;
  withTip.push_back(tip);
  ASSERT_TRUE(findProtrusions(spiked, withTip, found).ok());
  EXPECT_TRUE(found.empty()) << found.size() << " found, the first at x = " << spiked.points[found[0].vertex].x();

  // A club at the tip (a tuft): too much area within the smallest ball,
  // thin within twice that.
  const TriangleMesh clubbed = spikedSphere(0.02, 3.0, 0.08);
  ASSERT_TRUE(findProtrusions(clubbed, body, found).ok());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].vertex, clubbed.vertexCount() - 1);
  EXPECT_DOUBLE_EQ(found[0].ballRadius, 0.15);
  ProtrusionConeOptions smallest;
  smallest.ballScales = 1;
  ASSERT_TRUE(findProtrusions(clubbed, body, found, smallest).ok());
  EXPECT_TRUE(found.empty());
}

TEST(ProtrusionCones, FindTheTailsOfTheFourLeggedModelsThatHaveOne)
{
  CMP_REQUIRE_SHARED_DATA();
  // 383's tail tip is vertex 3 of its file; 382 and 387 have no tail.
  const test::LandmarkedModel tailed = test::landmarkedRealModel("383");
  std::vector<Protrusion> found;
  ASSERT_TRUE(findProtrusions(tailed.data.mesh, tailed.landmarks, found).ok());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].nearestFeature, 13); // the tail's root
  const double unit = std::sqrt(surfaceArea(tailed.data.mesh));
  EXPECT_LT((tailed.data.mesh.points[found[0].vertex] - tailed.data.mesh.points[tailed.data.fileToMeshPoint[3]]).norm(),
    0.02 * unit);
  EXPECT_GT(found[0].depth, 0.15);
  EXPECT_LT(found[0].ballShare, 0.2);
  for (const char* name : { "382", "387" })
  {
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    ASSERT_TRUE(findProtrusions(model.data.mesh, model.landmarks, found).ok());
    EXPECT_TRUE(std::none_of(found.begin(), found.end(), [](const Protrusion& p) { return p.nearestFeature == 13; }))
      << name;
  }
}

TEST(ProtrusionCones, ATailTheCollectionSharesGetsAConeInTheBaseTriangleHoldingItsTip)
{
  CMP_REQUIRE_SHARED_DATA();
  Collection c = collectionOf(test::landmarkedRealModels());
  const std::vector<test::LandmarkedModel>& models = c.models;
  ASSERT_GE(models.size(), 11u);
  std::vector<const TriangleMesh*>& surfaces = c.surfaces;
  std::vector<LandmarkList>& landmarks = c.landmarks;
  const int from = static_cast<int>(
    std::find_if(models.begin(), models.end(), [](const auto& m) { return m.name == "381"; }) - models.begin());
  BaseDomain domain;
  ProtrusionConeReport report;
  const Status status = addProtrusionCones(surfaces, landmarks, from, domain, {}, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  // One cone, at the tail (root 13), on the models with a long thin tail;
  // placed later on the others. 381 has none: the tip of the first model
  // that has one (383) chose the base triangle.
  ASSERT_EQ(report.roots, std::vector<int>{ 13 });
  std::set<std::string> with;
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    ASSERT_EQ(landmarks[m].size(), 22u);
    if (landmarks[m][21] != kMissingLandmark)
      with.insert(models[m].name);
  }
  EXPECT_EQ(with, (std::set<std::string>{ "383", "385", "388", "389", "392" })); // 384's thick tail: no
  EXPECT_EQ(models[report.tipModels[0]].name, "383");
  EXPECT_TRUE(report.disagreeing.empty()); // 385's, 388's and 389's tips lie in triangles beside 383's
  ASSERT_TRUE(checkBaseDomain(domain, 22).ok());
  EXPECT_EQ(domain.mesh.triangleCount(), 40);
  const int cone = static_cast<int>(std::find(domain.featureIds.begin(), domain.featureIds.end(), 21) -
    domain.featureIds.begin());
  // A thin fan up the tail to the landmarks round its root.
  EXPECT_EQ(neighbourFeatures(domain, cone), (std::set<int>{ 12, 13, 14 }));

  // Fewer than leastModels models with the tail: no cone.
  ProtrusionConeOptions many;
  many.leastModels = 6; // five models have the tail
  std::vector<LandmarkList> unchanged;
  for (const test::LandmarkedModel& model : models)
    unchanged.push_back(model.landmarks);
  ASSERT_TRUE(addProtrusionCones(surfaces, unchanged, from, domain, many, &report).ok());
  EXPECT_TRUE(report.roots.empty());
  EXPECT_EQ(domain.mesh.vertexCount(), 21);
  EXPECT_EQ(unchanged[0].size(), 21u);
}

TEST(ProtrusionCones, TheConeGoesBesideEveryTipOrNowhere)
{
  CMP_REQUIRE_SHARED_DATA();
  // Over L0 built from 381, 385's tail tip lies in base triangle 8-13-14,
  // 388's in 12-13-6: they share landmark 13 only, so in either one the
  // other model's map would have to turn its tail round 13 across two
  // curves. Triangle 12-13-14, between them, is beside both: the cone
  // goes there (where 383's tip puts it over the whole collection).
  Collection c = namedCollection({ "381", "385", "388" });
  std::vector<const TriangleMesh*>& surfaces = c.surfaces;
  std::vector<LandmarkList>& landmarks = c.landmarks;
  BaseDomain built;
  ProtrusionConeReport report;
  ASSERT_TRUE(addProtrusionCones(surfaces, landmarks, 0, built, {}, &report).ok());
  ASSERT_EQ(report.roots, std::vector<int>{ 13 });
  EXPECT_TRUE(report.disagreeing.empty());
  EXPECT_EQ(neighbourFeatures(built, 21), (std::set<int>{ 12, 13, 14 }));
  EXPECT_EQ(landmarks[1].size(), 22u);

  // With no triangle beside both (12-14 flipped, so that 12-13-14 is gone
  // and 8-13-14 and 6-12-13 stay), no cone: the models disagree where the
  // tail leaves the body (the CGAL bull's raised tail, with the others'
  // hanging, did not settle: ProtrusionCones.cpp).
  BaseDomain plain;
  ASSERT_TRUE(buildBaseDomain(c.models[0].data.mesh, c.models[0].landmarks, plain).ok());
  std::vector<int> vertexOf(21);
  for (int v = 0; v < 21; ++v)
    vertexOf[plain.featureIds[v]] = v;
  const int a = vertexOf[12], b = vertexOf[14], apex = vertexOf[13];
  int across = -1, inner = -1, outer = -1;
  for (int t = 0; t < plain.mesh.triangleCount(); ++t)
  {
    const Triangle& tri = plain.mesh.triangles[t];
    const bool hasA = std::count(tri.begin(), tri.end(), a) > 0, hasB = std::count(tri.begin(), tri.end(), b) > 0;
    if (!hasA || !hasB)
      continue;
    if (std::count(tri.begin(), tri.end(), apex))
      inner = t;
    else
    {
      outer = t;
      for (int v : tri)
        if (v != a && v != b)
          across = v;
    }
  }
  ASSERT_GE(inner, 0);
  ASSERT_GE(outer, 0);
  // Keep the orientation: the corners of 12-13-14 in their order, 14 then
  // 12 replaced by the vertex across.
  Triangle first = plain.mesh.triangles[inner], second = plain.mesh.triangles[inner];
  std::replace(first.begin(), first.end(), a, across);
  std::replace(second.begin(), second.end(), b, across);
  BaseDomain flipped = plain;
  flipped.mesh.triangles[inner] = first;
  flipped.mesh.triangles[outer] = second;
  ASSERT_TRUE(checkBaseDomain(flipped, 21).ok());
  std::vector<LandmarkList> lists;
  for (const test::LandmarkedModel& model : c.models)
    lists.push_back(model.landmarks);
  BaseDomain domain;
  ASSERT_TRUE(addProtrusionCones(surfaces, lists, flipped, domain, {}, &report).ok());
  EXPECT_TRUE(report.roots.empty());
  EXPECT_EQ(domain.mesh.vertexCount(), 21);
  EXPECT_EQ(lists[1].size(), 21u);
  ASSERT_EQ(report.disagreeing.size(), 1u);
  const ProtrusionConeReport::Disagreement& d = report.disagreeing[0];
  EXPECT_EQ(d.root, 13);
  const auto features = [&](int t) {
    std::set<int> f;
    for (int v : domain.mesh.triangles[t])
      f.insert(domain.featureIds[v]);
    return f;
  };
  const std::set<int> split = features(d.splitTriangle), apart = features(d.triangle);
  EXPECT_EQ(split.count(13) + apart.count(13), 2u);
  std::set<int> shared;
  for (int f : split)
    if (apart.count(f))
      shared.insert(f);
  EXPECT_EQ(shared, std::set<int>{ 13 });
}

TEST(ProtrusionCones, AGivenBaseDomainKeepsItsTrianglesButTheOneHoldingMostTips)
{
  CMP_REQUIRE_SHARED_DATA();
  // The published template (vertex i = landmark i, built from 381 by
  // another tool): it has no tail vertex either.
  MeshFileData file;
  ASSERT_TRUE(readOBJ(test::sharedDataDir() + "/layouts/fourleg-381.obj", file).ok());
  BaseDomain given;
  given.mesh = file.mesh;
  for (int v = 0; v < given.mesh.vertexCount(); ++v)
    given.featureIds.push_back(v);
  ASSERT_TRUE(checkBaseDomain(given, 21).ok());

  Collection c = namedCollection({ "381", "383", "385", "388" });
  const std::vector<test::LandmarkedModel>& models = c.models;
  std::vector<const TriangleMesh*>& surfaces = c.surfaces;
  std::vector<LandmarkList>& landmarks = c.landmarks;
  BaseDomain domain;
  ProtrusionConeReport report;
  const Status status = addProtrusionCones(surfaces, landmarks, given, domain, {}, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(report.roots, std::vector<int>{ 13 });
  // The three tips lie in three triangles round 13, each beside the split one.
  EXPECT_TRUE(report.disagreeing.empty());
  ASSERT_EQ(landmarks[0].size(), 22u);
  EXPECT_EQ(landmarks[0][21], kMissingLandmark); // 381 has no tail: placed later
  for (int m = 1; m < 4; ++m)
    EXPECT_NE(landmarks[m][21], kMissingLandmark) << models[m].name;
  ASSERT_TRUE(checkBaseDomain(domain, 22).ok());
  EXPECT_EQ(domain.mesh.triangleCount(), given.mesh.triangleCount() + 2);
  // The given vertices stay where they were, with their features.
  for (int v = 0; v < 21; ++v)
  {
    EXPECT_EQ(domain.featureIds[v], given.featureIds[v]);
    EXPECT_EQ(domain.mesh.points[v], given.mesh.points[v]);
  }
  // Every given triangle but the split one is kept; the cone is joined to
  // the split one's corners, round the tail's root.
  const Triangle split = given.mesh.triangles[report.splitTriangles[0]];
  for (int t = 0; t < given.mesh.triangleCount(); ++t)
    if (t != report.splitTriangles[0])
      EXPECT_NE(std::find(domain.mesh.triangles.begin(), domain.mesh.triangles.end(), given.mesh.triangles[t]),
        domain.mesh.triangles.end());
  const std::set<int> star = neighbourFeatures(domain, 21);
  EXPECT_EQ(star, (std::set<int>{ split[0], split[1], split[2] }));
  EXPECT_EQ(star.count(13), 1u);

  // A given L0 that is not one, or does not fit the landmarks, is refused.
  BaseDomain broken = given;
  broken.mesh.triangles.pop_back();
  std::vector<LandmarkList> lists;
  for (const test::LandmarkedModel& model : models)
    lists.push_back(model.landmarks);
  EXPECT_FALSE(addProtrusionCones(surfaces, lists, broken, domain).ok());
  lists[1].pop_back();
  EXPECT_FALSE(addProtrusionCones(surfaces, lists, given, domain).ok());
}

// Surfaces with boundaries (issue 27 B): a tail is as landmark-free on an
// animal cut open round the middle of its back as on a whole one. Without
// a cone there, consistent-remesh left 385 2.92% of its diagonal from its
// remesh (level 4, L0 from 381; known-issues.md, "Surfaces with
// boundaries").
TEST(ProtrusionCones, OpenSurfacesGetTheConeOnTheirOpenL0)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain closedL0 = test::realBaseDomain("381");
  OpenCollection back;
  ASSERT_NO_FATAL_FAILURE(cutOpen({ "381", "383", "385" }, closedL0, 12, back));
  const std::vector<test::OpenModel>& open = back.models;
  const std::vector<const TriangleMesh*>& surfaces = back.surfaces;
  const std::vector<LandmarkList>& landmarks = back.landmarks;
  const int features = static_cast<int>(landmarks[0].size());
  BaseDomain builtOpen;
  ASSERT_TRUE(buildBaseDomain(open[0].surface, open[0].landmarks, builtOpen).ok());

  // Built from the first model, and given: the same cone either way.
  for (const bool given : { false, true })
  {
    SCOPED_TRACE(given ? "given L0" : "built L0");
    std::vector<LandmarkList> lists = landmarks;
    BaseDomain domain;
    ProtrusionConeReport report;
    const Status status = given ? addProtrusionCones(surfaces, lists, builtOpen, domain, {}, &report)
                                : addProtrusionCones(surfaces, lists, 0, domain, {}, &report);
    ASSERT_TRUE(status.ok()) << status.message();
    // The tail's root, landmark 13, is feature 12 once 12 is cut out.
    ASSERT_EQ(report.roots, std::vector<int>{ 12 });
    EXPECT_EQ(report.tipModels, std::vector<int>{ 1 }); // 383's tip (381 has no tail)
    EXPECT_EQ(lists[0][features], kMissingLandmark);
    for (int m : { 1, 2 })
    {
      std::vector<char> onBoundary;
      ASSERT_TRUE(boundaryVertices(open[m].surface, onBoundary).ok());
      ASSERT_NE(lists[m][features], kMissingLandmark) << m;
      EXPECT_FALSE(onBoundary[lists[m][features]]) << m;
    }
    // L0 stays open, with the same hole; the cone, inside L0, splits a
    // triangle round the root (beside the hole: the back's boundary
    // landmark towards the tail is one of its corners).
    BaseDomain closed, closedBuilt;
    BaseDomainHoles holes, builtHoles;
    ASSERT_TRUE(closeBaseDomain(domain, closed, holes).ok());
    ASSERT_TRUE(closeBaseDomain(builtOpen, closedBuilt, builtHoles).ok());
    EXPECT_EQ(holes.loops, builtHoles.loops);
    EXPECT_EQ(domain.mesh.triangleCount(), builtOpen.mesh.triangleCount() + 2);
    const int cone = static_cast<int>(
      std::find(domain.featureIds.begin(), domain.featureIds.end(), features) - domain.featureIds.begin());
    ASSERT_LT(cone, domain.mesh.vertexCount());
    const std::set<int> star = neighbourFeatures(domain, cone);
    EXPECT_EQ(star.size(), 3u);
    EXPECT_EQ(star.count(12), 1u);
    EXPECT_FALSE(holes.onBoundary(features));
  }

  // Cut round the top of the head (landmark 1), the ears are nearest to
  // boundary landmarks, another on each model: they get no cone (4 cones
  // on 2 or 3 models each had left no model with every feature, and
  // consistent-remesh could place none). The tail keeps its cone.
  {
    OpenCollection heads;
    ASSERT_NO_FATAL_FAILURE(cutOpen({ "381", "383", "385", "spot" }, closedL0, 1, heads));
    const std::vector<const TriangleMesh*>& headSurfaces = heads.surfaces;
    std::vector<LandmarkList>& headLandmarks = heads.landmarks;
    const int headFeatures = static_cast<int>(headLandmarks[0].size());
    BaseDomain domain;
    ProtrusionConeReport report;
    const Status status = addProtrusionCones(headSurfaces, headLandmarks, 0, domain, {}, &report);
    ASSERT_TRUE(status.ok()) << status.message();
    BaseDomain closed;
    BaseDomainHoles holes;
    ASSERT_TRUE(closeBaseDomain(domain, closed, holes).ok());
    int byBoundary = 0; // protrusions found nearest to a boundary landmark
    for (const std::vector<Protrusion>& found : report.protrusions)
      for (const Protrusion& p : found)
        byBoundary += holes.onBoundary(p.nearestFeature) ? 1 : 0;
    EXPECT_GE(byBoundary, 3); // the ears of 381, 385 and Spot
    EXPECT_EQ(report.roots, std::vector<int>{ 12 }); // the tail: landmark 13 once 1 is cut out
    EXPECT_EQ(headLandmarks[1].size(), static_cast<std::size_t>(headFeatures + 1));
  }

  // Closed models with an open L0 are refused (each with as many landmarks:
  // its own and other vertices).
  Collection closedModels = namedCollection({ "381", "383" });
  for (LandmarkList& list : closedModels.landmarks)
    for (int v = 0; static_cast<int>(list.size()) < features; ++v)
      if (std::find(list.begin(), list.end(), v) == list.end())
        list.push_back(v);
  BaseDomain domain;
  const Status mixed = addProtrusionCones(closedModels.surfaces, closedModels.landmarks, builtOpen, domain);
  EXPECT_FALSE(mixed.ok());
  EXPECT_NE(mixed.message().find("boundary loops"), std::string::npos) << mixed.message();
}

TEST(ProtrusionCones, RefuseOptionsAndCollectionsThatDoNotFit)
{
  const TriangleMesh sphere = test::sphere(2);
  const LandmarkList landmarks{ 0, 1, 2, 3 };
  std::vector<Protrusion> found;
  ProtrusionConeOptions bad;
  bad.ballRadius = 0.0;
  EXPECT_FALSE(findProtrusions(sphere, landmarks, found, bad).ok());
  bad = {};
  bad.ballScales = 0;
  EXPECT_FALSE(findProtrusions(sphere, landmarks, found, bad).ok());
  bad.ballScales = 9;
  EXPECT_FALSE(findProtrusions(sphere, landmarks, found, bad).ok());
  bad = {};
  bad.leastModels = 0;
  EXPECT_FALSE(findProtrusions(sphere, landmarks, found, bad).ok());
  EXPECT_FALSE(findProtrusions(sphere, { 0, kMissingLandmark }, found).ok());
  EXPECT_FALSE(findProtrusions(TriangleMesh{}, landmarks, found).ok());
  // A sphere has no protrusion.
  ASSERT_TRUE(findProtrusions(sphere, landmarks, found).ok());
  EXPECT_TRUE(found.empty());

  std::vector<const TriangleMesh*> surfaces{ &sphere, &sphere };
  std::vector<LandmarkList> lists{ landmarks, { 0, 1, 2 } };
  BaseDomain domain;
  EXPECT_FALSE(addProtrusionCones(surfaces, lists, 0, domain).ok()); // 4 and 3 features
  lists = { landmarks };
  EXPECT_FALSE(addProtrusionCones(surfaces, lists, 0, domain).ok()); // one list for two surfaces
  lists = { landmarks, landmarks };
  EXPECT_FALSE(addProtrusionCones(surfaces, lists, 2, domain).ok()); // no model 2
  lists = { { 0, 1, 2, kMissingLandmark }, landmarks };
  EXPECT_FALSE(addProtrusionCones(surfaces, lists, 0, domain).ok()); // L0's model misses one
}
