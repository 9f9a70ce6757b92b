#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/, clang++ with ASan+UBSan) into build-fuzz/ and runs
# each for SECONDS (default 30), starting from the seed corpora in tests/fuzz/corpus/<target>/.
# What a run discovers is kept in build-fuzz/corpus/<target>/ (the seeds stay untouched), so a
# second run continues where the first stopped. A crash, a leak, undefined behaviour, a hang
# (>10 s for one input) or an out-of-memory stops the script with a non-zero exit; the input
# is saved as build-fuzz/findings/<target>/crash-* (or leak-, timeout-, oom-) and its report
# as build-fuzz/findings/<target>/log.
# Usage: tools/fuzz.sh [SECONDS] [TARGET ...]   targets: obj ply stl gltf glb scene preset hdr
# FUZZ_KEEP_GOING=1: libFuzzer's fork mode, which records a crash and keeps fuzzing (for long
# local runs while a known crash is unfixed); the status columns then come from its last line.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-30}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(obj ply stl gltf glb scene preset hdr)

command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (tools/setup.sh installs it)" >&2; exit 1; }
build="$root/build-fuzz"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMARBLE_FUZZ=ON >/dev/null
cmake --build "$build" --target fuzz_all -j"$(nproc)"

# The harness writes each input to a file; RAM-backed /dev/shm keeps that off the disk.
[[ -d /dev/shm && -w /dev/shm ]] && export TMPDIR=/dev/shm
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

printf '%-7s %8s %10s %9s %7s %7s %7s\n' target seconds execs exec/s cov ft corpus
status=0
for t in "${targets[@]}"; do
  work="$build/corpus/$t"
  findings="$build/findings/$t"
  mkdir -p "$work" "$findings"
  rm -f "$findings"/*  # this run's findings only
  dict=()
  [[ -f "$root/tests/fuzz/$t.dict" ]] && dict=(-dict="$root/tests/fuzz/$t.dict")
  log="$findings/log"
  keep=()
  [[ ${FUZZ_KEEP_GOING:-0} == 1 ]] && keep=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
  if ! "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -print_final_stats=1 -artifact_prefix="$findings/" "${dict[@]}" "${keep[@]}" "$work" "$root/tests/fuzz/corpus/$t" >"$log" 2>&1; then
    echo "fuzz.sh: fuzz_$t found a problem; report in $log, input(s):" >&2
    ls "$findings" | grep -v '^log$' | sed "s|^|  $findings/|" >&2 || true
    grep -m1 -E 'ERROR|runtime error|SUMMARY' "$log" >&2 || tail -n 20 "$log" >&2
    status=1
    continue
  fi
  # The last status line ("#N DONE cov: C ft: F corp: K/...") and the final stats.
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
  if ((${#keep[@]})) && grep -q 'crash: [0-9]*/[0-9]*/[1-9]' <<<"$last"; then
    echo "fuzz.sh: fuzz_$t crashed (kept going): $(ls "$findings" | grep -c -v '^log$') input(s) in $findings" >&2
    status=1
  fi
  cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
  ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
  corp=$(sed -nE 's/.* corp: ([0-9]+).*/\1/p' <<<"$last")
  execs=$(sed -nE 's/^stat::number_of_executed_units:\s+([0-9]+)/\1/p' "$log")
  rate=$(sed -nE 's/^stat::average_exec_per_sec:\s+([0-9]+)/\1/p' "$log")
  # Fork mode prints no final stats: take them from the status line.
  [[ -n $execs ]] || execs=$(sed -nE 's/^#([0-9]+).*/\1/p' <<<"$last")
  [[ -n $rate ]] || rate=$(sed -nE 's/.* exec\/s:? ([0-9]+).*/\1/p' <<<"$last")
  printf '%-7s %8s %10s %9s %7s %7s %7s\n' "$t" "$seconds" "$execs" "$rate" "$cov" "$ft" "$corp"
done
exit $status
