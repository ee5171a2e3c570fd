#include "TestData.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cmp::test
{

std::string sharedDataDir()
{
  return CMP_SHARED_DATA_DIR;
}

std::string tempPath(const std::string& name)
{
  const std::filesystem::path dir =
    std::filesystem::temp_directory_path() / ("cmp_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string writeTempFile(const std::string& name, const std::string& text)
{
  const std::string path = tempPath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

} // namespace cmp::test
