#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/io/MeshFile.h>
#include "TestMeshes.h"
#include "TestShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

using namespace cmp;
using cmp::test::octahedron;

namespace
{

SurfaceCheckResult expectDefect(const TriangleMesh& mesh, SurfaceDefect defect, const std::string& fragment)
{
  const SurfaceCheckResult result = checkSurface(mesh);
  EXPECT_EQ(defectName(result.defect), std::string(defectName(defect))) << result.message;
  EXPECT_NE(result.message.find(fragment), std::string::npos) << "message: " << result.message;
  return result;
}

} // namespace

TEST(SurfaceCheck, AcceptsClosedGenusZeroSurfaces)
{
  EXPECT_TRUE(checkSurface(octahedron()).ok());
  EXPECT_TRUE(checkSurface(test::tetrahedron()).ok());
  EXPECT_TRUE(checkSurface(test::sphere(4)).ok());
}

TEST(SurfaceCheck, RejectsEmpty)
{
  expectDefect(TriangleMesh{}, SurfaceDefect::Empty, "empty surface: 0 points and 0 triangles");
}

TEST(SurfaceCheck, RejectsNaNCoordinates)
{
  TriangleMesh mesh = octahedron();
  mesh.points[3].y() = std::nan("");
  expectDefect(mesh, SurfaceDefect::NonFiniteCoordinate, "point 3 has a NaN");
}

TEST(SurfaceCheck, RejectsBadIndicesAndRepeatedVertices)
{
  TriangleMesh mesh = octahedron();
  mesh.triangles[2][1] = 17;
  expectDefect(mesh, SurfaceDefect::IndexOutOfRange, "triangle 2 refers to point 17");
  mesh = octahedron();
  mesh.triangles[5] = { 1, 1, 5 };
  expectDefect(mesh, SurfaceDefect::RepeatedVertex, "triangle 5 uses a point twice");
}

TEST(SurfaceCheck, RejectsDegenerateTriangles)
{
  TriangleMesh mesh = octahedron();
  mesh.points[4] = 0.5 * (mesh.points[0] + mesh.points[2]); // triangle (0, 2, 4) becomes a segment
  expectDefect(mesh, SurfaceDefect::DegenerateTriangle, "e.g. triangle 0");
}

TEST(SurfaceCheck, RejectsUnusedPoints)
{
  TriangleMesh mesh = octahedron();
  mesh.points.emplace_back(3, 3, 3);
  expectDefect(mesh, SurfaceDefect::UnusedVertex, "1 points belong to no triangle, e.g. point 6");
}

TEST(SurfaceCheck, RejectsOpenSurfaceNamingABoundaryEdge)
{
  TriangleMesh mesh = octahedron();
  mesh.triangles.pop_back(); // removes (0, 3, 5)
  expectDefect(mesh, SurfaceDefect::BoundaryEdge, "open surface: 3 boundary edges");
}

TEST(SurfaceCheck, RejectsNonManifoldEdge)
{
  // Two tetrahedra glued along edge (0, 1): that edge has four triangles.
  TriangleMesh mesh = test::tetrahedron();
  mesh.points.emplace_back(0, -1, 0);
  mesh.points.emplace_back(0, 0, -1);
  const TriangleMesh other = [] {
    TriangleMesh t;
    t.triangles = { { 0, 4, 1 }, { 0, 1, 5 }, { 0, 5, 4 }, { 1, 4, 5 } };
    return t;
  }();
  for (const Triangle& tri : other.triangles)
    mesh.triangles.push_back(tri);
  expectDefect(mesh, SurfaceDefect::NonManifoldEdge, "edge (0, 1) shared by 4 triangles");
}

TEST(SurfaceCheck, RejectsInconsistentOrientation)
{
  TriangleMesh mesh = octahedron();
  std::swap(mesh.triangles[3][0], mesh.triangles[3][1]);
  expectDefect(mesh, SurfaceDefect::InconsistentOrientation, "inconsistent orientation: 3 edges");
}

// Issue 26: a fin, a triangle hung on an edge of a closed surface, was
// reported only as "open surface" by the boundary edges it leaves.
TEST(SurfaceCheck, ReportsAFinAsANonManifoldEdge)
{
  TriangleMesh mesh = octahedron();
  mesh.points.emplace_back(2, 2, 0);
  mesh.triangles.push_back({ 0, 2, 6 }); // edge (0, 2) now has three triangles
  expectDefect(mesh, SurfaceDefect::NonManifoldEdge,
    "1 non-manifold edges, e.g. edge (0, 2) shared by 3 triangles (and 2 boundary edges, e.g. edge");
}

