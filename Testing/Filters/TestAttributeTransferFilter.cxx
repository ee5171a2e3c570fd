#include "FilterTestUtilities.h"
#include <cmp/mesh/TriangleMesh.h> // cmp::kPi
#include "vtkCMPAttributeTransfer.h"
#include "vtkCMPSemiRegularRemesher.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <vector>

using namespace cmp::test;

namespace
{

/// A smooth scalar to carry over: it differs between models, so a value
/// that arrives shows where it was read.
void addHeight(vtkPolyData* surface)
{
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  height->SetNumberOfTuples(surface->GetNumberOfPoints());
  for (vtkIdType v = 0; v < surface->GetNumberOfPoints(); ++v)
    height->SetValue(v, static_cast<float>(surface->GetPoint(v)[2] + 0.5 * surface->GetPoint(v)[0]));
  surface->GetPointData()->AddArray(height);
}

/// Per-corner texture coordinates with a seam: u is the longitude around
/// the z axis over 2 pi, unwrapped per triangle so that a triangle across
/// the cut at -pi reads u near 1 at all its corners; v is z.
void addSeamedTextureCoordinates(vtkPolyData* surface)
{
  vtkNew<vtkFloatArray> corners;
  corners->SetName("CornerTCoords");
  corners->SetNumberOfComponents(6);
  corners->SetNumberOfTuples(surface->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < surface->GetNumberOfCells(); ++t)
  {
    surface->GetCellPoints(t, ids);
    std::array<double, 3> u{};
    for (int k = 0; k < 3; ++k)
    {
      const double* p = surface->GetPoint(ids->GetId(k));
      u[k] = (std::atan2(p[1], p[0]) + cmp::kPi) / (2 * cmp::kPi);
    }
    const double high = std::max({ u[0], u[1], u[2] });
    for (int k = 0; k < 3; ++k)
    {
      if (high - u[k] > 0.5)
        u[k] += 1.0; // across the cut: continue past 1
      corners->SetComponent(t, 2 * k, u[k]);
      corners->SetComponent(t, 2 * k + 1, surface->GetPoint(ids->GetId(k))[2]);
    }
  }
  surface->GetCellData()->AddArray(corners);
}

vtkSmartPointer<vtkPolyData> remeshOf(vtkPolyData* parameterizedSurface, vtkPolyData* l0, int level)
{
  vtkNew<vtkCMPSemiRegularRemesher> remesher;
  remesher->SetInputData(0, parameterizedSurface);
  remesher->SetInputData(1, l0);
  remesher->SetLevel(level);
  remesher->ComputeDistanceOff();
  const RunResult result = run(remesher);
  EXPECT_TRUE(result.succeeded) << result.error;
  return vtkPolyData::SafeDownCast(remesher->GetOutputDataObject(0));
}

struct Transfer
{
  RunResult result;
  vtkSmartPointer<vtkDataObject> output;
};

Transfer transfer(vtkDataObject* target, vtkPolyData* source, vtkPolyData* l0, bool splitSeams = true)
{
  vtkNew<vtkCMPAttributeTransfer> filter;
  filter->SetInputData(0, target);
  if (source)
    filter->SetInputData(1, source);
  if (l0)
    filter->SetInputData(2, l0);
  filter->SetSplitTextureSeams(splitSeams);
  Transfer t;
  t.result = run(filter);
  t.output = filter->GetOutputDataObject(0);
  return t;
}

/// Point of every feature id.
std::map<int, vtkIdType> landmarkPoints(vtkPolyData* surface)
{
  std::map<int, vtkIdType> points;
  vtkDataArray* ids = surface->GetPointData()->GetArray("FeatureId");
  for (vtkIdType v = 0; v < surface->GetNumberOfPoints(); ++v)
    if (ids->GetComponent(v, 0) >= 0)
      points[static_cast<int>(ids->GetComponent(v, 0))] = v;
  return points;
}

/// Every target corner at a landmark reads one of the texture coordinates
/// the source's corners at that landmark have.
void expectLandmarkCornersMatchSource(vtkPolyData* target, vtkPolyData* source, double tolerance)
{
  std::map<vtkIdType, int> featureOfSourcePoint;
  for (const auto& [f, v] : landmarkPoints(source))
    featureOfSourcePoint[v] = f;
  std::map<int, std::vector<std::array<double, 2>>> sourceValues;
  vtkDataArray* sourceCorners = source->GetCellData()->GetArray("CornerTCoords");
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < source->GetNumberOfCells(); ++t)
  {
    source->GetCellPoints(t, ids);
    for (int k = 0; k < 3; ++k)
      if (auto it = featureOfSourcePoint.find(ids->GetId(k)); it != featureOfSourcePoint.end())
        sourceValues[it->second].push_back(
          { sourceCorners->GetComponent(t, 2 * k), sourceCorners->GetComponent(t, 2 * k + 1) });
  }
  std::map<vtkIdType, int> featureOfTargetPoint;
  vtkDataArray* featureIds = target->GetPointData()->GetArray("FeatureId");
  for (vtkIdType v = 0; v < target->GetNumberOfPoints(); ++v)
    if (featureIds->GetComponent(v, 0) >= 0)
      featureOfTargetPoint[v] = static_cast<int>(featureIds->GetComponent(v, 0));
  vtkDataArray* corners = target->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(corners, nullptr);
  int checked = 0;
  for (vtkIdType t = 0; t < target->GetNumberOfCells(); ++t)
  {
    target->GetCellPoints(t, ids);
    for (int k = 0; k < 3; ++k)
    {
      auto it = featureOfTargetPoint.find(ids->GetId(k));
      if (it == featureOfTargetPoint.end())
        continue;
      double best = 1e9;
      for (const auto& uv : sourceValues[it->second])
        best = std::min(best,
          std::abs(uv[0] - corners->GetComponent(t, 2 * k)) + std::abs(uv[1] - corners->GetComponent(t, 2 * k + 1)));
      EXPECT_LT(best, tolerance) << "feature " << it->second << " in target triangle " << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

/// Point TCoords agree with each corner's CornerTCoords.
void expectPointTextureCoordinatesExact(vtkPolyData* target)
{
  vtkDataArray* points = target->GetPointData()->GetTCoords();
  vtkDataArray* corners = target->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(points, nullptr);
  vtkNew<vtkIdList> ids;
  double worst = 0.0;
  for (vtkIdType t = 0; t < target->GetNumberOfCells(); ++t)
  {
    target->GetCellPoints(t, ids);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 2; ++i)
        worst = std::max(worst, std::abs(points->GetComponent(ids->GetId(k), i) - corners->GetComponent(t, 2 * k + i)));
  }
  // The filter lets corners within 1e-5 (u + v) share their point's value
  // (float storage and the corners' inset leave differences near 1e-6; a
  // seam jumps by a texel or more): 1.2e-6 was measured on Spot's texture
  // carried to 387.
  EXPECT_LT(worst, 1e-5);
}

class AttributeTransferOnExamples : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    const std::string folder = examplesDir() + "/";
    vtkSmartPointer<vtkPolyData> blob = readLandmarked(folder + "blob.off", folder + "blob.vts");
    l0_ = baseDomainOf(blob);
    addHeight(blob);
    addSeamedTextureCoordinates(blob);
    blob_ = parameterized(blob, l0_);
    capsule_ = parameterized(readLandmarked(folder + "capsule.obj", folder + "capsule.pinned"), l0_);
  }
  static void TearDownTestSuite() { l0_ = blob_ = capsule_ = nullptr; }
  static vtkSmartPointer<vtkPolyData> l0_, blob_, capsule_;
};
vtkSmartPointer<vtkPolyData> AttributeTransferOnExamples::l0_, AttributeTransferOnExamples::blob_,
  AttributeTransferOnExamples::capsule_;

