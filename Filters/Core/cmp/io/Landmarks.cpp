#include <cmp/io/Landmarks.h>

#include <cmp/io/TextParsing.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace cmp
{
namespace
{

/// A `.vts` position further than this fraction of the bounding-box diagonal
/// from its vertex means the file belongs to another mesh.
constexpr double kVtsPositionTolerance = 1e-3;
/// A CSV position further than this from the surface's nearest vertex is
/// probably in another coordinate frame.
constexpr double kCsvSnapTolerance = 0.05;

std::string formatPoint(const Vec3& p)
{
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

/// Parses a leading integer id, accepting an optional `lk` keyword before it.
bool parseId(const std::string& line, long& id, const char** rest)
{
  const char* p = line.c_str();
  while (*p == ' ' || *p == '\t')
    ++p;
  if (p[0] == 'l' && p[1] == 'k')
    p += 2;
  char* end = nullptr;
  id = std::strtol(p, &end, 10);
  if (end == p || (*end != '\0' && *end != ' ' && *end != '\t' && *end != '\r' && *end != ','))
    return false;
  *rest = end;
  return true;
}

Status mapFileId(long id, const std::vector<int>& fileToMeshPoint, int vertexCount, const std::string& at, int& vertex)
{
  if (id == kMissingLandmark)
  {
    vertex = kMissingLandmark;
    return {};
  }
  const long fileCount = fileToMeshPoint.empty() ? vertexCount : static_cast<long>(fileToMeshPoint.size());
  if (id < 0 || id >= fileCount)
    return Status::error(at + "landmark vertex id " + std::to_string(id) + " is out of range (the mesh has " +
      std::to_string(fileCount) + " points)");
  vertex = fileToMeshPoint.empty() ? static_cast<int>(id) : fileToMeshPoint[id];
  return {};
}

Status parseIdList(const std::string& path, const std::string& text, const TriangleMesh& mesh,
  const std::vector<int>& fileToMeshPoint, bool withPositions, LandmarkList& landmarks)
{
  // Only .vts positions need it; the diagonal is a pass over every point.
  const double tolerance = withPositions ? kVtsPositionTolerance * boundingBoxDiagonal(mesh) : 0.0;
  LineReader lines(text);
  std::string line;
  while (lines.next(line))
  {
    const std::string at = fileLine(path, lines.number());
    long id = 0;
    const char* rest = nullptr;
    if (!parseId(line, id, &rest))
      return Status::error(at + "expected a vertex id, found '" + line + "'");
    // A field more than the format has is an error, not ignored: the file
    // is then likely of another format, or damaged.
    if (!withPositions && !trailingText(rest, ',').empty())
      return Status::error(at + "expected 'lk ID' or 'ID', found '" + trailingText(line.c_str()) + "' (a field more than the format has)");
    int vertex = -1;
    if (Status s = mapFileId(id, fileToMeshPoint, mesh.vertexCount(), at, vertex); !s.ok())
      return s;
    // A feature not placed on this model: `-1`, the rest of a .vts line
    // ignored (its position means nothing).
    if (vertex == kMissingLandmark)
    {
      landmarks.push_back(kMissingLandmark);
      continue;
    }
    if (withPositions)
    {
      double xyz[3];
      std::string extra;
      if (parseNumbers(rest, xyz, 3, ' ', &extra) != 3)
        return Status::error(at + "expected 'vertex_id x y z'");
      if (!extra.empty())
        return Status::error(at + "expected 'vertex_id x y z', found '" + extra + "' after them");
      const Vec3 filePosition(xyz[0], xyz[1], xyz[2]);
      if ((filePosition - mesh.points[vertex]).norm() > tolerance)
        return Status::error(at + "landmark " + std::to_string(landmarks.size()) + ": vertex " + std::to_string(id) +
          " is at " + formatPoint(mesh.points[vertex]) + " but the file says " + formatPoint(filePosition) +
          "; is this the landmark file of another mesh?");
    }
    landmarks.push_back(vertex);
  }
  return {};
}

int nearestVertex(const TriangleMesh& mesh, const Vec3& p, double& distance)
{
  int best = -1;
  double bestSquared = std::numeric_limits<double>::infinity();
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double d = (mesh.points[v] - p).squaredNorm();
    if (d < bestSquared)
    {
      bestSquared = d;
      best = v;
    }
  }
  distance = std::sqrt(bestSquared);
  return best;
}

Status parseCsvPositions(const std::string& path, const std::string& text, const TriangleMesh& mesh,
  LandmarkList& landmarks)
{
  const double tolerance = kCsvSnapTolerance * boundingBoxDiagonal(mesh);
  LineReader lines(text);
  std::string line;
  bool first = true;
  // Empty rows stand for features not placed on this model; those after the
  // last landmark are only the end of the file.
  int emptyRows = 0;
  std::size_t start = 0; // where the line read next starts in `text`
  while (lines.next(line, false))
  {
    const std::size_t end = std::min(lines.offset(), text.size());
    const bool comment = std::find(text.begin() + start, text.begin() + end, '#') != text.begin() + end;
    start = lines.offset();
    if (line.find_first_not_of(" \t\r,") == std::string::npos)
    {
      if (!first && !comment)
        ++emptyRows;
      continue;
    }
    double xyz[3];
    std::string extra;
    const int count = parseNumbers(line, xyz, 3, ',', &extra);
    if (count != 3)
    {
      if (first && count == 0)
      {
        first = false; // header row
        continue;
      }
      return Status::error(fileLine(path, lines.number()) + "expected 'x,y,z'");
    }
    if (!extra.empty())
      return Status::error(fileLine(path, lines.number()) + "expected 'x,y,z', found '" + extra + "' after them");
    first = false;
    landmarks.insert(landmarks.end(), emptyRows, kMissingLandmark);
    emptyRows = 0;
    const int nans = int(std::isnan(xyz[0])) + int(std::isnan(xyz[1])) + int(std::isnan(xyz[2]));
    if (nans == 3)
    {
      landmarks.push_back(kMissingLandmark);
      continue;
    }
    if (nans > 0 || !std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
      return Status::error(fileLine(path, lines.number()) + "landmark " + std::to_string(landmarks.size()) +
        ": expected three finite coordinates, or nan,nan,nan for a feature not placed on this model");
    double distance = 0.0;
    const Vec3 p(xyz[0], xyz[1], xyz[2]);
    const int vertex = nearestVertex(mesh, p, distance);
    if (vertex < 0 || distance > tolerance)
      return Status::error(fileLine(path, lines.number()) + "landmark " + std::to_string(landmarks.size()) + " at " +
        formatPoint(p) + " is " + std::to_string(distance) +
        " away from the nearest vertex (more than 5% of the bounding-box diagonal); wrong coordinate frame?");
    landmarks.push_back(vertex);
  }
  return {};
}

} // namespace

Status readLandmarkFile(const std::string& path, const TriangleMesh& mesh, const std::vector<int>& fileToMeshPoint,
  LandmarkList& landmarks)
{
  landmarks.clear();
  std::string text;
  if (Status s = readTextFile(path, text); !s.ok())
    return s;
  const std::string ext = fileExtension(path);
  Status status = ext == "csv" ? parseCsvPositions(path, text, mesh, landmarks)
                               : parseIdList(path, text, mesh, fileToMeshPoint, ext == "vts", landmarks);
  if (!status.ok())
    return status;
  if (landmarks.empty())
    return Status::error(path + ": no landmarks in the file");
  if (missingLandmarkCount(landmarks) == static_cast<int>(landmarks.size()))
    return Status::error(path + ": every landmark is missing (-1)");
  status = validateLandmarks(landmarks, mesh.vertexCount(), -1, true);
  return status.ok() ? status : Status::error(path + ": " + status.message());
}

Status formatLandmarkFile(const std::string& path, const LandmarkList& landmarks, const TriangleMesh& mesh,
  const std::vector<int>& fileToMeshPoint, std::string& text)
{
  text.clear();
  if (landmarks.empty())
    return Status::error("no landmarks to write");
  if (Status s = validateLandmarks(landmarks, mesh.vertexCount(), -1, true); !s.ok())
    return s;
  // The reader maps file ids to mesh vertices; write the first file id of
  // each landmark vertex (identity when no map is given).
  std::vector<int> fileIdOf(mesh.vertexCount(), -1);
  if (fileToMeshPoint.empty())
    for (int v = 0; v < mesh.vertexCount(); ++v)
      fileIdOf[v] = v;
  for (int i = static_cast<int>(fileToMeshPoint.size()) - 1; i >= 0; --i)
    if (fileToMeshPoint[i] >= 0 && fileToMeshPoint[i] < mesh.vertexCount())
      fileIdOf[fileToMeshPoint[i]] = i;
  const std::string ext = fileExtension(path);
  std::ostringstream out;
  out.precision(17); // positions round-trip, so .vts and .csv reread exactly
  if (ext == "csv")
    out << "x,y,z\n";
  for (int f = 0; f < static_cast<int>(landmarks.size()); ++f)
  {
    const int v = landmarks[f];
    if (v == kMissingLandmark)
    {
      out << (ext == "csv" ? "nan,nan,nan\n" : ext == "vts" ? "-1\n" : "lk -1\n");
      continue;
    }
    if (fileIdOf[v] < 0)
      return Status::error("landmark " + std::to_string(f) + " is on vertex " + std::to_string(v) +
        ", which no point of the mesh file maps to");
    const Vec3& p = mesh.points[v];
    if (ext == "csv")
      out << p.x() << "," << p.y() << "," << p.z() << "\n";
    else if (ext == "vts")
      out << fileIdOf[v] << " " << p.x() << " " << p.y() << " " << p.z() << "\n";
    else
      out << "lk " << fileIdOf[v] << "\n";
  }
  text = out.str();
  return {};
}

Status writeLandmarkFile(const std::string& path, const LandmarkList& landmarks, const TriangleMesh& mesh,
  const std::vector<int>& fileToMeshPoint)
{
  std::string text;
  if (Status s = formatLandmarkFile(path, landmarks, mesh, fileToMeshPoint, text); !s.ok())
    return Status::error(path + ": " + s.message());
  std::ofstream file(path);
  if (!file || !(file << text) || !file.flush())
    return Status::error(path + ": cannot write the landmark file");
  return {};
}

int missingLandmarkCount(const LandmarkList& landmarks)
{
  return static_cast<int>(std::count(landmarks.begin(), landmarks.end(), kMissingLandmark));
}

Status validateLandmarks(const LandmarkList& landmarks, int vertexCount, int expectedCount, bool allowMissing)
{
  if (expectedCount >= 0 && static_cast<int>(landmarks.size()) != expectedCount)
    return Status::error(std::to_string(landmarks.size()) + " landmarks but " + std::to_string(expectedCount) +
      " are expected (one per base-domain vertex)");
  std::vector<int> featureAt(vertexCount, -1);
  for (int f = 0; f < static_cast<int>(landmarks.size()); ++f)
  {
    const int v = landmarks[f];
    if (v == kMissingLandmark)
    {
      if (allowMissing)
        continue;
      return Status::error("landmark " + std::to_string(f) +
        " is missing (-1: not placed on this model); Missing Landmark Placer, or consistent-remesh, places it "
        "from the models that have it");
    }
    if (v < 0 || v >= vertexCount)
      return Status::error("landmark " + std::to_string(f) + " is vertex " + std::to_string(v) +
        ", which is out of range (the mesh has " + std::to_string(vertexCount) + " vertices)");
    if (featureAt[v] >= 0)
      return Status::error("duplicate landmark: features " + std::to_string(featureAt[v]) + " and " +
        std::to_string(f) + " are both on vertex " + std::to_string(v));
    featureAt[v] = f;
  }
  return {};
}

std::vector<int> featureIdsOf(const LandmarkList& landmarks, int vertexCount)
{
  std::vector<int> ids(vertexCount, -1);
  for (int f = 0; f < static_cast<int>(landmarks.size()); ++f)
    if (landmarks[f] != kMissingLandmark)
      ids[landmarks[f]] = f;
  return ids;
}

Status landmarksFromFeatureIds(
  const std::vector<int>& featureIds, LandmarkList& landmarks, int featureCount, bool allowMissing)
{
  landmarks.clear();
  const int n = static_cast<int>(featureIds.size());
  int maxId = -1;
  for (int v = 0; v < n; ++v)
  {
    if (featureIds[v] < -1)
      return Status::error("FeatureId " + std::to_string(featureIds[v]) + " at vertex " + std::to_string(v) +
        " is invalid (use -1 for vertices without a landmark)");
    maxId = std::max(maxId, featureIds[v]);
  }
  if (maxId < 0)
    return Status::error("no landmarks: every FeatureId is -1");
  if (maxId >= n)
    return Status::error("FeatureId " + std::to_string(maxId) + " is larger than the number of vertices");
  if (featureCount >= 0 && maxId >= featureCount)
    return Status::error("FeatureId " + std::to_string(maxId) + " is not below the feature count, " +
      std::to_string(featureCount));
  const int count = featureCount >= 0 ? featureCount : maxId + 1;
  landmarks.assign(count, kMissingLandmark);
  for (int v = 0; v < n; ++v)
  {
    const int f = featureIds[v];
    if (f < 0)
      continue;
    if (landmarks[f] >= 0)
      return Status::error("duplicate landmark: feature " + std::to_string(f) + " is on vertices " +
        std::to_string(landmarks[f]) + " and " + std::to_string(v));
    landmarks[f] = v;
  }
  for (int f = 0; f < count && !allowMissing; ++f)
  {
    if (landmarks[f] < 0)
      return Status::error("missing landmark: feature " + std::to_string(f) + " is on no vertex (features 0.." +
        std::to_string(count - 1) + " must all be present; Missing Landmark Placer places a feature from the "
        "models that have it)");
  }
  return {};
}

} // namespace cmp
