#include "marble/gl/program.h"

#include <regex>
#include <sstream>

namespace marble::gl {
namespace {

// Driver logs say "0:12(5): error ..." (Mesa) or "0(12) : error ..." (NVIDIA), where the
// first number is the #line file index set by ShaderLibrary; map it back to the file name, in
// the compilers' usual "file:line: message" form.
std::vector<std::string> mapLog(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\))");
  static const std::regex nv(R"(^(\d+)\((\d+)\))");
  std::istringstream in(log);
  std::string line;
  std::vector<std::string> out;
  while (std::getline(in, line)) {
    std::smatch m;
    const bool isMesa = std::regex_search(line, m, mesa);
    if (isMesa || std::regex_search(line, m, nv)) {
      const size_t idx = std::stoul(m[1]);
      const std::string file = idx < files.size() ? files[idx] : "shader" + m[1].str();
      std::string rest = line.substr(static_cast<size_t>(m[0].length()));
      rest.erase(0, rest.find_first_not_of(" :"));
      line = file + ":" + m[2].str() + ": " + rest;
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos) out.push_back(line);
  }
  return out;
}

// A marble error is one line: the first error the compiler gave (the others usually follow
// from it), and how many more lines the log had.
std::string oneLine(const std::vector<std::string>& lines, const std::string& fallback) {
  if (lines.empty()) return fallback;
  size_t first = 0;
  for (size_t i = 0; i < lines.size(); ++i)
    if (lines[i].find("error") != std::string::npos) {
      first = i;
      break;
    }
  std::string s = lines[first];
  if (lines.size() > 1)
    s += " (" + std::to_string(lines.size() - 1) + " more compiler message" + (lines.size() > 2 ? "s" : "") + ")";
  return s;
}

// The program's KHR_debug label, which debuggers and draw_state_check.h's reports show: its files
// and the variant's defines ("fullscreen.vert.glsl + post.frag.glsl [MODE 1, ...]").
void labelProgram(GLuint program, const std::vector<ShaderStageSource>& stages, const std::vector<std::string>& defines) {
  std::string label;
  for (const auto& st : stages) label += (label.empty() ? "" : " + ") + st.file;
  for (size_t i = 0; i < defines.size(); ++i) label += (i == 0 ? " [" : ", ") + defines[i];
  if (!defines.empty()) label += "]";
  GLint maxLength = 256;
  glGetIntegerv(GL_MAX_LABEL_LENGTH, &maxLength);
  if (label.size() >= static_cast<size_t>(maxLength)) label.resize(static_cast<size_t>(maxLength) - 1);
  glObjectLabel(GL_PROGRAM, program, static_cast<GLsizei>(label.size()), label.c_str());
}

}  // namespace

Program::Program(const ShaderLibrary& library, const std::vector<ShaderStageSource>& stages,
                 const std::vector<std::string>& defines)
    : program_(ProgramId::create()) {
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const auto& st : stages) {
    std::string text;
    try {
      text = library.assemble(st.file, defines);
    } catch (const std::exception& e) {
      cleanup();
      throw ShaderError(e.what());
    }
    const auto files = library.lastFiles();
    GLuint s = glCreateShader(st.stage);
    shaders.push_back(s);
    const char* src = text.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
      std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
      glGetShaderInfoLog(s, len, nullptr, log.data());
      cleanup();
      throw ShaderError(oneLine(mapLog(log.c_str(), files), st.file + ": shader compile failed (no log)"));
    }
    glAttachShader(program_.id(), s);
  }
  glLinkProgram(program_.id());
  cleanup();
  GLint ok = 0;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program_.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetProgramInfoLog(program_.id(), len, nullptr, log.data());
    std::string names;
    for (const auto& st : stages) names += (names.empty() ? "" : " + ") + st.file;
    throw ShaderError(names + ": shader link failed: " + oneLine(mapLog(log.c_str(), {}), "(no log)"));
  }
  labelProgram(program_.id(), stages, defines);
}

GLint Program::location(const char* name) const {
  auto it = locations_.find(std::string_view(name));
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(program_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

std::vector<UniformSlot> lookUpUniforms(GLuint program, std::span<const char* const> names) {
  std::vector<UniformSlot> slots(names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    if (!names[i]) continue;
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, names[i]);
    if (index == GL_INVALID_INDEX) continue;
    const GLenum props[] = {GL_LOCATION, GL_TYPE};
    GLint values[2] = {-1, 0};
    glGetProgramResourceiv(program, GL_UNIFORM, index, 2, props, 2, nullptr, values);
    slots[i] = {values[0], static_cast<GLenum>(values[1])};
  }
  return slots;
}

const std::vector<UniformSlot>& Program::uniformTable(std::span<const char* const> names) const {
  if (tableNames_ != names.data() || table_.size() != names.size()) {
    table_ = lookUpUniforms(program_.id(), names);
    tableNames_ = names.data();
  }
  return table_;
}

}  // namespace marble::gl
