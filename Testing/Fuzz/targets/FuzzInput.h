#pragma once
/// \file FuzzInput.h
/// \brief What every fuzz target shares: the core's readers take a path, so
///        each input is written to a file of this process first; and the
///        checks whose failure is a finding (a crash for libFuzzer).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace cmp_fuzz
{

/// Writes `size` bytes to a file of this process ending in `.extension`
/// (in $TMPDIR, else /tmp) and returns its path; the file is rewritten for
/// every input (so one extension per process) and removed at exit. Aborts if the file cannot be written: the harness, not the
/// input, is broken then.
inline std::string writeInput(const std::uint8_t* data, std::size_t size, const char* extension)
{
  static const std::string path = []
  {
    const char* folder = std::getenv("TMPDIR");
    return std::string(folder && *folder ? folder : "/tmp") + "/cmp-fuzz-" + std::to_string(getpid()) + "." +
      "input";
  }();
  const std::string file = path + "." + extension;
  static std::string written; // the one file of this process, removed at exit
  if (written.empty())
  {
    written = file;
    std::atexit([] { std::remove(written.c_str()); });
  }
  else if (written != file)
  {
    std::fprintf(stderr, "fuzz harness: one input file per process (%s, then %s)\n", written.c_str(), file.c_str());
    std::abort();
  }
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out || (size > 0 && std::fwrite(data, 1, size, out) != size) || std::fclose(out) != 0)
  {
    std::fprintf(stderr, "fuzz harness: cannot write %s\n", file.c_str());
    std::abort();
  }
  return file;
}

/// A finding that is not a memory error: prints what is wrong and aborts,
/// which libFuzzer reports as a crash and keeps the input of.
[[noreturn]] inline void fail(const std::string& what)
{
  std::fprintf(stderr, "fuzz target: %s\n", what.c_str());
  std::abort();
}

/// Every failure names the file it is about (issue 26: "every failure is a
/// message naming the file").
inline void expectNamesFile(const std::string& message, const std::string& path)
{
  if (message.empty())
    fail("a failure with an empty message");
  const std::string name = path.substr(path.find_last_of('/') + 1);
  if (message.find(name) == std::string::npos)
    fail("a failure that does not name the file: " + message);
}

} // namespace cmp_fuzz
