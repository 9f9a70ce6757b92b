#include "marble/gl/handles.h"

#include "marble/gl/checked_calls.h"

namespace marble::gl {
long& liveObjectCount() {
  static long count = 0;
  return count;
}

namespace {

bool isDepthFormat(GLenum f) {
  return f == GL_DEPTH_COMPONENT16 || f == GL_DEPTH_COMPONENT24 || f == GL_DEPTH_COMPONENT32 ||
         f == GL_DEPTH_COMPONENT32F || f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8;
}

bool isIntegerFormat(GLenum f) {
  switch (f) {
    case GL_R8I: case GL_R8UI: case GL_R16I: case GL_R16UI: case GL_R32I: case GL_R32UI:
    case GL_RG8I: case GL_RG8UI: case GL_RG16I: case GL_RG16UI: case GL_RG32I: case GL_RG32UI:
    case GL_RGBA8I: case GL_RGBA8UI: case GL_RGBA16I: case GL_RGBA16UI: case GL_RGBA32I: case GL_RGBA32UI:
    case GL_RGB10_A2UI: return true;
    default: return false;
  }
}

// A new texture's contents are undefined (OpenGL 4.5, 8.19: TexStorage leaves them so). llvmpipe's
// are zero; a GPU's memory holds whatever was there, often a freed texture's texels, so a read of
// a texel the frame never wrote gives another picture there, and a cached frame another than a
// fresh one. With the checks on (debug, the GL tests) each new texture holds a value of its own
// instead, different from texture to texture, so such a read changes the picture here too.
void fillWithUndefinedStandIn(GLuint texture, GLenum internalFormat) {
  static unsigned created = 0;
  const float v = 0.1f + 0.8f * static_cast<float>((++created * 2654435761u) >> 8) / static_cast<float>(1u << 24);
  if (isDepthFormat(internalFormat)) {
    if (internalFormat == GL_DEPTH24_STENCIL8 || internalFormat == GL_DEPTH32F_STENCIL8) return;
    glClearTexImage(texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &v);
    return;
  }
  if (isIntegerFormat(internalFormat)) return;
  const float rgba[4] = {v, 1.0f - v, 0.5f * v, 1.0f};
  glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, rgba);
}

}  // namespace

Texture makeTexture2D(GLenum internalFormat, int width, int height, GLenum filter) {
  Texture t = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, internalFormat, width, height);
  if (drawStateChecksOn) fillWithUndefinedStandIn(t.id(), internalFormat);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

void setMeshPassState() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
}

void setScreenPassState() {
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
}

void setSurfaceOnlyScreenPassState() {
  setScreenPassState();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);  // the triangle lies on the far plane (depth 1): passes where d < 1
  glDepthMask(GL_FALSE);    // nothing written, so sampling the same depth texture is defined
}

void setDepthCopyScreenPassState() {
  setScreenPassState();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);  // every texel takes its pixel's depth (setScreenPassState left writes on)
}

void drawFullscreenTriangle(GLuint program, GLuint emptyVao) {
  glUseProgram(program);
  glBindVertexArray(emptyVao);
  gl::drawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace marble::gl
