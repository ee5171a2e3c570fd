#pragma once
/// \file TestMeshes.h
/// \brief Small meshes the core tests build in code, and access to the
///        shared real data.

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

/// \brief Paths without extension of every SHREC'07 four-legged model that
///        has both `.off` and `.vts` (".../381", ...), sorted.
std::vector<std::string> landmarkedFourLeggedModels();

} // namespace cmp::test
