// shaders/nearest_texel.glsl reads a GL_NEAREST texture's texel through its sampler instead of
// texelFetch (fewer instructions on llvmpipe; docs/performance.md, "Twenty-third session: byte-equal
// savings"). The passes rely on it reading the same texel and the same bits: checked here at every
// texel of textures of the formats and sizes the passes read (the G-buffer's depth and normals,
// the light's layers, the bounce's and the blur's half floats; even, odd and one-texel sizes).
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "gl_support.h"
#include "marble/gl/checked_calls.h"
#include "marble/gl/draw_state_check.h"
#include "marble/gl/handles.h"
#include "marble/gl/headless_context.h"
#include "marble/gl/shader_library.h"

namespace marble {
namespace {

// Per texel i (row-major): out[2i] = texelFetch, out[2i + 1] = nearest_texel.
const char* kComputeMain = R"(
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_texture;
layout(std430, binding = 0) writeonly buffer Results { vec4 results[]; };
void main() {
  ivec2 size = textureSize(u_texture, 0);
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, size))) return;
  uint i = uint(t.y * size.x + t.x);
  results[2u * i] = texelFetch(u_texture, t, 0);
  results[2u * i + 1u] = nearest_texel(u_texture, t);
}
)";

class NearestTexelGlTest : public test::ComputeProgramTest {
protected:
  void SetUp() override { compileProgram(embeddedShaders().at("nearest_texel.glsl") + kComputeMain); }

  // Texels of `texture` (w x h) whose nearest_texel differs in any bit from texelFetch.
  int mismatches(const gl::Texture& texture, int w, int h) {
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
    gl::Buffer results = gl::Buffer::create();
    glNamedBufferStorage(results.id(), static_cast<GLsizeiptr>(2 * n * 4 * sizeof(float)), nullptr, GL_MAP_READ_BIT);
    glUseProgram(program_);
    glBindTextureUnit(0, texture.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, results.id());
    gl::dispatchCompute(static_cast<GLuint>((w + 7) / 8), static_cast<GLuint>((h + 7) / 8), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> out(2 * n * 4);
    glGetNamedBufferSubData(results.id(), 0, static_cast<GLsizeiptr>(out.size() * sizeof(float)), out.data());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    int bad = 0;
    for (size_t i = 0; i < n; ++i)
      if (std::memcmp(&out[8 * i], &out[8 * i + 4], 4 * sizeof(float)) != 0) ++bad;
    return bad;
  }

};

struct Format {
  GLenum internal, format, type;
  int channels;
  const char* name;
};

// Random texels of `format`, float data spread over many magnitudes (signed 16-bit for snorm).
gl::Texture randomTexture(const Format& f, int w, int h, GLenum filter, std::mt19937& rng) {
  gl::Texture t = gl::makeTexture2D(f.internal, w, h, filter);
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(f.channels);
  if (f.type == GL_SHORT) {
    std::uniform_int_distribution<int> s(-32767, 32767);
    std::vector<int16_t> data(n);
    for (auto& v : data) v = static_cast<int16_t>(s(rng));
    glTextureSubImage2D(t.id(), 0, 0, 0, w, h, f.format, f.type, data.data());
  } else {
    std::uniform_real_distribution<float> u(0.0f, 1.0f), e(-8.0f, 8.0f);
    std::vector<float> data(n);
    for (auto& v : data) v = f.format == GL_DEPTH_COMPONENT ? u(rng) : u(rng) * std::exp2(e(rng)) * (u(rng) < 0.3f ? -1.0f : 1.0f);
    glTextureSubImage2D(t.id(), 0, 0, 0, w, h, f.format, f.type, data.data());
  }
  return t;
}

const Format kFormats[] = {
    {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 1, "depth32f"},
    {GL_RG16_SNORM, GL_RG, GL_SHORT, 2, "rg16 snorm"},
    {GL_RGBA16_SNORM, GL_RGBA, GL_SHORT, 4, "rgba16 snorm"},
    {GL_RG32F, GL_RG, GL_FLOAT, 2, "rg32f"},
    {GL_RGBA16F, GL_RGBA, GL_FLOAT, 4, "rgba16f"},
};
const int kSizes[][2] = {{400, 400}, {801, 603}, {257, 3}, {1, 1}};

TEST_F(NearestTexelGlTest, ReadsTheSameBitsAsTexelFetchAtEveryTexel) {
  std::mt19937 rng(23);
  for (const Format& f : kFormats)
    for (const auto& s : kSizes) {
      const gl::Texture t = randomTexture(f, s[0], s[1], GL_NEAREST, rng);
      EXPECT_EQ(mismatches(t, s[0], s[1]), 0) << f.name << " " << s[0] << " x " << s[1];
    }
}

// The control: through a GL_LINEAR sampler the same read blends the neighbours now and then (its
// weights come from the centre's rounding), so a texture's filter must be GL_NEAREST for it.
TEST_F(NearestTexelGlTest, ControlALinearSamplerBlends) {
  std::mt19937 rng(23);
  const gl::Texture t = randomTexture(kFormats[3], 801, 603, GL_LINEAR, rng);
  EXPECT_GT(mismatches(t, 801, 603), 0);
}

}  // namespace
}  // namespace marble
