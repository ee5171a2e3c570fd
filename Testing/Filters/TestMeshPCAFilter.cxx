#include "FilterTestUtilities.h"
#include "vtkCMPMeshPCA.h"
#include "vtkCMPSemiRegularRemesher.h"
#include "vtkCMPShapeBlend.h"

#include <vtkCellArray.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTable.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace cmp::test;

namespace
{

/// The three shipped examples remeshed at level 3 as one multiblock (one
/// connectivity), blocks named after the models.
class CollectionFilters : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    const std::string folder = examplesDir() + "/";
    vtkSmartPointer<vtkPolyData> l0 = baseDomainOf(readLandmarked(folder + "blob.off", folder + "blob.vts"));
    vtkSmartPointer<vtkMultiBlockDataSet> models = parameterizedExamples(l0);
    remeshes_ = remesh(models, l0, 3);
    coarse_ = remesh(models, l0, 2);
  }
  static void TearDownTestSuite() { remeshes_ = coarse_ = nullptr; }

  static vtkSmartPointer<vtkMultiBlockDataSet> remesh(vtkMultiBlockDataSet* models, vtkPolyData* l0, int level)
  {
    vtkNew<vtkCMPSemiRegularRemesher> remesher;
    remesher->SetInputData(0, models);
    remesher->SetInputData(1, l0);
    remesher->SetLevel(level);
    remesher->ComputeDistanceOff();
    const RunResult result = run(remesher);
    EXPECT_TRUE(result.succeeded) << result.error;
    return vtkMultiBlockDataSet::SafeDownCast(remesher->GetOutputDataObject(0));
  }

  static vtkPolyData* block(vtkMultiBlockDataSet* blocks, unsigned b) { return vtkPolyData::SafeDownCast(blocks->GetBlock(b)); }

  static double largestDistance(vtkPolyData* a, vtkPolyData* b)
  {
    EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    double worst = 0.0;
    for (vtkIdType v = 0; v < std::min(a->GetNumberOfPoints(), b->GetNumberOfPoints()); ++v)
      for (int i = 0; i < 3; ++i)
        worst = std::max(worst, std::abs(a->GetPoint(v)[i] - b->GetPoint(v)[i]));
    return worst;
  }

  static vtkSmartPointer<vtkMultiBlockDataSet> remeshes_, coarse_;
};
vtkSmartPointer<vtkMultiBlockDataSet> CollectionFilters::remeshes_, CollectionFilters::coarse_;

TEST_F(CollectionFilters, PCARebuildsEveryAlignedModelAndDescribesItsModes)
{
  vtkNew<vtkCMPMeshPCA> pca;
  pca->SetInputData(remeshes_);
  pca->SetNumberOfModes(-1);
  pca->SetSynthesisMode(-1);
  pca->SetSynthesisAllModesFactor(1.0);
  for (int model = 0; model < 3; ++model)
  {
    pca->SetSynthesisModel(model);
    const RunResult result = run(pca);
    ASSERT_TRUE(result.succeeded) << result.error;
    auto* aligned = vtkMultiBlockDataSet::SafeDownCast(pca->GetOutputDataObject(4));
    ASSERT_NE(aligned, nullptr);
    auto* synthesis = vtkPolyData::SafeDownCast(pca->GetOutputDataObject(3));
    // All modes: the synthesis is the aligned model, to round-off.
    EXPECT_LT(largestDistance(synthesis, block(aligned, model)), 1e-10) << "model " << model;
    EXPECT_EQ(synthesis->GetPolys()->GetNumberOfCells(), block(remeshes_, 0)->GetNumberOfPolys());
  }
  auto* mean = vtkPolyData::SafeDownCast(pca->GetOutputDataObject(0));
  EXPECT_EQ(fieldValue(mean, "ModelCount"), 3.0);
  const int modes = static_cast<int>(fieldValue(mean, "ModeCount"));
  EXPECT_EQ(modes, 2); // three models vary in at most two directions
  EXPECT_EQ(fieldValue(mean, "AlignmentConverged"), 1.0);
  ASSERT_NE(mean->GetPointData()->GetArray("Mode1"), nullptr);
  EXPECT_EQ(mean->GetPointData()->GetArray("Mode1")->GetNumberOfComponents(), 3);
  EXPECT_NE(mean->GetPointData()->GetArray("FeatureId"), nullptr);
  // Mode k carries one standard deviation: its squared norm is the variance.
  auto* variances = vtkTable::SafeDownCast(pca->GetOutputDataObject(2));
  ASSERT_EQ(variances->GetNumberOfRows(), modes);
  for (int k = 0; k < modes; ++k)
  {
    vtkDataArray* mode = mean->GetPointData()->GetArray(("Mode" + std::to_string(k)).c_str());
    double squared = 0.0;
    for (vtkIdType v = 0; v < mode->GetNumberOfTuples(); ++v)
      for (int i = 0; i < 3; ++i)
        squared += std::pow(mode->GetComponent(v, i), 2);
    EXPECT_NEAR(squared, variances->GetValueByName(k, "Variance").ToDouble(), 1e-9 * squared);
  }
  EXPECT_NEAR(variances->GetValueByName(modes - 1, "CumulativeRatio").ToDouble(), 1.0, 1e-12);
  auto* coefficients = vtkTable::SafeDownCast(pca->GetOutputDataObject(1));
  ASSERT_EQ(coefficients->GetNumberOfRows(), 3);
  EXPECT_EQ(coefficients->GetValueByName(1, "Model").ToString(), "capsule");
}

