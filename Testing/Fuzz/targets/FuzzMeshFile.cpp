// libFuzzer target for one of the core's mesh file readers, chosen by
// CMP_FUZZ_FORMAT ("off", "obj" or "ply"): what the Surface Reader does with
// a file before any VTK code sees it, reading, welding, then the input check
// on the surface. Beyond memory errors and undefined behaviour (the
// sanitizers), a finding is: a failure that does not name the file, or a
// surface the reader accepted that breaks its documented shape.
#include "FuzzInput.h"

#include <cmp/io/MeshFile.h>
#include <cmp/mesh/SurfaceCheck.h>

#include <string>

#ifndef CMP_FUZZ_FORMAT
#error "compile with -DCMP_FUZZ_FORMAT=\"off\", \"obj\" or \"ply\""
#endif

namespace
{

cmp::Status readFormat(const std::string& path, cmp::MeshFileData& data)
{
  const std::string format = CMP_FUZZ_FORMAT;
  if (format == "off")
    return cmp::readOFF(path, data);
  if (format == "obj")
    return cmp::readOBJ(path, data);
  return cmp::readPLY(path, data);
}

void checkShape(const cmp::MeshFileData& data, std::size_t filePoints)
{
  const int points = data.mesh.vertexCount();
  for (const auto& triangle : data.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (triangle[k] < 0 || triangle[k] >= points)
        cmp_fuzz::fail("a triangle index out of range after reading");
  if (!data.cornerTexCoords.empty() && data.cornerTexCoords.size() != data.mesh.triangles.size())
    cmp_fuzz::fail("corner texture coordinates for some triangles only");
  for (const auto& property : data.pointProperties)
    if (property.values.size() != filePoints)
      cmp_fuzz::fail("point property '" + property.name + "' without one value per file point");
  for (const auto& property : data.triangleProperties)
    if (property.values.size() != data.mesh.triangles.size())
      cmp_fuzz::fail("triangle property '" + property.name + "' without one value per triangle");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  const std::string path = cmp_fuzz::writeInput(bytes, size, CMP_FUZZ_FORMAT);
  cmp::MeshFileData data;
  const cmp::Status status = readFormat(path, data);
  if (!status.ok())
  {
    cmp_fuzz::expectNamesFile(status.message(), path);
    return 0;
  }
  const std::size_t filePoints = data.mesh.points.size();
  checkShape(data, filePoints);
  cmp::weldIdenticalPoints(data);
  checkShape(data, filePoints);
  if (data.fileToMeshPoint.size() != filePoints)
    cmp_fuzz::fail("welding did not map every file point");
  for (int point : data.fileToMeshPoint)
    if (point < 0 || point >= data.mesh.vertexCount())
      cmp_fuzz::fail("welding mapped a file point out of range");
  const cmp::SurfaceCheckResult check = cmp::checkSurface(data.mesh);
  if (!check.ok() && check.message.empty())
    cmp_fuzz::fail("a surface check failure without a message");
  return 0;
}
