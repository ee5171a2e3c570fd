#include "FilterTestUtilities.h"
#include "TestData.h"
#include "vtkCMPSemiRegularRemesher.h"
#include "vtkCMPWaveletDetailTransfer.h"

#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace cmp::test;

namespace
{

/// Remeshes `models` (a multiblock of parameterized surfaces) on `l0`.
vtkSmartPointer<vtkMultiBlockDataSet> remesh(vtkMultiBlockDataSet* models, vtkPolyData* l0, int level,
  double adaptiveTolerance = 0.0)
{
  vtkNew<vtkCMPSemiRegularRemesher> remesher;
  remesher->SetInputData(0, models);
  remesher->SetInputData(1, l0);
  remesher->SetLevel(level);
  remesher->SetAdaptiveTolerance(adaptiveTolerance);
  remesher->ComputeDistanceOff();
  const RunResult result = run(remesher);
  EXPECT_TRUE(result.succeeded) << result.error;
  return vtkMultiBlockDataSet::SafeDownCast(remesher->GetOutputDataObject(0));
}

vtkPolyData* block(vtkMultiBlockDataSet* blocks, unsigned b)
{
  return vtkPolyData::SafeDownCast(blocks->GetBlock(b));
}

/// Largest coordinate difference between the points of `a` and `b`, over
/// the first `count` points (all when negative).
double largestDistance(vtkPolyData* a, vtkPolyData* b, vtkIdType count = -1)
{
  if (count < 0)
  {
    EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    count = std::min(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  }
  double worst = 0.0;
  for (vtkIdType v = 0; v < count; ++v)
    for (int i = 0; i < 3; ++i)
      worst = std::max(worst, std::abs(a->GetPoint(v)[i] - b->GetPoint(v)[i]));
  return worst;
}

double diagonalOf(vtkPolyData* surface)
{
  return surface->GetLength();
}

struct Transfer
{
  RunResult result;
  vtkSmartPointer<vtkPolyData> shape;
  vtkSmartPointer<vtkMultiBlockDataSet> levels;
};

/// Runs the filter on `collection` as configured by `configure`.
template <class Configure>
Transfer transfer(vtkDataObject* collection, Configure configure)
{
  vtkNew<vtkCMPWaveletDetailTransfer> filter;
  filter->SetInputData(collection);
  configure(filter.Get());
  Transfer t;
  t.result = run(filter);
  t.shape = filter->GetOutput();
  t.levels = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(1));
  return t;
}

/// The three shipped examples remeshed at level 3 (and adaptively) as one
/// collection.
class DetailTransferOnExamples : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    const std::string folder = examplesDir() + "/";
    l0_ = baseDomainOf(readLandmarked(folder + "blob.off", folder + "blob.vts"));
    models_ = parameterizedExamples(l0_);
    remeshes_ = remesh(models_, l0_, 3);
  }
  static void TearDownTestSuite() { l0_ = nullptr, models_ = remeshes_ = nullptr; }

  static vtkSmartPointer<vtkPolyData> l0_;
  static vtkSmartPointer<vtkMultiBlockDataSet> models_, remeshes_;
};
vtkSmartPointer<vtkPolyData> DetailTransferOnExamples::l0_;
vtkSmartPointer<vtkMultiBlockDataSet> DetailTransferOnExamples::models_, DetailTransferOnExamples::remeshes_;

TEST_F(DetailTransferOnExamples, ScheduleOfZerosOrOnesGivesEitherModelExactly)
{
  for (bool local : { true, false })
  {
    const Transfer a = transfer(remeshes_, [&](vtkCMPWaveletDetailTransfer* f) {
      f->SetCoarseModel(0), f->SetDetailModel(2), f->SetLocalFrames(local), f->SetDetailWeights({ 0, 0, 0, 0 });
    });
    ASSERT_TRUE(a.result.succeeded) << a.result.error;
    EXPECT_LT(largestDistance(a.shape, block(remeshes_, 0)), 1e-12 * diagonalOf(block(remeshes_, 0)));
    const Transfer b = transfer(remeshes_, [&](vtkCMPWaveletDetailTransfer* f) {
      f->SetCoarseModel(0), f->SetDetailModel(2), f->SetLocalFrames(local), f->SetDetailWeights({ 1, 1, 1, 1 });
    });
    ASSERT_TRUE(b.result.succeeded) << b.result.error;
    EXPECT_LT(largestDistance(b.shape, block(remeshes_, 2)), 1e-12 * diagonalOf(block(remeshes_, 2)));
  }
}

