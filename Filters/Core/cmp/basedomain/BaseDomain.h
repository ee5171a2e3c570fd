#pragma once
/// \file BaseDomain.h
/// \brief The base domain `L0`: one vertex per landmark, triangles that say
///        which landmarks bound each patch.

#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief The common base domain of a collection.
///
/// Its positions are only a picture (the paper gives base vertices no
/// geometry); its connectivity is what every model's patch layout must match.
struct BaseDomain
{
  TriangleMesh mesh;           ///< F vertices and their triangles.
  std::vector<int> featureIds; ///< Landmark (feature) of each base vertex.
};

/// \brief Checks that `domain` is a closed, manifold, oriented, connected
///        genus-0 triangulation whose `featureIds` are 0..F-1, each once, and
///        (when `landmarkCount >= 0`) that F equals the surface's landmark count.
///        Fails (Status), naming the first check that does not hold. The
///        positions are not checked: only the connectivity is `L0` (paper
///        §2, "Basic Setup").
Status checkBaseDomain(const BaseDomain& domain, int landmarkCount = -1);

/// \brief Checks that `domain` has one `FeatureId` per vertex, a
///        permutation of 0..F-1 (the first checks of `checkBaseDomain()`,
///        for an open L0 too). Fails (Status) naming the first that does not hold.
Status checkBaseDomainFeatureIds(const BaseDomain& domain);

/// \brief Number of distinct edges of a closed triangulation (3T/2).
int edgeCount(const TriangleMesh& closedMesh);

} // namespace cmp
