#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/MeshFile.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/layout/LayoutValidator.h>
#include <cmp/mesh/EdgePaths.h>
#include "TestMeshes.h"
#include "TestShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace cmp;

namespace
{

/// Traces and runs the independent validator; returns the report.
NetTracerReport expectValidNet(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  const std::string& what, NetTracerOptions options = {})
{
  TracedNet net;
  NetTracerReport report;
  const Status status = traceFeatureNet(surface, landmarks, domain, net, options, &report);
  EXPECT_TRUE(status.ok()) << what << ": " << status.message();
  if (!status.ok())
    return report;
  const LabelledSurface out = toLabelledSurface(net, domain);
  for (const std::string& problem : validateLayout(out, toBaseTriangles(domain)))
    ADD_FAILURE() << what << ": " << problem;
  EXPECT_NEAR(totalArea(out), surfaceArea(surface), 1e-9 * surfaceArea(surface)) << what;
  EXPECT_EQ(net.curves.size(), static_cast<std::size_t>(edgeCount(domain.mesh)));
  return report;
}

using test::bumpySphere;
using test::nearestVertex;

/// A base domain whose vertex i is feature i, with the given triangles.
BaseDomain domainOf(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles)
{
  BaseDomain domain;
  domain.mesh.points = positions;
  domain.mesh.triangles = triangles;
  for (int i = 0; i < static_cast<int>(positions.size()); ++i)
    domain.featureIds.push_back(i);
  return domain;
}

BaseDomain octahedronDomain()
{
  const TriangleMesh o = test::octahedron();
  return domainOf(o.points, o.triangles);
}

LandmarkList landmarksAt(const TriangleMesh& mesh, const std::vector<Vec3>& directions)
{
  LandmarkList landmarks;
  for (const Vec3& d : directions)
    landmarks.push_back(nearestVertex(mesh, d));
  return landmarks;
}

} // namespace

TEST(NetTracer, FourFullyConnectedLandmarksOfFigure3)
{
  // The paper's Figure 3: naive shortest paths cross; ours must not.
  const TriangleMesh sphere = bumpySphere(4);
  const TriangleMesh tetra = test::tetrahedron(Vec3(-0.25, -0.25, -0.25));
  const BaseDomain domain = domainOf(tetra.points, tetra.triangles);
  expectValidNet(sphere, landmarksAt(sphere, tetra.points), domain, "tetrahedron");
}

TEST(NetTracer, OctahedronAndIcosahedronLayoutsOnABumpySphere)
{
  const TriangleMesh sphere = bumpySphere(4);
  const BaseDomain octahedron = octahedronDomain();
  expectValidNet(sphere, landmarksAt(sphere, octahedron.mesh.points), octahedron, "octahedron");

  const double t = (1 + std::sqrt(5.0)) / 2;
  const std::vector<Vec3> ico = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  const std::vector<Triangle> faces = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  const BaseDomain icosahedron = domainOf(ico, faces);
  ASSERT_TRUE(checkBaseDomain(icosahedron, 12).ok());
  expectValidNet(sphere, landmarksAt(sphere, ico), icosahedron, "icosahedron");
}

TEST(NetTracer, EncirclingCaseOfFigure5)
{
  // Landmark 5 (the -z vertex of the octahedron) sits inside the base
  // triangle (0, 2, 4): tracing that triangle's short curves first would
  // encircle it. The spanning tree comes first, so it cannot happen.
  const TriangleMesh sphere = bumpySphere(4);
  std::vector<Vec3> positions = test::octahedron().points;
  positions[5] = Vec3(0.5, 0.5, 0.7);
  expectValidNet(sphere, landmarksAt(sphere, positions), octahedronDomain(), "encircled");
}

TEST(NetTracer, SwirledLayoutStillGivesAValidNet)
{
  // Landmarks 0 and 2 trade places: the octahedron's connectivity no longer
  // matches the geometry, so curves must wind around; the net stays valid.
  const TriangleMesh sphere = bumpySphere(4);
  std::vector<Vec3> positions = test::octahedron().points;
  std::swap(positions[0], positions[2]);
  std::swap(positions[1], positions[4]);
  for (bool swirls : { true, false })
  {
    NetTracerOptions options;
    options.detectSwirls = swirls;
    expectValidNet(sphere, landmarksAt(sphere, positions), octahedronDomain(),
      swirls ? "swirled" : "swirled, no detector", options);
  }
}

