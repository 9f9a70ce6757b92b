#!/usr/bin/env bash
# The contact sheet of the built-in presets (docs/images/presets.png): for each preset, the
# `marble texture` swatch (a slice of the solid pattern; the paper's 2D texture for `paper`),
# the slab and the sphere rendered in `marble` mode. Needs ImageMagick's montage (tools/deps.txt).
#   tools/contact-sheet.sh [BUILD_DIR] [OUT_PNG]
set -euo pipefail
build=${1:-build}
out=${2:-docs/images/presets.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tiles=()
for preset in $("$build/marble" presets | awk '{print $1}'); do
  "$build/marble" texture -o "$work/$preset" --preset "$preset" --size 256 >/dev/null
  "$build/marble" render builtin:slab --mode marble --preset "$preset" --width 256 --height 256 -o "$work/$preset-slab.png" >/dev/null
  "$build/marble" render builtin:sphere --mode marble --preset "$preset" --width 256 --height 256 -o "$work/$preset-sphere.png" >/dev/null
  tiles+=("$work/$preset/marble.png" "$work/$preset-slab.png" "$work/$preset-sphere.png")
  labels+=("$preset" "$preset, slab" "$preset, sphere")
done
args=()
for i in "${!tiles[@]}"; do args+=(-label "${labels[$i]}" "${tiles[$i]}"); done
mkdir -p "$(dirname "$out")"
montage "${args[@]}" -tile 6x -geometry 256x256+4+4 -background '#202020' -fill '#e0e0e0' -pointsize 14 -font DejaVu-Sans "$work/sheet.png"
mv "$work/sheet.png" "$out"
echo "$out"
