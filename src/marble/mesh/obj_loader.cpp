// Wavefront OBJ: v, vt, vn and f (v, v/vt, v//vn, v/vt/vn; negative = relative), polygons as fans.
// Everything else (o, g, s, usemtl, mtllib, l, p, vp, comments) is ignored.
//
// Speed: the whole file is in memory; a hand-written scanner, std::from_chars for numbers. A large
// file is cut at line boundaries into several chunks per core, which the threads take in turn as
// they finish one (a face line costs more per byte than a vertex line, so equal halves left one
// thread waiting), scan -- each checking its own bytes for NULs first -- and join in file order
// (loadObjInChunks). Anything unusual in a chunk -- a NUL, an error, a relative (negative) index,
// whose meaning depends on the counts before the chunk -- sends the whole file through the
// one-pass scanner instead, so every error message (file, line, problem) is the sequential
// scanner's own. When no face uses texture coordinates or normals, OBJ vertex i is render vertex i
// (no hashing). Otherwise each distinct (v, vt, vn) triple becomes one render vertex through an
// open-addressing hash table.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "marble/core/parallel_for.h"
#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::mesh_detail {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

struct Corner {
  uint32_t v, vt, vn;
};

// The faces' corners, one column per attribute. A file of positions only (the common large case)
// then writes and copies 4 bytes a corner, not 12. An attribute's column holds the first corners'
// values up to its size; a corner beyond it has none (kNone), so the column stays empty until a
// corner names one.
struct CornerColumns {
  std::vector<uint32_t> v, vt, vn;

  size_t size() const { return v.size(); }
  Corner operator[](size_t i) const { return {v[i], i < vt.size() ? vt[i] : kNone, i < vn.size() ? vn[i] : kNone}; }
  void push(const Corner& c) {
    v.push_back(c.v);
    pushAttribute(vt, c.vt);
    pushAttribute(vn, c.vn);
  }
  // A later chunk's corners after these.
  void append(CornerColumns&& next) {
    const size_t before = v.size();
    if (v.empty()) v = std::move(next.v);
    else v.insert(v.end(), next.v.begin(), next.v.end());
    for (auto [mine, theirs] : {std::pair{&vt, &next.vt}, {&vn, &next.vn}})
      if (!theirs->empty()) {
        mine->resize(before, kNone);
        mine->insert(mine->end(), theirs->begin(), theirs->end());
      }
  }

private:
  void pushAttribute(std::vector<uint32_t>& column, uint32_t value) {
    if (value == kNone && column.empty()) return;
    column.resize(v.size() - 1, kNone);  // the corners before this one without it
    column.push_back(value);
  }
};

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Largest positive index seen for one attribute, checked against the final count at the end so
// that (rare, but legal in practice) forward references work.
struct PendingMax {
  uint64_t index = 0;
  size_t line = 0;
};

// Thrown by a chunk's scan for what only the sequential scan can judge (see the top of the file).
struct NeedsSequentialScan {};

class ObjParser {
public:
  // `chunk`: this is one chunk of a larger file (line numbers and counts are the chunk's own, so
  // any problem throws NeedsSequentialScan or an InputError the caller discards).
  ObjParser(const std::string& file, std::string_view data, bool chunk = false)
      : file_(file), p_(data.data()), end_(data.data() + data.size()), chunk_(chunk) {}

  Mesh parse() {
    scan();
    return build();
  }

  // The statements only (v, vt, vn, f); build() or join() afterwards.
  void scan() {
    // A UTF-8 byte order mark, at the start of the file only (elsewhere it is binary data).
    if (!chunk_ && end_ - p_ >= 3 && std::memcmp(p_, "\xEF\xBB\xBF", 3) == 0) p_ += 3;
    reserveForStatements();
    while (p_ < end_) {
      while (p_ < end_ && (*p_ == ' ' || *p_ == '\t')) ++p_;
      if (p_ >= end_) break;
      const char c = *p_;
      const char d = p_ + 1 < end_ ? p_[1] : '\n';
      if (c == 'v') {
        if (isBlank(d)) {
          p_ += 1;
          parsePosition();
        } else if (d == 't' && p_ + 2 < end_ && isBlank(p_[2])) {
          p_ += 2;
          parseTexcoord();
        } else if (d == 'n' && p_ + 2 < end_ && isBlank(p_[2])) {
          p_ += 2;
          parseNormal();
        }
      } else if (c == 'f' && isBlank(d)) {
        p_ += 1;
        parseFace();
      } else if (c != '\n' && c != '\r' && c != '#' &&
                 (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)) {
        fail("unexpected binary data (not a text OBJ file?)");
      }
      skipLine();
    }
  }

