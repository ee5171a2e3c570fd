#pragma once
/// \file TestMeshes.h
/// \brief Small meshes the core tests build in code, and access to the
///        shared real data.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/io/Landmarks.h>
#include <cmp/io/MeshFile.h>
#include <cmp/layout/NetTracer.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/Status.h>
#include "TestData.h"
#include <cmp/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace cmp::test
{

/// \brief Regular octahedron with unit vertices on the axes (6 points, 8 triangles).
TriangleMesh octahedron();

/// \brief Tetrahedron with outward orientation, shifted by `offset`.
TriangleMesh tetrahedron(const Vec3& offset = Vec3::Zero());

/// \brief Octahedron subdivided `levels` times, projected to the unit sphere.
TriangleMesh sphere(int levels);


/// \brief Appends `b` to `a` as a separate component.
TriangleMesh disjointUnion(const TriangleMesh& a, const TriangleMesh& b);

/// \brief A flat square [-1, 1]^2 in the xy plane, `n` x `n` cells, each
///        cut in two along the diagonal from (i, j) to (i + 1, j + 1).
TriangleMesh flatSquare(int n);

/// \brief A sphere of `levels` subdivisions with bumps of 20% of its radius.
TriangleMesh bumpySphere(int levels);

/// \brief The octahedron as a base domain, features not in vertex order.
BaseDomain octahedronDomain();

/// \brief The tetrahedron as a base domain: every base vertex of valence 3.
BaseDomain tetrahedronDomain();

/// \brief The octahedron with one face split at its centre: base vertices
///        of valence 3, 4 and 5.
BaseDomain mixedValenceDomain();

/// \brief Points as the rows of a matrix.
Eigen::MatrixXd toMatrix(const std::vector<Vec3>& points);

/// \brief A remesh drawn on the flat triangles of its base domain.
TriangleMesh drawnOnDomain(const BaseDomain& domain, const SemiRegularMesh& mesh);

/// \brief The vertex whose direction from the origin is closest to `direction`.
int nearestVertex(const TriangleMesh& mesh, const Vec3& direction);

/// \brief A real model from the shared data with its landmarks.
struct LandmarkedModel
{
  std::string name;       ///< "381", ..., "spot".
  MeshFileData data;      ///< The welded mesh and its file-to-mesh point map.
  LandmarkList landmarks; ///< Mesh vertex of each feature.
};

/// \brief Every landmarked SHREC'07 four-legged model (sorted), then Spot
///        with its SHREC landmarks. A file that does not read is a test
///        failure (and the model is left out).
std::vector<LandmarkedModel> landmarkedRealModels();

/// \brief The landmarked real model called `name`; a test failure if absent.
LandmarkedModel landmarkedRealModel(const std::string& name);

/// \brief An open model made from a closed one (issue 27 B): the triangles
///        within `radius` times the shortest edge-path distance from the
///        landmark of `feature` to a landmark of its L0 neighbours are cut
///        away, and a boundary landmark is placed where the cut meets the
///        way to each neighbour (the boundary vertex nearest to it along
///        edges). `domain` loses `feature`'s star: each of its triangles
///        (X, Y_i, Y_i+1) becomes (B_i, Y_i, Y_i+1) and (B_i, Y_i+1, B_i+1),
///        the B_i the new boundary landmarks. Features above `feature` move
///        down by one; the B_i come last, in `domain`'s order round X.
///        Depends on `domain` and `feature` alone for the open L0, so every
///        model of a collection cut the same way shares it.
struct OpenModel
{
  TriangleMesh surface;
  LandmarkList landmarks;
  BaseDomain domain;
};
Status cutAroundFeature(const TriangleMesh& surface, const LandmarkList& landmarks, const BaseDomain& domain,
  int feature, double radius, OpenModel& out);

/// \brief The base domain `L0` built from the landmarks of real model
///        `name` ("381" for most tests); a test failure if it cannot be.
BaseDomain realBaseDomain(const std::string& name);

/// \brief A model's feature net straightened on a base domain, with its
///        per-patch parameterization: what remeshing needs.
struct ParameterizedModel
{
  TracedNet net;                          ///< The straightened net.
  PatchParameterization parameterization; ///< Its per-patch map.
};

/// \brief Traces (with `tracing`), straightens and parameterizes `model`
///        on `domain`, the curves fixed as the paper leaves them.
Status parameterizeOnDomain(const LandmarkedModel& model, const BaseDomain& domain, ParameterizedModel& out,
  const NetTracerOptions& tracing = {});

/// \brief The octahedron as a base domain, its vertices the features in order.
BaseDomain orderedOctahedronDomain();

/// \brief The unit sphere subdivided `levels` times, landmarked at the
///        vertices of `domain` (unit directions) and parameterized on it.
Status parameterizedSphere(const BaseDomain& domain, int levels, ParameterizedModel& model);

/// \brief Real models parameterized on one base domain and indexed for
///        remeshing; `collection` is what a split rule or the sample
///        relaxation takes.
struct IndexedModels
{
  std::vector<LandmarkedModel> models;         ///< The models as read.
  std::vector<ParameterizedModel> parameterized; ///< Their straightened nets and maps.
  std::vector<ParameterizedSurface> surfaces;  ///< Indexed for point location.
  std::vector<const ParameterizedSurface*> collection; ///< Pointers to `surfaces`.
};

/// \brief Reads, parameterizes (with `lowerStretch`, the straightener's
///        option) and indexes the real models `names` on `domain`.
Status indexRealModels(
  const std::vector<std::string>& names, const BaseDomain& domain, bool lowerStretch, IndexedModels& out);

/// \brief Paths without extension of every SHREC'07 four-legged model that
///        has both `.off` and `.vts` (".../381", ...), sorted.
std::vector<std::string> landmarkedFourLeggedModels();

} // namespace cmp::test
