#pragma once
/// \file vtkCMPCheckedSTLReader.h
/// \brief VTK's STL reader behind the project's STL check, so that a
///        hostile `.stl` gives an error message instead of aborting the
///        process (issue 26).

#include "CMPFiltersModule.h"

#include <vtkSTLReader.h>

/// \brief `vtkSTLReader` that reads only files the core's `checkSTLFile()`
///        passes.
///
/// VTK 9.2's STL reader trusts a binary file's triangle count and aborts
/// the process when it cannot allocate that much. A file VTK would take for
/// binary must be exactly as long as its count says; otherwise it fails
/// with `vtkErrorMacro`, naming the file, and the output is empty. Files
/// that pass are read by `vtkSTLReader`, so the output and `ScalarTags` are
/// VTK's.
///
/// The plugin makes this class ParaView's own reader of `.stl` files (the
/// `internal_sources` proxy `stlreadercore`).
class CMPFILTERS_EXPORT vtkCMPCheckedSTLReader : public vtkSTLReader
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPCheckedSTLReader* New();
  vtkTypeMacro(vtkCMPCheckedSTLReader, vtkSTLReader);

protected:
  vtkCMPCheckedSTLReader() = default;
  ~vtkCMPCheckedSTLReader() override = default;
  /// The core's check, then VTK's reading.
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkCMPCheckedSTLReader(const vtkCMPCheckedSTLReader&) = delete;
  void operator=(const vtkCMPCheckedSTLReader&) = delete;
};
