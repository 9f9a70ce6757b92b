#pragma once
// Every file marble writes goes through here. The bytes go to a fresh temporary in the target's
// folder, are flushed to disk (fsync), and the temporary is renamed over the target, so a reader
// never sees a half-written file and an old file survives a failed or killed write:
//  - the temporary is created exclusively (O_CREAT | O_EXCL, a random name, so it is never a
//    file or a symbolic link someone planted there) and named ".NAME.XXXXXX.tmp", with NAME cut
//    so the whole fits NAME_MAX (a 250-character target name works);
//  - a target that exists keeps its permission bits (and its owner and group where the process
//    may set them); a new file gets 0666 less the umask, as any program's would;
//  - a target that is a symbolic link to a regular file replaces the file the link points to
//    (the link stays a link); a target that is a directory, a device (/dev/null), a FIFO or a
//    socket is refused with one line: it is never replaced by a regular file;
//  - on every failure the temporary is removed and the target left as it was; on SIGINT,
//    SIGTERM and SIGHUP too (core/live_temporaries.h).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

namespace marble {

// Writes `bytes` to `path` atomically. Throws InputError naming the path on failure.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// Files that belong together (marble render's PNG and --hdr EXR, marble texture's stages):
// each is written to its temporary as it is added; commit() renames them all into place, one
// after the other, only once every one was written. A failure while adding leaves every target
// as it was; destroying the set without commit() removes its temporaries. Should a rename itself
// fail part way (the folder vanished), the earlier ones stay done and the error says which.
class AtomicFileSet {
public:
  AtomicFileSet();
  ~AtomicFileSet();
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;

  void add(const std::filesystem::path& path, std::string_view bytes);  // throws InputError
  void commit();                                                       // throws InputError

private:
  struct Pending;
  std::vector<std::unique_ptr<Pending>> pending_;
};

// Test hook: called after a temporary is written and flushed, before it may be renamed;
// throwing from it simulates a crash/disk-full mid-write. Null in normal use.
void setAtomicWriteFaultHookForTesting(std::function<void()> hook);

}  // namespace marble
