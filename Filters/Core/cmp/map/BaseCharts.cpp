#include <cmp/map/BaseCharts.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cmp
{

namespace
{
constexpr double kSixthTurn = 1.0471975511965976; // pi / 3
}

Vec2 BaseCharts::corner(int k)
{
  return k == 0 ? Vec2(0.0, 0.0) : k == 1 ? Vec2(1.0, 0.0) : Vec2(0.5, 0.5 * std::sqrt(3.0));
}

std::array<double, 3> barycentricIn(const std::array<Vec2, 3>& corners, const Vec2& p)
{
  const Vec2 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0], d = p - corners[0];
  const double det = cross2(e1, e2);
  const double b1 = cross2(d, e2) / det, b2 = cross2(e1, d) / det;
  return { 1.0 - b1 - b2, b1, b2 };
}

std::array<double, 3> BaseCharts::barycentric(const BasePoint& point)
{
  return barycentricIn({ corner(0), corner(1), corner(2) }, point.position);
}

BasePoint BaseCharts::fromBarycentric(int triangle, const std::array<double, 3>& coordinates)
{
  BasePoint p;
  p.triangle = triangle;
  p.position = coordinates[0] * corner(0) + coordinates[1] * corner(1) + coordinates[2] * corner(2);
  return p;
}

void BaseCharts::build(const BaseDomain& domain)
{
  const std::vector<Triangle>& triangles = domain.mesh.triangles;
  const int count = static_cast<int>(triangles.size());
  std::map<std::pair<int, int>, std::vector<int>> byEdge;
  std::vector<int> valence(domain.mesh.vertexCount(), 0);
  for (int t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k)
    {
      const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      byEdge[{ std::min(a, b), std::max(a, b) }].push_back(t);
      ++valence[a];
    }
  triangles_ = triangles;
  charts_.assign(count, {});
  for (int anchor = 0; anchor < count; ++anchor)
  {
    std::vector<Entry>& entries = charts_[anchor];
    entries.push_back({ anchor, { corner(0), corner(1), corner(2) } });
    for (int v : triangles[anchor])
    {
      // Breadth first around v, the shorter way round.
      std::vector<std::pair<int, std::array<Vec2, 3>>> layer{ { anchor, entries.front().corners } };
      // (valence - 1) / 2 each way: the triangle opposite an even valence's
      // anchor, reached both ways round with different unfoldings, has none.
      for (int depth = 1; depth <= (valence[v] - 1) / 2 && !layer.empty(); ++depth)
      {
        std::vector<std::pair<int, std::array<Vec2, 3>>> next;
        for (const auto& [x, at] : layer)
        {
          const Triangle& tx = triangles[x];
          const int i = static_cast<int>(std::find(tx.begin(), tx.end(), v) - tx.begin());
          for (int side : { 1, 2 }) // the two edges of x at v
          {
            const int j = (i + side) % 3, s = 3 - i - j; // corners v, w = tx[j], and the third
            const int w = tx[j];
            for (int y : byEdge[{ std::min(v, w), std::max(v, w) }])
            {
              if (y == x)
                continue;
              const bool known = std::any_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.other == y; });
              if (known)
                continue;
              std::array<Vec2, 3> corners;
              const Triangle& ty = triangles[y];
              for (int k = 0; k < 3; ++k)
                corners[k] = ty[k] == v ? at[i] : ty[k] == w ? at[j] : at[i] + at[j] - at[s];
              entries.push_back({ y, corners });
              next.emplace_back(y, corners);
            }
          }
        }
        layer = std::move(next);
      }
    }
  }
}

const std::array<Vec2, 3>* BaseCharts::corners(int anchor, int other) const
{
  if (anchor < 0 || anchor >= static_cast<int>(charts_.size()))
    return nullptr;
  for (const Entry& e : charts_[anchor])
    if (e.other == other)
      return &e.corners;
  return nullptr;
}

