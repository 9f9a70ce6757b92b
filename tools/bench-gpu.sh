#!/usr/bin/env bash
# The GPU benchmark of docs/performance.md (issue 20, item 5): on a machine with a GPU, `marble
# bench` on the paper's dragon and on its 1.6 M-triangle subdivision (tools/make-dense-mesh.py,
# the size of a scanned statue), at 800×800, 1920×1080 and 3840×2160, in every motion, plus the
# 1.6 M mesh's load (bench/marble_load_phases, when built) and the camera orbit with interaction detail. One prepared run, so that a
# borrowed machine's minutes go to measuring.
#
#   tools/bench-gpu.sh OUT_DIR [--models DIR] [--frames N] [--quick]
#
# Writes OUT_DIR/gpu.md (the GL renderer, then the tools/bench-matrix.sh table) and
# OUT_DIR/bench.jsonl (every run's whole `marble bench --json` object). --quick runs the dragon at
# 800×800 only (to check the machine first). Needs build/marble (or MARBLE=) and python3. The
# renderer must be a GPU's: the script stops if GL_RENDERER names llvmpipe or softpipe, unless
# MARBLE_BENCH_ANY_GL=1 (to try the script itself on a machine without one).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MARBLE="${MARBLE:-$ROOT/build/marble}"
MODELS="$ROOT/../shared/models"
FRAMES=60
QUICK=0
OUT=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --models) MODELS="$2"; shift 2 ;;
    --frames) FRAMES="$2"; shift 2 ;;
    --quick) QUICK=1; shift ;;
    -*) echo "bench-gpu: unknown option $1" >&2; exit 2 ;;
    *) OUT="$1"; shift ;;
  esac
done
[[ -n $OUT ]] || { echo "usage: tools/bench-gpu.sh OUT_DIR [--models DIR] [--frames N] [--quick]" >&2; exit 2; }
[[ -x "$MARBLE" ]] || { echo "bench-gpu: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }
[[ -f "$MODELS/dragon.obj" ]] || { echo "bench-gpu: $MODELS/dragon.obj: not found (--models DIR)" >&2; exit 1; }
mkdir -p "$OUT"
export MARBLE

# Which GL the benchmark runs on: the first line of the record.
probe=$("$MARBLE" bench --width 64 --height 64 --frames 1 --warmup 0 --json)
renderer=$(python3 -c 'import json,sys; j=json.loads(sys.argv[1]); print(j["gl_renderer"] + " | " + j.get("gl_version", ""))' "$probe")
echo "GL: $renderer"
if [[ $renderer =~ llvmpipe|softpipe ]] && [[ ${MARBLE_BENCH_ANY_GL:-0} != 1 ]]; then
  echo "bench-gpu: GL_RENDERER is a CPU rasterizer ($renderer): not a GPU benchmark" >&2
  exit 1
fi

dense="$OUT/dragon-1.6m.obj"
meshes="$MODELS/dragon.obj@z"
sizes="800x800"
if [[ $QUICK == 0 ]]; then
  [[ -f $dense ]] || python3 "$ROOT/tools/make-dense-mesh.py" "$MODELS/dragon.obj" "$dense" --levels 2
  meshes="$meshes $dense@z"
  sizes="800x800 1920x1080 3840x2160"
fi
runs="floor:camera marble:camera marble:camera:--interaction-detail=on marble:both marble:light marble:params"
runs="$runs marble:scattering marble:pattern marble:none paper:camera paper:both"

{
  echo "GL_RENDERER | GL_VERSION: $renderer"
  echo
  "$ROOT/tools/bench-matrix.sh" --frames "$FRAMES" --warmup 20 --meshes "$meshes" --sizes "$sizes" \
    --runs "$runs" --json-log "$OUT/bench.jsonl"
} | tee "$OUT/gpu.md"

# The load, per phase (the mesh's parse, points, normals, ...), for the record beside the frames.
phases=""
for p in "$(dirname "$MARBLE")/bench/marble_load_phases" "$(dirname "$MARBLE")/marble_load_phases"; do
  [[ -x $p ]] && phases=$p && break
done
if [[ $QUICK == 0 && -n $phases ]]; then
  echo
  "$phases" "$dense" --runs 3 --up z | tee -a "$OUT/gpu.md"
fi
