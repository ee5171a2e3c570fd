#pragma once
/// \file TriangleGrid.h
/// \brief Point location among the triangles of one base triangle, drawn in
///        its barycentric coordinates (c1, c2), inside the unit square.

#include <cmp/mesh/TriangleMesh.h>

#include <array>
#include <vector>

namespace cmp
{

/// \brief A uniform grid of cells over the unit square, each listing the
///        triangles whose bounding box meets it. About two triangles per
///        cell, so a query visits a handful of triangles.
class TriangleGrid
{
public:
  /// \brief Indexes `corners` (one entry per triangle), which must outlive
  ///        the grid and not change while it is used.
  void build(const std::vector<std::array<Vec2, 3>>& corners);

  /// \brief The triangle (index into `corners`) that contains `q` best:
  ///        largest smallest barycentric coordinate, searched in rings of
  ///        cells outwards until one contains it (within 1e-9); if none
  ///        does, the best of all (a point just outside every triangle
  ///        gets the nearest). `weights` are `q`'s barycentric coordinates
  ///        in it. Triangles without positive area are skipped. False only
  ///        if no triangle has positive area. \pre `build()` was called.
  bool locate(const Vec2& q, int& best, std::array<double, 3>& weights) const;

private:
  int cellOf(double u) const;
  template <class Visit>
  void forEachCell(Visit visit) const;
  void score(int i, const Vec2& q, double& bestScore, int& best, std::array<double, 3>& weights) const;

  const std::vector<std::array<Vec2, 3>>* corners_ = nullptr;
  int size_ = 1;
  std::vector<int> start_, entries_;
};

} // namespace cmp
