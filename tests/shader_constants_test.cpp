// The numbers C++ and the shaders share are written once (render/shader_constants.h) and reach
// every shader as #defines: no shader restates one by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>

#include "marble/gl/shader_library.h"
#include "marble/render/shader_constants.h"
#include "marble/scene/scene.h"

namespace marble {
namespace {

bool hasDefine(const std::string& d) {
  const auto& all = shader::sharedShaderDefines();
  return std::find(all.begin(), all.end(), d) != all.end();
}

TEST(ShaderConstants, ModesAndUnitsAreDefinedFromTheCppSide) {
  EXPECT_TRUE(hasDefine("MODE_MARBLE " + std::to_string(static_cast<int>(RenderMode::Marble))));
  EXPECT_TRUE(hasDefine("MODE_OREN_NAYAR " + std::to_string(static_cast<int>(RenderMode::OrenNayar))));
  EXPECT_TRUE(hasDefine("MODE_LIGHT_DEPTH " + std::to_string(static_cast<int>(RenderMode::LightDepth))));
  EXPECT_TRUE(hasDefine("UNIT_ENV_MAP " + std::to_string(shader::UNIT_ENV_MAP)));
  EXPECT_TRUE(hasDefine("MAX_TAPS " + std::to_string(shader::MAX_TAPS)));
  EXPECT_FALSE(hasDefine("MODE_MARBLE 0")) << "negative control";
}

TEST(ShaderConstants, EveryShaderGetsThemAfterItsVersionLine) {
  const std::string text = ShaderLibrary().assemble("lighting.frag.glsl");
  EXPECT_EQ(text.rfind("#version", 0), 0u);
  EXPECT_NE(text.find("\n#define MODE_MARBLE "), std::string::npos);
  EXPECT_LT(text.find("#define UNIT_LIGHTING_ALBEDO "), text.find("#line 2 0"));
}

TEST(ShaderConstants, NoShaderRestatesABindingOrAModeNumber) {
  const std::regex literalBinding(R"(binding\s*=\s*[0-9])");
  const std::regex modeConstant(R"(const\s+int\s+(MODE_|ENV_STUDIO|ENV_MAP|MAX_TAPS))");
  for (const auto& [name, text] : embeddedShaders()) {
    EXPECT_FALSE(std::regex_search(text, literalBinding)) << name << ": a texture unit written as a number";
    EXPECT_FALSE(std::regex_search(text, modeConstant)) << name << ": a shared constant restated";
  }
  // The check can fail: a line as the shaders had them before.
  EXPECT_TRUE(std::regex_search(std::string("layout(binding = 7) uniform sampler2D u_env_map;"), literalBinding));
}

}  // namespace
}  // namespace marble
