#include <cmp/mesh/EdgePaths.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace cmp;

// The octahedron's vertices are +x, -x, +y, -y, +z, -z (0 to 5); its edges
// are sqrt(2) long, and each vertex's opposite is two edges away.
TEST(EdgePaths, DistancesLimitsBlockedVerticesAndPaths)
{
  const TriangleMesh octahedron = test::octahedron();
  const EdgeGraph graph = edgeGraph(octahedron);
  ASSERT_EQ(graph.vertexCount(), 6);
  EXPECT_EQ(graph.to.size(), 24u); // 12 edges, both ways
  const double edge = std::sqrt(2.0);
  const double infinity = std::numeric_limits<double>::infinity();

  std::vector<int> parent;
  const std::vector<double> fromX = edgePathDistances(graph, { 0 }, infinity, &parent);
  EXPECT_EQ(fromX[0], 0.0);
  for (int v : { 2, 3, 4, 5 })
  {
    EXPECT_NEAR(fromX[v], edge, 1e-12) << v;
    EXPECT_EQ(parent[v], 0) << v;
  }
  EXPECT_NEAR(fromX[1], 2.0 * edge, 1e-12);
  const std::vector<int> across = edgePath(parent, fromX, 1);
  ASSERT_EQ(across.size(), 3u);
  EXPECT_EQ(across.front(), 0);
  EXPECT_EQ(across.back(), 1);
  EXPECT_NEAR(fromX[across[1]], edge, 1e-12);
  EXPECT_EQ(edgePath(parent, fromX, 0), std::vector<int>{ 0 });

  // Beyond the limit nothing is reached.
  const std::vector<double> near = edgePathDistances(graph, { 0 }, 2.0);
  EXPECT_NEAR(near[4], edge, 1e-12);
  EXPECT_TRUE(std::isinf(near[1]));

  // Several sources: the nearest counts.
  const std::vector<double> fromBothPoles = edgePathDistances(graph, { 4, 5 });
  EXPECT_NEAR(fromBothPoles[1], edge, 1e-12);
  EXPECT_EQ(fromBothPoles[5], 0.0);

  // Blocked vertices are reached but not passed through; a blocked source
  // still starts the search.
  std::vector<char> blocked(6, 0);
  blocked[2] = blocked[3] = blocked[4] = 1;
  const std::vector<double> roundTheBlock = edgePathDistances(graph, { 0 }, infinity, &parent, &blocked);
  EXPECT_NEAR(roundTheBlock[4], edge, 1e-12);
  EXPECT_NEAR(roundTheBlock[1], 2.0 * edge, 1e-12);
  EXPECT_EQ(edgePath(parent, roundTheBlock, 1), (std::vector<int>{ 0, 5, 1 }));
  blocked[5] = 1;
  const std::vector<double> walledIn = edgePathDistances(graph, { 0 }, infinity, &parent, &blocked);
  EXPECT_TRUE(std::isinf(walledIn[1]));
  EXPECT_TRUE(edgePath(parent, walledIn, 1).empty());
  blocked[0] = 1;
  EXPECT_NEAR(edgePathDistances(graph, { 0 }, infinity, nullptr, &blocked)[5], edge, 1e-12);
}
