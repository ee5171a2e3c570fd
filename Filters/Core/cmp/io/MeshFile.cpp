#include <cmp/io/MeshFile.h>

#include <cmp/io/TextParsing.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <numeric>

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

void identityPointMap(MeshFileData& out)
{
  out.fileToMeshPoint.resize(out.mesh.points.size());
  std::iota(out.fileToMeshPoint.begin(), out.fileToMeshPoint.end(), 0);
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
  const long pointCount = static_cast<long>(header[0]);
  const long faceCount = static_cast<long>(header[1]);
  if (pointCount < 0 || faceCount < 0 || header[0] != pointCount || header[1] != faceCount)
    return Status::error(fileLine(path, lines.number()) + "invalid vertex or face count");
  out.mesh.points.reserve(pointCount);
  double xyz[3];
  for (long i = 0; i < pointCount; ++i)
  {
    if (!lines.next(line, true))
      return Status::error(path + ": file ends after " + std::to_string(i) + " of " + std::to_string(pointCount) +
        " points");
    if (parseNumbers(line, xyz, 3) != 3)
      return Status::error(fileLine(path, lines.number()) + "expected three coordinates");
    out.mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  out.mesh.triangles.reserve(faceCount);
  std::vector<int> polygon;
  for (long f = 0; f < faceCount; ++f)
  {
    if (!lines.next(line, true))
      return Status::error(path + ": file ends after " + std::to_string(f) + " of " + std::to_string(faceCount) +
        " faces");
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
    else if (keyword == "f")
    {
      polygon.clear();
      polygonTex.clear();
      const char* p = rest.c_str();
      while (true)
      {
        char* end = nullptr;
        long v = std::strtol(p, &end, 10);
        if (end == p)
          break;
        long vt = 0;
        p = end;
        if (*p == '/')
        {
          ++p;
          vt = std::strtol(p, &end, 10); // 0 when empty ("v//vn")
          p = end;
          if (*p == '/')
          {
            ++p;
            std::strtol(p, &end, 10);
            p = end;
          }
        }
        const long pointCount = static_cast<long>(out.mesh.points.size());
        v = v < 0 ? pointCount + v : v - 1;
        if (v < 0 || v >= pointCount)
          return Status::error(fileLine(path, lines.number()) + "face refers to a vertex that is not defined");
        const long texCount = static_cast<long>(texCoords.size());
        vt = vt < 0 ? texCount + vt : vt - 1;
        if (vt >= texCount)
          return Status::error(fileLine(path, lines.number()) + "face refers to a texture coordinate not defined");
        polygon.push_back(static_cast<int>(v));
        polygonTex.push_back(static_cast<int>(vt));
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
