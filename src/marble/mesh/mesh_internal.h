#pragma once
// Shared pieces of the mesh loaders (not part of the public API; see mesh.h).
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>

#include "marble/core/error.h"
#include "marble/core/input_file.h"
#include "marble/mesh/mesh.h"

namespace marble::mesh_detail {

// Hard caps, checked before anything of that size is allocated.
inline constexpr uint64_t kMaxVertices = 50'000'000;
inline constexpr uint64_t kMaxTriangles = 50'000'000;
inline constexpr uint64_t kMaxFileBytes = 4ull << 30;  // 4 GiB

// "50,000,000"
std::string withThousands(uint64_t n);

// Reads a whole file through InputFile (regular files only); throws InputError(label, "", ...)
// for missing, non-regular, unreadable, empty or oversized files.
std::string readWholeFile(const std::filesystem::path& path, const std::string& label);
// The first `bytes` bytes of an opened mesh file (refusing an empty or oversized one).
std::string readMeshBytes(const InputFile& in, uint64_t bytes);

// How many bytes of an STL file of `fileSize` bytes the loader needs, from its first
// kStlProbeBytes (`head`): a binary STL's header declares its triangle count, so a file far
// larger than that (a 4 GB sparse file declaring no triangle) is refused or read only as far as
// the triangles go, before anything large is read. Throws the loader's header errors.
inline constexpr size_t kStlProbeBytes = 512;
uint64_t stlBytesToRead(const std::string& file, std::string_view head, uint64_t fileSize);

// Each loader returns the mesh as stored in the file: positions, indices, and normals/texcoords
// only when the file supplies one per position (otherwise empty). Every index is in range and
// every position finite; errors are InputError naming `file` and the place.
Mesh loadObj(const std::string& file, std::string_view data);
// loadObj's parallel path with a given number of chunks (loadObj picks kObjChunksPerThread per
// core for large files; one thread per chunk at most); the same mesh and, on bad input, the same
// error as the sequential scan (tested).
// `joined` (optional) is set to whether the chunks' scans were used (false: the sequential scan ran).
Mesh loadObjInChunks(const std::string& file, std::string_view data, unsigned chunks, bool* joined = nullptr);
// Text formats are cut into one chunk per core from this size on (OBJ, ASCII PLY and STL): below a
// few MB a thread's start and the join cost more than they save. Binary PLY decodes over threads
// from the same size.
inline constexpr size_t kTextBytesPerChunk = 4u << 20;
// A large OBJ is cut into this many chunks per thread (but none under kObjMinChunkBytes), which the
// threads take in turn: their costs differ (vertex and face lines), and a thread left with one
// chunk while the other has finished waits at most that chunk's scan (~1/16 of the file's on 2 cores).
inline constexpr size_t kObjChunksPerThread = 8;
inline constexpr size_t kObjMinChunkBytes = 1u << 20;
Mesh loadPly(const std::string& file, std::string_view data);
// loadPly with the body's large elements read in `parts` parts (1: front to back, as the messages
// are defined); the same mesh and, on bad input, the same error for any count (tested).
// `parallel` (optional) is set to whether the parts' reads were used for every large element.
Mesh loadPlyInParts(const std::string& file, std::string_view data, unsigned parts, bool* parallel = nullptr);
Mesh loadStl(const std::string& file, std::string_view data);
// loadStl's parallel path for an ASCII STL, cut into `chunks` at 'facet' lines (`joined` as for
// loadObjInChunks): the same mesh and error as one chunk (tested). A binary STL is read in one
// pass (its cost is the weld's cache misses, which threads did not cut).
Mesh loadStlAsciiInChunks(const std::string& file, std::string_view data, unsigned chunks, bool* joined = nullptr);
// glTF buffers are read only from inside `baseDir` unless `allowOutside` (docs/reliability.md).
Mesh loadGltf(const std::string& file, std::string_view data, const std::filesystem::path& baseDir, bool allowOutside = false);
Mesh loadGlb(const std::string& file, std::string_view data, const std::filesystem::path& baseDir, bool allowOutside = false);

// Throws InputError(file, "byte N", ...) if a text format holds a NUL byte (binary garbage).
void rejectBinary(const std::string& file, std::string_view data, std::string_view format);

inline std::string lineAt(size_t line) { return "line " + std::to_string(line); }
inline std::string byteAt(size_t byte) { return "byte " + std::to_string(byte); }

// The common short decimal ("-0.1234567", "12.5") read exactly, without std::from_chars: for a
// float at most 9 digits whose value m is at most 2^24, at most 10 of them after the point; for a
// double at most 15 digits (m < 10^15 < 2^53), at most 15 after the point; no exponent. Then m and
// 10^k are exact and one IEEE division rounds m / 10^k correctly, which is the value nearest the
// decimal: what from_chars gives (Clinger's fast path: W. D. Clinger, "How to read floating point
// numbers accurately", PLDI 1990). Returns nullptr for anything else (the caller then uses
// from_chars). tests/mesh_parse_float_test.cpp compares it with from_chars on millions of
// decimals. (from_chars was ≈ 30 % of a 60 MB OBJ's parse; this path reads %.7g output.)
template <class T>
const char* parseShortDecimal(const char* p, const char* end, T& out) {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
  constexpr bool kFloat = std::is_same_v<T, float>;
  constexpr int kMaxDigits = kFloat ? 9 : 15, kMaxFraction = kFloat ? 10 : 15;
  constexpr uint64_t kMaxExact = kFloat ? (1u << 24) : (1ull << 53);
  constexpr T kPow10[16] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  const bool negative = p < end && *p == '-';
  const char* q = p + (negative ? 1 : 0);
  uint64_t m = 0;
  int digits = 0, fraction = 0;
  auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  for (; q < end && isDigit(*q); ++q, ++digits) {
    if (digits == kMaxDigits) return nullptr;
    m = m * 10 + static_cast<uint64_t>(*q - '0');
  }
  if (q < end && *q == '.') {
    for (++q; q < end && isDigit(*q); ++q, ++digits, ++fraction) {
      if (digits == kMaxDigits) return nullptr;
      m = m * 10 + static_cast<uint64_t>(*q - '0');
    }
  }
  if (digits == 0 || m > kMaxExact || fraction > kMaxFraction || (q < end && (*q == 'e' || *q == 'E'))) return nullptr;
  const T value = static_cast<T>(m) / kPow10[fraction];
  out = negative ? -value : value;
  return q;
}

// The number of decimal digits at the start of the 8 bytes at p (0 to 8) and, when fewer than 8,
// their value: all 8 bytes looked at in a few word operations instead of a loop per digit with a
// branch and a multiply-add chain (the OBJ parse's face indices). A byte c is a digit exactly when
// c ^ '0' is 0-9; the value comes from combining neighbouring digits, then pairs, then fours
// (each lane's sum stays below its width, so no lane carries into the next). The caller makes
// sure 8 bytes are there to read.
inline int leadingDigits(const char* p, uint64_t& value) {
  uint64_t chunk;
  std::memcpy(&chunk, p, 8);
  const uint64_t x = chunk ^ 0x3030303030303030ull;  // a digit's byte becomes 0-9 (byte 0 the first)
  // A byte's top bit: set when x >= 0x80, or when x + 0x76 reaches 0x80 (x >= 10); x & 0x7F keeps
  // the sum in the byte.
  const uint64_t nonDigit = (x | ((x & 0x7F7F7F7F7F7F7F7Full) + 0x7676767676767676ull)) & 0x8080808080808080ull;
  if (nonDigit == 0) return 8;
  const int n = std::countr_zero(nonDigit) / 8;
  if (n == 0) {
    value = 0;
    return 0;
  }
  uint64_t v = x << (8 * (8 - n));  // the n digits as the last of eight, zeros before them
  v = (v * 10 + (v >> 8)) & 0x00FF00FF00FF00FFull;
  v = (v * 100 + (v >> 16)) & 0x0000FFFF0000FFFFull;
  v = (v * 10000 + (v >> 32)) & 0xFFFFFFFFull;
  value = v;
  return n;
}

// A forgiving float parser: optional leading '+', then the short decimal's exact path or
// std::from_chars (general format; accepts "nan"/"inf", which callers reject with a located
// message).
inline const char* parseFloat(const char* p, const char* end, float& out) {
  if (p < end && *p == '+') ++p;
  if (const char* after = parseShortDecimal(p, end, out)) return after;
  auto [ptr, ec] = std::from_chars(p, end, out);
  if (ec == std::errc{}) return ptr;
  if (ec != std::errc::result_out_of_range) return nullptr;
  // Out of float range: from_chars leaves `out` untouched, so decide by hand.
  double d = 0;
  if (std::from_chars(p, end, d).ec == std::errc{}) {
    out = static_cast<float>(d);  // inf when too large, 0 or denormal when tiny
    return ptr;
  }
  std::string_view text(p, static_cast<size_t>(ptr - p));
  bool tiny = text.find("e-") != std::string_view::npos || text.find("E-") != std::string_view::npos;
  out = tiny ? 0.0f : (text.front() == '-' ? -HUGE_VALF : HUGE_VALF);
  return ptr;
}

inline bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

inline bool equalsIgnoreCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

// Whitespace-separated tokens with line numbers (PLY and STL ASCII bodies).
struct TextCursor {
  const char* p;
  const char* end;
  size_t line = 1;

  // Skips whitespace including newlines; returns false at end of data.
  bool skipWhitespace() {
    while (p < end) {
      char c = *p;
      if (c == '\n') {
        ++line;
      } else if (!isSpace(c)) {
        return true;
      }
      ++p;
    }
    return false;
  }
  // Next token, or empty at end of data.
  std::string_view token() {
    if (!skipWhitespace()) return {};
    const char* s = p;
    while (p < end && !isSpace(*p) && *p != '\n') ++p;
    return {s, static_cast<size_t>(p - s)};
  }
  // Rest of the current line (without the newline); moves past it.
  std::string_view restOfLine() {
    const char* s = p;
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    const char* e = nl ? nl : end;
    p = nl ? nl + 1 : end;
    if (nl) ++line;
    while (e > s && isSpace(e[-1])) --e;
    return {s, static_cast<size_t>(e - s)};
  }
};

}  // namespace marble::mesh_detail
