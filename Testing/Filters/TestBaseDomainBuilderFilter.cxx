#include "FilterTestUtilities.h"
#include "vtkCMPBaseDomainBuilder.h"
#include "vtkCMPInputCheck.h"
#include "vtkCMPPolyDataBridge.h"
#include "vtkCMPSurfaceReader.h"

#include <cmp/io/Landmarks.h>
#include <cmp/mesh/BoundaryLoops.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

using namespace cmp::test;

namespace
{

std::set<std::pair<vtkIdType, vtkIdType>> edgesOf(vtkPolyData* mesh)
{
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  vtkIdType size;
  const vtkIdType* ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, size, ids);
    for (vtkIdType k = 0; k < size; ++k)
      edges.insert(std::minmax(ids[k], ids[(k + 1) % size]));
  }
  return edges;
}

/// `loop` rotated to start at its smallest element.
std::vector<int> fromSmallest(std::vector<int> loop)
{
  if (!loop.empty())
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

/// The shipped blob with a hole round its landmark of feature 0: the
/// triangles within 0.45 of it removed, its other landmarks kept as
/// features 0..4 and four vertices spread along the hole's boundary, in
/// the boundary's order, as features 5..8. `boundary` gets those.
vtkSmartPointer<vtkPolyData> openBlob(std::vector<int>& boundary)
{
  vtkSmartPointer<vtkPolyData> blob = readLandmarked(examplesDir() + "/blob.off", examplesDir() + "/blob.vts");
  cmp::TriangleMesh mesh;
  cmp::LandmarkList landmarks;
  EXPECT_TRUE(cmp::bridge::toTriangleMesh(blob, mesh).ok());
  EXPECT_TRUE(cmp::bridge::readLandmarks(blob, landmarks).ok());
  EXPECT_EQ(landmarks.size(), 6u);
  const cmp::Vec3 centre = mesh.points[landmarks[0]];
  cmp::TriangleMesh open;
  std::vector<int> newIndex(mesh.vertexCount(), -1);
  for (const cmp::Triangle& t : mesh.triangles)
  {
    if ((mesh.points[t[0]] - centre).norm() < 0.45 || (mesh.points[t[1]] - centre).norm() < 0.45 ||
      (mesh.points[t[2]] - centre).norm() < 0.45)
      continue;
    cmp::Triangle kept;
    for (int k = 0; k < 3; ++k)
    {
      if (newIndex[t[k]] < 0)
      {
        newIndex[t[k]] = open.vertexCount();
        open.points.push_back(mesh.points[t[k]]);
      }
      kept[k] = newIndex[t[k]];
    }
    open.triangles.push_back(kept);
  }
  std::vector<std::vector<int>> loops;
  EXPECT_TRUE(cmp::boundaryLoops(open, loops).ok());
  EXPECT_EQ(loops.size(), 1u);
  cmp::LandmarkList openLandmarks;
  for (std::size_t f = 1; f < landmarks.size(); ++f)
    openLandmarks.push_back(newIndex[landmarks[f]]);
  boundary.clear();
  if (loops.size() == 1)
    for (int i = 0; i < 4; ++i)
    {
      boundary.push_back(static_cast<int>(openLandmarks.size()));
      openLandmarks.push_back(loops[0][i * loops[0].size() / 4]);
    }
  vtkSmartPointer<vtkPolyData> surface = cmp::bridge::toPolyData(open);
  std::vector<int> ids(open.vertexCount(), -1);
  for (std::size_t f = 0; f < openLandmarks.size(); ++f)
    ids[openLandmarks[f]] = static_cast<int>(f);
  setFeatureIds(surface, ids);
  return surface;
}

} // namespace

TEST(BaseDomainBuilderFilter, BuildsL0FromSpotWithProgress)
{
  CMP_REQUIRE_SHARED_DATA();
  vtkSmartPointer<vtkPolyData> spot =
    readLandmarked(sharedDataDir() + "/spot/spot.obj", sharedDataDir() + "/spot/spot_shrec07.pinned");
  vtkNew<vtkCMPBaseDomainBuilder> builder;
  builder->SetInputData(spot);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  builder->AddObserver(vtkCommand::ProgressEvent, onProgress);
  ASSERT_TRUE(run(builder).succeeded);
  vtkPolyData* l0 = builder->GetOutput();
  EXPECT_EQ(l0->GetNumberOfPoints(), 21);
  EXPECT_EQ(l0->GetNumberOfPolys(), 38);
  EXPECT_EQ(edgesOf(l0).size(), 57u);
  EXPECT_GT(progressEvents, 1);
  vtkDataArray* ids = l0->GetPointData()->GetArray("FeatureId");
  ASSERT_NE(ids, nullptr);
  vtkDataArray* spotIds = spot->GetPointData()->GetArray("FeatureId");
  for (vtkIdType f = 0; f < 21; ++f)
  {
    EXPECT_EQ(ids->GetComponent(f, 0), f);
    for (vtkIdType v = 0; v < spot->GetNumberOfPoints(); ++v)
      if (spotIds->GetComponent(v, 0) == f)
        EXPECT_EQ(spot->GetPoint(v)[0], l0->GetPoint(f)[0]) << "L0 vertex f sits on landmark f";
  }
  EXPECT_GT(l0->GetFieldData()->GetArray("MinimumAngle")->GetComponent(0, 0), 1.0);

  // L0 is accepted as the base domain of the surface it came from.
  vtkNew<vtkCMPInputCheck> check;
  check->SetInputData(0, spot);
  check->SetInputData(1, l0);
  EXPECT_TRUE(run(check).succeeded);
}

