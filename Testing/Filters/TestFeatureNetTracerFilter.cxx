#include "FilterTestUtilities.h"
#include "vtkCMPBaseDomainBuilder.h"
#include "vtkCMPFeatureNetTracer.h"
#include "vtkCMPNetStraightener.h"
#include "vtkCMPSemiRegularRemesher.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

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
  // Per-corner texture coordinates (u, v) = (x, z): a split triangle's new
  // corners must get their own (x, z).
  addCornerTCoords(horse, 0, 2);

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
  EXPECT_EQ(cornersNotAtTheirPoints(surface, 0, 2, 1e-9), 0)
    << "CornerTCoords not interpolated at the corners of split triangles";

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
  expectError(openReader->GetOutput(), l0, "boundary loop(s) (one through vertex 0) but the base domain is closed");

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
  expectError(surface, openL0, "the surface is closed but the base domain has 1 boundary loop(s)");

  tracer->SetInputData(0, surface);
  tracer->SetInputConnection(1, nullptr);
  const RunResult noDomain = run(tracer);
  EXPECT_FALSE(noDomain.succeeded);
}

namespace
{

/// The `SourceFile` field value of `data`, "" if it has none.
std::string sourceFileOf(vtkDataObject* data)
{
  auto* array = data ? vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("SourceFile")) : nullptr;
  return array && array->GetNumberOfValues() == 1 ? array->GetValue(0) : "";
}

/// A copy of `surface` without its last landmark (the highest feature id
/// set to -1), as when a landmark file lost its last line.
vtkSmartPointer<vtkPolyData> withoutLastLandmark(vtkPolyData* surface)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(surface);
  vtkDataArray* ids = copy->GetPointData()->GetArray("FeatureId");
  vtkIdType last = 0;
  for (vtkIdType v = 0; v < ids->GetNumberOfTuples(); ++v)
    if (ids->GetComponent(v, 0) > ids->GetComponent(last, 0))
      last = v;
  ids->SetComponent(last, 0, -1);
  return copy;
}

/// The same without the field array FeatureCount: nothing says a feature
/// is missing, the surface has one landmark fewer.
vtkSmartPointer<vtkPolyData> withoutFeatureCount(vtkPolyData* surface)
{
  surface->GetFieldData()->RemoveArray("FeatureCount");
  return surface;
}

/// The octahedron of octahedronOFF() built in memory: no file, so no
/// SourceFile field array.
vtkSmartPointer<vtkPolyData> octahedronInMemory()
{
  std::istringstream off(octahedronOFF());
  std::string header;
  int points = 0, triangles = 0, edges = 0;
  off >> header >> points >> triangles >> edges;
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> coordinates;
  for (int p = 0; p < points; ++p)
  {
    double x, y, z;
    off >> x >> y >> z;
    coordinates->InsertNextPoint(x, y, z);
  }
  vtkNew<vtkCellArray> cells;
  for (int t = 0; t < triangles; ++t)
  {
    vtkIdType size, ids[3];
    off >> size >> ids[0] >> ids[1] >> ids[2];
    cells->InsertNextCell(3, ids);
  }
  surface->SetPoints(coordinates);
  surface->SetPolys(cells);
  return surface;
}

} // namespace

// The tutorial's case: a collection (GroupDatasets of landmarked models)
// goes through the tracer, which the composite pipeline runs once per block
// without telling it the block's name. The broken model's error must still
// say which model it is, through the file name the reader recorded.
TEST(FeatureNetTracerFilter, NamesTheBrokenModelOfACollection)
{
  const std::string folder = examplesDir() + "/";
  vtkSmartPointer<vtkPolyData> blob = readLandmarked(folder + "blob.off", folder + "blob.vts");
  vtkSmartPointer<vtkPolyData> capsule = readLandmarked(folder + "capsule.obj", folder + "capsule.pinned");
  vtkSmartPointer<vtkPolyData> l0 = baseDomainOf(blob);
  const std::string landmarks = std::to_string(l0->GetNumberOfPoints());
  const std::string fewer = std::to_string(l0->GetNumberOfPoints() - 1);

  for (const auto& [broken, message] :
    { std::pair{ withoutLastLandmark(capsule), "capsule.obj: missing landmark: feature " + fewer + " is on no vertex" },
      std::pair{ withoutFeatureCount(withoutLastLandmark(capsule)), "capsule.obj: base domain has " + landmarks +
        " vertices but the surface has " + fewer + " landmarks" },
      std::pair{ withNaNAt(capsule, 3), std::string("capsule.obj: ") } })
  {
    vtkSmartPointer<vtkMultiBlockDataSet> group = blocksOf({ blob, broken });
    group->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "blob");
    group->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "capsule");
    vtkNew<vtkCMPFeatureNetTracer> tracer;
    tracer->SetInputData(0, group);
    tracer->SetInputData(1, l0);
    const RunResult result = run(tracer);
    EXPECT_FALSE(result.succeeded);
    // Right after VTK's "vtkCMPFeatureNetTracer (0x...): ".
    EXPECT_NE(result.error.find("): " + message), std::string::npos) << result.error;
    EXPECT_EQ(result.error.find("blob.off"), std::string::npos) << result.error;

    // The good model is traced and keeps its name for the next filters.
    auto* traced = vtkMultiBlockDataSet::SafeDownCast(tracer->GetOutputDataObject(0));
    ASSERT_NE(traced, nullptr);
    auto* good = vtkPolyData::SafeDownCast(traced->GetBlock(0));
    ASSERT_NE(good, nullptr);
    EXPECT_GT(good->GetNumberOfPoints(), 0);
    EXPECT_EQ(sourceFileOf(good), "blob.off");
  }
}

