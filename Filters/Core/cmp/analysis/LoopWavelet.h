#pragma once
/// \file LoopWavelet.h
/// \brief Loop-subdivision wavelets on the shared semi-regular connectivity:
///        values at the finest level split into coarsest-level values and
///        one block of details per level, and put back together exactly.

#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <Eigen/Core>

#include <vector>

namespace cmp
{

/// \brief How the details of 3-column values (positions) are expressed.
enum class DetailFrame
{
  Global, ///< In the coordinates of the values themselves.
  /// \brief In an orthonormal frame at the detail's vertex of the surface
  ///        predicted from the coarser level (its Loop subdivision):
  ///        column 2 along that surface's normal, column 0 along the
  ///        vertex's parent edge projected to the tangent plane, column 1
  ///        across it. Details then follow the coarse shape they are put
  ///        on, whatever its orientation.
  Local
};

/// \brief Wavelet coefficients of values on a uniform semi-regular mesh.
///
/// Layout: one row per vertex of the finest level, so the coefficients can
/// be shown as point data on the finest mesh. A base vertex's row holds its
/// value at the coarsest level; the row of a vertex new at level l holds its
/// level-l detail. Because the remesher numbers vertices level by level,
/// each block is contiguous: rows [0, V_0) are the coarsest values and rows
/// [V_{l-1}, V_l) the details of level l, where V_l = `levelVertexCount[l]`.
struct WaveletCoefficients
{
  Eigen::MatrixXd values;                  ///< One row per finest vertex, one column per component.
  std::vector<int> levelVertexCount;       ///< V_0, ..., V_J: vertices of each level.
  DetailFrame frame = DetailFrame::Global; ///< How the details are expressed.

  /// \brief The finest level J (-1 when empty).
  int level() const { return static_cast<int>(levelVertexCount.size()) - 1; }
  /// \brief The coarsest-level values (V_0 rows; none when empty).
  Eigen::MatrixXd::ConstRowsBlockXpr coarse() const { return values.topRows(level() < 0 ? 0 : levelVertexCount[0]); }
  /// \brief The details of level `l` (1..J), one row per vertex new at `l`;
  ///        no rows for any other `l`.
  Eigen::MatrixXd::ConstRowsBlockXpr details(int l) const
  {
    if (l < 1 || l > level())
      return values.middleRows(0, 0);
    return values.middleRows(levelVertexCount[l - 1], levelVertexCount[l] - levelVertexCount[l - 1]);
  }
};

/// \brief A lifted Loop wavelet transform on one uniform semi-regular
///        connectivity, built once and applied to any values on it.
///
/// Values are an Eigen matrix with one row per vertex (in the remesh's
/// numbering) and any number of columns: 3 for positions, 1 for a scalar.
/// Synthesis with all details zero is exactly Loop subdivision of the
/// coarse values. Analysis makes each level (nearly) the least-squares Loop
/// control mesh of the next finer one, so coarse levels are a smoothed,
/// low-pass version of the input, not a subsampling. Both directions are
/// linear, cost O(vertices) and reconstruct exactly up to rounding. The
/// lifting steps are documented in LoopWavelet.cpp. Paper §3: the
/// "Loop-based wavelets" of its detail transfer (its reference [5]).
///
/// An open remesh (a surface with boundaries, `RemeshOptions::holeTriangles`;
/// beyond the paper) has Loop's boundary rules: the boundary curve is
/// subdivided as a cubic B-spline of its own values (odd 1/2, 1/2; even
/// 3/4, 1/8, 1/8) from boundary values alone, and the interior by Loop's
/// interior rules.
class LoopWaveletTransform
{
public:
  /// \brief Precomputes the lifting stencils of every level of `mesh`, which
  ///        must be uniform: `buildSemiRegularMesh()` output, not an
  ///        adaptive remesh.
  /// Fails (Status) on any other connectivity: a level out of range, a
  /// triangle count that is not a multiple of 4^level, triangles of several
  /// levels, vertices not numbered level by level, levels that are not
  /// quadrisections of a coarser mesh, or a coarser mesh that is not a
  /// manifold (an edge of more than two triangles, a vertex on more than
  /// two boundary edges). The transform is then empty.
  Status build(const SemiRegularMesh& mesh);

  /// \brief The finest level J (-1 before a successful `build()`).
  int level() const { return static_cast<int>(vertexCount_.size()) - 1; }
  /// \brief Number of vertices V_l of level `l` (0..J).
  int vertexCount(int l) const { return vertexCount_.at(l); }
  /// \brief The triangles of level `l` (0..J), in the remesh's numbering.
  const std::vector<Triangle>& triangles(int l) const { return triangles_.at(l); }

  /// \brief Splits `values` (V_J rows) into coarsest values and details.
  ///        `DetailFrame::Local` needs exactly 3 columns.
  /// Fails (Status) when the transform is not built, `values` has not V_J
  /// rows, has no column (or not 3 for local frames) or a non-finite entry.
  Status analyze(const Eigen::MatrixXd& values, DetailFrame frame, WaveletCoefficients& out) const;

  /// \brief Rebuilds the finest-level values from `coefficients`.
  /// Fails (Status) when the transform is not built, or `coefficients` are
  /// not of its levels and vertices (V_J rows, at least one column, 3 for
  /// local frames) or hold a non-finite entry.
  Status synthesize(const WaveletCoefficients& coefficients, Eigen::MatrixXd& values) const;

  /// \brief Rebuilds the values of level `l` (V_l rows) from the coarsest
  ///        values and the details of levels 1..l: the level-l
  ///        approximation, the mesh to show for that level. Fails as the
  ///        finest-level `synthesize()` does, and on `l` outside 0..J.
  Status synthesize(const WaveletCoefficients& coefficients, int l, Eigen::MatrixXd& values) const;

  LoopWaveletTransform();
  ~LoopWaveletTransform();
  LoopWaveletTransform(const LoopWaveletTransform&);
  LoopWaveletTransform& operator=(const LoopWaveletTransform&);
  LoopWaveletTransform(LoopWaveletTransform&&) noexcept;
  LoopWaveletTransform& operator=(LoopWaveletTransform&&) noexcept;

private:
  struct Level;

  Status checkCoefficients(const WaveletCoefficients& coefficients, int l) const;
  /// \brief Turns the global details of `coefficients` into local ones.
  void expressDetailsLocally(Eigen::MatrixXd& coefficients) const;

  std::vector<int> vertexCount_;                 ///< V_0..V_J.
  std::vector<std::vector<Triangle>> triangles_; ///< Triangles of levels 0..J.
  std::vector<Level> levels_;                    ///< levels_[l] refines l-1 to l (entry 0 unused).
};

} // namespace cmp
