#pragma once
/// \file NetTracer.h
/// \brief Traces on a surface a net of curves topologically equivalent to
///        the base domain (the paper's Sections 2.1 and 2.2).

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/FeatureParameterization.h>
#include <cmp/io/Landmarks.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <array>
#include <functional>
#include <vector>

namespace cmp
{

/// \brief A curve given by the caller instead of traced: from the landmark of
///        feature `from` to that of feature `to`, as surface vertex ids.
struct PresetCurve
{
  int from = -1;             ///< Feature whose landmark the curve starts at.
  int to = -1;               ///< Feature whose landmark it ends at.
  std::vector<int> vertices; ///< Vertices of the input surface, `landmarks[from]` first, `landmarks[to]` last.
};

/// \brief Tuning of `traceFeatureNet()`.
struct NetTracerOptions
{
  /// \brief How strongly curves follow the ridge of the harmonic
  ///        parameterization (K = pi[f] + pi[f']) rather than the shortest
  ///        path: each edge costs length * (1 + weight * (1 - K)). 0 gives
  ///        restricted shortest paths.
  double parameterizationWeight = 2.0;
  /// \brief How the harmonic parameterization behind that ridge is solved.
  FeatureCoordinateOptions featureCoordinates;
  /// \brief Run the paper's swirl detector before accepting a curve.
  bool detectSwirls = true;
  /// \brief How often one curve may be postponed by the swirl detector
  ///        before it is accepted anyway (keeps the loop finite).
  int maxPenalties = 2;
  /// \brief A postponed curve's priority is multiplied by this.
  double penaltyFactor = 2.0;
  /// \brief When a curve went in still swirling, its postponements spent
  ///        (`NetTracerReport::forcedSwirls`), trace the net a second
  ///        time, each postponed curve now waiting until a curve at
  ///        one of the four corners of its two base triangles is in (no
  ///        cap; when only postponed curves are left, the cheapest goes in
  ///        unchecked), and keep the shorter of the two nets. Requeueing
  ///        alone can force a curve in, its postponements spent, into the
  ///        very net it swirled in, which then detours round it (a net 1.8
  ///        times as long on SHREC'07 381 with the base domain of 383);
  ///        waiting alone can make a short curve wait until it must go a
  ///        long way round (Spot with the base domain of 384: 18.4 -> 24.4
  ///        per square root of area). The second trace reuses the harmonic
  ///        parameterization (Documentation/filters/FeatureNetTracer.md).
  bool retraceWaiting = true;
  /// \brief Called with the fraction of curves inserted, in [0, 1].
  std::function<void(double)> progress;
  /// \brief Curves that are not traced but taken as given (the caps that
  ///        close a surface's boundary loops: their curves must stay on the
  ///        boundary and the cap). Each becomes, exactly, the curve of the
  ///        base edge between the base vertices of its two features (its
  ///        vertex list reversed if that edge runs the other way); all are
  ///        inserted before any curve is traced, and the traced curves leave
  ///        room for them and respect their order round the landmarks.
  ///        Vertex ids are the input surface's: splits made for room only
  ///        append vertices. The caller answers for the cyclic order of the
  ///        preset curves round each landmark (it must be the base
  ///        domain's) and for their not enclosing a landmark away from the
  ///        other curves; otherwise labelling the patches fails ("internal
  ///        error"). Fails (Status), naming the curve and the problem, when
  ///        a feature is out of range or has no base vertex, no base edge
  ///        joins the two, the list has fewer than 2 vertices, does not
  ///        start and end at the two landmarks, holds a vertex out of
  ///        range, two consecutive vertices are not joined by a mesh edge,
  ///        a vertex repeats or an inner one is a landmark, or two preset
  ///        curves share an inner vertex or a base edge.
  std::vector<PresetCurve> presetCurves;
};

/// \brief Figures about a tracing run.
struct NetTracerReport
{
  double netLength = 0.0; ///< Sum of the curves' lengths.
  int traces = 0;         ///< Brush fires run to find curves (first tries and retraces).
  int retraced = 0;       ///< Tentative curves found invalid when their turn came.
  int penalised = 0;      ///< Curves postponed by the swirl detector.
  int splitEdges = 0;     ///< Mesh edges split to make room between curves.
  /// \brief Curves that went in still swirling, their postponements spent
  ///        (counted with `NetTracerOptions::retraceWaiting` only).
  int forcedSwirls = 0;
  /// \brief The net kept was traced with postponed curves waiting
  ///        (`NetTracerOptions::retraceWaiting`), as it was the shorter.
  bool waited = false;
  /// \brief Length of the other net traced (`retraceWaiting`), 0 when only
  ///        one was traced. `traces` counts both; the other figures are the
  ///        kept net's.
  double alternativeNetLength = 0.0;
};

/// \brief Traces, for every edge of `domain`, a curve on `surface` between
///        the landmarks of its two base vertices, such that the net is
///        topologically equivalent to `domain`.
///
/// Curves run along mesh edges, never cross and meet only at landmarks; at
/// every landmark they leave in the base domain's cyclic order. A spanning
/// tree of the base domain is traced first (so no landmark can be encircled),
/// shortest tentative curves first, re-validated and re-traced when earlier
/// curves got in the way. Before each curve the mesh is refined where two
/// curves touch (every non-curve edge between occupied vertices is split), so
/// the restricted brush fire always finds room and the proof of the paper
/// applies. Paper §2.1 (restricted brush fire, spanning tree first) and
/// §2.2 (harmonic F-vector ridge, priority queue, swirl detection); the
/// edge splits replace the paper's "lanes", and the net is traced on the
/// full surface, not on a simplified copy.
///
/// \pre `landmarks[f]` is the vertex of feature f of `surface`, and
///      `domain.featureIds` names the feature of each base vertex.
/// Fails (Status), naming the problem, when `surface` fails
/// `checkSurface()`, the landmarks are invalid (`validateLandmarks()`) or
/// not one per base vertex, `domain` fails `checkBaseDomain()`, a preset
/// curve is invalid (`NetTracerOptions::presetCurves`) or the
/// harmonic parameterization cannot be solved; messages starting with
/// "internal error" (a curve not found, a net that cannot be labelled) are
/// not expected after those checks.
Status traceFeatureNet(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  TracedNet& net, const NetTracerOptions& options = {}, NetTracerReport* report = nullptr);

} // namespace cmp
