#include <cmp/analysis/DetailTransfer.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace cmp
{

DetailSchedule detailsOfBAbove(int finestLevel, int lastLevelOfA)
{
  DetailSchedule schedule(std::max(finestLevel, 0) + 1, 0.0);
  for (int l = std::max(lastLevelOfA + 1, 1); l <= finestLevel; ++l)
    schedule[l] = 1.0;
  return schedule;
}

namespace
{

Status checkCompatible(const WaveletCoefficients& a, const WaveletCoefficients& b, const DetailSchedule& weightOfB)
{
  if (a.levelVertexCount != b.levelVertexCount)
    return Status::error("the two coefficient sets are of different levels or meshes (level " +
      std::to_string(a.level()) + " and " + std::to_string(b.level()) + ")");
  if (a.level() < 0)
    return Status::error("the coefficient sets are empty");
  if (a.values.rows() != a.levelVertexCount.back() || b.values.rows() != a.values.rows())
    return Status::error("a coefficient set does not have one row per vertex of the finest level");
  if (a.values.cols() != b.values.cols())
    return Status::error("the coefficient sets have " + std::to_string(a.values.cols()) + " and " +
      std::to_string(b.values.cols()) + " columns");
  if (!a.values.allFinite() || !b.values.allFinite())
    return Status::error("a coefficient set contains NaN or infinite entries");
  if (a.frame != b.frame)
    return Status::error("one coefficient set has local detail frames and the other global ones");
  if (static_cast<int>(weightOfB.size()) != a.level() + 1)
    return Status::error("the schedule has " + std::to_string(weightOfB.size()) + " weights but level " +
      std::to_string(a.level()) + " coefficients need " + std::to_string(a.level() + 1) +
      " (coarsest values, then levels 1.." + std::to_string(a.level()) + ")");
  if (!std::all_of(weightOfB.begin(), weightOfB.end(), [](double w) { return std::isfinite(w); }))
    return Status::error("the schedule contains NaN or infinite weights");
  return {};
}

/// RMS distance of the rows of `values` from their mean.
double spread(const Eigen::MatrixXd& values)
{
  return std::sqrt((values.rowwise() - values.colwise().mean()).squaredNorm() / static_cast<double>(values.rows()));
}

} // namespace

Status transferDetails(const WaveletCoefficients& a, const WaveletCoefficients& b, const DetailSchedule& weightOfB,
  WaveletCoefficients& out, DetailScaling scaling)
{
  if (Status s = checkCompatible(a, b, weightOfB); !s.ok())
    return s;
  WaveletCoefficients blend = a;
  const Eigen::Index coarseCount = a.levelVertexCount[0];
  blend.values.topRows(coarseCount) = (1.0 - weightOfB[0]) * a.coarse() + weightOfB[0] * b.coarse();
  double scaleA = 1.0, scaleB = 1.0;
  if (scaling == DetailScaling::RelativeToCoarseSize)
  {
    const double sizeA = spread(a.coarse()), sizeB = spread(b.coarse());
    if (!(sizeA > 0.0) || !(sizeB > 0.0))
      return Status::error("the coarsest values of a model are all equal, so its details have no size to be "
                           "relative to; use DetailScaling::Absolute");
    const double size = spread(blend.values.topRows(coarseCount));
    // Exactly 1 when the blended coarse level is the model's own.
    scaleA = weightOfB[0] == 0.0 ? 1.0 : size / sizeA;
    scaleB = weightOfB[0] == 1.0 ? 1.0 : size / sizeB;
  }
  for (int l = 1; l <= a.level(); ++l)
  {
    const Eigen::Index first = a.levelVertexCount[l - 1], count = a.levelVertexCount[l] - first;
    const double w = weightOfB[l];
    blend.values.middleRows(first, count) = (1.0 - w) * scaleA * a.details(l) + w * scaleB * b.details(l);
  }
  out = std::move(blend);
  return {};
}

Status transferDetails(const LoopWaveletTransform& transform, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
  const DetailSchedule& weightOfB, Eigen::MatrixXd& out, DetailFrame frame, DetailScaling scaling)
{
  WaveletCoefficients coefficientsA, coefficientsB;
  if (Status s = transform.analyze(a, frame, coefficientsA); !s.ok())
    return Status::error("model A: " + s.message());
  if (Status s = transform.analyze(b, frame, coefficientsB); !s.ok())
    return Status::error("model B: " + s.message());
  if (Status s = transferDetails(coefficientsA, coefficientsB, weightOfB, coefficientsA, scaling); !s.ok())
    return s;
  return transform.synthesize(coefficientsA, out);
}

} // namespace cmp
