#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/layout/LayoutValidator.h>
#include <cmp/io/MeshFile.h>
#include <cmp/map/NetStraightener.h>
#include <cmp/map/Straighten.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/map/PatchParameterization.h>
#include "TestMeshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

using namespace cmp;

namespace
{

/// Every vertex of `out` is the stated combination of input vertices, and
/// those vertices belong to the input triangle of every triangle using it.
void expectOnInputSurface(const TracedNet& input, const StraightenedNet& out, const std::string& what)
{
  const TriangleMesh before = input.mesh.toTriangleMesh();
  const double tolerance = 1e-9 * boundingBoxDiagonal(before);
  int off = 0, outside = 0;
  for (int v = 0; v < out.net.mesh.vertexCount(); ++v)
  {
    Vec3 p = Vec3::Zero();
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
      if (out.inputPoint[v].vertex[k] >= 0)
      {
        p += out.inputPoint[v].weight[k] * before.points[out.inputPoint[v].vertex[k]];
        sum += out.inputPoint[v].weight[k];
      }
    off += (p - out.net.mesh.point(v)).norm() > tolerance || std::abs(sum - 1.0) > 1e-12;
  }
  for (int t = 0; t < out.net.mesh.triangleCount(); ++t)
    for (int v : out.net.mesh.triangle(t))
      for (int u : out.inputPoint[v].vertex)
      {
        const Triangle& home = before.triangles[out.inputTriangle[t]];
        outside += u >= 0 && std::find(home.begin(), home.end(), u) == home.end();
      }
  EXPECT_EQ(off, 0) << what << ": vertices not where their input location says";
  EXPECT_EQ(outside, 0) << what << ": vertices outside their triangle's input triangle";
}

struct StraightenResult
{
  NetStraightenerReport report;
  PatchParameterization parameterization;
  double seconds = 0.0;
};

/// Traces, straightens, parameterizes and checks everything the issue asks.
StraightenResult expectStraightened(const TriangleMesh& surface, const LandmarkList& landmarks,
  const BaseDomain& domain, const std::string& what)
{
  StraightenResult result;
  TracedNet traced;
  const Status traceStatus = traceFeatureNet(surface, landmarks, domain, traced);
  EXPECT_TRUE(traceStatus.ok()) << what << ": " << traceStatus.message();
  if (!traceStatus.ok())
    return result;
  StraightenedNet straight;
  const auto start = std::chrono::steady_clock::now();
  StraightenOptions options;
  options.freeCurves = false; // this file checks the straightening itself
  StraightenReport report;
  const Status status = straighten(traced, domain, straight, result.parameterization, options, &report);
  result.report = report.net;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(status.ok()) << what << ": " << status.message();
  if (!status.ok())
    return result;
  const LabelledSurface labelled = toLabelledSurface(straight.net, domain);
  for (const std::string& problem : validateLayout(labelled, toBaseTriangles(domain)))
    ADD_FAILURE() << what << ": " << problem;
  EXPECT_NEAR(totalArea(labelled), surfaceArea(surface), 1e-9 * surfaceArea(surface)) << what;
  expectOnInputSurface(traced, straight, what);
  EXPECT_EQ(result.parameterization.flippedTriangles, 0) << what;
  // Every corner's coordinates can be read in the patch of every triangle
  // using it: vertices on curves lie on the shared base edge.
  int inconsistent = 0;
  for (int t = 0; t < straight.net.mesh.triangleCount(); ++t)
    for (int v : straight.net.mesh.triangle(t))
    {
      std::array<double, 3> inPatch;
      inconsistent += !coordinatesInTriangle(domain, result.parameterization.baseTriangle[v],
        result.parameterization.baseCoordinates[v], straight.net.patchOfTriangle[t], inPatch);
    }
  EXPECT_EQ(inconsistent, 0) << what;
  EXPECT_LE(result.report.netLengthAfter, 1.02 * result.report.netLengthBefore) << what;
  EXPECT_LT(result.report.areaVariationAfter, result.report.areaVariationBefore) << what;
  EXPECT_EQ(result.report.skippedStars, 0) << what;
  return result;
}

} // namespace

