#pragma once
/// \file vtkCMPLandmarksFromFile.h
/// \brief Adds the `FeatureId` landmark array to a surface from a landmark file.

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

/// \brief Marks landmark vertices from a `.vts`, `.pinned`, plain id list or
///        `.csv` file as point array `FeatureId` (-1, or the feature index).
///
/// Ids in the file index the points of the mesh file; if the reader welded
/// points, its `FileToMeshPointId` field array maps them. CSV positions are
/// snapped to the nearest vertex. The landmarks are the paper's F feature
/// points (§2, "Basic Setup"; core `cmp::readLandmarkFile()`). A feature
/// the file marks missing (`-1`, or `nan,nan,nan` in a `.csv`) is on no
/// vertex; field array `FeatureCount` says how many features the file has,
/// and Missing Landmark Placer places the missing ones from the other
/// models of a collection.
/// Duplicates, out-of-range ids, malformed lines, positions that do not
/// match the surface and a count different from `ExpectedLandmarkCount`
/// (when >= 0) are reported with `vtkErrorMacro` and produce no output
/// (messages in Documentation/filters/LandmarksFromFile.md).
class CMPFILTERS_EXPORT vtkCMPLandmarksFromFile : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPLandmarksFromFile* New();
  vtkTypeMacro(vtkCMPLandmarksFromFile, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief The landmark file.
  vtkSetStdStringFromCharMacro(LandmarkFile);
  /// \brief The landmark file.
  vtkGetCharFromStdStringMacro(LandmarkFile);

  /// \brief Number of landmarks the file must hold; -1 (default) accepts any.
  vtkSetMacro(ExpectedLandmarkCount, int);
  /// \brief Number of landmarks the file must hold; -1 (default) accepts any.
  vtkGetMacro(ExpectedLandmarkCount, int);

protected:
  vtkCMPLandmarksFromFile() = default;
  ~vtkCMPLandmarksFromFile() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPLandmarksFromFile(const vtkCMPLandmarksFromFile&) = delete;
  void operator=(const vtkCMPLandmarksFromFile&) = delete;

  std::string LandmarkFile;
  int ExpectedLandmarkCount = -1;
};
