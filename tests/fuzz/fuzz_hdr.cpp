// libFuzzer target: the Radiance .hdr reader (environment maps) through readHdr, as
// `marble render --environment-map x.hdr` reaches it. A bad file must end in InputError.
#include "fuzz_support.h"
#include "marble/core/error.h"
#include "marble/core/hdr_image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static marble::fuzz::InputFile file(".hdr");
  try {
    marble::readHdr(file.write(data, size));
  } catch (const marble::InputError&) {
  }
  return 0;
}
