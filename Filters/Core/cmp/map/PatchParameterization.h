#pragma once
/// \file PatchParameterization.h
/// \brief Maps every patch of a layout bijectively onto its base triangle:
///        every surface vertex gets a place in the base domain.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/mesh/Status.h>

#include <array>
#include <vector>

namespace cmp
{

/// \brief Where every vertex of a layout lies in the base domain.
struct PatchParameterization
{
  /// \brief Per vertex: the base triangle it is expressed in. For a vertex
  ///        on a curve or at a landmark, the lowest-numbered base triangle
  ///        of the patches that share it.
  std::vector<int> baseTriangle;
  /// \brief Per vertex: barycentric coordinates in `baseTriangle`, in the
  ///        order of that triangle's vertices in the base domain.
  std::vector<std::array<double, 3>> baseCoordinates;
  /// \brief Triangles whose image in their patch's base triangle has no
  ///        positive area (0 for a bijective map).
  int flippedTriangles = 0;
  /// \brief Smallest signed area of a triangle's image, relative to its base
  ///        triangle's area (which is 1 in barycentric coordinates / 2).
  double smallestRelativeArea = 0.0;
  /// \brief Smallest ratio, over all triangles, of the share of its base
  ///        triangle's area a triangle's image takes to its share of its
  ///        patch's surface area (1 for an area-preserving map; tiny where a
  ///        long protrusion without a landmark crowds).
  double smallestAreaRatio = 0.0;
};

/// \brief Tuning of `parameterizePatches()`.
struct PatchParameterizationOptions
{
  /// \brief Lower the distortion of every patch's map, not only spread
  ///        crowded ones: landmark-free protrusions (ears, horns, tails) get
  ///        more of the base domain, so uniform remesh samples reach further
  ///        into them (measured in Documentation/known-issues.md), at several
  ///        times the parameterization's cost.
  bool lowerStretch = false;
};

/// \brief Maps each patch onto its base triangle: the three curves onto the
///        triangle's edges by arc length (the same on both sides of a curve,
///        so shared vertices agree), the interior by Floater's mean value
///        weights. One sparse solve per patch; a crowded patch (a long
///        protrusion without a landmark) is re-solved with weights lowered
///        towards stretched vertices (Yoshizawa, Belyaev, Seidel 2004) while
///        that makes its most crowded triangle larger. With
///        `options.lowerStretch`, every patch's map then relaxes towards an
///        isometry (`relaxSymmetricDirichlet()`, flip-free steps).
///
/// Paper §2: the bijective map between the base domain and the model that
/// the remesh is built with; the paper does not say how it maps a patch,
/// and the map here reuses its edge straightening's recipe (curves by arc
/// length, Floater's weights inside). The reweighting and `lowerStretch`
/// are beyond the paper.
///
/// \pre `net` is a layout of `domain` (every patch a disk bounded by its
///      three curves, `patchOfTriangle` set) as `straightenNet()` leaves
///      it: no edge off the curves joins two curve vertices, which a
///      bijective map needs.
/// Fails (Status, "patch P: ...") when a patch's mean value system cannot
/// be factorized or solved (degenerate geometry). Triangles that come out
/// flipped are no failure: `out.flippedTriangles` counts them.
Status parameterizePatches(const TracedNet& net, const BaseDomain& domain, PatchParameterization& out,
  const PatchParameterizationOptions& options = {});

/// \brief Re-expresses barycentric coordinates given in base triangle
///        `from` in base triangle `to`. Possible only for a point on the
///        vertices the two triangles share; returns false otherwise.
/// \pre `from` and `to` are triangles of `domain`.
bool coordinatesInTriangle(const BaseDomain& domain, int from, const std::array<double, 3>& coordinates, int to,
  std::array<double, 3>& result);

} // namespace cmp
