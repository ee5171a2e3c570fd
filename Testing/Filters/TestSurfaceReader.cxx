#include "FilterTestUtilities.h"
#include "vtkCMPLandmarksFromFile.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace cmp::test;

namespace
{

vtkSmartPointer<vtkPolyData> readSurface(const std::string& path, RunResult* outcome = nullptr)
{
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(path.c_str());
  const RunResult result = run(reader);
  if (outcome)
    *outcome = result;
  else
    EXPECT_TRUE(result.succeeded) << path << ": " << result.error;
  return reader->GetOutput();
}

int countLandmarks(vtkPolyData* surface)
{
  vtkDataArray* ids = surface->GetPointData()->GetArray("FeatureId");
  int count = 0;
  for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
    count += ids->GetComponent(i, 0) >= 0 ? 1 : 0;
  return count;
}

} // namespace

TEST(SurfaceReader, ReadsOFF)
{
  vtkSmartPointer<vtkPolyData> surface = readSurface(writeTempFile("octa.off", octahedronOFF()));
  EXPECT_EQ(surface->GetNumberOfPoints(), 6);
  EXPECT_EQ(surface->GetNumberOfPolys(), 8);
}

TEST(SurfaceReader, ReportsMissingGarbageAndUnknownFiles)
{
  RunResult result;
  vtkSmartPointer<vtkPolyData> surface = readSurface("/nonexistent/a.off", &result);
  EXPECT_FALSE(result.succeeded);
  EXPECT_NE(result.error.find("cannot open '/nonexistent/a.off': no such file"), std::string::npos) << result.error;
  EXPECT_EQ(surface->GetNumberOfPoints(), 0);

  readSurface(writeTempFile("garbage.off", "this is not a mesh\n"), &result);
  EXPECT_NE(result.error.find("not an OFF file"), std::string::npos) << result.error;
  readSurface(writeTempFile("garbage.ply", "ply\nformat nonsense\n"), &result);
  EXPECT_NE(result.error.find("cannot read"), std::string::npos) << result.error;
  readSurface(writeTempFile("garbage.stl", std::string(10, '\x01')), &result);
  EXPECT_FALSE(result.succeeded);
  // VTK's own reason is kept, not just "cannot read".
  readSurface(writeTempFile("text.stl", "garbage\n"), &result);
  EXPECT_NE(result.error.find("as stl: "), std::string::npos) << result.error;
  EXPECT_NE(result.error.find("Expecting"), std::string::npos) << result.error;
  // A binary STL announcing 2^31-1 triangles must not make VTK allocate 6 GB and abort.
  std::string bogus(80, '\0');
  bogus += std::string("\xff\xff\xff\x7f", 4) + std::string(100, '\0');
  readSurface(writeTempFile("bogus.stl", bogus), &result);
  EXPECT_NE(result.error.find("the header announces 2147483647 triangles"), std::string::npos) << result.error;
  readSurface(writeTempFile("garbage.vtp", "<VTKFile>oops"), &result);
  EXPECT_FALSE(result.succeeded);
  readSurface(writeTempFile("mesh.xyz", "1 2 3\n"), &result);
  EXPECT_NE(result.error.find("unknown extension"), std::string::npos) << result.error;
}

TEST(SurfaceReader, WeldsSTLAndMapsLandmarkFilesThroughTheWelding)
{
  CMP_REQUIRE_SHARED_DATA();
  vtkSmartPointer<vtkPolyData> spot = readSurface(sharedDataDir() + "/spot/spot.obj");
  ASSERT_EQ(spot->GetNumberOfPoints(), 2930);
  vtkNew<vtkSTLWriter> writer;
  writer->SetInputData(spot);
  writer->SetFileName(tempPath("spot.stl").c_str());
  ASSERT_TRUE(writer->Write());
  vtkSmartPointer<vtkPolyData> welded = readSurface(tempPath("spot.stl"));
  EXPECT_EQ(welded->GetNumberOfPoints(), 2930);
  EXPECT_EQ(welded->GetNumberOfPolys(), 5856);
  vtkDataArray* map = welded->GetFieldData()->GetArray("FileToMeshPointId");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->GetNumberOfTuples(), 3 * 5856);
  EXPECT_EQ(welded->GetFieldData()->GetArray("WeldedPointCount")->GetComponent(0, 0), 3 * 5856 - 2930);

  // Landmark ids written against the STL's own (triplicated) points still land right.
  const double* target = spot->GetPoint(1054);
  std::string list;
  for (int i = 0; i < map->GetNumberOfTuples(); ++i)
  {
    // STL stores floats, so compare at float precision.
    const double* p = welded->GetPoint(static_cast<vtkIdType>(map->GetComponent(i, 0)));
    if (std::abs(p[0] - target[0]) + std::abs(p[1] - target[1]) + std::abs(p[2] - target[2]) < 1e-6)
    {
      list = "lk " + std::to_string(i) + "\n";
      break;
    }
  }
  ASSERT_FALSE(list.empty());
  vtkNew<vtkCMPLandmarksFromFile> assign;
  assign->SetInputData(welded);
  assign->SetLandmarkFile(writeTempFile("stl.pinned", list).c_str());
  ASSERT_TRUE(run(assign).succeeded);
  vtkDataArray* ids = assign->GetOutput()->GetPointData()->GetArray("FeatureId");
  for (vtkIdType v = 0; v < ids->GetNumberOfTuples(); ++v)
  {
    if (ids->GetComponent(v, 0) == 0)
    {
      const double* p = assign->GetOutput()->GetPoint(v);
      EXPECT_NEAR(p[0], target[0], 1e-6);
      EXPECT_NEAR(p[1], target[1], 1e-6);
      EXPECT_NEAR(p[2], target[2], 1e-6);
    }
  }
}

