#pragma once
/// \file vtkCMPCheckedOBJReader.h
/// \brief VTK's OBJ reader behind the project's own OBJ parser, so that a
///        damaged `.obj` gives an error message instead of crashing the
///        process (issue 26).

#include "CMPFiltersModule.h"

#include <vtkOBJReader.h>

/// \brief `vtkOBJReader` that reads only files the core's OBJ reader
///        accepts.
///
/// VTK 9.2's OBJ reader crashes on some damaged files (seeded mutations of
/// a good file, `python.PluginHostileFiles`). This reader first parses the
/// file with the core's `readOBJ()`, which checks every `v`, `vt` and `f`
/// record and every index of faces, lines and points (vertices, texture
/// coordinates, normals); a file it refuses fails with `vtkErrorMacro`,
/// naming the file and the line, and the output is empty. A file it accepts
/// is then read by `vtkOBJReader`, so the output (polygons, normals,
/// texture coordinates, groups) is VTK's; VTK's own messages are said again
/// with the file's name.
///
/// The plugin makes this class ParaView's own reader of `.obj` files (the
/// `sources` proxy `objreader`, *Wavefront OBJ Reader*).
class CMPFILTERS_EXPORT vtkCMPCheckedOBJReader : public vtkOBJReader
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPCheckedOBJReader* New();
  vtkTypeMacro(vtkCMPCheckedOBJReader, vtkOBJReader);

protected:
  vtkCMPCheckedOBJReader() = default;
  ~vtkCMPCheckedOBJReader() override = default;
  /// The core's parse, then VTK's reading.
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkCMPCheckedOBJReader(const vtkCMPCheckedOBJReader&) = delete;
  void operator=(const vtkCMPCheckedOBJReader&) = delete;
};
