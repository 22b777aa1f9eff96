#pragma once
// A fresh directory for one test's files, removed with everything in it.

#include <filesystem>
#include <string>
#include <string_view>

namespace hemiroll::test {

class TempDirectory {
 public:
  TempDirectory();
  ~TempDirectory();
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Writes `content` (bytes as they are) to `name` inside; returns the full path.
  std::string write(const std::string& name, std::string_view content) const;
  // A file's bytes ("" when it cannot be read): outputs of the program under test.
  static std::string read(const std::filesystem::path& file);

 private:
  std::filesystem::path path_;
};

}  // namespace hemiroll::test
