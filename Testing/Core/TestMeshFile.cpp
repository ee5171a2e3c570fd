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
  EXPECT_NE(s.message().find("file ends after 2 of 4 points"), std::string::npos) << s.message();
  s = readOFF(writeTempFile("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), data);
  EXPECT_NE(s.message().find(":6: vertex index 7 out of range"), std::string::npos) << s.message();
  s = readOFF("/nonexistent/mesh.off", data);
  EXPECT_NE(s.message().find("cannot open '/nonexistent/mesh.off'"), std::string::npos) << s.message();
  s = readOFF(writeTempFile("binary.off", std::string("OFF\0\1\2", 6)), data);
  EXPECT_NE(s.message().find("is not a text file"), std::string::npos) << s.message();
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
