#pragma once
/// \file FoldRepair.h
/// \brief Unfolds remesh triangles that point against their surface by
///        sliding a few vertices a short way along that surface.

#include <cmp/mesh/EditableMesh.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>
#include <cmp/remesh/SemiRegularRemesher.h>

#include <vector>

namespace cmp
{

/// \brief How far `repairFolds()` may go.
struct FoldRepairOptions
{
  /// \brief Sweeps over the vertices of folded triangles at most.
  int maximumSweeps = 20;
  /// \brief How far a vertex may go from where its parameterization put
  ///        it when it first moves with its region, in quarters of the
  ///        remesh's median edge (2: half of one); see `regionWidening`
  ///        and `singleWidening` for the farther moves. 0: nothing moves.
  double reach = 2.0;
  /// \brief Where moving regions within `reach` quarters of the median
  ///        edge leaves folds, the regions around the remaining ones try
  ///        again within 2, 3, ... up to this many times that (by default:
  ///        half a median edge, then one, one and a half, two). A fold
  ///        where the layout's curves leave a landmark bunched (a fan of
  ///        needles) needs moves of one or two edges; folds unfolded at a
  ///        smaller reach move no further unless they lie within five rings
  ///        of one that remains. The correspondence moves by at most `reach`
  ///        x `regionWidening` quarters of the median edge (two median
  ///        edges by default). 1 to 64; 1: regions never go beyond the
  ///        first reach.
  int regionWidening = 4;
  /// \brief Single vertices (after the regions, and in the centroid pass)
  ///        go up to this many times `reach` quarters of the median edge
  ///        (by default one median edge), in steps of their shortest, mean
  ///        and longest remesh edge. In a band of needles a vertex's
  ///        shortest edge is a needle's width, and the move that unfolds
  ///        the band runs along the needles: counted in the shortest edge
  ///        (until December 2026) the moves stayed within it and left such
  ///        folds. 1 to 64.
  double singleWidening = 2.0;
  /// \brief Then move single vertices of triangles flipped by the centroid
  ///        criterion (`centroidFlippedTriangles()`: the surface nearest to
  ///        the triangle's middle faces the other way, at the rim of an ear
  ///        or across a tail), never folding more by the corner criterion,
  ///        within the same reach.
  bool centroidFlips = true;
};

/// \brief What `repairFolds()` did.
struct FoldRepairReport
{
  int foldedBefore = 0;  ///< Triangles against the surface before.
  int foldedAfter = 0;   ///< Triangles against the surface after.
  int movedVertices = 0; ///< Vertices that left their parameterized place.
  int centroidFlipsBefore = 0; ///< Triangles flipped by the centroid criterion before its pass (after the folds').
  int centroidFlipsAfter = 0;  ///< The same after.
  double largestMove = 0.0; ///< Longest straight-line move of a vertex.
};

/// \brief Counts the remesh triangles whose normal points against the
///        surface under them: the sum of the unit normals of the surface
///        triangles holding their corners (landmark corners record none; a
///        triangle of landmarks only, or a flat one, is not counted).
/// \pre `samples` are `remesh` placed on `surface`, one per remesh vertex
///      (unchecked here; `repairFolds()` checks them).
int countFoldedTriangles(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples);

/// \brief 1 for each remesh triangle `countFoldedTriangles()` counts, 0
///        for the others, in triangle order. \pre As for
///        `countFoldedTriangles()`.
std::vector<char> foldedTriangles(
  const SemiRegularMesh& remesh, const EditableMesh& surface, const std::vector<SurfacePoint>& samples);

/// \brief The centroid criterion, a second opinion on folds that needs
///        no parameterization: 1 for each triangle of `placed` (a remesh
///        as placed in space) whose normal points against the normal of
///        the `surface` triangle holding the point of `surface` nearest to
///        its centroid, 0 for the others, in triangle order. A zero-area
///        triangle of either mesh is not counted.
///
/// Unlike `foldedTriangles()`, which asks the surface under a triangle's
/// corners, it also catches a triangle whose corners lie on one side of a
/// thin part (a tail, an ear) while its middle hangs over the other.
/// O(n log n) in the surface and O(log n) per remesh triangle.
std::vector<char> centroidFlippedTriangles(const TriangleMesh& surface, const TriangleMesh& placed);

/// \brief For every remesh triangle, the landmark nearest to it: feature f
///        (remesh vertex f, f < `landmarkCount`, the base domain's vertex
///        count) nearest, in remesh edges, to its closest corner. Ties are
///        broken by the connectivity alone. Depends on the connectivity
///        only, so one call serves every model of a collection. Linear in
///        the remesh; empty if `landmarkCount` is not between 0 and the
///        remesh's vertex count.
std::vector<int> nearestLandmarkOfTriangles(const SemiRegularMesh& remesh, int landmarkCount);

/// \brief How many of the `folded` remesh triangles (1 per folded
///        triangle, in triangle order, as `foldedTriangles()` gives) lie
///        nearest to each of the `landmarkCount` landmarks, given
///        `nearestLandmarkOfTriangles()`: says which landmark to move, or
///        to add one beside, where folds stay after repair. Empty if the
///        two lists differ in length or `landmarkCount` is negative.
std::vector<int> foldsNearLandmarks(
  const std::vector<int>& nearestLandmark, int landmarkCount, const std::vector<char>& folded);

/// \brief The same for one remesh: `nearestLandmarkOfTriangles()`, then the
///        counts; empty if `folded` does not have one entry per triangle or
///        `landmarkCount` is not between 0 and the remesh's vertex count.
std::vector<int> foldsNearLandmarks(
  const SemiRegularMesh& remesh, int landmarkCount, const std::vector<char>& folded);

/// \brief Moves vertices of folded remesh triangles along `surface` until
///        their triangles agree with it, or no move helps.
///
/// A thin remesh triangle on a curved surface can point against it even
/// though the parameterization is bijective: its normal is decided by the
/// short side, which curvature can tip over. First, the vertices within
/// five rings of the folds move together down the gradient of a penalty on
/// thin and folded triangles (a band of needles sheared at the scale of
/// several triangles needs such joint moves), and the state with fewest
/// folds is kept; while folds remain, again within 2, 3, ...
/// `regionWidening` times the first reach. Then each sweep tries, for every
/// vertex of a folded triangle that is left, short moves in 16 directions
/// of the tangent plane (walked across the surface's triangles, so the
/// vertex stays on it) and keeps the one that leaves fewest bad triangles
/// around the vertex (folded, or so flat that a fold would be traded for a
/// collapse), then the best worst shape quality (signed by the triangle's
/// agreement with the surface), never one with more folds; vertices with
/// most folds around them go first; a vertex the regions already took
/// farther than its own reach from its parameterized place does not move
/// alone. In the other order, single moves lock fans of needles that the
/// joint moves then cannot undo, and more folds remain (measured in
/// Documentation/filters/SemiRegularRemesher.md, "Fold repair").
/// Landmark samples never move, nor do the vertices of an open remesh's
/// boundary (they stay on the surface's boundary). Every moved sample still names the surface
/// triangle it lies in. Beyond the paper, whose remesh has no repair.
///
/// \pre `samples` are `remesh` placed on `surface` (`placeOnSurface()` on
///      the layout whose mesh is `surface`).
/// Fails (Status, "fold repair: ..."), changing nothing, when `samples` do
/// not fit `remesh` and `surface` (not one per vertex, a triangle or vertex
/// the surface does not have or has removed, weights that are not
/// barycentric in their triangle) or an option is out of range (`reach` or
/// `maximumSweeps` negative, `regionWidening` or `singleWidening` outside 1 to 64).
Status repairFolds(const SemiRegularMesh& remesh, const EditableMesh& surface, std::vector<SurfacePoint>& samples,
  const FoldRepairOptions& options = {}, FoldRepairReport* report = nullptr);

} // namespace cmp
