#include <cmp/mesh/EdgePaths.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

namespace cmp
{

EdgeGraph edgeGraph(const TriangleMesh& mesh)
{
  std::vector<std::pair<int, int>> arcs;
  arcs.reserve(6 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
    {
      arcs.emplace_back(t[k], t[(k + 1) % 3]);
      arcs.emplace_back(t[(k + 1) % 3], t[k]);
    }
  std::sort(arcs.begin(), arcs.end());
  arcs.erase(std::unique(arcs.begin(), arcs.end()), arcs.end());
  EdgeGraph graph;
  graph.first.assign(mesh.vertexCount() + 1, 0);
  graph.to.reserve(arcs.size());
  graph.length.reserve(arcs.size());
  for (const auto& [a, b] : arcs)
  {
    ++graph.first[a + 1];
    graph.to.push_back(b);
    graph.length.push_back((mesh.points[a] - mesh.points[b]).norm());
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
    graph.first[v + 1] += graph.first[v];
  return graph;
}

std::vector<double> edgePathDistances(const EdgeGraph& graph, const std::vector<int>& sources, double limit,
  std::vector<int>* parent, const std::vector<char>* blocked)
{
  const int n = graph.vertexCount();
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  if (parent)
    parent->assign(n, -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  std::vector<char> passable; // with `blocked`: may be passed through
  for (int v : sources)
  {
    distance[v] = 0.0;
    queue.emplace(0.0, v);
  }
  if (blocked)
  {
    passable.resize(n);
    for (int v = 0; v < n; ++v)
      passable[v] = !(*blocked)[v];
    for (int v : sources)
      passable[v] = 1;
  }
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v] || (blocked && !passable[v]))
      continue;
    for (int k = graph.first[v]; k < graph.first[v + 1]; ++k)
    {
      const double next = d + graph.length[k];
      const int u = graph.to[k];
      if (next < distance[u] && next <= limit)
      {
        distance[u] = next;
        if (parent)
          (*parent)[u] = v;
        queue.emplace(next, u);
      }
    }
  }
  return distance;
}

std::vector<int> edgePath(const std::vector<int>& parent, const std::vector<double>& distance, int to)
{
  std::vector<int> path;
  if (!std::isfinite(distance[to]))
    return path;
  for (int v = to; v >= 0; v = parent[v])
    path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

} // namespace cmp
