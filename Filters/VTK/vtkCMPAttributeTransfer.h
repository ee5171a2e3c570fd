#pragma once
/// \file vtkCMPAttributeTransfer.h
/// \brief Carries point data and texture coordinates from one parameterized
///        model to others through the shared base domain (paper Section 3).

#include "CMPFiltersModule.h"

#include <vtkDataObjectAlgorithm.h>

/// \brief Samples a source model's attributes at every point of one or
///        more target models, through the correspondence the base domain
///        defines: a target point at base location x gets the source's
///        values at the source's point at x.
///
/// Source and targets may be at any resolution: each is either a Net
/// Straightener output (the original surface, parameterized) or a
/// Semi-Regular Remesher output (a remesh, at any level). Both carry the
/// point arrays `BaseTriangle`/`BaseCoordinates`, the cell array `PatchId`
/// and `FeatureId`, which is all the filter reads to relate them.
///
/// Input 0: the target, a vtkPolyData or a vtkMultiBlockDataSet of them
/// (the output keeps the block structure). Input 1: the source vtkPolyData.
/// Input 2: the base domain `L0` both were parameterized over.
///
/// Output: each target with the source's point arrays added (replacing
/// target arrays of the same name; `FeatureId`, `BaseTriangle` and
/// `BaseCoordinates` stay the target's), floating-point arrays interpolated
/// and others copied from the nearest source point. If the source has
/// per-corner texture coordinates (cell array `CornerTCoords`, as the
/// surface reader makes for an OBJ with texture seams), every target corner
/// gets its own, read from the source triangle under the target triangle
/// (cell array `CornerTCoords`), and the point array `TCoords` is set as
/// the active texture coordinates. Field arrays: `TransferredArrays`,
/// `SeamPointsAdded`, `TransferSeconds`.
///
/// Paper §3 ("Transfer of Textures"); per-corner texture coordinates and
/// seam splitting are beyond the paper. Fails with `vtkErrorMacro` and an
/// empty output when the source or `L0` is not connected, `L0` is invalid,
/// the source or a target is not a surface parameterized over that `L0`
/// (the checks of Check Inputs, missing or inconsistent `BaseTriangle`,
/// `BaseCoordinates` or `PatchId`, a layout not equivalent to `L0`), or a
/// target point cannot be located on the source; the message says which
/// input. The messages are listed in Documentation/filters/AttributeTransfer.md.
class CMPFILTERS_EXPORT vtkCMPAttributeTransfer : public vtkDataObjectAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPAttributeTransfer* New();
  vtkTypeMacro(vtkCMPAttributeTransfer, vtkDataObjectAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Connects the model whose attributes are carried over to input 1.
  void SetSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  /// \brief Connects the base domain `L0` to input 2.
  void SetBaseDomainConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }

  /// \brief With per-corner source texture coordinates: duplicate each
  ///        target point whose corners read different texture coordinates
  ///        (it lies on a texture seam of the source), so that the point
  ///        array `TCoords` is exact and the texture renders without
  ///        smearing (default on). The point array `UnsplitPointId` then
  ///        gives each point's id in the target. Off keeps the target's
  ///        points and cells exactly (a remesh keeps the collection's
  ///        connectivity); `TCoords` then holds, at a seam point, the value
  ///        of one of its corners.
  vtkSetMacro(SplitTextureSeams, bool);
  /// \brief Duplicate target points on texture seams.
  vtkGetMacro(SplitTextureSeams, bool);
  /// \brief Duplicate target points on texture seams.
  vtkBooleanMacro(SplitTextureSeams, bool);

protected:
  vtkCMPAttributeTransfer();
  ~vtkCMPAttributeTransfer() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPAttributeTransfer(const vtkCMPAttributeTransfer&) = delete;
  void operator=(const vtkCMPAttributeTransfer&) = delete;

  bool SplitTextureSeams = true;
};
