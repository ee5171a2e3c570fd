#include <cmp/analysis/ShapeCollection.h>

#include <numeric>
#include <string>

namespace cmp
{
namespace
{

/// The first problem of this rank's models, compared with the vertex count
/// of global model 0.
Status checkLocalModels(const ShapeList& localModels, int firstModel, int vertexCount)
{
  if (vertexCount == 0)
    return Status::error("model 0 has no vertex");
  for (std::size_t i = 0; i < localModels.size(); ++i)
  {
    const std::vector<Vec3>& model = localModels[i];
    const std::string name = "model " + std::to_string(firstModel + static_cast<int>(i));
    if (model.size() != static_cast<std::size_t>(vertexCount))
    {
      return Status::error(name + " has " + std::to_string(model.size()) + " vertices but model 0 has " +
        std::to_string(vertexCount) + "; every model must have the same connectivity");
    }
    for (std::size_t v = 0; v < model.size(); ++v)
    {
      if (!model[v].allFinite())
        return Status::error(name + ", vertex " + std::to_string(v) + ": coordinate is not a finite number");
    }
  }
  return Status();
}

} // namespace

int CollectionLayout::ownerOf(int model) const
{
  int first = 0;
  for (std::size_t rank = 0; rank < modelsPerRank.size(); ++rank)
  {
    first += modelsPerRank[rank];
    if (model < first)
      return static_cast<int>(rank);
  }
  return -1;
}

int CollectionLayout::firstModelOf(int rank) const
{
  return std::accumulate(modelsPerRank.begin(), modelsPerRank.begin() + rank, 0);
}

Status describeCollection(const ShapeList& localModels, Communicator& communicator, CollectionLayout& out)
{
  out = CollectionLayout();
  out.modelsPerRank = communicator.allGather(static_cast<int>(localModels.size()));
  out.modelCount = std::accumulate(out.modelsPerRank.begin(), out.modelsPerRank.end(), 0);
  if (out.modelCount == 0)
    return Status::error("the collection has no model");
  out.firstModel = out.firstModelOf(communicator.rank());

  // Every rank learns the vertex count of global model 0 from its owner.
  const int localCount = localModels.empty() ? -1 : static_cast<int>(localModels.front().size());
  const std::vector<int> firstCounts = communicator.allGather(localCount);
  out.vertexCount = firstCounts[out.ownerOf(0)];
  return agreeOnStatus(checkLocalModels(localModels, out.firstModel, out.vertexCount), communicator);
}

} // namespace cmp
