// docs/materials.md's parameter tables are the parameters' descriptions
// (src/marble/scene/material_params.cpp): regenerate them with tools/update-material-docs.sh.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "marble/scene/material_params.h"

namespace marble {
namespace {

std::string readDoc() {
  std::ifstream in(std::string(MARBLE_SOURCE_DIR) + "/docs/materials.md", std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(MaterialDocs, TablesAreTheDescriptions) {
  const std::string doc = readDoc();
  ASSERT_FALSE(doc.empty());
  EXPECT_TRUE(doc == withMaterialDocTables(doc))
      << "docs/materials.md's parameter tables differ from material_params.cpp: run tools/update-material-docs.sh";
}

TEST(MaterialDocs, EveryParameterIsInATable) {
  const std::string doc = readDoc();
  for (const auto& p : materialParams())
    EXPECT_NE(doc.find(std::string("| `") + p.key + "` |"), std::string::npos) << p.key;
}

TEST(MaterialDocs, AnEditedTableIsDetected) {
  // Negative control: a changed cell is put back by the generator.
  std::string doc = readDoc();
  const size_t at = doc.find("| `ior` |");
  ASSERT_NE(at, std::string::npos);
  doc.insert(at + 9, " (edited)");
  EXPECT_NE(doc, withMaterialDocTables(doc));
  EXPECT_EQ(withMaterialDocTables(doc), readDoc());
}

}  // namespace
}  // namespace marble