TEST_F(CollectionFilters, PCAIsBlindToHowTheCollectionIsPlaced)
{
  // The whole collection rotated, moved and scaled: with unit centroid
  // size the explained variances and coefficients do not change.
  vtkNew<vtkTransform> motion;
  motion->Translate(3, -1, 2);
  motion->RotateWXYZ(50, 1, 2, 3);
  motion->Scale(2.5, 2.5, 2.5);
  vtkNew<vtkMultiBlockDataSet> moved;
  for (unsigned b = 0; b < 3; ++b)
  {
    vtkNew<vtkTransformFilter> apply;
    apply->SetInputData(block(remeshes_, b));
    apply->SetTransform(motion);
    apply->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    apply->Update();
    moved->SetBlock(b, apply->GetOutput());
  }
  std::array<vtkSmartPointer<vtkTable>, 2> tables;
  std::array<vtkDataObject*, 2> inputs{ { remeshes_, moved } };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkCMPMeshPCA> pca;
    pca->SetInputData(inputs[i]);
    pca->SetAlignment(vtkCMPMeshPCA::RIGID_UNIT_CENTROID_SIZE);
    const RunResult result = run(pca);
    ASSERT_TRUE(result.succeeded) << result.error;
    tables[i] = vtkTable::SafeDownCast(pca->GetOutputDataObject(1));
    tables[i]->Register(nullptr);
    tables[i]->Delete();
  }
  for (vtkIdType row = 0; row < 3; ++row)
    for (const char* column : { "Coefficient0", "Coefficient1" })
      EXPECT_NEAR(std::abs(tables[0]->GetValueByName(row, column).ToDouble()),
        std::abs(tables[1]->GetValueByName(row, column).ToDouble()), 1e-9)
        << column << " of model " << row;
}

