#pragma once
// One shader source compiled into specialized programs, one per set of #defines, each built
// the first time it is asked for and kept. Why: Mesa's llvmpipe runs both sides of every
// branch under a lane mask, even when the condition is a uniform, so an uber-shader that
// picks the render mode, noise basis or mapping at run time pays for all of them per pixel.
// Compiled as constants, the unused branches vanish (the geometry pass went from 66 to 37 ms
// on the dragon at 800x800; docs/performance.md). On a GPU it costs nothing either way.
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "marble/gl/program.h"

namespace marble::gl {

class ProgramVariants {
public:
  // `library` must outlive this object.
  ProgramVariants(const ShaderLibrary& library, std::vector<ShaderStageSource> stages);

  // The program for these defines ("NAME VALUE", as Program takes them), compiled on first
  // use. Throws ShaderError (file and line) if it does not compile.
  const Program& get(const std::vector<std::string>& defines);

  // The same, for the per-frame path: `key` (a small number the caller derives from what the
  // defines encode) finds a program already built without building any strings; `defines()`
  // is called only the first time a key is seen.
  template <typename MakeDefines>
  const Program& get(uint32_t key, MakeDefines defines) {
    if (auto it = byKey_.find(key); it != byKey_.end()) return *it->second;
    const Program& program = get(defines());
    byKey_.emplace(key, &program);
    return program;
  }

  size_t compiledCount() const { return programs_.size(); }

private:
  const ShaderLibrary* library_;
  std::vector<ShaderStageSource> stages_;
  std::map<std::vector<std::string>, Program> programs_;  // node-based: the pointers below stay valid
  std::unordered_map<uint32_t, const Program*> byKey_;
};

}  // namespace marble::gl
