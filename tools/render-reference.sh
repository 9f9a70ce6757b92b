#!/usr/bin/env bash
# Renders tools/reference-scenes/*.json with Blender Cycles (the reference) and with marble in
# its `marble` and `paper` modes, then prints `marble compare` for each and writes the
# side-by-side pictures (Cycles | marble) beside them (docs/quality.md).
#
#   tools/render-reference.sh [OUT_DIR] [--size N] [--samples N] [--skip-cycles] [--floor]
#                             [--models DIR] [--only NAME] [--refs DIR]
#
# --refs DIR takes the Cycles renders from DIR (NAME.cycles.exr, and NAME.cycles-seed1.exr for
# --floor) instead of rendering them: tools/reference-renders/ holds the standing ones at 200 x 200
# (its README says how they were made), so `tools/render-reference.sh out/q --refs
# tools/reference-renders --floor` reproduces docs/quality.md's table in minutes, without Blender.
#
# Samples: --samples N for every scene, or by default each scene's own count (reference_samples
# below), enough that two references differing only in seed score SSIM >= 0.97 against each other
# at 200 x 200 (issue 15, item 6; measured in session 21, docs/quality.md "References that meet
# item 6"): the back-lit scenes' random walks are by far the noisiest.
#
# The method (docs/quality.md, "Method"): Cycles renders N x N directly (default 200) with a box
# pixel filter one pixel wide (cycles_reference.py --box), which is what an 800x800 render
# averaged in 4x4 blocks is; marble renders the same N x N with --supersample 4 (800x800 inside,
# averaged in 4x4 blocks). --floor also renders every scene a second time with another seed and
# compares the two Cycles renders: the reference's own noise, the best any renderer can score.
# Needs Blender (installed here with apt when missing and run as root: only this script needs
# it, so it is not in tools/deps.txt and CI never installs it) and the paper's meshes: the scenes
# name ../../../shared/models/*.obj (the `shared` folder beside the repository); --models DIR
# points them elsewhere (copies of the scenes are written into OUT_DIR/scenes).
# Cycles is CPU-heavy: it runs under `nice -n 19`, 2 threads.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/out/reference"
SIZE=200
SAMPLES=""  # empty: reference_samples
SKIP_CYCLES=0
FLOOR=0
MODELS=""
ONLY=""
REFS=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --size) SIZE="$2"; shift 2 ;;
    --samples) SAMPLES="$2"; shift 2 ;;
    --skip-cycles) SKIP_CYCLES=1; shift ;;
    --floor) FLOOR=1; shift ;;
    --models) MODELS="$(cd "$2" && pwd)"; shift 2 ;;
    --only) ONLY="$2"; shift 2 ;;
    --refs) REFS="$(cd "$2" && pwd)"; shift 2 ;;
    *) OUT="$1"; shift ;;
  esac
done
MARBLE="${MARBLE:-$ROOT/build/marble}"

[[ -n $REFS ]] && SKIP_CYCLES=1
if [[ $SKIP_CYCLES == 0 ]] && ! command -v blender >/dev/null; then
  if [[ $(id -u) == 0 ]]; then
    apt-get install -y blender
  else
    echo "render-reference: blender is missing; run: sudo apt-get install -y blender" >&2
    exit 1
  fi
fi
[[ -x "$MARBLE" ]] || { echo "render-reference: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }
mkdir -p "$OUT/scenes"

# Samples per pixel for a scene's reference where --samples is not given. Measured floors (SSIM of
# two references of that many samples, different seeds, 200 x 200; docs/quality.md): 2048 samples:
# dragon-front 0.990, buddha-front 0.992, bunny-back 0.980, teapot-side 0.985; 4096: dragon-side
# 0.983, buddha-side 0.981, bunny-side 0.983, teapot-back 0.980 (0.966-0.970 at 2048); buddha-back
# 0.978 at 8192 (0.957 at 4096); dragon-back 0.963 at 8192, so twice that.
reference_samples() {
  case "$1" in
    dragon-back) echo 16384 ;;
    buddha-back) echo 8192 ;;
    dragon-side | buddha-side | bunny-side | teapot-back) echo 4096 ;;
    *) echo 2048 ;;
  esac
}

cycles() {  # scene out.exr seed
  if [[ -n $REFS ]]; then
    local kept="$REFS/$(basename "$2")"
    [[ -f $kept ]] || { echo "render-reference: no $kept (--refs)" >&2; exit 1; }
    cp "$kept" "$2"
    return 0
  fi
  [[ $SKIP_CYCLES == 1 && -f "$2" ]] && return 0
  local samples="${SAMPLES:-$(reference_samples "$(basename "$1" .json)")}"
  nice -n 19 blender -b --factory-startup -P "$ROOT/tools/cycles_reference.py" -- "$1" "$2" --samples "$samples" \
    --width "$SIZE" --height "$SIZE" --box --seed "$3" > "${2%.exr}.log" 2>&1
  grep -q "cycles_reference: wrote" "${2%.exr}.log" ||
    { echo "render-reference: Cycles failed on $1, see ${2%.exr}.log" >&2; exit 1; }
}

row() {  # name what ref.exr test.exr
  "$MARBLE" compare "$3" "$4" --json --side-by-side "$OUT/$1.$2.sbs.png" > "$OUT/$1.$2.json"
  python3 - "$OUT/$1.$2.json" "$1" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print("%-14s %-7s %7.4f %7.3f %7.3f %7.4f %7.4f" % (sys.argv[2], sys.argv[3], j["iou"], j["scale"], j["energy_ratio"],
                                                   j["relative_rmse"], j["ssim"]))
PY
}

printf '%-14s %-7s %7s %7s %7s %7s %7s\n' scene vs IoU k energy relRMSE SSIM
for src in "$ROOT"/tools/reference-scenes/*.json; do
  name="$(basename "$src" .json)"
  [[ -n $ONLY && $name != "$ONLY" ]] && continue
  scene="$OUT/scenes/$name.json"
  if [[ -n $MODELS ]]; then
    sed "s#\"\\.\\./\\.\\./\\.\\./shared/models/#\"$MODELS/#" "$src" > "$scene"
  else
    sed "s#\"\\.\\./\\.\\./\\.\\./shared/models/#\"$ROOT/../shared/models/#" "$src" > "$scene"
  fi
  ref="$OUT/$name.cycles.exr"
  if [[ -n $REFS && ! -f $REFS/$name.cycles.exr ]]; then
    echo "$name: no reference in $REFS, skipped"
    continue
  fi
  cycles "$scene" "$ref" 0
  for mode in marble paper; do
    "$MARBLE" render "$scene" --mode "$mode" --width "$SIZE" --height "$SIZE" --supersample 4 \
      -o "$OUT/$name.$mode.png" --hdr "$OUT/$name.$mode.exr" > /dev/null
    row "$name" "$mode" "$ref" "$OUT/$name.$mode.exr"
  done
  if [[ $FLOOR == 1 ]]; then
    cycles "$scene" "$OUT/$name.cycles-seed1.exr" 1
    row "$name" floor "$ref" "$OUT/$name.cycles-seed1.exr"
  fi
done
