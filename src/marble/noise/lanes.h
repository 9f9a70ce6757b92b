#pragma once
// Eight-lane float, uint and mask types with GLSL's operators and functions, so that
// shaders/pattern_core.glsl compiles as C++ over 8 points at once (src/marble/noise/vein_lanes.inc,
// the batched rows' SIMD path). GCC/Clang vector extensions; vein_lanes.inc compiles its
// functions for AVX2 (8 floats a register) and runs them where the CPU has it.
//
// Exactness: each lane operation is the IEEE operation the scalar build performs on that lane
// (+ - * / sqrt are correctly rounded in both; min/max are the same selects; floor is the same
// integer arithmetic as marble_pattern.cpp's; conversions round as the scalar casts do), so a
// lane's result is the scalar result bit for bit, provided the control flow is the same.
//
// Control flow: a comparison gives a Mask. Where the pattern branches on one (`if`, `?:`, a
// loop condition), the Mask converts to bool: fine while all lanes agree (parameters, which are
// the same in every lane; the rows' y and z). Where they disagree the conversion records it
// (divergedLanes()) and the caller recomputes those points one at a time: the lanes never
// silently follow another lane's branch.
#include <climits>
#include <cmath>
#include <cstdint>
#include <type_traits>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>  // the AVX2 gather (vein_lanes.inc)
#endif