TEST_F(AttributeTransferOnExamples, OntoItsOwnRemeshReproducesTheRemeshersInterpolation)
{
  // The remesher interpolates the blob's point arrays at each remesh
  // vertex; carrying them through the base domain must land on the same
  // source points and give the same values.
  vtkSmartPointer<vtkPolyData> remesh = remeshOf(blob_, l0_, 3);
  vtkNew<vtkPolyData> bare;
  bare->DeepCopy(remesh);
  bare->GetPointData()->RemoveArray("Height");
  const Transfer t = transfer(bare, blob_, l0_, false);
  ASSERT_TRUE(t.result.succeeded) << t.result.error;
  auto* out = vtkPolyData::SafeDownCast(t.output);
  ASSERT_EQ(out->GetNumberOfPoints(), remesh->GetNumberOfPoints());
  vtkDataArray* carried = out->GetPointData()->GetArray("Height");
  vtkDataArray* expected = remesh->GetPointData()->GetArray("Height");
  ASSERT_NE(carried, nullptr);
  double worst = 0.0;
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
    worst = std::max(worst, std::abs(carried->GetComponent(v, 0) - expected->GetComponent(v, 0)));
  EXPECT_LT(worst, 1e-6);
}

TEST_F(AttributeTransferOnExamples, LandmarksReadTheSourcesLandmarkValues)
{
  // Onto the capsule's remesh and onto the capsule's original surface.
  const std::map<int, vtkIdType> sourceLandmarks = landmarkPoints(blob_);
  vtkDataArray* sourceHeight = blob_->GetPointData()->GetArray("Height");
  const std::vector<vtkSmartPointer<vtkPolyData>> targets{ remeshOf(capsule_, l0_, 2), capsule_ };
  for (vtkPolyData* target : targets)
  {
    const Transfer t = transfer(target, blob_, l0_, false);
    ASSERT_TRUE(t.result.succeeded) << t.result.error;
    auto* out = vtkPolyData::SafeDownCast(t.output);
    EXPECT_EQ(out->GetNumberOfPoints(), target->GetNumberOfPoints());
    EXPECT_EQ(fieldValue(out, "SeamPointsAdded"), 0.0);
    EXPECT_EQ(fieldValue(out, "TransferredArrays"), 2.0); // Height and the texture
    vtkDataArray* height = out->GetPointData()->GetArray("Height");
    ASSERT_NE(height, nullptr);
    for (const auto& [f, v] : landmarkPoints(out))
      EXPECT_NEAR(height->GetComponent(v, 0), sourceHeight->GetComponent(sourceLandmarks.at(f), 0), 1e-6)
        << "feature " << f;
    // The target's own correspondence and geometry stay.
    EXPECT_EQ(out->GetPointData()->GetArray("BaseCoordinates"), target->GetPointData()->GetArray("BaseCoordinates"));
    expectLandmarkCornersMatchSource(out, blob_, 1e-4);
  }
}

