#include <cmp/io/TextParsing.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace cmp
{

Status readFileBytes(const std::string& path, std::string& bytes)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Status::error("cannot open '" + path + "'");
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad())
    return Status::error("cannot read '" + path + "'");
  return {};
}

Status readTextFile(const std::string& path, std::string& text)
{
  if (Status s = readFileBytes(path, text); !s.ok())
    return s;
  if (text.find('\0') != std::string::npos)
    return Status::error("'" + path + "' is not a text file");
  return {};
}

bool LineReader::next(std::string& line, bool skipBlank)
{
  while (pos_ < text_.size())
  {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line.assign(text_, pos_, end - pos_);
    pos_ = end + 1;
    ++number_;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos)
      line.resize(hash);
    if (!skipBlank || line.find_first_not_of(" \t\r") != std::string::npos)
      return true;
  }
  return false;
}

int parseNumbers(const std::string& line, double* values, int max, char separator, std::string* rest)
{
  const char* p = line.c_str();
  int count = 0;
  while (count < max)
  {
    while (*p == separator || *p == ' ' || *p == '\t')
      ++p;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p)
      break;
    values[count++] = v;
    p = end;
  }
  if (rest)
    *rest = trailingText(p, separator);
  return count;
}

std::string trailingText(const char* from, char separator)
{
  const auto blank = [separator](char c) { return c == ' ' || c == '\t' || c == '\r' || c == separator; };
  while (*from && blank(*from))
    ++from;
  std::string text(from);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
    text.pop_back();
  return text;
}

std::string fileLine(const std::string& path, int line)
{
  return path + ":" + std::to_string(line) + ": ";
}

} // namespace cmp
