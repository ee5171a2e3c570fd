#include <cmp/io/MeshFile.h>

#include <cmp/io/TextParsing.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <sstream>

namespace cmp
{
namespace
{

void fanTriangulate(const std::vector<int>& polygon, std::vector<Triangle>& triangles)
{
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
  {
    triangles.push_back({ polygon[0], polygon[k], polygon[k + 1] });
  }
}

// A count read as a double, written as an integer while it is one.
std::string formatCount(double count)
{
  if (count >= 0 && count < 1e18 && count == std::floor(count))
    return std::to_string(static_cast<long long>(count));
  std::ostringstream text;
  text << count;
  return text.str();
}

void identityPointMap(MeshFileData& out)
{
  out.fileToMeshPoint.resize(out.mesh.points.size());
  std::iota(out.fileToMeshPoint.begin(), out.fileToMeshPoint.end(), 0);
}

/// One vertex reference of an OBJ record: `v`, `v/vt` and, where normals
/// may follow, `v/vt/vn` or `v//vn`, resolved to 0-based indices (1-based
/// in the file, or counted back from the end when negative).
struct ObjReference
{
  long vertex = -1;
  long texture = -1; ///< -1 when the reference has none.
};

/// Reads the reference at `p` and moves `p` past it. Returns false at the
/// end of the record. `problem` gets what it refers to that is not defined
/// among the `points`, `textures` and `normals` defined so far ("a vertex",
/// "a texture coordinate", "a normal"), and is empty otherwise.
bool readObjReference(
  const char*& p, long points, long textures, long normals, bool withNormal, ObjReference& out, std::string& problem)
{
  problem.clear();
  char* end = nullptr;
  const long v = std::strtol(p, &end, 10);
  if (end == p)
    return false;
  p = end;
  long vt = 0, vn = 0;
  bool hasTex = false, hasNormal = false;
  if (*p == '/')
  {
    ++p;
    vt = std::strtol(p, &end, 10); // none when empty ("v//vn")
    hasTex = end != p;
    p = end;
    if (withNormal && *p == '/')
    {
      ++p;
      vn = std::strtol(p, &end, 10);
      hasNormal = end != p;
      p = end;
    }
  }
  out.vertex = v < 0 ? points + v : v - 1;
  out.texture = !hasTex ? -1 : vt < 0 ? textures + vt : vt - 1;
  vn = vn < 0 ? normals + vn : vn - 1;
  if (out.vertex < 0 || out.vertex >= points)
    problem = "a vertex that is not defined";
  else if (hasTex && (out.texture < 0 || out.texture >= textures))
    problem = "a texture coordinate not defined";
  // Normals are not kept, but a reference to one that is not defined is a
  // damaged file (VTK's OBJ reader reads out of bounds).
  else if (hasNormal && (vn < 0 || vn >= normals))
    problem = "a normal not defined";
  return true;
}

} // namespace

std::string fileExtension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

namespace
{

// Fewest bytes an OFF record can take: a point is three numbers ("1-2-3"),
// a face a count and three indices ("3 0 1 2"), each with its line break.
constexpr std::size_t kMinimumOFFPointBytes = 6;
constexpr std::size_t kMinimumOFFFaceBytes = 8;

// True if `line` reads as an OFF face: integers only, the first one n >= 3
// followed by exactly n more.
bool looksLikeOFFFace(const std::string& line)
{
  const char* p = line.c_str();
  char* end = nullptr;
  const long n = std::strtol(p, &end, 10);
  if (end == p || n < 3 || (*end != ' ' && *end != '\t'))
    return false;
  long count = 0;
  while (true)
  {
    p = end;
    std::strtol(p, &end, 10);
    if (end == p)
      break;
    if (*end != '\0' && *end != ' ' && *end != '\t' && *end != '\r')
      return false; // "0.5" and the like: a coordinate
    ++count;
  }
  return count == n && std::string(p).find_first_not_of(" \t\r") == std::string::npos;
}

} // namespace

Status readOFF(const std::string& path, MeshFileData& out)
{
  out = MeshFileData{};
  std::string text;
  if (Status s = readTextFile(path, text); !s.ok())
    return s;
  LineReader lines(text);
  std::string line;
  if (!lines.next(line, true))
    return Status::error(path + ": empty file");
  const std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string::npos || line.compare(start, 3, "OFF") != 0)
    return Status::error(fileLine(path, lines.number()) + "not an OFF file (first line must be 'OFF')");
  // Counts may follow the keyword on the same line.
  std::string counts = line.substr(start + 3);
  double header[3];
  if (parseNumbers(counts, header, 3) < 2)
  {
    if (!lines.next(counts, true) || parseNumbers(counts, header, 3) < 2)
      return Status::error(fileLine(path, lines.number()) + "expected 'vertex_count face_count edge_count'");
  }
  const int headerLine = lines.number();
  if (!(header[0] >= 0 && header[1] >= 0) || header[0] != std::floor(header[0]) || header[1] != std::floor(header[1]))
    return Status::error(fileLine(path, headerLine) + "invalid vertex or face count");
  // Bound the counts by what the rest of the file can hold before reserving
  // memory for them: a hostile header must not exhaust memory.
  const std::size_t rest = text.size() - std::min(text.size(), lines.offset()) + 1;
  const std::size_t pointRoom = std::min<std::size_t>(rest / kMinimumOFFPointBytes, std::numeric_limits<int>::max());
  if (header[0] > static_cast<double>(pointRoom))
    return Status::error(fileLine(path, headerLine) + "the header claims " + formatCount(header[0]) +
      " points but the file has room for at most " + std::to_string(pointRoom));
  const long pointCount = static_cast<long>(header[0]);
  out.mesh.points.reserve(pointCount);
  double xyz[3];
  // The first of the trailing point lines that read as faces (-1 if none):
  // when the header claims more points than the file lists, the faces are
  // read as points and the file seems to end in the faces.
  long firstFaceLikePoint = -1;
  int firstFaceLikeLine = 0;
  for (long i = 0; i < pointCount; ++i)
  {
    if (!lines.next(line, true))
      return Status::error(fileLine(path, lines.number()) + "the file ends after " + std::to_string(i) + " of the " +
        std::to_string(pointCount) + " points the header (line " + std::to_string(headerLine) + ") claims");
    if (parseNumbers(line, xyz, 3) != 3)
      return Status::error(fileLine(path, lines.number()) + "expected three coordinates");
    if (!looksLikeOFFFace(line))
      firstFaceLikePoint = -1;
    else if (firstFaceLikePoint < 0)
    {
      firstFaceLikePoint = i;
      firstFaceLikeLine = lines.number();
    }
    out.mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  // When the header claims more points than the file lists, its first faces
  // were read as points: say so rather than blame the faces.
  const auto missingPoints = [&]()
  {
    return Status::error(fileLine(path, headerLine) + "the header claims " + std::to_string(pointCount) +
      " points but the file lists only " + std::to_string(firstFaceLikePoint) + ": points are missing (line " +
      std::to_string(firstFaceLikeLine) + ", a face, was read as point " + std::to_string(firstFaceLikePoint) + ")");
  };
  const std::size_t faceRoom = std::min<std::size_t>(
    (text.size() - std::min(text.size(), lines.offset()) + 1) / kMinimumOFFFaceBytes, std::numeric_limits<int>::max());
  if (header[1] > static_cast<double>(faceRoom))
  {
    if (firstFaceLikePoint >= 0)
      return missingPoints();
    return Status::error(fileLine(path, headerLine) + "the header claims " + formatCount(header[1]) +
      " faces but the file has room for at most " + std::to_string(faceRoom) + " after its " +
      std::to_string(pointCount) + " points");
  }
  const long faceCount = static_cast<long>(header[1]);
  out.mesh.triangles.reserve(faceCount);
  std::vector<int> polygon;
  for (long f = 0; f < faceCount; ++f)
  {
    if (!lines.next(line, true))
    {
      if (firstFaceLikePoint >= 0)
        return missingPoints();
      return Status::error(fileLine(path, lines.number()) + "the file ends after " + std::to_string(f) + " of the " +
        std::to_string(faceCount) + " faces the header (line " + std::to_string(headerLine) + ") claims");
    }
    const char* p = line.c_str();
    char* end = nullptr;
    const long n = std::strtol(p, &end, 10);
    if (end == p || n < 3)
      return Status::error(fileLine(path, lines.number()) + "a face needs at least three vertices");
    polygon.clear();
    for (long k = 0; k < n; ++k)
    {
      p = end;
      const long v = std::strtol(p, &end, 10);
      if (end == p)
        return Status::error(fileLine(path, lines.number()) + "face has fewer indices than announced");
      if (v < 0 || v >= pointCount)
        return Status::error(fileLine(path, lines.number()) + "vertex index " + std::to_string(v) + " out of range");
      polygon.push_back(static_cast<int>(v));
    }
    fanTriangulate(polygon, out.mesh.triangles);
  }
  identityPointMap(out);
  return {};
}

Status readOBJ(const std::string& path, MeshFileData& out)
{
  out = MeshFileData{};
  std::string text;
  if (Status s = readTextFile(path, text); !s.ok())
    return s;
  LineReader lines(text);
  std::string line;
  std::vector<Eigen::Vector2d> texCoords;
  // Corner texture-coordinate index per triangle corner; -1 when absent.
  std::vector<std::array<int, 3>> cornerTex;
  bool everyCornerHasTex = true;
  std::vector<int> polygon, polygonTex;
  std::vector<Triangle> texTriangles;
  long normalCount = 0;
  double values[3];
  while (lines.next(line, true))
  {
    const std::size_t s = line.find_first_not_of(" \t");
    const std::size_t e = line.find_first_of(" \t\r", s);
    const std::string keyword = line.substr(s, e == std::string::npos ? std::string::npos : e - s);
    const std::string rest = e == std::string::npos ? std::string() : line.substr(e);
    if (keyword == "v")
    {
      if (parseNumbers(rest, values, 3) != 3)
        return Status::error(fileLine(path, lines.number()) + "a 'v' record needs three coordinates");
      out.mesh.points.emplace_back(values[0], values[1], values[2]);
    }
    else if (keyword == "vt")
    {
      if (parseNumbers(rest, values, 2) < 1)
        return Status::error(fileLine(path, lines.number()) + "a 'vt' record needs texture coordinates");
      texCoords.emplace_back(values[0], values[1]);
    }
    else if (keyword == "vn")
      ++normalCount;
    else if (keyword == "l" || keyword == "p")
    {
      // Lines and points are not kept, but one referring to a vertex that
      // is not defined is a damaged file (VTK's OBJ reader reads out of
      // bounds).
      const char* p = rest.c_str();
      ObjReference reference;
      std::string problem;
      while (readObjReference(p, static_cast<long>(out.mesh.points.size()), static_cast<long>(texCoords.size()),
        normalCount, false, reference, problem))
        if (!problem.empty())
          return Status::error(fileLine(path, lines.number()) + "'" + keyword + "' record refers to " + problem);
    }
    else if (keyword == "f")
    {
      polygon.clear();
      polygonTex.clear();
      const char* p = rest.c_str();
      ObjReference reference;
      std::string problem;
      while (readObjReference(p, static_cast<long>(out.mesh.points.size()), static_cast<long>(texCoords.size()),
        normalCount, true, reference, problem))
      {
        if (!problem.empty())
          return Status::error(fileLine(path, lines.number()) + "face refers to " + problem);
        polygon.push_back(static_cast<int>(reference.vertex));
        polygonTex.push_back(static_cast<int>(reference.texture));
      }
      if (polygon.size() < 3)
        return Status::error(fileLine(path, lines.number()) + "a face needs at least three vertices");
      fanTriangulate(polygon, out.mesh.triangles);
      fanTriangulate(polygonTex, texTriangles);
      everyCornerHasTex = everyCornerHasTex && *std::min_element(polygonTex.begin(), polygonTex.end()) >= 0;
    }
  }
  if (out.mesh.points.empty() && out.mesh.triangles.empty())
    return Status::error(path + ": no 'v' or 'f' records: not an OBJ surface");
  if (everyCornerHasTex && !texTriangles.empty())
  {
    out.cornerTexCoords.resize(texTriangles.size());
    for (std::size_t t = 0; t < texTriangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
        out.cornerTexCoords[t][k] = texCoords[texTriangles[t][k]];
    }
  }
  identityPointMap(out);
  return {};
}

int weldIdenticalPoints(MeshFileData& data)
{
  if (data.fileToMeshPoint.empty())
    identityPointMap(data);
  std::vector<Vec3>& points = data.mesh.points;
  const int n = static_cast<int>(points.size());
  // NaN breaks the ordering the sort needs; such a mesh is rejected by
  // checkSurface() anyway, so leave it as it is.
  if (!std::all_of(points.begin(), points.end(), [](const Vec3& p) { return p.allFinite(); }))
    return 0;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto less = [&](int a, int b)
  {
    const Vec3& p = points[a];
    const Vec3& q = points[b];
    if (p.x() != q.x())
      return p.x() < q.x();
    if (p.y() != q.y())
      return p.y() < q.y();
    if (p.z() != q.z())
      return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  // Representative of each point: the lowest index with the same position.
  std::vector<int> representative(n);
  for (int i = 0; i < n;)
  {
    int j = i;
    while (j < n && points[order[j]] == points[order[i]])
      representative[order[j++]] = order[i];
    i = j;
  }
  std::vector<int> newIndex(n, -1);
  int kept = 0;
  for (int v = 0; v < n; ++v)
  {
    if (representative[v] == v)
    {
      points[kept] = points[v];
      newIndex[v] = kept++;
    }
  }
  const int removed = n - kept;
  if (removed == 0)
    return 0;
  points.resize(kept);
  for (Triangle& tri : data.mesh.triangles)
  {
    for (int& v : tri)
      v = newIndex[representative[v]];
  }
  for (int& v : data.fileToMeshPoint)
    v = newIndex[representative[v]];
  return removed;
}

} // namespace cmp
