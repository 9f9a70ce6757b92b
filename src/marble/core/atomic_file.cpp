#include "marble/core/atomic_file.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "marble/core/error.h"
#include "marble/core/live_temporaries.h"

namespace marble {
namespace {

std::function<void()>& faultHook() {
  static std::function<void()> hook;
  return hook;
}

std::string errnoText(int err) { return std::strerror(err); }

std::string whatItIs(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Six random characters from [a-z0-9].
std::string randomSuffix() {
  unsigned char raw[6];
  if (::getrandom(raw, sizeof raw, 0) != static_cast<ssize_t>(sizeof raw)) {
    // getrandom cannot fail for 6 bytes once the pool is initialized; fall back to the clock.
    const auto t = static_cast<unsigned long long>(::getpid()) * 2654435761ull ^ static_cast<unsigned long long>(clock());
    for (size_t i = 0; i < sizeof raw; ++i) raw[i] = static_cast<unsigned char>(t >> (8 * i));
  }
  static const char alphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::string s;
  for (unsigned char b : raw) s += alphabet[b % 36];
  return s;
}

// ".NAME.XXXXXX.tmp" with NAME cut (at a UTF-8 character boundary) so the whole fits NAME_MAX.
std::string temporaryName(const std::string& targetName) {
  constexpr size_t kOverhead = 1 + 1 + 6 + 4;  // "." NAME "." XXXXXX ".tmp"
  std::string name = targetName;
  if (name.size() + kOverhead > NAME_MAX) {
    size_t cut = NAME_MAX - kOverhead;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0u) == 0x80u) --cut;
    name.resize(cut);
  }
  return "." + name + "." + randomSuffix() + ".tmp";
}

// The signals that remove temporaries are blocked while one is created and registered, so that
// no temporary exists unregistered.
class CleanupSignalsBlocked {
public:
  CleanupSignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~CleanupSignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

private:
  sigset_t old_;
};

}  // namespace

struct AtomicFileSet::Pending {
  std::string label;           // the target as the caller named it (messages)
  std::filesystem::path target;  // where the rename goes (a symbolic link's file)
  std::filesystem::path temp;
  LiveTemporary registration;
  bool renamed = false;

  ~Pending() {
    if (!renamed && !temp.empty()) ::unlink(temp.c_str());
  }
};

AtomicFileSet::AtomicFileSet() = default;
AtomicFileSet::~AtomicFileSet() = default;  // each Pending removes its temporary

void AtomicFileSet::add(const std::filesystem::path& path, std::string_view bytes) {
  auto p = std::make_unique<Pending>();
  p->label = path.string();
  const std::string& label = p->label;
  if (path.empty() || !path.has_filename()) throw InputError(label.empty() ? "\"\"" : label, "", "is not a file name");

  // What is there now decides where the rename goes and what mode the new file gets.
  std::filesystem::path target = path;
  struct stat st {};
  bool exists = false;
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode)) {
      if (::stat(path.c_str(), &st) != 0)
        throw InputError(label, "", "is a symbolic link to nothing (" + errnoText(errno) + "); not writing through it");
      std::error_code ec;
      target = std::filesystem::canonical(path, ec);
      if (ec) throw InputError(label, "", "cannot resolve the symbolic link: " + ec.message());
    }
    exists = true;
    if (S_ISDIR(st.st_mode)) throw InputError(label, "", "is a directory, not a file");
    if (!S_ISREG(st.st_mode))
      throw InputError(label, "", "is " + whatItIs(st.st_mode) + ", not a regular file; refusing to replace it");
  } else if (errno != ENOENT) {
    throw InputError(label, "", "cannot write: " + errnoText(errno));
  }
  p->target = target;

  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    const std::filesystem::path temp = folder / temporaryName(target.filename().string());
    CleanupSignalsBlocked blocked;
    // O_EXCL: created here and now, never an existing file or a planted symbolic link.
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd >= 0) {
      p->temp = temp;
      p->registration = LiveTemporary(temp.string());
    } else if (errno != EEXIST) {
      throw InputError(label, "", "cannot write: " + errnoText(errno));
    }
  }
  if (fd < 0) throw InputError(label, "", "cannot write: no free temporary name in its folder");

  auto fail = [&](const std::string& why) {
    ::close(fd);
    throw InputError(label, "", why);  // ~Pending removes the temporary
  };
  if (exists) {
    // The replacement keeps what the old file had: owner and group where allowed (only root, or
    // an owner changing to one of its groups), then the permission bits (chown may clear setuid).
    if (::fchown(fd, st.st_uid, st.st_gid) != 0) { /* not permitted: the new file is ours */ }
    if (::fchmod(fd, st.st_mode & 07777) != 0) fail("cannot set the file's mode: " + errnoText(errno));
  }
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed: " + errnoText(errno));
    }
    done += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) fail("fsync failed: " + errnoText(errno));
  if (faultHook()) {
    try {
      faultHook()();
    } catch (const std::exception& e) {
      fail(std::string("write interrupted: ") + e.what());
    }
  }
  if (::close(fd) != 0) throw InputError(label, "", "close failed: " + errnoText(errno));
  pending_.push_back(std::move(p));
}

void AtomicFileSet::commit() {
  const RenamesInProgress renaming;  // Ctrl-C now waits until every file is in place
  for (auto& p : pending_) {
    if (::rename(p->temp.c_str(), p->target.c_str()) != 0) {
      const int err = errno;
      std::string done;
      for (auto& q : pending_)
        if (q->renamed) done += (done.empty() ? "" : ", ") + q->label;
      throw InputError(p->label, "", "cannot rename into place: " + errnoText(err) +
                                         (done.empty() ? std::string() : " (already written: " + done + ")"));
    }
    p->renamed = true;
    p->registration.forget();
    // The rename is durable once the folder is flushed too.
    const std::filesystem::path folder = p->target.has_parent_path() ? p->target.parent_path() : ".";
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
      ::fsync(dir);
      ::close(dir);
    }
  }
  pending_.clear();
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  AtomicFileSet set;
  set.add(path, bytes);
  set.commit();
}

void setAtomicWriteFaultHookForTesting(std::function<void()> hook) { faultHook() = std::move(hook); }

}  // namespace marble