// Every function here is always inlined into its caller, so a lane value never crosses a call
// between code built for different targets (the AVX2 functions of vein_lanes.inc and baseline
// code such as the tests): passing 32-byte vectors by value would differ between the two ABIs.
// That is also why the compilers' note on that ABI difference (-Wpsabi) is off here.
#define MARBLE_LANE inline __attribute__((always_inline))
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace marble::simd {

constexpr int kLanes = 8;
typedef float F8 __attribute__((vector_size(32)));
typedef uint32_t U8 __attribute__((vector_size(32)));
typedef int32_t I8 __attribute__((vector_size(32)));

// Set when a Mask with lanes that disagree was used as a bool on this thread (see above).
inline thread_local bool laneDivergence = false;

struct Mask {
  I8 v;  // -1 (true) or 0 per lane
  // NOLINTNEXTLINE(google-explicit-constructor): GLSL's `if (a < b)` needs the conversion
  __attribute__((always_inline)) operator bool() const {
    int32_t any = 0, all = -1;
    for (int i = 0; i < kLanes; ++i) {
      any |= v[i];
      all &= v[i];
    }
    if (any != all) laneDivergence = true;
    return any != 0;
  }
};
MARBLE_LANE Mask operator&&(Mask a, Mask b) { return {a.v & b.v}; }
MARBLE_LANE Mask operator||(Mask a, Mask b) { return {a.v | b.v}; }
MARBLE_LANE Mask operator!(Mask a) { return {~a.v}; }

struct LaneU;

struct LaneF {
  F8 v;
  LaneF() = default;
  // A scalar in every lane. At run time a shuffle of lane 0: GCC 12 builds the equivalent
  // vector literal {s, s, ...} from a register with seven inserts (and in a loop short of
  // registers rebuilds it every iteration: 8 of lerpOctave's 17 loop instructions were that),
  // the shuffle with one broadcast. Constant evaluation keeps the literal. (Assigned in the body,
  // not returned by a helper: a function returning a 32-byte vector trips -Wpsabi in baseline
  // translation units that include this header.)
  // NOLINTNEXTLINE(google-explicit-constructor): literals as in GLSL
  __attribute__((always_inline)) constexpr LaneF(float s) : v() {
    if (std::is_constant_evaluated()) {
      v = F8{s, s, s, s, s, s, s, s};
    } else {
#if defined(__clang__)
      v = __builtin_shufflevector(F8{s}, F8{s}, 0, 0, 0, 0, 0, 0, 0, 0);
#else
      v = __builtin_shuffle(F8{s}, U8{});
#endif
    }
  }
  __attribute__((always_inline)) constexpr explicit LaneF(F8 x) : v(x) {}
  explicit LaneF(LaneU u);
  __attribute__((always_inline)) explicit LaneF(Mask m) : v(__builtin_convertvector(m.v & 1, F8)) {}  // float(bool): 1 or 0
  __attribute__((always_inline)) LaneF& operator+=(LaneF b) { v += b.v; return *this; }
  __attribute__((always_inline)) LaneF& operator-=(LaneF b) { v -= b.v; return *this; }
  __attribute__((always_inline)) LaneF& operator*=(LaneF b) { v *= b.v; return *this; }
  __attribute__((always_inline)) LaneF& operator/=(LaneF b) { v /= b.v; return *this; }
};

struct LaneU {
  U8 v;
  LaneU() = default;
  // NOLINTNEXTLINE(google-explicit-constructor): as LaneF's
  __attribute__((always_inline)) constexpr LaneU(uint32_t s) : v() {
    if (std::is_constant_evaluated()) {
      v = U8{s, s, s, s, s, s, s, s};
    } else {
#if defined(__clang__)
      v = __builtin_shufflevector(U8{s}, U8{s}, 0, 0, 0, 0, 0, 0, 0, 0);
#else
      v = __builtin_shuffle(U8{s}, U8{});
#endif
    }
  }
  __attribute__((always_inline)) constexpr explicit LaneU(U8 x) : v(x) {}
  // uint(f) for 0 <= f < 2^31 (cell and lattice indices; the scalar cast's range too).
  __attribute__((always_inline)) explicit LaneU(LaneF f) : v(reinterpret_cast<U8>(__builtin_convertvector(f.v, I8))) {}
  __attribute__((always_inline)) LaneU& operator^=(LaneU b) { v ^= b.v; return *this; }
  __attribute__((always_inline)) LaneU& operator*=(LaneU b) { v *= b.v; return *this; }
  __attribute__((always_inline)) LaneU& operator+=(LaneU b) { v += b.v; return *this; }
  __attribute__((always_inline)) LaneU& operator&=(LaneU b) { v &= b.v; return *this; }
};

MARBLE_LANE LaneF::LaneF(LaneU u) : v(__builtin_convertvector(u.v, F8)) {}

MARBLE_LANE LaneF operator+(LaneF a, LaneF b) { return LaneF(a.v + b.v); }
MARBLE_LANE LaneF operator-(LaneF a, LaneF b) { return LaneF(a.v - b.v); }
MARBLE_LANE LaneF operator*(LaneF a, LaneF b) { return LaneF(a.v * b.v); }
MARBLE_LANE LaneF operator/(LaneF a, LaneF b) { return LaneF(a.v / b.v); }
MARBLE_LANE LaneF operator-(LaneF a) { return LaneF(-a.v); }
MARBLE_LANE Mask operator<(LaneF a, LaneF b) { return {a.v < b.v}; }
MARBLE_LANE Mask operator<=(LaneF a, LaneF b) { return {a.v <= b.v}; }
MARBLE_LANE Mask operator>(LaneF a, LaneF b) { return {a.v > b.v}; }
MARBLE_LANE Mask operator>=(LaneF a, LaneF b) { return {a.v >= b.v}; }
MARBLE_LANE Mask operator==(LaneF a, LaneF b) { return {a.v == b.v}; }
MARBLE_LANE Mask operator!=(LaneF a, LaneF b) { return {a.v != b.v}; }

MARBLE_LANE LaneU operator+(LaneU a, LaneU b) { return LaneU(a.v + b.v); }
MARBLE_LANE LaneU operator-(LaneU a, LaneU b) { return LaneU(a.v - b.v); }
MARBLE_LANE LaneU operator*(LaneU a, LaneU b) { return LaneU(a.v * b.v); }
MARBLE_LANE LaneU operator^(LaneU a, LaneU b) { return LaneU(a.v ^ b.v); }
MARBLE_LANE LaneU operator&(LaneU a, LaneU b) { return LaneU(a.v & b.v); }
MARBLE_LANE LaneU operator|(LaneU a, LaneU b) { return LaneU(a.v | b.v); }
MARBLE_LANE LaneU operator>>(LaneU a, uint32_t s) { return LaneU(a.v >> s); }
MARBLE_LANE LaneU operator<<(LaneU a, uint32_t s) { return LaneU(a.v << s); }
MARBLE_LANE Mask operator<(LaneU a, LaneU b) { return {reinterpret_cast<I8>(a.v < b.v)}; }
MARBLE_LANE Mask operator>=(LaneU a, LaneU b) { return {reinterpret_cast<I8>(a.v >= b.v)}; }
MARBLE_LANE Mask operator==(LaneU a, LaneU b) { return {reinterpret_cast<I8>(a.v == b.v)}; }

// Per-lane choice: m ? a : b. The uint choice is made on signed lanes with the mask as it is:
// with the mask converted to unsigned lanes GCC 12 no longer sees that it is a comparison's
// (all bits 0 or 1 per lane) and inverts it by a compare with zero before each byte blend
// (336 of them in shadeBatch); the same lanes are chosen either way.
MARBLE_LANE LaneF select(Mask m, LaneF a, LaneF b) { return LaneF(m.v ? a.v : b.v); }
MARBLE_LANE LaneU select(Mask m, LaneU a, LaneU b) {
  return LaneU(reinterpret_cast<U8>(m.v ? reinterpret_cast<I8>(a.v) : reinterpret_cast<I8>(b.v)));
}

// The scalar build's definitions, lane by lane (marble_pattern.cpp): min/max as `a < b ? a : b`.
MARBLE_LANE LaneF min(LaneF a, LaneF b) { return LaneF(a.v < b.v ? a.v : b.v); }
MARBLE_LANE LaneF max(LaneF a, LaneF b) { return LaneF(a.v > b.v ? a.v : b.v); }
MARBLE_LANE LaneF abs(LaneF a) { return LaneF(reinterpret_cast<F8>(reinterpret_cast<U8>(a.v) & 0x7fffffffu)); }
MARBLE_LANE LaneF floor(LaneF x) {
  // Truncation, minus 1 where it rounded up: the scalar floor's integer arithmetic.
  const I8 n = __builtin_convertvector(x.v, I8);
  return LaneF(__builtin_convertvector(n + (x.v < __builtin_convertvector(n, F8)), F8));
}
MARBLE_LANE LaneF sqrt(LaneF x) {
  LaneF r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = std::sqrt(x.v[i]);
  return r;
}
// Rare in the rows (the depth cover, the paper's colour ramp): the scalar functions per lane.
MARBLE_LANE LaneF exp(LaneF x) {
  LaneF r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = std::exp(x.v[i]);
  return r;
}
MARBLE_LANE LaneF sin(LaneF x) {
  LaneF r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = std::sin(x.v[i]);
  return r;
}
MARBLE_LANE LaneF pow(LaneF x, LaneF y) {
  LaneF r;
  for (int i = 0; i < kLanes; ++i) r.v[i] = std::pow(x.v[i], y.v[i]);
  return r;
}

// GLSL's vectors over lanes: component-wise as GLM's (which the scalar build uses).
struct LaneVec2 {
  LaneF x, y;
  LaneVec2() = default;
  __attribute__((always_inline)) explicit LaneVec2(LaneF s) : x(s), y(s) {}
  __attribute__((always_inline)) LaneVec2(LaneF a, LaneF b) : x(a), y(b) {}
};
struct LaneVec3 {
  LaneF x, y, z;
  LaneVec3() = default;
  __attribute__((always_inline)) explicit LaneVec3(LaneF s) : x(s), y(s), z(s) {}
  __attribute__((always_inline)) LaneVec3(LaneF a, LaneF b, LaneF c) : x(a), y(b), z(c) {}
};
struct LaneVec4 {
  LaneF x, y, z, w;
  LaneVec4() = default;
  __attribute__((always_inline)) explicit LaneVec4(LaneF s) : x(s), y(s), z(s), w(s) {}
  __attribute__((always_inline)) LaneVec4(LaneF a, LaneF b, LaneF c, LaneF d) : x(a), y(b), z(c), w(d) {}
};

MARBLE_LANE LaneVec2 operator*(LaneVec2 a, LaneF s) { return {a.x * s, a.y * s}; }
MARBLE_LANE LaneVec2 operator-(LaneVec2 a, LaneVec2 b) { return {a.x - b.x, a.y - b.y}; }
MARBLE_LANE LaneVec2 floor(LaneVec2 a) { return {floor(a.x), floor(a.y)}; }

MARBLE_LANE LaneVec3 operator+(LaneVec3 a, LaneVec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
MARBLE_LANE LaneVec3 operator-(LaneVec3 a, LaneVec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
MARBLE_LANE LaneVec3 operator*(LaneVec3 a, LaneVec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
MARBLE_LANE LaneVec3 operator/(LaneVec3 a, LaneVec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
MARBLE_LANE LaneVec3 operator+(LaneVec3 a, LaneF s) { return {a.x + s, a.y + s, a.z + s}; }
MARBLE_LANE LaneVec3 operator-(LaneVec3 a, LaneF s) { return {a.x - s, a.y - s, a.z - s}; }
MARBLE_LANE LaneVec3 operator*(LaneVec3 a, LaneF s) { return {a.x * s, a.y * s, a.z * s}; }
MARBLE_LANE LaneVec3 operator/(LaneVec3 a, LaneF s) { return {a.x / s, a.y / s, a.z / s}; }
MARBLE_LANE LaneVec3 operator*(LaneF s, LaneVec3 a) { return {s * a.x, s * a.y, s * a.z}; }
MARBLE_LANE LaneVec3 floor(LaneVec3 a) { return {floor(a.x), floor(a.y), floor(a.z)}; }
MARBLE_LANE LaneVec3 abs(LaneVec3 a) { return {abs(a.x), abs(a.y), abs(a.z)}; }
// GLM's dot for vec3: (x*x' + y*y') + z*z'.
MARBLE_LANE LaneF dot(LaneVec3 a, LaneVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace marble::simd

#pragma GCC diagnostic pop
