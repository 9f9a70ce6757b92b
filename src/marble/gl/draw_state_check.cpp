#include "marble/gl/draw_state_check.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

#include "marble/gl/debug_output.h"

namespace marble::gl {
namespace {

enum class Components { Float, Int, Uint };

// What a GLSL sampler type reads: the texture target (and its binding's query), the component
// type it returns, whether it compares against a reference (a shadow sampler).
struct SamplerKind {
  GLenum target = 0;
  GLenum binding = 0;
  Components components = Components::Float;
  bool shadow = false;
  const char* glslName = "";
};

// Every sampler type of GLSL 4.50; 0 target for anything else (images, plain uniforms).
SamplerKind samplerKind(GLenum type) {
  using C = Components;
  switch (type) {
    case GL_SAMPLER_1D: return {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, C::Float, false, "sampler1D"};
    case GL_SAMPLER_2D: return {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D, C::Float, false, "sampler2D"};
    case GL_SAMPLER_3D: return {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D, C::Float, false, "sampler3D"};
    case GL_SAMPLER_CUBE: return {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP, C::Float, false, "samplerCube"};
    case GL_SAMPLER_1D_ARRAY: return {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY, C::Float, false, "sampler1DArray"};
    case GL_SAMPLER_2D_ARRAY: return {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY, C::Float, false, "sampler2DArray"};
    case GL_SAMPLER_CUBE_MAP_ARRAY:
      return {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY, C::Float, false, "samplerCubeArray"};
    case GL_SAMPLER_2D_RECT: return {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE, C::Float, false, "sampler2DRect"};
    case GL_SAMPLER_BUFFER: return {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER, C::Float, false, "samplerBuffer"};
    case GL_SAMPLER_2D_MULTISAMPLE:
      return {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE, C::Float, false, "sampler2DMS"};
    case GL_SAMPLER_2D_MULTISAMPLE_ARRAY:
      return {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY, C::Float, false, "sampler2DMSArray"};
    case GL_SAMPLER_1D_SHADOW: return {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, C::Float, true, "sampler1DShadow"};
    case GL_SAMPLER_2D_SHADOW: return {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D, C::Float, true, "sampler2DShadow"};
    case GL_SAMPLER_CUBE_SHADOW: return {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP, C::Float, true, "samplerCubeShadow"};
    case GL_SAMPLER_1D_ARRAY_SHADOW:
      return {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY, C::Float, true, "sampler1DArrayShadow"};
    case GL_SAMPLER_2D_ARRAY_SHADOW:
      return {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY, C::Float, true, "sampler2DArrayShadow"};
    case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW:
      return {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY, C::Float, true, "samplerCubeArrayShadow"};
    case GL_SAMPLER_2D_RECT_SHADOW:
      return {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE, C::Float, true, "sampler2DRectShadow"};
    case GL_INT_SAMPLER_1D: return {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, C::Int, false, "isampler1D"};
    case GL_INT_SAMPLER_2D: return {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D, C::Int, false, "isampler2D"};
    case GL_INT_SAMPLER_3D: return {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D, C::Int, false, "isampler3D"};
    case GL_INT_SAMPLER_CUBE: return {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP, C::Int, false, "isamplerCube"};
    case GL_INT_SAMPLER_1D_ARRAY: return {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY, C::Int, false, "isampler1DArray"};
    case GL_INT_SAMPLER_2D_ARRAY: return {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY, C::Int, false, "isampler2DArray"};
    case GL_INT_SAMPLER_2D_RECT: return {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE, C::Int, false, "isampler2DRect"};
    case GL_INT_SAMPLER_BUFFER: return {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER, C::Int, false, "isamplerBuffer"};
    case GL_UNSIGNED_INT_SAMPLER_1D: return {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, C::Uint, false, "usampler1D"};
    case GL_UNSIGNED_INT_SAMPLER_2D: return {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D, C::Uint, false, "usampler2D"};
    case GL_UNSIGNED_INT_SAMPLER_3D: return {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D, C::Uint, false, "usampler3D"};
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
      return {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP, C::Uint, false, "usamplerCube"};
    case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY:
      return {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY, C::Uint, false, "usampler1DArray"};
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
      return {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY, C::Uint, false, "usampler2DArray"};
    case GL_UNSIGNED_INT_SAMPLER_2D_RECT:
      return {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE, C::Uint, false, "usampler2DRect"};
    case GL_UNSIGNED_INT_SAMPLER_BUFFER:
      return {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER, C::Uint, false, "usamplerBuffer"};
    default: return {};
  }
}

const char* targetName(GLenum target) {
  switch (target) {
    case GL_TEXTURE_1D: return "GL_TEXTURE_1D";
    case GL_TEXTURE_2D: return "GL_TEXTURE_2D";
    case GL_TEXTURE_3D: return "GL_TEXTURE_3D";
    case GL_TEXTURE_CUBE_MAP: return "GL_TEXTURE_CUBE_MAP";
    case GL_TEXTURE_1D_ARRAY: return "GL_TEXTURE_1D_ARRAY";
    case GL_TEXTURE_2D_ARRAY: return "GL_TEXTURE_2D_ARRAY";
    case GL_TEXTURE_CUBE_MAP_ARRAY: return "GL_TEXTURE_CUBE_MAP_ARRAY";
    case GL_TEXTURE_RECTANGLE: return "GL_TEXTURE_RECTANGLE";
    case GL_TEXTURE_BUFFER: return "GL_TEXTURE_BUFFER";
    case GL_TEXTURE_2D_MULTISAMPLE: return "GL_TEXTURE_2D_MULTISAMPLE";
    default: return "GL_TEXTURE_2D_MULTISAMPLE_ARRAY";
  }
}

// One element of an active sampler uniform (an array has one per element).
struct SamplerUniform {
  std::string name;
  GLint location = -1;
  SamplerKind kind;
};

struct ProgramSamplers {
  std::string label;  // the program's object label, or "program N"
  std::vector<SamplerUniform> samplers;
};

std::unordered_map<GLuint, ProgramSamplers>& programCache() {
  static std::unordered_map<GLuint, ProgramSamplers> cache;
  return cache;
}

// The active uniforms' names, types and locations do not change after the link (marble links a
// program once, in its constructor), so they are read once. The units they hold are read at each
// check: glProgramUniform1i may change them at any time.
ProgramSamplers lookUpSamplers(GLuint program) {
  ProgramSamplers p;
  GLint labelLength = 0;
  char label[256] = {};
  glGetObjectLabel(GL_PROGRAM, program, sizeof label, &labelLength, label);
  p.label = labelLength > 0 ? std::string(label, static_cast<size_t>(labelLength)) : "program " + std::to_string(program);
  GLint count = 0, maxName = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxName);
  std::string name(static_cast<size_t>(std::max(maxName, 1)), '\0');
  for (GLint i = 0; i < count; ++i) {
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, static_cast<GLuint>(i), maxName, &length, &size, &type, name.data());
    const SamplerKind kind = samplerKind(type);
    if (!kind.target) continue;
    std::string base(name.data(), static_cast<size_t>(length));
    if (size > 1 && base.size() > 3 && base.compare(base.size() - 3, 3, "[0]") == 0) base.resize(base.size() - 3);
    for (GLint e = 0; e < size; ++e) {
      const std::string element = size > 1 ? base + "[" + std::to_string(e) + "]" : base;
      const GLint location = glGetUniformLocation(program, element.c_str());
      if (location >= 0) p.samplers.push_back({element, location, kind});
    }
  }
  return p;
}

