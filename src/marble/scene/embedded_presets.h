#pragma once
// presets/*.json, embedded at build time (cmake/EmbedShaders.cmake): file name -> JSON text.
#include <map>
#include <string>

namespace marble {
const std::map<std::string, std::string>& embeddedPresets();
}