  // Appends a later chunk's statements (scanned with chunk = true) to this one's.
  void join(ObjParser&& next) {
    positions_.insert(positions_.end(), next.positions_.begin(), next.positions_.end());
    texcoords_.insert(texcoords_.end(), next.texcoords_.begin(), next.texcoords_.end());
    normals_.insert(normals_.end(), next.normals_.begin(), next.normals_.end());
    corners_.append(std::move(next.corners_));
    for (auto [mine, theirs] : {std::pair{&maxV_, &next.maxV_}, {&maxVt_, &next.maxVt_}, {&maxVn_, &next.maxVn_}})
      mine->index = std::max(mine->index, theirs->index);
    anyVt_ = anyVt_ || next.anyVt_;
    anyVn_ = anyVn_ || next.anyVn_;
    allVt_ = allVt_ && next.allVt_;
    allVn_ = allVn_ && next.allVn_;
  }

  // The mesh from chunks scanned in file order, built without joining their arrays first, when no
  // face uses texture coordinates or normals (then OBJ vertex i is render vertex i): each chunk's
  // positions and corner indices are copied straight into place, on threads. (Joining first copied
  // every later chunk's corners onto the first's, which meant a fresh allocation of all of them.)
  // nullopt when the joined statements need the general build or are not clean (joinedIsClean).
  static std::optional<Mesh> buildPositionsOnly(std::vector<std::optional<ObjParser>>& chunks) {
    bool anyVt = false, anyVn = false, allVt = true, allVn = true;
    size_t positions = 0, texcoords = 0, normals = 0, corners = 0;
    uint64_t maxV = 0;
    std::vector<size_t> positionAt, cornerAt;
    for (const auto& c : chunks) {
      anyVt = anyVt || c->anyVt_;
      anyVn = anyVn || c->anyVn_;
      allVt = allVt && c->allVt_;
      allVn = allVn && c->allVn_;
      positionAt.push_back(positions);
      cornerAt.push_back(corners);
      positions += c->positions_.size();
      texcoords += c->texcoords_.size();
      normals += c->normals_.size();
      corners += c->corners_.size();
      maxV = std::max(maxV, c->maxV_.index);
    }
    if ((anyVt && allVt) || (anyVn && allVn)) return std::nullopt;
    if (positions > kMaxVertices || texcoords > kMaxVertices || normals > kMaxVertices || corners / 3 > kMaxTriangles ||
        maxV > positions)
      return std::nullopt;
    Mesh mesh;
    mesh.positions.reserve(capacityForCreaseCopies(positions));
    mesh.positions.resize(positions);
    mesh.indices.resize(corners);
    // Each chunk's arrays are freed by the thread that copied them (not all on the calling thread
    // when `chunks` goes).
    parallelForEachInTurn(chunks.size(), [&](size_t i) {
      ObjParser& c = *chunks[i];
      std::copy(c.positions_.begin(), c.positions_.end(), mesh.positions.begin() + static_cast<std::ptrdiff_t>(positionAt[i]));
      uint32_t* out = mesh.indices.data() + cornerAt[i];
      std::copy(c.corners_.v.begin(), c.corners_.v.end(), out);
      c.releaseStatements();
    });
    return mesh;
  }

  void releaseStatements() {
    std::vector<glm::vec3>().swap(positions_);
    corners_ = CornerColumns();
  }

