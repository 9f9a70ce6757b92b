#include "cmd_presets.h"

#include <algorithm>
#include <string>
#include <iostream>

#include "marble/scene/material_io.h"

namespace marble {

int runPresetsCommand() {
  size_t width = 0;
  const auto presets = builtinPresets();
  for (const auto& p : presets) width = std::max(width, p.name.size());
  for (const auto& p : presets) std::cout << p.name << std::string(width + 2 - p.name.size(), ' ') << p.description << "\n";
  return 0;
}

}  // namespace marble
