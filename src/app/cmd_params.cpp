#include "cmd_params.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/scene/material_params.h"

namespace marble {

int runParamsCommand(const std::string& updateDoc) {
  if (!updateDoc.empty()) {
    try {
      std::ifstream in(updateDoc, std::ios::binary);
      if (!in) throw InputError(updateDoc, "", "cannot open for reading");
      std::ostringstream text;
      text << in.rdbuf();
      const std::string updated = withMaterialDocTables(text.str());
      if (updated.find("<!-- params:") == std::string::npos)
        throw InputError(updateDoc, "", "has no <!-- params:GROUP --> markers");
      writeFileAtomically(updateDoc, updated);
      return 0;
    } catch (const InputError& e) {
      std::cerr << "marble: " << e.what() << "\n";
      return 2;
    }
  }
  const Material defaults;
  for (const auto& g : paramGroups()) {
    std::cout << g.title << " (" << g.what << ")\n";
    for (const auto& p : materialParams()) {
      if (p.group != g.id) continue;
      std::string line = std::string("  ") + p.key;
      line += std::string(line.size() < 20 ? 20 - line.size() : 1, ' ');
      line += "default " + formatValue(p, p.get(defaults));
      if (*p.unit) line += std::string(" ") + p.unit;
      if (p.modes) line += "; read by " + modeNames(p.modes);
      std::cout << line << "\n";
    }
  }
  return 0;
}

}  // namespace marble
