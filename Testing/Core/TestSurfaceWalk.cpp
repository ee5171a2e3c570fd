#include <cmp/mesh/SurfaceWalk.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace cmp;

namespace
{

SurfacePoint centroidOf(const EditableMesh& mesh, int triangle)
{
  SurfacePoint p;
  p.triangle = triangle;
  p.vertex = mesh.triangle(triangle);
  p.weight = { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 };
  return p;
}

double weightSum(const SurfacePoint& p)
{
  return p.weight[0] + p.weight[1] + p.weight[2];
}

} // namespace

TEST(SurfaceWalk, StepsStraightWithinATriangleAndUnfoldsAcrossAnEdge)
{
  EditableMesh octahedron;
  ASSERT_TRUE(octahedron.build(test::octahedron()).ok());
  // Face 0 is (+x, +y, +z); face 4, (+y, +x, -z), lies across its edge +x +y.
  const SurfacePoint start = centroidOf(octahedron, 0);
  const Vec3 centre = surfacePosition(octahedron, start);
  const Vec3 edgeMiddle(0.5, 0.5, 0.0);

  // A short step stays in the face, exactly where it points (after
  // projection into the face's plane).
  const Vec3 inPlane = 0.1 * (edgeMiddle - centre).normalized();
  const SurfacePoint near = walkOnSurface(octahedron, start, inPlane + 0.05 * surfaceTriangleNormal(octahedron, 0));
  EXPECT_EQ(near.triangle, 0);
  EXPECT_NEAR((surfacePosition(octahedron, near) - (centre + inPlane)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(weightSum(near), 1.0, 1e-12);

  // Towards the middle of edge +x +y and past it: the rest of the step
  // goes on into face 4 as if the two faces were unfolded flat, so it ends
  // on the line from that middle to face 4's centre.
  const double toEdge = (edgeMiddle - centre).norm(), length = toEdge + 0.2;
  const SurfacePoint beyond = walkOnSurface(octahedron, start, length * (edgeMiddle - centre).normalized());
  EXPECT_EQ(beyond.triangle, 4);
  EXPECT_GE(*std::min_element(beyond.weight.begin(), beyond.weight.end()), 0.0);
  EXPECT_EQ(beyond.vertex, octahedron.triangle(4)); // weights in the order of its corners
  const Vec3 otherCentre = surfacePosition(octahedron, centroidOf(octahedron, 4));
  const Vec3 expected = edgeMiddle + 0.2 * (otherCentre - edgeMiddle).normalized();
  EXPECT_NEAR((surfacePosition(octahedron, beyond) - expected).norm(), 0.0, 1e-12);

  // A zero step stays put; a step around the octahedron's equator keeps
  // the point on the surface (|x| + |y| + |z| = 1).
  EXPECT_EQ(walkOnSurface(octahedron, start, Vec3::Zero()).weight, start.weight);
  const SurfacePoint far = walkOnSurface(octahedron, start, Vec3(3.0, -1.0, 0.5));
  const Vec3 p = surfacePosition(octahedron, far);
  EXPECT_NEAR(p.cwiseAbs().sum(), 1.0, 1e-12);
}
