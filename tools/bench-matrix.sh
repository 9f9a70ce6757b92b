#!/usr/bin/env bash
# The frame benchmark matrix of docs/performance.md: for each mesh and size, `marble bench` with
# each mode/motion, one markdown row per run (frame median, min-max, p90; CPU of all threads;
# per-pass medians with how often each pass ran; the load average when the row was taken).
#
#   tools/bench-matrix.sh [--frames N] [--warmup K] [--meshes "a.obj@z b.obj"] [--sizes "800x800 1920x1080"]
#                         [--runs "marble:camera floor:camera ..."]   (MESH@AXIS: the up axis, default y)
#
# Meshes default to the paper's dragon, bunny and buddha in ../shared/models (not part of the
# repository; pass others with --meshes). Needs build/marble (tools/setup.sh builds it).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MARBLE="${MARBLE:-$ROOT/build/marble}"
MODELS="$ROOT/../shared/models"
FRAMES=20
WARMUP=3
MESHES="$MODELS/dragon.obj@z $MODELS/bunny.obj@y $MODELS/buddha.obj@z"
SIZES="800x800 1920x1080"
RUNS="floor:camera marble:camera marble:both marble:light marble:params marble:scattering marble:pattern marble:none"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --frames) FRAMES="$2"; shift 2 ;;
    --warmup) WARMUP="$2"; shift 2 ;;
    --meshes) MESHES="$2"; shift 2 ;;
    --sizes) SIZES="$2"; shift 2 ;;
    --runs) RUNS="$2"; shift 2 ;;
    *) echo "bench-matrix: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -x "$MARBLE" ]] || { echo "bench-matrix: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }

echo "| mesh | size | mode | motion | frame ms median (min–max, p90) | CPU ms/frame (all threads) | passes, median ms per frame (ran/frames) | load avg |"
echo "| --- | --- | --- | --- | --- | ---: | --- | ---: |"
for entry in $MESHES; do
  mesh="${entry%@*}"
  up="${entry##*@}"
  [[ $up == "$entry" ]] && up=y
  for size in $SIZES; do
    for run in $RUNS; do
      mode="${run%%:*}"
      motion="${run##*:}"
      json=$("$MARBLE" bench "$mesh" --up "$up" --width "${size%x*}" --height "${size#*x}" --mode "$mode" \
        --motion "$motion" --frames "$FRAMES" --warmup "$WARMUP" --json)
      load=$(cut -d' ' -f1 /proc/loadavg)
      python3 - "$json" "$(basename "$mesh" .obj)" "${size/x/×}" "$load" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
runs = j["pass_runs"]
passes = ", ".join("%s %.1f (%d/%d)" % (k, v, runs.get(k, j["frames"]), j["frames"]) for k, v in j["passes"].items())
print("| %s | %s | %s | %s | %.1f (%.1f–%.1f, %.1f) | %.1f | %s | %s |" % (
    sys.argv[2], sys.argv[3], j["mode"], j["motion"], j["frame_ms_median"], j["frame_ms_min"], j["frame_ms_max"],
    j["frame_ms_p90"], j["cpu_process_ms_median"], passes, sys.argv[4]))
PY
    done
  done
done
