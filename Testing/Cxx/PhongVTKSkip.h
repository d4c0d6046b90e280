/**
 * PHONGVTK_SKIP() << "why": GTEST_SKIP, except where every prerequisite must be present (the
 * environment variable PHONGVTK_NO_SKIPS set and not "0", as the test command sets it on
 * ParaView's flavour, where the set-up installs everything): there a missing prerequisite fails
 * the test instead of leaving the run green.
 */
#ifndef PhongVTKSkip_h
#define PhongVTKSkip_h

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

namespace phongvtk_test
{
inline bool NoSkips()
{
  const char* value = std::getenv("PHONGVTK_NO_SKIPS");
  return value && *value && std::strcmp(value, "0") != 0;
}
}

#define PHONGVTK_SKIP()                                                                            \
  return ::testing::internal::AssertHelper(::phongvtk_test::NoSkips()                              \
             ? ::testing::TestPartResult::kFatalFailure                                            \
             : ::testing::TestPartResult::kSkip,                                                   \
           __FILE__, __LINE__,                                                                     \
           ::phongvtk_test::NoSkips() ? "a prerequisite is missing where none may be "             \
                                        "(PHONGVTK_NO_SKIPS is set)"                               \
                                      : "") = ::testing::Message()

#endif
