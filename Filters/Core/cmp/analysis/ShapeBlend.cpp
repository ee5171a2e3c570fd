#include <cmp/analysis/ShapeBlend.h>

#include <cmath>
#include <sstream>
#include <string>

namespace cmp
{
namespace
{

static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are summed as one vector of 3n numbers");

/// Weights are given for the whole collection, so every rank checks them
/// alike and needs no agreement.
Status checkWeights(const std::vector<double>& weights, int modelCount)
{
  if (weights.size() != static_cast<std::size_t>(modelCount))
  {
    return Status::error("blending needs one weight per model: got " + std::to_string(weights.size()) +
      " weights for " + std::to_string(modelCount) + " models");
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < weights.size(); ++i)
  {
    if (!std::isfinite(weights[i]))
      return Status::error("the weight of model " + std::to_string(i) + " is not a finite number");
    sum += weights[i];
  }
  if (!(std::abs(sum - 1.0) <= 1e-9))
  {
    std::ostringstream message;
    message.precision(15);
    message << "blending weights must sum to 1 (an affine combination), but they sum to " << sum;
    return Status::error(message.str());
  }
  return Status();
}

} // namespace

Status blendShapes(
  const ShapeList& localModels, const std::vector<double>& weights, Communicator& communicator, ShapeBlend& out)
{
  out = ShapeBlend();
  CollectionLayout layout;
  Status status = describeCollection(localModels, communicator, layout);
  if (!status.ok())
    return status;
  status = checkWeights(weights, layout.modelCount);
  if (!status.ok())
    return status;

  const Eigen::Index size = 3 * static_cast<Eigen::Index>(layout.vertexCount);
  out.positions.assign(static_cast<std::size_t>(layout.vertexCount), Vec3::Zero());
  Eigen::Map<Eigen::VectorXd> blend(out.positions.data()->data(), size);
  for (std::size_t i = 0; i < localModels.size(); ++i)
    blend += weights[layout.firstModel + i] * Eigen::Map<const Eigen::VectorXd>(localModels[i].data()->data(), size);
  communicator.allReduceSum(blend.data(), static_cast<std::size_t>(size));

  for (double w : weights)
    out.extrapolating = out.extrapolating || w < 0.0 || w > 1.0;
  return Status();
}

Status blendShapes(const ShapeList& models, const std::vector<double>& weights, ShapeBlend& out)
{
  SingleProcess serial;
  return blendShapes(models, weights, serial, out);
}

} // namespace cmp
