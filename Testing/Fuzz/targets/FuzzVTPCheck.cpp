// libFuzzer target for checkVTPFile, the check of a VTK XML PolyData file
// before vtkXMLPolyDataReader sees it, with a zlib decompressor as the
// Surface Reader gives it (VTK's compressors are zlib, LZ4 and LZMA; zlib is
// the one VTK and ParaView write by default). A finding is a crash, a hang
// or a memory error in the check itself, or a failure that does not name
// the file. (What VTK's reader does with a file the check passes is not
// fuzzed here: the core has no VTK.)
#include "FuzzInput.h"

#include <cmp/io/VTPCheck.h>

#include <zlib.h>

#include <string>

namespace
{

bool decompress(const std::string& compressor, const unsigned char* compressed, std::size_t compressedSize,
  unsigned char* raw, std::size_t rawSize)
{
  if (compressor != "vtkZLibDataCompressor")
    return false;
  uLongf size = static_cast<uLongf>(rawSize);
  return uncompress(raw, &size, compressed, static_cast<uLong>(compressedSize)) == Z_OK && size == rawSize;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  const std::string path = cmp_fuzz::writeInput(bytes, size, "vtp");
  const cmp::Status status = cmp::checkVTPFile(path, decompress);
  if (!status.ok())
    cmp_fuzz::expectNamesFile(status.message(), path);
  return 0;
}
