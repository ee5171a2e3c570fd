#include <cmp/analysis/ProcrustesAlignment.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>
#include <sstream>
#include <string>

namespace cmp
{
namespace
{

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a model's positions are read as one 3 x n matrix");

/// A model's positions as the columns of a 3 x n matrix, without a copy.
Eigen::Map<const Eigen::Matrix3Xd> asMatrix(const std::vector<Vec3>& points)
{
  return { points.data()->data(), 3, static_cast<Eigen::Index>(points.size()) };
}

Vec3 centroidOf(const std::vector<Vec3>& points)
{
  return asMatrix(points).rowwise().mean();
}

std::string modelName(int model)
{
  return "model " + std::to_string(model);
}

Status checkOptions(const AlignmentOptions& options)
{
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    return Status::error("alignment tolerance must be a positive number");
  if (options.maximumIterations < 1)
    return Status::error("alignment needs at least one iteration");
  return Status();
}

Status checkTriangles(const std::vector<Triangle>& triangles, int vertexCount)
{
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int v : triangles[t])
    {
      if (v < 0 || v >= vertexCount)
      {
        return Status::error("triangle " + std::to_string(t) + " has vertex index " + std::to_string(v) +
          ", outside 0.." + std::to_string(vertexCount - 1));
      }
    }
  }
  return Status();
}

/// Whether a volume is too small against the model's extent to fix a scale:
/// a flat model, or a surface that does not close.
bool isNegligibleVolume(double volume, const std::vector<Vec3>& points)
{
  const double rmsRadius = centroidSize(points) / std::sqrt(static_cast<double>(points.size()));
  return !(std::abs(volume) > 1e-12 * rmsRadius * rmsRadius * rmsRadius);
}

/// Scale factors that bring every local model to the mean of the input
/// volumes. Collective.
Status equalVolumeScales(const ShapeList& localModels, const std::vector<Triangle>& triangles,
  const CollectionLayout& layout, Communicator& communicator, std::vector<double>& scales)
{
  Status status = agreeOnStatus(checkTriangles(triangles, layout.vertexCount), communicator);
  if (!status.ok())
    return status;

  std::vector<double> volumes;
  double sum = 0.0;
  for (const std::vector<Vec3>& model : localModels)
  {
    volumes.push_back(enclosedVolume(model, triangles));
    sum += volumes.back();
  }
  communicator.allReduceSum(&sum, 1);
  double firstVolume = layout.firstModel == 0 && !volumes.empty() ? volumes.front() : 0.0;
  communicator.broadcast(&firstVolume, 1, layout.ownerOf(0));
  const double meanVolume = sum / layout.modelCount;

  for (std::size_t i = 0; i < localModels.size() && status.ok(); ++i)
  {
    const std::string name = modelName(layout.firstModel + static_cast<int>(i));
    std::ostringstream message;
    if (isNegligibleVolume(volumes[i], localModels[i]))
    {
      message << name << " encloses no volume (" << volumes[i]
              << "), so it cannot be scaled to equal volume; are its triangles a closed surface?";
      status = Status::error(message.str());
    }
    else if ((volumes[i] > 0.0) != (firstVolume > 0.0))
    {
      message << name << " encloses a volume of the opposite sign to model 0's (" << volumes[i] << " against "
              << firstVolume << "): it is a mirror image or inside out, and equal-volume scaling needs every "
              << "model oriented alike";
      status = Status::error(message.str());
    }
    else
      scales.push_back(std::cbrt(meanVolume / volumes[i]));
  }
  return agreeOnStatus(status, communicator);
}

Status unitSizeScales(const ShapeList& localModels, const CollectionLayout& layout, std::vector<double>& scales)
{
  for (std::size_t i = 0; i < localModels.size(); ++i)
  {
    const double size = centroidSize(localModels[i]);
    if (!(size > 0.0))
    {
      return Status::error(modelName(layout.firstModel + static_cast<int>(i)) +
        " has all its vertices at one point, so it cannot be scaled to unit centroid size");
    }
    scales.push_back(1.0 / size);
  }
  return Status();
}

