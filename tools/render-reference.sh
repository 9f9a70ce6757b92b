#!/usr/bin/env bash
# Renders tools/reference-scenes/*.json with Blender Cycles (the reference) and with marble in
# its `marble` and `paper` modes, then prints `marble compare` for each (docs/quality.md).
#
#   tools/render-reference.sh [OUT_DIR] [--samples N] [--skip-cycles]
#
# Needs Blender (installed here with apt when missing and run as root: only this script needs
# it, so it is not in tools/deps.txt and CI never installs it) and the paper's meshes in
# ../shared/models beside the repository (the scenes reference ../../../shared/models/*.obj).
# Each Cycles render is 256x256, 64 samples, CPU, 2 threads: about a minute on two cores.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/out/reference"
SAMPLES=64
SKIP_CYCLES=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --samples) SAMPLES="$2"; shift 2 ;;
    --skip-cycles) SKIP_CYCLES=1; shift ;;
    *) OUT="$1"; shift ;;
  esac
done
MARBLE="${MARBLE:-$ROOT/build/marble}"

if [[ $SKIP_CYCLES == 0 ]] && ! command -v blender >/dev/null; then
  if [[ $(id -u) == 0 ]]; then
    apt-get install -y blender
  else
    echo "render-reference: blender is missing; run: sudo apt-get install -y blender" >&2
    exit 1
  fi
fi
[[ -x "$MARBLE" ]] || { echo "render-reference: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }
mkdir -p "$OUT"

printf '%-14s %-11s %7s %7s %7s %7s\n' scene mode IoU k relRMSE SSIM
for scene in "$ROOT"/tools/reference-scenes/*.json; do
  name="$(basename "$scene" .json)"
  ref="$OUT/$name.cycles.exr"
  if [[ $SKIP_CYCLES == 0 || ! -f "$ref" ]]; then
    blender -b --factory-startup -P "$ROOT/tools/cycles_reference.py" -- "$scene" "$ref" --samples "$SAMPLES" \
      > "$OUT/$name.cycles.log" 2>&1 || { echo "render-reference: Cycles failed on $name, see $OUT/$name.cycles.log" >&2; exit 1; }
  fi
  # marble-full: the marble mode with its subsurface blur at full resolution (the default is half).
  for mode in marble marble-full paper; do
    args=(--mode "${mode%-full}")
    [[ $mode == *-full ]] && args+=(--subsurface-resolution full)
    "$MARBLE" render "$scene" "${args[@]}" -o "$OUT/$name.$mode.png" --hdr "$OUT/$name.$mode.exr" > /dev/null
    "$MARBLE" compare "$ref" "$OUT/$name.$mode.exr" --json > "$OUT/$name.$mode.json"
    python3 - "$OUT/$name.$mode.json" "$name" "$mode" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print("%-14s %-11s %7.4f %7.3f %7.4f %7.4f" % (sys.argv[2], sys.argv[3], j["iou"], j["scale"], j["relative_rmse"], j["ssim"]))
PY
  done
done
