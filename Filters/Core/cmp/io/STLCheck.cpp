#include <cmp/io/STLCheck.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace cmp
{

bool mayBeBinarySTL(const std::string& head)
{
  if (head.empty())
    return true;
  std::size_t other = 0;
  for (char c : head)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u == 0)
      return true;
    if ((u < 32 || u > 126) && u != '\n' && u != '\r' && u != '\t')
      ++other;
  }
  return 50 * other >= head.size();
}

Status checkSTLFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Status::error("cannot read '" + path + "' as stl: cannot open it");
  char head[256] = {};
  in.read(head, sizeof(head));
  const std::size_t read = static_cast<std::size_t>(in.gcount());
  if (!mayBeBinarySTL(std::string(head, read)))
    return {};
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error)
    return Status::error("cannot read '" + path + "' as stl: " + error.message());
  if (read < 84)
    return Status::error("cannot read '" + path + "' as stl: a binary STL has at least 84 bytes, this file " +
      std::to_string(size));
  std::uint32_t count = 0;
  for (int b = 3; b >= 0; --b)
    count = (count << 8) | static_cast<unsigned char>(head[80 + b]);
  const std::uintmax_t expected = 84 + 50 * static_cast<std::uintmax_t>(count);
  if (size != expected)
    return Status::error("cannot read '" + path + "' as stl: the header announces " + std::to_string(count) +
      " triangles (" + std::to_string(expected) + " bytes) but the file has " + std::to_string(size) + " bytes");
  return {};
}

} // namespace cmp
