#!/usr/bin/env bash
# Instructions per pass of one frame, counted by callgrind: the cost measure docs/performance.md
# uses since session 10 ("Where the frame stands after ..."). On llvmpipe the shaders run on the
# CPU, so a pass's instruction count is its cost, and unlike a frame time it does not drift with
# the machine's load: two builds can be compared to a few hundredths of a percent.
#
#   tools/frame-instructions.sh [MESH[@UP]] [--motion camera|light|both|...] [--view WxH]
#                               [--out DIR] [-- BENCH OPTIONS]
#
# Runs `marble bench MESH --motion M --frames 1 --warmup 2 --serial-passes` under callgrind with one
# dump after every `marble::*Pass::run`, and prints the last frame's passes (M instructions) and
# their sum. MESH defaults to ../shared/models/dragon.obj@z (not part of the repository), the view
# to 800x800, the motion to camera. Options after `--` go to `marble bench` (e.g. `--light back`,
# `--interaction-detail on`); MARBLE_SHADER_DIR passes through, so shader variants can be counted
# without a rebuild. The dumps stay in --out (default: a temporary folder, removed).
# Work done between two passes (the stretch of a reduced frame, a texture upload) is charged to the
# next pass's count. llvmpipe runs on one thread here (LP_NUM_THREADS=0), so the count is the same
# on any number of cores. A frame takes 2-4 minutes under callgrind.
# Needs valgrind: installed with apt when missing and run as root (only this script needs it, so it
# is not in tools/deps.txt and CI never installs it).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MARBLE="${MARBLE:-$ROOT/build/marble}"
MESH="$ROOT/../shared/models/dragon.obj@z"
MOTION=camera
VIEW=800x800
OUT=""
EXTRA=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --motion) MOTION="$2"; shift 2 ;;
    --view) VIEW="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --) shift; EXTRA=("$@"); break ;;
    -*) echo "frame-instructions: unknown option $1" >&2; exit 2 ;;
    *) MESH="$1"; shift ;;
  esac
done
[[ -x "$MARBLE" ]] || { echo "frame-instructions: no marble binary at $MARBLE (build first, or set MARBLE=)" >&2; exit 1; }
[[ "$VIEW" =~ ^[0-9]+x[0-9]+$ ]] || { echo "frame-instructions: --view: expected WxH, got $VIEW" >&2; exit 2; }
if ! command -v valgrind >/dev/null; then
  if [[ $(id -u) == 0 ]]; then
    apt-get install -y -qq valgrind >/dev/null
  else
    echo "frame-instructions: valgrind is missing; run: sudo apt-get install -y valgrind" >&2
    exit 1
  fi
fi
mesh="${MESH%@*}"
up="${MESH##*@}"
[[ $up == "$MESH" ]] && up=y
if [[ -z $OUT ]]; then
  OUT=$(mktemp -d)
  trap 'rm -rf "$OUT"' EXIT
else
  mkdir -p "$OUT"
  rm -f "$OUT"/callgrind.out*
fi
LP_NUM_THREADS=0 valgrind --tool=callgrind --callgrind-out-file="$OUT/callgrind.out" \
  --dump-after='marble::*Pass::run*' \
  "$MARBLE" bench "$mesh" --up "$up" --width "${VIEW%x*}" --height "${VIEW#*x}" --motion "$MOTION" \
  --frames 1 --warmup 2 --serial-passes --json "${EXTRA[@]}" > "$OUT/bench.json" 2> "$OUT/valgrind.log" ||
  { echo "frame-instructions: marble bench failed under valgrind, see $OUT/valgrind.log" >&2; exit 1; }
python3 - "$OUT" "$(basename "$mesh")" "$VIEW" "$MOTION" <<'PY'
import glob, os, re, sys
out, mesh, view, motion = sys.argv[1:5]
# callgrind numbers its dumps callgrind.out.1, .2, ... in the order the passes ran.
files = sorted(glob.glob(os.path.join(out, "callgrind.out.*")), key=lambda p: int(p.rsplit(".", 1)[1]))
dumps = []
for path in files:
    trigger, total = None, None
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("desc: Trigger:"):
                m = re.search(r"--dump-after=(\S+)", line)
                trigger = m.group(1) if m else line.split(":", 2)[2].strip()
            elif line.startswith("summary:") or line.startswith("totals:"):
                total = int(line.split()[1])
                break
    if trigger is not None and total is not None:
        dumps.append((trigger, total))
# Each pass runs once a frame: walking back from the last dump, the last frame ends where a pass repeats.
frame, seen = [], set()
for trigger, total in reversed(dumps):
    if trigger in seen:
        break
    seen.add(trigger)
    frame.append((trigger, total))
if not frame:
    sys.exit("frame-instructions: callgrind wrote no per-pass dumps")
frame.reverse()
print("%s, view %s, motion %s: the last frame's passes, M instructions" % (mesh, view, motion))
for trigger, total in frame:
    name = re.sub(r"\(.*", "", trigger).replace("marble::", "").replace("::run", "")
    print("  %-28s %9.2f" % (name, total / 1e6))
print("  %-28s %9.2f" % ("frame", sum(t for _, t in frame) / 1e6))
PY
