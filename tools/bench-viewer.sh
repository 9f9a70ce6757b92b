#!/usr/bin/env bash
# Frame times of the viewer in a window, measured the way the paper's program was (issue 8): the
# window under Xvfb with its panel, one value per frame from Mesa's GALLIUM_HUD=frametime written
# to GALLIUM_HUD_DUMP_DIR; prints the median, p10 and p90 over the frames after the first ten.
#
#   tools/bench-viewer.sh [MESH[@UP]] [--turntable object|light|off] [--frames N] [--view WxH] [-- VIEW OPTIONS]
#
# Options after `--` go to `marble view` (e.g. `-- --interaction-detail off --interaction-resolution 1`
# for the full picture in every frame, `-- --interaction-light-maps off` for the light's maps at
# full size while the object turns).
# MESH defaults to ../shared/models/dragon.obj@z (not part of the repository). The window is the
# view plus the panel (390 pixels at scale 1), so --view 800x800 opens a 1190x800 window.
# `object` turns the model every frame: every pass re-runs, as the paper's program does each frame.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MARBLE="${MARBLE:-$ROOT/build/marble}"
MESH="$ROOT/../shared/models/dragon.obj@z"
TURNTABLE=object
FRAMES=120
VIEW=800x800
PANEL=390
EXTRA=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --turntable) TURNTABLE="$2"; shift 2 ;;
    --frames) FRAMES="$2"; shift 2 ;;
    --view) VIEW="$2"; shift 2 ;;
    --) shift; EXTRA=("$@"); break ;;
    -*) echo "bench-viewer: unknown option $1" >&2; exit 2 ;;
    *) MESH="$1"; shift ;;
  esac
done
[[ -x "$MARBLE" ]] || { echo "bench-viewer: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "bench-viewer: xvfb-run is missing (tools/setup.sh installs it)" >&2; exit 1; }
[[ "$FRAMES" =~ ^[0-9]+$ && "$FRAMES" -gt 20 ]] || { echo "bench-viewer: --frames: expected more than 20, got $FRAMES" >&2; exit 2; }
mesh="${MESH%@*}"
up="${MESH##*@}"
[[ $up == "$MESH" ]] && up=y
width=$(( ${VIEW%x*} + PANEL ))
height=${VIEW#*x}
dump=$(mktemp -d)
trap 'rm -rf "$dump"' EXIT
GALLIUM_HUD=frametime GALLIUM_HUD_DUMP_DIR="$dump" xvfb-run -a -s "-screen 0 $((width + 64))x$((height + 64))x24" \
  "$MARBLE" view "$mesh" --up "$up" --width "$width" --height "$height" --frames "$FRAMES" \
  --turntable "$TURNTABLE" "${EXTRA[@]}" >/dev/null
python3 - "$dump" "$(basename "$mesh")" "$VIEW" "$TURNTABLE" <<'PY'
import glob, sys
values = []
for f in glob.glob(sys.argv[1] + "/frametime*"):
    values += [float(l) for l in open(f) if l.strip()]
v = sorted(values[10:])
if not v:
    sys.exit("bench-viewer: GALLIUM_HUD wrote no frame times")
n = len(v)
print("%s, view %s, turntable %s: %d frames, ms per frame median %.1f (p10 %.1f, p90 %.1f)" % (
    sys.argv[2], sys.argv[3], sys.argv[4], n, v[n // 2], v[n // 10], v[9 * n // 10]))
PY
