#pragma once
// The texture state NVIDIA's driver checks, checked here on any driver (llvmpipe says nothing about
// it). NVIDIA looks at every *active* sampler uniform of the current program, whether the shader's
// path reads it or not, at draws and dispatches and, as its reports in the GL tests show, at
// clears too (a program left current after its owner's textures went was reported at the next
// renderer's first clear: docs/performance.md, "Eighteenth session"). It reports through KHR_debug:
//  - a shadow sampler whose unit holds no depth texture, or one with depth comparisons off
//    (undefined behaviour: OpenGL 4.5, 11.1.3.5 "Texture Access"; id 131222 on NVIDIA);
//  - a unit with nothing (texture 0) or an incomplete texture on the sampler's target ("does not
//    have a defined base level"; the spec's result is (0, 0, 0, 1), 11.1.3.5, but nothing in
//    marble means to read it, so it is a bug here).
// This adds what the same section leaves undefined as well: comparisons on under a non-shadow
// sampler, a float sampler over an integer texture or the other way round, an integer texture
// filtered linearly (incomplete, 8.17).
//
// On with the debug output (enableDebugOutput: debug builds, MARBLE_GL_DEBUG=1, the GL tests); a
// problem goes to the same handler as the driver's messages, as undefined behaviour of medium
// severity from GL_DEBUG_SOURCE_APPLICATION, naming the program's label, the uniform and the unit,
// so a GL test fails on it as it would on NVIDIA. Off, checkBeforeDraw is one load and a branch.
#include <epoxy/gl.h>

namespace marble::gl {

// Set by enableDebugOutput / disableDebugOutput; not meant to be set elsewhere but in tests.
inline bool drawStateChecksOn = false;

// Checks the current program's active samplers against what their units hold now.
void checkDrawState();

// Runs before every draw, dispatch, clear and blit: the functions of gl/checked_calls.h call it,
// and marble's code calls those, never the raw commands (a source rule test holds it to that).
inline void checkBeforeDraw() {
  if (drawStateChecksOn) checkDrawState();
}

// The sampler list is looked up once per program and kept by its name; a deleted program's
// entry must go, since GL reuses the name (ProgramTraits::destroy calls this).
void forgetProgramSamplers(GLuint program);
// Drops them all: another context is current, where the same names are other programs
// (HeadlessContext calls this when it makes its context current and when it restores the previous).
void forgetAllProgramSamplers();

// Application message ids of the check's reports (GL_DEBUG_SOURCE_APPLICATION).
enum DrawStateProblem : GLuint {
  kNothingBound = 1,         // texture 0 on the sampler's target
  kIncomplete = 2,           // no defined base level, missing mipmap levels, integer + linear
  kShadowWithoutDepth = 3,   // shadow sampler, texture of a non-depth format
  kShadowWithoutCompare = 4, // shadow sampler, depth texture with comparisons off
  kCompareWithoutShadow = 5, // non-shadow sampler, depth texture with comparisons on
  kWrongComponentType = 6,   // float sampler over an integer texture, or the other way round
};

}  // namespace marble::gl
