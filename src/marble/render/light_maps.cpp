#include "marble/render/light_maps.h"

#include <algorithm>

namespace marble {
namespace {

// A mipmapped render target (all levels down to 1x1), clamped; read bilinearly within the nearest
// level (bounce.glsl picks a level per sample): trilinear cost the dragon's lighting pass ~1.5x.
gl::Texture makeMipmapped(GLenum internalFormat, int size) {
  int levels = 1;
  while ((size >> levels) > 0) ++levels;
  gl::Texture t = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), levels, internalFormat, size, size);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

}  // namespace

LightMaps::LightMaps(int size_)
    : size(size_),
      // Nearest, not linear: at the object's silhouette seen from the light, blending a surface
      // distance with the "nothing hit" clear value would invent huge entry distances, hence
      // zero thickness and light leaking through past the terminator.
      distance(gl::makeTexture2D(GL_RG32F, size, size, GL_NEAREST)),
      depth(gl::makeTexture2D(GL_DEPTH_COMPONENT32F, size, size, GL_LINEAR)),
      // The reflective shadow map at an eighth of the size, in a draw of its own: the bounce's
      // finest read (its centre sample, a disk of 1/32 of the map's width, bounce.glsl) is level 3
      // here, level 4 of session 7's 256² map: texels 64 of the full map's wide either way, so the
      // levels it reads are the same to within how the rasterizer covers a texel, and the draw
      // and its mipmaps cost less (docs/performance.md, "The bounce gathered coarsely"). 32-bit:
      // w is a texel's area, ~1e-5 scene units^2, below half float's normal range (and so is the
      // glossy weight a in the normal's alpha).
      bounceSize(std::max(size / 8, 1)),
      bouncePosition(makeMipmapped(GL_RGBA32F, bounceSize)),
      bounceNormal(makeMipmapped(GL_RGBA32F, bounceSize)),
      bounceDepth(gl::makeTexture2D(GL_DEPTH_COMPONENT32F, bounceSize, bounceSize, GL_NEAREST)),
      // A quarter of the light map's size (1.35 mm texels for the reference scenes): at an eighth,
      // the reflective shadow map's, the ten scenes' mean SSIM was 0.0002 lower (docs/quality.md,
      // "Twenty-second session"). Nearest: a blend of an entry or exit with "none" is meaningless.
      layersSize(std::max(size / 4, 1)),
      layers(gl::makeTexture2D(GL_RG32F, layersSize, layersSize, GL_NEAREST)),
      fbo(gl::Framebuffer::create()),
      bounceFbo(gl::Framebuffer::create()),
      layersFbo(gl::Framebuffer::create()) {
  // Shadows read the depth with hardware comparison and bilinear filtering (PCF).
  glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, distance.id(), 0);
  glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
  // The shader's outputs 1 and 2 go to the reflective shadow map's framebuffer only.
  glNamedFramebufferTexture(bounceFbo.id(), GL_COLOR_ATTACHMENT1, bouncePosition.id(), 0);
  glNamedFramebufferTexture(bounceFbo.id(), GL_COLOR_ATTACHMENT2, bounceNormal.id(), 0);
  const GLenum bounceBuffers[] = {GL_NONE, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(bounceFbo.id(), 3, bounceBuffers);
  glNamedFramebufferTexture(bounceFbo.id(), GL_DEPTH_ATTACHMENT, bounceDepth.id(), 0);
  glNamedFramebufferTexture(layersFbo.id(), GL_COLOR_ATTACHMENT0, layers.id(), 0);
}

}  // namespace marble
