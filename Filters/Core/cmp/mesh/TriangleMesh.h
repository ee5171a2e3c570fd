#pragma once
/// \file TriangleMesh.h
/// \brief The core's triangle mesh: an indexed face set plus a corner-table
///        topology for closed, oriented manifolds.

#include <Eigen/Core>

#include <array>
#include <vector>

namespace cmp
{

/// \brief pi, for every angle the core computes (`M_PI` is not standard C++).
constexpr double kPi = 3.14159265358979323846;

/// \brief A 3D point or vector.
using Vec3 = Eigen::Vector3d;

/// \brief A point or vector of a parameter plane.
using Vec2 = Eigen::Vector2d;

/// \brief The z component of the cross product of two plane vectors: twice
///        the signed area of the triangle they span (positive when `b` lies
///        counter-clockwise of `a`).
inline double cross2(const Vec2& a, const Vec2& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

/// \brief Three vertex indices, counter-clockwise seen from outside.
using Triangle = std::array<int, 3>;

/// \brief An indexed triangle mesh: positions and triangles, nothing else.
///
/// This is what the VTK adapters fill from `vtkPolyData` and what every core
/// algorithm takes. It makes no promise about topology; run
/// `checkSurface()` before relying on any.
struct TriangleMesh
{
  std::vector<Vec3> points;        ///< Vertex positions.
  std::vector<Triangle> triangles; ///< Vertex indices per triangle.

  /// \brief Number of vertices.
  int vertexCount() const { return static_cast<int>(points.size()); }
  /// \brief Number of triangles.
  int triangleCount() const { return static_cast<int>(triangles.size()); }
};

/// \brief Length of the diagonal of the axis-aligned bounding box of
///        `points` (0 if empty).
double boundingBoxDiagonal(const std::vector<Vec3>& points);

/// \brief Length of the diagonal of the axis-aligned bounding box (0 if empty).
double boundingBoxDiagonal(const TriangleMesh& mesh);

/// \brief Area of triangle `t`.
double triangleArea(const TriangleMesh& mesh, int t);

/// \brief Total surface area.
double surfaceArea(const TriangleMesh& mesh);

/// \brief The halfedges `h = 3 t + k` (from `triangles[t][k]` to
///        `triangles[t][(k+1)%3]`) ordered by their undirected edge (its
///        smaller vertex, then its larger one), then by h, so that the sides
///        of each edge are next to each other.
///
/// A counting sort by the smaller vertex, then each vertex's halfedges sorted
/// by the larger one: linear time on meshes of bounded valence.
/// \pre Every triangle indexes vertices of `mesh`.
std::vector<int> halfedgesByEdge(const TriangleMesh& mesh);

/// \brief Corner-table topology of a closed, edge-manifold, oriented mesh.
///
/// Halfedge `h = 3 t + k` runs from `triangles[t][k]` to
/// `triangles[t][(k+1)%3]`. `opposite(h)` is the halfedge of the neighbouring
/// triangle running the other way. Construction sorts the halfedges by edge
/// (`halfedgesByEdge()`) and needs no hash map. Only valid for meshes that
/// passed the edge checks of `checkSurface()`; `build()` reports failure
/// otherwise.
class CornerTable
{
public:
  /// \brief Builds the table; returns false if some edge does not have exactly
  ///        two oppositely oriented halfedges.
  bool build(const TriangleMesh& mesh);
  /// \brief The same with the halfedges already ordered by edge (`order`,
  ///        `halfedgesByEdge(mesh)`), so that a caller that needed the order
  ///        too sorts once; false as above, or when `order` does not have one
  ///        entry per halfedge. \pre `order` is `halfedgesByEdge(mesh)`.
  bool build(const TriangleMesh& mesh, const std::vector<int>& order);

  /// \brief Halfedge running the other way across the same edge.
  int opposite(int h) const { return opposite_[h]; }
  /// \brief Next halfedge in the same triangle.
  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  /// \brief Previous halfedge in the same triangle.
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  /// \brief Triangle holding halfedge `h`.
  static int triangleOf(int h) { return h / 3; }
  /// \brief Vertex halfedge `h` starts from.
  int from(int h) const { return (*triangles_)[h / 3][h % 3]; }
  /// \brief Vertex halfedge `h` points to.
  int to(int h) const { return from(next(h)); }
  /// \brief One halfedge leaving vertex `v` (-1 for an unused vertex).
  int outgoing(int v) const { return outgoing_[v]; }
  /// \brief The next halfedge leaving the same vertex, counter-clockwise.
  int nextAroundVertex(int h) const { return opposite_[prev(h)]; }
  /// \brief Number of halfedges (three per triangle).
  int halfedgeCount() const { return static_cast<int>(opposite_.size()); }

private:
  const std::vector<Triangle>* triangles_ = nullptr;
  std::vector<int> opposite_;
  std::vector<int> outgoing_;
};

} // namespace cmp
