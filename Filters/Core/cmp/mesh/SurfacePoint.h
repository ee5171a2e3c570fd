#pragma once
/// \file SurfacePoint.h
/// \brief The core's one type for a point on a triangle of a mesh: of an
///        input surface, of a straightened surface, or of the base domain
///        `L0` (where it is a place in the base domain).

#include <cmp/mesh/TriangleMesh.h>

#include <array>

namespace cmp
{

/// \brief A point of a triangle mesh as a convex combination of at most
///        three of its vertices, with the triangle that holds it.
///
/// `weight[k]` is the weight of `vertex[k]`, and the weights sum to 1.
/// Unused slots have vertex -1 and weight 0. One vertex: that vertex; two:
/// a point of their edge; three: a point of their triangle (a point made by
/// `inTriangle()` keeps all three corners, some perhaps with weight 0).
///
/// `triangle` is a triangle of the mesh holding the point, or -1 where no
/// triangle is recorded (a landmark vertex of a remesh sample; the
/// straightener's points, whose triangles are split as it cuts the
/// surface). When `triangle` is set by `inTriangle()` the three vertices
/// are that triangle's corners in its order, so `weight` is the point's
/// barycentric coordinates in that triangle (a place in the base domain is
/// always so).
struct SurfacePoint
{
  std::array<int, 3> vertex{ { -1, -1, -1 } };       ///< Mesh vertices.
  std::array<double, 3> weight{ { 0.0, 0.0, 0.0 } }; ///< Their weights, summing to 1.
  int triangle = -1;                                 ///< A triangle holding the point, or -1.

  /// \brief The vertex `v` itself (no triangle recorded).
  static SurfacePoint at(int v)
  {
    SurfacePoint p;
    p.vertex[0] = v;
    p.weight[0] = 1.0;
    return p;
  }

  /// \brief The point of `mesh`'s triangle `t` with barycentric coordinates
  ///        `coordinates` in the order of its corners.
  /// \pre 0 <= t < mesh.triangleCount().
  static SurfacePoint inTriangle(const TriangleMesh& mesh, int t, const std::array<double, 3>& coordinates)
  {
    SurfacePoint p;
    p.triangle = t;
    p.vertex = mesh.triangles[t];
    p.weight = coordinates;
    return p;
  }

  /// \brief Number of slots in use (vertex not -1).
  int supportSize() const { return (vertex[0] >= 0) + (vertex[1] >= 0) + (vertex[2] >= 0); }
};

} // namespace cmp
