#pragma once
/// \file SymmetricDirichletRelaxation.h
/// \brief Lowers the distortion of a bijective map of a disk-like surface to
///        the plane, its boundary held: symmetric Dirichlet energy, lowered
///        by SLIM steps (Rabinovich, Poranne, Panozzo, Sorkine-Hornung 2017)
///        with a line search that never lets a triangle flip; a crushed map
///        first goes through progressive reference shapes (Liu, Ye, Wang,
///        Xiang, Hu 2018).

#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>

#include <vector>

namespace cmp
{

/// \brief Tuning of `relaxSymmetricDirichlet()`.
struct SymmetricDirichletOptions
{
  /// \brief Steps at most: a safety bound, set high enough that a crowded
  ///        protrusion's map settles (`leastRelativeGain`) before it. A
  ///        relaxation cut short while still progressive stops at a point of
  ///        its path that rounding decides, so the result would depend on
  ///        the machine (figures in Documentation/filters/NetStraightener.md,
  ///        "Lower stretch").
  int maximumIterations = 400;
  /// \brief A step that lowers the energy by less than this fraction ends
  ///        the relaxation; a smaller value takes more steps (its cost and
  ///        gain: Documentation/filters/NetStraightener.md, "Speed").
  double leastRelativeGain = 1e-3;
  /// \brief A map that scales some triangle by more than this factor (in
  ///        either direction) is first relaxed by progressive steps: each
  ///        aims at reference shapes between the current triangles and the
  ///        surface's, no further than `progressiveStepDistortion` from the
  ///        current map, instead of at the surface itself. From a long
  ///        protrusion squeezed by orders of magnitude in a mean value map,
  ///        plain steps are cut to almost nothing by the flip-free line
  ///        search and stall; progressive ones are not. Infinity turns them
  ///        off.
  double progressiveAbove = 1000.0;
  /// \brief How far, as a scale factor, a progressive step's reference
  ///        shapes lie from the current map; 1 or less turns progressive
  ///        steps off.
  double progressiveStepDistortion = 2.0;
};

/// \brief What `relaxSymmetricDirichlet()` did.
struct SymmetricDirichletReport
{
  int iterations = 0;         ///< Steps taken, progressive ones included.
  int progressiveIterations = 0; ///< Of those, steps towards reference shapes.
  double energyBefore = 0.0;  ///< Energy of the starting map.
  double energyAfter = 0.0;   ///< Energy of the result.
};

/// \brief The symmetric Dirichlet energy of the map `plane` (n x 2, one row
///        per vertex of `surface`): sum over triangles of area x (|J|^2 +
///        |J^-1|^2), J the map's differential from the surface triangle to
///        the plane; 4 x area for an isometry, infinite if a triangle of
///        positive area has a flipped or degenerate image. Triangles of zero
///        surface area do not count.
/// \pre `plane` has one row per vertex of `surface` and 2 columns.
double symmetricDirichletEnergy(const TriangleMesh& surface, const Eigen::MatrixXd& plane);

/// \brief Moves the free vertices of `plane` (those with `fixed[v] == 0`)
///        to lower the symmetric Dirichlet energy, which grows without bound
///        as a triangle's image shrinks to nothing: crowded protrusions get
///        room, and the map stays bijective (every step stops short of the
///        first flip). Fixed vertices keep their rows bit for bit.
///
/// A progressive step lowers the energy measured against its reference
/// shapes; the energy against the surface usually falls with it, and the
/// progressive phase ends, handing back to plain steps, when that energy
/// falls by less than `leastRelativeGain` (a step that raises it is undone)
/// or the map is within `progressiveStepDistortion` everywhere.
///
/// \pre `plane` is n x 2 and `fixed` has n entries (n =
///      `surface.vertexCount()`), at least one vertex is fixed, and every
///      triangle of positive surface area starts counter-clockwise with
///      positive image area (a bijective map such as a Tutte or mean value
///      embedding).
/// Fails (Status), naming the problem and leaving `plane` unchanged, when
/// one of these does not hold or a coordinate is not finite. A system that
/// cannot be solved (a free vertex with no triangle of positive area) is no
/// failure: it ends the relaxation with the map as it is. Beyond the paper
/// (SLIM and progressive steps, cited above); used by the per-patch maps'
/// `lowerStretch`. Cost per step: one sparse Cholesky factorization of
/// 2 x (free vertices) unknowns, its pattern analysed once.
Status relaxSymmetricDirichlet(const TriangleMesh& surface, const std::vector<char>& fixed, Eigen::MatrixXd& plane,
  const SymmetricDirichletOptions& options = {}, SymmetricDirichletReport* report = nullptr);

} // namespace cmp