const ProgramSamplers& samplersOf(GLuint program) {
  auto& cache = programCache();
  auto it = cache.find(program);
  if (it == cache.end()) it = cache.emplace(program, lookUpSamplers(program)).first;
  return it->second;
}

bool isMipmapFilter(GLint filter) { return filter != GL_NEAREST && filter != GL_LINEAR; }
bool isLinearFilter(GLint filter) { return filter != GL_NEAREST && filter != GL_NEAREST_MIPMAP_NEAREST; }

// A sampler state: the bound sampler object's where one is bound, else the texture's own.
GLint samplingParameter(GLuint texture, GLuint sampler, GLenum pname) {
  GLint v = 0;
  if (sampler)
    glGetSamplerParameteriv(sampler, pname, &v);
  else
    glGetTextureParameteriv(texture, pname, &v);
  return v;
}

GLint levelParameter(GLuint texture, GLint level, GLenum pname) {
  GLint v = 0;
  glGetTextureLevelParameteriv(texture, level, pname, &v);
  return v;
}

Components componentsOf(GLuint texture, GLint level, bool depth, bool stencilRead) {
  if (stencilRead) return Components::Uint;
  if (depth) return Components::Float;
  GLint type = GL_NONE;
  for (GLenum channel : {GL_TEXTURE_RED_TYPE, GL_TEXTURE_GREEN_TYPE, GL_TEXTURE_BLUE_TYPE, GL_TEXTURE_ALPHA_TYPE}) {
    type = levelParameter(texture, level, channel);
    if (type != GL_NONE) break;
  }
  if (type == GL_INT) return Components::Int;
  if (type == GL_UNSIGNED_INT) return Components::Uint;
  return Components::Float;
}