bool BaseCharts::inFrame(int anchor, const BasePoint& point, Vec2& result) const
{
  if (point.triangle == anchor)
  {
    result = point.position;
    return true;
  }
  if (anchor < 0 || anchor >= static_cast<int>(charts_.size()) || point.triangle < 0 ||
    point.triangle >= static_cast<int>(charts_.size()))
    return false;
  const std::array<double, 3> b = barycentric(point);
  // On vertices the anchor has too (a landmark, a point of a shared edge):
  // their corners, whatever way round the point's triangle unfolds.
  const Triangle& own = triangles_[point.triangle];
  const Triangle& frame = triangles_[anchor];
  Vec2 shared = Vec2::Zero();
  bool allShared = true;
  for (int k = 0; k < 3 && allShared; ++k)
  {
    if (b[k] == 0.0)
      continue;
    const auto it = std::find(frame.begin(), frame.end(), own[k]);
    if (it == frame.end())
      allShared = false;
    else
      shared += b[k] * corner(static_cast<int>(it - frame.begin()));
  }
  if (allShared)
  {
    result = shared;
    return true;
  }
  const std::array<Vec2, 3>* c = corners(anchor, point.triangle);
  if (!c)
    return false;
  result = b[0] * (*c)[0] + b[1] * (*c)[1] + b[2] * (*c)[2];
  return true;
}

bool BaseCharts::locate(int anchor, const Vec2& position, BasePoint& result, double slack) const
{
  if (anchor < 0 || anchor >= static_cast<int>(charts_.size()))
    return false;
  for (const Entry& e : charts_[anchor])
  {
    std::array<double, 3> b = barycentricIn(e.corners, position);
    if (b[0] >= -slack && b[1] >= -slack && b[2] >= -slack)
    {
      double sum = 0.0;
      for (double& x : b)
        sum += (x = std::max(x, 0.0));
      for (double& x : b)
        x /= sum;
      result = fromBarycentric(e.other, b);
      return true;
    }
  }
  return false;
}

bool StarUnfolding::build(const BaseDomain& domain, int anchor, int center, int towards)
{
  const std::vector<Triangle>& triangles = domain.mesh.triangles;
  triangles_ = &triangles;
  const auto at = [](const Triangle& t, int v) { return static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin()); };
  // The triangle across edge (center, w) from triangle `from`.
  const auto across = [&](int from, int w) {
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
      if (t != from && at(triangles[t], center) < 3 && at(triangles[t], w) < 3)
        return t;
    return -1;
  };
  int valence = 0;
  for (const Triangle& t : triangles)
    valence += at(t, center) < 3 ? 1 : 0;
  const Triangle& first = triangles[anchor];
  const int c = at(first, center);
  if (c > 2 || at(first, towards) > 2 || towards == center || valence < 3)
    return false;
  // In a triangle (center, r, s), counter-clockwise round the centre, the
  // next triangle is across spoke s and the previous one across spoke r.
  const bool edgeBehind = first[(c + 1) % 3] == towards; // the edge is spoke r of the anchor
  const std::array<Vec2, 3> anchorCorners{ BaseCharts::corner(0), BaseCharts::corner(1), BaseCharts::corner(2) };
  center_ = center;
  centre_ = anchorCorners[c];
  // The whole star both ways round from the anchor: each step reflects the
  // far corner across the shared spoke (two equilateral triangles make a
  // rhombus).
  const auto walk = [&](int triangle, std::array<Vec2, 3> corners, bool counterClockwise, int steps,
                      std::vector<Sector>& out) {
    out.push_back({ triangle, corners });
    for (int i = 0; i < steps; ++i)
    {
      const Triangle& tri = triangles[triangle];
      const int k = at(tri, center);
      const int shared = counterClockwise ? tri[(k + 2) % 3] : tri[(k + 1) % 3];
      const int far = counterClockwise ? tri[(k + 1) % 3] : tri[(k + 2) % 3];
      const int next = across(triangle, shared);
      if (next < 0)
        return false;
      const Triangle& nt = triangles[next];
      const Vec2 pc = corners[k], ps = corners[at(tri, shared)], pf = corners[at(tri, far)];
      std::array<Vec2, 3> nextCorners;
      for (int j = 0; j < 3; ++j)
        nextCorners[j] = nt[j] == center ? pc : nt[j] == shared ? ps : Vec2(pc + ps - pf);
      out.push_back({ next, nextCorners });
      triangle = next;
      corners = nextCorners;
    }
    return true;
  };
  ccw_.clear();
  cw_.clear();
  // From the edge on, counter-clockwise and clockwise, `valence` triangles each.
  if (!walk(anchor, anchorCorners, edgeBehind, valence - 1, edgeBehind ? ccw_ : cw_))
    return false;
  std::vector<Sector>& otherWay = edgeBehind ? cw_ : ccw_;
  std::vector<Sector> start;
  if (!walk(anchor, anchorCorners, !edgeBehind, 1, start))
    return false;
  if (!walk(start[1].triangle, start[1].corners, !edgeBehind, valence - 1, otherWay))
    return false;
  edge_ = anchorCorners[at(first, towards)] - centre_;
  return true;
}