TEST_F(DetailTransferOnExamples, KeepsTheCoarseLevelsOfOneAndTheDetailsOfTheOther)
{
  const Transfer t = transfer(remeshes_, [](vtkCMPWaveletDetailTransfer* f) {
    f->SetCoarseModel(1), f->SetDetailModel(2), f->SetLastCoarseLevel(1), f->ScaleDetailsToCoarseSizeOff();
  });
  ASSERT_TRUE(t.result.succeeded) << t.result.error;
  const Transfer coarseAlone = transfer(remeshes_, [](vtkCMPWaveletDetailTransfer* f) {
    f->SetCoarseModel(1), f->SetDetailModel(1);
  });
  ASSERT_TRUE(coarseAlone.result.succeeded) << coarseAlone.result.error;
  EXPECT_LT(largestDistance(coarseAlone.shape, block(remeshes_, 1)), 1e-12 * diagonalOf(block(remeshes_, 1)));

  // Levels 0 and 1 of the result are the coarse model's; level 2 is not.
  ASSERT_EQ(t.levels->GetNumberOfBlocks(), 4u);
  for (unsigned l = 0; l <= 1; ++l)
    EXPECT_LT(largestDistance(block(t.levels, l), block(coarseAlone.levels, l)), 1e-12) << "level " << l;
  EXPECT_GT(largestDistance(block(t.levels, 2), block(coarseAlone.levels, 2)), 1e-3);
  for (unsigned l = 0; l < 4; ++l)
    EXPECT_STREQ(t.levels->GetMetaData(l)->Get(vtkCompositeDataSet::NAME()), ("Level " + std::to_string(l)).c_str());

  // The coefficients say where each part came from: the coarse model's
  // below level 2, the detail model's (unscaled, local) from level 2 on.
  vtkPointData* points = t.shape->GetPointData();
  vtkDataArray* blended = points->GetArray("WaveletCoefficients");
  vtkDataArray* ofCoarse = points->GetArray("CoarseModelCoefficients");
  vtkDataArray* ofDetail = points->GetArray("DetailModelCoefficients");
  vtkDataArray* levels = points->GetArray("VertexLevel");
  vtkDataArray* magnitude = points->GetArray("DetailMagnitude");
  ASSERT_TRUE(blended && ofCoarse && ofDetail && levels && magnitude);
  for (vtkIdType v = 0; v < t.shape->GetNumberOfPoints(); ++v)
  {
    vtkDataArray* expected = levels->GetComponent(v, 0) <= 1 ? ofCoarse : ofDetail;
    double length = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(blended->GetComponent(v, c), expected->GetComponent(v, c)) << "vertex " << v;
      length += blended->GetComponent(v, c) * blended->GetComponent(v, c);
    }
    EXPECT_NEAR(magnitude->GetComponent(v, 0), levels->GetComponent(v, 0) == 0 ? 0.0 : std::sqrt(length), 1e-12);
  }
  vtkDataArray* weights = t.shape->GetFieldData()->GetArray("DetailWeights");
  ASSERT_NE(weights, nullptr);
  EXPECT_EQ(weights->GetNumberOfTuples(), 4);
  EXPECT_EQ(weights->GetComponent(1, 0), 0.0);
  EXPECT_EQ(weights->GetComponent(2, 0), 1.0);
  EXPECT_GE(fieldValue(t.shape, "TransferSeconds"), 0.0);
  // The correspondence stays: landmarks are still vertices 0..F-1.
  ASSERT_NE(points->GetArray("FeatureId"), nullptr);
  EXPECT_EQ(points->GetArray("FeatureId")->GetComponent(3, 0), 3.0);
}

