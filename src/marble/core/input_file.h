#pragma once
// The one way marble opens a file it reads (meshes, glTF buffers, scenes, presets, .hdr maps,
// EXR references): only a regular file is opened, so a FIFO, a device (/dev/zero, a tape, a
// terminal) or a socket is refused with a true message instead of blocking or never ending;
// every failure is an InputError naming the file with the real reason (a symlink loop, a
// dangling symlink, a permission, a directory). Sizes come from the open file, so a reader can
// check what a header declares against them before it reads anything large.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "marble/core/page_buffer.h"

namespace marble {

// A file's bytes in memory that no one zeroed first (a std::string is zero-filled: for a 60 MB
// mesh, a memset and every page's fault on one thread before the read), in pages of their own
// that a later array can take over (page_buffer.h).
struct FileBytes {
  PageBuffer pages;
  std::string_view view() const { return {pages.data(), pages.size()}; }
};

class InputFile {
public:
  // `label` names the file in messages (usually the path as the user gave it); `kind` completes
  // "is a directory, not <kind>" ("a mesh file").
  InputFile(const std::filesystem::path& path, std::string label, std::string_view kind = "a file");
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  InputFile(InputFile&& other) noexcept : label_(std::move(other.label_)), fd_(other.fd_), size_(other.size_) { other.fd_ = -1; }
  InputFile& operator=(InputFile&&) = delete;

  uint64_t size() const { return size_; }
  const std::string& label() const { return label_; }

  // The first min(n, size()) bytes.
  std::string readPrefix(size_t n) const;
  // The first min(n, size()) bytes, refusing a file larger than `maxBytes` (InputError
  // "file is N bytes; the limit is M").
  std::string read(uint64_t n, uint64_t maxBytes) const;
  // The whole file, refusing one larger than `maxBytes`.
  std::string readAll(uint64_t maxBytes) const { return read(size_, maxBytes); }
  // What read() reads, for large files: into memory left unset, in ranges of at least 8 MB read by
  // threads at once (each thread's pread copies its range from the page cache and faults in its
  // pages). An error names the range's byte; "shrank" counts from the file's start.
  FileBytes readLarge(uint64_t n, uint64_t maxBytes) const;

private:
  std::string label_;
  int fd_ = -1;
  uint64_t size_ = 0;
};

// InputFile(path, label, kind).readAll(maxBytes).
std::string readInputFile(const std::filesystem::path& path, const std::string& label, uint64_t maxBytes,
                          std::string_view kind = "a file");

}  // namespace marble
