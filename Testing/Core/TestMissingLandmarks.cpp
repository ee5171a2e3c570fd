#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/remesh/MissingLandmarks.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using namespace cmp;

namespace
{

void expectError(const Status& status, const std::string& fragment)
{
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find(fragment), std::string::npos) << "message: " << status.message();
}

} // namespace

// Issue 27 A: take landmarks away from models where we know them and place
// them from the others. The target is a mean error below 5% of
// sqrt(area) and a worst below 12%. Features 5, 9 and 11 are feet, at the
// tip of a protrusion on the sources: they climb from where the maps carry
// them to the tip near there (`climbToTips`), which must bring them closer;
// the others (3, on the head; 13, at the rump; 17, by a front leg) stay
// where the maps carry them.
/// Five SHREC'07 models with their landmarks, as the placer takes them.
struct RealCollection
{
  std::vector<test::LandmarkedModel> models;
  std::vector<const TriangleMesh*> surfaces;
  std::vector<LandmarkList> landmarks;

  RealCollection()
  {
    for (const char* name : { "381", "383", "384", "388", "391" })
      models.push_back(test::landmarkedRealModel(name));
    for (const test::LandmarkedModel& model : models)
    {
      surfaces.push_back(&model.data.mesh);
      landmarks.push_back(model.landmarks);
    }
  }
};

