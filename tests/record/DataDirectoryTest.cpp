// engine/record/DataDirectory: where a user's files go, by the override,
// then XDG, then HOME, then the working folder.

#include "engine/record/DataDirectory.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace hemiroll::record {
namespace {

TEST(DataDirectoryTest, FollowsTheOverrideThenXdgThenHome) {
  const char* savedHome = std::getenv("HOME");
  const std::string keepHome = savedHome ? savedHome : "";
  const char* saved = std::getenv("HEMIROLL_DATA_DIR");
  const std::string keep = saved ? saved : "";
  setenv("HEMIROLL_DATA_DIR", "/some/where", 1);
  EXPECT_EQ(dataDirectory(), std::filesystem::path("/some/where"));
  unsetenv("HEMIROLL_DATA_DIR");
  setenv("XDG_DATA_HOME", "/xdg", 1);
  EXPECT_EQ(dataDirectory(), std::filesystem::path("/xdg/hemiroll"));
  unsetenv("XDG_DATA_HOME");
  setenv("HOME", "/home/p", 1);
  EXPECT_EQ(dataDirectory(), std::filesystem::path("/home/p/.local/share/hemiroll"));
  unsetenv("HOME");
  EXPECT_EQ(dataDirectory(), std::filesystem::path(".hemiroll"));
  if (saved) setenv("HEMIROLL_DATA_DIR", keep.c_str(), 1);
  if (savedHome) setenv("HOME", keepHome.c_str(), 1);
}

}  // namespace
}  // namespace hemiroll::record