/// A copy of a parameterized surface textured as an atlas with one chart
/// per patch: (u, v) = (0.1 (x + PatchId), 0.1 y) at every corner, so the
/// texture jumps across every curve of the net.
vtkSmartPointer<vtkPolyData> withOneChartPerPatch(vtkPolyData* parameterized)
{
  auto atlas = vtkSmartPointer<vtkPolyData>::New();
  atlas->DeepCopy(parameterized);
  vtkDataArray* patchIds = atlas->GetCellData()->GetArray("PatchId");
  addCornerTCoords(atlas, [&](const double* point, vtkIdType cell)
    { return std::array<double, 2>{ 0.1 * (point[0] + patchIds->GetComponent(cell, 0)), 0.1 * point[1] }; });
  return atlas;
}

TEST_F(AttributeTransferOnExamples, TextureSeamsSplitPointsOnlyWhenAsked)
{
  // Every remesh vertex on an L0 edge (7 per edge at level 3) lies on a net
  // curve of the source, where the atlas's charts meet: its corners on the
  // two sides read different charts, so it gets one duplicate; a landmark
  // where d patches meet gets d - 1 (2 E - V in all).
  vtkSmartPointer<vtkPolyData> remesh = remeshOf(capsule_, l0_, 3);
  vtkSmartPointer<vtkPolyData> atlas = withOneChartPerPatch(blob_);
  const vtkIdType baseEdges = 3 * l0_->GetNumberOfPoints() - 6;
  const Transfer kept = transfer(remesh, atlas, l0_, false);
  ASSERT_TRUE(kept.result.succeeded) << kept.result.error;
  auto* same = vtkPolyData::SafeDownCast(kept.output);
  // Unsplit: the collection's connectivity, untouched.
  EXPECT_EQ(same->GetPolys(), remesh->GetPolys());
  EXPECT_EQ(same->GetNumberOfPoints(), remesh->GetNumberOfPoints());

  const Transfer split = transfer(remesh, atlas, l0_, true);
  ASSERT_TRUE(split.result.succeeded) << split.result.error;
  auto* out = vtkPolyData::SafeDownCast(split.output);
  const double added = fieldValue(out, "SeamPointsAdded");
  EXPECT_EQ(added, 7.0 * baseEdges + 2.0 * baseEdges - static_cast<double>(l0_->GetNumberOfPoints()));
  EXPECT_EQ(out->GetNumberOfPoints(), remesh->GetNumberOfPoints() + static_cast<vtkIdType>(added));
  EXPECT_EQ(out->GetNumberOfCells(), remesh->GetNumberOfCells());
  expectPointTextureCoordinatesExact(out);
  // A duplicate sits where its original is and says which one it copies.
  vtkDataArray* unsplit = out->GetPointData()->GetArray("UnsplitPointId");
  ASSERT_NE(unsplit, nullptr);
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
  {
    const auto from = static_cast<vtkIdType>(unsplit->GetComponent(v, 0));
    ASSERT_EQ(v < remesh->GetNumberOfPoints(), from == v);
    for (int i = 0; i < 3; ++i)
      ASSERT_EQ(out->GetPoint(v)[i], remesh->GetPoint(from)[i]);
  }
}