// The reader's SourceFile survives every per-surface filter, and the
// remesher keeps it on the model's remesh (not on the shared connectivity,
// nor on L0, which are no model's).
TEST(FeatureNetTracerFilter, CarriesTheSourceFileToTheRemesh)
{
  const std::string folder = examplesDir() + "/";
  vtkSmartPointer<vtkPolyData> blob = readLandmarked(folder + "blob.off", folder + "blob.vts");
  EXPECT_EQ(sourceFileOf(blob), "blob.off"); // reader, then Landmarks From File
  vtkSmartPointer<vtkPolyData> capsule = readLandmarked(folder + "capsule.obj", folder + "capsule.pinned");
  EXPECT_EQ(sourceFileOf(capsule), "capsule.obj");
  vtkSmartPointer<vtkPolyData> l0 = baseDomainOf(blob);
  EXPECT_EQ(sourceFileOf(l0), "");

  vtkNew<vtkCMPFeatureNetTracer> tracer;
  tracer->SetInputData(0, capsule);
  tracer->SetInputData(1, l0);
  vtkNew<vtkCMPNetStraightener> straightener;
  straightener->SetInputConnection(0, tracer->GetOutputPort(0));
  straightener->SetInputData(1, l0);
  vtkNew<vtkCMPSemiRegularRemesher> remesher;
  remesher->SetInputConnection(0, straightener->GetOutputPort(0));
  remesher->SetInputData(1, l0);
  remesher->SetLevel(2);
  const RunResult result = run(remesher);
  ASSERT_TRUE(result.succeeded) << result.error;
  for (vtkAlgorithm* filter : { static_cast<vtkAlgorithm*>(tracer), static_cast<vtkAlgorithm*>(straightener) })
    for (int port : { 0, 1 })
      EXPECT_EQ(sourceFileOf(filter->GetOutputDataObject(port)), "capsule.obj")
        << filter->GetClassName() << " output " << port;
  EXPECT_EQ(sourceFileOf(remesher->GetOutputDataObject(0)), "capsule.obj");
  EXPECT_EQ(sourceFileOf(remesher->GetOutputDataObject(1)), "");
}

// A surface made in memory has no file name: the messages are as before.
TEST(FeatureNetTracerFilter, InMemorySurfaceGivesTheUnprefixedMessage)
{
  vtkSmartPointer<vtkPolyData> octahedron = octahedronInMemory();
  setFeatureIds(octahedron, { 0, 1, 2, 3, 4, 5 });
  vtkSmartPointer<vtkPolyData> l0 = vtkSmartPointer<vtkPolyData>::New();
  l0->DeepCopy(octahedron);
  vtkSmartPointer<vtkPolyData> fewer = vtkSmartPointer<vtkPolyData>::New();
  fewer->DeepCopy(octahedron);
  setFeatureIds(fewer, { 0, 1, 2, 3, 4 });
  ASSERT_EQ(sourceFileOf(fewer), "");

  vtkNew<vtkCMPFeatureNetTracer> tracer;
  tracer->SetInputData(0, fewer);
  tracer->SetInputData(1, l0);
  const RunResult result = run(tracer);
  EXPECT_FALSE(result.succeeded);
  EXPECT_NE(result.error.find("): base domain has 6 vertices but the surface has 5 landmarks"), std::string::npos)
    << result.error;

  // The same surface in a multiblock: still no name to give, still the old message.
  tracer->SetInputData(0, blocksOf({ octahedron, fewer }));
  const RunResult inBlocks = run(tracer);
  EXPECT_FALSE(inBlocks.succeeded);
  EXPECT_NE(inBlocks.error.find("): base domain has 6 vertices but the surface has 5 landmarks"), std::string::npos)
    << inBlocks.error;
}
