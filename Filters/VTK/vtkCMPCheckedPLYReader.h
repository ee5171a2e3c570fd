#pragma once
/// \file vtkCMPCheckedPLYReader.h
/// \brief VTK's PLY reader behind the project's own PLY parser, so that a
///        hostile `.ply` gives an error message instead of crashing the
///        process (issue 26).

#include "CMPFiltersModule.h"

#include <vtkPLYReader.h>

/// \brief A `vtkPLYReader` whose files are read by the core's PLY reader.
///
/// VTK 9.2's PLY parser crashes or aborts on face indices out of range,
/// lines with too few values, a file without a face element, an ASCII file
/// whose last line has no newline, and damaged binary lists, including
/// files that are otherwise well formed. This reader never gives VTK's
/// parser the file: the core's `readPLY()` validates the header, the counts
/// against the file's size and every value and index, and the output is
/// made from what it read, as VTK's reader makes it: the points in the
/// file's order, the faces (fan-triangulated), point `Normals`, `RGB` or
/// `RGBA` and `TCoords`, and face `RGB`. A file it refuses fails with
/// `vtkErrorMacro`, naming the file and the line or byte, and the output is
/// empty; so does a PLY without faces (a point cloud, on which VTK 9.2
/// aborts). `DuplicatePointsForFaceTexture` and `FaceTextureTolerance` are
/// kept for ParaView's property panel and state files; face texture
/// coordinates (a face `texcoord` list) are not read. A string input
/// (`ReadFromInputString`) is VTK's to read.
///
/// The plugin makes this class ParaView's own reader of `.ply` files (the
/// `internal_sources` proxy `PLYReaderCore`).
class CMPFILTERS_EXPORT vtkCMPCheckedPLYReader : public vtkPLYReader
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPCheckedPLYReader* New();
  vtkTypeMacro(vtkCMPCheckedPLYReader, vtkPLYReader);

protected:
  vtkCMPCheckedPLYReader() = default;
  ~vtkCMPCheckedPLYReader() override = default;
  /// The core's reading, as VTK's output.
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkCMPCheckedPLYReader(const vtkCMPCheckedPLYReader&) = delete;
  void operator=(const vtkCMPCheckedPLYReader&) = delete;
};
