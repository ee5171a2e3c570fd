// libFuzzer target for readLandmarkFile in one format, chosen by
// CMP_FUZZ_FORMAT ("vts", "pinned" or "csv"), on the mesh CMP_FUZZ_MESH (a
// shipped example whose own landmark file is among the seeds), as Landmarks
// From File reads it. A finding is a failure that does not name the file,
// landmarks accepted that are out of range or repeated, or accepted
// landmarks that do not come back the same through FeatureId and through
// the file formatLandmarkFile writes for them.
#include "FuzzInput.h"

#include <cmp/io/Landmarks.h>
#include <cmp/io/MeshFile.h>

#include <cstdio>
#include <set>
#include <string>

#if !defined(CMP_FUZZ_FORMAT) || !defined(CMP_FUZZ_MESH)
#error "compile with -DCMP_FUZZ_FORMAT=\"vts\", \"pinned\" or \"csv\" and -DCMP_FUZZ_MESH=\"path\""
#endif

namespace
{

const cmp::MeshFileData& mesh()
{
  static const cmp::MeshFileData data = []
  {
    cmp::MeshFileData read;
    const std::string path = CMP_FUZZ_MESH;
    const cmp::Status status =
      cmp::fileExtension(path) == "obj" ? cmp::readOBJ(path, read) : cmp::readOFF(path, read);
    if (!status.ok())
      cmp_fuzz::fail("cannot read the target's mesh: " + status.message());
    cmp::weldIdenticalPoints(read);
    return read;
  }();
  return data;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  mesh(); // a broken mesh fails before the first input
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  const cmp::MeshFileData& data = mesh();
  const std::string path = cmp_fuzz::writeInput(bytes, size, CMP_FUZZ_FORMAT);
  cmp::LandmarkList landmarks;
  const cmp::Status status = cmp::readLandmarkFile(path, data.mesh, data.fileToMeshPoint, landmarks);
  if (!status.ok())
  {
    cmp_fuzz::expectNamesFile(status.message(), path);
    return 0;
  }
  const int vertices = data.mesh.vertexCount();
  std::set<int> seen;
  // A feature may be missing (-1), not every one.
  for (int vertex : landmarks)
    if (vertex != cmp::kMissingLandmark && (vertex < 0 || vertex >= vertices || !seen.insert(vertex).second))
      cmp_fuzz::fail("accepted a landmark out of range or repeated");
  if (seen.empty())
    cmp_fuzz::fail("accepted a file whose every landmark is missing");
  if (!cmp::validateLandmarks(landmarks, vertices, -1, true).ok())
    cmp_fuzz::fail("accepted landmarks that validateLandmarks refuses");
  cmp::LandmarkList back;
  const int count = static_cast<int>(landmarks.size());
  if (!cmp::landmarksFromFeatureIds(cmp::featureIdsOf(landmarks, vertices), back, count, true).ok() ||
    back != landmarks)
    cmp_fuzz::fail("landmarks changed through FeatureId");
  std::string text;
  if (!cmp::formatLandmarkFile(path, landmarks, data.mesh, data.fileToMeshPoint, text).ok())
    cmp_fuzz::fail("cannot format accepted landmarks");
  const std::string again = cmp_fuzz::writeInput(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(),
    CMP_FUZZ_FORMAT);
  back.clear();
  const cmp::Status reread = cmp::readLandmarkFile(again, data.mesh, data.fileToMeshPoint, back);
  if (!reread.ok() || back != landmarks)
    cmp_fuzz::fail("landmarks changed through the file formatLandmarkFile wrote: " + reread.message());
  return 0;
}
