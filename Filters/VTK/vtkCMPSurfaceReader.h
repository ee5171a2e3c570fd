#pragma once
/// \file vtkCMPSurfaceReader.h
/// \brief Reads a triangle surface from OFF, OBJ, PLY, STL or VTP and welds
///        duplicated points.

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

/// \brief Reads a closed triangle surface for the consistent-parameterization
///        pipeline.
///
/// The format follows the file extension (`.off`, `.obj`, `.ply`, `.stl`,
/// `.vtp`). Points with identical coordinates are merged (STL and OBJ files
/// with texture seams duplicate them) and the file-to-surface point map is
/// kept as field array `FileToMeshPointId` so landmark files, which index the
/// file's points, still apply. OBJ texture coordinates are kept per triangle
/// corner in the 6-component cell array `CornerTCoords` (seams need no
/// duplicated points); when every point has a single texture coordinate they
/// are also set as point `TCoords`. Polygons are fan-triangulated. Field
/// array `WeldedPointCount` says how many points were merged.
/// Errors (missing, unreadable or garbage file, unknown extension, an STL
/// or VTP file the core's checks refuse before VTK's reader sees it) are
/// reported with `vtkErrorMacro` and produce no output (messages in
/// Documentation/filters/SurfaceReader.md).
class CMPFILTERS_EXPORT vtkCMPSurfaceReader : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPSurfaceReader* New();
  vtkTypeMacro(vtkCMPSurfaceReader, vtkPolyDataAlgorithm);
  /// \brief Prints the file name.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief The file to read.
  vtkSetStdStringFromCharMacro(FileName);
  /// \brief The file to read.
  vtkGetCharFromStdStringMacro(FileName);

  /// \brief True if the extension of `fileName` is one this reader handles.
  static bool CanReadExtension(const char* fileName);

protected:
  vtkCMPSurfaceReader();
  ~vtkCMPSurfaceReader() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPSurfaceReader(const vtkCMPSurfaceReader&) = delete;
  void operator=(const vtkCMPSurfaceReader&) = delete;

  std::string FileName;
};
