#pragma once
/// \file TestData.h
/// \brief What the core and filter tests share: the location of the shared
///        real data and scratch files. No VTK, no core dependency.

#include <string>

namespace cmp::test
{

/// \brief The shared data folder (`CMP_SHARED_DATA_DIR`, "" when not configured).
std::string sharedDataDir();

/// \brief A path in a fresh per-process scratch folder.
std::string tempPath(const std::string& name);

/// \brief Writes `text` to tempPath(name) and returns the path.
std::string writeTempFile(const std::string& name, const std::string& text);

} // namespace cmp::test

/// Skips the current test when the shared data is absent (a developer
/// machine without ../shared); CI always has it.
#define CMP_REQUIRE_SHARED_DATA()                                                                                     \
  do                                                                                                                   \
  {                                                                                                                    \
    if (cmp::test::sharedDataDir().empty())                                                                           \
      GTEST_SKIP() << "CMP_SHARED_DATA_DIR is not set";                                                               \
  } while (0)
