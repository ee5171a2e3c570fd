#pragma once
/// \file vtkCMPShapeBlend.h
/// \brief n-way affine blend of a consistently remeshed collection (paper
///        Section 3, Figure 14).

#include "CMPFiltersModule.h"

#include <vtkDataObjectAlgorithm.h>
#include <vtkSmartPointer.h>

class vtkMultiProcessController;

#include <vector>

/// \brief The shape sum_i w_i model_i of a collection of remeshes with one
///        connectivity, with one weight per model summing to one.
///
/// A weight may be negative or above one: the blend then extrapolates,
/// exaggerating the differences between models; the filter says so with a
/// warning and field array `Extrapolating`. Models are aligned first as
/// `Alignment` chooses (default rigid: rotations and translations), so that
/// shapes, not placements, are blended. Under `mpirun ... pvbatch` each
/// process blends the blocks it holds and the sums are combined.
///
/// Input: a vtkMultiBlockDataSet of remeshes (Semi-Regular Remesher
/// output), all with the same connectivity. Output (on rank 0 of a
/// parallel run): the blend with the shared triangles, the correspondence
/// arrays and cell arrays of the first model, field arrays `Extrapolating`
/// (0 or 1) and `Weights`.
///
/// Fails with `vtkErrorMacro` and no output when the models differ in
/// connectivity or have a non-finite coordinate (as for Mesh PCA), the
/// weights are not one finite number per model summing to one, or the
/// alignment fails; messages in Documentation/filters/ShapeBlend.md.
class CMPFILTERS_EXPORT vtkCMPShapeBlend : public vtkDataObjectAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPShapeBlend* New();
  vtkTypeMacro(vtkCMPShapeBlend, vtkDataObjectAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Sets the weights, one per model in block order.
  void SetWeights(const std::vector<double>& weights);
  /// \brief Appends one weight (ParaView's repeatable property).
  void AddWeight(double weight);
  /// \brief Removes every weight.
  void RemoveAllWeights();
  /// \brief The weights.
  const std::vector<double>& GetWeights() const { return this->Weights; }

  /// \brief Alignment before blending: 0 none, 1 rigid (default), 2 rigid
  ///        and equal volume, 3 rigid and unit centroid size.
  vtkSetClampMacro(Alignment, int, 0, 3);
  /// \brief Alignment before blending.
  vtkGetMacro(Alignment, int);

  /// \brief The processes that together hold the collection (default: the
  ///        global controller, i.e. every rank of `mpirun ... pvbatch`; a
  ///        vtkDummyController makes this process work alone).
  void SetController(vtkMultiProcessController* controller);
  /// \brief The processes that together hold the collection.
  vtkMultiProcessController* GetController();

protected:
  vtkCMPShapeBlend();
  ~vtkCMPShapeBlend() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPShapeBlend(const vtkCMPShapeBlend&) = delete;
  vtkSmartPointer<vtkMultiProcessController> Controller;
  void operator=(const vtkCMPShapeBlend&) = delete;

  std::vector<double> Weights;
  int Alignment = 1;
};
