#include <cmp/analysis/ProcrustesAlignment.h>
#include <cmp/analysis/ShapeBlend.h>
#include "TestMeshes.h"
#include "TestShapes.h"
#include "ThreadCommunicator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <mutex>

using namespace cmp;
using namespace cmp::test;

namespace
{

ShapeList blendCollection()
{
  const TriangleMesh base = bumpySphere(2);
  const std::vector<std::vector<Vec3>> fields = { smoothField(base.points, 0.2, 1), smoothField(base.points, 0.1, 2) };
  std::mt19937 random(3);
  ShapeList models;
  for (const std::vector<Vec3>& model : deformedCopies(base.points, fields, 5, 4))
    models.push_back(moved(model, randomSimilarity(random, 2.0, 0.8, 1.2)));
  return models;
}

std::vector<double> unitWeight(std::size_t count, std::size_t model)
{
  std::vector<double> weights(count, 0.0);
  weights[model] = 1.0;
  return weights;
}

std::vector<Vec3> weightedSum(const ShapeList& models, const std::vector<double>& weights)
{
  std::vector<Vec3> sum(models[0].size(), Vec3::Zero());
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t v = 0; v < sum.size(); ++v)
      sum[v] += weights[i] * models[i][v];
  return sum;
}

} // namespace

TEST(ShapeBlend, AUnitWeightGivesThatModelExactly)
{
  const ShapeList models = blendCollection();
  for (std::size_t i = 0; i < models.size(); ++i)
  {
    ShapeBlend blend;
    ASSERT_TRUE(blendShapes(models, unitWeight(models.size(), i), blend).ok());
    EXPECT_EQ(blend.positions, models[i]) << "model " << i;
    EXPECT_FALSE(blend.extrapolating);
  }
}

TEST(ShapeBlend, IsTheAffineCombinationOfTheModels)
{
  const ShapeList models = blendCollection();
  const std::vector<double> inside = { 0.5, 0.25, 0.125, 0.125, 0.0 };
  ShapeBlend blend;
  ASSERT_TRUE(blendShapes(models, inside, blend).ok());
  EXPECT_LT(maxDistance(blend.positions, weightedSum(models, inside)), 1e-14);
  EXPECT_FALSE(blend.extrapolating);

  const std::vector<double> outside = { 1.5, -0.5, 0.0, 0.25, -0.25 };
  ASSERT_TRUE(blendShapes(models, outside, blend).ok());
  EXPECT_LT(maxDistance(blend.positions, weightedSum(models, outside)), 1e-13);
  EXPECT_TRUE(blend.extrapolating);

  // Weights summing to one make the blend follow the models when all move.
  SimilarityTransform shift;
  shift.translation = Vec3(3.0, -1.0, 2.0);
  ShapeList shifted;
  for (const std::vector<Vec3>& model : models)
    shifted.push_back(moved(model, shift));
  ShapeBlend shiftedBlend;
  ASSERT_TRUE(blendShapes(shifted, outside, shiftedBlend).ok());
  EXPECT_LT(maxDistance(shiftedBlend.positions, moved(blend.positions, shift)), 1e-13);
}

TEST(ShapeBlend, OfAlignedRigidCopiesIsTheFirstModel)
{
  const TriangleMesh base = bumpySphere(2);
  std::mt19937 random(5);
  ShapeList copies;
  for (int i = 0; i < 4; ++i)
    copies.push_back(moved(base.points, randomSimilarity(random, 3.0, 1.0, 1.0)));
  AlignmentOptions rigid;
  rigid.scaling = AlignmentScaling::None;
  ShapeAlignment alignment;
  ASSERT_TRUE(alignShapes(copies, base.triangles, rigid, alignment).ok());
  ShapeBlend blend;
  ASSERT_TRUE(blendShapes(alignment.alignedModels, { 0.7, -0.4, 0.5, 0.2 }, blend).ok());
  EXPECT_LT(maxDistance(blend.positions, copies[0]), 1e-12);
}

TEST(ShapeBlend, ModelsSpreadOverRanksBlendAsInOneProcess)
{
  const ShapeList models = blendCollection();
  const std::vector<double> weights = { 0.3, -0.2, 0.6, 0.1, 0.2 };
  ShapeBlend serial;
  ASSERT_TRUE(blendShapes(models, weights, serial).ok());
  const std::vector<int> split = { 2, 0, 3 };
  std::mutex mutex;
  runOnRanks(3, [&](Communicator& communicator) {
    const ShapeList part = partForRank(models, split, communicator.rank());
    ShapeBlend blend, first;
    const Status status = blendShapes(part, weights, communicator, blend);
    const Status firstStatus = blendShapes(part, unitWeight(models.size(), 0), communicator, first);
    const std::lock_guard<std::mutex> lock(mutex);
    ASSERT_TRUE(status.ok() && firstStatus.ok());
    EXPECT_LT(maxDistance(blend.positions, serial.positions), 1e-14);
    EXPECT_TRUE(blend.extrapolating);
    EXPECT_EQ(first.positions, models[0]);
  });
}

TEST(ShapeBlend, BadWeightsAreReported)
{
  const ShapeList models = blendCollection();
  ShapeBlend blend;
  EXPECT_EQ(blendShapes(models, { 0.5, 0.5 }, blend).message(),
    "blending needs one weight per model: got 2 weights for 5 models");
  EXPECT_EQ(blendShapes(models, { 0.5, 0.2, 0.1, 0.1, 0.0 }, blend).message(),
    "blending weights must sum to 1 (an affine combination), but they sum to 0.9");
  EXPECT_EQ(blendShapes(models, { 0.5, 0.5, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0 }, blend).message(),
    "the weight of model 2 is not a finite number");
  EXPECT_TRUE(blendShapes(models, { 0.5, 0.5 + 5e-10, 0.0, 0.0, 0.0 }, blend).ok());
  EXPECT_EQ(blendShapes({}, {}, blend).message(), "the collection has no model");
}
