#pragma once
/// \file EditableMesh.h
/// \brief A closed triangle mesh (corner table) that supports edge splits
///        and remembers how every new vertex was made.

#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief How a vertex came to be: an input vertex (`a == -1`) or the point
///        at `t` along the edge from `a` to `b` (`(1-t) a + t b`).
struct VertexOrigin
{
  int a = -1;     ///< First end of the split edge, or -1 for an input vertex.
  int b = -1;     ///< Second end of the split edge.
  double t = 0.0; ///< Position along the edge.
};

/// \brief Corner-table mesh of a closed oriented manifold with edge splits.
///
/// Halfedge `h = 3 t + k` runs from corner k to corner k+1 of triangle t.
/// Splitting keeps every existing vertex and triangle index (new ones are
/// appended), so per-vertex data can be extended in creation order using
/// `origin()`. Each halfedge carries an integer tag (default -1) that splits
/// keep on the right halfedge; the tracer stores curve ids there.
class EditableMesh
{
public:
  /// \brief Builds the table from `mesh`.
  /// Fails (Status) when some edge does not have exactly two oppositely
  /// oriented triangles (an open, non-manifold or misoriented surface) or a
  /// point belongs to no triangle.
  Status build(const TriangleMesh& mesh);

  /// \brief Number of vertices.
  int vertexCount() const { return static_cast<int>(points_.size()); }
  /// \brief Number of triangles.
  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  /// \brief Number of halfedges (three per triangle).
  int halfedgeCount() const { return static_cast<int>(opposite_.size()); }
  /// \brief Position of vertex `v`.
  const Vec3& point(int v) const { return points_[v]; }
  /// \brief Positions of all vertices, removed ones included.
  const std::vector<Vec3>& points() const { return points_; }
  /// \brief Vertex indices of triangle `t`.
  const Triangle& triangle(int t) const { return triangles_[t]; }

  /// \brief Next halfedge in the same triangle.
  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  /// \brief Previous halfedge in the same triangle.
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  /// \brief Triangle holding halfedge `h`.
  static int triangleOf(int h) { return h / 3; }
  /// \brief Vertex halfedge `h` starts from.
  int from(int h) const { return triangles_[h / 3][h % 3]; }
  /// \brief Vertex halfedge `h` points to.
  int to(int h) const { return from(next(h)); }
  /// \brief The halfedge running the other way across the same edge.
  int opposite(int h) const { return opposite_[h]; }
  /// \brief One halfedge leaving `v`.
  int outgoing(int v) const { return outgoing_[v]; }
  /// \brief The next halfedge leaving the same vertex, counter-clockwise.
  int nextAroundVertex(int h) const { return opposite_[prev(h)]; }
  /// \brief The halfedge from `a` to `b`, or -1 if they are not adjacent.
  int findHalfedge(int a, int b) const;
  /// \brief Length of the edge of halfedge `h`.
  double length(int h) const { return (points_[to(h)] - points_[from(h)]).norm(); }

  /// \brief Tag of halfedge `h` (-1 unless set).
  int tag(int h) const { return tags_[h]; }
  /// \brief Sets the tag of halfedge `h` only.
  void setTag(int h, int value) { tags_[h] = value; }

  /// \brief How vertex `v` was made.
  const VertexOrigin& origin(int v) const { return origins_[v]; }
  /// \brief The input triangle that triangle `t` is part of (itself for an
  ///        input triangle), so cell data can be carried through splits.
  int inputTriangle(int t) const { return inputTriangle_[t]; }

  /// \brief Inserts a vertex at `t` along the edge of `h` and splits the two
  ///        triangles beside it. Returns the new vertex. Afterwards the
  ///        halfedge `h` runs from its old start to the new vertex. The two
  ///        halves of the edge inherit its tags.
  /// \pre `build()` succeeded and `h` is a halfedge of a triangle not
  ///      removed; the new vertex lies on the edge for `t` in [0, 1].
  int splitEdge(int h, double t = 0.5);

  /// \brief Merges the start of `h` into its end: the two triangles beside
  ///        the edge are removed (`isRemoved()`), the start vertex is left
  ///        unused. Only topology changes; the caller checks the link
  ///        condition and the geometry first. Tags of the surviving edges are
  ///        kept.
  void collapseEdge(int h);
  /// \brief True for a triangle removed by `collapseEdge()`.
  bool isRemoved(int t) const { return triangles_[t][0] < 0; }

  /// \brief The current mesh as an indexed face set (removed triangles are
  ///        left out; use it only on a mesh without collapses to keep
  ///        triangle indices).
  TriangleMesh toTriangleMesh() const;

private:
  void link(int h, int g)
  {
    opposite_[h] = g;
    opposite_[g] = h;
  }

  std::vector<Vec3> points_;
  std::vector<Triangle> triangles_;
  std::vector<int> opposite_;
  std::vector<int> outgoing_;
  std::vector<int> tags_;
  std::vector<VertexOrigin> origins_;
  std::vector<int> inputTriangle_;
};

} // namespace cmp