TEST(SurfaceReader, KeepsPerCornerTextureCoordinatesOfSpot)
{
  CMP_REQUIRE_SHARED_DATA();
  vtkSmartPointer<vtkPolyData> spot = readSurface(sharedDataDir() + "/spot/spot.obj");
  vtkDataArray* corners = spot->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(corners, nullptr);
  EXPECT_EQ(corners->GetNumberOfComponents(), 6);
  EXPECT_EQ(corners->GetNumberOfTuples(), 5856);
  EXPECT_EQ(spot->GetPointData()->GetTCoords(), nullptr) << "Spot's texture has seams: no point TCoords";
  // Spot's UVs span about [-0.05, 1.0] in u and [0, 1] in v.
  for (int component = 0; component < 6; ++component)
  {
    double range[2];
    corners->GetRange(range, component);
    EXPECT_GT(range[0], -0.1) << component;
    EXPECT_LT(range[1], 1.01) << component;
  }
  EXPECT_FLOAT_EQ(corners->GetComponent(0, 0), 0.800375f); // first corner is "vt 0.800375 0.667457"
}

TEST(SurfaceReader, VTPKeepsPointArrays)
{
  CMP_REQUIRE_SHARED_DATA();
  vtkSmartPointer<vtkPolyData> spot = readLandmarked(sharedDataDir() + "/spot/spot.obj",
    sharedDataDir() + "/spot/spot_shrec07.pinned");
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(spot);
  writer->SetFileName(tempPath("spot.vtp").c_str());
  // ParaView 5.11's VTK cannot read back appended-mode files that carry
  // numeric field data (the reader welds, so it has some).
  writer->SetDataModeToBinary();
  ASSERT_TRUE(writer->Write());
  vtkSmartPointer<vtkPolyData> back = readSurface(tempPath("spot.vtp"));
  EXPECT_EQ(back->GetNumberOfPoints(), 2930);
  EXPECT_EQ(countLandmarks(back), 21);
}

TEST(LandmarksFromFile, MarksTheLandmarksOfEveryRealModel)
{
  CMP_REQUIRE_SHARED_DATA();
  for (const char* model : { "381", "387", "392" })
  {
    const std::string base = sharedDataDir() + "/shrec07-fourleg/" + model;
    EXPECT_EQ(countLandmarks(readLandmarked(base + ".off", base + ".vts")), 21) << model;
  }
}

TEST(LandmarksFromFile, ReportsBadLandmarkFiles)
{
  vtkSmartPointer<vtkPolyData> octahedron = readSurface(writeTempFile("lm.off", octahedronOFF()));
  vtkNew<vtkCMPLandmarksFromFile> assign;
  assign->SetInputData(octahedron);
  const auto expectError = [&](const std::string& file, const std::string& text, const std::string& fragment)
  {
    assign->SetLandmarkFile(writeTempFile(file, text).c_str());
    const RunResult result = run(assign);
    EXPECT_FALSE(result.succeeded);
    EXPECT_NE(result.error.find(fragment), std::string::npos) << result.error;
    EXPECT_EQ(assign->GetOutput()->GetNumberOfPoints(), 0);
  };
  expectError("dup.pinned", "lk 1\nlk 2\nlk 1\n", "duplicate landmark: features 0 and 2 are both on vertex 1");
  expectError("range.txt", "0\n9\n", "landmark vertex id 9 is out of range");
  assign->SetExpectedLandmarkCount(4);
  expectError("count.txt", "0\n1\n2\n", "3 landmarks but 4 are expected");
  assign->SetExpectedLandmarkCount(-1);
  expectError("missing.vts", "", "no landmarks");
  assign->SetLandmarkFile("");
  EXPECT_NE(run(assign).error.find("no landmark file set"), std::string::npos);
}

TEST(LandmarksFromFile, ChecksTheSurfaceFirst)
{
  vtkSmartPointer<vtkPolyData> open = readSurface(writeTempFile("lm-open.off", octahedronOFF(true)));
  vtkNew<vtkCMPLandmarksFromFile> assign;
  assign->SetInputData(open);
  assign->SetLandmarkFile(writeTempFile("lm-open.txt", "0\n1\n").c_str());
  const RunResult result = run(assign);
  EXPECT_NE(result.error.find("open surface: 3 boundary edges"), std::string::npos) << result.error;
}
