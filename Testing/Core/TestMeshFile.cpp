#include <cmp/io/MeshFile.h>
#include <cmp/mesh/SurfaceCheck.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

using namespace cmp;
using test::writeTempFile;

TEST(MeshFile, ReadsOFFWithCommentsQuadsAndCountsOnHeaderLine)
{
  const std::string path = writeTempFile("quad.off", "OFF # cube\n8 6 0\n"
                                                     "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                                     "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n"
                                                     "4 0 4 7 3\n");
  MeshFileData data;
  ASSERT_TRUE(readOFF(path, data).ok());
  EXPECT_EQ(data.mesh.vertexCount(), 8);
  EXPECT_EQ(data.mesh.triangleCount(), 12);
  EXPECT_TRUE(checkSurface(data.mesh).ok()) << checkSurface(data.mesh).message;
  EXPECT_NEAR(surfaceArea(data.mesh), 6.0, 1e-12);
}

TEST(MeshFile, ReportsGarbageAndTruncatedOFF)
{
  MeshFileData data;
  Status s = readOFF(writeTempFile("garbage.off", "hello world\n"), data);
  EXPECT_NE(s.message().find("not an OFF file"), std::string::npos) << s.message();
  s = readOFF(writeTempFile("short.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n"), data);
  EXPECT_NE(s.message().find(":2: the header claims 4 points but the file has room for at most 2"), std::string::npos)
    << s.message();
  s = readOFF(writeTempFile("short2.off", "OFF\n4 4 0\n0.0 0.0 0.0\n1.0 0.0 0.0\n"), data);
  EXPECT_NE(s.message().find(":4: the file ends after 2 of the 4 points the header (line 2) claims"), std::string::npos)
    << s.message();
  s = readOFF(writeTempFile("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), data);
  EXPECT_NE(s.message().find(":6: vertex index 7 out of range"), std::string::npos) << s.message();
  s = readOFF("/nonexistent/mesh.off", data);
  EXPECT_NE(s.message().find("cannot open '/nonexistent/mesh.off'"), std::string::npos) << s.message();
  s = readOFF(writeTempFile("binary.off", std::string("OFF\0\1\2", 6)), data);
  EXPECT_NE(s.message().find("is not a text file"), std::string::npos) << s.message();
}

TEST(MeshFile, BoundsTheOFFCountsByTheFileSize)
{
  // The header alone used to make readOFF reserve 2^31 points and abort
  // with std::bad_alloc.
  MeshFileData data;
  Status s = readOFF(writeTempFile("huge.off", "OFF\n2147483648 0 0\n"), data);
  EXPECT_NE(s.message().find("huge.off:2: the header claims 2147483648 points but the file has room for at most 0"),
    std::string::npos)
    << s.message();
  s = readOFF(writeTempFile("huge1.off", "OFF 1e300 1 0\n0 0 0\n"), data);
  EXPECT_NE(s.message().find("huge1.off:1: the header claims 1e+300 points but the file has room for at most 1"),
    std::string::npos)
    << s.message();
  s = readOFF(writeTempFile("faces.off", "OFF\n3 2147483647 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), data);
  EXPECT_NE(s.message().find("faces.off:2: the header claims 2147483647 faces but the file has room for at most 1 "
                             "after its 3 points"),
    std::string::npos)
    << s.message();
  s = readOFF(writeTempFile("negative.off", "OFF\n-3 1 0\n"), data);
  EXPECT_NE(s.message().find("negative.off:2: invalid vertex or face count"), std::string::npos) << s.message();
}

TEST(MeshFile, BlamesMissingOFFPointsNotFaces)
{
  MeshFileData data;
  // The octahedron's header claims one point more than it lists: its first
  // face is read as point 6 and the file seems to end in the faces.
  const std::string octahedron = "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                 "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  ASSERT_TRUE(readOFF(writeTempFile("octahedron.off", octahedron), data).ok());
  std::string text = octahedron;
  text.replace(text.find("6 8"), 3, "7 8");
  Status s = readOFF(writeTempFile("missing.off", text), data);
  EXPECT_NE(s.message().find("missing.off:2: the header claims 7 points but the file lists only 6: points are "
                             "missing (line 9, a face, was read as point 6)"),
    std::string::npos)
    << s.message();
  // Genuinely missing faces are still reported as faces.
  text = octahedron;
  text.resize(text.rfind("3 "));
  s = readOFF(writeTempFile("nofaces.off", text), data);
  EXPECT_NE(s.message().find("nofaces.off:2: the header claims 8 faces but the file has room for at most 7 after its "
                             "6 points"),
    std::string::npos)
    << s.message();
  text += "3 0 3 5            \n"; // room enough, but a face short
  text.replace(text.find("6 8"), 3, "6 9");
  s = readOFF(writeTempFile("nofaces2.off", text), data);
  EXPECT_NE(s.message().find("nofaces2.off:16: the file ends after 8 of the 9 faces the header (line 2) claims"),
    std::string::npos)
    << s.message();
}

TEST(MeshFile, ReadsOBJWithPerCornerTexCoordsAcrossASeam)
{
  // A tetrahedron whose vertex 0 has two texture coordinates (a seam).
  const std::string path = writeTempFile("seam.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                     "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
                                                     "f 1/1/1 3/3/1 2/2/1\nf 1/4/1 2/2/1 4/3/1\n"
                                                     "f -4/1 -1/2 -2/3\nf 2/2 3/3 4/4\n");
  MeshFileData data;
  ASSERT_TRUE(readOBJ(path, data).ok());
  EXPECT_EQ(data.mesh.vertexCount(), 4);
  EXPECT_TRUE(checkSurface(data.mesh).ok()) << checkSurface(data.mesh).message;
  ASSERT_EQ(data.cornerTexCoords.size(), 4u);
  EXPECT_EQ(data.cornerTexCoords[0][0], Eigen::Vector2d(0, 0));
  EXPECT_EQ(data.cornerTexCoords[1][0], Eigen::Vector2d(0.5, 0.5)); // same point, other side of the seam
  EXPECT_EQ(data.mesh.triangles[2], (Triangle{ 0, 3, 2 }));         // negative indices
}

TEST(MeshFile, ReportsBadOBJ)
{
  MeshFileData data;
  Status s = readOBJ(writeTempFile("bad.obj", "v 0 0 0\nf 1 2 3\n"), data);
  EXPECT_NE(s.message().find(":2: face refers to a vertex that is not defined"), std::string::npos) << s.message();
  s = readOBJ(writeTempFile("none.obj", "this is not a mesh\n"), data);
  EXPECT_NE(s.message().find("no 'v' or 'f' records"), std::string::npos) << s.message();
  // Texture coordinates and normals a face refers to must be defined, also
  // counted from the end; "v//vn" has none (VTK's OBJ reader reads out of
  // bounds otherwise).
  const std::string points = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  s = readOBJ(writeTempFile("normal.obj", points + "f 1/1/1 2/1/99999999999 3/1/1\n"), data);
  EXPECT_NE(s.message().find(":6: face refers to a normal not defined"), std::string::npos) << s.message();
  s = readOBJ(writeTempFile("normal-back.obj", points + "f 1//-2 2//1 3//1\n"), data);
  EXPECT_NE(s.message().find(":6: face refers to a normal not defined"), std::string::npos) << s.message();
  s = readOBJ(writeTempFile("texture-back.obj", points + "f 1/-5 2/1 3/1\n"), data);
  EXPECT_NE(s.message().find(":6: face refers to a texture coordinate not defined"), std::string::npos) << s.message();
  s = readOBJ(writeTempFile("texture-zero.obj", points + "f 1/0 2/1 3/1\n"), data);
  EXPECT_NE(s.message().find(":6: face refers to a texture coordinate not defined"), std::string::npos) << s.message();
  s = readOBJ(writeTempFile("line.obj", points + "f 1 2 3\nl 1 7\n"), data);
  EXPECT_NE(s.message().find(":7: 'l' record refers to a vertex that is not defined"), std::string::npos) << s.message();
  EXPECT_TRUE(readOBJ(writeTempFile("good.obj", points + "f 1/1/1 2/-1/-1 3//1\nl 1 2/1\np -1\n"), data).ok());
}

TEST(MeshFile, WeldsDuplicatedPointsAndKeepsTheFileToMeshMap)
{
  // An octahedron written STL-style: three fresh points per triangle.
  const TriangleMesh octahedron = test::octahedron();
  MeshFileData data;
  for (const Triangle& tri : octahedron.triangles)
  {
    Triangle fresh;
    for (int k = 0; k < 3; ++k)
    {
      fresh[k] = data.mesh.vertexCount();
      data.mesh.points.push_back(octahedron.points[tri[k]]);
    }
    data.mesh.triangles.push_back(fresh);
  }
  for (int v = 0; v < data.mesh.vertexCount(); ++v)
    data.fileToMeshPoint.push_back(v);
  EXPECT_FALSE(checkSurface(data.mesh).ok());
  EXPECT_EQ(weldIdenticalPoints(data), 24 - 6);
  EXPECT_EQ(data.mesh.vertexCount(), 6);
  EXPECT_TRUE(checkSurface(data.mesh).ok()) << checkSurface(data.mesh).message;
  for (int v = 0; v < 24; ++v)
    EXPECT_EQ(data.mesh.points[data.fileToMeshPoint[v]], octahedron.points[octahedron.triangles[v / 3][v % 3]]);
  EXPECT_EQ(weldIdenticalPoints(data), 0);
}

TEST(MeshFile, ReadsSpotWithItsTextureSeams)
{
  CMP_REQUIRE_SHARED_DATA();
  MeshFileData data;
  ASSERT_TRUE(readOBJ(test::sharedDataDir() + "/spot/spot.obj", data).ok());
  EXPECT_EQ(weldIdenticalPoints(data), 0);
  EXPECT_EQ(data.mesh.vertexCount(), 2930);
  EXPECT_EQ(data.mesh.triangleCount(), 5856);
  EXPECT_EQ(data.cornerTexCoords.size(), 5856u);
}