TEST(NetTracer, LandmarkOnAThinSpike)
{
  TriangleMesh sphere = test::sphere(4);
  for (Vec3& p : sphere.points)
    if (p.x() > 0.8)
      p = Vec3(0.8 + (p.x() - 0.8) * 25.0, 0.3 * p.y(), 0.3 * p.z()); // a long thin spike along +x
  const BaseDomain octahedron = octahedronDomain();
  expectValidNet(sphere, landmarksAt(sphere, octahedron.mesh.points), octahedron, "spike");
}

TEST(NetTracer, PureShortestPathsAreValidToo)
{
  NetTracerOptions options;
  options.parameterizationWeight = 0.0;
  options.detectSwirls = false;
  const TriangleMesh sphere = bumpySphere(3);
  const BaseDomain octahedron = octahedronDomain();
  expectValidNet(sphere, landmarksAt(sphere, octahedron.mesh.points), octahedron, "shortest", options);
}

TEST(NetTracer, EveryVertexALandmark)
{
  // No free vertex at all: the harmonic system is empty and every curve
  // needs a split edge to exist.
  const BaseDomain octahedron = octahedronDomain();
  expectValidNet(octahedron.mesh, { 0, 1, 2, 3, 4, 5 }, octahedron, "octahedron on itself");
}

TEST(NetTracer, RefusesBadInput)
{
  const TriangleMesh sphere = test::sphere(3);
  const BaseDomain octahedron = octahedronDomain();
  TracedNet net;
  const auto expectError = [&](const Status& s, const std::string& fragment)
  {
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message().find(fragment), std::string::npos) << s.message();
  };
  expectError(traceFeatureNet(sphere, { 0, 1, 2, 3, 4 }, octahedron, net), "5 landmarks but 6 are expected");
  expectError(traceFeatureNet(sphere, { 0, 1, 2, 3, 4, 4 }, octahedron, net), "duplicate landmark");
  TriangleMesh open = sphere;
  open.triangles.pop_back();
  expectError(traceFeatureNet(open, { 0, 1, 2, 3, 4, 5 }, octahedron, net), "open surface");
  BaseDomain torus;
  torus.mesh = test::torus(3, 3);
  for (int i = 0; i < 9; ++i)
    torus.featureIds.push_back(i);
  expectError(traceFeatureNet(test::sphere(3), { 0, 1, 2, 3, 4, 5, 6, 7, 8 }, torus, net), "genus 1");
  expectError(traceFeatureNet(TriangleMesh{}, {}, octahedron, net), "empty surface");
}

namespace
{

/// A shortest path along mesh edges from `from` to `to` through vertices not
/// marked in `blocked` (the ends may be), or empty.
std::vector<int> meshPath(const TriangleMesh& mesh, int from, int to, const std::vector<char>& blocked)
{
  std::vector<int> parent;
  const std::vector<double> distance =
    edgePathDistances(edgeGraph(mesh), { from }, std::numeric_limits<double>::infinity(), &parent, &blocked);
  return edgePath(parent, distance, to);
}

/// The curve of the base edge between features (= base vertices) `a` and
/// `b`, from a's landmark to b's.
std::vector<int> curveBetween(const TracedNet& net, int a, int b)
{
  for (std::size_t e = 0; e < net.baseEdges.size(); ++e)
  {
    if (net.baseEdges[e] == std::array<int, 2>{ a, b })
      return net.curves[e];
    if (net.baseEdges[e] == std::array<int, 2>{ b, a })
      return std::vector<int>(net.curves[e].rbegin(), net.curves[e].rend());
  }
  return {};
}

/// Traces with `options` and checks the net as `expectValidNet()` does,
/// and that every preset curve is the curve of its base edge, vertex for
/// vertex.
void expectPresetCurvesKept(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  const NetTracerOptions& options, const std::string& what)
{
  TracedNet net;
  const Status status = traceFeatureNet(surface, landmarks, domain, net, options);
  ASSERT_TRUE(status.ok()) << what << ": " << status.message();
  const LabelledSurface out = toLabelledSurface(net, domain);
  for (const std::string& problem : validateLayout(out, toBaseTriangles(domain)))
    ADD_FAILURE() << what << ": " << problem;
  EXPECT_NEAR(totalArea(out), surfaceArea(surface), 1e-9 * surfaceArea(surface)) << what;
  for (const PresetCurve& preset : options.presetCurves)
    EXPECT_EQ(curveBetween(net, preset.from, preset.to), preset.vertices)
      << what << ": preset curve from " << preset.from << " to " << preset.to;
}

} // namespace

