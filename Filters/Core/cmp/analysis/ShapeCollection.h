#pragma once
/// \file ShapeCollection.h
/// \brief A collection of models that share one connectivity, possibly
///        spread over several processes: its global numbering and the input
///        checks every collection algorithm makes.

#include <cmp/numerics/Communicator.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vector>

namespace cmp
{

/// \brief The vertex positions of the models one process holds. Vertex k of
///        every model corresponds to vertex k of every other (they are
///        remeshes with one connectivity).
using ShapeList = std::vector<std::vector<Vec3>>;

/// \brief Where the models of this process sit in the collection.
///
/// Global model order is rank order, then local order: rank 0's models
/// come first. A rank may hold no model.
struct CollectionLayout
{
  int modelCount = 0;               ///< Models over all ranks.
  int vertexCount = 0;              ///< Vertices of every model.
  int firstModel = 0;               ///< Global index of this rank's first model.
  std::vector<int> modelsPerRank;   ///< How many models each rank holds.

  /// \brief The rank that holds global model `model`.
  int ownerOf(int model) const;
  /// \brief Global index of rank `rank`'s first model.
  int firstModelOf(int rank) const;
};

/// \brief Checks the models of every rank and numbers them. Collective.
///
/// \pre Every rank of `communicator` calls it, in the same order as its
///      other collective calls.
/// Fails (Status) on every rank, with the same message naming the global
/// model, when the collection has no model, when a model has no vertex or
/// another vertex count than the first model, or when a coordinate is not
/// finite.
Status describeCollection(const ShapeList& localModels, Communicator& communicator, CollectionLayout& out);

} // namespace cmp
