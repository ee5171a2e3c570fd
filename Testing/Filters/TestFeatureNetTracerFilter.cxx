#include "FilterTestUtilities.h"
#include "vtkCMPBaseDomainBuilder.h"
#include "vtkCMPFeatureNetTracer.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace cmp::test;


TEST(FeatureNetTracerFilter, TracesModel387AgainstL0From381AndCarriesArraysThrough)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::string folder = sharedDataDir() + "/shrec07-fourleg/";
  vtkSmartPointer<vtkPolyData> l0 = baseDomainOf(readLandmarked(folder + "381.off", folder + "381.vts"));
  vtkSmartPointer<vtkPolyData> horse = readLandmarked(folder + "387.off", folder + "387.vts");
  // A point array (x coordinate) and a cell array (cell id) to carry through.
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType v = 0; v < horse->GetNumberOfPoints(); ++v)
    height->InsertNextValue(horse->GetPoint(v)[1]);
  horse->GetPointData()->AddArray(height);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("InputCellId");
  for (vtkIdType c = 0; c < horse->GetNumberOfCells(); ++c)
    cellIds->InsertNextValue(static_cast<int>(c));
  horse->GetCellData()->AddArray(cellIds);

  vtkNew<vtkCMPFeatureNetTracer> tracer;
  tracer->SetInputData(0, horse);
  tracer->SetInputData(1, l0);
  ASSERT_TRUE(run(tracer).succeeded);
  vtkPolyData* surface = tracer->GetOutput(0);
  vtkPolyData* curves = tracer->GetOutput(1);

  EXPECT_EQ(fieldValue(surface, "NetValid"), 1.0);
  EXPECT_GT(fieldValue(surface, "NetLengthPerSqrtArea"), 10.0);
  EXPECT_LT(fieldValue(surface, "NetLengthPerSqrtArea"), 24.0);
  EXPECT_NEAR(areaOf(surface), areaOf(horse), 1e-9 * areaOf(horse));
  EXPECT_GE(surface->GetNumberOfPoints(), horse->GetNumberOfPoints());

  // Every input point keeps its values; new points interpolate Height exactly
  // (it is linear along edges) and carry FeatureId -1.
  vtkDataArray* heightOut = surface->GetPointData()->GetArray("Height");
  vtkDataArray* featureOut = surface->GetPointData()->GetArray("FeatureId");
  ASSERT_NE(heightOut, nullptr);
  ASSERT_NE(featureOut, nullptr);
  int landmarks = 0;
  for (vtkIdType v = 0; v < surface->GetNumberOfPoints(); ++v)
  {
    EXPECT_NEAR(heightOut->GetComponent(v, 0), surface->GetPoint(v)[1], 1e-12);
    landmarks += featureOut->GetComponent(v, 0) >= 0 ? 1 : 0;
    if (v < horse->GetNumberOfPoints())
      ASSERT_EQ(featureOut->GetComponent(v, 0), horse->GetPointData()->GetArray("FeatureId")->GetComponent(v, 0));
  }
  EXPECT_EQ(landmarks, 21);
  ASSERT_NE(surface->GetCellData()->GetArray("InputCellId"), nullptr);
  vtkDataArray* patchIds = surface->GetCellData()->GetArray("PatchId");
  ASSERT_NE(patchIds, nullptr);
  std::set<int> patches;
  for (vtkIdType c = 0; c < patchIds->GetNumberOfTuples(); ++c)
    patches.insert(static_cast<int>(patchIds->GetComponent(c, 0)));
  EXPECT_EQ(patches.size(), 38u);

  EXPECT_EQ(curves->GetNumberOfLines(), 57);
  vtkDataArray* a = curves->GetCellData()->GetArray("FeatureIdA");
  vtkDataArray* b = curves->GetCellData()->GetArray("FeatureIdB");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  ASSERT_NE(curves->GetCellData()->GetArray("BaseEdgeId"), nullptr);
  std::set<std::pair<int, int>> baseEdges;
  for (vtkIdType c = 0; c < 57; ++c)
    baseEdges.insert(std::minmax(static_cast<int>(a->GetComponent(c, 0)), static_cast<int>(b->GetComponent(c, 0))));
  EXPECT_EQ(baseEdges.size(), 57u);
}

TEST(FeatureNetTracerFilter, ReportsBadInput)
{
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(writeTempFile("tracer-octa.off", octahedronOFF()).c_str());
  ASSERT_TRUE(run(reader).succeeded);
  vtkSmartPointer<vtkPolyData> surface = reader->GetOutput();
  setFeatureIds(surface, { 0, 1, 2, 3, 4, 5 });
  vtkSmartPointer<vtkPolyData> l0 = vtkSmartPointer<vtkPolyData>::New();
  l0->DeepCopy(surface);

  vtkNew<vtkCMPFeatureNetTracer> tracer;
  const auto expectError = [&](vtkPolyData* input, vtkPolyData* domain, const std::string& fragment)
  {
    tracer->SetInputData(0, input);
    tracer->SetInputData(1, domain);
    const RunResult result = run(tracer);
    EXPECT_FALSE(result.succeeded);
    EXPECT_NE(result.error.find(fragment), std::string::npos) << result.error;
    EXPECT_EQ(tracer->GetOutput(0)->GetNumberOfPoints(), 0);
    EXPECT_EQ(tracer->GetOutput(1)->GetNumberOfPoints(), 0);
  };
  // The octahedron itself, traced against itself, works.
  tracer->SetInputData(0, surface);
  tracer->SetInputData(1, l0);
  ASSERT_TRUE(run(tracer).succeeded) << run(tracer).error;
  EXPECT_EQ(tracer->GetOutput(1)->GetNumberOfLines(), 12);

  vtkNew<vtkPolyData> empty;
  expectError(empty, l0, "empty surface");

  vtkNew<vtkCMPSurfaceReader> openReader;
  openReader->SetFileName(writeTempFile("tracer-open.off", octahedronOFF(true)).c_str());
  ASSERT_TRUE(run(openReader).succeeded);
  setFeatureIds(openReader->GetOutput(), { 0, 1, 2, 3, 4, 5 });
  expectError(openReader->GetOutput(), l0, "open surface");

  vtkNew<vtkPolyData> fewer;
  fewer->DeepCopy(surface);
  setFeatureIds(fewer, { 0, 1, 2, 3, 4 });
  expectError(fewer, l0, "base domain has 6 vertices but the surface has 5 landmarks");

  vtkNew<vtkPolyData> duplicate;
  duplicate->DeepCopy(surface);
  setFeatureIds(duplicate, { 0, 1, 2, 3, 3, 5 });
  expectError(duplicate, l0, "duplicate landmark: feature 3 is on vertices 3 and 4");

  vtkNew<vtkPolyData> openL0;
  openL0->DeepCopy(openReader->GetOutput());
  expectError(surface, openL0, "base domain: open surface");

  tracer->SetInputData(0, surface);
  tracer->SetInputConnection(1, nullptr);
  const RunResult noDomain = run(tracer);
  EXPECT_FALSE(noDomain.succeeded);
}
