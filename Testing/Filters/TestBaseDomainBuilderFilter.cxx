#include "FilterTestUtilities.h"
#include "vtkCMPBaseDomainBuilder.h"
#include "vtkCMPInputCheck.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <set>

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
}
