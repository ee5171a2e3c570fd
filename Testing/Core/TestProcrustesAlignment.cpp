#include <cmp/analysis/ProcrustesAlignment.h>
#include "TestMeshes.h"
#include "TestShapes.h"
#include "ThreadCommunicator.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>

using namespace cmp;
using namespace cmp::test;

namespace
{

/// A bumpy sphere and `modelCount` smooth deformations of it.
struct Collection
{
  TriangleMesh base = bumpySphere(3);
  ShapeList models;
};

Collection deformedCollection(int modelCount, unsigned seed)
{
  Collection collection;
  const std::vector<std::vector<Vec3>> fields = { smoothField(collection.base.points, 0.1, seed),
    smoothField(collection.base.points, 0.05, seed + 1), smoothField(collection.base.points, 0.03, seed + 2) };
  collection.models = deformedCopies(collection.base.points, fields, modelCount, seed + 3);
  return collection;
}

/// Every model moved by its own random similarity (scale 1 unless
/// `scaled`).
ShapeList randomlyMoved(const ShapeList& models, unsigned seed, bool scaled)
{
  std::mt19937 random(seed);
  ShapeList result;
  for (const std::vector<Vec3>& model : models)
    result.push_back(moved(model, randomSimilarity(random, 5.0, scaled ? 0.5 : 1.0, scaled ? 2.0 : 1.0)));
  return result;
}

double sumOfSquaredDistances(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  double sum = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    sum += (a[v] - b[v]).squaredNorm();
  return sum;
}

AlignmentOptions withScaling(AlignmentScaling scaling)
{
  AlignmentOptions options;
  options.scaling = scaling;
  return options;
}

} // namespace

TEST(ProcrustesAlignment, VolumeAndCentroidSizeOfKnownShapes)
{
  // |x| + |y| + |z| <= 1 encloses 4/3; its six vertices lie at distance 1
  // from the centroid.
  const TriangleMesh octahedron = cmp::test::octahedron();
  EXPECT_NEAR(enclosedVolume(octahedron.points, octahedron.triangles), 4.0 / 3.0, 1e-15);
  EXPECT_NEAR(centroidSize(octahedron.points), std::sqrt(6.0), 1e-15);

  // Far from the origin the volume keeps its digits.
  const TriangleMesh far = tetrahedron(Vec3(1e6, -2e6, 3e6));
  EXPECT_NEAR(enclosedVolume(far.points, far.triangles), 1.0 / 6.0, 1e-9);

  TriangleMesh inverted = octahedron;
  for (Triangle& t : inverted.triangles)
    std::swap(t[1], t[2]);
  EXPECT_NEAR(enclosedVolume(inverted.points, inverted.triangles), -4.0 / 3.0, 1e-15);
}

TEST(ProcrustesAlignment, RigidCopiesLandOnTheFirstModel)
{
  const TriangleMesh base = bumpySphere(3);
  const ShapeList models = randomlyMoved(ShapeList(6, base.points), 7, false);

  ShapeAlignment alignment;
  ASSERT_TRUE(alignShapes(models, base.triangles, withScaling(AlignmentScaling::None), alignment).ok());
  EXPECT_TRUE(alignment.converged);
  EXPECT_LE(alignment.iterations, 3);
  ASSERT_EQ(alignment.alignedModels.size(), models.size());
  ASSERT_EQ(alignment.transforms.size(), models.size());
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    EXPECT_LT(maxDistance(alignment.alignedModels[i], models[0]), 1e-12) << "model " << i;
    EXPECT_LT(maxDistance(moved(models[i], alignment.transforms[i]), alignment.alignedModels[i]), 1e-12);
    EXPECT_NEAR(alignment.transforms[i].rotation.determinant(), 1.0, 1e-14);
    EXPECT_NEAR(alignment.transforms[i].scale, 1.0, 0.0);
  }
  EXPECT_LT(maxDistance(alignment.mean, models[0]), 1e-12);
  EXPECT_TRUE(alignment.transforms[0].rotation.isIdentity(1e-14));
}

