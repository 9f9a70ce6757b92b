#!/usr/bin/env bash
# The frame benchmark matrix of docs/performance.md: for each mesh and size, `marble bench` with
# each mode/motion, one markdown row per run (frame median, min-max, p90; CPU of all threads;
# per-pass medians with how often each pass ran; the load average when the row was taken).
#
#   tools/bench-matrix.sh [--frames N] [--warmup K] [--meshes "a.obj@z b.obj"] [--sizes "800x800 1920x1080"]
#                         [--runs "marble:camera floor:camera ..."] [--repeat N] [--json-log FILE]
#
# MESH@AXIS: the up axis (default y). A run is MODE:MOTION, optionally :OPTIONS, more `marble bench`
# options joined by commas (e.g. marble:both:--interaction-detail=on,--light-proxy=off).
# --repeat N runs the whole matrix N times over, interleaved (each repetition runs every row once,
# in turn, so a shared machine's drift hits all rows alike), prints every row with its repetition,
# then one summary row per configuration: the median over the repetitions of the frame medians,
# with each repetition's value (the form docs/performance.md reports).
# --json-log FILE appends each run's whole `marble bench --json` object to FILE, one per line, with
# the row's mesh, size, options and repetition added (for a machine whose runs are not repeated,
# e.g. a borrowed GPU: tools/bench-gpu.sh). Times under 10 ms are printed with two decimals (a GPU's
# frames are a fraction of a millisecond), longer ones with one.
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
REPEAT=1
JSON_LOG=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --frames) FRAMES="$2"; shift 2 ;;
    --warmup) WARMUP="$2"; shift 2 ;;
    --meshes) MESHES="$2"; shift 2 ;;
    --sizes) SIZES="$2"; shift 2 ;;
    --runs) RUNS="$2"; shift 2 ;;
    --repeat) REPEAT="$2"; shift 2 ;;
    --json-log) JSON_LOG="$2"; shift 2 ;;
    *) echo "bench-matrix: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -x "$MARBLE" ]] || { echo "bench-matrix: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }
[[ "$REPEAT" =~ ^[1-9][0-9]*$ ]] || { echo "bench-matrix: --repeat: expected a positive count, got $REPEAT" >&2; exit 2; }
medians=$(mktemp)
trap 'rm -f "$medians"' EXIT

echo "| mesh | size | mode | motion | options | rep | frame ms median (min–max, p90) | CPU ms/frame (all threads) | passes, median ms per frame (ran/frames) | load avg |"
echo "| --- | --- | --- | --- | --- | ---: | --- | ---: | --- | ---: |"
for ((rep = 1; rep <= REPEAT; rep++)); do
  for entry in $MESHES; do
    mesh="${entry%@*}"
    up="${entry##*@}"
    [[ $up == "$entry" ]] && up=y
    for size in $SIZES; do
      for run in $RUNS; do
        IFS=: read -r mode motion options <<<"$run"
        extra=()
        [[ -n $options ]] && IFS=, read -r -a extra <<<"$options"
        json=$("$MARBLE" bench "$mesh" --up "$up" --width "${size%x*}" --height "${size#*x}" --mode "$mode" \
          --motion "$motion" --frames "$FRAMES" --warmup "$WARMUP" "${extra[@]}" --json)
        load=$(cut -d' ' -f1 /proc/loadavg)
        python3 - "$json" "$(basename "$mesh" .obj)" "${size/x/×}" "$load" "${options:--}" "$rep" "$medians" "$JSON_LOG" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
def ms(v):  # two decimals below 10 ms (a GPU's passes), one above
    return "%.2f" % v if v < 10 else "%.1f" % v
runs = j["pass_runs"]
passes = ", ".join("%s %s (%d/%d)" % (k, ms(v), runs.get(k, j["frames"]), j["frames"]) for k, v in j["passes"].items())
row = "| %s | %s | %s | %s | %s |" % (sys.argv[2], sys.argv[3], j["mode"], j["motion"], sys.argv[5])
print("%s %s | %s (%s–%s, %s) | %s | %s | %s |" % (
    row, sys.argv[6], ms(j["frame_ms_median"]), ms(j["frame_ms_min"]), ms(j["frame_ms_max"]), ms(j["frame_ms_p90"]),
    ms(j["cpu_process_ms_median"]), passes, sys.argv[4]))
with open(sys.argv[7], "a") as f:
    f.write("%s\t%s\t%s\n" % (row, ms(j["frame_ms_median"]), sys.argv[4]))
if sys.argv[8]:
    j.update({"row_mesh": sys.argv[2], "row_size": sys.argv[3], "row_options": sys.argv[5], "row_rep": int(sys.argv[6])})
    with open(sys.argv[8], "a") as f:
        f.write(json.dumps(j) + "\n")
PY
      done
    done
  done
done
if ((REPEAT > 1)); then
  echo
  echo "| mesh | size | mode | motion | options | frame ms, median of $REPEAT repetitions (each) | load avg |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  python3 - "$medians" <<'PY'
import statistics, sys
rows, loads = {}, {}
for line in open(sys.argv[1]):
    row, value, load = line.rstrip("\n").split("\t")
    rows.setdefault(row, []).append(float(value))
    loads.setdefault(row, []).append(load)
for row, values in rows.items():
    print("%s %.2f (%s) | %s |" % (row, statistics.median(values), ", ".join("%.2f" % v for v in values),
                                   "–".join(sorted(set(loads[row]), key=float)[::max(1, len(set(loads[row])) - 1)])))
PY
fi
