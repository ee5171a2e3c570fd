#include <cmp/mesh/Subdivision.h>
#include <cmp/mesh/SurfaceCheck.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

using namespace cmp;

TEST(Subdivision, QuadruplesTrianglesKeepsOriginalVerticesAndArea)
{
  const TriangleMesh base = test::octahedron();
  const TriangleMesh fine = subdivideMidpoint(base, 3);
  EXPECT_EQ(fine.triangleCount(), 8 * 64);
  EXPECT_EQ(fine.vertexCount(), 2 + 4 * 64); // Euler: V = F/2 + 2
  for (int v = 0; v < base.vertexCount(); ++v)
    EXPECT_EQ(fine.points[v], base.points[v]);
  EXPECT_NEAR(surfaceArea(fine), surfaceArea(base), 1e-12);
  EXPECT_TRUE(checkSurface(fine).ok());
}
