#pragma once
/// \file NetStraightener.h
/// \brief The paper's edge straightening (Section 2.2, "Edge
///        Straightening"): the curves around every landmark are replaced by
///        straight lines of a planar map of the landmark's star.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/SurfacePoint.h>

#include <array>
#include <functional>
#include <vector>

namespace cmp
{

/// \brief The point at `t` from `a` to `b` (1 - t, t), its weights merged
///        over the input vertices both use. No triangle is recorded.
/// \pre `a` and `b` lie in one input triangle (on it, an edge or a vertex
///      of it), so at most three vertices remain.
SurfacePoint interpolate(const SurfacePoint& a, const SurfacePoint& b, double t);

/// \brief Tuning of `straightenNet()`.
struct NetStraightenerOptions
{
  /// \brief At most this many sweeps over all landmarks.
  int maxSweeps = 5;
  /// \brief Stop when a sweep changes the total net length by less than
  ///        this fraction.
  double tolerance = 0.002;
  /// \brief A straight line that crosses a mesh edge within this fraction
  ///        of the edge's length from a free vertex goes through that vertex
  ///        instead, so no sliver triangles are cut.
  double snapTolerance = 0.1;
  /// \brief Called with the fraction of work done, in [0, 1].
  std::function<void(double)> progress;
  /// \brief Features whose landmarks' stars are not straightened (the
  ///        boundary landmarks and cap centres of a closed open surface,
  ///        whose curves must stay on the boundary and the cap). A curve
  ///        from such a landmark to another may still be re-traced from the
  ///        other end's star; a curve between two kept landmarks is never
  ///        changed (its vertices keep their places and their order; only
  ///        their numbering follows the rebuilt mesh). Fails (Status) when an
  ///        id is not a feature of `domain`, naming it.
  std::vector<int> keptFeatures;
};

/// \brief Figures about a straightening run.
struct NetStraightenerReport
{
  double netLengthBefore = 0.0;     ///< Total curve length of the input net.
  double netLengthAfter = 0.0;      ///< Total curve length of the result.
  double areaVariationBefore = 0.0; ///< Coefficient of variation of the input's patch areas.
  double areaVariationAfter = 0.0;  ///< The same for the result.
  int sweeps = 0;                   ///< Sweeps run.
  int skippedStars = 0;  ///< Landmark steps that kept their curves (numerically degenerate star map).
  int removedVertices = 0; ///< Vertices left behind by replaced curves and removed again.
};

/// \brief A straightened net: the layout on a re-triangulated surface and
///        where every new vertex and triangle lies on the input surface.
struct StraightenedNet
{
  TracedNet net; ///< Layout; its mesh is the input surface cut along straight curves.
  /// \brief For every vertex of `net.mesh`, its place on the input surface
  ///        (the traced surface given to `straightenNet()`): point data is
  ///        carried with these weights.
  std::vector<SurfacePoint> inputPoint;
  /// \brief For every triangle of `net.mesh`, the input triangle it lies in.
  std::vector<int> inputTriangle;
};

/// \brief Straightens every curve of `traced` as the paper does: for each
///        landmark i, the patches around i are mapped to the plane (the
///        neighbours of i on a convex polygon inscribed in the unit circle,
///        angles proportional to the lengths of the curves between them,
///        those curves straight by arc length, the interior by Floater's mean
///        value weights), and the curves from i are replaced by the images of
///        the straight segments, cutting the triangles they cross.
///
/// Sweeps repeat until the net length changes by less than
/// `options.tolerance`. Every step keeps the layout topologically
/// equivalent to `domain` (a step that would not, on numerically
/// degenerate input, keeps the old curves). Vertices left behind by
/// replaced curves are removed again where that leaves the surface
/// unchanged. At the end, every non-curve edge between two curve vertices is
/// split, so every patch can be parameterized bijectively. Paper §2.2
/// ("Edge Straightening"); the sweeps, the snapping and the clean-up are
/// ours.
///
/// \pre `traced` is a layout of `domain` (`traceFeatureNet()` or
///      `layoutFromPatchIds()` output).
/// Fails (Status), naming the problem, when `domain` fails
/// `checkBaseDomain()`, `traced` has not one curve per base edge, one
/// landmark per base vertex and one patch per triangle ("the net does not
/// belong to this base domain"), an option is out of range (sweeps >= 0,
/// tolerance >= 0, 0 <= snap < 0.5, `keptFeatures` features of `domain`)
/// or the traced mesh is not a closed
/// oriented edge-manifold; messages starting with "internal error" are not
/// expected. `out` is complete only on success.
Status straightenNet(const TracedNet& traced, const BaseDomain& domain, StraightenedNet& out,
  const NetStraightenerOptions& options = {}, NetStraightenerReport* report = nullptr);

} // namespace cmp
