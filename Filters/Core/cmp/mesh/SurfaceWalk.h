#pragma once
/// \file SurfaceWalk.h
/// \brief Points of a triangle surface and straight walks along it, for
///        moving a sample without leaving the surface.

#include <cmp/mesh/EditableMesh.h>

#include <Eigen/Core>

namespace cmp
{

/// \brief A point of a surface given by the triangle holding it and its
///        barycentric coordinates in the order of that triangle's vertices
///        (unlike the straightener's `SurfacePoint`, always three).
struct TrianglePoint
{
  int triangle = -1;                                     ///< Surface triangle.
  Eigen::Vector3d coordinates = Eigen::Vector3d::Zero(); ///< Barycentric coordinates (sum 1).
};

/// \brief The position of `p`.
Vec3 surfacePosition(const EditableMesh& surface, const TrianglePoint& p);

/// \brief Unit normal of surface triangle `t`; zero for a degenerate one.
Vec3 surfaceTriangleNormal(const EditableMesh& surface, int t);

/// \brief Moves `p` by `step` along the surface: straight within a
///        triangle (the step projected into its plane), and across an edge
///        the rest of the step is turned about that edge into the next
///        triangle's plane, as if the two were unfolded flat. So the result
///        lies on the surface about |step| from `p`, on the side `step`
///        points to. Stops early at a degenerate triangle or after 2000
///        crossings (a step circling a degenerate spot).
TrianglePoint walkOnSurface(const EditableMesh& surface, TrianglePoint p, Vec3 step);

} // namespace cmp
