#pragma once
// `marble compare REF.exr TEST.exr [--json] [--downsample N] [--side-by-side OUT.png]`: how close a render is to a reference (issue 5,
// item 9; docs/quality.md).
#include <string>

namespace marble {

struct CompareOptions {
  std::string reference;
  std::string test;
  bool json = false;
  int downsample = 1;          // box-filter both images by this factor first
  std::string sideBySide;      // when set, write reference | test (at k) here
};

int runCompareCommand(const CompareOptions& o);

}  // namespace marble
