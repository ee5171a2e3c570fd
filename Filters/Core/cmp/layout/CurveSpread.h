#pragma once
/// \file CurveSpread.h
/// \brief How evenly the curves of a layout leave each landmark. Where they
///        all leave on one side, the patch on the other side wraps round
///        the landmark and the others are slivers; a remesh gets a fan of
///        needles there, and needles fold.

#include <cmp/layout/PatchLayout.h>

#include <vector>

namespace cmp
{

/// \brief Where on the surface the directions of the curves are read, as a
///        fraction of the surface's bounding-box diagonal (or half the
///        curve, if shorter): far enough that the first mesh edge of a
///        curve does not decide it.
constexpr double kCurveSpreadReach = 0.02;

/// \brief The landmark whose curves leave most bunched.
struct CurveGap
{
  int baseVertex = -1;  ///< Base vertex (landmark) of the gap; -1 without landmarks.
  double degrees = 0.0; ///< The largest angle between two consecutive curves there.
};

/// \brief For every base vertex (landmark) of `net`, the largest angle, in
///        degrees, between two consecutive curves leaving it (0 where it
///        has no tangent plane or no curve). A curve's direction is that of
///        the chord from the landmark to the curve's first vertex at least
///        `reach` × the bounding-box diagonal along it (at least half-way
///        if the curve is shorter than twice that), projected into the
///        landmark's tangent plane (normal: the area-weighted normal of its
///        triangles). 360 / valence for curves spread evenly; the wider
///        the largest gap, the likelier a remesh keeps folds at that
///        landmark (a rule of thumb, not a bound: the gaps measured against
///        folds are in Documentation/filters/NetStraightener.md, field
///        array `WidestCurveGap`). Beyond the paper: a diagnostic of the
///        layout. Linear in the mesh's vertices and the curves' lengths.
/// \pre `net` is a layout (`traceFeatureNet()`, `straightenNet()` or
///      `layoutFromPatchIds()` output) whose curves start and end at its
///      landmarks.
std::vector<double> largestCurveGaps(const TracedNet& net, double reach = kCurveSpreadReach);

/// \brief The largest of `largestCurveGaps()` and its base vertex.
CurveGap widestCurveGap(const TracedNet& net, double reach = kCurveSpreadReach);

} // namespace cmp
