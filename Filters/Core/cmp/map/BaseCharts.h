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

/// \brief The star of one base vertex unfolded into the frame of one of
///        its triangles all the way round, opened half a turn from one of
///        its edges: the chart in which a curve along that edge sees every
///        triangle round its end as L0 has it (`BaseCharts` stops short of
///        the triangle opposite an even valence's anchor, and each anchor
///        opens its star elsewhere).
class StarUnfolding
{
public:
  /// \brief The star of `center`, a vertex of base triangle `anchor`, in
  ///        `anchor`'s frame, opened opposite the edge from `center` to
  ///        `towards` (another vertex of `anchor`); false if the star is
  ///        not one fan.
  bool build(const BaseDomain& domain, int anchor, int center, int towards);

  /// \brief `point` in the unfolding, the way round nearer the edge;
  ///        false if it lies outside the closed star or more than half a
  ///        turn from the edge both ways.
  bool position(const BasePoint& point, Vec2& result) const;

  /// \brief `point`'s distance from the centre and its angle round it,
  ///        counter-clockwise from the edge (0 to `turn()`); false if it
  ///        lies outside the closed star.
  bool polar(const BasePoint& point, double& radius, double& angle) const;

  /// \brief The point at `radius` from the centre and `angle`
  ///        counter-clockwise from the edge, in the anchor's frame: the
  ///        star unfolded on and on (past `turn()` it laps over itself
  ///        above valence 6 and leaves a gap below), so that any arc of it
  ///        shorter than a turn is drawn as L0 has it.
  Vec2 atPolar(double radius, double angle) const;

  /// \brief The star's whole angle round its centre: valence sixths of a turn.
  double turn() const;

private:
  struct Sector
  {
    int triangle = -1;
    std::array<Vec2, 3> corners; ///< In the triangle's vertex order.
  };
  /// `point` in one way round, and its angle from the edge.
  bool locate(const std::vector<Sector>& chain, const BasePoint& point, Vec2& result, double& angle) const;

  const std::vector<Triangle>* triangles_ = nullptr;
  int center_ = -1;
  Vec2 centre_ = Vec2::Zero(); ///< The centre in the anchor's frame.
  Vec2 edge_ = Vec2::Zero();   ///< The edge from the centre.
  std::vector<Sector> ccw_;    ///< The star counter-clockwise from the edge.
  std::vector<Sector> cw_;     ///< The star clockwise from the edge.
};

/// \brief Barycentric coordinates of `p` in the 2D triangle `corners`.
std::array<double, 3> barycentricIn(const std::array<Vec2, 3>& corners, const Vec2& p);

} // namespace cmp