const char* componentsName(Components c) {
  return c == Components::Float ? "float" : c == Components::Int ? "signed integer" : "unsigned integer";
}

struct Finding {
  DrawStateProblem problem;
  std::string what;
};

// What is wrong with `texture` (bound with `sampler`) under a sampler of `kind`; empty if nothing.
std::vector<Finding> inspect(const SamplerKind& kind, GLuint texture, GLuint sampler) {
  std::vector<Finding> found;
  const std::string target = targetName(kind.target);
  if (!texture) {
    found.push_back({kNothingBound, "no texture bound to " + target + " (the driver reads texture 0, which has no "
                                    "defined base level)"});
    return found;
  }
  // Buffer textures and multisample textures have no levels, filters or comparisons. A cube map's
  // levels are its faces' (marble has none): only its presence is checked.
  if (kind.target == GL_TEXTURE_BUFFER || kind.target == GL_TEXTURE_2D_MULTISAMPLE ||
      kind.target == GL_TEXTURE_2D_MULTISAMPLE_ARRAY || kind.target == GL_TEXTURE_CUBE_MAP ||
      kind.target == GL_TEXTURE_CUBE_MAP_ARRAY)
    return found;
  const std::string named = "texture " + std::to_string(texture) + " on " + target;
  GLint base = 0, maxLevel = 1000, immutable = 0, immutableLevels = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_BASE_LEVEL, &base);
  glGetTextureParameteriv(texture, GL_TEXTURE_MAX_LEVEL, &maxLevel);
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  if (immutable) {
    // Immutable storage clamps the levels to those it has (8.17).
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &immutableLevels);
    base = std::min(base, immutableLevels - 1);
    maxLevel = std::clamp(maxLevel, base, immutableLevels - 1);
  }
  const GLint width = levelParameter(texture, base, GL_TEXTURE_WIDTH);
  const GLint height = levelParameter(texture, base, GL_TEXTURE_HEIGHT);
  const GLint depthExtent = levelParameter(texture, base, GL_TEXTURE_DEPTH);
  if (width <= 0) {
    found.push_back({kIncomplete, named + " has no defined base level (level " + std::to_string(base) + ")"});
    return found;
  }
  const GLint minFilter = samplingParameter(texture, sampler, GL_TEXTURE_MIN_FILTER);
  const GLint magFilter = samplingParameter(texture, sampler, GL_TEXTURE_MAG_FILTER);
  if (isMipmapFilter(minFilter)) {
    int extent = std::max({width, kind.target == GL_TEXTURE_1D || kind.target == GL_TEXTURE_1D_ARRAY ? 1 : height,
                           kind.target == GL_TEXTURE_3D ? depthExtent : 1});
    GLint last = base;
    while (extent > 1) extent /= 2, ++last;
    last = std::min(last, maxLevel);
    for (GLint level = base + 1; level <= last; ++level)
      if (levelParameter(texture, level, GL_TEXTURE_WIDTH) <= 0) {
        found.push_back({kIncomplete, named + " is sampled with mipmaps but has no level " + std::to_string(level)});
        break;
      }
  }
  const bool depth = levelParameter(texture, base, GL_TEXTURE_DEPTH_SIZE) > 0;
  const bool stencil = levelParameter(texture, base, GL_TEXTURE_STENCIL_SIZE) > 0;
  GLint depthStencilMode = GL_DEPTH_COMPONENT;
  if (depth && stencil) glGetTextureParameteriv(texture, GL_DEPTH_STENCIL_TEXTURE_MODE, &depthStencilMode);
  const bool stencilRead = stencil && (!depth || depthStencilMode == GL_STENCIL_INDEX);
  const bool depthRead = depth && !stencilRead;
  const Components components = componentsOf(texture, base, depthRead, stencilRead);
  if (components != Components::Float && (isLinearFilter(minFilter) || isLinearFilter(magFilter)))
    found.push_back({kIncomplete, named + " holds " + componentsName(components) + " texels and is filtered linearly"});
  const bool compares = samplingParameter(texture, sampler, GL_TEXTURE_COMPARE_MODE) == GL_COMPARE_REF_TO_TEXTURE;
  if (kind.shadow && !depthRead)
    found.push_back({kShadowWithoutDepth, named + " has a non-depth format under a shadow sampler"});
  else if (kind.shadow && !compares)
    found.push_back({kShadowWithoutCompare, named + " has depth comparisons off under a shadow sampler"});
  else if (!kind.shadow && depthRead && compares)
    found.push_back({kCompareWithoutShadow, named + " has depth comparisons on under a non-shadow sampler"});
  if (!kind.shadow && components != kind.components)
    found.push_back({kWrongComponentType, named + " holds " + componentsName(components) + " texels under a " +
                                              componentsName(kind.components) + " sampler"});
  return found;
}

