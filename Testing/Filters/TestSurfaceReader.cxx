#include "FilterTestUtilities.h"
#include "vtkCMPLandmarksFromFile.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkBase64Utilities.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkCellArray.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkSTLWriter.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkZLibDataCompressor.h>

#include <cmp/io/VTPCheck.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

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
  EXPECT_NE(result.error.find("garbage.ply:2: expected 'format ascii|binary_little_endian|binary_big_endian 1.0'"),
    std::string::npos)
    << result.error;
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
  // An open surface is a sphere with holes (issue 27 B); a fin is no surface.
  vtkSmartPointer<vtkPolyData> open = readSurface(writeTempFile("lm-open.off", octahedronOFF(true)));
  vtkNew<vtkCMPLandmarksFromFile> assign;
  assign->SetInputData(open);
  assign->SetLandmarkFile(writeTempFile("lm-open.txt", "0\n1\n").c_str());
  EXPECT_TRUE(run(assign).succeeded) << run(assign).error;
  vtkSmartPointer<vtkPolyData> flipped = readSurface(writeTempFile("lm-flip.off", octahedronOFF()));
  flipped->GetPolys()->ReplaceCellAtId(0, { 2, 0, 4 });
  assign->SetInputData(flipped);
  const RunResult result = run(assign);
  EXPECT_NE(result.error.find("inconsistent orientation"), std::string::npos) << result.error;
}

namespace
{

// What VTK's own reader makes of a PLY file, triangulated as the surface
// reader used to.
vtkSmartPointer<vtkPolyData> readWithVTKPLYReader(const std::string& path)
{
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(reader->GetOutputPort());
  triangulate->Update();
  return triangulate->GetOutput();
}

void expectSameSurface(vtkPolyData* actual, vtkPolyData* expected, const std::string& what)
{
  ASSERT_EQ(actual->GetNumberOfPoints(), expected->GetNumberOfPoints()) << what;
  ASSERT_EQ(actual->GetNumberOfPolys(), expected->GetNumberOfPolys()) << what;
  int differentPoints = 0, differentTriangles = 0;
  for (vtkIdType p = 0; p < actual->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    actual->GetPoint(p, a);
    expected->GetPoint(p, b);
    differentPoints += (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) ? 1 : 0;
  }
  vtkNew<vtkIdList> a, b;
  for (vtkIdType c = 0; c < actual->GetNumberOfPolys(); ++c)
  {
    actual->GetCellPoints(c, a);
    expected->GetCellPoints(c, b);
    bool same = a->GetNumberOfIds() == b->GetNumberOfIds();
    for (vtkIdType k = 0; same && k < a->GetNumberOfIds(); ++k)
      same = a->GetId(k) == b->GetId(k);
    differentTriangles += same ? 0 : 1;
  }
  EXPECT_EQ(differentPoints, 0) << what;
  EXPECT_EQ(differentTriangles, 0) << what;
}

std::string expectReadError(const std::string& name, const std::string& text)
{
  RunResult result;
  vtkSmartPointer<vtkPolyData> surface = readSurface(writeTempFile(name, text), &result);
  EXPECT_FALSE(result.succeeded) << name;
  EXPECT_EQ(surface->GetNumberOfPoints(), 0) << name;
  EXPECT_NE(result.error.find(name), std::string::npos) << "the message names the file: " << result.error;
  return result.error;
}

} // namespace

TEST(SurfaceReader, ReadsPLYAsVTKsReaderDid)
{
  CMP_REQUIRE_SHARED_DATA();
  for (const std::string model : { "/spot/spot.obj", "/shrec07-fourleg/381.off" })
  {
    vtkSmartPointer<vtkPolyData> surface = readSurface(sharedDataDir() + model);
    for (const bool binary : { false, true })
    {
      const std::string path = tempPath(std::string("vtk-") + (binary ? "binary" : "ascii") + ".ply");
      vtkNew<vtkPLYWriter> writer;
      writer->SetInputData(surface);
      writer->SetFileName(path.c_str());
      if (binary)
        writer->SetFileTypeToBinary();
      else
        writer->SetFileTypeToASCII();
      ASSERT_TRUE(writer->Write()) << path;
      expectSameSurface(readSurface(path), readWithVTKPLYReader(path), model + (binary ? " binary" : " ASCII"));
    }
  }
}

