#pragma once
/// \file vtkCMPCollection.h
/// \brief A collection of surfaces given as one vtkPolyData or as the
///        leaves of a vtkMultiBlockDataSet, and an output of the same shape;
///        shared by the filters that take collections (private header).

#include <cmp/io/Landmarks.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkDataObject;
class vtkInformationVector;
class vtkPolyData;

namespace cmp::bridge
{

/// \brief The surfaces of one input, in traversal order.
struct SurfaceCollection
{
  std::vector<vtkPolyData*> surfaces; ///< Non-empty leaves (or the input itself).
  /// \brief Prefix naming each surface in messages: "block 2 ('387'): "
  ///        for a multiblock leaf, "387.off: " for a single surface read
  ///        from a file (its `SourceFile` field array), "" otherwise.
  std::vector<std::string> labels;
  /// \brief Block name of each surface ("" if none).
  std::vector<std::string> names;
  bool multiblock = false; ///< Whether the input was a multiblock.
};

/// \brief Lists the surfaces of `input`: a vtkPolyData, or every non-empty
///        leaf of a vtkMultiBlockDataSet (each must be a vtkPolyData). With
///        `allowEmpty`, a multiblock without leaves is accepted (a rank of a
///        parallel run may hold none).
Status collectSurfaces(vtkDataObject* input, SurfaceCollection& out, bool allowEmpty = false);

/// \brief The surfaces of a collection as the core takes them: each
///        checked (closed, or with boundary loops given `withBoundaries`)
///        and its landmarks (`FeatureId`, missing features allowed).
struct LandmarkedCollection
{
  std::vector<std::unique_ptr<TriangleMesh>> meshes;
  std::vector<const TriangleMesh*> surfaces; ///< The meshes, for the core's entries.
  std::vector<LandmarkList> landmarks;
};

/// \brief Reads `collection`'s surfaces and landmarks, every list as long
///        as the longest (a file without `FeatureCount` that misses its last
///        features has fewer: they are missing). Fails (Status, the message
///        led by the surface's label) on the first surface or landmark list
///        that does not fit, and when a file's `FeatureCount` differs from
///        another's.
Status toLandmarkedCollection(const SurfaceCollection& collection, bool withBoundaries, LandmarkedCollection& out);

/// \brief Makes output `port` of an algorithm the same kind of object as
///        `input` (vtkMultiBlockDataSet or vtkPolyData). For RequestDataObject.
void matchOutputType(vtkDataObject* input, vtkInformationVector* outputVector, int port);

/// \brief Fills `output` (same kind as `input`) with one result per
///        surface of `input`, keeping a multiblock's structure and names.
void assembleOutput(vtkDataObject* input, vtkDataObject* output, const std::vector<vtkSmartPointer<vtkPolyData>>& results);

} // namespace cmp::bridge
