#include <cmp/mesh/Subdivision.h>

#include <algorithm>
#include <cstdint>

namespace cmp
{
namespace
{

TriangleMesh subdivideOnce(const TriangleMesh& mesh)
{
  // Number every undirected edge once by sorting its halfedge keys.
  const int corners = 3 * mesh.triangleCount();
  std::vector<std::pair<std::uint64_t, int>> keys(corners);
  for (int h = 0; h < corners; ++h)
  {
    const auto a = static_cast<std::uint64_t>(mesh.triangles[h / 3][h % 3]);
    const auto b = static_cast<std::uint64_t>(mesh.triangles[h / 3][(h % 3 + 1) % 3]);
    keys[h] = { (std::min(a, b) << 32) | std::max(a, b), h };
  }
  std::sort(keys.begin(), keys.end());
  TriangleMesh out;
  out.points = mesh.points;
  std::vector<int> midpointOf(corners, -1);
  for (int i = 0; i < corners; ++i)
  {
    if (i == 0 || keys[i].first != keys[i - 1].first)
    {
      const int a = static_cast<int>(keys[i].first >> 32);
      const int b = static_cast<int>(keys[i].first & 0xffffffffu);
      out.points.push_back(0.5 * (mesh.points[a] + mesh.points[b]));
    }
    midpointOf[keys[i].second] = out.vertexCount() - 1;
  }
  out.triangles.reserve(4 * mesh.triangles.size());
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    const int m0 = midpointOf[3 * t], m1 = midpointOf[3 * t + 1], m2 = midpointOf[3 * t + 2];
    out.triangles.push_back({ tri[0], m0, m2 });
    out.triangles.push_back({ m0, tri[1], m1 });
    out.triangles.push_back({ m2, m1, tri[2] });
    out.triangles.push_back({ m0, m1, m2 });
  }
  return out;
}

} // namespace

TriangleMesh subdivideMidpoint(const TriangleMesh& mesh, int levels)
{
  TriangleMesh result = mesh;
  for (int i = 0; i < levels; ++i)
    result = subdivideOnce(result);
  return result;
}

} // namespace cmp
