#include <cmp/mesh/TriangleGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmp
{

void TriangleGrid::build(const std::vector<std::array<Vec2, 3>>& corners)
{
  corners_ = &corners;
  size_ = std::max(1, static_cast<int>(std::sqrt(0.5 * static_cast<double>(corners.size()))));
  start_.assign(static_cast<std::size_t>(size_) * size_ + 1, 0);
  forEachCell([&](int, int cell) { ++start_[cell + 1]; });
  for (std::size_t i = 1; i < start_.size(); ++i)
    start_[i] += start_[i - 1];
  entries_.resize(start_.back());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  forEachCell([&](int i, int cell) { entries_[fill[cell]++] = i; });
}

bool TriangleGrid::locate(const Vec2& q, int& best, std::array<double, 3>& weights) const
{
  best = -1;
  double bestScore = -std::numeric_limits<double>::infinity();
  const int cx = cellOf(q.x()), cy = cellOf(q.y());
  for (int radius = 0; radius < size_; ++radius)
  {
    for (int x = std::max(0, cx - radius); x <= std::min(size_ - 1, cx + radius); ++x)
      for (int y = std::max(0, cy - radius); y <= std::min(size_ - 1, cy + radius); ++y)
      {
        if (std::max(std::abs(x - cx), std::abs(y - cy)) != radius)
          continue;
        const int cell = x * size_ + y;
        for (int e = start_[cell]; e < start_[cell + 1]; ++e)
          score(entries_[e], q, bestScore, best, weights);
      }
    if (bestScore > -1e-9)
      return true;
  }
  return best >= 0;
}

int TriangleGrid::cellOf(double u) const
{
  return std::clamp(static_cast<int>(u * size_), 0, size_ - 1);
}

template <class Visit>
void TriangleGrid::forEachCell(Visit visit) const
{
  for (int i = 0; i < static_cast<int>(corners_->size()); ++i)
  {
    const auto& c = (*corners_)[i];
    const int x0 = cellOf(std::min({ c[0].x(), c[1].x(), c[2].x() }));
    const int x1 = cellOf(std::max({ c[0].x(), c[1].x(), c[2].x() }));
    const int y0 = cellOf(std::min({ c[0].y(), c[1].y(), c[2].y() }));
    const int y1 = cellOf(std::max({ c[0].y(), c[1].y(), c[2].y() }));
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y)
        visit(i, x * size_ + y);
  }
}

void TriangleGrid::score(int i, const Vec2& q, double& bestScore, int& best, std::array<double, 3>& weights) const
{
  const auto& c = (*corners_)[i];
  const Vec2 e1 = c[1] - c[0], e2 = c[2] - c[0], d = q - c[0];
  const double area = cross2(e1, e2);
  if (!(area > 0.0))
    return; // crowded to nothing: its neighbours cover the point too
  const double w1 = cross2(d, e2) / area;
  const double w2 = cross2(e1, d) / area;
  const double w0 = 1.0 - w1 - w2;
  const double s = std::min({ w0, w1, w2 });
  if (s > bestScore)
  {
    bestScore = s;
    best = i;
    weights = { w0, w1, w2 };
  }
}

} // namespace cmp