TEST(NetStraightener, OctahedronLayoutOnABumpySphere)
{
  const TriangleMesh mesh = test::bumpySphere(4);
  const TriangleMesh o = test::octahedron();
  BaseDomain domain{ o, { 0, 1, 2, 3, 4, 5 } };
  LandmarkList landmarks;
  // Turned so that no curve can follow the sphere's great-circle edges.
  const Eigen::Matrix3d turn =
    (Eigen::AngleAxisd(0.4, Vec3::UnitZ()) * Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized())).toRotationMatrix();
  for (const Vec3& axis : o.points)
    landmarks.push_back(test::nearestVertex(mesh, turn * axis));
  const StraightenResult result = expectStraightened(mesh, landmarks, domain, "bumpy sphere");
  EXPECT_GE(result.report.sweeps, 1);
  std::cout << "bumpy sphere: length " << result.report.netLengthBefore << " -> " << result.report.netLengthAfter
            << ", area variation " << result.report.areaVariationBefore << " -> "
            << result.report.areaVariationAfter << ", sweeps " << result.report.sweeps << "\n";
}

TEST(NetStraightener, EveryRealModelWithL0From381)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::vector<test::LandmarkedModel> models = test::landmarkedRealModels();
  ASSERT_GE(models.size(), 11u);
  const auto source =
    std::find_if(models.begin(), models.end(), [](const test::LandmarkedModel& m) { return m.name == "381"; });
  ASSERT_NE(source, models.end());
  BaseDomain domain;
  ASSERT_TRUE(buildBaseDomain(source->data.mesh, source->landmarks, domain).ok());

  for (const auto& [name, data, landmarks] : models)
  {
    const StraightenResult r = expectStraightened(data.mesh, landmarks, domain, name);
    const double root = std::sqrt(surfaceArea(data.mesh));
    std::cout << name << ": length/sqrt(area) " << r.report.netLengthBefore / root << " -> "
              << r.report.netLengthAfter / root << ", area variation " << r.report.areaVariationBefore << " -> "
              << r.report.areaVariationAfter << ", sweeps " << r.report.sweeps << ", removed "
              << r.report.removedVertices << ", smallest area ratio " << r.parameterization.smallestAreaRatio
              << ", " << r.seconds << " s\n";
  }
}


TEST(NetStraightener, RebuildsTheNetFromPatchIdsAndRefusesBadInput)
{
  const TriangleMesh mesh = test::sphere(3);
  const TriangleMesh o = test::octahedron();
  BaseDomain domain{ o, { 0, 1, 2, 3, 4, 5 } };
  LandmarkList landmarks;
  for (const Vec3& d : o.points)
    landmarks.push_back(test::nearestVertex(mesh, d));
  TracedNet traced;
  ASSERT_TRUE(traceFeatureNet(mesh, landmarks, domain, traced).ok());
  const TriangleMesh refined = traced.mesh.toTriangleMesh();

  TracedNet rebuilt;
  const Status ok = layoutFromPatchIds(refined, traced.patchOfTriangle, landmarks, domain, rebuilt);
  ASSERT_TRUE(ok.ok()) << ok.message();
  EXPECT_EQ(rebuilt.curves, traced.curves);

  std::vector<int> broken = traced.patchOfTriangle;
  broken[0] = (broken[0] + 1) % domain.mesh.triangleCount();
  EXPECT_FALSE(layoutFromPatchIds(refined, broken, landmarks, domain, rebuilt).ok());
  broken[0] = 99;
  const Status outOfRange = layoutFromPatchIds(refined, broken, landmarks, domain, rebuilt);
  EXPECT_NE(outOfRange.message().find("PatchId 99"), std::string::npos) << outOfRange.message();

  StraightenedNet out;
  NetStraightenerOptions options;
  options.snapTolerance = 0.7;
  EXPECT_NE(straightenNet(traced, domain, out, options).message().find("out of range"), std::string::npos);
  const TriangleMesh t = test::tetrahedron();
  BaseDomain other{ t, { 0, 1, 2, 3 } };
  EXPECT_NE(straightenNet(traced, other, out).message().find("does not belong"), std::string::npos);
  options = {};
  options.maxSweeps = 0; // only the final clean-up: the traced net itself
  NetStraightenerReport report;
  ASSERT_TRUE(straightenNet(traced, domain, out, options, &report).ok());
  EXPECT_EQ(report.sweeps, 0);
  EXPECT_NEAR(report.netLengthAfter, report.netLengthBefore, 1e-12 * report.netLengthBefore);
}