TEST_F(DetailTransferOnExamples, ReportsBadInput)
{
  const auto expectError = [](vtkDataObject* input, const std::string& expected, auto configure) {
    SCOPED_TRACE(expected);
    const Transfer t = transfer(input, configure);
    EXPECT_FALSE(t.result.succeeded);
    EXPECT_NE(t.result.error.find(expected), std::string::npos) << "got: " << t.result.error;
  };
  const auto defaults = [](vtkCMPWaveletDetailTransfer*) {};
  expectError(remeshes_, "CoarseModel 5: the collection has 3 models (0 to 2)",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetCoarseModel(5); });
  expectError(remeshes_, "DetailModel -1: the collection has 3 models",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetDetailModel(-1); });
  expectError(remeshes_, "DetailWeights has 2 entries; the level-3 remesh needs 4",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetDetailWeights({ 0, 1 }); });
  expectError(remeshes_, "DetailWeights has a NaN",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetDetailWeights({ 0, 1, std::nan(""), 1 }); });
  expectError(remeshes_, "LastCoarseLevel 4 is above the remesh's finest level 3",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetLastCoarseLevel(4); });
  // Out of the remesh levels: refused, not clamped.
  expectError(remeshes_, "LastCoarseLevel must be between 0 and 8 (it is -1)",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetLastCoarseLevel(-1); });
  expectError(remeshes_, "LastCoarseLevel must be between 0 and 8 (it is 9)",
    [](vtkCMPWaveletDetailTransfer* f) { f->SetLastCoarseLevel(9); });

  vtkSmartPointer<vtkMultiBlockDataSet> adaptive = remesh(models_, l0_, 3, 0.02);
  ASSERT_LT(block(adaptive, 0)->GetNumberOfCells(), block(remeshes_, 0)->GetNumberOfCells()) << "not adaptive";
  expectError(adaptive, "not a uniform semi-regular remesh (remesh with adaptive tolerance 0)", defaults);

  vtkNew<vtkPolyData> withoutLevels;
  withoutLevels->DeepCopy(block(remeshes_, 0));
  withoutLevels->GetPointData()->RemoveArray("VertexLevel");
  expectError(blocksOf({ withoutLevels, block(remeshes_, 1) }), "block 0: the model has no point array 'VertexLevel'",
    defaults);

  vtkSmartPointer<vtkMultiBlockDataSet> coarser = remesh(models_, l0_, 2);
  expectError(blocksOf({ block(remeshes_, 0), block(coarser, 1) }), "its connectivity differs from block 0", defaults);

  vtkSmartPointer<vtkPolyData> withNaN = withNaNAt(block(remeshes_, 1), 7);
  expectError(
    blocksOf({ block(remeshes_, 0), withNaN }), "block 1: point 7 has a NaN or infinite coordinate", defaults);

  vtkNew<vtkMultiBlockDataSet> none;
  expectError(none, "the input multiblock holds no surfaces", defaults);
}

/// The paper's Figure 13 on real data: SHREC'07 model 381's coarse shape
/// with 383's details at level 4.
TEST(WaveletDetailTransferFilter, FourLeggedDetailsOntoAnotherFourLeggedShape)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::string folder = sharedDataDir() + "/shrec07-fourleg/";
  vtkSmartPointer<vtkPolyData> l0 = baseDomainOf(readLandmarked(folder + "381.off", folder + "381.vts"));
  vtkNew<vtkMultiBlockDataSet> models;
  for (unsigned m = 0; m < 2; ++m)
  {
    const std::string name = m == 0 ? "381" : "383";
    models->SetBlock(m, parameterized(readLandmarked(folder + name + ".off", folder + name + ".vts"), l0));
  }
  vtkSmartPointer<vtkMultiBlockDataSet> remeshes = remesh(models, l0, 4);
  const Transfer t = transfer(remeshes, [](vtkCMPWaveletDetailTransfer* f) { f->SetLastCoarseLevel(2); });
  ASSERT_TRUE(t.result.succeeded) << t.result.error;
  const Transfer coarseAlone =
    transfer(remeshes, [](vtkCMPWaveletDetailTransfer* f) { f->SetDetailWeights({ 0, 0, 0, 0, 0 }); });
  ASSERT_TRUE(coarseAlone.result.succeeded) << coarseAlone.result.error;
  EXPECT_LT(largestDistance(coarseAlone.shape, block(remeshes, 0)), 1e-9 * diagonalOf(block(remeshes, 0)));

  // The shape is 381's up to level 2, and its finest details are 383's
  // (scaled by the ratio of the coarse sizes): the result differs from 381
  // by details only, well under a tenth of its size, and not by nothing.
  const double diagonal = diagonalOf(block(remeshes, 0));
  EXPECT_LT(largestDistance(block(t.levels, 2), block(coarseAlone.levels, 2)), 1e-9 * diagonal);
  const double change = largestDistance(t.shape, block(remeshes, 0));
  EXPECT_GT(change, 1e-3 * diagonal);
  EXPECT_LT(change, 0.1 * diagonal);
  // Landmark vertices keep 381's coarse place up to the details: the body
  // is where 381's is.
  double centre[2][3];
  t.shape->GetCenter(centre[0]);
  block(remeshes, 0)->GetCenter(centre[1]);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(centre[0][i], centre[1][i], 0.02 * diagonal);
}

} // namespace
