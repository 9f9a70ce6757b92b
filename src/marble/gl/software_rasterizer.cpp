#include "marble/gl/software_rasterizer.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <epoxy/gl.h>

namespace marble::gl {

bool isSoftwareRenderer(const char* glRenderer) {
  if (!glRenderer) return false;
  std::string name(glRenderer);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* software : {"llvmpipe", "softpipe", "swiftshader", "software rasterizer"})
    if (name.find(software) != std::string::npos) return true;
  return false;
}

bool rasterizesInSoftware() { return isSoftwareRenderer(reinterpret_cast<const char*>(glGetString(GL_RENDERER))); }

}  // namespace marble::gl
