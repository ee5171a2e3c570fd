#include <cmp/map/BaseCharts.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cmp
{

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

} // namespace cmp
