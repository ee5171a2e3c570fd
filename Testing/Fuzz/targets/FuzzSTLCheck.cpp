// libFuzzer target for checkSTLFile, the check of an STL file before VTK's
// reader sees it. A finding is a failure that does not name the file, or a
// file the check passes that VTK would read as binary with a count its size
// disagrees with.
#include "FuzzInput.h"

#include <cmp/io/STLCheck.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  const std::string path = cmp_fuzz::writeInput(bytes, size, "stl");
  const cmp::Status status = cmp::checkSTLFile(path);
  if (!status.ok())
  {
    cmp_fuzz::expectNamesFile(status.message(), path);
    return 0;
  }
  const std::string text(reinterpret_cast<const char*>(bytes), size);
  if (cmp::mayBeBinarySTL(text.substr(0, 256)))
  {
    if (size < 84)
      cmp_fuzz::fail("a binary STL shorter than its header passed");
    std::uint64_t count = 0;
    for (int b = 3; b >= 0; --b)
      count = (count << 8) | bytes[80 + b];
    if (size != 84 + 50 * count)
      cmp_fuzz::fail("a binary STL whose count disagrees with its size passed");
  }
  return 0;
}
