#include <cmp/analysis/AttributeTransfer.h>

#include <cmp/map/PatchParameterization.h>

#include <string>

namespace cmp
{

Status locateVertices(
  const ParameterizedSurface& source, const BaseDomainMesh& target, std::vector<SurfacePoint>& samples)
{
  samples.assign(target.locations.size(), SurfacePoint{});
  for (std::size_t v = 0; v < target.locations.size(); ++v)
    if (Status s = source.locate(target.locations[v], samples[v]); !s.ok())
      return Status::error("target point " + std::to_string(v) + ": " + s.message());
  return {};
}

Status locateCorners(const ParameterizedSurface& source, const BaseDomain& domain, const BaseDomainMesh& target,
  std::vector<SurfacePoint>& corners, double inset)
{
  if (target.patchOfTriangle.size() != target.triangles.size())
    return Status::error("the target has " + std::to_string(target.patchOfTriangle.size()) + " patch ids for " +
      std::to_string(target.triangles.size()) + " triangles");
  corners.assign(3 * target.triangles.size(), SurfacePoint{});
  for (std::size_t t = 0; t < target.triangles.size(); ++t)
  {
    const int patch = target.patchOfTriangle[t];
    std::array<std::array<double, 3>, 3> inPatch;
    for (int k = 0; k < 3; ++k)
    {
      const int v = target.triangles[t][k];
      if (v < 0 || v >= static_cast<int>(target.locations.size()))
        return Status::error("target triangle " + std::to_string(t) + " uses point " + std::to_string(v) +
          ", which has no base location");
      const SurfacePoint& at = target.locations[v];
      if (!coordinatesInTriangle(domain, at.triangle, at.weight, patch, inPatch[k]))
        return Status::error("target triangle " + std::to_string(t) + " lies in patch " + std::to_string(patch) +
          " but its point " + std::to_string(v) + " lies inside base triangle " + std::to_string(at.triangle));
    }
    for (int k = 0; k < 3; ++k)
    {
      SurfacePoint nudged = SurfacePoint::inTriangle(domain.mesh, patch, {});
      for (int c = 0; c < 3; ++c)
      {
        const double centroid = (inPatch[0][c] + inPatch[1][c] + inPatch[2][c]) / 3.0;
        nudged.weight[c] = (1.0 - inset) * inPatch[k][c] + inset * centroid;
      }
      if (Status s = source.locate(nudged, corners[3 * t + k]); !s.ok())
        return Status::error("target triangle " + std::to_string(t) + ": " + s.message());
    }
  }
  return {};
}

} // namespace cmp
