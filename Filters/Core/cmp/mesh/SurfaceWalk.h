#pragma once
/// \file SurfaceWalk.h
/// \brief Points of a triangle surface and straight walks along it, for
///        moving a sample without leaving the surface.

#include <cmp/mesh/EditableMesh.h>
#include <cmp/mesh/SurfacePoint.h>

#include <Eigen/Core>

namespace cmp
{

/// \brief The position of `p`.
/// \pre `p.triangle` is a triangle of `surface` and `p.weight` its
///      barycentric coordinates there (`SurfacePoint::inTriangle`).
Vec3 surfacePosition(const EditableMesh& surface, const SurfacePoint& p);

/// \brief Unit normal of surface triangle `t`; zero for a degenerate one.
Vec3 surfaceTriangleNormal(const EditableMesh& surface, int t);

/// \brief Moves `p` by `step` along the surface: straight within a
///        triangle (the step projected into its plane), and across an edge
///        the rest of the step is turned about that edge into the next
///        triangle's plane, as if the two were unfolded flat. So the result
///        lies on the surface about |step| from `p`, on the side `step`
///        points to. Stops early at a degenerate triangle or after 2000
///        crossings (a step circling a degenerate spot).
/// \pre `p` as for `surfacePosition()`; so is the result.
SurfacePoint walkOnSurface(const EditableMesh& surface, SurfacePoint p, Vec3 step);

} // namespace cmp
