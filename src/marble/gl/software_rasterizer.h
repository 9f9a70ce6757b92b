#pragma once
// Whether the current context's GL is a software rasterizer (Mesa's llvmpipe or softpipe, Google's
// SwiftShader), read from GL_RENDERER. Work that only pays where the CPU rasterizes is chosen by it:
// on llvmpipe each triangle's vertex shading and setup cost CPU instructions whether or not culling
// then discards it, so dropping the culled ones on the CPU first saves more than it costs
// (render/screen_cull.h); a GPU culls in fixed-function hardware for nothing, and the same CPU pass
// would only add to the frame (docs/performance.md, "Twenty-eighth session: ... s28-cost").
namespace marble::gl {

// Needs a current context.
bool rasterizesInSoftware();

// The rule itself, for a GL_RENDERER string (case-insensitive substrings).
bool isSoftwareRenderer(const char* glRenderer);

}  // namespace marble::gl