TEST(NetTracer, PresetCurvesAreKeptAsGiven)
{
  // On the bumpy sphere, the curve from +x (0) to +y (2) is given as a
  // detour through a vertex well inside the face (0, 2, 4), and the curve
  // from -z (5) to +x as a shortest path beside it, given from its other
  // end: both are the net's curves exactly, and the net is valid.
  const TriangleMesh sphere = bumpySphere(4);
  const BaseDomain octahedron = octahedronDomain();
  const LandmarkList landmarks = landmarksAt(sphere, octahedron.mesh.points);
  std::vector<char> blocked(sphere.vertexCount(), 0);
  for (int v : landmarks)
    blocked[v] = 1;
  const int waypoint = nearestVertex(sphere, Vec3(1.0, 1.0, 0.8));
  std::vector<int> detour = meshPath(sphere, landmarks[0], waypoint, blocked);
  ASSERT_GE(detour.size(), 3u);
  for (int v : detour)
    blocked[v] = 1;
  const std::vector<int> rest = meshPath(sphere, waypoint, landmarks[2], blocked);
  ASSERT_GE(rest.size(), 3u);
  detour.insert(detour.end(), rest.begin() + 1, rest.end());
  for (int v : detour)
    blocked[v] = 1;
  const std::vector<int> down = meshPath(sphere, landmarks[5], landmarks[0], blocked);
  ASSERT_GE(down.size(), 3u);

  TracedNet plain;
  ASSERT_TRUE(traceFeatureNet(sphere, landmarks, octahedron, plain).ok());
  EXPECT_NE(curveBetween(plain, 0, 2), detour); // the tracer alone goes elsewhere

  NetTracerOptions options;
  options.presetCurves = { { 0, 2, detour }, { 5, 0, down } };
  expectPresetCurvesKept(sphere, landmarks, octahedron, options, "detour and shortest path");
  options.detectSwirls = false;
  expectPresetCurvesKept(sphere, landmarks, octahedron, options, "without the swirl detector");

  // The octahedron on itself: preset curves of one edge each, between
  // landmarks, are not split to make room. A cycle (the face 0, 2, 4) and
  // a spoke, then every edge (nothing left to trace).
  NetTracerOptions edges;
  edges.presetCurves = { { 0, 2, { 0, 2 } }, { 4, 2, { 4, 2 } }, { 0, 4, { 0, 4 } }, { 5, 1, { 5, 1 } } };
  expectPresetCurvesKept(octahedron.mesh, { 0, 1, 2, 3, 4, 5 }, octahedron, edges, "one face and a spoke");
  // The star of 0, as a cap's spokes: the traced curves cannot reach 0, so
  // the spanning tree is complete only if the preset curves count in it.
  edges.presetCurves = { { 0, 2, { 0, 2 } }, { 0, 3, { 0, 3 } }, { 4, 0, { 4, 0 } }, { 5, 0, { 5, 0 } } };
  expectPresetCurvesKept(octahedron.mesh, { 0, 1, 2, 3, 4, 5 }, octahedron, edges, "the star of 0");
  edges.presetCurves.clear();
  const TriangleMesh& o = octahedron.mesh;
  for (const Triangle& t : o.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < t[(k + 1) % 3])
        edges.presetCurves.push_back({ t[k], t[(k + 1) % 3], { t[k], t[(k + 1) % 3] } });
  ASSERT_EQ(edges.presetCurves.size(), 12u);
  expectPresetCurvesKept(octahedron.mesh, { 0, 1, 2, 3, 4, 5 }, octahedron, edges, "every edge preset");
}

