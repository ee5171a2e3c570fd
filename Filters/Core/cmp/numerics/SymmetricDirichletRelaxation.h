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
  /// \brief Steps at most; most patch maps settle within 20, a crowded
  ///        protrusion takes 100 or more (385's tail, squeezed 1e9 times in
  ///        its mean value map: about 210). A relaxation cut short while
  ///        still progressive stops at a point of its path that rounding
  ///        decides: 385's remesh then lay 1.7% to 6.6% of the diagonal
  ///        from its tail's tip, depending on the machine, where the
  ///        settled map gives 4.3% to 4.8%.
  int maximumIterations = 400;
  /// \brief A step that lowers the energy by less than this fraction ends
  ///        the relaxation (1e-4 takes twice the time on a 1M-triangle
  ///        surface for a 1% lower summed remesh Hausdorff distance on the
  ///        SHREC'07 models).
  double leastRelativeGain = 1e-3;
  /// \brief A map that scales some triangle by more than this factor (in
  ///        either direction) is first relaxed by progressive steps: each
  ///        aims at reference shapes between the current triangles and the
  ///        surface's, no further than `progressiveStepDistortion` from the
  ///        current map, instead of at the surface itself. From a long
  ///        protrusion squeezed a million times in a mean value map, plain
  ///        steps are cut to a millionth by the flip-free line search and
  ///        stall; progressive ones are not. Infinity turns them off.
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
/// Every triangle's image must start counter-clockwise with positive area
/// (a bijective map such as a Tutte or mean value embedding); fails, naming
/// the problem, if it does not, if the sizes disagree, if a coordinate is
/// not finite or if no vertex is fixed. A system that cannot be solved (a
/// free vertex with no triangle of positive area) ends the relaxation with
/// the map as it is. Cost per step: one sparse Cholesky factorization of
/// 2 x (free vertices) unknowns, its pattern analysed once.
Status relaxSymmetricDirichlet(const TriangleMesh& surface, const std::vector<char>& fixed, Eigen::MatrixXd& plane,
  const SymmetricDirichletOptions& options = {}, SymmetricDirichletReport* report = nullptr);

} // namespace cmp
