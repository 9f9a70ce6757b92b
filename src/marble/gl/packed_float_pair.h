#pragma once
// Two floats' bits in one 64-bit uniform element, for arrays a shader indexes per lane: llvmpipe
// reads such an array lane by lane, one load per lane and component, so a `double` element unpacked
// in the shader (uintBitsToFloat(unpackDouble2x32(d))) costs one load per lane where a `vec2` costs
// two (docs/performance.md, "Thirtieth session: ... s30-cost"). The double is a carrier of bits,
// never a value: nothing computes with it on either side, so no NaN or denormal rule applies.
#include <bit>
#include <cstdint>

namespace marble::gl {

// `low` in the low 32 bits (unpackDouble2x32(d).x in GLSL), `high` in the high 32 bits (.y).
inline double packFloatPair(float low, float high) {
  return std::bit_cast<double>(static_cast<uint64_t>(std::bit_cast<uint32_t>(low)) |
                               static_cast<uint64_t>(std::bit_cast<uint32_t>(high)) << 32);
}

}  // namespace marble::gl
