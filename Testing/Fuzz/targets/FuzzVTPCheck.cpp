// libFuzzer target for checkVTPFile, the check of a VTK XML PolyData file
// before vtkXMLPolyDataReader sees it. A finding is a crash, a hang or a
// memory error in the check itself, or a failure that does not name the
// file. (What VTK's reader does with a file the check passes is not fuzzed
// here: the core has no VTK.)
#include "FuzzInput.h"

#include <cmp/io/VTPCheck.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  const std::string path = cmp_fuzz::writeInput(bytes, size, "vtp");
  const cmp::Status status = cmp::checkVTPFile(path);
  if (!status.ok())
    cmp_fuzz::expectNamesFile(status.message(), path);
  return 0;
}
