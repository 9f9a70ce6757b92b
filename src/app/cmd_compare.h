#pragma once
// `marble compare REF.exr TEST.exr [--json]`: how close a render is to a reference (issue 5,
// item 9; docs/quality.md).
#include <string>

namespace marble {

struct CompareOptions {
  std::string reference;
  std::string test;
  bool json = false;
};

int runCompareCommand(const CompareOptions& o);

}  // namespace marble
