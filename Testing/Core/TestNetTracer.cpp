#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/io/MeshFile.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/layout/LayoutValidator.h>
#include "TestMeshes.h"
#include "TestShapes.h"

#include <gtest/gtest.h>

#include <cmath>

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
