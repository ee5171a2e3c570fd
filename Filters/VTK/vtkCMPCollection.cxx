#include "vtkCMPCollection.h"

#include "vtkCMPPolyDataBridge.h"

#include <vtkCompositeDataSet.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace cmp::bridge
{

namespace
{

std::string blockName(vtkDataObjectTreeIterator* it)
{
  vtkInformation* meta = it->HasCurrentMetaData() ? it->GetCurrentMetaData() : nullptr;
  return meta && meta->Has(vtkCompositeDataSet::NAME()) ? meta->Get(vtkCompositeDataSet::NAME()) : "";
}

vtkSmartPointer<vtkDataObjectTreeIterator> leavesOf(vtkMultiBlockDataSet* blocks)
{
  auto leaves = vtk::TakeSmartPointer(blocks->NewTreeIterator());
  leaves->SkipEmptyNodesOn();
  return leaves;
}

} // namespace

Status toLandmarkedCollection(const SurfaceCollection& collection, bool withBoundaries, LandmarkedCollection& out)
{
  out = LandmarkedCollection{};
  const std::size_t count = collection.surfaces.size();
  out.landmarks.resize(count);
  for (std::size_t m = 0; m < count; ++m)
  {
    out.meshes.push_back(std::make_unique<TriangleMesh>());
    const Status read = withBoundaries ? toCheckedSurfaceWithBoundaries(collection.surfaces[m], *out.meshes[m])
                                       : toCheckedSurface(collection.surfaces[m], *out.meshes[m]);
    if (!read.ok())
      return Status::error(collection.labels[m] + read.message());
    if (Status s = readLandmarks(collection.surfaces[m], out.landmarks[m], true); !s.ok())
      return Status::error(collection.labels[m] + s.message());
    out.surfaces.push_back(out.meshes[m].get());
  }
  // Without FeatureCount a model that misses the last features has fewer:
  // it has as many as the one with most. With it, the counts must agree.
  std::size_t featureCount = 0;
  for (const LandmarkList& list : out.landmarks)
    featureCount = std::max(featureCount, list.size());
  for (std::size_t m = 0; m < count; ++m)
  {
    if (out.landmarks[m].size() == featureCount)
      continue;
    if (featureCountOf(collection.surfaces[m]) >= 0)
      return Status::error(collection.labels[m] + "its landmark file has " + std::to_string(out.landmarks[m].size()) +
        " features but another model's has " + std::to_string(featureCount));
    out.landmarks[m].resize(featureCount, kMissingLandmark);
  }
  return {};
}

Status collectSurfaces(vtkDataObject* input, SurfaceCollection& out, bool allowEmpty)
{
  out = SurfaceCollection{};
  if (auto* surface = vtkPolyData::SafeDownCast(input))
  {
    out.surfaces.push_back(surface);
    out.labels.push_back(modelPrefix(surface));
    out.names.emplace_back();
    return {};
  }
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(input);
  if (!blocks)
    return Status::error(std::string("the input must be a vtkPolyData or a vtkMultiBlockDataSet of them (it is ") +
      (input ? input->GetClassName() : "missing") + ")");
  out.multiblock = true;
  auto leaves = leavesOf(blocks);
  int index = 0;
  for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem(), ++index)
  {
    const std::string name = blockName(leaves);
    const std::string label = "block " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')") + ": ";
    auto* surface = vtkPolyData::SafeDownCast(leaves->GetCurrentDataObject());
    if (!surface)
      return Status::error(
        label + "is a " + leaves->GetCurrentDataObject()->GetClassName() + ", not a vtkPolyData surface");
    out.surfaces.push_back(surface);
    out.labels.push_back(label);
    out.names.push_back(name);
  }
  if (out.surfaces.empty() && !allowEmpty)
    return Status::error("the input multiblock holds no surfaces");
  return {};
}

void matchOutputType(vtkDataObject* input, vtkInformationVector* outputVector, int port)
{
  const bool multiblock = vtkMultiBlockDataSet::SafeDownCast(input) != nullptr;
  vtkInformation* info = outputVector->GetInformationObject(port);
  vtkDataObject* output = vtkDataObject::GetData(info);
  if (multiblock && !vtkMultiBlockDataSet::SafeDownCast(output))
    info->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkMultiBlockDataSet>::New());
  else if (!multiblock && !vtkPolyData::SafeDownCast(output))
    info->Set(vtkDataObject::DATA_OBJECT(), vtkSmartPointer<vtkPolyData>::New());
}

void assembleOutput(vtkDataObject* input, vtkDataObject* output, const std::vector<vtkSmartPointer<vtkPolyData>>& results)
{
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(input);
  auto* outputBlocks = vtkMultiBlockDataSet::SafeDownCast(output);
  if (blocks && outputBlocks)
  {
    outputBlocks->CopyStructure(blocks); // same tree, names and other block metadata
    auto leaves = leavesOf(blocks);
    std::size_t m = 0;
    for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal() && m < results.size(); leaves->GoToNextItem())
      outputBlocks->SetDataSet(leaves, results[m++]);
  }
  else if (!results.empty() && output)
    output->ShallowCopy(results.front());
}

} // namespace cmp::bridge
