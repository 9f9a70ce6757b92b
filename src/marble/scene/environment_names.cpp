#include <stdexcept>

#include "marble/scene/scene.h"

namespace marble {

const std::vector<std::string>& environmentNames() {
  static const std::vector<std::string> names = {"studio", "none", "map"};
  return names;
}

Environment parseEnvironment(const std::string& name) {
  const auto& names = environmentNames();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<Environment>(i);
  throw std::invalid_argument("expected \"studio\", \"none\" or \"map\", got \"" + name + "\"");
}

}  // namespace marble
