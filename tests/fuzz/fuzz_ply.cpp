// libFuzzer target: the PLY mesh loader through loadMesh, as `marble render x.ply` reaches it.
// A bad file must end in InputError (one line for the user); anything else is a finding.
// Differential: the body read in 3 parts (ply_parts.h) must give the front-to-back read's mesh,
// or its exact error message; a difference aborts (a finding).
#include <cstdlib>
#include <string_view>

#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/mesh_internal.h"

namespace {

std::string outcome(std::string_view data, unsigned parts) {
  return marble::fuzz::meshOutcome([&] { return marble::mesh_detail::loadPlyInParts("fuzz.ply", data, parts); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".ply");
  try {
    marble::loadMesh(file.write(data, size));
  } catch (const marble::InputError&) {
  }
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (outcome(bytes, 1) != outcome(bytes, 3)) std::abort();
  return 0;
}