  // Whether the joined chunks are within every limit and every index in range; when not, the
  // sequential scan finds the first problem and its line.
  bool joinedIsClean() const {
    const bool useVt = anyVt_ && allVt_, useVn = anyVn_ && allVn_;
    return positions_.size() <= kMaxVertices && texcoords_.size() <= kMaxVertices && normals_.size() <= kMaxVertices &&
           corners_.size() / 3 <= kMaxTriangles && maxV_.index <= positions_.size() &&
           (!useVt || maxVt_.index <= texcoords_.size()) && (!useVn || maxVn_.index <= normals_.size());
  }

private:
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(file_, lineAt(line_), problem); }
  [[noreturn]] void failAt(size_t line, const std::string& problem) const {
    throw InputError(file_, lineAt(line), problem);
  }

  // Room for the positions and triangles of a large file before it is scanned, which saves growing
  // the arrays by doubling (their copies and fresh pages cost ≈ 1/4 of the scan). The counts are
  // estimated from up to 32 windows of 32 KB spread over the data: lines starting "v " and "f " (three
  // corners each: a polygon's extra corners grow the array as before), scaled to the whole and
  // given 1/8 more; capped so a garbage file cannot ask for much. (Counting every line start cost
  // ≈ 1/10 of the scan; an estimate that falls short only means one doubling.)
  void reserveForStatements() {
    constexpr size_t kWorthIt = 1u << 20, kWindow = 32u << 10;
    const size_t size = static_cast<size_t>(end_ - p_);
    if (size < kWorthIt) return;
    // One window per MB, 4 to 32 of them: a file's few-MB chunks sample ~1/32 of their bytes.
    const size_t kWindows = std::clamp<size_t>(size >> 20, 4, 32);
    size_t vLines = 0, fLines = 0, sampled = 0;
    for (size_t w = 0; w < kWindows; ++w) {
      const char* q = p_ + (size - kWindow) / (kWindows - 1) * w;
      const char* windowEnd = q + kWindow;
      sampled += kWindow;
      // From the first line start in the window (the data's start counts as one).
      if (q != p_) {
        const void* nl = std::memchr(q, '\n', kWindow);
        if (!nl) continue;
        q = static_cast<const char*>(nl) + 1;
      }
      while (q + 1 < windowEnd) {
        if (q[1] == ' ' || q[1] == '\t') {
          vLines += q[0] == 'v';
          fLines += q[0] == 'f';
        }
        const void* nl = std::memchr(q, '\n', static_cast<size_t>(windowEnd - q));
        if (!nl) break;
        q = static_cast<const char*>(nl) + 1;
      }
    }
    const double scale = static_cast<double>(size) / static_cast<double>(sampled) * 1.125;
    positions_.reserve(std::min<size_t>(static_cast<size_t>(static_cast<double>(vLines) * scale), kMaxVertices));
    corners_.v.reserve(3 * std::min<size_t>(static_cast<size_t>(static_cast<double>(fLines) * scale), kMaxTriangles));
  }

  void skipLine() {
    if (p_ < end_ && *p_ == '\n') {  // where a statement's scan usually stops
      ++p_;
      ++line_;
      return;
    }
    const void* nl = std::memchr(p_, '\n', static_cast<size_t>(end_ - p_));
    if (nl) {
      p_ = static_cast<const char*>(nl) + 1;
      ++line_;
    } else {
      p_ = end_;
    }
  }

  std::string tokenHere() const {
    const char* e = p_;
    while (e < end_ && !isBlank(*e) && *e != '\n' && e - p_ < 24) ++e;
    return std::string(p_, e);
  }

  float number(const char* statement, int needed) {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t')) ++p_;
    if (p_ >= end_ || *p_ == '\n' || *p_ == '\r' || *p_ == '#')
      fail(std::string("'") + statement + "' needs " + std::to_string(needed) + (needed == 1 ? " number" : " numbers"));
    float value = 0.0f;
    const char* after = parseFloat(p_, end_, value);
    if (!after || (after < end_ && !isBlank(*after) && *after != '\n' && *after != '#'))
      fail(std::string("'") + statement + "': expected a number, found '" + tokenHere() + "'");
    if (!std::isfinite(value)) fail(std::string("'") + statement + "': number is NaN or infinite ('" + tokenHere() + "')");
    p_ = after;
    return value;
  }

  void parsePosition() {
    if (positions_.size() >= kMaxVertices)
      fail("more than " + withThousands(kMaxVertices) + " vertices (the limit)");
    float x = number("v", 3), y = number("v", 3), z = number("v", 3);
    positions_.emplace_back(x, y, z);
  }
  void parseTexcoord() {
    if (texcoords_.size() >= kMaxVertices)
      fail("more than " + withThousands(kMaxVertices) + " texture coordinates (the limit)");
    float u = number("vt", 1);
    float v = 0.0f;
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t')) ++p_;
    if (p_ < end_ && *p_ != '\n' && *p_ != '\r' && *p_ != '#') v = number("vt", 1);
    texcoords_.emplace_back(u, v);
  }
  void parseNormal() {
    if (normals_.size() >= kMaxVertices)
      fail("more than " + withThousands(kMaxVertices) + " normals (the limit)");
    float x = number("vn", 3), y = number("vn", 3), z = number("vn", 3);
    normals_.emplace_back(x, y, z);
  }

  // One index of a face corner; returns it 0-based. The common case (1 to 10 digits, positive, no
  // sign) in a few instructions with the position in a register; anything else is read again by
  // indexInFull, which judges it and words the message.
  uint32_t index(size_t count, PendingMax& pending, const char* what, const char* plural) {
    const char* q = p_;
    uint64_t value = 0;
    // Up to 7 digits (10 million vertices) in a few word operations where 8 bytes are there to
    // read (leadingDigits); 8 or more digits, or the chunk's last bytes, digit by digit.
    int digits = 8;
    if (end_ - q >= 8) digits = leadingDigits(q, value);
    if (digits < 8) {
      q += digits;
    } else {
      value = 0;
      const char* digitsEnd = q + std::min<std::ptrdiff_t>(end_ - q, 10);
      while (q < digitsEnd && isDigit(*q)) value = value * 10 + static_cast<uint64_t>(*q++ - '0');
    }
    if (value == 0 || value > 0xFFFFFFFEull || (q < end_ && isDigit(*q)))
      return indexInFull(count, pending, what, plural);
    p_ = q;
    if (value > pending.index) {
      pending.index = value;
      pending.line = line_;
    }
    return static_cast<uint32_t>(value - 1);
  }

  [[gnu::noinline]] uint32_t indexInFull(size_t count, PendingMax& pending, const char* what, const char* plural) {
    bool negative = false;
    if (p_ < end_ && (*p_ == '-' || *p_ == '+')) {
      negative = *p_ == '-';
      ++p_;
    }
    if (p_ >= end_ || !isDigit(*p_)) fail("bad face vertex '" + tokenHere() + "'");
    uint64_t value = 0;
    // Up to 10 digits cannot overflow 64 bits: one range check after them, not one per digit.
    const char* digitsEnd = p_ + std::min<std::ptrdiff_t>(end_ - p_, 10);
    while (p_ < digitsEnd && isDigit(*p_)) value = value * 10 + static_cast<uint64_t>(*p_++ - '0');
    for (; p_ < end_ && isDigit(*p_); ++p_) {  // more digits (leading zeros?): checked one by one
      value = value * 10 + static_cast<uint64_t>(*p_ - '0');
      if (value > 0xFFFFFFFEull) fail(std::string(what) + " index is too large");
    }
    if (value > 0xFFFFFFFEull) fail(std::string(what) + " index is too large");
    if (value == 0) fail(std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
    if (negative) {
      if (chunk_) throw NeedsSequentialScan{};  // relative to counts this chunk does not know
      if (value > count)
        fail(std::string("relative ") + what + " index -" + std::to_string(value) + " is out of range (only " +
             std::to_string(count) + " " + plural + " defined so far)");
      return static_cast<uint32_t>(count - value);
    }
    if (value > pending.index) {
      pending.index = value;
      pending.line = line_;
    }
    return static_cast<uint32_t>(value - 1);
  }

  void parseFace() {
    polygon_.clear();
    for (;;) {
      while (p_ < end_ && isBlank(*p_)) ++p_;
      if (p_ >= end_ || *p_ == '\n' || *p_ == '#') break;
      Corner c{index(positions_.size(), maxV_, "vertex", "vertices"), kNone, kNone};
      if (p_ < end_ && *p_ == '/') {
        ++p_;
        if (p_ < end_ && *p_ != '/') c.vt = index(texcoords_.size(), maxVt_, "texture coordinate", "texture coordinates");
        if (p_ < end_ && *p_ == '/') {
          ++p_;
          c.vn = index(normals_.size(), maxVn_, "normal", "normals");
        }
      }
      if (p_ < end_ && !isBlank(*p_) && *p_ != '\n' && *p_ != '#') fail("bad face vertex near '" + tokenHere() + "'");
      polygon_.push_back(c);
    }
    if (polygon_.size() < 3)
      fail("face has " + std::to_string(polygon_.size()) + " vertices; a face needs at least 3");
    const uint64_t triangles = corners_.size() / 3 + polygon_.size() - 2;
    if (triangles > kMaxTriangles) fail("more than " + withThousands(kMaxTriangles) + " triangles (the limit)");
    for (const Corner& c : polygon_) {
      allVt_ = allVt_ && c.vt != kNone;
      allVn_ = allVn_ && c.vn != kNone;
      anyVt_ = anyVt_ || c.vt != kNone;
      anyVn_ = anyVn_ || c.vn != kNone;
    }
    for (size_t i = 1; i + 1 < polygon_.size(); ++i) {
      corners_.push(polygon_[0]);
      corners_.push(polygon_[i]);
      corners_.push(polygon_[i + 1]);
    }
  }

  void checkPending(const PendingMax& pending, size_t count, const char* what, const char* plural) const {
    if (pending.index > count)
      failAt(pending.line, std::string(what) + " index " + std::to_string(pending.index) + " is out of range (the file has " +
                               withThousands(count) + " " + plural + ")");
  }

public:
  // The mesh from the scanned (or joined) statements; checks the indices resolved at the end.
  Mesh build() {
    checkPending(maxV_, positions_.size(), "vertex", "vertices");
    const bool useVt = anyVt_ && allVt_;
    const bool useVn = anyVn_ && allVn_;
    if (useVt) checkPending(maxVt_, texcoords_.size(), "texture coordinate", "texture coordinates");
    if (useVn) checkPending(maxVn_, normals_.size(), "normal", "normals");

    Mesh mesh;
    if (!useVt && !useVn) {
      // Fast path: OBJ vertex i is render vertex i.
      mesh.indices.resize(corners_.size());
      std::copy(corners_.v.begin(), corners_.v.end(), mesh.indices.begin());
      mesh.positions = std::move(positions_);
      return mesh;
    }

    // Split vertices by (v, vt, vn): open addressing, linear probing, load factor <= 1/2.
    size_t capacity = 16;
    while (capacity < corners_.size() * 2) capacity *= 2;
    std::vector<Corner> keys(capacity, Corner{kNone, kNone, kNone});
    std::vector<uint32_t> values(capacity);
    const size_t mask = capacity - 1;
    mesh.indices.reserve(corners_.size());
    for (size_t i = 0; i < corners_.size(); ++i) {
      const Corner raw = corners_[i];
      const Corner c{raw.v, useVt ? raw.vt : kNone, useVn ? raw.vn : kNone};
      uint64_t h = (static_cast<uint64_t>(c.v) * 0x9E3779B97F4A7C15ull) ^
                   (static_cast<uint64_t>(c.vt) * 0xC2B2AE3D27D4EB4Full) ^ (static_cast<uint64_t>(c.vn) * 0x165667B19E3779F9ull);
      h ^= h >> 29;
      size_t slot = static_cast<size_t>(h) & mask;
      for (;;) {
        Corner& k = keys[slot];
        if (k.v == kNone) {
          k = c;
          values[slot] = static_cast<uint32_t>(mesh.positions.size());
          mesh.indices.push_back(values[slot]);
          mesh.positions.push_back(positions_[c.v]);
          if (useVt) mesh.texcoords.push_back(texcoords_[c.vt]);
          if (useVn) mesh.normals.push_back(normals_[c.vn]);
          break;
        }
        if (k.v == c.v && k.vt == c.vt && k.vn == c.vn) {
          mesh.indices.push_back(values[slot]);
          break;
        }
        slot = (slot + 1) & mask;
      }
    }
    if (mesh.positions.size() > kMaxVertices)
      throw InputError(file_, "", "more than " + withThousands(kMaxVertices) + " distinct vertices (the limit)");
    return mesh;
  }

private:
  const std::string& file_;
  const char* p_;
  const char* end_;
  bool chunk_;
  size_t line_ = 1;
  std::vector<glm::vec3> positions_;
  std::vector<glm::vec2> texcoords_;
  std::vector<glm::vec3> normals_;
  CornerColumns corners_;  // three per triangle
  std::vector<Corner> polygon_;
  PendingMax maxV_, maxVt_, maxVn_;
  bool anyVt_ = false, anyVn_ = false, allVt_ = true, allVn_ = true;
};

}  // namespace

