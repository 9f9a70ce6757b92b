#include "marble/core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "marble/core/error.h"
#include "marble/core/parallel_for.h"

namespace marble {
namespace {

std::string withThousands(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// What a stat() failure means for the user.
std::string whyUnreachable(int err, const std::filesystem::path& path) {
  switch (err) {
    case ENOENT: {
      struct stat link {};
      if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
        return "is a symbolic link to a file that does not exist";
      return "file not found";
    }
    case ELOOP: return "too many levels of symbolic links (a symbolic link loop?)";
    case EACCES: return "permission denied (a folder on the path cannot be searched)";
    case ENOTDIR: return "file not found (a part of the path is a file, not a folder)";
    case ENAMETOOLONG: return "the file name is too long";
    default: return std::string("cannot open: ") + std::strerror(err);
  }
}

// Empty for a regular file, else what it is instead.
std::string notRegular(mode_t mode, std::string_view kind) {
  if (S_ISREG(mode)) return {};
  if (S_ISDIR(mode)) return "is a directory, not " + std::string(kind);
  if (S_ISFIFO(mode)) return "is a named pipe (FIFO), not a regular file; marble reads only regular files";
  if (S_ISCHR(mode)) return "is a character device, not a regular file; marble reads only regular files";
  if (S_ISBLK(mode)) return "is a block device, not a regular file; marble reads only regular files";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file; marble reads only regular files";
  return "is not a regular file";
}

// Reads bytes [offset, offset + count) of the file into `out`; `total` (the whole read's size)
// for the message when the file ends first.
void readRange(int fd, const std::string& label, char* out, uint64_t offset, size_t count, uint64_t total) {
  size_t done = 0;
  while (done < count) {
    const ssize_t got = ::pread(fd, out + done, count - done, static_cast<off_t>(offset + done));
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputError(label, "byte " + std::to_string(offset + done), std::string("read error: ") + std::strerror(errno));
    }
    if (got == 0)
      throw InputError(label, "", "the file shrank while it was read (" + withThousands(offset + done) + " of " +
                                      withThousands(total) + " bytes)");
    done += static_cast<size_t>(got);
  }
}

// Below this many bytes per thread a read runs on one (a thread's start would cost more).
constexpr size_t kBytesPerReadThread = 8u << 20;

}  // namespace

InputFile::InputFile(const std::filesystem::path& path, std::string label, std::string_view kind)
    : label_(std::move(label)) {
  // stat first: a FIFO or a device is refused without being opened (opening a FIFO blocks until
  // a writer comes; opening some devices has effects of its own).
  struct stat st {};
  if (path.empty()) throw InputError(label_.empty() ? "\"\"" : label_, "", "file not found (empty path)");
  if (::stat(path.c_str(), &st) != 0) throw InputError(label_, "", whyUnreachable(errno, path));
  if (std::string why = notRegular(st.st_mode, kind); !why.empty()) throw InputError(label_, "", why);
  // O_NONBLOCK: should the path be swapped for a FIFO between stat and open, open still returns.
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd_ < 0) {
    const int err = errno;
    throw InputError(label_, "", err == EACCES ? "permission denied" : whyUnreachable(err, path));
  }
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string why = notRegular(st.st_mode, kind);
    ::close(fd_);
    throw InputError(label_, "", why.empty() ? "cannot read its size" : why);
  }
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
  size_ = static_cast<uint64_t>(st.st_size);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::string InputFile::readPrefix(size_t n) const {
  return read(n, UINT64_MAX);
}

std::string InputFile::read(uint64_t n, uint64_t maxBytes) const {
  if (size_ > maxBytes)
    throw InputError(label_, "", "file is " + withThousands(size_) + " bytes; the limit is " + withThousands(maxBytes));
  if (n > size_) n = size_;
  std::string data(static_cast<size_t>(n), '\0');
  readRange(fd_, label_, data.data(), 0, data.size(), data.size());
  return data;
}

FileBytes InputFile::readLarge(uint64_t n, uint64_t maxBytes) const {
  if (size_ > maxBytes)
    throw InputError(label_, "", "file is " + withThousands(size_) + " bytes; the limit is " + withThousands(maxBytes));
  if (n > size_) n = size_;
  FileBytes bytes{PageBuffer(static_cast<size_t>(n))};
  parallelFor(bytes.pages.size(), kBytesPerReadThread, [&](size_t begin, size_t end) {
    readRange(fd_, label_, bytes.pages.data() + begin, begin, end - begin, bytes.pages.size());
  });
  return bytes;
}

std::string readInputFile(const std::filesystem::path& path, const std::string& label, uint64_t maxBytes,
                          std::string_view kind) {
  return InputFile(path, label, kind).readAll(maxBytes);
}

}  // namespace marble
