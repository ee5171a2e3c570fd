#include <cmp/layout/OpenSurface.h>
#include <cmp/mesh/BoundaryLoops.h>
#include <cmp/mesh/SurfaceCheck.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <utility>

namespace cmp
{

namespace
{

std::string joined(const std::vector<int>& values)
{
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i ? ", " : "") + std::to_string(values[i]);
  return text;
}

/// `loop` turned so that it starts at its smallest entry.
std::vector<int> startingAtSmallest(const std::vector<int>& loop)
{
  std::vector<int> turned(loop);
  std::rotate(turned.begin(), std::min_element(turned.begin(), turned.end()), turned.end());
  return turned;
}

} // namespace

bool BaseDomainHoles::onBoundary(int f) const
{
  for (const auto& loop : loops)
    if (std::find(loop.begin(), loop.end(), f) != loop.end())
      return true;
  return false;
}

std::vector<int> BaseDomainHoles::keptFeatures() const
{
  std::vector<int> kept;
  for (std::size_t j = 0; j < loops.size(); ++j)
  {
    kept.insert(kept.end(), loops[j].begin(), loops[j].end());
    kept.push_back(openVertexCount + static_cast<int>(j));
  }
  return kept;
}

Status closeBaseDomain(const BaseDomain& domain, BaseDomain& closed, BaseDomainHoles& holes)
{
  holes = BaseDomainHoles{};
  const int vertices = domain.mesh.vertexCount();
  if (Status s = checkBaseDomainFeatureIds(domain); !s.ok())
    return s;
  std::vector<int> vertexOfFeature(vertices, -1);
  for (int v = 0; v < vertices; ++v)
    vertexOfFeature[domain.featureIds[v]] = v;
  for (const Triangle& t : domain.mesh.triangles)
    for (int v : t)
      if (v < 0 || v >= vertices)
        return Status::error("base domain: a triangle names vertex " + std::to_string(v) + ", outside 0.." +
          std::to_string(vertices - 1));
  std::vector<std::vector<int>> loops;
  if (Status s = boundaryLoops(domain.mesh, loops); !s.ok())
    return Status::error("base domain: " + s.message());
  holes.openVertexCount = vertices;
  holes.openTriangleCount = domain.mesh.triangleCount();
  closed = domain;
  for (const auto& loop : loops)
  {
    std::vector<int> features;
    for (int v : loop)
      features.push_back(domain.featureIds[v]);
    if (loop.size() < 3)
      return Status::error("base domain: a boundary loop of L0 needs at least 3 landmarks; the loop through features " +
        joined(features) + " has " + std::to_string(loop.size()));
    holes.loops.push_back(startingAtSmallest(features));
  }
  std::sort(holes.loops.begin(), holes.loops.end(),
    [](const std::vector<int>& a, const std::vector<int>& b) { return a.front() < b.front(); });
  holes.holeTriangle.assign(domain.mesh.triangleCount(), 0);
  for (std::size_t j = 0; j < holes.loops.size(); ++j)
  {
    const auto& loop = holes.loops[j];
    const int centre = closed.mesh.vertexCount();
    Vec3 centroid = Vec3::Zero();
    for (int f : loop)
      centroid += domain.mesh.points[vertexOfFeature[f]];
    closed.mesh.points.push_back(centroid / static_cast<double>(loop.size()));
    closed.featureIds.push_back(centre);
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      const int a = vertexOfFeature[loop[i]], b = vertexOfFeature[loop[(i + 1) % loop.size()]];
      closed.mesh.triangles.push_back({ b, a, centre });
      holes.holeTriangle.push_back(1);
    }
  }
  if (Status s = checkBaseDomain(closed); !s.ok())
    return holes.empty() ? s
                         : Status::error(s.message() + " (L0 closed over its " + std::to_string(holes.loops.size()) +
                             " boundary loops: L0 must be a sphere with holes)");
  return {};
}