/// The factor that normalises each local model's size. Collective.
Status normalisingScales(const ShapeList& localModels, const std::vector<Triangle>& triangles,
  const CollectionLayout& layout, AlignmentScaling scaling, Communicator& communicator, std::vector<double>& scales)
{
  scales.clear();
  switch (scaling)
  {
    case AlignmentScaling::EqualVolume:
      return equalVolumeScales(localModels, triangles, layout, communicator, scales);
    case AlignmentScaling::UnitCentroidSize:
      return agreeOnStatus(unitSizeScales(localModels, layout, scales), communicator);
    case AlignmentScaling::None:
      break;
  }
  scales.assign(localModels.size(), 1.0);
  return Status();
}

/// The proper rotation R that minimises sum |R x_k - m_k|^2, given
/// `correlation` = sum x_k m_k^T (Kabsch). Flipping the axis of the
/// smallest singular value when the best orthogonal map is a reflection
/// keeps mirror images from being "aligned" by turning them inside out.
Eigen::Matrix3d kabschRotation(const Eigen::Matrix3d& correlation)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(correlation, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0)
    flip(2, 2) = -1.0;
  return svd.matrixV() * flip * svd.matrixU().transpose();
}

/// Centroid and size factor of one local model: its normalised shape is
/// scale * (p - centroid).
struct Normalisation
{
  Vec3 centroid;
  double scale;
};

/// The normalised shape of global model 0 on every rank: the first mean.
Eigen::Matrix3Xd firstModelShape(const ShapeList& localModels, const std::vector<Normalisation>& normalisations,
  const CollectionLayout& layout, Communicator& communicator)
{
  Eigen::Matrix3Xd shape(3, layout.vertexCount);
  if (layout.firstModel == 0 && !localModels.empty())
    shape = normalisations[0].scale * (asMatrix(localModels[0]).colwise() - normalisations[0].centroid);
  communicator.broadcast(shape.data(), static_cast<std::size_t>(shape.size()), layout.ownerOf(0));
  return shape;
}

/// Rotates every local model onto `mean` and returns the new mean of all
/// models. Collective.
Eigen::Matrix3Xd alignToMean(const ShapeList& localModels, const std::vector<Normalisation>& normalisations,
  const Eigen::Matrix3Xd& mean, const CollectionLayout& layout, Communicator& communicator,
  std::vector<Eigen::Matrix3d>& rotations)
{
  Eigen::Matrix3Xd sum = Eigen::Matrix3Xd::Zero(3, layout.vertexCount);
  for (std::size_t i = 0; i < localModels.size(); ++i)
  {
    // Centred on the fly: one 3 x n temporary instead of a stored copy of the collection.
    const Eigen::Matrix3Xd shape =
      normalisations[i].scale * (asMatrix(localModels[i]).colwise() - normalisations[i].centroid);
    rotations[i] = kabschRotation(shape * mean.transpose());
    sum.noalias() += rotations[i] * shape;
  }
  communicator.allReduceSum(sum.data(), static_cast<std::size_t>(sum.size()));
  return sum / layout.modelCount;
}

/// Global model 0's centroid (3 values) and rotation onto the mean (9
/// values), on every rank.
Eigen::Matrix<double, 12, 1> firstModelFrame(const std::vector<Normalisation>& normalisations,
  const std::vector<Eigen::Matrix3d>& rotations, const CollectionLayout& layout, Communicator& communicator)
{
  Eigen::Matrix<double, 12, 1> frame = Eigen::Matrix<double, 12, 1>::Zero();
  if (layout.firstModel == 0 && !rotations.empty())
  {
    frame.head<3>() = normalisations[0].centroid;
    frame.tail<9>() = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(rotations[0].data());
  }
  communicator.broadcast(frame.data(), 12, layout.ownerOf(0));
  return frame;
}

