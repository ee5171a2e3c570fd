#pragma once
/// \file ProcrustesAlignment.h
/// \brief Generalised Procrustes alignment of a collection of models with
///        one connectivity: each model rotated and translated onto the
///        collection's mean, after an optional normalisation of its size.

#include <cmp/numerics/Communicator.h>
#include <cmp/analysis/ShapeCollection.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>

#include <vector>

namespace cmp
{

/// \brief How the models' sizes are made comparable before they are aligned.
enum class AlignmentScaling
{
  /// Sizes are kept: only rotations and translations.
  None,
  /// Each model is scaled about its centroid so that the volume it encloses
  /// equals the mean of the input volumes (the paper's choice for its
  /// principal mesh components, Section 3); the result keeps the user's
  /// units.
  EqualVolume,
  /// Each model is scaled about its centroid to centroid size 1 (see
  /// `centroidSize()`), the usual normalisation of shape analysis.
  UnitCentroidSize
};

/// \brief Settings of `alignShapes()`.
struct AlignmentOptions
{
  AlignmentScaling scaling = AlignmentScaling::EqualVolume; ///< Size normalisation.
  /// \brief The iteration stops when the mean moves by less than this
  ///        fraction of its centroid size.
  double tolerance = 1e-10;
  int maximumIterations = 100; ///< Upper bound on the alignment iterations.
};

/// \brief A similarity transform p -> scale * rotation * p + translation.
struct SimilarityTransform
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< Proper rotation (determinant +1).
  double scale = 1.0;                                     ///< Uniform scale factor.
  Vec3 translation = Vec3::Zero();                        ///< Applied last.

  /// \brief The image of `p`.
  Vec3 apply(const Vec3& p) const { return scale * (rotation * p) + translation; }
};

/// \brief The result of `alignShapes()`.
///
/// The aligned collection is expressed in the frame of global model 0: the
/// rigid motion that aligns model 0 to the mean is undone for every model,
/// so the aligned model 0 and the mean sit where the user's model 0 is,
/// with its orientation (model 0 is only rescaled about its centroid).
struct ShapeAlignment
{
  ShapeList alignedModels;                       ///< This rank's models, aligned.
  std::vector<SimilarityTransform> transforms;   ///< Input to aligned, per local model.
  std::vector<Vec3> mean;                        ///< Mean of all aligned models (on every rank).
  int iterations = 0;                            ///< Alignment iterations run.
  bool converged = false;                        ///< Whether the tolerance was reached.
  double lastChange = 0.0;                       ///< Last relative change of the mean.
};

/// \brief Aligns every model of the collection to the collection's mean.
///        Collective: every rank passes its own models and the same
///        `triangles` and `options`.
///
/// Each model is centred at its centroid and scaled as `options.scaling`
/// says; then, starting from model 0 as the mean, every model is rotated
/// onto the mean by the Kabsch method (a 3x3 SVD, reflections excluded)
/// and the mean is recomputed, until it moves by less than
/// `options.tolerance` of its size or `options.maximumIterations` is
/// reached (then `converged` is false; the models are still aligned as far
/// as the iteration got). Each iteration reads every vertex a fixed number
/// of times: O(models x vertices).
///
/// `triangles` (the shared connectivity, counter-clockwise seen from
/// outside) are only used for the volumes of `EqualVolume`; then every
/// model must enclose a volume of the same sign that is not negligible
/// against its size. Paper §3 (models "aligned through rigid body motion
/// and scaled to equal volume"); generalised Procrustes is our choice of
/// how.
///
/// \pre Vertex k of every model corresponds to vertex k of every other.
/// Fails (Status), naming the problem, on options out of range (a
/// tolerance that is not a positive number, fewer than one iteration), and,
/// on every rank with the same message, on the input errors of
/// `describeCollection()`, on a triangle with a vertex index out of range,
/// on such volumes and, with `UnitCentroidSize`, on a model whose vertices
/// all lie at one point.
Status alignShapes(const ShapeList& localModels, const std::vector<Triangle>& triangles,
  const AlignmentOptions& options, Communicator& communicator, ShapeAlignment& out);

/// \brief `alignShapes()` of a collection held by this process alone:
///        same preconditions and failures.
Status alignShapes(const ShapeList& models, const std::vector<Triangle>& triangles,
  const AlignmentOptions& options, ShapeAlignment& out);

/// \brief The signed volume enclosed by `triangles` over `points`: positive
///        when they turn counter-clockwise seen from outside. Indices must
///        be valid.
double enclosedVolume(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);

/// \brief The centroid size of a point set: the square root of the sum of
///        squared distances of its points to their centroid (so it grows
///        with the square root of the number of points).
double centroidSize(const std::vector<Vec3>& points);

} // namespace cmp