Status closeSurface(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomainHoles& holes,
  TriangleMesh& closed, LandmarkList& closedLandmarks, SurfaceHoles& surfaceHoles)
{
  surfaceHoles = SurfaceHoles{};
  surfaceHoles.openVertexCount = surface.vertexCount();
  surfaceHoles.openTriangleCount = surface.triangleCount();
  closed = surface;
  closedLandmarks = landmarks;
  std::vector<std::vector<int>> loops;
  if (Status s = boundaryLoops(surface, loops); !s.ok())
    return s;
  if (loops.empty() && holes.empty())
    return {};
  if (holes.empty())
    return Status::error("the surface has " + std::to_string(loops.size()) +
      " boundary loop(s) (one through vertex " + std::to_string(loops.front().front()) +
      ") but the base domain is closed: an open surface needs an L0 with as many boundary loops, through the "
      "boundary landmarks");
  if (loops.empty())
    return Status::error("the surface is closed but the base domain has " + std::to_string(holes.loops.size()) +
      " boundary loop(s) (through features " + joined(holes.loops.front()) + ")");

  std::map<int, int> featureAt;
  for (std::size_t f = 0; f < landmarks.size(); ++f)
    if (landmarks[f] >= 0)
      featureAt[landmarks[f]] = static_cast<int>(f);
  for (const auto& loop : holes.loops)
    for (int f : loop)
      if (f >= static_cast<int>(landmarks.size()) || landmarks[f] < 0)
        return Status::error("feature " + std::to_string(f) +
          " lies on the base domain's boundary but is missing on this surface: boundary landmarks cannot be placed");

  std::vector<char> matched(holes.loops.size(), 0);
  std::vector<std::vector<int>> matchedLoop(holes.loops.size());
  for (const auto& loop : loops)
  {
    std::vector<int> onLoop; // features in the loop's order
    std::vector<int> position;
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (const auto found = featureAt.find(loop[i]); found != featureAt.end())
      {
        onLoop.push_back(found->second);
        position.push_back(static_cast<int>(i));
      }
    for (int f : onLoop)
      if (!holes.onBoundary(f))
        return Status::error("feature " + std::to_string(f) + " (vertex " + std::to_string(landmarks[f]) +
          ") lies on the surface's boundary but inside the base domain");
    if (onLoop.size() < 3)
      return Status::error(tooFewBoundaryLandmarks(loop, static_cast<int>(onLoop.size())));
    const std::vector<int> turned = startingAtSmallest(onLoop);
    int hole = -1;
    for (std::size_t j = 0; j < holes.loops.size() && hole < 0; ++j)
      if (std::find(holes.loops[j].begin(), holes.loops[j].end(), turned.front()) != holes.loops[j].end())
        hole = static_cast<int>(j);
    if (hole < 0)
      return Status::error("feature " + std::to_string(turned.front()) + " lies on the surface's boundary but inside the base domain");
    if (turned != holes.loops[hole])
    {
      std::vector<int> sortedA(turned), sortedB(holes.loops[hole]);
      std::sort(sortedA.begin(), sortedA.end());
      std::sort(sortedB.begin(), sortedB.end());
      if (sortedA == sortedB)
        return Status::error("the boundary landmarks run " + joined(turned) +
          " along the surface's boundary but " + joined(holes.loops[hole]) +
          " along the base domain's (the same cyclic order is needed, both with the surface on the left)");
      for (int f : holes.loops[hole])
        if (std::find(turned.begin(), turned.end(), f) == turned.end())
          return Status::error("feature " + std::to_string(f) + " lies on the base domain's boundary (loop " +
            joined(holes.loops[hole]) + ") but not on the surface's boundary (vertex " +
            std::to_string(landmarks[f]) + ")");
    }
    if (matched[hole])
      return Status::error("two boundary loops of the surface carry the landmarks of one loop of the base domain");
    matched[hole] = 1;
    // The loop, starting at the landmark of the hole's first feature.
    const int first = position[std::find(onLoop.begin(), onLoop.end(), turned.front()) - onLoop.begin()];
    std::vector<int> ordered(loop.begin() + first, loop.end());
    ordered.insert(ordered.end(), loop.begin(), loop.begin() + first);
    matchedLoop[hole] = ordered;
  }
  for (std::size_t j = 0; j < holes.loops.size(); ++j)
    if (!matched[j])
      return Status::error("feature " + std::to_string(holes.loops[j].front()) +
        " lies on the base domain's boundary but inside the surface (vertex " +
        std::to_string(landmarks[holes.loops[j].front()]) + ")");

  closedLandmarks.resize(holes.openVertexCount, kMissingLandmark);
  for (std::size_t j = 0; j < holes.loops.size(); ++j)
  {
    const std::vector<int>& loop = matchedLoop[j];
    const int count = static_cast<int>(loop.size());
    int centre = -1;
    if (Status s = capLoop(closed, loop, centre); !s.ok())
      return s;
    const int capFeature = holes.openVertexCount + static_cast<int>(j);
    closedLandmarks.push_back(centre);
    surfaceHoles.loops.push_back(loop);
    surfaceHoles.boundaryLandmarks.emplace_back();
    for (int f : holes.loops[j])
      surfaceHoles.boundaryLandmarks.back().push_back(landmarks[f]);
    // The boundary stretches and the spokes.
    const std::vector<int>& features = holes.loops[j];
    const int k = static_cast<int>(features.size());
    for (int i = 0; i < k; ++i)
    {
      const int from = features[i], to = features[(i + 1) % k];
      PresetCurve stretch{ from, to, {} };
      int at = static_cast<int>(std::find(loop.begin(), loop.end(), landmarks[from]) - loop.begin());
      do
      {
        stretch.vertices.push_back(loop[at]);
        at = (at + 1) % count;
      } while (loop[at] != landmarks[to]);
      stretch.vertices.push_back(landmarks[to]);
      surfaceHoles.curves.push_back(std::move(stretch));
      surfaceHoles.curves.push_back(PresetCurve{ capFeature, from, { centre, landmarks[from] } });
    }
  }
  return {};
}

