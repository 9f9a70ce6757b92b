#pragma once
// Runs the marble binary as a user would and captures what it says.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "temp_dir.h"

namespace marble::test {

struct RunResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

inline RunResult runMarble(const std::string& args, const std::string& envPrefix = "") {
  const std::string cmd = envPrefix + " " + std::string(MARBLE_BINARY) + " " + args + " 2>&1";
  RunResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// A scratch folder for one test, removed when the test ends (tests/temp_dir.h).
inline TempDir tempDir(const std::string& name) { return TempDir(name); }

}  // namespace marble::test
