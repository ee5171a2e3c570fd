#include <cmp/io/Landmarks.h>
#include <cmp/io/MeshFile.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

using namespace cmp;
using test::writeTempFile;

namespace
{

void expectError(const Status& status, const std::string& fragment)
{
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find(fragment), std::string::npos) << "message: " << status.message();
}

} // namespace

TEST(Landmarks, ReadsPinnedAndPlainLists)
{
  const TriangleMesh mesh = test::octahedron();
  LandmarkList landmarks;
  ASSERT_TRUE(readLandmarkFile(writeTempFile("a.pinned", "lk 4\nlk 0\n# comment\n\nlk 5\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 4, 0, 5 }));
  ASSERT_TRUE(readLandmarkFile(writeTempFile("b.txt", "2\n3\n1\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 2, 3, 1 }));
}

TEST(Landmarks, ReadsVtsAndChecksPositions)
{
  const TriangleMesh mesh = test::octahedron();
  LandmarkList landmarks;
  ASSERT_TRUE(readLandmarkFile(writeTempFile("a.vts", "  4  0 0 1\n 1 -1 0 0\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 4, 1 }));
  expectError(readLandmarkFile(writeTempFile("b.vts", "4 0 0 1\n1 0.5 0 0\n"), mesh, {}, landmarks),
    "b.vts:2: landmark 1: vertex 1 is at (-1, 0, 0) but the file says (0.5, 0, 0)");
  expectError(readLandmarkFile(writeTempFile("c.vts", "4 0 0\n"), mesh, {}, landmarks), "expected 'vertex_id x y z'");
}

TEST(Landmarks, SnapsCsvPositionsToNearestVertex)
{
  const TriangleMesh mesh = test::sphere(3);
  LandmarkList landmarks;
  ASSERT_TRUE(
    readLandmarkFile(writeTempFile("a.csv", "x,y,z\n0.99,0.01,0\n0, -0.02, 1.01\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 0, 4 }));
  expectError(readLandmarkFile(writeTempFile("b.csv", "5,5,5\n"), mesh, {}, landmarks), "wrong coordinate frame?");
  expectError(readLandmarkFile(writeTempFile("c.csv", "1,0,0\n1,0.001,0\n"), mesh, {}, landmarks),
    "duplicate landmark: features 0 and 1 are both on vertex 0");
}

TEST(Landmarks, MapsFileIdsThroughWelding)
{
  const TriangleMesh mesh = test::octahedron();
  LandmarkList landmarks;
  const std::vector<int> fileToMesh = { 0, 1, 2, 3, 4, 5, 0, 4 };
  ASSERT_TRUE(readLandmarkFile(writeTempFile("w.pinned", "lk 7\nlk 2\n"), mesh, fileToMesh, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 4, 2 }));
  expectError(readLandmarkFile(writeTempFile("x.pinned", "lk 8\n"), mesh, fileToMesh, landmarks),
    "x.pinned:1: landmark vertex id 8 is out of range (the mesh has 8 points)");
}

TEST(Landmarks, WrittenFilesReadBackInEveryFormat)
{
  const TriangleMesh mesh = test::octahedron();
  // File points 3 and 6 were welded into mesh vertex 0, and file point 0
  // is mesh vertex 3: the writer gives each vertex its first file point.
  const std::vector<int> fileToMesh = { 3, 1, 2, 0, 4, 5, 0 };
  const LandmarkList landmarks = { 5, 0, 3 };
  for (const char* name : { "round.vts", "round.pinned", "round.csv", "round.txt" })
  {
    const std::string path = test::tempPath(name);
    ASSERT_TRUE(writeLandmarkFile(path, landmarks, mesh, fileToMesh).ok()) << name;
    LandmarkList read;
    const Status status = readLandmarkFile(path, mesh, fileToMesh, read);
    ASSERT_TRUE(status.ok()) << name << ": " << status.message();
    EXPECT_EQ(read, landmarks) << name;
  }
  std::string text;
  ASSERT_TRUE(formatLandmarkFile("a.pinned", landmarks, mesh, fileToMesh, text).ok());
  EXPECT_EQ(text, "lk 5\nlk 3\nlk 0\n");

  expectError(formatLandmarkFile("a.vts", {}, mesh, {}, text), "no landmarks to write");
  expectError(formatLandmarkFile("a.vts", { 1, 1 }, mesh, {}, text), "duplicate landmark");
  expectError(formatLandmarkFile("a.vts", { 1 }, mesh, { 0, 0 }, text), "which no point of the mesh file maps to");
  expectError(writeLandmarkFile("/nonexistent-folder/a.vts", landmarks, mesh, {}),
    "/nonexistent-folder/a.vts: cannot write the landmark file");
}

TEST(Landmarks, ReportsBadFiles)
{
  const TriangleMesh mesh = test::octahedron();
  LandmarkList landmarks;
  expectError(readLandmarkFile(writeTempFile("d.pinned", "lk 1\nlk 1\n"), mesh, {}, landmarks),
    "duplicate landmark: features 0 and 1 are both on vertex 1");
  expectError(readLandmarkFile(writeTempFile("e.pinned", "lk 1\nlk 6\n"), mesh, {}, landmarks),
    "e.pinned:2: landmark vertex id 6 is out of range");
  expectError(readLandmarkFile(writeTempFile("f.pinned", "lk one\n"), mesh, {}, landmarks),
    "f.pinned:1: expected a vertex id, found 'lk one'");
  expectError(readLandmarkFile(writeTempFile("g.pinned", "# nothing\n"), mesh, {}, landmarks), "no landmarks");
  expectError(readLandmarkFile("/nonexistent.vts", mesh, {}, landmarks), "cannot open '/nonexistent.vts'");
}

// Issue 26: a line with a field more than its format has was accepted, the
// field ignored; such a file is of another format or damaged.
TEST(Landmarks, RejectsLinesWithExtraFields)
{
  const TriangleMesh mesh = test::octahedron();
  LandmarkList landmarks;
  expectError(readLandmarkFile(writeTempFile("extra.vts", "4 0 0 1\n1 -1 0 0 7\n"), mesh, {}, landmarks),
    "extra.vts:2: expected 'vertex_id x y z', found '7' after them");
  expectError(readLandmarkFile(writeTempFile("word.vts", "4 0 0 1 nose\n"), mesh, {}, landmarks),
    "word.vts:1: expected 'vertex_id x y z', found 'nose' after them");
  expectError(readLandmarkFile(writeTempFile("extra.pinned", "lk 4\nlk 0 5\n"), mesh, {}, landmarks),
    "extra.pinned:2: expected 'lk ID' or 'ID', found 'lk 0 5'");
  expectError(readLandmarkFile(writeTempFile("extra.txt", "4\n0 1\n"), mesh, {}, landmarks),
    "extra.txt:2: expected 'lk ID' or 'ID', found '0 1'");
  expectError(readLandmarkFile(writeTempFile("extra.csv", "x,y,z\n1,0,0\n0,1,0,1\n"), mesh, {}, landmarks),
    "extra.csv:3: expected 'x,y,z', found '1' after them");
  // Blanks, a CR and comments after the fields are no fields.
  ASSERT_TRUE(readLandmarkFile(writeTempFile("blank.vts", "4 0 0 1  \r\n1 -1 0 0 # tip\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 4, 1 }));
  ASSERT_TRUE(readLandmarkFile(writeTempFile("blank.pinned", "lk 4 \r\nlk 0\t# nose\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 4, 0 }));
  ASSERT_TRUE(readLandmarkFile(writeTempFile("blank.csv", "1,0,0 \r\n0,1,0\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 0, 2 }));
}

// Issue 26: some damaged .pinned files failed with an empty message. Every
// damage here must fail with a message that names the file.
TEST(Landmarks, DamagedPinnedFilesFailWithAMessage)
{
  const TriangleMesh mesh = test::octahedron();
  const std::string damaged[] = { "", "\n\n", "lk\n", "lk \n", "lk -\n", "lk 4\nlk", "lk 4\nl", "lk 4\nk 0\n",
    "lk 99999999999999999999999\n", "lk -1\n", "lk 1e3\n", "lk 0x4\n", "lk 4\nlk 4\n", std::string("lk 4\0\n", 6),
    "\xff\xfe\x00\x01", "lk 4\r\nlk 5\r\nlk\r\n", "lk\t\t\n", "lklk 4\n", "lk 2147483648\n" };
  int index = 0;
  for (const std::string& text : damaged)
  {
    const std::string name = "damaged" + std::to_string(index++) + ".pinned";
    LandmarkList landmarks;
    const Status status = readLandmarkFile(writeTempFile(name, text), mesh, {}, landmarks);
    EXPECT_FALSE(status.ok()) << name;
    EXPECT_NE(status.message().find(name), std::string::npos) << name << ": '" << status.message() << "'";
    EXPECT_GT(status.message().size(), test::tempPath(name).size() + 4) << name << ": '" << status.message() << "'";
  }
}

TEST(Landmarks, ValidatesCountAndRange)
{
  expectError(validateLandmarks({ 0, 1, 2 }, 6, 4), "3 landmarks but 4 are expected");
  expectError(validateLandmarks({ 0, 9 }, 6), "landmark 1 is vertex 9, which is out of range");
  EXPECT_TRUE(validateLandmarks({ 5, 0, 3 }, 6, 3).ok());
}

TEST(Landmarks, FeatureIdArrayRoundTripsAndIsValidated)
{
  const LandmarkList landmarks = { 5, 0, 3 };
  const std::vector<int> ids = featureIdsOf(landmarks, 6);
  EXPECT_EQ(ids, (std::vector<int>{ 1, -1, -1, 2, -1, 0 }));
  LandmarkList back;
  ASSERT_TRUE(landmarksFromFeatureIds(ids, back).ok());
  EXPECT_EQ(back, landmarks);
  expectError(landmarksFromFeatureIds({ 0, -1, 2, -1 }, back), "missing landmark: feature 1 is on no vertex");
  expectError(landmarksFromFeatureIds({ 0, 1, 1, -1 }, back), "feature 1 is on vertices 1 and 2");
  expectError(landmarksFromFeatureIds({ -1, -1 }, back), "no landmarks");
  expectError(landmarksFromFeatureIds({ -3, 0 }, back), "FeatureId -3 at vertex 0 is invalid");
}

TEST(Landmarks, RealLandmarkFilesMatchTheirMeshes)
{
  CMP_REQUIRE_SHARED_DATA();
  for (const std::string& model : test::landmarkedFourLeggedModels())
  {
    MeshFileData data;
    ASSERT_TRUE(readOFF(model + ".off", data).ok());
    LandmarkList landmarks;
    const Status s = readLandmarkFile(model + ".vts", data.mesh, data.fileToMeshPoint, landmarks);
    EXPECT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(landmarks.size(), 21u) << model;
  }
  MeshFileData spot;
  ASSERT_TRUE(readOBJ(test::sharedDataDir() + "/spot/spot.obj", spot).ok());
  LandmarkList landmarks;
  ASSERT_TRUE(
    readLandmarkFile(test::sharedDataDir() + "/spot/spot_shrec07.pinned", spot.mesh, spot.fileToMeshPoint, landmarks)
      .ok());
  EXPECT_EQ(landmarks.size(), 21u);
}

// Issue 27: a feature that could not be placed on a model is -1 in every
// format, and reads back as kMissingLandmark.
TEST(Landmarks, MissingFeaturesReadAndWriteInEveryFormat)
{
  const TriangleMesh mesh = test::sphere(2);
  LandmarkList landmarks;
  ASSERT_TRUE(readLandmarkFile(writeTempFile("m.vts", "0 1 0 0\n-1 9 9 9 anything\n4 0 0 1\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 0, kMissingLandmark, 4 }));
  ASSERT_TRUE(readLandmarkFile(writeTempFile("m.pinned", "lk -1\nlk 4\n-1\n"), mesh, {}, landmarks).ok());
  EXPECT_EQ(landmarks, (LandmarkList{ kMissingLandmark, 4, kMissingLandmark }));
  // nan,nan,nan and an empty row are missing; empty rows at the end are not.
  // A comment line is no row.
  ASSERT_TRUE(readLandmarkFile(
    writeTempFile("m.csv", "x,y,z\n1,0,0\n# the tail\nnan,nan,nan\n\n0,0,1\n\n\n"), mesh, {}, landmarks)
                .ok());
  EXPECT_EQ(landmarks, (LandmarkList{ 0, kMissingLandmark, kMissingLandmark, 4 }));
  EXPECT_EQ(missingLandmarkCount(landmarks), 2);
  expectError(readLandmarkFile(writeTempFile("n.csv", "1,0,0\nnan,0,1\n"), mesh, {}, landmarks),
    "n.csv:2: landmark 1: expected three finite coordinates, or nan,nan,nan");
  expectError(readLandmarkFile(writeTempFile("all.pinned", "lk -1\n-1\n"), mesh, {}, landmarks),
    "all.pinned: every landmark is missing");
  expectError(readLandmarkFile(writeTempFile("neg.pinned", "lk 4\nlk -2\n"), mesh, {}, landmarks),
    "neg.pinned:2: landmark vertex id -2 is out of range");

  const LandmarkList withMissing = { 4, kMissingLandmark, 0 };
  for (const char* name : { "missing.vts", "missing.pinned", "missing.csv" })
  {
    const std::string path = test::tempPath(name);
    ASSERT_TRUE(writeLandmarkFile(path, withMissing, mesh, {}).ok()) << name;
    LandmarkList read;
    const Status status = readLandmarkFile(path, mesh, {}, read);
    ASSERT_TRUE(status.ok()) << name << ": " << status.message();
    EXPECT_EQ(read, withMissing) << name;
  }

  // Stages that need every feature say that one is missing.
  expectError(validateLandmarks(withMissing, mesh.vertexCount()), "landmark 1 is missing");
  EXPECT_TRUE(validateLandmarks(withMissing, mesh.vertexCount(), 3, true).ok());
  // FeatureId holds a missing feature as no vertex; the feature count says
  // how many there are when the last ones are missing.
  const std::vector<int> ids = featureIdsOf({ 4, kMissingLandmark, 0, kMissingLandmark }, mesh.vertexCount());
  LandmarkList back;
  expectError(landmarksFromFeatureIds(ids, back), "missing landmark: feature 1 is on no vertex");
  ASSERT_TRUE(landmarksFromFeatureIds(ids, back, 4, true).ok());
  EXPECT_EQ(back, (LandmarkList{ 4, kMissingLandmark, 0, kMissingLandmark }));
  expectError(landmarksFromFeatureIds(ids, back, 2, true), "FeatureId 2 is not below the feature count, 2");
}
