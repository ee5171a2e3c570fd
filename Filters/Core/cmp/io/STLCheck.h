#pragma once
/// \file STLCheck.h
/// \brief A check of an STL file before VTK's reader sees it, without VTK.

#include <cmp/mesh/Status.h>

#include <string>

namespace cmp
{

/// \brief True if VTK's STL reader may take a file starting with `head`
///        (its first 256 bytes, or all of a shorter file) for binary.
///
/// VTK looks at the first bytes (kwsys DetectFileType) and calls the file
/// binary when a share of them are not text, whatever the header says. This
/// errs towards binary (any NUL byte, or 2% of other bytes), so that every
/// file VTK reads as binary gets `checkSTLFile`'s size check.
bool mayBeBinarySTL(const std::string& head);

/// \brief Refuses an STL file that VTK 9.2's `vtkSTLReader` would take for
///        binary and whose triangle count disagrees with its size.
///
/// vtkSTLReader trusts a binary STL's count and aborts the process when it
/// cannot allocate that much. A binary STL is an 80-byte header, a 4-byte
/// little-endian count and 50 bytes per triangle; the file must be exactly
/// that long. An ASCII STL has no count (VTK's parser grows with what it
/// reads) and passes. Fails, naming the file, on a missing or unreadable
/// file too.
Status checkSTLFile(const std::string& path);

} // namespace cmp