TEST(SurfaceReader, RefusesPLYFilesThatCrashedVTKsReader)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string points = "0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n";
  EXPECT_NE(expectReadError("range.ply", header + points + "3 0 2 1\n3 0 1 3\n3 0 3 9\n3 1 2 3\n")
              .find("range.ply:16: vertex index 9 out of range"),
    std::string::npos);
  EXPECT_NE(expectReadError("short.ply", header + "0.0 0.0 0.0\n1.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n3 0 2 1\n3 0 1 3\n"
                                                  "3 0 3 2\n3 1 2 3\n")
              .find("short.ply:11: point 1 has 1 values, too few"),
    std::string::npos);
  EXPECT_NE(expectReadError("noface.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                          "property float y\nproperty float z\nend_header\n0 0 0\n")
              .find("noface.ply:7: no 'face' element"),
    std::string::npos);
  // Binary: four float points and a face whose uchar count says 200.
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  binary += std::string(48, '\0') + std::string(1, '\xc8') + std::string(12, '\0');
  EXPECT_NE(expectReadError("damaged.ply", binary).find("list 'vertex_indices' announces 200 values"),
    std::string::npos);
}

TEST(SurfaceReader, RefusesHostileCountsInOFFSTLAndVTP)
{
  EXPECT_NE(expectReadError("huge.off", "OFF\n2147483648 0 0\n").find("huge.off:2: the header claims 2147483648 points"),
    std::string::npos);
  // A binary STL whose header starts with "solid" is still binary to VTK.
  std::string stl = "solid looks like text";
  stl += std::string(80 - stl.size(), ' ') + std::string("\xff\xff\xff\x7f", 4);
  for (int k = 0; k < 50; ++k)
    stl += std::string("\x01\x80\x00\x3f", 4);
  EXPECT_NE(expectReadError("solid.stl", stl).find("the header announces 2147483647 triangles"), std::string::npos);
  const std::string vtp = "<VTKFile type=\"PolyData\" version=\"1.0\">\n<PolyData>\n<FieldData>\n"
                          "<Array type=\"String\" Name=\"S\" NumberOfTuples=\"2147483648\" format=\"ascii\">"
                          "97 0</Array>\n</FieldData>\n<Piece NumberOfPoints=\"0\"></Piece>\n</PolyData>\n"
                          "</VTKFile>\n";
  EXPECT_NE(expectReadError("strings.vtp", vtp).find("strings.vtp:4: Array 'S' needs 2147483648 values"),
    std::string::npos);
  std::string unknown = vtp;
  unknown.replace(unknown.find("type=\"String\""), 13, "type=\"Str1ng\"");
  EXPECT_NE(expectReadError("type.vtp", unknown).find("type.vtp:4: Array 'S' has type 'Str1ng'"),
    std::string::npos);
}

