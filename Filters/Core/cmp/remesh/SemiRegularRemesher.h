#pragma once
/// \file SemiRegularRemesher.h
/// \brief The paper's remeshing: the base domain refined by 1-to-4
///        quadrisection, one connectivity for every model, each model's
///        vertices placed through its parameterization.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/SurfacePoint.h>
#include <cmp/mesh/TriangleMesh.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cmp
{

/// A place in the base domain is a `SurfacePoint` of `L0`'s mesh made by
/// `SurfacePoint::inTriangle()`: a base triangle, its three corners and the
/// place's barycentric coordinates in their order.

/// \brief `at` in barycentric coordinates (c1, c2) of base triangle
///        `triangle` (its own, or one sharing the vertices `at` lies on);
///        false, `result` untouched, if `at` is not on that triangle.
/// \pre `at.triangle` and `triangle` are triangles of `domain`.
bool locationInBaseTriangle(const BaseDomain& domain, const SurfacePoint& at, int triangle, Vec2& result);

/// \brief The semi-regular connectivity shared by every model of a
///        collection.
///
/// Vertex numbering: the F base vertices first, vertex f being the base
/// vertex of feature f; then the midpoints made by each quadrisection, level
/// by level, in the order in which their parent edges first appear when the
/// previous level's triangles are read in order (edge k -> k+1 of each
/// triangle). So the vertices of level l are the first ones of level l+1.
/// Triangles: each base triangle's 4^level triangles, base triangles in order,
/// within one in the order of recursive quadrisection (corner a, corner b,
/// corner c, centre), counter-clockwise like the base domain.
struct SemiRegularMesh
{
  int level = 0;                        ///< Quadrisections applied to L0.
  std::vector<Triangle> triangles;      ///< Counter-clockwise triangles.
  std::vector<int> patchOfTriangle;     ///< Base triangle of each triangle.
  std::vector<SurfacePoint> locations;  ///< Base-domain place of each vertex.
  std::vector<int> levelOfVertex;       ///< Level at which each vertex appears (0 for base vertices).
  /// \brief Level of each triangle: `level` everywhere for uniform
  ///        refinement; for adaptive refinement the depth of the leaf it
  ///        belongs to (a leaf bisected to close a T-junction gives both
  ///        halves its own level).
  std::vector<int> levelOfTriangle;

  /// \brief Number of vertices.
  int vertexCount() const { return static_cast<int>(locations.size()); }
};

/// \brief The finest remesh level: L0 refined 8 times has 65,536 triangles
///        per base triangle (2.5M for the 38 of a four-legged L0).
constexpr int kMaximumRemeshLevel = 8;

/// \brief Whether `level` is a remesh level (0 to `kMaximumRemeshLevel`).
constexpr bool isRemeshLevel(int level) { return level >= 0 && level <= kMaximumRemeshLevel; }

/// \brief Why `level` is not one, in the words every stage uses.
std::string remeshLevelProblem(int level);

/// \brief Why the user's setting `property` (a filter property such as
///        `Level`) is not a remesh level: "PROPERTY must be between 0 and
///        8 (it is N)". Levels out of range are refused with this message,
///        never clamped.
std::string remeshLevelProblem(const std::string& property, int level);

/// \brief Builds the connectivity of `domain` refined `level` times (0 to
///        `kMaximumRemeshLevel`).
///        Depends only on the base domain and the level. Paper §2:
///        repeated quadrisection of `L0`, one connectivity for every model.
///        Fails (Status) on a level out of range (`remeshLevelProblem()`)
///        and on a `domain` that fails `checkBaseDomain()`.
Status buildSemiRegularMesh(const BaseDomain& domain, int level, SemiRegularMesh& out);

/// \brief Leaves out of `mesh` its triangles in the base triangles marked in
///        `holeTriangles` (one entry per base triangle of `domain`; the caps
///        `closeBaseDomain()` added to an open L0) and the vertices only
///        they use, the others in their order: the base vertices of the open
///        L0, whose features come before the caps', stay vertices 0..F-1,
///        and the vertices of level l stay the first of level l + 1. A
///        vertex on an edge between a hole and a kept base triangle gets its
///        place named in the kept one. Nothing changes with `holeTriangles`
///        empty. Beyond the paper (surfaces with boundaries).
/// \pre `mesh` was built on `domain`.
/// Fails (Status), `mesh` unchanged, when `holeTriangles` has not one entry
/// per base triangle or marks all of them.
Status removeHoleTriangles(const BaseDomain& domain, const std::vector<char>& holeTriangles, SemiRegularMesh& mesh);

/// \brief Decides whether a triangle of an adaptive remesh is split: gets
///        its corners as locations in its base triangle and its level.
using SplitRule = std::function<bool(const std::array<SurfacePoint, 3>& corners, int level)>;

/// \brief Builds an adaptive semi-regular connectivity: triangles are
///        quadrisected while `needsSplit` says so, up to `maximumLevel`;
///        then neighbours are split until levels differ by at most one
///        across every edge, and a triangle with one finer neighbour is
///        bisected at that edge's midpoint so that the mesh has no
///        T-junctions (a triangle with two or more is quadrisected).
///
/// The result depends only on the base domain and on which triangles are
/// split, so every model remeshed with one rule shares it. Numbering is
/// that of `buildSemiRegularMesh()` restricted to the split triangles (with
/// every triangle split it is identical): base vertices first, then the
/// midpoints of level l in the order their edges first appear when the
/// split triangles of level l - 1 are read in order; triangles in the order
/// of recursive quadrisection, a bisected leaf giving its two halves.
/// Paper §2 ("this can be done in an adaptive fashion"); the balancing and
/// the bisections that close T-junctions are ours.
///
/// \pre `needsSplit` answers the same for the same corners and level (so
///      the result is one connectivity, whoever builds it).
/// Fails (Status) on a maximum level out of range (`remeshLevelProblem()`)
/// and on a `domain` that fails `checkBaseDomain()`.
Status buildAdaptiveSemiRegularMesh(
  const BaseDomain& domain, int maximumLevel, const SplitRule& needsSplit, SemiRegularMesh& out);

/// \brief One parameterized model, ready to answer where a base-domain
///        location lies on it: a uniform grid per patch over the images
///        of its triangles, built once.
class ParameterizedSurface
{
public:
  /// \brief Indexes `net` (the straightener's output) with its per-patch
  ///        parameterization.
  /// \pre `net` and `domain` outlive this object; `net` is a layout of
  ///      `domain` and `parameterization` its `parameterizePatches()` (or
  ///      `freeCurves()`) map.
  /// Fails (Status) when `parameterization` has not one entry per vertex of
  /// `net`, `net` has not one landmark per base vertex, or a vertex has no
  /// coordinates in a patch it belongs to (its base triangle is not that
  /// patch and it does not lie on the vertices they share).
  Status build(const TracedNet& net, const BaseDomain& domain, const PatchParameterization& parameterization);

  /// \brief The surface point at base location `at`: the landmark itself
  ///        at a base vertex, otherwise the triangle of `at`'s patch whose
  ///        image contains it, with barycentric weights (a point just
  ///        outside every image gets the nearest).
  /// \pre `at` is a place in the base domain given to `build()`
  ///      (`SurfacePoint::inTriangle()` of its mesh).
  /// Fails (Status) when the surface was not built, or when no triangle of
  /// the patch has an image of positive area.
  Status locate(const SurfacePoint& at, SurfacePoint& sample) const;

  /// \brief The position of `sample` on the surface. \pre `built()`, and
  ///        `sample` a point of its layout's mesh (`locate()`).
  Vec3 position(const SurfacePoint& sample) const;

  /// \brief Length of the diagonal of the surface's bounding box.
  double boundingBoxDiagonal() const { return diagonal_; }

  /// \brief True once `build()` succeeded.
  bool built() const { return index_ != nullptr; }

  /// \brief The layout it was built on. \pre `built()`.
  const TracedNet& net() const { return *net_; }

  /// \brief Calls `visit(patch, image, area)` for every surface triangle:
  ///        its patch, its image's corners in barycentric coordinates
  ///        (c1, c2) of that patch's base triangle, and its surface area.
  void forEachTriangleImage(const std::function<void(int, const std::array<Vec2, 3>&, double)>& visit) const;

  ParameterizedSurface();
  ~ParameterizedSurface();
  ParameterizedSurface(ParameterizedSurface&&) noexcept;
  ParameterizedSurface& operator=(ParameterizedSurface&&) noexcept;

private:
  struct Index;
  std::unique_ptr<Index> index_;
  const TracedNet* net_ = nullptr;
  const BaseDomain* domain_ = nullptr;
  double diagonal_ = 0.0;
};

/// \brief The split rule for adaptive remeshing of a collection: a triangle
///        is split when, on any of `models`, the surface point at one of
///        the 12 points of its next two quadrisections (its barycentric
///        lattice of order 4 without the corners) lies farther than
///        `tolerance` times that model's bounding-box diagonal from the
///        point the flat triangle through its corners' surface points puts
///        there. A corner or point a model cannot locate splits the
///        triangle. Beyond the paper, which does not say when to refine.
/// \pre The models are built over the base domain the adaptive remesh is
///      built on, and outlive the rule.
SplitRule flatnessSplitRule(const std::vector<const ParameterizedSurface*>& models, double tolerance);

/// \brief Places every vertex of `remesh` on a parameterized model by
///        inverting its parameterization: the triangle of the vertex's patch
///        whose image contains the vertex's base location (a uniform grid
///        per patch, not a scan), interpolated barycentrically. `net` and
///        `parameterization` are the straightener's and the per-patch
///        map's output for the same surface. Paper §2: the remesh's
///        vertices on each model through its map.
/// \pre `remesh` was built on `domain`.
/// Fails (Status) where `ParameterizedSurface::build()` fails, and when a
/// remesh vertex cannot be located ("remesh vertex V: ...").
Status placeOnSurface(const SemiRegularMesh& remesh, const TracedNet& net, const BaseDomain& domain,
  const PatchParameterization& parameterization, std::vector<SurfacePoint>& samples);

/// \brief Places every vertex of `remesh` on a model already indexed.
/// \pre `surface` was built over the base domain `remesh` was built on.
/// Fails (Status, "remesh vertex V: ...") where
/// `ParameterizedSurface::locate()` fails.
Status placeOnSurface(
  const SemiRegularMesh& remesh, const ParameterizedSurface& surface, std::vector<SurfacePoint>& samples);

/// \brief The position of `sample` on `mesh`: its weights on its (up to
///        three) vertices. \pre Its vertices are vertices of `mesh` (or -1).
Vec3 samplePosition(const EditableMesh& mesh, const SurfacePoint& sample);

/// \brief The positions of `samples` on the mesh of `net`.
std::vector<Vec3> samplePositions(const TracedNet& net, const std::vector<SurfacePoint>& samples);

} // namespace cmp