TEST(SurfaceCheck, RejectsNonManifoldVertex)
{
  // Two tetrahedra touching at one vertex (a bow tie).
  TriangleMesh mesh = test::tetrahedron();
  TriangleMesh second = test::tetrahedron(Vec3(-1, -1, -1));
  for (Triangle tri : second.triangles)
  {
    for (int& v : tri)
      v = v == 3 ? 0 : v + 4; // second's apex (-1,-1,0) is replaced by the shared vertex 0
    mesh.triangles.push_back(tri);
  }
  for (int v = 0; v < 3; ++v)
    mesh.points.push_back(second.points[v]);
  expectDefect(mesh, SurfaceDefect::NonManifoldVertex, "non-manifold vertices");
}

TEST(SurfaceCheck, RejectsTwoComponents)
{
  const TriangleMesh mesh = test::disjointUnion(octahedron(), test::tetrahedron(Vec3(5, 0, 0)));
  expectDefect(mesh, SurfaceDefect::SeveralComponents, "2 connected components (triangles per component: 8, 4)");
}

TEST(SurfaceCheck, RejectsGenusOne)
{
  expectDefect(test::torus(12, 8), SurfaceDefect::WrongGenus, "genus 1 (Euler characteristic 0)");
}

TEST(SurfaceCheck, TopologyOnlyIgnoresGeometry)
{
  TriangleMesh mesh = octahedron();
  mesh.points[2] = mesh.points[0]; // triangle (0, 2, 4) collapses to a segment
  SurfaceCheckOptions options;
  options.checkGeometry = false;
  EXPECT_TRUE(checkSurface(mesh, options).ok());
  EXPECT_FALSE(checkSurface(mesh).ok());
}

TEST(SurfaceCheck, CornerTableWalksAroundVertices)
{
  const TriangleMesh mesh = test::sphere(2);
  CornerTable table;
  ASSERT_TRUE(table.build(mesh));
  for (int h = 0; h < table.halfedgeCount(); ++h)
  {
    EXPECT_EQ(table.opposite(table.opposite(h)), h);
    EXPECT_EQ(table.from(table.opposite(h)), table.to(h));
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const int start = table.outgoing(v);
    int h = start, steps = 0;
    do
    {
      EXPECT_EQ(table.from(h), v);
      h = table.nextAroundVertex(h);
      ++steps;
    } while (h != start && steps < 100);
    EXPECT_TRUE(steps == 4 || steps == 6) << "vertex " << v;
  }
}

TEST(SurfaceCheck, RealModelsPass)
{
  CMP_REQUIRE_SHARED_DATA();
  std::vector<std::string> models = test::landmarkedFourLeggedModels();
  ASSERT_GE(models.size(), 10u);
  models.push_back(test::sharedDataDir() + "/shrec07-fourleg/386");
  models.push_back(test::sharedDataDir() + "/shrec07-fourleg/390");
  for (const std::string& model : models)
  {
    MeshFileData data;
    ASSERT_TRUE(readOFF(model + ".off", data).ok()) << model;
    weldIdenticalPoints(data);
    const SurfaceCheckResult result = checkSurface(data.mesh);
    EXPECT_TRUE(result.ok()) << model << ": " << result.message;
  }
  MeshFileData spot;
  ASSERT_TRUE(readOBJ(test::sharedDataDir() + "/spot/spot.obj", spot).ok());
  weldIdenticalPoints(spot);
  EXPECT_TRUE(checkSurface(spot.mesh).ok()) << checkSurface(spot.mesh).message;
}

TEST(SurfaceCheck, HalfedgesByEdgeSortsAsAFullSortDoes)
{
  // A torus with its vertices shuffled, and a triangle hung on one of its
  // edges (three halfedges on one edge), against a plain sort by
  // (smaller vertex, larger vertex, halfedge).
  TriangleMesh mesh = test::torus(7, 5);
  std::vector<int> relabel(mesh.vertexCount());
  std::iota(relabel.begin(), relabel.end(), 0);
  std::shuffle(relabel.begin(), relabel.end(), std::mt19937(3));
  for (Triangle& tri : mesh.triangles)
    for (int& v : tri)
      v = relabel[v];
  mesh.points.push_back(Vec3(9, 9, 9));
  mesh.triangles.push_back({ mesh.triangles[4][0], mesh.triangles[4][1], mesh.vertexCount() - 1 });

  std::vector<std::array<int, 3>> expected;
  for (int h = 0; h < 3 * mesh.triangleCount(); ++h)
  {
    const int a = mesh.triangles[h / 3][h % 3], b = mesh.triangles[h / 3][(h % 3 + 1) % 3];
    expected.push_back({ std::min(a, b), std::max(a, b), h });
  }
  std::sort(expected.begin(), expected.end());
  const std::vector<int> order = halfedgesByEdge(mesh);
  ASSERT_EQ(order.size(), expected.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    EXPECT_EQ(order[i], expected[i][2]) << "position " << i;
}