TEST(NetTracer, RefusesBadPresetCurvesNamingTheProblem)
{
  const TriangleMesh sphere = bumpySphere(3);
  const BaseDomain octahedron = octahedronDomain();
  const LandmarkList landmarks = landmarksAt(sphere, octahedron.mesh.points);
  std::vector<char> blocked(sphere.vertexCount(), 0);
  for (int v : landmarks)
    blocked[v] = 1;
  const std::vector<int> good = meshPath(sphere, landmarks[0], landmarks[2], blocked);
  ASSERT_GE(good.size(), 4u);
  {
    NetTracerOptions options;
    options.presetCurves = { { 0, 2, good } };
    expectPresetCurvesKept(sphere, landmarks, octahedron, options, "the good curve");
  }
  const auto expectRefused = [&](const std::vector<PresetCurve>& presets, const std::string& fragment)
  {
    NetTracerOptions options;
    options.presetCurves = presets;
    TracedNet net;
    const Status s = traceFeatureNet(sphere, landmarks, octahedron, net, options);
    EXPECT_FALSE(s.ok()) << fragment;
    EXPECT_NE(s.message().find(fragment), std::string::npos) << s.message();
  };
  const std::vector<int> reversed(good.rbegin(), good.rend());
  expectRefused({ { 0, 9, good } }, "preset curve 0 (features 0 to 9): feature 9 is out of range (0..5)");
  expectRefused({ { -1, 2, good } }, "feature -1 is out of range");
  expectRefused({ { 0, 1, good } }, "no edge of the base domain joins the two features");
  expectRefused({ { 0, 2, { landmarks[0] } } }, "needs at least 2 vertices (it has 1)");
  expectRefused({ { 2, 0, good } }, "does not run from the landmark of feature 2");
  std::vector<int> broken = good;
  broken[1] = sphere.vertexCount();
  expectRefused({ { 0, 2, broken } }, "is out of range (the surface has");
  broken = good;
  broken.erase(broken.begin() + 1);
  expectRefused({ { 0, 2, broken } }, "are not joined by a mesh edge");
  broken = good;
  broken.insert(broken.begin() + 3, { good[1], good[2] }); // back and forth along two edges
  expectRefused({ { 0, 2, broken } }, "vertex " + std::to_string(good[1]) + " repeats");
  // Through another landmark: 0 to 4 (+z) by way of 2 (+y).
  std::vector<int> through = good;
  std::vector<char> beyond = blocked;
  for (int v : good)
    beyond[v] = 1;
  const std::vector<int> up = meshPath(sphere, landmarks[2], landmarks[4], beyond);
  ASSERT_GE(up.size(), 2u);
  through.insert(through.end(), up.begin() + 1, up.end());
  expectRefused({ { 0, 4, through } }, "inner vertex " + std::to_string(landmarks[2]) + " is a landmark");
  // Two curves through one inner vertex: 0 to 3 leaves along the first
  // edge of 0 to 2.
  std::vector<char> aside = blocked;
  for (std::size_t k = 2; k < good.size(); ++k)
    aside[good[k]] = 1;
  std::vector<int> sharing = meshPath(sphere, good[1], landmarks[3], aside);
  ASSERT_FALSE(sharing.empty());
  sharing.insert(sharing.begin(), landmarks[0]);
  expectRefused({ { 0, 2, good }, { 0, 3, sharing } },
    "preset curve 1 (features 0 to 3): inner vertex " + std::to_string(good[1]) + " is on preset curve 0 too");
  expectRefused({ { 0, 2, good }, { 2, 0, reversed } },
    "preset curve 1 (features 2 to 0): preset curve 0 is already the curve of that base edge");
}

TEST(NetTracer, EveryRealModelWithL0From381AndFromSpot)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::vector<test::LandmarkedModel> models = test::landmarkedRealModels();
  ASSERT_GE(models.size(), 11u);
  for (const std::string source : { "381", "spot" })
  {
    const auto it = std::find_if(models.begin(), models.end(), [&](const test::LandmarkedModel& m) { return m.name == source; });
    ASSERT_NE(it, models.end());
    BaseDomain domain;
    ASSERT_TRUE(buildBaseDomain(it->data.mesh, it->landmarks, domain).ok());
    for (const test::LandmarkedModel& model : models)
    {
      const NetTracerReport report =
        expectValidNet(model.data.mesh, model.landmarks, domain, model.name + " with L0 from " + source);
      std::cout << model.name << " (L0 " << source << "): length/sqrt(area) "
                << report.netLength / std::sqrt(surfaceArea(model.data.mesh)) << ", retraced " << report.retraced
                << ", penalised " << report.penalised << ", split edges " << report.splitEdges << "\n";
    }
  }
}

