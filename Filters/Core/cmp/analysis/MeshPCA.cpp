#include <cmp/analysis/MeshPCA.h>

#include <cmp/analysis/ProcrustesAlignment.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <cmath>
#include <string>

// Why a Gram matrix. The centred data X has one column of 3n numbers per
// model (3n in the hundred thousands, m models in the tens or hundreds).
// The covariance X X^T is 3n x 3n, far too large to form; the Gram matrix
// G = X^T X is m x m and has the same non-zero eigenvalues (the squared
// singular values of X), its eigenvectors V giving the modes as
// X V Sigma^-1. Forming G costs one matrix product over the data, and each
// rank can compute its rows of G from its own models plus one other model
// at a time, so the data never has to be gathered in one place.
//
// Why a second pass. Squaring the singular values halves the digits left to
// the small ones: modes computed as X V Sigma^-1 are orthogonal only to
// about eps * (sigma_1 / sigma_k)^2. So the Gram step is only used to find
// the subspace the modes span; an orthonormal basis Q of it is made by a QR
// factorisation, and the small matrix B = Q^T X (its coordinates of each
// model, computed from the data, not from G) is decomposed by an SVD. That
// gives modes orthonormal to round-off and singular values and
// coefficients with the accuracy of a direct SVD of X (a Rayleigh-Ritz
// step), at the cost of two more products of the data with K vectors.