TEST(MissingLandmarks, PlacesLandmarksTakenAwayFromRealModels)
{
  RealCollection collection;
  const std::vector<test::LandmarkedModel>& models = collection.models;
  const std::vector<const TriangleMesh*>& surfaces = collection.surfaces;
  std::vector<LandmarkList>& landmarks = collection.landmarks;
  // By model, then feature, as the report lists them.
  const std::vector<std::pair<int, int>> taken = { { 1, 3 }, { 1, 9 }, { 1, 17 }, { 3, 5 }, { 3, 11 }, { 3, 13 } };
  const std::vector<int> tips = { 5, 9, 11 };
  for (auto [m, f] : taken)
    landmarks[m][f] = kMissingLandmark;

  MissingLandmarkReport report;
  const Status status = placeMissingLandmarks(surfaces, landmarks, {}, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(report.missingFeatures, (std::vector<int>{ 3, 5, 9, 11, 13, 17 }));
  EXPECT_EQ(report.baseDomainModel, 0);
  for (std::size_t m = 0; m < models.size(); ++m)
    EXPECT_EQ(report.modelErrors[m], "") << models[m].name;
  ASSERT_EQ(report.placed.size(), taken.size());
  auto error = [&](int m, int f, int vertex) {
    const TriangleMesh& mesh = models[m].data.mesh;
    return (mesh.points[vertex] - mesh.points[models[m].landmarks[f]]).norm() / std::sqrt(surfaceArea(mesh));
  };
  double sum = 0.0, worst = 0.0, tipsMapped = 0.0, tipsClimbed = 0.0;
  for (std::size_t i = 0; i < taken.size(); ++i)
  {
    const auto [m, f] = taken[i];
    const PlacedLandmark& placed = report.placed[i];
    EXPECT_EQ(placed.model, m);
    EXPECT_EQ(placed.feature, f);
    EXPECT_EQ(landmarks[m][f], placed.vertex);
    EXPECT_EQ(placed.sources, 3); // the three models with every feature
    const double placedError = error(m, f, placed.vertex), mappedError = error(m, f, placed.mappedVertex);
    std::cout << models[m].name << " feature " << f << ": " << 100.0 * placedError << "% of sqrt(area) (the maps: "
              << 100.0 * mappedError << "%, climbed " << 100.0 * placed.climbed << "%)\n";
    sum += placedError;
    worst = std::max(worst, placedError);
    EXPECT_LT(placedError, 0.12) << models[m].name << " feature " << f;
    if (std::find(tips.begin(), tips.end(), f) != tips.end())
    {
      EXPECT_GT(placed.climbed, 0.0) << models[m].name << " feature " << f;
      EXPECT_LE(placedError, mappedError) << models[m].name << " feature " << f;
      tipsMapped += mappedError;
      tipsClimbed += placedError;
    }
    else
    {
      EXPECT_EQ(placed.climbed, 0.0) << models[m].name << " feature " << f;
      EXPECT_EQ(placed.vertex, placed.mappedVertex) << models[m].name << " feature " << f;
    }
  }
  EXPECT_LT(sum / taken.size(), 0.05);
  EXPECT_LT(tipsClimbed, 0.7 * tipsMapped);
  for (const LandmarkList& list : landmarks)
    EXPECT_EQ(missingLandmarkCount(list), 0);
  EXPECT_TRUE(validateLandmarks(landmarks[1], surfaces[1]->vertexCount()).ok());
}

// With the L0 the collection will be mapped over, each climb to a tip is
// judged by the model's own map over it: the climb is undone where that map
// does not settle with it (more than twice as distorted as without). The
// hooves above climb; here each is mapped both ways, and both maps settle.
TEST(MissingLandmarks, AClimbIsUndoneOnlyWhereTheModelsMapOverL0DoesNotSettleWithIt)
{
  RealCollection collection;
  const std::vector<test::LandmarkedModel>& models = collection.models;
  const std::vector<const TriangleMesh*>& surfaces = collection.surfaces;
  std::vector<LandmarkList>& landmarks = collection.landmarks;
  const std::vector<std::pair<int, int>> taken = { { 1, 9 }, { 1, 17 }, { 3, 5 }, { 3, 11 } };
  const std::vector<int> tips = { 5, 9, 11 };
  for (auto [m, f] : taken)
    landmarks[m][f] = kMissingLandmark;
  const BaseDomain domain = test::realBaseDomain("381");
  MissingLandmarkOptions options;
  options.domain = &domain;
  MissingLandmarkReport report;
  const Status status = placeMissingLandmarks(surfaces, landmarks, options, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(report.placed.size(), taken.size());
  for (std::size_t i = 0; i < taken.size(); ++i)
  {
    const auto [m, f] = taken[i];
    const PlacedLandmark& placed = report.placed[i];
    ASSERT_EQ(placed.model, m);
    ASSERT_EQ(placed.feature, f);
    EXPECT_EQ(landmarks[m][f], placed.vertex);
    std::cout << models[m].name << " feature " << f << ": map distortion " << placed.tipDistortion
              << " at the tip, " << placed.mappedDistortion << " where the maps carried it"
              << (placed.climbUndone ? " (climb undone)" : "") << "\n";
    if (std::find(tips.begin(), tips.end(), f) == tips.end())
    {
      // Not at a tip: nothing climbed, nothing judged.
      EXPECT_EQ(placed.climbed, 0.0);
      EXPECT_EQ(placed.tipDistortion, 0.0);
      EXPECT_EQ(placed.mappedDistortion, 0.0);
      EXPECT_FALSE(placed.climbUndone);
      continue;
    }
    // Both maps settle near isometric (1 is isometric).
    EXPECT_GE(placed.tipDistortion, 1.0) << models[m].name << " feature " << f;
    EXPECT_LT(placed.tipDistortion, 10.0) << models[m].name << " feature " << f;
    EXPECT_GE(placed.mappedDistortion, 1.0) << models[m].name << " feature " << f;
    EXPECT_LT(placed.mappedDistortion, 10.0) << models[m].name << " feature " << f;
    EXPECT_EQ(placed.climbUndone, options.unsettledRatio * placed.mappedDistortion < placed.tipDistortion);
    if (placed.climbUndone)
    {
      EXPECT_EQ(placed.vertex, placed.mappedVertex);
      EXPECT_EQ(placed.climbed, 0.0);
    }
    else
    {
      EXPECT_NE(placed.vertex, placed.mappedVertex);
      EXPECT_GT(placed.climbed, 0.0);
    }
    EXPECT_EQ(placed.position, models[m].data.mesh.points[placed.vertex]);
  }
  // An L0 of other features is refused by name before any work.
  BaseDomain other = domain;
  other.featureIds.pop_back();
  other.mesh.points.pop_back();
  std::vector<LandmarkList> again = { models[0].landmarks, models[1].landmarks };
  again[1][9] = kMissingLandmark;
  options.domain = &other;
  const Status refused = placeMissingLandmarks({ surfaces[0], surfaces[1] }, again, options);
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("the base domain the climbs are judged over"), std::string::npos)
    << refused.message();
}

TEST(MissingLandmarks, NothingMissingIsNothingToDo)
{
  const test::LandmarkedModel model = test::landmarkedRealModel("391");
  std::vector<LandmarkList> landmarks = { model.landmarks };
  MissingLandmarkReport report;
  ASSERT_TRUE(placeMissingLandmarks({ &model.data.mesh }, landmarks, {}, &report).ok());
  EXPECT_TRUE(report.placed.empty());
  EXPECT_EQ(report.baseDomainModel, -1);
  EXPECT_EQ(landmarks[0], model.landmarks);
}

TEST(MissingLandmarks, RefusesWhatCannotBePlaced)
{
  const TriangleMesh mesh = test::sphere(2);
  const LandmarkList full = { 0, 1, 2, 3, 4, 5 };
  LandmarkList gap = full;
  gap[2] = kMissingLandmark;
  std::vector<LandmarkList> landmarks = { gap, gap };
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks), "feature 2 is missing on every model");
  landmarks = { gap, full, { 0, 1, 2, kMissingLandmark, 4, 5 } };
  MissingLandmarkOptions options;
  options.baseDomainModel = 0;
  expectError(placeMissingLandmarks({ &mesh, &mesh, &mesh }, landmarks, options),
    "model 0, which should give the base domain, misses features");
  landmarks = { gap, { 0, 1, 2, kMissingLandmark, 4, 5 } };
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks), "no model has every feature");
  landmarks = { { kMissingLandmark, 1, kMissingLandmark, 3, 4 }, { 0, 1, 2, 3, 4 } };
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks), "a model has only 3 features");
  MissingLandmarkOptions negative;
  negative.maximumSources = -1;
  landmarks = { gap, full };
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks, negative), "the most sources must be 0");
  negative = MissingLandmarkOptions();
  negative.similarityWidth = -0.1;
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks, negative), "the similarity width must be 0");
  negative = MissingLandmarkOptions();
  negative.tipRadius = 0.0;
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks, negative), "the tip radius and reach must be positive");
  negative = MissingLandmarkOptions();
  negative.tipReach = std::nan("");
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks, negative), "the tip radius and reach must be positive");
  negative = MissingLandmarkOptions();
  negative.unsettledRatio = 0.5;
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks, negative), "the unsettled ratio must be at least 1");
  negative = MissingLandmarkOptions();
  negative.tipTolerance = -0.01;
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks, negative), "the tip tolerance 0 or positive");
  landmarks = { full, { 0, 1 } };
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks), "model 1 has 2 features but model 0 has 6");
  landmarks = { full, { 0, 1, 2, 3, 4, 99 } };
  expectError(placeMissingLandmarks({ &mesh, &mesh }, landmarks), "model 1: landmark 5 is vertex 99");
}

