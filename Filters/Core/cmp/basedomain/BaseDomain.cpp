#include <cmp/basedomain/BaseDomain.h>

#include <cmp/mesh/SurfaceCheck.h>

namespace cmp
{

Status checkBaseDomain(const BaseDomain& domain, int landmarkCount)
{
  const int vertices = domain.mesh.vertexCount();
  if (static_cast<int>(domain.featureIds.size()) != vertices)
    return Status::error("base domain: " + std::to_string(vertices) + " points but " +
      std::to_string(domain.featureIds.size()) + " FeatureId values");
  if (landmarkCount >= 0 && vertices != landmarkCount)
    return Status::error("base domain has " + std::to_string(vertices) + " vertices but the surface has " +
      std::to_string(landmarkCount) + " landmarks; they must match one to one");
  if (Status s = checkBaseDomainFeatureIds(domain); !s.ok())
    return s;
  SurfaceCheckOptions topologyOnly;
  topologyOnly.checkGeometry = false;
  const SurfaceCheckResult check = checkSurface(domain.mesh, topologyOnly);
  if (!check.ok())
    return Status::error("base domain: " + check.message);
  return {};
}

Status checkBaseDomainFeatureIds(const BaseDomain& domain)
{
  const int vertices = domain.mesh.vertexCount();
  if (static_cast<int>(domain.featureIds.size()) != vertices)
    return Status::error("base domain: " + std::to_string(vertices) + " points but " +
      std::to_string(domain.featureIds.size()) + " FeatureId values");
  std::vector<int> baseVertexOfFeature(vertices, -1);
  for (int v = 0; v < vertices; ++v)
  {
    const int f = domain.featureIds[v];
    if (f < 0 || f >= vertices)
      return Status::error("base domain: vertex " + std::to_string(v) + " has FeatureId " + std::to_string(f) +
        ", outside 0.." + std::to_string(vertices - 1));
    if (baseVertexOfFeature[f] >= 0)
      return Status::error("base domain: FeatureId " + std::to_string(f) + " is on vertices " +
        std::to_string(baseVertexOfFeature[f]) + " and " + std::to_string(v));
    baseVertexOfFeature[f] = v;
  }
  return {};
}

int edgeCount(const TriangleMesh& closedMesh)
{
  return 3 * closedMesh.triangleCount() / 2;
}

} // namespace cmp
