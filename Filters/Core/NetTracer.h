#pragma once
/// \file NetTracer.h
/// \brief Traces on a surface a net of curves topologically equivalent to
///        the base domain (the paper's Sections 2.1 and 2.2).

#include "BaseDomain.h"
#include "EditableMesh.h"
#include "Landmarks.h"
#include "LayoutValidator.h"
#include "Status.h"
#include "TriangleMesh.h"

#include <array>
#include <functional>
#include <vector>

namespace cmp
{

/// \brief Tuning of `traceFeatureNet()`.
struct NetTracerOptions
{
  /// \brief How strongly curves follow the ridge of the harmonic
  ///        parameterization (K = pi[f] + pi[f']) rather than the shortest
  ///        path: each edge costs length * (1 + weight * (1 - K)). 0 gives
  ///        restricted shortest paths.
  double parameterizationWeight = 2.0;
  /// \brief Run the paper's swirl detector before accepting a curve.
  bool detectSwirls = true;
  /// \brief How often one curve may be postponed by the swirl detector
  ///        before it is accepted anyway (keeps the loop finite).
  int maxPenalties = 2;
  /// \brief A postponed curve's priority is multiplied by this.
  double penaltyFactor = 2.0;
  /// \brief Called with the fraction of curves inserted, in [0, 1].
  std::function<void(double)> progress;
};

/// \brief The traced net and the refined surface it lives on.
struct TracedNet
{
  /// \brief The input surface, with edges split where curves needed room.
  ///        Vertices 0..n-1 are the input's; `mesh.origin(v)` tells how later
  ///        ones were made.
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

/// \brief Figures about a tracing run.
struct NetTracerReport
{
  double netLength = 0.0; ///< Sum of the curves' lengths.
  int traces = 0;         ///< Brush fires run to find curves (first tries and retraces).
  int retraced = 0;       ///< Tentative curves found invalid when their turn came.
  int penalised = 0;      ///< Curves postponed by the swirl detector.
  int splitEdges = 0;     ///< Mesh edges split to make room between curves.
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
/// applies. `surface` must pass `checkSurface()`; `landmarks[f]` is the
/// vertex of feature f and `domain.featureIds` names the feature of each base
/// vertex.
Status traceFeatureNet(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  TracedNet& net, const NetTracerOptions& options = {}, NetTracerReport* report = nullptr);

/// \brief The traced net as the layout validator's input: the refined
///        surface, its PatchId and the landmarks' feature ids.
LabelledSurface toLabelledSurface(const TracedNet& net, const BaseDomain& domain);

/// \brief Length of a curve given as mesh vertices.
double curveLength(const EditableMesh& mesh, const std::vector<int>& curve);

} // namespace cmp