bool StarUnfolding::locate(const std::vector<Sector>& chain, const BasePoint& point, Vec2& result, double& angle) const
{
  const std::array<double, 3> c = BaseCharts::barycentric(point);
  const Triangle& tri = (*triangles_)[point.triangle];
  for (std::size_t i = 0; i < chain.size(); ++i)
  {
    const Triangle& s = (*triangles_)[chain[i].triangle];
    Vec2 sum = Vec2::Zero();
    double weight = 0.0;
    bool holds = true;
    for (int j = 0; j < 3 && holds; ++j)
    {
      if (chain[i].triangle != point.triangle && std::abs(c[j]) < 1e-12)
        continue;
      const int k = static_cast<int>(std::find(s.begin(), s.end(), tri[j]) - s.begin());
      if (k > 2)
        holds = false;
      else
      {
        sum += c[j] * chain[i].corners[k];
        weight += c[j];
      }
    }
    if (!holds || weight == 0.0)
      continue;
    result = sum / weight;
    // Its angle from the edge: whole sectors, then from this sector's
    // spoke on the edge's side (the edge turned by i sixths of a turn).
    const double turn = (&chain == &ccw_ ? 1.0 : -1.0) * static_cast<double>(i) * kSixthTurn;
    const Vec2 spoke(std::cos(turn) * edge_.x() - std::sin(turn) * edge_.y(),
      std::sin(turn) * edge_.x() + std::cos(turn) * edge_.y());
    const Vec2 d = result - centre_;
    const double within = d.squaredNorm() > 0.0 ? std::abs(std::atan2(cross2(spoke, d), spoke.dot(d))) : 0.0;
    angle = static_cast<double>(i) * kSixthTurn + within;
    return true;
  }
  return false;
}

bool StarUnfolding::polar(const BasePoint& point, double& radius, double& angle) const
{
  Vec2 at;
  if (!triangles_ || !locate(ccw_, point, at, angle))
    return false;
  radius = (at - centre_).norm();
  return true;
}

Vec2 StarUnfolding::atPolar(double radius, double angle) const
{
  const Vec2 along = edge_.normalized();
  return centre_ + radius * Vec2(std::cos(angle) * along.x() - std::sin(angle) * along.y(),
                              std::sin(angle) * along.x() + std::cos(angle) * along.y());
}

double StarUnfolding::turn() const
{
  return static_cast<double>(ccw_.size()) * kSixthTurn;
}

bool StarUnfolding::position(const BasePoint& point, Vec2& result) const
{
  if (!triangles_)
    return false;
  Vec2 a, b;
  double angleA = 0.0, angleB = 0.0;
  const bool inA = locate(ccw_, point, a, angleA), inB = locate(cw_, point, b, angleB);
  if (!inA && !inB)
    return false;
  const bool useA = inA && (!inB || angleA <= angleB);
  // More than half a turn from the edge both ways (a valence above 6):
  // a second sheet, left out.
  if ((useA ? angleA : angleB) > 3.0 * kSixthTurn + 1e-12)
    return false;
  result = useA ? a : b;
  return true;
}

} // namespace cmp
