#pragma once
// Where marble's GLSL comes from (issue 7: a shader that fails to compile must give one line
// and a non-zero exit, so there has to be a way to hand marble a shader that is not built in).
//
// Normally the sources embedded at build time. MARBLE_SHADER_DIR names a folder whose files
// replace the embedded ones of the same name (files it lacks stay embedded): for shader work
// without rebuilding, and to try a broken shader. `marble view --dev` reloads (R) from that
// folder, or from the source tree's shaders/ when the variable is not set.
#include "marble/gl/shader_library.h"

namespace marble {

inline constexpr const char* kShaderDirVariable = "MARBLE_SHADER_DIR";

// Throws InputError naming MARBLE_SHADER_DIR when it is set but not a folder.
ShaderLibrary shaderLibraryFor(bool dev);

}  // namespace marble