TEST(BaseDomainBuilderFilter, ReportsBadInput)
{
  vtkNew<vtkCMPBaseDomainBuilder> builder;
  vtkSmartPointer<vtkPolyData> octahedron = readLandmarked(writeTempFile("o.off", octahedronOFF()),
    writeTempFile("o.txt", "0\n1\n2\n"));
  builder->SetInputData(octahedron);
  RunResult result = run(builder);
  EXPECT_NE(result.error.find("too few landmarks: 3 given"), std::string::npos) << result.error;
  EXPECT_EQ(builder->GetOutput()->GetNumberOfPoints(), 0);

  octahedron->GetPointData()->RemoveArray("FeatureId");
  result = run(builder);
  EXPECT_NE(result.error.find("missing point array 'FeatureId'"), std::string::npos) << result.error;

  // Landmarks From File refuses an open surface, so label it directly.
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(writeTempFile("open.off", octahedronOFF(true)).c_str());
  ASSERT_TRUE(run(reader).succeeded);
  vtkNew<vtkIntArray> ids;
  ids->SetName("FeatureId");
  for (int id : { 0, 1, 2, 3, -1, -1 })
    ids->InsertNextValue(id);
  reader->GetOutput()->GetPointData()->AddArray(ids);
  builder->SetInputData(reader->GetOutput());
  result = run(builder);
  EXPECT_NE(result.error.find("open surface"), std::string::npos) << result.error;
  // Its boundary loop (0, 3, 5) passes through landmarks 0 and 3 only.
  EXPECT_NE(result.error.find("passes through 2 landmarks"), std::string::npos) << result.error;
}

TEST(BaseDomainBuilderFilter, AnOpenSurfaceGivesAnOpenL0BoundedByItsBoundaryLandmarks)
{
  std::vector<int> boundary;
  vtkSmartPointer<vtkPolyData> open = openBlob(boundary);
  ASSERT_EQ(boundary.size(), 4u);
  vtkNew<vtkCMPBaseDomainBuilder> builder;
  builder->SetInputData(open);
  const RunResult result = run(builder);
  ASSERT_TRUE(result.succeeded) << result.error;
  vtkPolyData* l0 = builder->GetOutput();
  ASSERT_EQ(l0->GetNumberOfPoints(), 9);
  vtkDataArray* ids = l0->GetPointData()->GetArray("FeatureId");
  ASSERT_NE(ids, nullptr);
  vtkDataArray* surfaceIds = open->GetPointData()->GetArray("FeatureId");
  for (vtkIdType f = 0; f < 9; ++f)
  {
    EXPECT_EQ(ids->GetComponent(f, 0), f);
    for (vtkIdType v = 0; v < open->GetNumberOfPoints(); ++v)
      if (surfaceIds->GetComponent(v, 0) == f)
        for (int k = 0; k < 3; ++k)
          EXPECT_EQ(open->GetPoint(v)[k], l0->GetPoint(f)[k]) << "L0 vertex f sits on landmark f";
  }
  // One hole, bounded by the boundary landmarks in the surface's order.
  cmp::TriangleMesh mesh;
  ASSERT_TRUE(cmp::bridge::toTriangleMesh(l0, mesh).ok());
  std::vector<std::vector<int>> loops;
  ASSERT_TRUE(cmp::boundaryLoops(mesh, loops).ok());
  ASSERT_EQ(loops.size(), 1u);
  std::vector<int> features;
  for (int v : loops[0])
    features.push_back(static_cast<int>(ids->GetComponent(v, 0)));
  EXPECT_EQ(fromSmallest(features), fromSmallest(boundary));
  EXPECT_EQ(l0->GetNumberOfPoints() - static_cast<vtkIdType>(edgesOf(l0).size()) + l0->GetNumberOfPolys(), 1);
  EXPECT_GT(l0->GetFieldData()->GetArray("MinimumAngle")->GetComponent(0, 0), 0.0);

  // Two landmarks on the loop are too few.
  vtkNew<vtkPolyData> twoOnTheLoop;
  twoOnTheLoop->DeepCopy(open);
  vtkDataArray* twoIds = twoOnTheLoop->GetPointData()->GetArray("FeatureId");
  for (vtkIdType v = 0; v < twoOnTheLoop->GetNumberOfPoints(); ++v)
    if (twoIds->GetComponent(v, 0) >= 7)
      twoIds->SetComponent(v, 0, -1);
  builder->SetInputData(twoOnTheLoop);
  const RunResult refused = run(builder);
  EXPECT_FALSE(refused.succeeded);
  EXPECT_NE(refused.error.find("passes through 2 landmarks, but every boundary loop needs at least 3"),
    std::string::npos)
    << refused.error;
  EXPECT_EQ(builder->GetOutput()->GetNumberOfPoints(), 0);
}
