#pragma once
/// \file MeshPCA.h
/// \brief Principal mesh components (the paper's Section 3): the mean shape
///        of a collection with one connectivity, its principal modes of
///        variation, and shapes rebuilt from them.

#include <cmp/numerics/Communicator.h>
#include <cmp/analysis/ShapeCollection.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>

#include <vector>

namespace cmp
{

/// \brief The principal components of a collection of m models with n
///        vertices each, the same on every rank.
///
/// A model is read as one vector of 3n numbers (x, y, z of vertex 0, then
/// of vertex 1, ...). Mode k is a unit vector of that space; model i is
/// `mean + sum_k coefficients(i, k) * mode k` when all modes are kept.
struct MeshPCA
{
  std::vector<Vec3> mean;                   ///< Mean shape (n vertices).
  /// \brief 3n x K: column k is mode k, the displacement of vertex v at
  ///        rows 3v .. 3v + 2. The columns are orthonormal.
  Eigen::MatrixXd modes;
  Eigen::VectorXd singularValues;           ///< Of the centred data, decreasing (K).
  Eigen::VectorXd variances;                ///< singularValues^2 / (m - 1) (K).
  /// \brief Share of the total variance each mode explains (K); they sum
  ///        to less than 1 when modes were left out.
  Eigen::VectorXd explainedVarianceRatios;
  double totalVariance = 0.0;               ///< Sum of the variances of all modes, kept or not.
  Eigen::MatrixXd coefficients;             ///< m x K: row i is global model i in mode coordinates.

  /// \brief Number of modes K.
  int modeCount() const { return static_cast<int>(modes.cols()); }
  /// \brief Number of models m.
  int modelCount() const { return static_cast<int>(coefficients.rows()); }
  /// \brief Mode `k` as one displacement per vertex.
  std::vector<Vec3> modeDisplacements(int k) const;
};

/// \brief Principal components of the collection whose models this rank
///        holds `localModels` of. Collective: every rank passes the same
///        `requestedModes` and receives the same result.
///
/// Keeps K = min(requestedModes, m - 1) modes (all of them when
/// `requestedModes` is negative; m models centred on their mean span at
/// most m - 1 directions), fewer when the collection varies in fewer
/// directions. A mode is dropped as numerical noise when its singular
/// value is below 1e-6 of the largest (the Gram matrix squares singular
/// values, so smaller ones drown in its round-off) or below 1e-12 sqrt(m)
/// times the mean's centroid size (models that differ only by round-off).
/// So identical models give no mode.
///
/// Each mode's sign is chosen so that the model with the largest absolute
/// coefficient on it (the first such model on a tie) has a positive one:
/// it does not depend on how the models are spread over ranks, nor on a
/// rigid motion of the collection.
///
/// Models are taken as they are; align them first with `alignShapes()`
/// (the paper aligns them rigidly and scales them to equal volume). Paper
/// §3, "Principal Mesh Components"; the rules for dropping and orienting
/// modes are ours.
///
/// \pre Vertex k of every model corresponds to vertex k of every other
///      (remeshes of one collection, `ShapeList`).
/// Fails (Status), on every rank with the same message, with fewer than two
/// models and on the input errors of `describeCollection()`.
Status computeMeshPCA(
  const ShapeList& localModels, int requestedModes, Communicator& communicator, MeshPCA& out);

/// \brief `computeMeshPCA()` of a collection held by this process alone:
///        same preconditions and failures.
Status computeMeshPCA(const ShapeList& models, int requestedModes, MeshPCA& out);

/// \brief The shape `mean + sum_k modeFactors[k] * coefficients[k] * mode k`.
///
/// With every factor 1 it rebuilds the shape whose coefficients are given;
/// the paper's Figure 11 triples one mode (factor 3 on it, 1 elsewhere) or
/// doubles all modes (factor 2 everywhere). Fails (Status) unless both
/// vectors have one finite entry per mode.
Status synthesizeShape(const MeshPCA& pca, const Eigen::VectorXd& coefficients, const Eigen::VectorXd& modeFactors,
  std::vector<Vec3>& out);

/// \brief `synthesizeShape()` with the coefficients of global model `model`.
///        Fails if there is no such model.
Status synthesizeModel(const MeshPCA& pca, int model, const Eigen::VectorXd& modeFactors, std::vector<Vec3>& out);

} // namespace cmp