// A base domain is built from a model with every feature.
TEST(MissingLandmarks, TheBaseDomainBuilderRefusesAModelThatMissesOne)
{
  const test::LandmarkedModel model = test::landmarkedRealModel("391");
  LandmarkList landmarks = model.landmarks;
  landmarks[4] = kMissingLandmark;
  BaseDomain domain;
  expectError(buildBaseDomain(model.data.mesh, landmarks, domain), "landmark 4 is missing");
}

// Identical models carry a feature exactly, whatever the number of threads
// and of sources.
TEST(MissingLandmarks, IdenticalModelsGiveTheTrueVertexWithAnyThreadsAndSources)
{
  const TriangleMesh mesh = test::bumpySphere(3);
  LandmarkList truth;
  for (const Vec3& direction : { Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1),
         Vec3(0, 0, -1), Vec3(0.6, 0.6, 0.5) })
    truth.push_back(test::nearestVertex(mesh, direction));
  for (int threads : { 1, 2 })
  {
    std::vector<LandmarkList> landmarks = { truth, truth, truth };
    landmarks[1][6] = kMissingLandmark;
    landmarks[2][2] = kMissingLandmark;
    MissingLandmarkOptions options;
    options.threads = threads;
    MissingLandmarkReport report;
    const Status status = placeMissingLandmarks({ &mesh, &mesh, &mesh }, landmarks, options, &report);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_EQ(landmarks[1], truth) << threads << " threads";
    EXPECT_EQ(landmarks[2], truth) << threads << " threads";
    ASSERT_EQ(report.placed.size(), 2u);
    EXPECT_EQ(report.placed[0].model, 1);
    EXPECT_EQ(report.placed[0].sources, 1); // model 2 misses another feature
    EXPECT_LT(report.placed[0].spread, 0.01); // the remesh lies within a chord of the surface
  }
  // MaximumSources bounds the models a feature is carried from.
  for (int sources : { 0, 1, 2 })
  {
    std::vector<LandmarkList> landmarks = { truth, truth, truth, truth };
    landmarks[0][3] = kMissingLandmark;
    MissingLandmarkOptions options;
    options.maximumSources = sources;
    MissingLandmarkReport report;
    ASSERT_TRUE(placeMissingLandmarks({ &mesh, &mesh, &mesh, &mesh }, landmarks, options, &report).ok());
    ASSERT_EQ(report.placed.size(), 1u);
    EXPECT_EQ(report.placed[0].sources, sources == 0 ? 3 : sources);
    EXPECT_EQ(landmarks[0], truth);
  }
}

