#pragma once
/// \file VTPCheck.h
/// \brief A check of a VTK XML PolyData file (.vtp) before VTK's reader
///        sees it, without VTK.

#include <cmp/mesh/Status.h>

#include <cstddef>
#include <functional>
#include <string>

namespace cmp
{

/// \brief Decompresses one block of a compressed array: `compressor` is the
///        file's (`vtkZLibDataCompressor`, `vtkLZ4DataCompressor` or
///        `vtkLZMADataCompressor`); `raw` must receive exactly `rawSize`
///        bytes. Returns false if the block does not decompress to that.
using VTPDecompressor = std::function<bool(const std::string& compressor, const unsigned char* compressed,
  std::size_t compressedSize, unsigned char* raw, std::size_t rawSize)>;

/// \brief Refuses a `.vtp` file that VTK 9.2's `vtkXMLPolyDataReader` could
///        crash on or exhaust memory with; accepts every file VTK writes.
///
/// Checks, naming the file and the line of the offending tag:
/// - the XML is well formed as far as the reader relies on it: tags close in
///   order, attributes are quoted, the file does not end inside a tag;
/// - the root is `<VTKFile type="PolyData">` with a known `byte_order`,
///   `header_type` (UInt32, UInt64) and `compressor`;
/// - every `Piece` count (`NumberOfPoints`, `NumberOfPolys`, ...) and every
///   array's (`DataArray`, and `Array` for strings) `NumberOfTuples` and
///   `NumberOfComponents` is an integer (components at most 2^31 - 1, and
///   1 in a cell array's connectivity and offsets);
/// - every array has a type VTK knows (Int8 ... UInt64, Float32,
///   Float64, String, Bit) and a format (ascii, binary, appended);
/// - the values an array must hold (its `NumberOfTuples`, or the piece's
///   point or cell count for point, cell and offset arrays, times its
///   components; at least one byte per string) are present: as many ASCII
///   values; in inline base64 data, as many bytes, and a block header that
///   agrees with the bytes that follow; in appended data (raw or base64),
///   a header inside the appended section and as many bytes after it, the
///   section starting with `_` after blanks only. A compressed array must
///   not claim more than 1032 times its compressed size (deflate's limit,
///   also above LZ4's), or 65536 times for LZMA;
/// - where the data can be read without decompressing (ASCII, uncompressed
///   binary or appended): a string array holds exactly as many strings as
///   it declares (VTK writes past the end of its array otherwise), and a
///   cell array's last offset does not exceed the values its connectivity
///   holds (VTK allocates the connectivity by it).
///
/// The core has no zlib, LZ4 or LZMA: given `decompress` (the Surface Reader
/// passes VTK's own compressors), the string counts and last offsets of
/// compressed arrays are checked too, one block at a time, and a block that
/// does not decompress to the size its header claims fails the check.
/// Without it a crafted compressed file can still carry a string count or a
/// last offset that VTK trusts. Other values (for example connectivity ids)
/// are not checked: VTK's reader reports those.
Status checkVTPFile(const std::string& path, const VTPDecompressor& decompress = {});

} // namespace cmp
