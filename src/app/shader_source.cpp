#include "shader_source.h"

#include <cstdlib>
#include <filesystem>
#include <string>

#include "marble/core/error.h"

namespace marble {

ShaderLibrary shaderLibraryFor(bool dev) {
  const char* dir = std::getenv(kShaderDirVariable);
  if (dir && *dir) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
      throw InputError(kShaderDirVariable, "", std::string("'") + dir + "' is not a folder");
    return ShaderLibrary(dir);
  }
  if (dev) return ShaderLibrary(std::string(MARBLE_SOURCE_DIR) + "/shaders");
  return ShaderLibrary();
}

}  // namespace marble