/// Undoes model 0's rigid motion for every model and the mean, and fills
/// the transforms and aligned positions.
void expressInFirstModelFrame(const ShapeList& localModels, const std::vector<Normalisation>& normalisations,
  const std::vector<Eigen::Matrix3d>& rotations, const Eigen::Matrix3Xd& mean, const CollectionLayout& layout,
  Communicator& communicator, ShapeAlignment& out)
{
  const Eigen::Matrix<double, 12, 1> frame = firstModelFrame(normalisations, rotations, layout, communicator);
  const Vec3 firstCentroid = frame.head<3>();
  const Eigen::Matrix3d firstRotationInverse = Eigen::Map<const Eigen::Matrix3d>(frame.data() + 3).transpose();

  for (std::size_t i = 0; i < localModels.size(); ++i)
  {
    SimilarityTransform transform;
    transform.rotation = firstRotationInverse * rotations[i];
    transform.scale = normalisations[i].scale;
    transform.translation = firstCentroid - transform.scale * (transform.rotation * normalisations[i].centroid);
    std::vector<Vec3> aligned(localModels[i].size());
    Eigen::Map<Eigen::Matrix3Xd>(aligned.data()->data(), 3, static_cast<Eigen::Index>(aligned.size())) =
      (transform.scale * transform.rotation * asMatrix(localModels[i])).colwise() + transform.translation;
    out.transforms.push_back(transform);
    out.alignedModels.push_back(std::move(aligned));
  }

  out.mean.resize(static_cast<std::size_t>(layout.vertexCount));
  Eigen::Map<Eigen::Matrix3Xd>(out.mean.data()->data(), 3, layout.vertexCount) =
    (firstRotationInverse * mean).colwise() + firstCentroid;
}

} // namespace

double enclosedVolume(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
{
  // Tetrahedra from the centroid rather than the origin: the same sum, but
  // without cancellation when the model lies far from the origin.
  const Vec3 centre = points.empty() ? Vec3::Zero() : centroidOf(points);
  double sixTimesVolume = 0.0;
  for (const Triangle& t : triangles)
  {
    const Vec3 a = points[t[0]] - centre, b = points[t[1]] - centre, c = points[t[2]] - centre;
    sixTimesVolume += a.dot(b.cross(c));
  }
  return sixTimesVolume / 6.0;
}

double centroidSize(const std::vector<Vec3>& points)
{
  if (points.empty())
    return 0.0;
  return (asMatrix(points).colwise() - centroidOf(points)).norm();
}

Status alignShapes(const ShapeList& localModels, const std::vector<Triangle>& triangles,
  const AlignmentOptions& options, Communicator& communicator, ShapeAlignment& out)
{
  out = ShapeAlignment();
  Status status = checkOptions(options);
  if (!status.ok())
    return status;
  CollectionLayout layout;
  status = describeCollection(localModels, communicator, layout);
  if (!status.ok())
    return status;
  std::vector<double> scales;
  status = normalisingScales(localModels, triangles, layout, options.scaling, communicator, scales);
  if (!status.ok())
    return status;

  std::vector<Normalisation> normalisations;
  for (std::size_t i = 0; i < localModels.size(); ++i)
    normalisations.push_back({ centroidOf(localModels[i]), scales[i] });

  std::vector<Eigen::Matrix3d> rotations(localModels.size(), Eigen::Matrix3d::Identity());
  Eigen::Matrix3Xd mean = firstModelShape(localModels, normalisations, layout, communicator);
  while (out.iterations < options.maximumIterations && !out.converged)
  {
    const Eigen::Matrix3Xd next = alignToMean(localModels, normalisations, mean, layout, communicator, rotations);
    const double size = next.norm();
    out.lastChange = size > 0.0 ? (next - mean).norm() / size : 0.0;
    out.converged = out.lastChange <= options.tolerance;
    mean = next;
    ++out.iterations;
  }
  expressInFirstModelFrame(localModels, normalisations, rotations, mean, layout, communicator, out);
  return Status();
}

Status alignShapes(const ShapeList& models, const std::vector<Triangle>& triangles,
  const AlignmentOptions& options, ShapeAlignment& out)
{
  SingleProcess serial;
  return alignShapes(models, triangles, options, serial, out);
}

} // namespace cmp