/// With L0 built from 383, requeueing a curve the swirl detector flags
/// forces it in, its postponements spent, into the net it swirled in, and
/// 381's net detours round it (40.4 per square root of area, 18.8 on its
/// own L0). The tracer's second trace, postponed curves waiting for the net
/// to change round them, must be kept where it is shorter, and every
/// model's net must stay near its length on its own L0.
TEST(NetTracer, PostponedCurvesWaitForTheNetWhereThatIsShorter)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::vector<test::LandmarkedModel> models = test::landmarkedRealModels();
  ASSERT_GE(models.size(), 11u);
  const auto named = [&](const std::string& name)
  {
    const auto it = std::find_if(models.begin(), models.end(), [&](const test::LandmarkedModel& m) { return m.name == name; });
    EXPECT_NE(it, models.end()) << name;
    return it;
  };
  const auto source = named("383");
  ASSERT_NE(source, models.end());
  BaseDomain domain;
  ASSERT_TRUE(buildBaseDomain(source->data.mesh, source->landmarks, domain).ok());
  bool someWaited = false;
  for (const test::LandmarkedModel& model : models)
  {
    BaseDomain own;
    ASSERT_TRUE(buildBaseDomain(model.data.mesh, model.landmarks, own).ok()) << model.name;
    const NetTracerReport onOwn = expectValidNet(model.data.mesh, model.landmarks, own, model.name + " on its own L0");
    const NetTracerReport report =
      expectValidNet(model.data.mesh, model.landmarks, domain, model.name + " with L0 from 383");
    std::cout << model.name << ": net on L0 from 383 / on its own " << report.netLength / onOwn.netLength
              << (report.waited ? " (waited" : " (requeued") << ", other net " << report.alternativeNetLength / onOwn.netLength
              << ")\n";
    EXPECT_LT(report.netLength, 1.3 * onOwn.netLength) << model.name;
    if (report.alternativeNetLength > 0.0)
      EXPECT_LE(report.netLength, report.alternativeNetLength) << model.name;
    someWaited = someWaited || report.waited;
  }
  EXPECT_TRUE(someWaited);

  // Without the second trace, 381's net is the detour.
  const auto mistraced = named("381");
  ASSERT_NE(mistraced, models.end());
  NetTracerOptions requeueOnly;
  requeueOnly.retraceWaiting = false;
  const NetTracerReport requeued =
    expectValidNet(mistraced->data.mesh, mistraced->landmarks, domain, "381 with L0 from 383, requeued", requeueOnly);
  const NetTracerReport kept = expectValidNet(mistraced->data.mesh, mistraced->landmarks, domain, "381 with L0 from 383");
  EXPECT_FALSE(requeued.waited);
  EXPECT_EQ(requeued.alternativeNetLength, 0.0);
  EXPECT_TRUE(kept.waited);
  EXPECT_NEAR(kept.alternativeNetLength, requeued.netLength, 1e-9 * requeued.netLength);
  EXPECT_LT(kept.netLength, 0.6 * requeued.netLength);
}

/// Whether one of `problems` contains `text`; prints them if not.
bool mentions(const std::vector<std::string>& problems, const std::string& text)
{
  for (const std::string& problem : problems)
    if (problem.find(text) != std::string::npos)
      return true;
  for (const std::string& problem : problems)
    std::cout << "  problem: " << problem << "\n";
  return false;
}

TEST(NetValidator, CatchesBrokenLayouts)
{
  const TriangleMesh sphere = bumpySphere(3);
  const BaseDomain octahedron = octahedronDomain();
  TracedNet net;
  ASSERT_TRUE(traceFeatureNet(sphere, landmarksAt(sphere, octahedron.mesh.points), octahedron, net).ok());
  const LabelledSurface good = toLabelledSurface(net, octahedron);
  const BaseTriangles base = toBaseTriangles(octahedron);
  ASSERT_TRUE(validateLayout(good, base).empty());

  LabelledSurface swapped = good; // two whole patches exchange labels
  for (int& p : swapped.patchId)
    p = p == 0 ? 1 : p == 1 ? 0 : p;
  EXPECT_TRUE(mentions(validateLayout(swapped, base), "patch 0: its boundary passes landmarks"));

  LabelledSurface stray = good; // one triangle inside patch 0 claims patch 7
  const auto inside = std::find(stray.patchId.begin(), stray.patchId.end(), 0) - stray.patchId.begin();
  stray.patchId[inside] = 7;
  EXPECT_TRUE(mentions(validateLayout(stray, base), "patch 7: "));

  BaseTriangles mirrored = base; // the base domain with reversed orientation
  for (auto& t : mirrored.triangles)
    std::swap(t[1], t[2]);
  EXPECT_TRUE(mentions(validateLayout(good, mirrored), "in that order"));

  LabelledSurface merged = good; // patch 2 swallowed by patch 3: 3 is no longer a 3-landmark disk
  for (int& p : merged.patchId)
    p = p == 2 ? 3 : p;
  const std::vector<std::string> mergedProblems = validateLayout(merged, base);
  EXPECT_TRUE(mentions(mergedProblems, "patch 2: has no triangles"));
  EXPECT_TRUE(mentions(mergedProblems, "patch 3: its boundary passes landmarks"));
  EXPECT_TRUE(mentions(mergedProblems, "should share a curve but do not touch"));

  LabelledSurface outOfRange = good;
  outOfRange.patchId[5] = 8;
  EXPECT_TRUE(mentions(validateLayout(outOfRange, base), "triangle 5 has PatchId 8"));
}
