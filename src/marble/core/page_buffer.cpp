#include "marble/core/page_buffer.h"

#include <sys/mman.h>
#include <unistd.h>

#include <mutex>
#include <new>
#include <utility>

#include "marble/core/allocator_tuning.h"

namespace marble {
namespace {

size_t wholePages(size_t bytes) {
  static const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
  return (bytes + page - 1) / page * page;
}

// The one mapping kept for reuse.
struct Kept {
  std::mutex mutex;
  char* data = nullptr;
  size_t mapped = 0;
};
Kept& kept() {
  static Kept k;
  return k;
}

}  // namespace

PageBuffer::PageBuffer(PageBuffer&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, 0)) {}

PageBuffer& PageBuffer::operator=(PageBuffer&& other) noexcept {
  if (this != &other) {
    release();
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, 0);
  }
  return *this;
}

void PageBuffer::release() noexcept {
  if (!data_) return;
  char* unmap = data_;
  size_t unmapBytes = mapped_;
  {
    // Keep the larger of this mapping and the kept one, up to what the heap keeps free
    // (allocator_tuning.h); unmap the other.
    Kept& k = kept();
    std::lock_guard lock(k.mutex);
    if (mapped_ > k.mapped && mapped_ <= static_cast<size_t>(kTrimThresholdBytes)) {
      std::swap(unmap, k.data);
      std::swap(unmapBytes, k.mapped);
    }
  }
  if (unmap) ::munmap(unmap, unmapBytes);
  data_ = nullptr;
  size_ = mapped_ = 0;
}

void PageBuffer::resize(size_t bytes) {
  if (!data_ && bytes > 0) {
    Kept& k = kept();
    std::lock_guard lock(k.mutex);
    data_ = std::exchange(k.data, nullptr);
    mapped_ = std::exchange(k.mapped, 0);
  }
  const size_t needed = wholePages(bytes);
  if (needed > mapped_) {
    void* p = data_ ? ::mremap(data_, mapped_, needed, MREMAP_MAYMOVE)
                    : ::mmap(nullptr, needed, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<char*>(p);
    mapped_ = needed;
  }
  size_ = bytes;
}

void releaseKeptPages() {
  Kept& k = kept();
  std::lock_guard lock(k.mutex);
  if (k.data) ::munmap(k.data, k.mapped);
  k.data = nullptr;
  k.mapped = 0;
}

}  // namespace marble