// Surfaces with boundaries (issue 27 A on open models): the models cut open
// round their back (feature 12, as OpenSurface's tests cut them), and inner
// features taken away are placed as on closed models, never on the
// boundary; a boundary feature cannot be placed.
TEST(MissingLandmarks, PlacesInnerLandmarksOnOpenModels)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  std::vector<test::OpenModel> models;
  const std::vector<std::string> names{ "381", "383", "384", "388", "391" };
  for (const std::string& name : names)
  {
    const test::LandmarkedModel model = test::landmarkedRealModel(name);
    test::OpenModel open;
    const Status cut = test::cutAroundFeature(model.data.mesh, model.landmarks, domain, 12, 0.4, open);
    ASSERT_TRUE(cut.ok()) << name << ": " << cut.message();
    models.push_back(std::move(open));
  }
  std::vector<const TriangleMesh*> surfaces;
  std::vector<LandmarkList> landmarks;
  for (const test::OpenModel& model : models)
  {
    surfaces.push_back(&model.surface);
    landmarks.push_back(model.landmarks);
  }
  // As on the closed models: features 3 and 17 of one model, the tail's
  // root (13) of another; above the cut feature 12 they are 16 and 12.
  const std::vector<std::pair<int, int>> taken = { { 1, 3 }, { 1, 16 }, { 3, 12 } };
  for (auto [m, f] : taken)
    landmarks[m][f] = kMissingLandmark;

  MissingLandmarkReport report;
  const Status status = placeMissingLandmarks(surfaces, landmarks, {}, &report);
  ASSERT_TRUE(status.ok()) << status.message();
  for (std::size_t m = 0; m < models.size(); ++m)
    EXPECT_EQ(report.modelErrors[m], "") << names[m];
  ASSERT_EQ(report.placed.size(), taken.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < taken.size(); ++i)
  {
    const auto [m, f] = taken[i];
    const PlacedLandmark& placed = report.placed[i];
    EXPECT_EQ(placed.feature, f);
    const TriangleMesh& mesh = models[m].surface;
    const double error =
      (mesh.points[placed.vertex] - mesh.points[models[m].landmarks[f]]).norm() / std::sqrt(surfaceArea(mesh));
    std::cout << names[m] << " feature " << f << ": placed " << error << " of sqrt(area) from the true one\n";
    sum += error;
    EXPECT_LT(error, 0.12) << names[m] << " feature " << f;
  }
  EXPECT_LT(sum / taken.size(), 0.05);
  // Each model now fits the open L0's contract, its boundary landmarks as
  // they were.
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    EXPECT_TRUE(checkSurfaceWithBoundaries(models[m].surface, &landmarks[m]).ok()) << names[m];
    for (std::size_t f = 0; f < landmarks[m].size(); ++f)
      if (std::none_of(taken.begin(), taken.end(), [&](auto t) { return t.first == static_cast<int>(m) && t.second == static_cast<int>(f); }))
        EXPECT_EQ(landmarks[m][f], models[m].landmarks[f]) << names[m] << " feature " << f;
  }

  // A boundary landmark (the last features are the cut's) cannot be placed.
  landmarks.clear();
  for (const test::OpenModel& model : models)
    landmarks.push_back(model.landmarks);
  const int boundaryFeature = static_cast<int>(landmarks[0].size()) - 1;
  landmarks[2][boundaryFeature] = kMissingLandmark;
  expectError(placeMissingLandmarks(surfaces, landmarks),
    "feature " + std::to_string(boundaryFeature) + " lies on model 0's boundary: a boundary landmark cannot be placed");
}

