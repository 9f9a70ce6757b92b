#include "marble/render/shader_constants.h"

#include <cctype>

#include "marble/scene/scene.h"

namespace marble::shader {

const std::vector<std::string>& sharedShaderDefines() {
  static const std::vector<std::string> defines = [] {
    std::vector<std::string> out = {
#define MARBLE_SHADER_CONSTANT_DEFINE(name, value) #name " " #value,
        MARBLE_SHADER_CONSTANTS(MARBLE_SHADER_CONSTANT_DEFINE)
#undef MARBLE_SHADER_CONSTANT_DEFINE
    };
    const auto& modes = renderModeNames();
    for (size_t i = 0; i < modes.size(); ++i) {
      std::string name = "MODE_";
      for (char c : modes[i]) name += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      out.push_back(name + " " + std::to_string(i));
    }
    return out;
  }();
  return defines;
}

}  // namespace marble::shader
