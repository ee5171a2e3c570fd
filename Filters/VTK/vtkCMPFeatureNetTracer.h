#pragma once
/// \file vtkCMPFeatureNetTracer.h
/// \brief Traces on a landmarked surface a patch layout topologically
///        equivalent to the base domain (paper Sections 2.1 and 2.2).

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

/// \brief For every base-domain edge, traces a curve between its two
///        landmarks on the surface, such that the net of curves is
///        topologically equivalent to the base domain `L0`.
///
/// Input 0: a closed genus-0 triangle surface with point array `FeatureId`
/// (a multiblock of such surfaces is traced block by block against the same
/// `L0`). Input 1: the base domain `L0` (point array `FeatureId`, its F
/// vertices matching the surface's F landmarks).
///
/// Output 0: the surface, with edges split only where curves needed room, so
/// every curve runs along mesh edges; every input point array is carried
/// through (interpolated at new points; `FeatureId` is -1 there), cell
/// arrays are inherited by the pieces of split triangles (`CornerTCoords` is
/// interpolated at their new corners), and cell array `PatchId` holds the
/// `L0` triangle each triangle belongs to.
/// Output 1: the net as polylines, one cell per `L0` edge, with cell arrays
/// `BaseEdgeId`, `FeatureIdA` and `FeatureIdB` (the landmarks at its start
/// and end). Both carry field arrays `NetLength`, `NetLengthPerSqrtArea`,
/// `NetValid` (1 when the independent layout check passes), `RetracedCurves`,
/// `PenalisedCurves` and `SplitEdges`.
///
/// Paper §2.1 and §2.2 (core `cmp::traceFeatureNet()`). Fails with
/// `vtkErrorMacro` and no output when `L0` is not connected, the surface,
/// its landmarks or `L0` fail the checks of Check Inputs (for example `L0`
/// with another vertex count than the surface's landmarks) or the tracing
/// fails; warns, with `NetValid` 0, when the net fails the layout check.
/// The messages are listed in Documentation/filters/FeatureNetTracer.md.
class CMPFILTERS_EXPORT vtkCMPFeatureNetTracer : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPFeatureNetTracer* New();
  vtkTypeMacro(vtkCMPFeatureNetTracer, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Connects the base domain `L0` to input port 1.
  void SetBaseDomainConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// \brief How strongly curves follow the harmonic parameterization rather
  ///        than the shortest path (default 2; 0 = restricted shortest paths).
  vtkSetClampMacro(ParameterizationWeight, double, 0.0, 1000.0);
  /// \brief How strongly curves follow the harmonic parameterization.
  vtkGetMacro(ParameterizationWeight, double);

  /// \brief Postpone curves that the paper's swirl detector flags (default on).
  vtkSetMacro(DetectSwirls, bool);
  /// \brief Postpone curves that the paper's swirl detector flags.
  vtkGetMacro(DetectSwirls, bool);
  /// \brief Postpone curves that the paper's swirl detector flags.
  vtkBooleanMacro(DetectSwirls, bool);

protected:
  vtkCMPFeatureNetTracer();
  ~vtkCMPFeatureNetTracer() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPFeatureNetTracer(const vtkCMPFeatureNetTracer&) = delete;
  void operator=(const vtkCMPFeatureNetTracer&) = delete;

  double ParameterizationWeight = 2.0;
  bool DetectSwirls = true;
};
