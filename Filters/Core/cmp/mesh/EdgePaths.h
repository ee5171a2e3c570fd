#pragma once
/// \file EdgePaths.h
/// \brief Shortest paths along the edges of a triangle mesh (Dijkstra).

#include <cmp/mesh/TriangleMesh.h>

#include <limits>
#include <vector>

namespace cmp
{

/// \brief The edges of a mesh as adjacency lists with their lengths, built
///        once for many searches.
struct EdgeGraph
{
  std::vector<int> first;     ///< Per vertex, where its arcs start in `to`; one more entry at the end.
  std::vector<int> to;        ///< Arc heads, grouped by tail vertex.
  std::vector<double> length; ///< Arc lengths (the edges' Euclidean lengths).

  /// \brief Number of vertices.
  int vertexCount() const { return static_cast<int>(first.size()) - 1; }
};

/// \brief The edge graph of `mesh`: each edge once in each direction.
/// \pre The triangles' vertex ids are vertices of `mesh`.
EdgeGraph edgeGraph(const TriangleMesh& mesh);

/// \brief Shortest edge-path distances from the nearest of `sources` (0
///        there) to every vertex; infinite where the distance would exceed
///        `limit` or no path exists.
///
/// With `blocked` (one flag per vertex), a blocked vertex that is not a
/// source is reached but never passed through. With `parent`, each reached
/// vertex gets its predecessor on a shortest path (-1 at the sources and
/// at unreached vertices); `edgePath()` reads a path from it.
/// \pre `sources` are vertices of `graph`; `blocked`, if given, has one
///      entry per vertex.
std::vector<double> edgePathDistances(const EdgeGraph& graph, const std::vector<int>& sources,
  double limit = std::numeric_limits<double>::infinity(), std::vector<int>* parent = nullptr,
  const std::vector<char>* blocked = nullptr);

/// \brief The path from a source to `to` recorded by `edgePathDistances()`'s
///        `parent`, the source first; empty when `to` was not reached and is
///        not a source (a source gives the one-vertex path).
std::vector<int> edgePath(const std::vector<int>& parent, const std::vector<double>& distance, int to);

} // namespace cmp
