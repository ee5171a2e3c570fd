#pragma once
/// \file ShapeBlend.h
/// \brief n-way shape blending (the paper's Figure 14): an affine
///        combination of the models of a collection with one connectivity.

#include <cmp/numerics/Communicator.h>
#include <cmp/analysis/ShapeCollection.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief The result of `blendShapes()`, the same on every rank.
struct ShapeBlend
{
  std::vector<Vec3> positions; ///< sum_i weights[i] * model i, per vertex.
  /// \brief True when a weight lies outside [0, 1]: the blend then leaves
  ///        the convex hull of the models and exaggerates their differences
  ///        (allowed, but the caller may want to say so).
  bool extrapolating = false;
};

/// \brief The affine combination of all models of the collection with one
///        weight per global model. Collective: every rank passes its own
///        models and the same `weights`.
///
/// The weights must sum to one (within 1e-9), so that the blend does not
/// depend on where the models are placed; any of them may be negative or
/// above one. Pass the aligned models of `alignShapes()` to blend shapes
/// rather than positions. Paper §3, "Shape Blending" (Figure 14).
///
/// \pre Vertex k of every model corresponds to vertex k of every other.
/// Fails (Status), on every rank with the same message, on the input errors
/// of `describeCollection()`, when the number of weights is not the number
/// of models, when a weight is not finite, or when their sum is not one
/// (the message gives the sum).
Status blendShapes(
  const ShapeList& localModels, const std::vector<double>& weights, Communicator& communicator, ShapeBlend& out);

/// \brief `blendShapes()` of a collection held by this process alone:
///        same preconditions and failures.
Status blendShapes(const ShapeList& models, const std::vector<double>& weights, ShapeBlend& out);

} // namespace cmp