TEST_F(AttributeTransferOnExamples, EveryBlockOfAMultiblockTarget)
{
  vtkNew<vtkMultiBlockDataSet> targets;
  targets->SetBlock(0, remeshOf(capsule_, l0_, 2));
  targets->SetBlock(1, capsule_);
  const Transfer t = transfer(targets, blob_, l0_);
  ASSERT_TRUE(t.result.succeeded) << t.result.error;
  auto* out = vtkMultiBlockDataSet::SafeDownCast(t.output);
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfBlocks(), 2u);
  for (unsigned b = 0; b < 2; ++b)
    EXPECT_NE(vtkPolyData::SafeDownCast(out->GetBlock(b))->GetPointData()->GetArray("Height"), nullptr);
}

TEST_F(AttributeTransferOnExamples, ReportsBadInput)
{
  const auto expectError = [](const Transfer& t, const std::string& expected)
  {
    EXPECT_FALSE(t.result.succeeded);
    EXPECT_NE(t.result.error.find(expected), std::string::npos) << t.result.error;
  };
  expectError(transfer(capsule_, nullptr, l0_), "no source");
  expectError(transfer(capsule_, blob_, nullptr), "no base domain");
  vtkNew<vtkPolyData> unparameterized;
  unparameterized->DeepCopy(blob_);
  unparameterized->GetPointData()->RemoveArray("BaseTriangle");
  expectError(transfer(capsule_, unparameterized, l0_), "source: input has no BaseTriangle point array");
  expectError(transfer(unparameterized, blob_, l0_), "target: input has no BaseTriangle point array");
  expectError(transfer(capsule_, blob_, withFeatures0And1Swapped(l0_)), "not equivalent to L0");
  vtkNew<vtkPolyData> empty;
  expectError(transfer(empty, blob_, l0_), "target: ");
  vtkNew<vtkMultiBlockDataSet> withBad;
  withBad->SetBlock(0, capsule_);
  withBad->SetBlock(1, unparameterized);
  expectError(transfer(withBad, blob_, l0_), "block 1: input has no BaseTriangle point array");
}

TEST(AttributeTransferFilter, SpotsTextureOntoAFourLeggedRemesh)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::string folder = sharedDataDir() + "/";
  vtkSmartPointer<vtkPolyData> l0 =
    baseDomainOf(readLandmarked(folder + "shrec07-fourleg/381.off", folder + "shrec07-fourleg/381.vts"));
  vtkSmartPointer<vtkPolyData> spot =
    parameterized(readLandmarked(folder + "spot/spot.obj", folder + "spot/spot_shrec07.pinned"), l0);
  ASSERT_NE(spot->GetCellData()->GetArray("CornerTCoords"), nullptr);
  vtkSmartPointer<vtkPolyData> target = remeshOf(
    parameterized(readLandmarked(folder + "shrec07-fourleg/387.off", folder + "shrec07-fourleg/387.vts"), l0), l0, 4);
  const Transfer t = transfer(target, spot, l0, true);
  ASSERT_TRUE(t.result.succeeded) << t.result.error;
  auto* out = vtkPolyData::SafeDownCast(t.output);
  expectLandmarkCornersMatchSource(out, spot, 1e-4);
  expectPointTextureCoordinatesExact(out);
  std::cout << "seam points added: " << fieldValue(out, "SeamPointsAdded") << " of "
            << target->GetNumberOfPoints() << "\n";
  // Every texture coordinate is a convex combination of the source's, so
  // it lies within their range (Spot's atlas: u from -0.052 to 0.989).
  vtkDataArray* tcoords = out->GetPointData()->GetTCoords();
  vtkDataArray* sourceCorners = spot->GetCellData()->GetArray("CornerTCoords");
  for (int i = 0; i < 2; ++i)
  {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int corner = 0; corner < 3; ++corner)
    {
      low = std::min(low, sourceCorners->GetRange(2 * corner + i)[0]);
      high = std::max(high, sourceCorners->GetRange(2 * corner + i)[1]);
    }
    EXPECT_GE(tcoords->GetRange(i)[0], low - 1e-6);
    EXPECT_LE(tcoords->GetRange(i)[1], high + 1e-6);
  }
}

} // namespace
