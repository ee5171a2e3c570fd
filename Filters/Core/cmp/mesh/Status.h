#pragma once
/// \file Status.h
/// \brief Success or a message saying what went wrong, for core functions
///        that read or validate user input.

#include <string>
#include <utility>

namespace cmp
{

/// \brief Either success (empty message) or a human-readable error.
///
/// Core functions report bad input through this instead of throwing, so the
/// VTK layer can turn it into `vtkErrorMacro` and a false return. Messages
/// quote words of damaged files: a byte that is neither valid UTF-8 nor a
/// printable character (nor a newline or tab) is written as `\xNN`, so a
/// message is always valid UTF-8 text (Python, ParaView's output window).
class Status
{
public:
  /// \brief Success.
  Status() = default;
  /// \brief An error with its message.
  static Status error(std::string message) { return Status(std::move(message)); }
  /// \brief True on success.
  bool ok() const { return message_.empty(); }
  /// \brief The error message (empty on success).
  const std::string& message() const { return message_; }

private:
  explicit Status(std::string message)
    : message_(message.empty() ? std::string("unknown error") : printable(message))
  {
  }
  static std::string printable(const std::string& text)
  {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();)
    {
      const auto c = static_cast<unsigned char>(text[i]);
      // The length of a well-formed UTF-8 sequence starting here (0: none).
      std::size_t length = 0;
      if (c >= 0x20 && c < 0x7F)
        length = 1;
      else if (c == '\n' || c == '\t')
        length = 1;
      else if (c >= 0xC2 && c <= 0xF4)
      {
        const std::size_t need = c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
        length = need;
        for (std::size_t k = 1; k < need; ++k)
          if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80)
            length = 0;
        // No overlong forms, surrogates or code points above U+10FFFF.
        const auto second = length > 0 ? static_cast<unsigned char>(text[i + 1]) : 0;
        if ((c == 0xE0 && second < 0xA0) || (c == 0xED && second >= 0xA0) || (c == 0xF0 && second < 0x90) ||
          (c == 0xF4 && second >= 0x90))
          length = 0;
      }
      if (length > 0)
      {
        out.append(text, i, length);
        i += length;
      }
      else
      {
        out += "\\x";
        out += hex[c >> 4];
        out += hex[c & 15];
        ++i;
      }
    }
    return out;
  }
  std::string message_;
};

} // namespace cmp
