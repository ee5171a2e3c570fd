#pragma once
/// \file vtkCMPCheckedXMLPolyDataReader.h
/// \brief VTK's XML PolyData reader behind the project's checks, so that a
///        hostile `.vtp` gives an error message instead of crashing the
///        process (issue 26).

#include "CMPFiltersModule.h"

#include <vtkXMLPolyDataReader.h>

#include <ctime>
#include <string>

/// \brief `vtkXMLPolyDataReader` that checks the file before VTK parses it.
///
/// Before VTK's reader reads the file's information, the file goes through
/// the core's `checkVTPFile()` (with VTK's decompressors, so compressed
/// arrays are checked too): a file VTK 9.2 could crash on or exhaust memory
/// with (unknown array types, counts the data cannot hold, string counts
/// and last cell offsets past the data) fails with `vtkErrorMacro`, naming
/// the file and the line, and the output is empty. After reading, a cell
/// whose offsets are malformed or whose point ids are outside the points
/// fails the same way (VTK's reader passes those on, and drawing the cells
/// would read out of bounds). Every file VTK writes passes unchanged: the
/// output is `vtkXMLPolyDataReader`'s, with its array selection and time
/// properties.
///
/// The plugin makes this class ParaView's own reader of `.vtp` files (the
/// `internal_sources` proxy `XMLPolyDataReaderCore`, which *File > Open*
/// and `OpenDataFile()` use), so opening a damaged file in ParaView is an
/// error message, not a dead ParaView. The check reads the whole file once
/// more; it runs again only when the file name or the file's time changes.
class CMPFILTERS_EXPORT vtkCMPCheckedXMLPolyDataReader : public vtkXMLPolyDataReader
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPCheckedXMLPolyDataReader* New();
  vtkTypeMacro(vtkCMPCheckedXMLPolyDataReader, vtkXMLPolyDataReader);

protected:
  vtkCMPCheckedXMLPolyDataReader() = default;
  ~vtkCMPCheckedXMLPolyDataReader() override = default;
  /// The check, then VTK's reading of the file's information.
  int ReadXMLInformation() override;
  /// VTK's reading, then the cells' point ids.
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkCMPCheckedXMLPolyDataReader(const vtkCMPCheckedXMLPolyDataReader&) = delete;
  void operator=(const vtkCMPCheckedXMLPolyDataReader&) = delete;

  std::string CheckedFile;       ///< The file the last check was of...
  std::time_t CheckedTime = 0;   ///< ... its time then...
  std::string CheckFailure;      ///< ... and why it failed (empty: it passed).
};
