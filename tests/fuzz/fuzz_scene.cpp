// libFuzzer target: the scene JSON reader (loadScene), as `marble render scene.json` reaches it.
// The mesh it names is not loaded: the mesh loaders have targets of their own.
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".json");
  std::vector<std::string> warnings;
  try {
    marble::loadScene(file.write(data, size), warnings);
  } catch (const marble::InputError&) {
  }
  return 0;
}
