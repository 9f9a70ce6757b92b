#include "marble/core/live_temporaries.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace marble {
namespace {

constexpr int kSlots = 64;  // marble writes at most a handful of files at once
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Each slot holds a malloc'ed, NUL-terminated path or null. The handler only reads the slots
// and calls unlink(), both async-signal-safe.
std::atomic<char*> gSlots[kSlots];
std::atomic<int> gRenaming{0};       // RenamesInProgress objects alive
std::atomic<int> gHeldSignal{0};     // a signal that came while they were

extern "C" void removeTemporariesAndDie(int sig) {
  if (gRenaming.load() > 0) {
    gHeldSignal.store(sig);
    return;
  }
  for (auto& slot : gSlots)
    if (char* p = slot.load()) ::unlink(p);
  // The default action, so that the parent sees the process ended by this signal. The signal is
  // blocked while its handler runs: the raise() takes effect when the handler returns.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void installHandlerOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kSignals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0) continue;
      // Leave a signal ignored (nohup) or handled by someone else as it is.
      if (!(old.sa_flags & SA_SIGINFO) && old.sa_handler == SIG_DFL) {
        struct sigaction act {};
        act.sa_handler = removeTemporariesAndDie;
        sigemptyset(&act.sa_mask);
        for (int other : kSignals) sigaddset(&act.sa_mask, other);
        ::sigaction(sig, &act, nullptr);
      }
    }
  });
}

// Blocks kSignals for its lifetime (in this thread, which is the one the handler would
// interrupt while the registry changes).
class SignalsBlocked {
public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kSignals) sigaddset(&set, sig);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

private:
  sigset_t old_;
};

}  // namespace

LiveTemporary::LiveTemporary(const std::string& path) {
  installHandlerOnce();
  char* copy = static_cast<char*>(std::malloc(path.size() + 1));
  if (!copy) return;
  std::memcpy(copy, path.c_str(), path.size() + 1);
  SignalsBlocked blocked;
  for (int i = 0; i < kSlots; ++i) {
    char* expected = nullptr;
    if (gSlots[i].compare_exchange_strong(expected, copy)) {
      slot_ = i;
      return;
    }
  }
  std::free(copy);  // full: the temporary is still removed on every ordinary failure path
}

LiveTemporary& LiveTemporary::operator=(LiveTemporary&& other) noexcept {
  if (this != &other) {
    forget();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void LiveTemporary::forget() {
  if (slot_ < 0) return;
  char* p = nullptr;
  {
    SignalsBlocked blocked;
    p = gSlots[slot_].exchange(nullptr);
  }
  std::free(p);
  slot_ = -1;
}

RenamesInProgress::RenamesInProgress() { gRenaming.fetch_add(1); }

RenamesInProgress::~RenamesInProgress() {
  if (gRenaming.fetch_sub(1) == 1) {
    if (const int sig = gHeldSignal.exchange(0); sig != 0) removeTemporariesAndDie(sig);
  }
}

int liveTemporaryCount() {
  int n = 0;
  for (auto& slot : gSlots)
    if (slot.load()) ++n;
  return n;
}

}  // namespace marble
