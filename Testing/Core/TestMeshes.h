#pragma once
/// \file TestMeshes.h
/// \brief Small meshes the core tests build in code, and access to the
///        shared real data.

#include "Landmarks.h"
#include "MeshFile.h"
#include "TestData.h"
#include "TriangleMesh.h"

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

/// \brief A torus (genus 1) made of an n-by-m grid.
TriangleMesh torus(int n, int m);

/// \brief Appends `b` to `a` as a separate component.
TriangleMesh disjointUnion(const TriangleMesh& a, const TriangleMesh& b);

/// \brief A sphere of `levels` subdivisions with bumps of 20% of its radius.
TriangleMesh bumpySphere(int levels);

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

/// \brief Paths without extension of every SHREC'07 four-legged model that
///        has both `.off` and `.vts` (".../381", ...), sorted.
std::vector<std::string> landmarkedFourLeggedModels();

} // namespace cmp::test
