#include <cmp/io/MeshFile.h>
#include <cmp/analysis/MeshPCA.h>
#include <cmp/analysis/ProcrustesAlignment.h>
#include "TestMeshes.h"
#include "TestShapes.h"
#include "ThreadCommunicator.h"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>

using namespace cmp;
using namespace cmp::test;

namespace
{

/// The models as the columns of a 3n x m matrix.
Eigen::MatrixXd dataMatrix(const ShapeList& models)
{
  Eigen::MatrixXd data(3 * models[0].size(), models.size());
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t v = 0; v < models[i].size(); ++v)
      data.col(i).segment<3>(3 * v) = models[i][v];
  return data;
}

Eigen::VectorXd asVector(const std::vector<Vec3>& points)
{
  return dataMatrix({ points }).col(0);
}

/// `fields.size()` smooth fields over `base` whose amplitudes are
/// `amplitudes`, and `modelCount` random combinations of them.
ShapeList smoothCollection(const std::vector<Vec3>& base, const std::vector<double>& amplitudes, int modelCount,
  unsigned seed, std::vector<std::vector<Vec3>>* fieldsOut = nullptr)
{
  std::vector<std::vector<Vec3>> fields;
  for (std::size_t j = 0; j < amplitudes.size(); ++j)
    fields.push_back(smoothField(base, amplitudes[j], seed + static_cast<unsigned>(j)));
  if (fieldsOut)
    *fieldsOut = fields;
  return deformedCopies(base, fields, modelCount, seed + 1000);
}

Eigen::VectorXd factors(int modeCount, double value)
{
  return Eigen::VectorXd::Constant(modeCount, value);
}

double largestDeviation(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return a.rows() == b.rows() && a.cols() == b.cols() ? (a - b).cwiseAbs().maxCoeff()
                                                      : std::numeric_limits<double>::infinity();
}

/// Mode k's displacement of every vertex rotated by `rotation`.
Eigen::MatrixXd rotatedModes(const Eigen::MatrixXd& modes, const Eigen::Matrix3d& rotation)
{
  Eigen::MatrixXd result(modes.rows(), modes.cols());
  for (Eigen::Index k = 0; k < modes.cols(); ++k)
    for (Eigen::Index v = 0; v < modes.rows() / 3; ++v)
      result.col(k).segment<3>(3 * v) = rotation * modes.col(k).segment<3>(3 * v);
  return result;
}

} // namespace

TEST(MeshPCA, AllModesRebuildEveryModelExactly)
{
  const TriangleMesh base = bumpySphere(3);
  const ShapeList models = smoothCollection(base.points, { 0.2, 0.1, 0.1, 0.05, 0.05, 0.02, 0.01, 0.01, 0.01 }, 8, 1);
  MeshPCA pca;
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  ASSERT_EQ(pca.modeCount(), 7); // 8 models centred on their mean span 7 directions
  ASSERT_EQ(pca.modelCount(), 8);
  for (int i = 0; i < 8; ++i)
  {
    std::vector<Vec3> rebuilt;
    ASSERT_TRUE(synthesizeModel(pca, i, factors(7, 1.0), rebuilt).ok());
    double difference = 0.0, size = 0.0;
    for (std::size_t v = 0; v < rebuilt.size(); ++v)
    {
      difference = std::max(difference, (rebuilt[v] - models[i][v]).norm());
      size = std::max(size, (models[i][v] - pca.mean[v]).norm());
    }
    EXPECT_LT(difference, 1e-12 * size) << "model " << i;
  }
  EXPECT_NEAR(pca.explainedVarianceRatios.sum(), 1.0, 1e-13);
}

TEST(MeshPCA, ModesAreOrthonormalEvenWhenTheirScalesDifferWidely)
{
  // Singular values spread over five orders of magnitude: modes computed
  // from the Gram matrix alone would be orthogonal only to ~1e-6.
  const TriangleMesh base = bumpySphere(3);
  const ShapeList models = smoothCollection(base.points, { 1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5 }, 10, 2);
  MeshPCA pca;
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  ASSERT_EQ(pca.modeCount(), 6);
  const Eigen::MatrixXd product = pca.modes.transpose() * pca.modes;
  EXPECT_LT(largestDeviation(product, Eigen::MatrixXd::Identity(6, 6)), 1e-12);
  EXPECT_GT(pca.singularValues(0) / pca.singularValues(5), 1e4);
}