Status traceClosedSurface(const TriangleMesh& closed, const LandmarkList& closedLandmarks,
  const SurfaceHoles& surfaceHoles, const BaseDomain& closedDomain, TracedNet& net, NetTracerOptions options,
  NetTracerReport* report)
{
  options.presetCurves = surfaceHoles.curves; // the caps' curves, traced already
  return traceFeatureNet(closed, closedLandmarks, closedDomain, net, options, report);
}

Status traceSurfaceWithBoundaries(const TriangleMesh& surface, const LandmarkList& landmarks,
  const BaseDomainHoles& holes, const BaseDomain& closedDomain, TracedNet& net, const NetTracerOptions& options,
  NetTracerReport* report)
{
  TriangleMesh closed;
  LandmarkList closedLandmarks;
  SurfaceHoles surfaceHoles;
  if (Status s = closeSurface(surface, landmarks, holes, closed, closedLandmarks, surfaceHoles); !s.ok())
    return s;
  return traceClosedSurface(closed, closedLandmarks, surfaceHoles, closedDomain, net, options, report);
}

std::vector<int> capPatchIds(const SurfaceHoles& surfaceHoles, const BaseDomainHoles& holes)
{
  std::vector<int> patches;
  int first = holes.openTriangleCount;
  for (std::size_t j = 0; j < surfaceHoles.loops.size() && j < holes.loops.size(); ++j)
  {
    const std::vector<int>& loop = surfaceHoles.loops[j];
    const std::vector<int>& features = holes.loops[j];
    // The loop starts at the first feature's landmark; each boundary
    // landmark met starts the next stretch.
    int stretch = -1;
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      if (stretch + 1 < static_cast<int>(features.size()) && loop[i] == surfaceHoles.boundaryLandmarks[j][stretch + 1])
        ++stretch;
      patches.push_back(first + std::max(stretch, 0));
    }
    first += static_cast<int>(features.size());
  }
  return patches;
}

OpenPart openPart(const TriangleMesh& closed, const std::vector<int>& patchOfTriangle,
  const std::vector<char>& holeTriangle)
{
  OpenPart part;
  part.newIndex.assign(closed.vertexCount(), -1);
  const auto hole = [&](int t) {
    const int p = t < static_cast<int>(patchOfTriangle.size()) ? patchOfTriangle[t] : -1;
    return p >= 0 && p < static_cast<int>(holeTriangle.size()) && holeTriangle[p];
  };
  for (int t = 0; t < closed.triangleCount(); ++t)
    if (!hole(t))
      for (int v : closed.triangles[t])
        part.newIndex[v] = 0;
  for (int v = 0; v < closed.vertexCount(); ++v)
    if (part.newIndex[v] == 0)
    {
      part.newIndex[v] = part.mesh.vertexCount();
      part.vertexOf.push_back(v);
      part.mesh.points.push_back(closed.points[v]);
    }
  for (int t = 0; t < closed.triangleCount(); ++t)
    if (!hole(t))
    {
      const Triangle& tri = closed.triangles[t];
      part.mesh.triangles.push_back({ part.newIndex[tri[0]], part.newIndex[tri[1]], part.newIndex[tri[2]] });
      part.triangleOf.push_back(t);
    }
  return part;
}

TriangleMesh openSurface(const TriangleMesh& closed, const SurfaceHoles& holes)
{
  if (holes.empty())
    return closed;
  TriangleMesh open;
  open.points.assign(closed.points.begin(), closed.points.begin() + holes.openVertexCount);
  open.triangles.assign(closed.triangles.begin(), closed.triangles.begin() + holes.openTriangleCount);
  return open;
}

} // namespace cmp
