#pragma once
/// \file BoundaryLoops.h
/// \brief The boundary loops of a surface, and caps that close them: what
///        surfaces with boundaries (beyond the paper) are built on.

#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <string>
#include <vector>

namespace cmp
{

/// \brief The boundary loops of `mesh`, each as its vertices in order, the
///        surface on the left (each pair of consecutive vertices is an edge
///        of one triangle, in that triangle's direction). Loops are ordered
///        by their smallest vertex and each starts there.
/// Fails (Status), naming the vertex, when two boundary edges leave one
/// vertex in the same direction (a pinched boundary, or triangles that
/// disagree in orientation).
Status boundaryLoops(const TriangleMesh& mesh, std::vector<std::vector<int>>& loops);

/// \brief Per vertex of `mesh`, 1 if it lies on one of its boundary loops
///        (`boundaryLoops()`), else 0. Fails as `boundaryLoops()` does.
Status boundaryVertices(const TriangleMesh& mesh, std::vector<char>& onBoundary);

/// \brief Closes `loop` (a boundary loop of `mesh`, `boundaryLoops()`'s) by
///        a fan of triangles from a new vertex, its index returned: the
///        vertex lies off the loop's centroid, on the side away from the
///        surface (against the loop's vector area, which is the surface's),
///        by half the loop's mean radius, so that the fan's triangles have
///        area. Fails (Status), `mesh` unchanged, when the loop encloses no
///        vector area (a degenerate loop).
Status capLoop(TriangleMesh& mesh, const std::vector<int>& loop, int& centre);

/// \brief A surface with every boundary loop closed by `capLoop()`.
struct CappedSurface
{
  TriangleMesh mesh;                   ///< The surface, then the caps' centres and triangles.
  std::vector<std::vector<int>> loops; ///< The surface's boundary loops (`boundaryLoops()`).
  std::vector<int> centres;            ///< Per loop, its cap's centre.
};

/// \brief Checks a surface that may have boundary loops (beyond the paper):
///        a closed one by `checkSurface()` alone; an open one must have no
///        other defect than its boundary edges (a turned triangle is named
///        as such), and closed by a cap per loop it must pass
///        `checkSurface()` (a sphere with holes, sound geometry). With
///        `landmarks` (the vertex of each feature, -1 for a missing one),
///        each loop must carry at least 3 of them. `capped`, when given,
///        gets the capped surface.
/// Fails (Status) with the first problem, in the user's terms; a closed
/// surface's messages are `checkSurface()`'s.
Status checkSurfaceWithBoundaries(const TriangleMesh& surface, const std::vector<int>* landmarks = nullptr,
  CappedSurface* capped = nullptr);

/// \brief The message for a boundary loop (`loop`) that carries `count` < 3
///        landmarks, one wording for every stage.
std::string tooFewBoundaryLandmarks(const std::vector<int>& loop, int count);

} // namespace cmp
