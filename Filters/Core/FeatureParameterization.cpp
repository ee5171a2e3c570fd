#include "FeatureParameterization.h"

#include "MeanValueSystem.h"

namespace cmp
{

void FeatureCoordinates::appendInterpolated(int a, int b, double t)
{
  const std::size_t rowA = static_cast<std::size_t>(a) * featureCount;
  const std::size_t rowB = static_cast<std::size_t>(b) * featureCount;
  for (int f = 0; f < featureCount; ++f)
    values.push_back((1.0 - t) * values[rowA + f] + t * values[rowB + f]);
}

Status computeFeatureCoordinates(const TriangleMesh& mesh, const LandmarkList& landmarks, FeatureCoordinates& out)
{
  const int n = mesh.vertexCount();
  const int featureCount = static_cast<int>(landmarks.size());
  std::vector<int> fixedRow(n, -1);
  for (int f = 0; f < featureCount; ++f)
    fixedRow[landmarks[f]] = f;
  Eigen::MatrixXd values;
  if (Status s = solveMeanValueSystem(mesh, fixedRow, Eigen::MatrixXd::Identity(featureCount, featureCount), values);
      !s.ok())
    return Status::error("harmonic parameterization: " + s.message());
  out.featureCount = featureCount;
  out.values.resize(static_cast<std::size_t>(n) * featureCount);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(out.values.data(), n,
    featureCount) = values;
  return {};
}

} // namespace cmp