TEST(SurfaceReader, TheVTPCheckAcceptsEveryModeVTKWrites)
{
  CMP_REQUIRE_SHARED_DATA();
  vtkSmartPointer<vtkPolyData> spot = readLandmarked(sharedDataDir() + "/spot/spot.obj",
    sharedDataDir() + "/spot/spot_shrec07.pinned");
  ASSERT_GT(spot->GetFieldData()->GetNumberOfArrays(), 0) << "field data, a string array among them";
  struct Mode
  {
    const char* name;
    int dataMode;
    bool compressed;
    bool base64;
  };
  for (const Mode& mode : { Mode{ "ascii", vtkXMLWriter::Ascii, false, false },
         Mode{ "binary", vtkXMLWriter::Binary, false, false }, Mode{ "binary-zlib", vtkXMLWriter::Binary, true, false },
         Mode{ "appended", vtkXMLWriter::Appended, false, false },
         Mode{ "appended-zlib", vtkXMLWriter::Appended, true, false },
         Mode{ "appended-base64", vtkXMLWriter::Appended, true, true } })
  {
    for (const int headerType : { vtkXMLWriter::UInt32, vtkXMLWriter::UInt64 })
    {
      const std::string path = tempPath(std::string("spot-") + mode.name + std::to_string(headerType) + ".vtp");
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputData(spot);
      writer->SetFileName(path.c_str());
      writer->SetDataMode(mode.dataMode);
      writer->SetHeaderType(headerType);
      writer->SetEncodeAppendedData(mode.base64);
      if (!mode.compressed)
        writer->SetCompressorTypeToNone();
      ASSERT_TRUE(writer->Write()) << path;
      const cmp::Status s = cmp::checkVTPFile(path);
      EXPECT_TRUE(s.ok()) << mode.name << ": " << s.message();
    }
  }
}

TEST(SurfaceReader, KeepsThePLYAttributesVTKsReaderKept)
{
  // A tetrahedron with normals, colours with alpha, texture coordinates and
  // a quality per point, a colour per face, and one face a quad.
  const std::string text = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                           "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                           "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                           "property float u\nproperty float v\nproperty float quality\nelement face 4\n"
                           "property list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
                           "property uchar blue\nend_header\n"
                           "0 0 0 -1 -1 -1 255 0 0 10 0.1 0.2 5\n1 0 0 1 0 0 0 255 0 20 0.3 0.4 6\n"
                           "0 1 0 0 1 0 0 0 255 30 0.5 0.6 7\n0 0 1 0 0 1 9 9 9 40 0.7 0.8 8\n"
                           "1 1 0 1 1 0 1 2 3 50 0.9 1.0 9\n"
                           "4 0 2 4 1 10 20 30\n3 0 1 3 40 50 60\n3 1 4 3 70 80 90\n3 0 3 2 100 110 120\n";
  const std::string path = writeTempFile("attributes.ply", text);
  vtkSmartPointer<vtkPolyData> ours = readSurface(path);
  vtkSmartPointer<vtkPolyData> theirs = readWithVTKPLYReader(path);
  ASSERT_EQ(ours->GetNumberOfPoints(), 5);
  ASSERT_EQ(ours->GetNumberOfPolys(), 5);
  const auto expectSameArray = [](vtkDataArray* a, vtkDataArray* b, const std::string& name)
  {
    ASSERT_NE(a, nullptr) << name;
    ASSERT_NE(b, nullptr) << name;
    EXPECT_STREQ(a->GetName(), b->GetName());
    EXPECT_EQ(a->GetDataType(), b->GetDataType()) << name;
    ASSERT_EQ(a->GetNumberOfComponents(), b->GetNumberOfComponents()) << name;
    ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples()) << name;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        EXPECT_EQ(a->GetComponent(i, c), b->GetComponent(i, c)) << name << " tuple " << i << " component " << c;
  };
  expectSameArray(ours->GetPointData()->GetNormals(), theirs->GetPointData()->GetNormals(), "Normals");
  expectSameArray(ours->GetPointData()->GetScalars(), theirs->GetPointData()->GetScalars(), "RGBA");
  expectSameArray(ours->GetPointData()->GetTCoords(), theirs->GetPointData()->GetTCoords(), "TCoords");
  expectSameArray(ours->GetCellData()->GetScalars(), theirs->GetCellData()->GetScalars(), "cell RGB");
  EXPECT_EQ(ours->GetPointData()->GetArray("quality"), nullptr) << "VTK's reader dropped other properties";
}

namespace
{

// Base64 as VTK writes it.
std::string base64(const std::string& bytes)
{
  std::string out(bytes.size() * 4 / 3 + 8, '\0');
  const std::size_t size = vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char*>(bytes.data()),
    bytes.size(), reinterpret_cast<unsigned char*>(&out[0]));
  out.resize(size);
  return out;
}

