#pragma once
/// \file TextParsing.h
/// \brief Line-oriented helpers shared by the core's text file parsers.

#include <cmp/mesh/Status.h>

#include <string>

namespace cmp
{

/// \brief Reads a whole file as bytes; a missing or unreadable file is an error.
Status readFileBytes(const std::string& path, std::string& bytes);

/// \brief Reads a whole text file; a missing, unreadable or binary file is an error.
Status readTextFile(const std::string& path, std::string& text);

/// \brief Iterates over the lines of a text, stripping `#` comments and
///        counting line numbers for error messages.
class LineReader
{
public:
  /// \brief Reads from `text`, which must outlive the reader.
  explicit LineReader(const std::string& text)
    : text_(text)
  {
  }
  /// \brief Next line (comment removed); skips blank lines when asked.
  ///        Returns false at the end of the text.
  bool next(std::string& line, bool skipBlank = true);
  /// \brief 1-based number of the line last returned.
  int number() const { return number_; }
  /// \brief Byte offset just past the line last returned (its line break
  ///        included), so `text.size() - offset()` bytes remain, or one less.
  std::size_t offset() const { return pos_; }

private:
  const std::string& text_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

/// \brief Parses up to `max` numbers separated by blanks or `separator` from
///        the start of `line`; returns how many were read. With `rest`, sets
///        it to what follows the last number read, blanks and separators
///        skipped (empty when nothing does).
int parseNumbers(const std::string& line, double* values, int max, char separator = ' ', std::string* rest = nullptr);

/// \brief `text` from `from` on, without leading and trailing blanks (spaces,
///        tabs, a CR) and leading `separator`s: empty if nothing else is there.
std::string trailingText(const char* from, char separator = ' ');

/// \brief "path:line: ", the prefix of a parse error message.
std::string fileLine(const std::string& path, int line);

} // namespace cmp