GLint integer(GLenum pname) {
  GLint v = 0;
  glGetIntegerv(pname, &v);
  return v;
}

}  // namespace

void checkDrawState() {
  const auto program = static_cast<GLuint>(integer(GL_CURRENT_PROGRAM));
  if (!program) return;
  const ProgramSamplers& p = samplersOf(program);
  if (p.samplers.empty()) return;
  const GLint activeUnit = integer(GL_ACTIVE_TEXTURE);
  for (const SamplerUniform& s : p.samplers) {
    GLint unit = 0;
    glGetUniformiv(program, s.location, &unit);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    const auto texture = static_cast<GLuint>(integer(s.kind.binding));
    const auto sampler = static_cast<GLuint>(integer(GL_SAMPLER_BINDING));
      for (const Finding& f : inspect(s.kind, texture, sampler))
      deliverDebugMessage({GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR, GL_DEBUG_SEVERITY_MEDIUM,
                           f.problem,
                           "draw state check: " + p.label + ": " + s.kind.glslName + " " + s.name + " on unit " +
                               std::to_string(unit) + ": " + f.what});
  }
  glActiveTexture(static_cast<GLenum>(activeUnit));
}

void forgetProgramSamplers(GLuint program) { programCache().erase(program); }

void forgetAllProgramSamplers() { programCache().clear(); }

}  // namespace marble::gl
