#pragma once
/// \file Straighten.h
/// \brief The map stage in one call: a traced layout straightened (paper
///        Section 2.2, "Edge Straightening"), every patch mapped onto its
///        base triangle (Section 2.2), and, by default, the curves freed by
///        one low-distortion map of the whole surface (beyond the paper,
///        Documentation/algorithm.md, "The map").
///
/// `straighten()` runs the chain the Net Straightener, the benchmark and the
/// tests share: `straightenNet()`, `parameterizePatches()`, then
/// `freeCurves()`. Its parts stay available for a caller who needs one alone.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/GlobalMap.h>
#include <cmp/map/NetStraightener.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/Status.h>

#include <functional>
#include <string>

namespace cmp
{

/// \brief What `straighten()` runs, with each part's own options.
struct StraightenOptions
{
  /// \brief `straightenNet()`'s options (its `progress` is not used: see
  ///        `progress` below).
  NetStraightenerOptions net;
  /// \brief `parameterizePatches()`'s options (the map's start with
  ///        `freeCurves`).
  PatchParameterizationOptions patches;
  /// \brief Free the curves (`freeCurves()`): where that would not give a
  ///        layout equivalent to L0, the straightened net is kept and the
  ///        report says why.
  bool freeCurves = true;
  /// \brief With `freeCurves`, the most triangles a traced surface may have
  ///        for its curves to be freed (0: no limit). The map takes its
  ///        Newton steps on the whole surface, each one sparse
  ///        factorization, and its time grows faster than the surface
  ///        (Documentation/known-issues.md, "Large surfaces"): above the
  ///        limit the straightened curves are kept and the report says why.
  int freeCurvesMaximumTriangles = 150000;
  /// \brief The whole-surface map's options, with `freeCurves`.
  GlobalMapOptions map;
  /// \brief Called with the fraction (0 to 1) of the straightening done, if set.
  std::function<void(double)> progress;
};

/// \brief Checks the options `straighten()` checks first. The messages name
///        the options as the Net Straightener's properties do
///        (`MaximumSweeps`, `Tolerance`, `SnapTolerance`, `MapIterations`,
///        `FreeCurvesMaximumTriangles`), so
///        that a filter can pass them on as they are; the map's options only
///        with `freeCurves` (`checkGlobalMapOptions()`).
Status checkStraightenOptions(const StraightenOptions& options);

/// \brief What `straighten()` did.
struct StraightenReport
{
  /// \brief `straightenNet()`'s report; with the curves freed,
  ///        `netLengthAfter` and `areaVariationAfter` are the freed net's.
  NetStraightenerReport net;
  /// \brief The straightened net's length, before the curves were freed
  ///        (`straightenNet()`'s `netLengthAfter`): the freed curves follow
  ///        the map, not shortest paths, and are longer.
  double straightenedNetLength = 0.0;
  /// \brief Why the traced curves were kept instead of the straightened
  ///        ones (empty: they were straightened): a straightened patch whose
  ///        map onto its base triangle could not be computed (its mean value
  ///        system singular), where the traced net's patches can be. The
  ///        curves are then freed from the traced net.
  std::string tracedCurvesKept;
  /// \brief `freeCurves()`'s report (untouched without `freeCurves`).
  FreeCurvesReport freeCurves;
  double straightenSeconds = 0.0;   ///< `straightenNet()` alone.
  double parameterizeSeconds = 0.0; ///< `parameterizePatches()` alone.
  double mapSeconds = 0.0;          ///< `freeCurves()` alone (0 without it).
  double seconds = 0.0;             ///< The whole call.
};

/// \brief Straightens `traced` against `domain` (`straightenNet()`), maps
///        every patch of the result onto its base triangle
///        (`parameterizePatches()`) and, with `options.freeCurves`, moves
///        the curves where one map of the whole surface puts L0's edges
///        (`freeCurves()`). `out` is the final layout with where each of its
///        vertices and triangles lies on the traced surface, `map` its
///        vertices' places in L0.
///
/// \pre `traced` is a layout of one surface equivalent to `domain` (as
///      `traceFeatureNet()` or `layoutFromPatchIds()` build it).
///
/// Fails, naming the problem, on options out of range
/// (`checkStraightenOptions()`) and where a part fails (`straightenNet()`:
/// a net that does not belong to `domain`; `parameterizePatches()`). Curves
/// that cannot be freed (`freeCurves()` fails, for example on a patch map
/// that starts with a crushed triangle, or its cut does not give a layout),
/// or are not because the surface has more than
/// `options.freeCurvesMaximumTriangles`, are not a failure:
/// `report->freeCurves.applied` is false, with the reason, and `out` is the
/// straightened net. `out` and
/// `map` are complete only on success.
Status straighten(const TracedNet& traced, const BaseDomain& domain, StraightenedNet& out, PatchParameterization& map,
  const StraightenOptions& options = {}, StraightenReport* report = nullptr);

} // namespace cmp
