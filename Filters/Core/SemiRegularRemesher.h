#pragma once
/// \file SemiRegularRemesher.h
/// \brief The paper's remeshing: the base domain refined by 1-to-4
///        quadrisection, one connectivity for every model, each model's
///        vertices placed through its parameterization.

#include "BaseDomain.h"
#include "PatchLayout.h"
#include "PatchParameterization.h"
#include "Status.h"
#include "TriangleMesh.h"

#include <array>
#include <vector>

namespace cmp
{

/// \brief A place in the base domain: a base triangle and barycentric
///        coordinates in the order of its vertices.
struct BaseLocation
{
  int triangle = -1;                                  ///< Base triangle.
  std::array<double, 3> coordinates{ { 0.0, 0.0, 0.0 } }; ///< Barycentric coordinates.
};

/// \brief The semi-regular connectivity shared by every model of a
///        collection.
///
/// Vertex numbering: the F base vertices first, vertex f being the base
/// vertex of feature f; then the midpoints made by each quadrisection, level
/// by level, in the order in which their parent edges first appear when the
/// previous level's triangles are read in order (edge k -> k+1 of each
/// triangle). So the vertices of level l are the first ones of level l+1.
/// Triangles: each base triangle's 4^level triangles, base triangles in order,
/// within one in the order of recursive quadrisection (corner a, corner b,
/// corner c, centre), counter-clockwise like the base domain.
struct SemiRegularMesh
{
  int level = 0;                        ///< Quadrisections applied to L0.
  std::vector<Triangle> triangles;      ///< Counter-clockwise triangles.
  std::vector<int> patchOfTriangle;     ///< Base triangle of each triangle.
  std::vector<BaseLocation> locations;  ///< Base-domain place of each vertex.
  std::vector<int> levelOfVertex;       ///< Level at which each vertex appears (0 for base vertices).

  /// \brief Number of vertices.
  int vertexCount() const { return static_cast<int>(locations.size()); }
};

/// \brief Builds the connectivity of `domain` refined `level` times (0..8).
///        Depends only on the base domain and the level.
Status buildSemiRegularMesh(const BaseDomain& domain, int level, SemiRegularMesh& out);

/// \brief Where one remesh vertex lands on a model: a convex combination of
///        three vertices of the parameterized surface.
struct SurfaceSample
{
  std::array<int, 3> vertex{ { -1, -1, -1 } };        ///< Surface vertices.
  std::array<double, 3> weight{ { 0.0, 0.0, 0.0 } };  ///< Their weights (sum 1).
};

/// \brief Places every vertex of `remesh` on a parameterized model by
///        inverting its parameterization: the triangle of the vertex's patch
///        whose image contains the vertex's base location (a uniform grid
///        per patch, not a scan), interpolated barycentrically. `net` and
///        `parameterization` are the straightener's and the per-patch
///        map's output for the same surface.
Status placeOnSurface(const SemiRegularMesh& remesh, const TracedNet& net, const BaseDomain& domain,
  const PatchParameterization& parameterization, std::vector<SurfaceSample>& samples);

/// \brief The positions of `samples` on the mesh of `net`.
std::vector<Vec3> samplePositions(const TracedNet& net, const std::vector<SurfaceSample>& samples);

} // namespace cmp
