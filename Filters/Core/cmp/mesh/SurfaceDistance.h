#pragma once
/// \file SurfaceDistance.h
/// \brief How far apart two surfaces are: exact closest-point queries on a
///        triangle mesh and the sampled Hausdorff and mean distances built on
///        them, to measure how faithfully a remesh follows its input.

#include <cmp/mesh/SurfacePoint.h>
#include <cmp/mesh/TriangleMesh.h>

#include <algorithm>
#include <array>
#include <vector>

namespace cmp
{

/// \brief Closest-point queries on a triangle mesh through an axis-aligned bounding-box tree.
///
/// Degenerate (zero-area) triangles are treated as the segments they
/// collapse to, so they never produce NaN. Coordinates must be finite (as
/// `checkSurface()` ensures). A mesh without triangles answers every query
/// with triangle -1 and an infinite distance.
class ClosestPointQuery
{
public:
  /// \brief The closest point of the mesh to a query point.
  struct Result
  {
    /// \brief The closest point on the mesh: its triangle (-1 for a mesh
    ///        without triangles) and its barycentric coordinates there.
    SurfacePoint at;
    Vec3 point = Vec3::Zero(); ///< Its position.
    double distance = 0.0;     ///< Its distance to the query point.
  };

  /// \brief Builds the tree (O(n log n)) over copies of the mesh's
  ///        corners and triangles, so the mesh need not outlive the query.
  explicit ClosestPointQuery(const TriangleMesh& mesh);

  /// \brief The closest point to `p` (exact point-triangle distance, branch and bound).
  Result closest(const Vec3& p) const;

private:
  /// \brief A box of the tree: a leaf holds `order_[begin, end)`, an inner
  ///        node has its two children at `left` and `left + 1`.
  struct Node
  {
    Vec3 lo, hi;
    int begin = 0, end = 0;
    int left = -1;
  };

  /// \brief Fills `node` with the triangles `order_[begin, end)` and splits
  ///        it at the median centroid along its longest axis.
  void build(const TriangleMesh& mesh, int node, int begin, int end, const std::vector<Vec3>& centroids);
  /// \brief Squared distance from `p` to the box of `node` (0 inside).
  static double boxDistanceSquared(const Node& node, const Vec3& p);
  /// \brief Replaces `best` by a closer point of a triangle of the leaf `node`.
  void testLeaf(const Node& node, const Vec3& p, Result& best, double& bestSquared) const;

  std::vector<Triangle> triangles_; ///< The mesh's triangles (a result's corners), so the query keeps no reference.
  std::vector<Node> nodes_;
  std::vector<int> order_; ///< Triangle ids, grouped by leaf.
  /// \brief Corners of `order_[i]`, copied next to each other so a leaf's
  ///        triangles are read from one place instead of three indirections.
  std::vector<std::array<Vec3, 3>> corners_;
  std::vector<char> flat_; ///< Whether `order_[i]` is too thin to have a normal.
};

/// \brief Sampled one- and two-sided distances between two surfaces.
struct SurfaceDistance
{
  double aToB = 0.0;     ///< max over samples of a of the distance to b.
  double bToA = 0.0;     ///< max over samples of b of the distance to a.
  double meanAToB = 0.0; ///< area-weighted mean distance of a's samples to b.
  double meanBToA = 0.0; ///< same from b to a.
  Vec3 farthestOfA = Vec3::Zero(); ///< A sample of a at distance aToB from b.
  Vec3 farthestOfB = Vec3::Zero(); ///< A sample of b at distance bToA from a.

  /// \brief The two-sided Hausdorff distance, max(aToB, bToA).
  double hausdorff() const { return std::max(aToB, bToA); }
  /// \brief Whether the Hausdorff distance is reached at a sample of a
  ///        (a part of a that b misses), rather than of b.
  bool reachedOnA() const { return aToB >= bToA; }
  /// \brief Where the Hausdorff distance is reached: `farthestOfA` or
  ///        `farthestOfB` (see `reachedOnA()`).
  Vec3 farthestPoint() const { return reachedOnA() ? farthestOfA : farthestOfB; }
};

/// \brief Distances between surfaces `a` and `b`, sampling each triangle at the
///        points of its barycentric grid with `subdivisions` steps per edge
///        (vertices, edge points and interior points; 1 = the vertices only).
///
/// Each vertex and each edge point is measured once however many triangles
/// share it. A triangle's samples count equally towards its share of the
/// mean, which is weighted by triangle area (plain mean over triangles if
/// the total area is zero). `subdivisions` below 1 counts as 1. Distances to
/// a mesh without triangles are infinite.
SurfaceDistance surfaceDistance(const TriangleMesh& a, const TriangleMesh& b, int subdivisions = 3);

/// \brief `surfaceDistance(a, b, subdivisions)` and, in the same sampling,
///        `farOfB` = `trianglesFartherThan(a, b, limit, subdivisions)`: the
///        triangles of `b` where `b` misses `a` by more than `limit` (each
///        sample is measured once, where the two calls would measure the
///        two meshes twice; an edge's points are computed along the edge, so
///        a sample within rounding of `limit` may come out on the other side).
/// \pre Finite coordinates (`checkSurface()`).
SurfaceDistance surfaceDistance(
  const TriangleMesh& a, const TriangleMesh& b, int subdivisions, double limit, std::vector<char>* farOfB);

/// \brief Where `remesh` misses `surface` by more than `limit`: per triangle
///        of `remesh`, 1 if a sample of it lies farther than `limit` from
///        `surface`, or if it is the triangle of `remesh` nearest to a
///        sample of `surface` that lies farther than `limit` from `remesh`.
///        Both are sampled as `surfaceDistance()` does, with `subdivisions`
///        steps per edge; so the marked triangles are those a two-sided
///        distance above `limit` is measured at.
/// \pre Finite coordinates (`checkSurface()`).
std::vector<char> trianglesFartherThan(
  const TriangleMesh& surface, const TriangleMesh& remesh, double limit, int subdivisions = 3);

// `boundingBoxDiagonal(const TriangleMesh&)`, the usual scale for these
// distances, is declared in TriangleMesh.h.

} // namespace cmp
