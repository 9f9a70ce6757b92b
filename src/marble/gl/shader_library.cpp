#include "marble/gl/shader_library.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "marble/render/shader_constants.h"

namespace marble {

ShaderLibrary::ShaderLibrary(std::string sourceDir) : sourceDir_(std::move(sourceDir)) {}

std::string ShaderLibrary::source(const std::string& name) const {
  if (!sourceDir_.empty()) {
    std::ifstream in(std::filesystem::path(sourceDir_) / name);
    if (in) {
      std::stringstream ss;
      ss << in.rdbuf();
      return ss.str();
    }
  }
  const auto& table = embeddedShaders();
  auto it = table.find(name);
  if (it == table.end()) throw std::runtime_error("shader '" + name + "' not found");
  return it->second;
}

bool ShaderLibrary::exists(const std::string& name) const {
  std::error_code ec;
  if (!sourceDir_.empty() && std::filesystem::is_regular_file(std::filesystem::path(sourceDir_) / name, ec)) return true;
  return embeddedShaders().count(name) > 0;
}

std::string ShaderLibrary::displayName(const std::string& name) const {
  if (sourceDir_.empty()) return name;
  const auto path = std::filesystem::path(sourceDir_) / name;
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) ? path.string() : name;
}

std::string ShaderLibrary::assemble(const std::string& name, const std::vector<std::string>& defines) const {
  files_.clear();
  std::string body;
  expand(name, body, 0);
  // The top file starts with #version; the defines go right after it.
  const auto eol = body.find('\n');
  if (body.rfind("#version", 0) != 0 || eol == std::string::npos)
    throw std::runtime_error(displayName(name) + ":1: error: a shader must start with #version");
  std::string head = body.substr(0, eol + 1);
  for (const auto& d : shader::sharedShaderDefines()) head += "#define " + d + "\n";
  for (const auto& d : defines) head += "#define " + d + "\n";
  head += "#line 2 0\n";
  return head + body.substr(eol + 1);
}

void ShaderLibrary::expand(const std::string& name, std::string& out, int depth) const {
  if (depth > 16) throw std::runtime_error("shader include depth exceeded at '" + name + "'");
  const int fileIndex = static_cast<int>(files_.size());
  files_.push_back(displayName(name));
  if (depth > 0) out += "#line 1 " + std::to_string(fileIndex) + "\n";
  std::istringstream in(source(name));
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.rfind("#include", 0) == 0) {
      const auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a)
        throw std::runtime_error(files_[fileIndex] + ":" + std::to_string(lineNo) + ": error: malformed #include");
      const std::string included = line.substr(a + 1, b - a - 1);
      if (!exists(included))
        throw std::runtime_error(files_[fileIndex] + ":" + std::to_string(lineNo) + ": error: #include \"" + included +
                                 "\": no such shader");
      expand(included, out, depth + 1);
      // Back in this file: GLSL's "#line L F" sets the number of the *next* line.
      out += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
      continue;
    }
    out += line;
    out += '\n';
  }
}

}  // namespace marble
