#include <cmp/layout/FeatureParameterization.h>

#include <cmp/numerics/MeanValueSystem.h>

namespace cmp
{

void FeatureCoordinates::appendInterpolated(int a, int b, double t)
{
  for (std::vector<double>& component : components)
    component.push_back((1.0 - t) * component[a] + t * component[b]);
}

Status computeFeatureCoordinates(const TriangleMesh& mesh, const LandmarkList& landmarks, FeatureCoordinates& out,
  const FeatureCoordinateOptions& options)
{
  const int n = mesh.vertexCount();
  const int featureCount = static_cast<int>(landmarks.size());
  std::vector<int> fixedRow(n, -1);
  for (int f = 0; f < featureCount; ++f)
    fixedRow[landmarks[f]] = f;
  Eigen::MatrixXd values;
  const Eigen::MatrixXd unitVectors = Eigen::MatrixXd::Identity(featureCount, featureCount);
  const Status s = n > options.directSolveLimit
    ? solveConvexCombinationMultilevel(meanValueWeights(mesh), fixedRow, unitVectors, values, options.multilevel)
    : solveMeanValueSystem(mesh, fixedRow, unitVectors, values, ConvexCombinationFactorization::DiagonalPivots);
  if (!s.ok())
    return Status::error("harmonic parameterization: " + s.message());
  out.featureCount = featureCount;
  out.components.assign(featureCount, {});
  for (int f = 0; f < featureCount; ++f)
    out.components[f].assign(values.col(f).data(), values.col(f).data() + n);
  return {};
}

} // namespace cmp