namespace cmp
{
namespace
{

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a model's positions are read as one vector of 3n numbers");

/// A model's positions as one vector of 3n numbers, without a copy.
Eigen::Map<const Eigen::VectorXd> asVector(const std::vector<Vec3>& points)
{
  return { points.data()->data(), 3 * static_cast<Eigen::Index>(points.size()) };
}

/// Relative to the largest squared singular value, the squared singular
/// values below which the Gram matrix holds only round-off.
constexpr double gramNoiseFloor = 1e-12;
/// Relative to the mean shape's size (per model), singular values below
/// which models differ only by round-off.
constexpr double shapeNoiseFloor = 1e-12;

/// The mean of all models, on every rank.
Eigen::VectorXd meanShape(const ShapeList& localModels, const CollectionLayout& layout, Communicator& communicator)
{
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(3 * layout.vertexCount);
  for (const std::vector<Vec3>& model : localModels)
    sum += asVector(model);
  communicator.allReduceSum(sum.data(), static_cast<std::size_t>(sum.size()));
  return sum / layout.modelCount;
}

/// One column per local model: its positions minus the mean.
Eigen::MatrixXd centredData(const ShapeList& localModels, const Eigen::VectorXd& mean)
{
  Eigen::MatrixXd data(mean.size(), static_cast<Eigen::Index>(localModels.size()));
  for (std::size_t i = 0; i < localModels.size(); ++i)
    data.col(static_cast<Eigen::Index>(i)) = asVector(localModels[i]) - mean;
  return data;
}

/// G = X^T X over all models, on every rank. Each rank fills the rows of
/// its own models: the block among them by one symmetric product, the
/// other columns from the models of the other ranks, broadcast by their
/// owners one at a time so that at most one foreign model is held.
/// Collective.
Eigen::MatrixXd gramMatrix(const Eigen::MatrixXd& localData, const CollectionLayout& layout, Communicator& communicator)
{
  const Eigen::Index first = layout.firstModel, localCount = localData.cols();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(layout.modelCount, layout.modelCount);
  if (localCount > 0) // Eigen's product kernels read through the data pointer even when it is empty
  {
    Eigen::MatrixXd localBlock = Eigen::MatrixXd::Zero(localCount, localCount);
    localBlock.selfadjointView<Eigen::Lower>().rankUpdate(localData.transpose());
    gram.block(first, first, localCount, localCount) = localBlock.selfadjointView<Eigen::Lower>();
  }

  if (communicator.size() > 1)
  {
    Eigen::VectorXd model(localData.rows());
    for (int j = 0; j < layout.modelCount; ++j)
    {
      const int owner = layout.ownerOf(j);
      const bool mine = owner == communicator.rank();
      if (mine)
        model = localData.col(j - first);
      communicator.broadcast(model.data(), static_cast<std::size_t>(model.size()), owner);
      if (!mine && localCount > 0)
        gram.block(first, j, localCount, 1).noalias() = localData.transpose() * model;
    }
  }
  communicator.allReduceSum(gram.data(), static_cast<std::size_t>(gram.size()));
  return gram;
}

/// How many of the decreasing `eigenvalues` of the Gram matrix belong to
/// modes that are kept: at most `requested` (all if negative) and m - 1,
/// and none below the noise floors.
int keptModeCount(const Eigen::VectorXd& eigenvalues, double meanSize, int requested)
{
  const Eigen::Index m = eigenvalues.size();
  const double largest = eigenvalues.size() > 0 ? eigenvalues(0) : 0.0;
  const double shapeFloor = shapeNoiseFloor * meanSize;
  const double floor = std::max(gramNoiseFloor * largest, shapeFloor * shapeFloor * static_cast<double>(m));
  Eigen::Index limit = m - 1;
  if (requested >= 0)
    limit = std::min<Eigen::Index>(limit, requested);
  int kept = 0;
  while (kept < limit && eigenvalues(kept) > floor)
    ++kept;
  return kept;
}

/// An orthonormal basis (3n x K) of the span of the first K modes X V
/// Sigma^-1, on every rank. Collective.
Eigen::MatrixXd modeSubspace(const Eigen::MatrixXd& localData, const Eigen::MatrixXd& eigenvectors,
  const Eigen::VectorXd& eigenvalues, int modeCount, const CollectionLayout& layout, Communicator& communicator)
{
  // Dividing by sigma makes the columns nearly orthonormal already, so the
  // QR does not have to resolve columns of very different lengths.
  const Eigen::VectorXd inverseSigma = eigenvalues.head(modeCount).cwiseSqrt().cwiseInverse();
  Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(localData.rows(), modeCount);
  if (localData.cols() > 0)
  {
    modes.noalias() = localData *
      (eigenvectors.block(layout.firstModel, 0, localData.cols(), modeCount) * inverseSigma.asDiagonal());
  }
  communicator.allReduceSum(modes.data(), static_cast<std::size_t>(modes.size()));
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(modes);
  return qr.householderQ() * Eigen::MatrixXd::Identity(modes.rows(), modeCount);
}

/// B = Q^T X: the coordinates of every model in the basis, K x m, on every
/// rank. Collective.
Eigen::MatrixXd coordinatesInBasis(const Eigen::MatrixXd& basis, const Eigen::MatrixXd& localData,
  const CollectionLayout& layout, Communicator& communicator)
{
  Eigen::MatrixXd coordinates = Eigen::MatrixXd::Zero(basis.cols(), layout.modelCount);
  if (localData.cols() > 0)
    coordinates.middleCols(layout.firstModel, localData.cols()).noalias() = basis.transpose() * localData;
  communicator.allReduceSum(coordinates.data(), static_cast<std::size_t>(coordinates.size()));
  return coordinates;
}

/// Gives each mode the sign that makes the largest coefficient on it
/// positive.
void orientModes(MeshPCA& pca)
{
  for (Eigen::Index k = 0; k < pca.modes.cols(); ++k)
  {
    Eigen::Index largest = 0;
    pca.coefficients.col(k).cwiseAbs().maxCoeff(&largest);
    if (pca.coefficients(largest, k) < 0.0)
    {
      pca.coefficients.col(k) *= -1.0;
      pca.modes.col(k) *= -1.0;
    }
  }
}

/// Fills the modes, singular values and coefficients from the SVD of the
/// coordinates B = Q^T X of the models in the basis Q.
void decomposeInBasis(const Eigen::MatrixXd& basis, const Eigen::MatrixXd& coordinates, MeshPCA& out)
{
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(coordinates, Eigen::ComputeThinU | Eigen::ComputeThinV);
  out.singularValues = svd.singularValues();
  out.modes.noalias() = basis * svd.matrixU();
  out.coefficients.noalias() = coordinates.transpose() * svd.matrixU();
}

} // namespace

std::vector<Vec3> MeshPCA::modeDisplacements(int k) const
{
  std::vector<Vec3> displacements(mean.size());
  for (std::size_t v = 0; v < displacements.size(); ++v)
    displacements[v] = modes.col(k).segment<3>(3 * static_cast<Eigen::Index>(v));
  return displacements;
}

Status computeMeshPCA(const ShapeList& localModels, int requestedModes, Communicator& communicator, MeshPCA& out)
{
  out = MeshPCA();
  CollectionLayout layout;
  const Status status = describeCollection(localModels, communicator, layout);
  if (!status.ok())
    return status;
  if (layout.modelCount < 2)
    return Status::error("principal components need at least two models; the collection has one");

  const Eigen::VectorXd mean = meanShape(localModels, layout, communicator);
  out.mean.resize(static_cast<std::size_t>(layout.vertexCount));
  Eigen::Map<Eigen::VectorXd>(out.mean.data()->data(), mean.size()) = mean;

  const Eigen::MatrixXd data = centredData(localModels, mean);
  const Eigen::MatrixXd gram = gramMatrix(data, layout, communicator);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  const Eigen::VectorXd eigenvalues = eigen.eigenvalues().reverse();
  const Eigen::MatrixXd eigenvectors = eigen.eigenvectors().rowwise().reverse();

  const int modeCount = keptModeCount(eigenvalues, centroidSize(out.mean), requestedModes);
  if (modeCount > 0)
  {
    const Eigen::MatrixXd basis = modeSubspace(data, eigenvectors, eigenvalues, modeCount, layout, communicator);
    decomposeInBasis(basis, coordinatesInBasis(basis, data, layout, communicator), out);
    orientModes(out);
  }
  else
  {
    out.modes.resize(mean.size(), 0);
    out.singularValues.resize(0);
    out.coefficients.resize(layout.modelCount, 0);
  }

  const double sampleCount = layout.modelCount - 1.0;
  out.totalVariance = gram.trace() / sampleCount;
  out.variances = out.singularValues.array().square() / sampleCount;
  out.explainedVarianceRatios = out.variances / out.totalVariance;
  return Status();
}

Status computeMeshPCA(const ShapeList& models, int requestedModes, MeshPCA& out)
{
  SingleProcess serial;
  return computeMeshPCA(models, requestedModes, serial, out);
}

Status synthesizeShape(const MeshPCA& pca, const Eigen::VectorXd& coefficients, const Eigen::VectorXd& modeFactors,
  std::vector<Vec3>& out)
{
  const Eigen::Index modeCount = pca.modes.cols();
  if (coefficients.size() != modeCount || modeFactors.size() != modeCount)
  {
    return Status::error("synthesis needs one coefficient and one factor per mode (" + std::to_string(modeCount) +
      "), got " + std::to_string(coefficients.size()) + " coefficients and " + std::to_string(modeFactors.size()) +
      " factors");
  }
  if (!coefficients.allFinite() || !modeFactors.allFinite())
    return Status::error("synthesis coefficients and factors must be finite numbers");

  out = pca.mean;
  if (out.empty())
    return Status();
  Eigen::Map<Eigen::VectorXd>(out.data()->data(), 3 * static_cast<Eigen::Index>(out.size())).noalias() +=
    pca.modes * coefficients.cwiseProduct(modeFactors);
  return Status();
}

Status synthesizeModel(const MeshPCA& pca, int model, const Eigen::VectorXd& modeFactors, std::vector<Vec3>& out)
{
  if (model < 0 || model >= pca.modelCount())
  {
    return Status::error("model " + std::to_string(model) + " is not in the collection of " +
      std::to_string(pca.modelCount()) + " models");
  }
  return synthesizeShape(pca, pca.coefficients.row(model).transpose(), modeFactors, out);
}

} // namespace cmp