TEST(MeshPCA, AgreesWithADirectSVDOfTheCentredData)
{
  const TriangleMesh base = sphere(2);
  const ShapeList models = smoothCollection(base.points, { 0.3, 0.2, 0.1, 0.05, 0.02 }, 9, 3);
  MeshPCA pca;
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  ASSERT_EQ(pca.modeCount(), 5);

  const Eigen::MatrixXd data = dataMatrix(models);
  const Eigen::VectorXd mean = data.rowwise().mean();
  const Eigen::MatrixXd centred = data.colwise() - mean;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinU | Eigen::ComputeThinV);

  EXPECT_LT(largestDeviation(asVector(pca.mean), mean), 1e-15);
  for (int k = 0; k < 5; ++k)
  {
    EXPECT_NEAR(pca.singularValues(k), svd.singularValues()(k), 1e-12 * svd.singularValues()(0));
    // Same mode up to its sign, and coefficients that are the projections
    // of the centred models on it.
    const double sign = pca.modes.col(k).dot(svd.matrixU().col(k)) > 0.0 ? 1.0 : -1.0;
    EXPECT_LT(largestDeviation(pca.modes.col(k), sign * svd.matrixU().col(k)), 1e-10) << "mode " << k;
    EXPECT_LT(largestDeviation(pca.coefficients.col(k), centred.transpose() * pca.modes.col(k)), 1e-13);
    EXPECT_NEAR(pca.variances(k), pca.singularValues(k) * pca.singularValues(k) / 8.0, 1e-15);
  }
  EXPECT_NEAR(pca.totalVariance, centred.squaredNorm() / 8.0, 1e-13 * pca.totalVariance);
  EXPECT_NEAR(pca.explainedVarianceRatios(0), pca.variances(0) / pca.totalVariance, 1e-15);
  EXPECT_TRUE(std::is_sorted(pca.singularValues.data(), pca.singularValues.data() + 5,
    [](double a, double b) { return a > b; }));
}

TEST(MeshPCA, KeepsOnlyTheModesTheCollectionHasAndAsked)
{
  const TriangleMesh base = bumpySphere(2);
  std::vector<std::vector<Vec3>> fields;
  const ShapeList models = smoothCollection(base.points, { 0.2, 0.1, 0.05 }, 10, 4, &fields);
  MeshPCA pca;
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  ASSERT_EQ(pca.modeCount(), 3);
  EXPECT_NEAR(pca.explainedVarianceRatios.sum(), 1.0, 1e-13);
  // The modes span the fields the models were made of.
  for (const std::vector<Vec3>& field : fields)
  {
    const Eigen::VectorXd f = asVector(field);
    EXPECT_LT((f - pca.modes * (pca.modes.transpose() * f)).norm(), 1e-12 * f.norm());
  }

  ASSERT_TRUE(computeMeshPCA(models, 2, pca).ok());
  EXPECT_EQ(pca.modeCount(), 2);
  EXPECT_EQ(pca.coefficients.cols(), 2);
  EXPECT_LT(pca.explainedVarianceRatios.sum(), 1.0 - 1e-6);

  ASSERT_TRUE(computeMeshPCA(models, 0, pca).ok());
  EXPECT_EQ(pca.modeCount(), 0);
  EXPECT_EQ(pca.coefficients.rows(), 10);
  EXPECT_EQ(pca.mean.size(), base.points.size());

  // Identical models (up to round-off of a rigid motion undone) vary in
  // no direction at all.
  std::mt19937 random(5);
  ShapeList copies;
  for (int i = 0; i < 4; ++i)
    copies.push_back(moved(base.points, randomSimilarity(random, 3.0, 1.0, 1.0)));
  ShapeAlignment alignment;
  AlignmentOptions rigid;
  rigid.scaling = AlignmentScaling::None;
  ASSERT_TRUE(alignShapes(copies, base.triangles, rigid, alignment).ok());
  ASSERT_TRUE(computeMeshPCA(alignment.alignedModels, -1, pca).ok());
  EXPECT_EQ(pca.modeCount(), 0);
}

