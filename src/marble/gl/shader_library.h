#pragma once
// GLSL sources: embedded at build time from shaders/ (file name -> text), with a tiny
// preprocessor for `#include "name.glsl"` that emits `#line` directives so compile errors
// point at the right file and line (file numbers are listed in the error message).
#include <map>
#include <string>
#include <vector>

namespace marble {

const std::map<std::string, std::string>& embeddedShaders();

class ShaderLibrary {
public:
  // Uses the embedded sources; if `sourceDir` is non-empty, files there win (hot reload in
  // development mode from the source tree's shaders/).
  explicit ShaderLibrary(std::string sourceDir = {});

  // Expands includes. `defines` are inserted after the #version line. Throws
  // std::runtime_error naming the file for a missing include.
  std::string assemble(const std::string& name, const std::vector<std::string>& defines = {}) const;

  // File names in include order for the last assemble() call, so "0(12)" in a driver
  // message can be mapped back to a file. A file read from the source directory is named by
  // its path there (what the user can open), an embedded one by its name.
  const std::vector<std::string>& lastFiles() const { return files_; }

  std::string source(const std::string& name) const;
  const std::string& sourceDir() const { return sourceDir_; }

private:
  std::string displayName(const std::string& name) const;
  bool exists(const std::string& name) const;
  void expand(const std::string& name, std::string& out, int depth) const;
  std::string sourceDir_;
  mutable std::vector<std::string> files_;
};

}  // namespace marble
