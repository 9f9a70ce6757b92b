// libFuzzer target: the OBJ mesh loader through loadMesh, as `marble render x.obj` reaches it.
// A bad file must end in InputError (one line for the user); anything else is a finding.
#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/mesh/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".obj");
  try {
    marble::loadMesh(file.write(data, size));
  } catch (const marble::InputError&) {
  }
  return 0;
}
