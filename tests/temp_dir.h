#pragma once
// The one scratch folder type of the test suite: a fresh folder under the system's temporary
// folder, removed with everything in it when the test that made it ends — passed, failed or
// stopped by an ASSERT — so runs leave nothing behind and no run finds an earlier run's files.
//
// mkdtemp makes the name unique (`marble-test-NAME-XXXXXX`; the X's are mkdtemp's pattern), so
// parallel test processes and recycled process ids never share a folder.
//
// A temporary TempDir would remove its folder at the end of the expression that made it, so the
// conversions and `/` are deleted on temporaries: `fs::path p = tempDir("x")` or
// `tempDir("x") / "out"` do not compile; hold the TempDir in a named variable.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace marble::test {

class TempDir {
public:
  explicit TempDir(const std::string& name = "scratch") {
    std::string pattern = (std::filesystem::temp_directory_path() / ("marble-test-" + name + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) ADD_FAILURE() << "mkdtemp failed for " << pattern;
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;  // a test that removed it itself, or a folder left read-only: never throw here
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const& { return path_; }
  const std::filesystem::path& path() const&& = delete;
  operator const std::filesystem::path&() const& { return path_; }
  operator const std::filesystem::path&() const&& = delete;
  std::filesystem::path operator/(const std::filesystem::path& rest) const& { return path_ / rest; }
  std::filesystem::path operator/(const std::filesystem::path& rest) const&& = delete;
  std::string string() const { return path_.string(); }

  // Writes bytes to NAME in the folder and returns its path.
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    const auto p = path_ / name;
    std::ofstream out(p, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p;
  }

private:
  std::filesystem::path path_;
};

}  // namespace marble::test
