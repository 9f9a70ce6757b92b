#pragma once
// Temporaries that exist only while a file is being written (atomic_file.cpp). Should marble be
// ended by SIGINT (Ctrl-C), SIGTERM or SIGHUP meanwhile, the signal handler installed here
// removes every registered temporary and then lets the signal end the process as it would have
// (so the exit status still says "killed by SIGINT"). SIGKILL cannot be caught: after it, a
// temporary (".NAME.XXXXXX.tmp" beside the target) can remain; the target itself is never half
// written.
#include <string>

namespace marble {

// A registration; the destructor forgets it. Signals are blocked while the registry changes,
// so the handler never sees a half-made entry.
class LiveTemporary {
public:
  LiveTemporary() = default;
  explicit LiveTemporary(const std::string& path);
  ~LiveTemporary() { forget(); }
  LiveTemporary(LiveTemporary&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
  LiveTemporary& operator=(LiveTemporary&& other) noexcept;
  LiveTemporary(const LiveTemporary&) = delete;
  LiveTemporary& operator=(const LiveTemporary&) = delete;

  void forget();  // the temporary was renamed or removed: nothing to clean up any more

private:
  int slot_ = -1;  // -1: not registered (or the registry was full: then only normal cleanup)
};

// While one exists, the temporaries are being renamed into place: a cleanup signal that arrives
// then is held until the renames are done (a set of files must not end half renamed, half
// removed), and then ends the process as it would have.
class RenamesInProgress {
public:
  RenamesInProgress();
  ~RenamesInProgress();
  RenamesInProgress(const RenamesInProgress&) = delete;
  RenamesInProgress& operator=(const RenamesInProgress&) = delete;
};

// How many temporaries are registered now (tests).
int liveTemporaryCount();

}  // namespace marble
