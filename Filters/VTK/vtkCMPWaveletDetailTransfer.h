#pragma once
/// \file vtkCMPWaveletDetailTransfer.h
/// \brief The coarse shape of one remeshed model with the details of
///        another, blended level by level in a Loop wavelet basis (paper
///        Section 3, Figure 13).

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <vector>

class vtkMultiProcessController;

/// \brief Detail transfer between two models of a collection remeshed with
///        one uniform semi-regular connectivity.
///
/// Both models' positions are analysed with a lifted Loop wavelet
/// transform into coarsest-level positions plus one block of details per
/// level. The coarsest level and every level's details are then blended
/// with the per-level weight of the detail model, and synthesised. The
/// default schedule keeps the coarse model's coarsest level and its details
/// up to `LastCoarseLevel` and takes the detail model's above it: the
/// paper's cow details on the horse's coarse shape. `DetailWeights`, when
/// given, sets the weight of every level instead (a scale-dependent morph).
///
/// Input: a collection of uniform remeshes (Semi-Regular Remesher output
/// with adaptive tolerance 0; a multiblock, possibly spread over MPI
/// ranks). Outputs (on rank 0 of a parallel run):
/// - port 0, the result at the finest level with the correspondence arrays,
///   point arrays `WaveletCoefficients` (the blended coefficients: coarsest
///   positions at the base vertices, level-l details at the vertices new at
///   level l), `CoarseModelCoefficients`, `DetailModelCoefficients` and
///   `DetailMagnitude` (length of the blended detail, 0 at base vertices),
///   field arrays `DetailWeights` (the schedule used) and `TransferSeconds`;
/// - port 1, a multiblock with the result's approximation at every level
///   0..J ("Level l"), for seeing what each scale contributes.
///
/// Paper §3 ("Transfer of Wavelet Details", Figure 13; core
/// `cmp::transferDetails()`); local detail frames and size scaling are
/// beyond the paper. Fails with `vtkErrorMacro` and no output when
/// `CoarseModel` or `DetailModel` names no model, the collection is not one
/// uniform remesh (adaptive, no `VertexLevel`, connectivities that differ),
/// `LastCoarseLevel` is out of range or above the remesh's finest level,
/// or `DetailWeights` has not one finite entry per level; messages in
/// Documentation/filters/WaveletDetailTransfer.md.
class CMPFILTERS_EXPORT vtkCMPWaveletDetailTransfer : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPWaveletDetailTransfer* New();
  vtkTypeMacro(vtkCMPWaveletDetailTransfer, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Index (block order over all ranks) of the model whose coarse
  ///        shape is kept (default 0).
  vtkSetMacro(CoarseModel, int);
  /// \brief Index of the model whose coarse shape is kept.
  vtkGetMacro(CoarseModel, int);
  /// \brief Index of the model whose details are transferred (default 1).
  vtkSetMacro(DetailModel, int);
  /// \brief Index of the model whose details are transferred.
  vtkGetMacro(DetailModel, int);

  /// \brief Without `DetailWeights`: the finest level whose details come
  ///        from the coarse model (default 2); the detail model gives every
  ///        level above. 0 puts all its details on the coarsest mesh.
  ///        Must be a remesh level (0 to 8) not above the remesh's finest
  ///        level; not clamped: a value out of range is reported when the
  ///        filter runs.
  vtkSetMacro(LastCoarseLevel, int);
  /// \brief The finest level whose details come from the coarse model.
  vtkGetMacro(LastCoarseLevel, int);

  /// \brief Weight of the detail model per level, J + 1 entries (entry 0
  ///        for the coarsest positions, entry l for the level-l details;
  ///        0 keeps the coarse model, 1 takes the detail model, others
  ///        blend or extrapolate). Empty (default): `LastCoarseLevel` decides.
  void SetDetailWeights(const std::vector<double>& weights);
  /// \brief Appends one level's weight (ParaView's repeatable property).
  void AddDetailWeight(double weight);
  /// \brief Removes every weight, so that `LastCoarseLevel` decides.
  void RemoveAllDetailWeights();
  /// \brief The per-level weights (empty when `LastCoarseLevel` decides).
  const std::vector<double>& GetDetailWeights() const { return this->DetailWeights; }

  /// \brief Express details in a frame of the surface they sit on (default
  ///        on), so that they follow the coarse shape they are put on;
  ///        off keeps them in world coordinates.
  vtkSetMacro(LocalFrames, bool);
  /// \brief Whether details are expressed in local frames.
  vtkGetMacro(LocalFrames, bool);
  /// \brief Whether details are expressed in local frames.
  vtkBooleanMacro(LocalFrames, bool);

  /// \brief Scale each model's details by the size of the blended coarse
  ///        shape over its own (default on), so that details moved onto a
  ///        smaller model shrink with it; off keeps their length.
  vtkSetMacro(ScaleDetailsToCoarseSize, bool);
  /// \brief Whether details follow the size of the coarse shape.
  vtkGetMacro(ScaleDetailsToCoarseSize, bool);
  /// \brief Whether details follow the size of the coarse shape.
  vtkBooleanMacro(ScaleDetailsToCoarseSize, bool);

  /// \brief The processes that together hold the collection (default: the
  ///        global controller; a vtkDummyController makes this process
  ///        work alone).
  void SetController(vtkMultiProcessController* controller);
  /// \brief The processes that together hold the collection.
  vtkMultiProcessController* GetController();

protected:
  vtkCMPWaveletDetailTransfer();
  ~vtkCMPWaveletDetailTransfer() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPWaveletDetailTransfer(const vtkCMPWaveletDetailTransfer&) = delete;
  void operator=(const vtkCMPWaveletDetailTransfer&) = delete;

  vtkSmartPointer<vtkMultiProcessController> Controller;
  int CoarseModel = 0;
  int DetailModel = 1;
  int LastCoarseLevel = 2;
  std::vector<double> DetailWeights;
  bool LocalFrames = true;
  bool ScaleDetailsToCoarseSize = true;
};
