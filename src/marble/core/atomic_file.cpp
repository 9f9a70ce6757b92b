#include "marble/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <string>

#include "marble/core/error.h"

namespace marble {
namespace {
std::function<void()>& faultHook() {
  static std::function<void()> hook;
  return hook;
}

std::filesystem::path temporaryBeside(const std::filesystem::path& path) {
  std::random_device rd;
  std::string name = "." + path.filename().string() + ".tmp-" + std::to_string(rd());
  return path.has_parent_path() ? path.parent_path() / name : std::filesystem::path(name);
}
}  // namespace

void setAtomicWriteFaultHookForTesting(std::function<void()> hook) { faultHook() = std::move(hook); }

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  const std::string target = path.string();
  if (std::filesystem::is_directory(path)) throw InputError(target, "", "is a directory, not a file");
  const auto tmp = temporaryBeside(path);
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(target, "", std::string("cannot write: ") + std::strerror(errno));
  auto fail = [&](const std::string& why) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw InputError(target, "", why);
  };
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(std::string("write failed: ") + std::strerror(errno));
    }
    done += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) fail(std::string("fsync failed: ") + std::strerror(errno));
  if (faultHook()) {
    try {
      faultHook()();
    } catch (const std::exception& e) {
      fail(std::string("write interrupted: ") + e.what());
    }
  }
  if (::close(fd) != 0) {
    ::unlink(tmp.c_str());
    throw InputError(target, "", std::string("close failed: ") + std::strerror(errno));
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    ::unlink(tmp.c_str());
    throw InputError(target, "", std::string("cannot rename into place: ") + std::strerror(err));
  }
}

}  // namespace marble