TEST(ProcrustesAlignment, EqualVolumeBringsEveryModelToTheMeanVolume)
{
  const Collection collection = deformedCollection(7, 11);
  const ShapeList models = randomlyMoved(collection.models, 12, true);
  double meanVolume = 0.0;
  for (const std::vector<Vec3>& model : models)
    meanVolume += enclosedVolume(model, collection.base.triangles) / static_cast<double>(models.size());

  ShapeAlignment alignment;
  ASSERT_TRUE(
    alignShapes(models, collection.base.triangles, withScaling(AlignmentScaling::EqualVolume), alignment).ok());
  EXPECT_TRUE(alignment.converged);
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    EXPECT_NEAR(enclosedVolume(alignment.alignedModels[i], collection.base.triangles), meanVolume,
      1e-12 * meanVolume);
    EXPECT_LT(maxDistance(moved(models[i], alignment.transforms[i]), alignment.alignedModels[i]), 1e-12);
  }
  // Model 0 keeps its place and orientation; only its size changes.
  const Vec3 c0 = centroid(models[0]);
  for (std::size_t v = 0; v < models[0].size(); ++v)
  {
    const Vec3 expected = c0 + alignment.transforms[0].scale * (models[0][v] - c0);
    EXPECT_LT((alignment.alignedModels[0][v] - expected).norm(), 1e-12);
  }
  EXPECT_LT((centroid(alignment.mean) - c0).norm(), 1e-12);
}

TEST(ProcrustesAlignment, UnitCentroidSizeNormalisesEveryModel)
{
  const Collection collection = deformedCollection(5, 21);
  const ShapeList models = randomlyMoved(collection.models, 22, true);
  ShapeAlignment alignment;
  ASSERT_TRUE(
    alignShapes(models, collection.base.triangles, withScaling(AlignmentScaling::UnitCentroidSize), alignment).ok());
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    EXPECT_NEAR(centroidSize(alignment.alignedModels[i]), 1.0, 1e-13);
    EXPECT_LT((centroid(alignment.alignedModels[i]) - centroid(models[0])).norm(), 1e-12);
    EXPECT_NEAR(alignment.transforms[i].scale * centroidSize(models[i]), 1.0, 1e-13);
  }
}

TEST(ProcrustesAlignment, AlignedModelsAreClosestToTheirMean)
{
  const Collection collection = deformedCollection(6, 31);
  const ShapeList models = randomlyMoved(collection.models, 32, false);
  AlignmentOptions options = withScaling(AlignmentScaling::None);
  options.tolerance = 1e-14;
  ShapeAlignment alignment;
  ASSERT_TRUE(alignShapes(models, collection.base.triangles, options, alignment).ok());
  ASSERT_TRUE(alignment.converged);

  // The mean is the mean of the aligned models ...
  std::vector<Vec3> mean(models[0].size(), Vec3::Zero());
  for (const std::vector<Vec3>& aligned : alignment.alignedModels)
    for (std::size_t v = 0; v < mean.size(); ++v)
      mean[v] += aligned[v] / static_cast<double>(models.size());
  EXPECT_LT(maxDistance(mean, alignment.mean), 1e-13);

  // ... and no small rotation or shift of an aligned model brings it closer.
  std::mt19937 random(33);
  std::normal_distribution<double> gaussian;
  for (const std::vector<Vec3>& aligned : alignment.alignedModels)
  {
    const double best = sumOfSquaredDistances(aligned, alignment.mean);
    const Vec3 c = centroid(aligned);
    for (int trial = 0; trial < 10; ++trial)
    {
      SimilarityTransform nudge;
      const Vec3 axis = Vec3(gaussian(random), gaussian(random), gaussian(random)).normalized();
      nudge.rotation = Eigen::AngleAxisd(1e-3, axis).toRotationMatrix();
      nudge.translation = c - nudge.rotation * c + 1e-4 * Vec3(gaussian(random), gaussian(random), gaussian(random));
      EXPECT_GT(sumOfSquaredDistances(moved(aligned, nudge), alignment.mean), best);
    }
  }
}

TEST(ProcrustesAlignment, NeverReflects)
{
  // A mirror image cannot be rotated onto the original: the best proper
  // rotation is returned, and no reflection sneaks in.
  const TriangleMesh base = bumpySphere(2);
  std::vector<Vec3> mirrored = base.points;
  for (Vec3& p : mirrored)
    p.x() = -p.x();
  ShapeAlignment alignment;
  ASSERT_TRUE(
    alignShapes({ base.points, mirrored }, base.triangles, withScaling(AlignmentScaling::None), alignment).ok());
  for (const SimilarityTransform& transform : alignment.transforms)
  {
    EXPECT_NEAR(transform.rotation.determinant(), 1.0, 1e-14);
    EXPECT_TRUE((transform.rotation.transpose() * transform.rotation).isIdentity(1e-14));
  }
}

