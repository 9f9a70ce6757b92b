#!/usr/bin/env bash
# The main job: set everything up, then show the default marble scene — in the viewer if
# there is a display, otherwise rendered headless to out/default.png (its path is printed).
# Arguments are passed to `marble view` / `marble render` (e.g. a scene or mesh file).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/setup.sh"
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
  exec "$root/build/marble" view "$@"
fi
mkdir -p "$root/out"
"$root/build/marble" render "$@" -o "$root/out/default.png"
echo "no display: rendered headless to $root/out/default.png"
