#pragma once
// Memory of its own pages (an anonymous mapping) for a load's large arrays, whose resize keeps the
// pages it already has (within its mapping, or by mremap: the page tables move, the bytes are not
// copied). So one array can take over another's memory: loadMesh reads the file into one, and once
// the file is parsed the crease normals' per-triangle records are written into the same pages. A
// page's first write costs a fault (≈ 1.4 µs on the project's 2-core VM: 27 ms of CPU for 77 MB);
// the reused ones were faulted once, by the read.
//
// A released mapping is kept for the next buffer (one, the largest up to kTrimThresholdBytes: what
// a later load's file and records take again, faulted in already), as glibc keeps up to that much
// freed heap memory for reuse (allocator_tuning.h); releaseKeptPages() gives it back to the
// system. (The cost: a loaded 1.6 M-triangle mesh leaves 77 MB kept; the memory's peak does not grow.)
#include <cstddef>

namespace marble {

class PageBuffer {
public:
  PageBuffer() = default;
  // `bytes` unset; throws std::bad_alloc.
  explicit PageBuffer(size_t bytes) { resize(bytes); }
  ~PageBuffer() { release(); }
  PageBuffer(PageBuffer&& other) noexcept;
  PageBuffer& operator=(PageBuffer&& other) noexcept;
  PageBuffer(const PageBuffer&) = delete;
  PageBuffer& operator=(const PageBuffer&) = delete;

  // The first min(old, new) bytes kept, the rest unset; the data may move. Throws std::bad_alloc.
  void resize(size_t bytes);
  char* data() const { return data_; }
  size_t size() const { return size_; }

private:
  void release() noexcept;
  char* data_ = nullptr;
  size_t size_ = 0;
  size_t mapped_ = 0;  // the mapping's bytes (whole pages, >= size_)
};

// Unmaps the mapping kept for reuse, if any.
void releaseKeptPages();

}  // namespace marble