Mesh loadObjInChunks(const std::string& file, std::string_view data, unsigned chunks, bool* joined) {
  if (joined) *joined = false;
  // Chunk boundaries just after a newline (a chunk may be empty: a file of few, long lines).
  std::vector<std::string_view> parts;
  size_t begin = 0;
  for (unsigned i = 1; i <= chunks && begin < data.size(); ++i) {
    size_t end = i == chunks ? data.size() : std::max(begin, data.size() * i / chunks);
    if (end < data.size()) {
      const size_t nl = data.find('\n', end);
      end = nl == std::string_view::npos ? data.size() : nl + 1;
    }
    parts.push_back(data.substr(begin, end - begin));
    begin = end;
  }
  if (parts.size() > 1) {
    std::vector<std::optional<ObjParser>> parsers(parts.size());
    // Set by the first chunk that needs the sequential scan: the others then stop early.
    std::atomic<bool> sequential{false};
    parallelForEachInTurn(parts.size(), [&](size_t i) {
      if (sequential.load(std::memory_order_relaxed)) return;
      // A NUL byte anywhere: the sequential path names the first (rejectBinary).
      if (std::memchr(parts[i].data(), '\0', parts[i].size())) {
        sequential = true;
        return;
      }
      try {
        parsers[i].emplace(file, parts[i], /*chunk=*/i > 0);
        parsers[i]->scan();
      } catch (const NeedsSequentialScan&) {
        sequential = true;
      } catch (const InputError&) {
        sequential = true;
      }
    });
    try {
      if (!sequential) {
        if (std::optional<Mesh> mesh = ObjParser::buildPositionsOnly(parsers)) {
          if (joined) *joined = true;
          return std::move(*mesh);
        }
        for (size_t i = 1; i < parsers.size(); ++i) parsers[0]->join(std::move(*parsers[i]));
        if (parsers[0]->joinedIsClean()) {
          Mesh mesh = parsers[0]->build();
          if (joined) *joined = true;
          return mesh;
        }
      }
    } catch (const InputError&) {  // a limit the joined file exceeds: the sequential scan words it
    }
  }
  rejectBinary(file, data, "OBJ");
  return ObjParser(file, data).parse();
}

Mesh loadObj(const std::string& file, std::string_view data) {
  const unsigned threads = workerThreadCount(data.size(), kTextBytesPerChunk);
  if (threads <= 1) {
    rejectBinary(file, data, "OBJ");
    return ObjParser(file, data).parse();
  }
  const size_t chunks = std::min<size_t>(size_t{threads} * kObjChunksPerThread, data.size() / kObjMinChunkBytes);
  return loadObjInChunks(file, data, static_cast<unsigned>(std::max<size_t>(chunks, threads)));
}

}  // namespace marble::mesh_detail
