#include <cmp/io/MeshFile.h>
#include <cmp/mesh/SurfaceCheck.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

using namespace cmp;
using test::writeTempFile;

namespace
{

enum class Encoding
{
  Ascii,
  Little,
  Big
};

const char* formatName(Encoding encoding)
{
  return encoding == Encoding::Ascii ? "ascii" : encoding == Encoding::Little ? "binary_little_endian"
                                                                             : "binary_big_endian";
}

// Appends the `size` low bytes of `bits` in the file's byte order.
void putBytes(std::string& out, std::uint64_t bits, int size, Encoding encoding)
{
  for (int b = 0; b < size; ++b)
  {
    const int shift = encoding == Encoding::Little ? b : size - 1 - b;
    out.push_back(static_cast<char>((bits >> (8 * shift)) & 0xff));
  }
}

void putDouble(std::string& out, double value, Encoding encoding)
{
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  putBytes(out, bits, 8, encoding);
}

void putFloat(std::string& out, float value, Encoding encoding)
{
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  putBytes(out, bits, 4, encoding);
}

std::string exact(double value)
{
  char text[40];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

// `mesh` as PLY with double coordinates, an extra uchar and a list per
// vertex, a uchar face count and int indices, and a trailing element: what
// the reader must skip by the declared types.
std::string writePLY(const TriangleMesh& mesh, Encoding encoding)
{
  std::string out = std::string("ply\nformat ") + formatName(encoding) +
    " 1.0\ncomment written by TestPlyFile\nelement vertex " + std::to_string(mesh.vertexCount()) +
    "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar quality\n"
    "property list uchar float extra\nelement face " +
    std::to_string(mesh.triangleCount()) +
    "\nproperty list uchar int vertex_indices\nproperty short label\nelement material 1\nproperty float shine\n"
    "end_header\n";
  const bool ascii = encoding == Encoding::Ascii;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const Vec3& p = mesh.points[v];
    if (ascii)
      out += exact(p.x()) + " " + exact(p.y()) + " " + exact(p.z()) + " 7 2 0.5 -1\n";
    else
    {
      for (int k = 0; k < 3; ++k)
        putDouble(out, p[k], encoding);
      putBytes(out, 7, 1, encoding);
      putBytes(out, 2, 1, encoding);
      putFloat(out, 0.5f, encoding);
      putFloat(out, -1.0f, encoding);
    }
  }
  for (const Triangle& t : mesh.triangles)
  {
    if (ascii)
      out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " -3\n";
    else
    {
      putBytes(out, 3, 1, encoding);
      for (int k = 0; k < 3; ++k)
        putBytes(out, static_cast<std::uint32_t>(t[k]), 4, encoding);
      putBytes(out, static_cast<std::uint16_t>(-3), 2, encoding);
    }
  }
  if (ascii)
    out += "0.25\n";
  else
    putFloat(out, 0.25f, encoding);
  return out;
}

Status readPLYText(const std::string& name, const std::string& text, MeshFileData& data)
{
  return readPLY(writeTempFile(name, text), data);
}

void expectError(const std::string& name, const std::string& text, const std::string& fragment)
{
  MeshFileData data;
  const Status s = readPLYText(name, text, data);
  EXPECT_FALSE(s.ok()) << name;
  EXPECT_NE(s.message().find(fragment), std::string::npos) << name << ": " << s.message();
  EXPECT_NE(s.message().find(name), std::string::npos) << "the message names the file: " << s.message();
  EXPECT_TRUE(data.mesh.points.empty() && data.mesh.triangles.empty()) << name;
}

const char* kTetraHeader = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
const char* kTetraPoints = "0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n";

} // namespace

