#pragma once
// The GL commands at which NVIDIA's driver checks the current program's samplers (draws, dispatches,
// clears, blits: gl/draw_state_check.h), each behind one function that runs the draw state check
// first. marble's code calls these, never the raw commands: a source rule test
// (CheckedCalls.NoRawCommandOutsideThisFile) fails on a raw one anywhere under src/, so a new pass
// cannot forget the check. Off (release, no debug output) each costs one load and a branch.
//
// Texture clears (glClearTexImage, glClearTexSubImage) are not here: they read no program state,
// and marble fills new textures with them in debug mode while the passes are being built, when a
// program left current by its caller may still be checked (a false report, seen in
// DrawStateCheck.AProgramLeftCurrentIsCheckedAtTheNextClear).
//
// Not covered: Dear ImGui's OpenGL backend (third-party code, compiled as it comes) draws the
// viewer's panel itself; its one program has one sampler, which it binds to its font texture
// before each of its draws.
#include <epoxy/gl.h>

#include "marble/gl/draw_state_check.h"

namespace marble::gl {

inline void drawArrays(GLenum mode, GLint first, GLsizei count) {
  checkBeforeDraw();
  glDrawArrays(mode, first, count);
}

inline void drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  checkBeforeDraw();
  glDrawElements(mode, count, type, indices);
}

inline void dispatchCompute(GLuint groupsX, GLuint groupsY, GLuint groupsZ) {
  checkBeforeDraw();
  glDispatchCompute(groupsX, groupsY, groupsZ);
}

// The group counts come from the buffer bound to GL_DISPATCH_INDIRECT_BUFFER, at `offset`.
inline void dispatchComputeIndirect(GLintptr offset) {
  checkBeforeDraw();
  glDispatchComputeIndirect(offset);
}

// glClearNamedFramebufferfv: one colour attachment (buffer GL_COLOR, drawBuffer its index) or the
// depth (GL_DEPTH, drawBuffer 0) of framebuffer `fbo` (0: the default framebuffer).
inline void clearFramebuffer(GLuint fbo, GLenum buffer, GLint drawBuffer, const GLfloat* value) {
  checkBeforeDraw();
  glClearNamedFramebufferfv(fbo, buffer, drawBuffer, value);
}

// glClearBufferfv: the same, on the framebuffer bound for drawing.
inline void clearBoundFramebuffer(GLenum buffer, GLint drawBuffer, const GLfloat* value) {
  checkBeforeDraw();
  glClearBufferfv(buffer, drawBuffer, value);
}

// glClear on the framebuffer bound for drawing, with the clear values set by glClearColor & co.
inline void clearBound(GLbitfield mask) {
  checkBeforeDraw();
  glClear(mask);
}

// glBlitNamedFramebuffer from `source`'s read buffer to `target`'s draw buffers.
inline void blitFramebuffer(GLuint source, GLuint target, GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1,
                            GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter) {
  checkBeforeDraw();
  glBlitNamedFramebuffer(source, target, srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1, mask, filter);
}

}  // namespace marble::gl