TEST(ProcrustesAlignment, OneSimilarityOfTheCollectionMovesTheResultRigidly)
{
  const Collection collection = deformedCollection(6, 41);
  const ShapeList models = randomlyMoved(collection.models, 42, true);
  std::mt19937 random(43);
  const SimilarityTransform motion = randomSimilarity(random, 10.0, 2.5, 2.5);
  ShapeList movedModels;
  for (const std::vector<Vec3>& model : models)
    movedModels.push_back(moved(model, motion));
  const Vec3 c0 = centroid(models[0]), movedC0 = centroid(movedModels[0]);

  for (AlignmentScaling scaling :
    { AlignmentScaling::None, AlignmentScaling::EqualVolume, AlignmentScaling::UnitCentroidSize })
  {
    ShapeAlignment original, copy;
    ASSERT_TRUE(alignShapes(models, collection.base.triangles, withScaling(scaling), original).ok());
    ASSERT_TRUE(alignShapes(movedModels, collection.base.triangles, withScaling(scaling), copy).ok());
    // Unit centroid size takes the collection's scale away; the others
    // keep the user's units, so it scales the result.
    const double scale = scaling == AlignmentScaling::UnitCentroidSize ? 1.0 : motion.scale;
    for (std::size_t i = 0; i < models.size(); ++i)
    {
      for (std::size_t v = 0; v < models[i].size(); ++v)
      {
        const Vec3 expected = movedC0 + scale * (motion.rotation * (original.alignedModels[i][v] - c0));
        EXPECT_LT((copy.alignedModels[i][v] - expected).norm(), 1e-9) << "model " << i << " vertex " << v;
      }
    }
  }
}

TEST(ProcrustesAlignment, ModelsSpreadOverRanksAlignAsInOneProcess)
{
  const Collection collection = deformedCollection(7, 51);
  const ShapeList models = randomlyMoved(collection.models, 52, true);
  for (AlignmentScaling scaling : { AlignmentScaling::EqualVolume, AlignmentScaling::UnitCentroidSize })
  {
    ShapeAlignment serial;
    ASSERT_TRUE(alignShapes(models, collection.base.triangles, withScaling(scaling), serial).ok());
    for (const std::vector<int>& split : { std::vector<int>{ 4, 3 }, std::vector<int>{ 0, 4, 0, 3 },
           std::vector<int>{ 1, 1, 5 } })
    {
      std::mutex mutex;
      runOnRanks(static_cast<int>(split.size()), [&](Communicator& communicator) {
        const int first = std::accumulate(split.begin(), split.begin() + communicator.rank(), 0);
        ShapeAlignment part;
        const Status status = alignShapes(partForRank(models, split, communicator.rank()),
          collection.base.triangles, withScaling(scaling), communicator, part);
        const std::lock_guard<std::mutex> lock(mutex);
        ASSERT_TRUE(status.ok()) << status.message();
        EXPECT_EQ(part.iterations, serial.iterations);
        EXPECT_LT(maxDistance(part.mean, serial.mean), 1e-10);
        ASSERT_EQ(part.alignedModels.size(), static_cast<std::size_t>(split[communicator.rank()]));
        for (std::size_t i = 0; i < part.alignedModels.size(); ++i)
        {
          EXPECT_LT(maxDistance(part.alignedModels[i], serial.alignedModels[first + i]), 1e-10);
          EXPECT_NEAR(part.transforms[i].scale, serial.transforms[first + i].scale, 1e-12);
        }
      });
    }
  }
}

TEST(ProcrustesAlignment, StopsAtTheIterationLimit)
{
  const Collection collection = deformedCollection(6, 61);
  const ShapeList models = randomlyMoved(collection.models, 62, false);
  AlignmentOptions options = withScaling(AlignmentScaling::None);
  options.maximumIterations = 1;
  options.tolerance = 1e-15;
  ShapeAlignment alignment;
  ASSERT_TRUE(alignShapes(models, collection.base.triangles, options, alignment).ok());
  EXPECT_FALSE(alignment.converged);
  EXPECT_EQ(alignment.iterations, 1);
  EXPECT_GT(alignment.lastChange, options.tolerance);
  EXPECT_EQ(alignment.alignedModels.size(), models.size());
}

