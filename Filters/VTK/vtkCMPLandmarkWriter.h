#pragma once
/// \file vtkCMPLandmarkWriter.h
/// \brief Saves a surface's `FeatureId` landmarks as a landmark file.

#include "CMPFiltersModule.h"

#include <vtkWriter.h>

#include <string>

/// \brief Writes the landmarks of a surface (point array `FeatureId`: -1, or
///        the feature index at its landmark vertex) to a file that Landmarks
///        From File reads back: `.vts` (`id x y z`), `.csv` (`x,y,z`) or any
///        other extension (`lk id`), chosen by the file name.
///
/// Ids refer to the points of the surface's file: when the surface reader
/// welded points, its field array `FileToMeshPointId` maps them and the
/// file gets each vertex's first file point. A feature on no vertex (below
/// the field array `FeatureCount`, when there is one) could not be placed
/// on this model and is written as missing: `-1`, `lk -1` or
/// `nan,nan,nan`. Errors are reported with `vtkErrorMacro`, before
/// anything is written: no `FeatureId`, a feature on two vertices, a cell
/// that is not a triangle, no file name; and an unwritable file.
class CMPFILTERS_EXPORT vtkCMPLandmarkWriter : public vtkWriter
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPLandmarkWriter* New();
  vtkTypeMacro(vtkCMPLandmarkWriter, vtkWriter);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief The landmark file to write; its extension picks the format.
  vtkSetStdStringFromCharMacro(FileName);
  /// \brief The landmark file to write.
  vtkGetCharFromStdStringMacro(FileName);

protected:
  vtkCMPLandmarkWriter() = default;
  ~vtkCMPLandmarkWriter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

private:
  vtkCMPLandmarkWriter(const vtkCMPLandmarkWriter&) = delete;
  void operator=(const vtkCMPLandmarkWriter&) = delete;

  std::string FileName;
};
