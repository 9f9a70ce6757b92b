// libFuzzer target: the OBJ mesh loader through loadMesh, as `marble render x.obj` reaches it.
// A bad file must end in InputError (one line for the user); anything else is a finding.
// Differential: the parallel path (the file cut into 3 chunks) must give the sequential scan's
// mesh, or its exact error message; a difference aborts (a finding).
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/mesh_internal.h"

namespace {

std::string outcome(std::string_view text, unsigned chunks) {
  return marble::fuzz::meshOutcome([&] { return marble::mesh_detail::loadObjInChunks("fuzz.obj", text, chunks); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".obj");
  try {
    marble::loadMesh(file.write(data, size));
  } catch (const marble::InputError&) {
  }
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (!std::memchr(data, '\0', size) && outcome(text, 1) != outcome(text, 3)) std::abort();
  return 0;
}
