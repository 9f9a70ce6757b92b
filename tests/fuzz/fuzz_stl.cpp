// libFuzzer target: the STL mesh loader through loadMesh, as `marble render x.stl` reaches it.
// A bad file must end in InputError (one line for the user); anything else is a finding.
// Differential: read as ASCII and cut into 3 chunks, every input must give the one-pass read's
// mesh or its exact error message; a difference aborts (a finding).
#include <cstdlib>
#include <string_view>

#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/mesh_internal.h"

namespace {

std::string asciiOutcome(std::string_view data, unsigned chunks) {
  return marble::fuzz::meshOutcome([&] { return marble::mesh_detail::loadStlAsciiInChunks("fuzz.stl", data, chunks); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".stl");
  try {
    marble::loadMesh(file.write(data, size));
  } catch (const marble::InputError&) {
  }
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (asciiOutcome(bytes, 1) != asciiOutcome(bytes, 3)) std::abort();
  return 0;
}