TEST(NetStraightener, KeptFeaturesKeepTheCurvesBetweenThemAndRefuseUnknownFeatures)
{
  // The bumpy sphere's octahedron layout with the face (0, 2, 4) kept: the
  // stars of its landmarks are not straightened, so its three curves are
  // the traced ones, vertex for vertex, while the other curves move.
  const TriangleMesh mesh = test::bumpySphere(4);
  const TriangleMesh o = test::octahedron();
  BaseDomain domain{ o, { 0, 1, 2, 3, 4, 5 } };
  LandmarkList landmarks;
  const Eigen::Matrix3d turn =
    (Eigen::AngleAxisd(0.4, Vec3::UnitZ()) * Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized())).toRotationMatrix();
  for (const Vec3& axis : o.points)
    landmarks.push_back(test::nearestVertex(mesh, turn * axis));
  TracedNet traced;
  ASSERT_TRUE(traceFeatureNet(mesh, landmarks, domain, traced).ok());

  // A straightened curve as the traced vertices it runs through (-1 for a
  // vertex the straightening made) and as points.
  const auto asTraced = [](const StraightenedNet& s, const std::vector<int>& curve)
  {
    std::vector<int> vertices;
    for (int v : curve)
      vertices.push_back(s.inputPoint[v].supportSize() == 1 ? s.inputPoint[v].vertex[0] : -1);
    return vertices;
  };
  const auto points = [](const EditableMesh& m, const std::vector<int>& curve)
  {
    std::vector<Vec3> p;
    for (int v : curve)
      p.push_back(m.point(v));
    return p;
  };
  const std::vector<int> kept{ 0, 2, 4 };
  const auto isKept = [&](int bv) { return std::find(kept.begin(), kept.end(), bv) != kept.end(); };

  NetStraightenerOptions options;
  StraightenedNet unkept;
  ASSERT_TRUE(straightenNet(traced, domain, unkept, options).ok());
  options.keptFeatures = kept;
  StraightenedNet straight;
  NetStraightenerReport report;
  const Status status = straightenNet(traced, domain, straight, options, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_GE(report.sweeps, 1);
  EXPECT_EQ(report.skippedStars, 0);
  for (const std::string& problem :
    validateLayout(toLabelledSurface(straight.net, domain), toBaseTriangles(domain)))
    ADD_FAILURE() << problem;
  expectOnInputSurface(traced, straight, "kept features");

  int keptCurves = 0, freedKeptCurves = 0, movedOthers = 0;
  for (std::size_t e = 0; e < traced.curves.size(); ++e)
  {
    const int a = traced.baseEdges[e][0], b = traced.baseEdges[e][1];
    ASSERT_EQ(straight.net.baseEdges[e], traced.baseEdges[e]);
    if (isKept(a) && isKept(b))
    {
      ++keptCurves;
      EXPECT_EQ(asTraced(straight, straight.net.curves[e]), traced.curves[e]) << "curve " << a << "-" << b;
      EXPECT_EQ(points(straight.net.mesh, straight.net.curves[e]), points(traced.mesh, traced.curves[e]))
        << "curve " << a << "-" << b;
      freedKeptCurves += asTraced(unkept, unkept.net.curves[e]) != traced.curves[e] ? 1 : 0;
    }
    else if (!isKept(a) && !isKept(b))
      movedOthers += asTraced(straight, straight.net.curves[e]) != traced.curves[e] ? 1 : 0;
  }
  EXPECT_EQ(keptCurves, 3);
  EXPECT_GT(freedKeptCurves, 0); // without keptFeatures they would move
  EXPECT_GT(movedOthers, 0);     // the other stars are still straightened

  for (int bad : { 6, -1 })
  {
    options.keptFeatures = { 0, bad };
    const Status refused = straightenNet(traced, domain, straight, options);
    EXPECT_NE(refused.message().find("keptFeatures names feature " + std::to_string(bad)), std::string::npos)
      << refused.message();
  }
}
