// libFuzzer target: the material preset reader (loadPreset on a file), as `--preset x.json`
// and the viewer's preset loading reach it.
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/scene/material_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".json");
  std::vector<std::string> warnings;
  try {
    marble::loadPreset(file.write(data, size).string(), &warnings);
  } catch (const marble::InputError&) {
  }
  return 0;
}
