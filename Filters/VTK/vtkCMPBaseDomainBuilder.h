#pragma once
/// \file vtkCMPBaseDomainBuilder.h
/// \brief Makes the base domain `L0` from one landmarked surface.

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

/// \brief Builds the base domain `L0` by decimating a landmarked surface
///        until only its landmarks remain.
///
/// Input: a closed genus-0 triangle surface with point array `FeatureId`
/// (at least 4 landmarks). Output: `L0` as a `vtkPolyData` with one point per
/// landmark (point f is feature f, at the landmark's position, so `L0`
/// renders as a low-poly version of the surface), its triangles (2F-4 of
/// them), point array `FeatureId` and field arrays `MinimumAngle` (degrees),
/// `MeanShapeQuality` (1 = all equilateral) and `FoldingCollapses`.
/// Every step is a topology-preserving half-edge collapse, so the result is
/// always a valid genus-0 triangulation laid out like the surface.
///
/// A surface with boundary loops (beyond the paper) is accepted when each
/// loop passes through at least 3 landmarks: `L0` is then open, with as
/// many boundary loops, each made of exactly the landmarks on one of the
/// surface's loops, in the same cyclic order (`cmp::buildBaseDomain()`).
///
/// Paper §2 lets `L0` be given or "found automatically"; this decimation is
/// ours (core `cmp::buildBaseDomain()`). Fails with `vtkErrorMacro` and no
/// output when the surface or its landmarks fail the checks of Check
/// Inputs (a closed surface), when the model misses landmarks (a `-1` in
/// its file), with fewer than 4 landmarks on a closed surface, when an open
/// surface breaks the contract above (a boundary loop with fewer than 3
/// landmarks, a pinched boundary, or a surface that is not a sphere once
/// its loops are capped), or when the decimation gets stuck; messages in
/// Documentation/filters/BaseDomainBuilder.md.
class CMPFILTERS_EXPORT vtkCMPBaseDomainBuilder : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPBaseDomainBuilder* New();
  vtkTypeMacro(vtkCMPBaseDomainBuilder, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Weight of triangle shape against closeness to the surface when
  ///        choosing collapses (default 1). Higher favours rounder triangles.
  vtkSetClampMacro(ShapeWeight, double, 0.0, 100.0);
  /// \brief Weight of triangle shape against closeness to the surface.
  vtkGetMacro(ShapeWeight, double);

protected:
  vtkCMPBaseDomainBuilder() = default;
  ~vtkCMPBaseDomainBuilder() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPBaseDomainBuilder(const vtkCMPBaseDomainBuilder&) = delete;
  void operator=(const vtkCMPBaseDomainBuilder&) = delete;

  double ShapeWeight = 1.0;
};