TEST(PlyFile, ReadsEveryEncodingIdenticallySkippingOtherProperties)
{
  const TriangleMesh octahedron = test::octahedron();
  for (Encoding encoding : { Encoding::Ascii, Encoding::Little, Encoding::Big })
  {
    MeshFileData data;
    const Status s = readPLYText(std::string("octa-") + formatName(encoding) + ".ply", writePLY(octahedron, encoding),
      data);
    ASSERT_TRUE(s.ok()) << formatName(encoding) << ": " << s.message();
    EXPECT_EQ(data.mesh.points, octahedron.points) << formatName(encoding);
    EXPECT_EQ(data.mesh.triangles, octahedron.triangles) << formatName(encoding);
    EXPECT_EQ(data.fileToMeshPoint.size(), 6u);
    EXPECT_TRUE(data.cornerTexCoords.empty());
    // Scalar properties are kept, lists and other elements skipped.
    ASSERT_EQ(data.pointProperties.size(), 1u) << formatName(encoding);
    EXPECT_EQ(data.pointProperties[0].name, "quality");
    EXPECT_EQ(data.pointProperties[0].values, std::vector<double>(6, 7.0));
    ASSERT_EQ(data.triangleProperties.size(), 1u) << formatName(encoding);
    EXPECT_EQ(data.triangleProperties[0].name, "label");
    EXPECT_EQ(data.triangleProperties[0].values, std::vector<double>(8, -3.0));
  }
}

TEST(PlyFile, FanTriangulatesPolygonsAndRoundsFloatValues)
{
  // A cube of quads with a CRLF header and a vertex_index list of ushort count.
  const std::string text = "ply\r\nformat ascii 1.0\r\nelement vertex 8\r\nproperty float x\r\nproperty float y\r\n"
                           "property float z\r\nelement face 6\r\nproperty list ushort uint vertex_index\r\n"
                           "end_header\r\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0.1 1 1\n"
                           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
  MeshFileData data;
  const Status s = readPLYText("cube.ply", text, data);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(data.mesh.triangleCount(), 12);
  EXPECT_EQ(data.mesh.triangles[0], (Triangle{ 0, 3, 2 }));
  EXPECT_EQ(data.mesh.triangles[1], (Triangle{ 0, 2, 1 }));
  EXPECT_EQ(data.mesh.points[7].x(), static_cast<double>(0.1f)) << "declared float: rounded as VTK's reader does";
  EXPECT_TRUE(data.pointProperties.empty());
  EXPECT_TRUE(checkSurface(data.mesh).ok()) << checkSurface(data.mesh).message;
}

TEST(PlyFile, ReadsTheSharedModelsAsTheirOFFAndOBJ)
{
  CMP_REQUIRE_SHARED_DATA();
  const std::string dir = test::sharedDataDir();
  for (const std::string model : { "shrec07-fourleg/381.off", "spot/spot.obj" })
  {
    MeshFileData reference;
    const std::string path = dir + "/" + model;
    ASSERT_TRUE((fileExtension(path) == "off" ? readOFF(path, reference) : readOBJ(path, reference)).ok()) << path;
    ASSERT_GT(reference.mesh.triangleCount(), 1000) << path;
    for (Encoding encoding : { Encoding::Ascii, Encoding::Little, Encoding::Big })
    {
      MeshFileData data;
      const std::string name = "model-" + std::string(formatName(encoding)) + ".ply";
      const Status s = readPLYText(name, writePLY(reference.mesh, encoding), data);
      ASSERT_TRUE(s.ok()) << model << " " << formatName(encoding) << ": " << s.message();
      EXPECT_EQ(data.mesh.points, reference.mesh.points) << model << " " << formatName(encoding);
      EXPECT_EQ(data.mesh.triangles, reference.mesh.triangles) << model << " " << formatName(encoding);
      EXPECT_EQ(data.fileToMeshPoint, reference.fileToMeshPoint) << model;
    }
  }
}