std::string littleEndian64(std::uint64_t value)
{
  std::string out;
  for (int b = 0; b < 8; ++b)
    out.push_back(static_cast<char>((value >> (8 * b)) & 0xff));
  return out;
}

// A zlib-compressed inline binary array of `bytes` in one block, as
// vtkXMLPolyDataWriter writes it with a UInt64 header.
std::string zlibArray(const std::string& bytes)
{
  vtkNew<vtkZLibDataCompressor> zlib;
  vtkSmartPointer<vtkUnsignedCharArray> packed = vtk::TakeSmartPointer(
    zlib->Compress(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  const std::string data(reinterpret_cast<const char*>(packed->GetPointer(0)), packed->GetNumberOfValues());
  return base64(littleEndian64(1) + littleEndian64(bytes.size()) + littleEndian64(bytes.size()) +
           littleEndian64(data.size())) +
    base64(data);
}

// A compressed one-triangle VTP whose offsets end at `lastOffset`, with the
// field data `fields`.
std::string compressedTriangle(std::uint64_t lastOffset, const std::string& fields = "")
{
  std::string points;
  for (float value : { 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f })
    points.append(reinterpret_cast<const char*>(&value), sizeof(value)); // little endian, as the header says
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n<PolyData>\n<FieldData>" +
    fields + "</FieldData>\n<Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">\n<Points><DataArray type=\"Float32\" " +
    "NumberOfComponents=\"3\" format=\"binary\">" + zlibArray(points) + "</DataArray></Points>\n" +
    "<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">" +
    zlibArray(littleEndian64(0) + littleEndian64(1) + littleEndian64(2)) + "</DataArray>" +
    "<DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">" + zlibArray(littleEndian64(lastOffset)) +
    "</DataArray></Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

} // namespace

TEST(SurfaceReader, ChecksCompressedVTPValuesWithVTKsDecompressors)
{
  // Zlib hides these from a check that does not decompress; VTK 9.2 then
  // aborted allocating 2^41 values, or wrote past its string array.
  readSurface(writeTempFile("compressed-ok.vtp", compressedTriangle(3)));
  EXPECT_NE(expectReadError("compressed-offset.vtp", compressedTriangle(std::uint64_t(1) << 41))
              .find("compressed-offset.vtp:7: DataArray 'offsets': its last offset, 2199023255552, is beyond the 3 "
                    "values of the connectivity"),
    std::string::npos);
  const std::string strings = "<Array type=\"String\" Name=\"S\" NumberOfTuples=\"1\" format=\"binary\">" +
    zlibArray(std::string("a\0b\0c\0", 6)) + "</Array>";
  EXPECT_NE(expectReadError("compressed-strings.vtp", compressedTriangle(3, strings))
              .find("compressed-strings.vtp:4: Array 'S' holds 3 strings but declares 1"),
    std::string::npos);
}

TEST(SurfaceReader, RefusesAVTPTriangleWithAPointIdOutOfRange)
{
  // VTK's reader passes connectivity on unchecked; welding (the file has a
  // point twice) and every filter after it read points by these ids.
  for (const char* id : { "7", "-1", "100000000" })
  {
    const std::string text = std::string("<VTKFile type=\"PolyData\" version=\"1.0\">\n<PolyData>\n") +
      "<Piece NumberOfPoints=\"4\" NumberOfPolys=\"1\">\n<Points><DataArray type=\"Float32\" " +
      "NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 1 0</DataArray></Points>\n" +
      "<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 " + id +
      "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys>\n" +
      "</Piece>\n</PolyData>\n</VTKFile>\n";
    EXPECT_NE(expectReadError("id.vtp", text).find(std::string("id.vtp: cell 0 refers to point ") + id +
                ", but the surface has 4 points"),
      std::string::npos)
      << id;
  }
}