TEST(ProcrustesAlignment, BadInputIsReportedByName)
{
  const TriangleMesh base = bumpySphere(2);
  const AlignmentOptions equalVolume = withScaling(AlignmentScaling::EqualVolume);
  ShapeAlignment alignment;

  Status status = alignShapes({}, base.triangles, equalVolume, alignment);
  EXPECT_EQ(status.message(), "the collection has no model");

  std::vector<Vec3> shorter(base.points.begin(), base.points.end() - 1);
  status = alignShapes({ base.points, base.points, shorter }, base.triangles, equalVolume, alignment);
  EXPECT_EQ(status.message(),
    "model 2 has " + std::to_string(shorter.size()) + " vertices but model 0 has " +
      std::to_string(base.points.size()) + "; every model must have the same connectivity");

  std::vector<Vec3> withNaN = base.points;
  withNaN[17].y() = std::numeric_limits<double>::quiet_NaN();
  status = alignShapes({ base.points, withNaN }, base.triangles, equalVolume, alignment);
  EXPECT_EQ(status.message(), "model 1, vertex 17: coordinate is not a finite number");

  std::vector<Vec3> flat = base.points;
  for (Vec3& p : flat)
    p.z() = 0.0;
  status = alignShapes({ base.points, flat }, base.triangles, equalVolume, alignment);
  EXPECT_NE(status.message().find("model 1 encloses no volume"), std::string::npos) << status.message();
  // Without volumes, a flat model is fine.
  EXPECT_TRUE(alignShapes({ base.points, flat }, base.triangles, withScaling(AlignmentScaling::None), alignment).ok());

  std::vector<Vec3> mirrored = base.points;
  for (Vec3& p : mirrored)
    p.x() = -p.x();
  status = alignShapes({ base.points, mirrored }, base.triangles, equalVolume, alignment);
  EXPECT_NE(status.message().find("model 1 encloses a volume of the opposite sign"), std::string::npos)
    << status.message();

  std::vector<Triangle> badTriangles = base.triangles;
  badTriangles[3][1] = static_cast<int>(base.points.size());
  status = alignShapes({ base.points, base.points }, badTriangles, equalVolume, alignment);
  EXPECT_EQ(status.message(),
    "triangle 3 has vertex index " + std::to_string(base.points.size()) + ", outside 0.." +
      std::to_string(base.points.size() - 1));

  std::vector<Vec3> point(base.points.size(), Vec3(1, 2, 3));
  status = alignShapes({ base.points, point }, base.triangles, withScaling(AlignmentScaling::UnitCentroidSize),
    alignment);
  EXPECT_EQ(status.message(),
    "model 1 has all its vertices at one point, so it cannot be scaled to unit centroid size");

  AlignmentOptions badOptions;
  badOptions.tolerance = 0.0;
  EXPECT_FALSE(alignShapes({ base.points }, base.triangles, badOptions, alignment).ok());
  badOptions = AlignmentOptions();
  badOptions.maximumIterations = 0;
  EXPECT_FALSE(alignShapes({ base.points }, base.triangles, badOptions, alignment).ok());
}

TEST(ProcrustesAlignment, EveryRankReportsTheErrorOfAnyRank)
{
  const TriangleMesh base = bumpySphere(2);
  std::vector<Vec3> withNaN = base.points;
  withNaN[5].x() = std::numeric_limits<double>::infinity();
  const ShapeList models = { base.points, base.points, base.points, withNaN };
  const std::vector<int> split = { 2, 0, 2 };
  std::mutex mutex;
  runOnRanks(3, [&](Communicator& communicator) {
    ShapeAlignment alignment;
    const Status status = alignShapes(partForRank(models, split, communicator.rank()), base.triangles,
      AlignmentOptions(), communicator, alignment);
    const std::lock_guard<std::mutex> lock(mutex);
    EXPECT_EQ(status.message(), "model 3, vertex 5: coordinate is not a finite number")
      << "rank " << communicator.rank();
  });
}