TEST_F(CollectionFilters, BlendGivesAModelExactlyAndSaysWhenItExtrapolates)
{
  vtkNew<vtkCMPShapeBlend> blend;
  blend->SetInputData(remeshes_);
  blend->SetAlignment(0);
  const auto output = [&blend] { return vtkPolyData::SafeDownCast(blend->GetOutputDataObject(0)); };
  blend->SetWeights({ 0.0, 1.0, 0.0 });
  RunResult result = run(blend);
  ASSERT_TRUE(result.succeeded) << result.error;
  EXPECT_EQ(largestDistance(output(), block(remeshes_, 1)), 0.0);
  EXPECT_EQ(fieldValue(output(), "Extrapolating"), 0.0);

  blend->SetWeights({ 1.5, -0.5, 0.0 });
  result = run(blend);
  ASSERT_TRUE(result.succeeded) << result.error;
  EXPECT_EQ(fieldValue(output(), "Extrapolating"), 1.0);
  // Affine: 1.5 a - 0.5 b, vertex for vertex.
  vtkPolyData* a = block(remeshes_, 0);
  vtkPolyData* b = block(remeshes_, 1);
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); v += 97)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(output()->GetPoint(v)[i], 1.5 * a->GetPoint(v)[i] - 0.5 * b->GetPoint(v)[i], 1e-12);

  // Aligned (the default) a blend of one model is that model, aligned: the
  // same shape, so the same edge lengths.
  blend->SetAlignment(1);
  blend->SetWeights({ 1.0, 0.0, 0.0 });
  ASSERT_TRUE(run(blend).succeeded);
  vtkPolyData* aligned = output();
  for (vtkIdType v = 1; v < a->GetNumberOfPoints(); v += 101)
  {
    double d0 = 0, d1 = 0;
    for (int i = 0; i < 3; ++i)
    {
      d0 += std::pow(a->GetPoint(v)[i] - a->GetPoint(0)[i], 2);
      d1 += std::pow(aligned->GetPoint(v)[i] - aligned->GetPoint(0)[i], 2);
    }
    EXPECT_NEAR(std::sqrt(d0), std::sqrt(d1), 1e-9);
  }
}

TEST_F(CollectionFilters, RefuseCollectionsWithoutOneConnectivity)
{
  const auto expectError = [](vtkAlgorithm* filter, vtkDataObject* input, const std::string& expected)
  {
    filter->SetInputDataObject(0, input);
    const RunResult result = run(filter);
    EXPECT_FALSE(result.succeeded);
    EXPECT_NE(result.error.find(expected), std::string::npos) << result.error;
  };
  vtkNew<vtkCMPMeshPCA> pca;
  vtkNew<vtkCMPShapeBlend> blend;
  blend->SetWeights({ 0.5, 0.5 });

  vtkNew<vtkMultiBlockDataSet> mixed; // levels 3 and 2
  mixed->SetBlock(0, block(remeshes_, 0));
  mixed->SetBlock(1, block(coarse_, 1));
  mixed->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "capsule");
  for (vtkAlgorithm* filter : { static_cast<vtkAlgorithm*>(pca), static_cast<vtkAlgorithm*>(blend) })
    expectError(filter, mixed, "block 1 ('capsule'): its connectivity differs from block 0");

  vtkNew<vtkPolyData> reordered; // same sizes, one triangle turned
  reordered->DeepCopy(block(remeshes_, 1));
  vtkIdType ids[3];
  {
    vtkNew<vtkIdList> cell;
    reordered->GetCellPoints(5, cell);
    ids[0] = cell->GetId(1);
    ids[1] = cell->GetId(2);
    ids[2] = cell->GetId(0);
    reordered->ReplaceCell(5, 3, ids);
  }
  vtkNew<vtkMultiBlockDataSet> turned;
  turned->SetBlock(0, block(remeshes_, 0));
  turned->SetBlock(1, reordered);
  expectError(pca, turned, "block 1: its connectivity differs from block 0: triangle 5 is");

  vtkSmartPointer<vtkPolyData> withNaN = withNaNAt(block(remeshes_, 1), 7);
  expectError(pca, blocksOf({ block(remeshes_, 0), withNaN }), "block 1: point 7 has a NaN or infinite coordinate");

  vtkNew<vtkMultiBlockDataSet> one;
  one->SetBlock(0, block(remeshes_, 0));
  expectError(pca, one, "at least two models (the input has 1)");
  expectError(pca, block(remeshes_, 0), "at least two models (the input has 1)");
  vtkNew<vtkMultiBlockDataSet> none;
  expectError(pca, none, "the input multiblock holds no surfaces");

  expectError(blend, remeshes_, "give one weight per model: 2 weights for 3 models");
  blend->SetWeights({ 0.5, 0.6, 0.1 });
  expectError(blend, remeshes_, "1.2");
  pca->SetSynthesisModel(7);
  expectError(pca, remeshes_, "SynthesisModel 7 is not a model: give -1 (the mean) or 0..2");
}

} // namespace
