#pragma once
/// \file vtkCMPInputCheck.h
/// \brief Checks a surface (and optionally its base domain) the way every
///        filter of the pipeline does, and says what is wrong.

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

/// \brief Validates pipeline input and passes the surface through.
///
/// Port 0: the surface. It must be a closed, edge- and vertex-manifold,
/// consistently oriented, connected genus-0 triangle surface without NaN
/// coordinates or degenerate triangles. If it has a `FeatureId` array (or
/// `RequireLandmarks` is on) the landmarks must be valid: -1 or 0..F-1, each
/// feature exactly once (at most once with `AllowMissingLandmarks`).
/// Port 1 (optional): a base domain `L0`, which must be a closed, oriented
/// genus-0 triangulation whose `FeatureId`s are 0..F-1 with F equal to the
/// surface's landmark count.
/// On success the surface is passed through with field array `InputCheck`
/// = "ok"; on failure the filter reports the problem with `vtkErrorMacro`
/// (for example "open surface: 12 boundary edges ..., e.g. edge (3, 17)") and
/// produces no output.
class CMPFILTERS_EXPORT vtkCMPInputCheck : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPInputCheck* New();
  vtkTypeMacro(vtkCMPInputCheck, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Fail if the surface has no `FeatureId` array (default off).
  vtkSetMacro(RequireLandmarks, bool);
  /// \brief Fail if the surface has no `FeatureId` array (default off).
  vtkGetMacro(RequireLandmarks, bool);
  /// \brief Fail if the surface has no `FeatureId` array (default off).
  vtkBooleanMacro(RequireLandmarks, bool);

  /// \brief Accept features that are on no vertex (missing on this model,
  ///        up to the field array `FeatureCount`), for Missing Landmark
  ///        Placer to place (default off: every feature must be there).
  ///        Against a base domain every feature must be there regardless.
  vtkSetMacro(AllowMissingLandmarks, bool);
  /// \brief Accept features missing on this model.
  vtkGetMacro(AllowMissingLandmarks, bool);
  /// \brief Accept features missing on this model.
  vtkBooleanMacro(AllowMissingLandmarks, bool);

  /// \brief Connects the optional base domain to port 1.
  void SetBaseDomainConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// \brief The message of the last failed check ("" after a success).
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkCMPInputCheck();
  ~vtkCMPInputCheck() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPInputCheck(const vtkCMPInputCheck&) = delete;
  void operator=(const vtkCMPInputCheck&) = delete;

  bool RequireLandmarks = false;
  bool AllowMissingLandmarks = false;
  std::string LastError;
};
