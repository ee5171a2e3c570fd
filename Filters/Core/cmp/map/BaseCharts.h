#pragma once
/// \file BaseCharts.h
/// \brief The base domain drawn with equilateral triangles, and the charts
///        that lay the triangles around a base vertex flat beside each
///        other: where a map of the whole surface onto L0 measures its
///        distortion and moves points across patch boundaries.

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>

#include <array>
#include <vector>

namespace cmp
{

/// \brief A point of the base domain: a base triangle and a position in
///        that triangle's unit equilateral frame (corner 0 at (0, 0),
///        corner 1 at (1, 0), corner 2 at (1/2, sqrt(3)/2)).
struct BasePoint
{
  int triangle = -1; ///< Base triangle.
  Vec2 position = Vec2::Zero(); ///< Position in its frame.
};

/// \brief Every base triangle unfolded into the frame of every other one
///        that shares a vertex with it, across the edges around that
///        vertex (the shorter way round; none for the triangle opposite
///        an even valence's, which has two): isometric for equilateral
///        triangles, so a surface triangle whose corners lie in triangles
///        around one base vertex has one shape in all of their frames.
class BaseCharts
{
public:
  /// \brief Builds the unfoldings; `domain` must pass `checkBaseDomain()`.
  void build(const BaseDomain& domain);

  /// \brief Corners of base triangle `other` in the frame of `anchor`, in
  ///        `other`'s vertex order; null if the two share no vertex.
  const std::array<Vec2, 3>* corners(int anchor, int other) const;

  /// \brief `point` in the frame of `anchor`; false if its triangle shares
  ///        no vertex with `anchor`.
  bool inFrame(int anchor, const BasePoint& point, Vec2& result) const;

  /// \brief The base point at `position` of `anchor`'s frame: `anchor`
  ///        itself or the unfolded triangle around it holding `position`
  ///        (barycentric coordinates >= -`slack`, clamped); false if none
  ///        holds it.
  bool locate(int anchor, const Vec2& position, BasePoint& result, double slack = 1e-12) const;

  /// \brief Barycentric coordinates of `point` in its triangle's vertex order.
  static std::array<double, 3> barycentric(const BasePoint& point);
  /// \brief The base point with barycentric coordinates `coordinates` in `triangle`.
  static BasePoint fromBarycentric(int triangle, const std::array<double, 3>& coordinates);
  /// \brief Corner k of the unit equilateral frame.
  static Vec2 corner(int k);

private:
  struct Entry
  {
    int other = -1;
    std::array<Vec2, 3> corners;
  };
  std::vector<Triangle> triangles_;
  std::vector<std::vector<Entry>> charts_; ///< Per anchor, the triangles around it (itself first).
};

/// \brief Barycentric coordinates of `p` in the 2D triangle `corners`.
std::array<double, 3> barycentricIn(const std::array<Vec2, 3>& corners, const Vec2& p);

} // namespace cmp
