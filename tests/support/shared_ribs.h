// The conformance RIB files of ../shared/ribs, beside the project and not part of it: the tests
// that render them skip, saying so, where that folder is absent.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace darc::test {

// `folder` of ../shared/ribs ("aqsis", "realworld").
std::filesystem::path shared_ribs(const std::string& folder);

}  // namespace darc::test

// Skips the calling test, with a message, when `folder` of ../shared/ribs is absent. (A macro:
// GTEST_SKIP returns from the test body.)
#define SKIP_WITHOUT_SHARED_RIBS(folder)                                 \
  if (!std::filesystem::is_directory(::darc::test::shared_ribs(folder))) \
  GTEST_SKIP() << "shared RIBs not found at " << ::darc::test::shared_ribs(folder) << ": conformance skipped"
