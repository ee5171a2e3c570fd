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
/// VTK layer can turn it into `vtkErrorMacro` and a false return.
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
    : message_(message.empty() ? std::string("unknown error") : std::move(message))
  {
  }
  std::string message_;
};

} // namespace cmp
