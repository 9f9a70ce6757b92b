#include "marble/render/turbulence_texture.h"

namespace marble {

GLuint TurbulenceTexture::update(const Material& m) {
  if (!enabled_) return 0;
  const TurbulenceGridKey key = turbulenceGridKey(m);
  if (key.dimensions == 0) return 0;
  if (texture_ && key == key_) return texture_.id();
  const std::vector<uint16_t> grid = bakeTurbulenceGrid(m);
  const int w = turbulenceGridSize(m);
  // 16-bit unsigned normalized: turbulence is in [0,1); half a step is 7.6e-6. Linear
  // filtering is the interpolation the grid is exact for; GL_REPEAT is the lattice's period.
  // The vein models' grid holds their four samples per texel (RGBA).
  const bool four = turbulenceGridChannels(m) == 4;
  texture_ = gl::Texture::create(key.dimensions == 3 ? GL_TEXTURE_3D : GL_TEXTURE_2D);
  const GLuint id = texture_.id();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  if (key.dimensions == 3) {
    glTextureStorage3D(id, 1, four ? GL_RGBA16 : GL_R16, w, w, w);
    glTextureSubImage3D(id, 0, 0, 0, 0, w, w, w, four ? GL_RGBA : GL_RED, GL_UNSIGNED_SHORT, grid.data());
  } else {
    glTextureStorage2D(id, 1, GL_R16, w, w);
    glTextureSubImage2D(id, 0, 0, 0, w, w, GL_RED, GL_UNSIGNED_SHORT, grid.data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(id, wrap, GL_REPEAT);
  key_ = key;
  bytes_ = grid.size() * sizeof(uint16_t);
  return id;
}

}  // namespace marble