TEST(PlyFile, RefusesHeadersItCannotTrust)
{
  expectError("notply.ply", "OFF\n", ":1: not a PLY file");
  expectError("format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", ":2: unknown format");
  expectError("version.ply", "ply\nformat ascii 2.0\nend_header\n", ":2: unsupported PLY version '2.0'");
  expectError("noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\n", ":3: the file ends in the header");
  expectError("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
    ":4: unknown property type 'float128'");
  expectError("orphan.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", ":3: 'property' before any");
  expectError("listcount.ply",
    "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n",
    ":4: a list's count type must be an integer type");
  expectError("twice.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\nend_header\n",
    ":5: a second property 'x'");
  expectError("keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 1\nend_header\n", ":3: unknown header line");
  expectError("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n",
    ":3: the vertex element needs the scalar properties x, y and z");
  expectError("empty.ply", "ply\nformat ascii 1.0\nelement vertex 2\nend_header\n", ":3: element 'vertex' has no properties");
}

TEST(PlyFile, RefusesAMissingFaceElementOrIndexList)
{
  // VTK 9.2's reader reaches assert(0) on a missing face element.
  expectError("noface.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "end_header\n0 0 0\n1 0 0\n0 1 0\n",
    ":7: no 'face' element in the header: not a surface");
  expectError("nolist.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3\n",
    ":7: the face element has no list property 'vertex_indices'");
  expectError("floatindex.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    ":7: face indices must have an integer type");
}

TEST(PlyFile, RefusesFaceIndicesOutOfRange)
{
  // VTK 9.2's reader segfaults on these.
  expectError("range.ply", std::string(kTetraHeader) + kTetraPoints + "3 0 1 2\n3 0 3 1\n3 0 2 4\n3 1 3 2\n",
    ":16: vertex index 4 out of range (the file has 4 points)");
  expectError("negative.ply", std::string(kTetraHeader) + kTetraPoints + "3 0 1 2\n3 0 3 -1\n3 0 2 3\n3 1 3 2\n",
    ":15: vertex index -1 out of range");
  std::string binary = writePLY(test::tetrahedron(), Encoding::Little);
  // Face 2's second index, in the binary body: 4 vertices of 34 bytes, then faces of 15 bytes.
  const std::size_t body = binary.find("end_header\n") + 11;
  const std::size_t at = body + 4 * 34 + 2 * 15 + 1 + 4;
  binary[at] = '\x10';
  binary[at + 3] = '\x7f';
  expectError("range-binary.ply", binary,
    ": byte " + std::to_string(body + 4 * 34 + 2 * 15) + ": vertex index 2130706448 out of range");
}

TEST(PlyFile, RefusesRecordsWithTooFewOrTooManyValues)
{
  // VTK 9.2's reader calls strtod(NULL) on a short line.
  expectError("short.ply", std::string(kTetraHeader) + "0.0 0.0 0.0\n1.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    ":11: point 1 has 2 values, too few for its properties ('z' is missing)");
  expectError("shortface.ply", std::string(kTetraHeader) + kTetraPoints + "3 0 1 2\n3 0 3\n3 0 2 3\n3 1 3 2\n",
    ":15: face 1: list 'vertex_indices' announces 3 values but the line has 2 left");
  expectError("long.ply", std::string(kTetraHeader) + kTetraPoints + "3 0 1 2 3\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    ":14: face 0 has 5 values; its properties take 4");
  expectError("two.ply", std::string(kTetraHeader) + kTetraPoints + "2 0 1\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    ":14: face 0 has 2 vertices; a face needs at least three");
  expectError("word.ply", std::string(kTetraHeader) + "0 0 x\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    ":10: point 0: 'x' is not a float (property 'z')");
  expectError("uchar.ply", std::string(kTetraHeader) + kTetraPoints + "300 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    ":14: face 0: list count '300' is not a uchar");
  expectError("ends.ply", std::string(kTetraHeader) + kTetraPoints + "3 0 1 2\n3 0 3 1\n3 0 2 3\n",
    ":16: the file ends after 3 of the 4 faces the header (line 7) claims");
  expectError("trailing.ply", std::string(kTetraHeader) + kTetraPoints + "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n9\n",
    ":18: data after the last element");
}

TEST(PlyFile, BoundsEveryCountByTheFileSize)
{
  expectError("huge.ply",
    "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\nproperty float x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
    ":3: the header claims 2147483648 points but the file has room for at most 0");
  expectError("overflow.ply",
    "ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\nproperty float x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n",
    ":3: the header claims 99999999999999999999999 points but the file has room for at most 1");
  // Four points fit, but not also 1000 faces of at least 13 bytes each.
  std::string binary = writePLY(test::tetrahedron(), Encoding::Little);
  binary.replace(binary.find("element face 4"), 14, "element face 1000");
  expectError("faces.ply", binary, ":10: the header claims 1000 faces but the file has room for at most");
  // A list count of 255 floats where the file ends: no read past its end.
  binary = writePLY(test::tetrahedron(), Encoding::Big);
  const std::size_t body = binary.find("end_header\n") + 11;
  binary[body + 3 * 8 + 1] = '\xff';
  expectError("list.ply", binary,
    ": byte " + std::to_string(body + 25) + ": point 0: list 'extra' announces 255 values but the file ends");
}

TEST(PlyFile, RefusesEveryTruncationAndSurvivesDamageOfABinaryFile)
{
  // A binary file cut anywhere is incomplete; damaged anywhere, it may read
  // or fail, but must not crash (the sanitizer build checks every access).
  const std::string binary = writePLY(test::sphere(1), Encoding::Little);
  const std::string path = test::tempPath("damaged.ply");
  MeshFileData data;
  for (std::size_t size = 0; size < binary.size(); size += 7)
  {
    writeTempFile("damaged.ply", binary.substr(0, size));
    const Status s = readPLY(path, data);
    EXPECT_FALSE(s.ok()) << "cut at " << size;
    EXPECT_EQ(s.message().compare(0, path.size(), path), 0) << s.message();
  }
  std::mt19937 random(26);
  int accepted = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    std::string damaged = binary;
    for (int k = 0; k < 4; ++k)
      damaged[random() % damaged.size()] = static_cast<char>(random() & 0xff);
    writeTempFile("damaged.ply", damaged);
    const Status s = readPLY(path, data);
    if (s.ok())
    {
      ++accepted;
      for (const Triangle& t : data.mesh.triangles)
        for (int v : t)
          ASSERT_TRUE(v >= 0 && v < data.mesh.vertexCount());
    }
    else
      EXPECT_EQ(s.message().compare(0, path.size(), path), 0) << s.message();
  }
  EXPECT_GT(accepted, 0) << "some damage only changes coordinates";
  EXPECT_LT(accepted, 300) << "some damage breaks the header or the indices";
}

TEST(PlyFile, MessagesQuotingDamagedBytesAreValidText)
{
  // A face's list count with bytes that are not text: the message quotes the
  // word with those bytes escaped, so Python and ParaView can show it.
  const std::string text = std::string(kTetraHeader) + kTetraPoints + "3 0 1 2\n3H\xad\xce 0 1 3\n3 0 2 3\n3 1 2 3\n";
  MeshFileData data;
  const Status s = readPLYText("binary-word.ply", text, data);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("'3H\\xAD\\xCE'"), std::string::npos) << s.message();
  // Valid UTF-8 (a file name with an accent) and newlines are kept.
  EXPECT_EQ(Status::error("caf\xc3\xa9.ply:\tline 2\n").message(), "caf\xc3\xa9.ply:\tline 2\n");
  EXPECT_EQ(Status::error("\x01\xff\xc3").message(), "\\x01\\xFF\\xC3");
  EXPECT_EQ(Status::error("\xed\xa0\x80").message(), "\\xED\\xA0\\x80") << "a surrogate is not text";
}
