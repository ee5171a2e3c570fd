#pragma once
/// \file AttributeTransfer.h
/// \brief Where the points and triangle corners of one parameterized mesh
///        land on another model, through the shared base domain (paper
///        Section 3: texture and attribute transfer).

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief A target mesh described in base-domain terms: the base location
///        of every vertex and the base triangle (patch) of every triangle.
///        A semi-regular remesh and a straightened original surface both
///        give one.
struct BaseDomainMesh
{
  std::vector<SurfacePoint> locations; ///< Base location of every vertex.
  std::vector<Triangle> triangles;     ///< Triangles over those vertices.
  std::vector<int> patchOfTriangle;    ///< Base triangle of every triangle.
};

/// \brief The source point under every target vertex (paper §3, "Transfer
///        of Textures": direct parametric mapping).
/// \pre `source` is built over the base domain `target`'s locations are
///      places in.
/// Fails (Status, "target point V: ...") where
/// `ParameterizedSurface::locate()` fails.
Status locateVertices(
  const ParameterizedSurface& source, const BaseDomainMesh& target, std::vector<SurfacePoint>& samples);

/// \brief The source point under every corner of every target triangle
///        (3 per triangle, in corner order), seen from inside that
///        triangle: the corner is moved a tiny step (`inset` of the way)
///        towards the triangle's centroid in its patch before it is
///        located. Across a texture seam of the source the two sides of a
///        target vertex then read the texture coordinates of their own side.
///        Per-corner lookup for texture seams is beyond the paper.
/// \pre `source` is built over `domain`.
/// Fails (Status), naming the triangle, when `target` has not one patch
/// per triangle, a triangle uses a point without a base location, a
/// corner's base location lies neither in its triangle's patch nor on that
/// patch's boundary, or a nudged corner cannot be located on `source`.
Status locateCorners(const ParameterizedSurface& source, const BaseDomain& domain, const BaseDomainMesh& target,
  std::vector<SurfacePoint>& corners, double inset = 1e-6);

} // namespace cmp
