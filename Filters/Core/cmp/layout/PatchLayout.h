#pragma once
/// \file PatchLayout.h
/// \brief A net of curves on a surface that lays out the base domain's
///        triangles as patches: what the tracer produces and the
///        straightener and the per-patch parameterization refine.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/mesh/EditableMesh.h>
#include <cmp/io/Landmarks.h>
#include <cmp/layout/LayoutValidator.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <array>
#include <functional>
#include <vector>

namespace cmp
{

/// \brief Edges of the base domain, the triangles beside them and the cyclic
///        (counter-clockwise) order of edges around every base vertex.
struct BaseTopology
{
  std::vector<std::array<int, 2>> edges; ///< Base vertices of each edge.
  std::vector<int> left;                 ///< Base triangle left of each edge's direction.
  std::vector<int> right;                ///< Base triangle right of each edge's direction.
  std::vector<std::vector<int>> rotation; ///< Per base vertex, its edges counter-clockwise.

  /// \brief Fills the tables; `domain` must pass `checkBaseDomain()`.
  void build(const BaseDomain& domain);
  /// \brief The end of `edge` that is not `vertex`.
  int other(int edge, int vertex) const { return edges[edge][0] == vertex ? edges[edge][1] : edges[edge][0]; }
  /// \brief The edge between base vertices `a` and `b`, or -1.
  int edgeBetween(int a, int b) const;
};

/// \brief A patch layout: the surface, refined so that every curve runs
///        along mesh edges, the curves and the patch of every triangle.
struct TracedNet
{
  /// \brief The surface, with edges split where curves needed room.
  ///        Vertices 0..n-1 are the input's; `mesh.origin(v)` tells how later
  ///        ones were made. Curve edges carry their base edge as tag.
  EditableMesh mesh;
  /// \brief The base domain's edges as (base vertex, base vertex), in the
  ///        direction of the base halfedge whose triangle is `leftTriangle`.
  std::vector<std::array<int, 2>> baseEdges;
  /// \brief Base triangle on the left of each base edge's direction.
  std::vector<int> leftTriangle;
  /// \brief Base triangle on the right of each base edge's direction.
  std::vector<int> rightTriangle;
  /// \brief For each base edge, the mesh vertices of its curve, from the
  ///        landmark of `baseEdges[e][0]` to that of `baseEdges[e][1]`.
  std::vector<std::vector<int>> curves;
  /// \brief Base triangle (patch) of every mesh triangle.
  std::vector<int> patchOfTriangle;
  /// \brief Mesh vertex of each base vertex.
  std::vector<int> landmarkVertex;
};

/// \brief Tags every curve edge of `net.mesh` with its base edge and gives
///        every triangle the base triangle on its side of the curves.
/// \pre `net.curves`, `net.leftTriangle` and `net.rightTriangle` are set,
///      one entry per base edge.
/// Fails (Status, "internal error: ...") when a curve leaves the mesh
/// edges, two patches touch away from a curve or a triangle is enclosed by
/// no curve: the curves are then not a layout.
Status labelPatches(TracedNet& net);

/// \brief Gives every triangle reachable from the curves `seedEdges`
///        without crossing a curve the base triangle on its side of them.
///        With `allowed`, the fill stays in the triangles marked there.
/// \pre `net.patchOfTriangle` has one entry per triangle, -1 for those to
///      fill; the curve edges are tagged; every curve of `seedEdges` runs
///      along mesh edges.
/// Fails (Status, "internal error: ...") when a curve has another patch
/// beside it already, two patches meet away from a curve, or the fill
/// would leave `allowed`.
Status floodFillPatches(TracedNet& net, const std::vector<int>& seedEdges, const std::vector<char>* allowed = nullptr);

/// \brief Splits every untagged edge from one of `vertices` to a vertex
///        marked in `occupied`, by calling `split(h)` with a halfedge of it,
///        so that every gap between curves holds a free vertex. Edges are
///        found again by their ends before each split (indices move as edges
///        split); `occupied` is read before the first split. Returns the
///        number of splits.
int splitEdgesBetweenCurves(const EditableMesh& mesh, const std::vector<int>& vertices,
  const std::vector<char>& occupied, const std::function<void(int)>& split);

/// \brief Copies the triangles `triangles` of `mesh` into a mesh of their
///        own. `localIndex` must hold -1 for every vertex of `mesh`;
///        afterwards it holds the local index of each copied vertex, and
///        `global` lists the copied vertices in local order (use it to reset
///        `localIndex`).
TriangleMesh extractTriangles(const EditableMesh& mesh, const std::vector<int>& triangles,
  std::vector<int>& localIndex, std::vector<int>& global);

/// \brief Arc-length position of every vertex of `curve`, from 0 at its
///        start to 1 at its end (all 0 for a curve of zero length).
std::vector<double> arcLengthParameters(const EditableMesh& mesh, const std::vector<int>& curve);

/// \brief Rebuilds a layout from a labelled surface (`patchId` per
///        triangle, the landmark vertex of each feature): the curve of a base
///        edge is the chain of mesh edges between its two patches, from one
///        landmark to the other. The labelling should pass
///        `validateLayout()`; anything else is reported, never followed.
/// \pre `domain` passes `checkBaseDomain()`.
/// Fails (Status), naming the problem, when `patchId` has not one value per
/// triangle or names a triangle `domain` does not have, the landmarks are
/// invalid or not one per base vertex (`validateLandmarks()`), `surface` is
/// not a closed oriented edge-manifold (`EditableMesh::build()`), a boundary
/// between two patches branches or does not run from landmark to landmark,
/// or the curves enclose other patches than `patchId` says.
Status layoutFromPatchIds(const TriangleMesh& surface, const std::vector<int>& patchId,
  const LandmarkList& landmarks, const BaseDomain& domain, TracedNet& net);

/// \brief The net as the layout validator's input: the refined surface, its
///        PatchId and the landmarks' feature ids.
LabelledSurface toLabelledSurface(const TracedNet& net, const BaseDomain& domain);

/// \brief A surface with PatchId per triangle and `landmarks[f]` the vertex
///        of feature f, as the layout validator's input.
LabelledSurface toLabelledSurface(
  const TriangleMesh& surface, const std::vector<int>& patchId, const LandmarkList& landmarks);

/// \brief Length of a curve given as mesh vertices.
double curveLength(const EditableMesh& mesh, const std::vector<int>& curve);

/// \brief Sum of the lengths of all curves of the net.
double netLength(const TracedNet& net);

/// \brief Area of every patch.
std::vector<double> patchAreas(const TracedNet& net, int patchCount);

/// \brief Coefficient of variation (standard deviation / mean) of the patch
///        areas: 0 when all patches have the same area.
double areaVariation(const std::vector<double>& areas);

} // namespace cmp
