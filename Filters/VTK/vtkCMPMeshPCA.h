#pragma once
/// \file vtkCMPMeshPCA.h
/// \brief Principal mesh components of a consistently remeshed collection
///        (paper Section 3): alignment, mean, modes, coefficients, synthesis.

#include "CMPFiltersModule.h"

#include <vtkDataObjectAlgorithm.h>
#include <vtkSmartPointer.h>

class vtkMultiProcessController;

/// \brief The mean shape and principal modes of variation of a collection
///        of remeshes with one connectivity (Semi-Regular Remesher output).
///
/// The models are first aligned to their mean (generalised Procrustes:
/// rotations and translations, with the scaling `Alignment` chooses), then
/// the centred data is decomposed (Gram matrix of the models, never the
/// 3n x 3n covariance). Works on the blocks each process holds under
/// `mpirun ... pvbatch`, combining across ranks: the same mean and modes as
/// one process, to round-off.
///
/// Input: a vtkMultiBlockDataSet of remeshes (at least two), all with the
/// same points count and triangles; anything else is refused, naming the
/// block that differs. Outputs (all on rank 0 of a parallel run, empty on
/// the others, but output 4):
/// 0. *Mean*: the mean shape with the shared triangles; point arrays
///    `Mode0`, `Mode1`, ...: the displacement of one standard deviation
///    along each mode (Warp By Vector with scale factor 2 shows +2 sigma);
///    `FeatureId`, `BaseTriangle`, `BaseCoordinates` and the cell arrays of
///    the first model; field arrays `ModelCount`, `ModeCount`, `Variance`,
///    `ExplainedVarianceRatio` (one value per mode), `TotalVariance`,
///    `AlignmentIterations`, `AlignmentConverged`, `PCASeconds`.
/// 1. *Coefficients*: a vtkTable, one row per model: `Model` (block name),
///    `Index`, `Coefficient0`, `Coefficient1`, ...
/// 2. *Variances*: a vtkTable, one row per mode: `Mode`, `Variance`,
///    `StandardDeviation`, `ExplainedVarianceRatio`, `CumulativeRatio`.
/// 3. *Synthesis*: mean + sum_k f_k c_k mode_k, with c the coefficients of
///    model `SynthesisModel` (or, for -1, one standard deviation on mode
///    `SynthesisMode` and 0 elsewhere) and f_k = `SynthesisAllModesFactor`,
///    times `SynthesisModeFactor` on mode `SynthesisMode`.
/// 4. *Aligned*: the input collection, each model aligned (same blocks,
///    same arrays), on every rank for the blocks it holds.
///
/// Paper §3 ("Principal Mesh Components", Figures 10 and 11; core
/// `cmp::alignShapes()` and `cmp::computeMeshPCA()`). Fails with
/// `vtkErrorMacro` and no output when the collection has fewer than two
/// models, the models differ in connectivity (on one rank or between
/// ranks) or have a non-finite coordinate, the alignment fails (for example
/// a model enclosing no volume with equal-volume scaling), or
/// `SynthesisModel` or `SynthesisMode` names no model or kept mode; the
/// messages are listed in Documentation/filters/MeshPCA.md.
class CMPFILTERS_EXPORT vtkCMPMeshPCA : public vtkDataObjectAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPMeshPCA* New();
  vtkTypeMacro(vtkCMPMeshPCA, vtkDataObjectAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief How models are aligned before the analysis.
  enum AlignmentMode
  {
    NO_ALIGNMENT = 0,           ///< Positions as they are.
    RIGID = 1,                  ///< Rotations and translations only.
    RIGID_EQUAL_VOLUME = 2,     ///< And scaled to the mean enclosed volume (the paper's choice).
    RIGID_UNIT_CENTROID_SIZE = 3 ///< And scaled to centroid size 1.
  };

  /// \brief Alignment before the analysis (default RIGID_EQUAL_VOLUME).
  vtkSetClampMacro(Alignment, int, NO_ALIGNMENT, RIGID_UNIT_CENTROID_SIZE);
  /// \brief Alignment before the analysis.
  vtkGetMacro(Alignment, int);

  /// \brief Modes kept (default 5; -1: all). At most models - 1 exist;
  ///        modes of numerically zero variance are dropped.
  vtkSetMacro(NumberOfModes, int);
  /// \brief Modes kept.
  vtkGetMacro(NumberOfModes, int);

  /// \brief Model whose coefficients output 3 starts from (default -1: the
  ///        mean, with one standard deviation on `SynthesisMode`).
  vtkSetMacro(SynthesisModel, int);
  /// \brief Model whose coefficients output 3 starts from.
  vtkGetMacro(SynthesisModel, int);
  /// \brief Mode scaled by `SynthesisModeFactor` in output 3 (default 0; -1: none).
  vtkSetMacro(SynthesisMode, int);
  /// \brief Mode scaled by `SynthesisModeFactor` in output 3.
  vtkGetMacro(SynthesisMode, int);
  /// \brief Factor on mode `SynthesisMode` (default 3: the paper's "triple one mode").
  vtkSetMacro(SynthesisModeFactor, double);
  /// \brief Factor on mode `SynthesisMode`.
  vtkGetMacro(SynthesisModeFactor, double);
  /// \brief Factor on every mode (default 1; 2: the paper's "double all modes").
  vtkSetMacro(SynthesisAllModesFactor, double);
  /// \brief Factor on every mode.
  vtkGetMacro(SynthesisAllModesFactor, double);

  /// \brief The processes that together hold the collection (default: the
  ///        global controller, i.e. every rank of `mpirun ... pvbatch`; a
  ///        vtkDummyController makes this process work alone).
  void SetController(vtkMultiProcessController* controller);
  /// \brief The processes that together hold the collection.
  vtkMultiProcessController* GetController();

protected:
  vtkCMPMeshPCA();
  ~vtkCMPMeshPCA() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPMeshPCA(const vtkCMPMeshPCA&) = delete;
  vtkSmartPointer<vtkMultiProcessController> Controller;
  void operator=(const vtkCMPMeshPCA&) = delete;

  int Alignment = RIGID_EQUAL_VOLUME;
  int NumberOfModes = 5;
  int SynthesisModel = -1;
  int SynthesisMode = 0;
  double SynthesisModeFactor = 3.0;
  double SynthesisAllModesFactor = 1.0;
};
