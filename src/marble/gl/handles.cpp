#include "marble/gl/handles.h"

namespace marble::gl {
long& liveObjectCount() {
  static long count = 0;
  return count;
}

Texture makeTexture2D(GLenum internalFormat, int width, int height, GLenum filter) {
  Texture t = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, internalFormat, width, height);
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

void drawFullscreenTriangle(GLuint program, GLuint emptyVao) {
  glUseProgram(program);
  glBindVertexArray(emptyVao);
  checkBeforeDraw();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace marble::gl
