#!/usr/bin/env bash
# The whole test suite (unit, GL on headless llvmpipe, CLI, viewer under Xvfb) built with
# AddressSanitizer and UndefinedBehaviorSanitizer into build-asan/, and run. Any report fails a
# test: UBSan halts, ASan halts, and LeakSanitizer's exit code fails the test that leaked.
# Leaks inside Mesa/llvmpipe/EGL/LLVM (not ours, not fixable here) are suppressed narrowly in
# tools/lsan.supp. Usage: tools/sanitize.sh [extra ctest arguments]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-asan"
# -g1: line numbers in reports at a fraction of the cost of full debug info.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMARBLE_SANITIZE=ON -DCMAKE_CXX_FLAGS=-g1 >/dev/null
cmake --build "$build" -j"$(nproc)"
# Mesa's driver is dlopen()ed by EGL and dlclose()d by eglTerminate; preloading it keeps it mapped
# to the end, so LeakSanitizer can still read its globals (else what they point to looks leaked)
# and name it in stacks. ASan insists on being first in the library list; this preload is the
# one deliberate exception (verify_asan_link_order=0).
driver=$(ls /usr/lib/*/dri/swrast_dri.so 2>/dev/null | head -n 1 || true)
if [[ -n $driver ]]; then
  export LD_PRELOAD="$driver${LD_PRELOAD:+:$LD_PRELOAD}"
fi
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1:verify_asan_link_order=0
export LSAN_OPTIONS=suppressions="$root/tools/lsan.supp":print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
ctest --output-on-failure -j2 "$@"