TEST(MeshPCA, TheLargestCoefficientOfEveryModeIsPositive)
{
  const TriangleMesh base = bumpySphere(2);
  const ShapeList models = smoothCollection(base.points, { 0.2, 0.1, 0.05, 0.03 }, 9, 6);
  MeshPCA pca;
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  for (int k = 0; k < pca.modeCount(); ++k)
  {
    Eigen::Index largest = 0;
    pca.coefficients.col(k).cwiseAbs().maxCoeff(&largest);
    EXPECT_GT(pca.coefficients(largest, k), 0.0) << "mode " << k;
  }
}

TEST(MeshPCA, Figure11TriplesOneModeOrDoublesThemAll)
{
  const TriangleMesh base = bumpySphere(2);
  const ShapeList models = smoothCollection(base.points, { 0.2, 0.1, 0.05, 0.03, 0.02 }, 8, 7);
  MeshPCA pca;
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  ASSERT_EQ(pca.modeCount(), 5);
  const Eigen::VectorXd original = asVector(models[0]);
  const Eigen::VectorXd mean = asVector(pca.mean);

  // Tripling the third mode adds twice its share to the model.
  Eigen::VectorXd tripleThird = factors(5, 1.0);
  tripleThird(2) = 3.0;
  std::vector<Vec3> shape;
  ASSERT_TRUE(synthesizeModel(pca, 0, tripleThird, shape).ok());
  const Eigen::VectorXd expected = original + 2.0 * pca.coefficients(0, 2) * pca.modes.col(2);
  EXPECT_LT((asVector(shape) - expected).cwiseAbs().maxCoeff(), 1e-12);

  // Doubling every mode doubles the model's difference from the mean.
  ASSERT_TRUE(synthesizeModel(pca, 0, factors(5, 2.0), shape).ok());
  EXPECT_LT((asVector(shape) - (mean + 2.0 * (original - mean))).cwiseAbs().maxCoeff(), 1e-12);

  // Any coefficients: the mean plus the modes they weigh.
  Eigen::VectorXd coefficients(5);
  coefficients << 0.5, -0.25, 0.0, 1.0, 2.0;
  ASSERT_TRUE(synthesizeShape(pca, coefficients, factors(5, 1.0), shape).ok());
  EXPECT_LT((asVector(shape) - (mean + pca.modes * coefficients)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(MeshPCA, ASimilarityOfTheCollectionRotatesTheModes)
{
  const TriangleMesh base = bumpySphere(3);
  std::mt19937 random(8);
  ShapeList models;
  for (const std::vector<Vec3>& model : smoothCollection(base.points, { 0.2, 0.1, 0.05, 0.03 }, 9, 8))
    models.push_back(moved(model, randomSimilarity(random, 4.0, 0.7, 1.4)));
  const SimilarityTransform motion = randomSimilarity(random, 10.0, 3.0, 3.0);
  ShapeList movedModels;
  for (const std::vector<Vec3>& model : models)
    movedModels.push_back(moved(model, motion));

  for (AlignmentScaling scaling :
    { AlignmentScaling::None, AlignmentScaling::EqualVolume, AlignmentScaling::UnitCentroidSize })
  {
    AlignmentOptions options;
    options.scaling = scaling;
    ShapeAlignment alignment, movedAlignment;
    ASSERT_TRUE(alignShapes(models, base.triangles, options, alignment).ok());
    ASSERT_TRUE(alignShapes(movedModels, base.triangles, options, movedAlignment).ok());
    MeshPCA pca, movedPCA;
    ASSERT_TRUE(computeMeshPCA(alignment.alignedModels, -1, pca).ok());
    ASSERT_TRUE(computeMeshPCA(movedAlignment.alignedModels, -1, movedPCA).ok());

    ASSERT_EQ(movedPCA.modeCount(), pca.modeCount());
    ASSERT_EQ(pca.modeCount(), 8);
    // Unit centroid size takes the collection's scale away; the others
    // keep the user's units, so it scales the result.
    const double scale = scaling == AlignmentScaling::UnitCentroidSize ? 1.0 : motion.scale;
    const double size = pca.singularValues(0);
    EXPECT_LT(largestDeviation(movedPCA.explainedVarianceRatios, pca.explainedVarianceRatios), 1e-9);
    EXPECT_LT(largestDeviation(movedPCA.singularValues, scale * pca.singularValues), 1e-9 * scale * size);
    EXPECT_LT(largestDeviation(movedPCA.coefficients, scale * pca.coefficients), 1e-9 * scale * size);
    // Only modes well separated from their neighbours are unique.
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_LT(largestDeviation(movedPCA.modes.col(k), rotatedModes(pca.modes.col(k), motion.rotation)), 1e-8)
        << "mode " << k;
    }
  }
}

TEST(MeshPCA, ModelsSpreadOverRanksGiveTheResultOfOneProcess)
{
  const TriangleMesh base = bumpySphere(3);
  const ShapeList models = smoothCollection(base.points, { 0.2, 0.1, 0.08, 0.05, 0.03, 0.02 }, 9, 9);
  MeshPCA serial;
  ASSERT_TRUE(computeMeshPCA(models, 5, serial).ok());
  ASSERT_EQ(serial.modeCount(), 5);
  for (const std::vector<int>& split :
    { std::vector<int>{ 9 }, std::vector<int>{ 5, 4 }, std::vector<int>{ 4, 0, 5 }, std::vector<int>{ 1, 1, 7 } })
  {
    std::mutex mutex;
    runOnRanks(static_cast<int>(split.size()), [&](Communicator& communicator) {
      MeshPCA part;
      const Status status = computeMeshPCA(partForRank(models, split, communicator.rank()), 5, communicator, part);
      const std::lock_guard<std::mutex> lock(mutex);
      ASSERT_TRUE(status.ok()) << status.message();
      ASSERT_EQ(part.modeCount(), 5);
      EXPECT_LT(maxDistance(part.mean, serial.mean), 1e-12);
      EXPECT_LT(largestDeviation(part.modes, serial.modes), 1e-10);
      EXPECT_LT(largestDeviation(part.singularValues, serial.singularValues), 1e-12);
      EXPECT_LT(largestDeviation(part.coefficients, serial.coefficients), 1e-12);
      EXPECT_LT(largestDeviation(part.explainedVarianceRatios, serial.explainedVarianceRatios), 1e-12);
      EXPECT_NEAR(part.totalVariance, serial.totalVariance, 1e-12 * serial.totalVariance);
    });
  }
}

TEST(MeshPCA, BadInputIsReportedByName)
{
  const TriangleMesh base = bumpySphere(2);
  MeshPCA pca;
  EXPECT_EQ(computeMeshPCA({}, -1, pca).message(), "the collection has no model");
  EXPECT_EQ(computeMeshPCA({ base.points }, -1, pca).message(),
    "principal components need at least two models; the collection has one");

  std::vector<Vec3> longer = base.points;
  longer.push_back(Vec3::Zero());
  EXPECT_EQ(computeMeshPCA({ base.points, longer }, -1, pca).message(),
    "model 1 has " + std::to_string(longer.size()) + " vertices but model 0 has " +
      std::to_string(base.points.size()) + "; every model must have the same connectivity");

  std::vector<Vec3> withNaN = base.points;
  withNaN[0].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(computeMeshPCA({ withNaN, base.points }, -1, pca).message(),
    "model 0, vertex 0: coordinate is not a finite number");

  const ShapeList models = smoothCollection(base.points, { 0.2, 0.1 }, 4, 10);
  ASSERT_TRUE(computeMeshPCA(models, -1, pca).ok());
  std::vector<Vec3> shape;
  EXPECT_EQ(synthesizeModel(pca, 0, factors(3, 1.0), shape).message(),
    "synthesis needs one coefficient and one factor per mode (2), got 2 coefficients and 3 factors");
  EXPECT_EQ(synthesizeModel(pca, 4, factors(2, 1.0), shape).message(),
    "model 4 is not in the collection of 4 models");
  EXPECT_FALSE(synthesizeShape(pca, Eigen::Vector2d(1.0, std::nan("")), factors(2, 1.0), shape).ok());

  // A mismatch on one rank stops every rank with the same message.
  const ShapeList mixed = { base.points, base.points, longer };
  std::mutex mutex;
  runOnRanks(2, [&](Communicator& communicator) {
    MeshPCA part;
    const Status status = computeMeshPCA(partForRank(mixed, { 2, 1 }, communicator.rank()), -1, communicator, part);
    const std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(status.message(),
      "model 2 has " + std::to_string(longer.size()) + " vertices but model 0 has " +
        std::to_string(base.points.size()) + "; every model must have the same connectivity")
      << "rank " << communicator.rank();
  });
}

namespace
{

/// Three smooth deformations of a four-legged animal standing along x with
/// y up: longer legs, a raised head and a fatter body, each moving the
/// surface by up to about a tenth of its size.
std::vector<std::vector<Vec3>> animalDeformations(const std::vector<Vec3>& points)
{
  Eigen::AlignedBox3d box;
  for (const Vec3& p : points)
    box.extend(p);
  const Vec3 centre = box.center(), extent = box.sizes();
  std::vector<std::vector<Vec3>> fields(3);
  for (const Vec3& p : points)
  {
    const Vec3 q = (p - centre).cwiseQuotient(extent); // about -0.5 .. 0.5
    const double below = 1.0 / (1.0 + std::exp(20.0 * q.y()));
    fields[0].push_back(Vec3(0.0, 0.2 * extent.y() * q.y() * below, 0.0));
    const double front = std::max(0.0, q.x());
    fields[1].push_back(Vec3(0.0, 0.4 * extent.y() * front * front, 0.0));
    const double body = std::exp(-8.0 * q.x() * q.x());
    fields[2].push_back(0.2 * body * Vec3(0.0, extent.y() * q.y(), extent.z() * q.z()));
  }
  return fields;
}

/// An orthonormal basis of the infinitesimal rigid motions of `shape`:
/// three translations and three rotations about its centroid.
Eigen::MatrixXd rigidDirections(const std::vector<Vec3>& shape)
{
  const Vec3 c = centroid(shape);
  Eigen::MatrixXd directions = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(shape.size()), 6);
  for (std::size_t v = 0; v < shape.size(); ++v)
  {
    const Vec3 r = shape[v] - c;
    for (int axis = 0; axis < 3; ++axis)
    {
      directions(3 * v + axis, axis) = 1.0;
      directions.col(3 + axis).segment<3>(3 * v) = Vec3::Unit(axis).cross(r);
    }
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(directions);
  return qr.householderQ() * Eigen::MatrixXd::Identity(directions.rows(), 6);
}

} // namespace

TEST(MeshPCA, RecoversTheDeformationsOfARealAnimalThroughAlignment)
{
  CMP_REQUIRE_SHARED_DATA();
  MeshFileData file;
  ASSERT_TRUE(readOFF(sharedDataDir() + "/shrec07-fourleg/381.off", file).ok());
  const TriangleMesh& animal = file.mesh;
  const double diagonal = boundingBoxDiagonal(animal);
  const std::vector<std::vector<Vec3>> fields = animalDeformations(animal.points);
  const ShapeList models = deformedCopies(animal.points, fields, 12, 11);

  // As they are made, the models vary in exactly three directions, the
  // span of the deformations.
  MeshPCA raw;
  ASSERT_TRUE(computeMeshPCA(models, -1, raw).ok());
  ASSERT_EQ(raw.modeCount(), 3);
  EXPECT_NEAR(raw.explainedVarianceRatios.sum(), 1.0, 1e-12);
  for (const std::vector<Vec3>& field : fields)
  {
    const Eigen::VectorXd f = asVector(field);
    EXPECT_LT((f - raw.modes * (raw.modes.transpose() * f)).norm(), 1e-10 * f.norm());
  }

  // Thrown about by rigid motions, then aligned: the alignment ends in the
  // frame of model 0, where it gives what aligning the unmoved models
  // gave, moved by model 0's motion.
  std::mt19937 random(12);
  std::vector<SimilarityTransform> motions;
  ShapeList movedModels;
  for (const std::vector<Vec3>& model : models)
  {
    motions.push_back(randomSimilarity(random, diagonal, 1.0, 1.0));
    movedModels.push_back(moved(model, motions.back()));
  }
  AlignmentOptions rigid;
  rigid.scaling = AlignmentScaling::None;
  ShapeAlignment alignment, movedAlignment;
  ASSERT_TRUE(alignShapes(models, animal.triangles, rigid, alignment).ok());
  ASSERT_TRUE(alignShapes(movedModels, animal.triangles, rigid, movedAlignment).ok());
  EXPECT_TRUE(movedAlignment.converged);
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    EXPECT_LT(
      maxDistance(movedAlignment.alignedModels[i], moved(alignment.alignedModels[i], motions[0])), 1e-9 * diagonal);
  }

  // Aligned, the collection varies again essentially in three directions,
  // those of the deformations less their rigid part (up to second-order
  // terms, as the alignment of a deformed model is not exactly linear in
  // the deformation). Unaligned, the motions spread the variance.
  MeshPCA aligned, unaligned;
  ASSERT_TRUE(computeMeshPCA(alignment.alignedModels, -1, aligned).ok());
  ASSERT_TRUE(computeMeshPCA(movedModels, -1, unaligned).ok());
  EXPECT_LT(1.0 - aligned.explainedVarianceRatios.head(3).sum(), 1e-3);
  EXPECT_GT(1.0 - unaligned.explainedVarianceRatios.head(3).sum(), 1e-2);
  const Eigen::MatrixXd rigidMotions = rigidDirections(aligned.mean);
  const Eigen::MatrixXd deformationModes = aligned.modes.leftCols(3);
  for (const std::vector<Vec3>& field : fields)
  {
    Eigen::VectorXd f = asVector(field);
    f -= rigidMotions * (rigidMotions.transpose() * f);
    EXPECT_LT((f - deformationModes * (deformationModes.transpose() * f)).norm(), 0.05 * f.norm());
  }

  // Rescaled too, and aligned to equal volume: every model encloses the
  // mean of the input volumes, so the result is the unmoved one moved by
  // model 0's rigid motion and scaled by the cube root of the ratio of
  // the mean volumes.
  ShapeList scaledModels;
  double volume = 0.0, scaledVolume = 0.0;
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    std::uniform_real_distribution<double> scale(0.5, 2.0);
    SimilarityTransform motion = motions[i];
    motion.scale = scale(random);
    scaledModels.push_back(moved(models[i], motion));
    volume += enclosedVolume(models[i], animal.triangles);
    scaledVolume += enclosedVolume(scaledModels.back(), animal.triangles);
  }
  AlignmentOptions equalVolume;
  equalVolume.scaling = AlignmentScaling::EqualVolume;
  ShapeAlignment volumeAlignment, scaledAlignment;
  ASSERT_TRUE(alignShapes(models, animal.triangles, equalVolume, volumeAlignment).ok());
  ASSERT_TRUE(alignShapes(scaledModels, animal.triangles, equalVolume, scaledAlignment).ok());
  SimilarityTransform firstMotion = motions[0];
  firstMotion.scale = std::cbrt(scaledVolume / volume);
  firstMotion.translation =
    centroid(scaledModels[0]) - firstMotion.scale * (firstMotion.rotation * centroid(models[0]));
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    EXPECT_NEAR(enclosedVolume(scaledAlignment.alignedModels[i], animal.triangles), scaledVolume / 12.0,
      1e-12 * scaledVolume);
    EXPECT_LT(maxDistance(scaledAlignment.alignedModels[i], moved(volumeAlignment.alignedModels[i], firstMotion)),
      1e-9 * diagonal);
  }
}
