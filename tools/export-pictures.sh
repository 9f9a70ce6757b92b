#!/usr/bin/env bash
# Regenerates the side-by-side pictures of docs/export.md: each model exported with
# `marble export`, then seen by marble itself, by three.js in headless chromium
# (tools/web/shoot.mjs, lit mode) and by Blender's Cycles through tools/blender_marble.py.
# Needs the meshes in ../shared/models (not part of the repository), chromium, node with
# tools/web (tools/setup-web-tools.sh) and Blender (with python3-numpy).
# Usage: tools/export-pictures.sh [MODELS_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
models=${1:-$root/../../shared/models}
[[ -d $models ]] || models=/work/shared/models
marble=$root/build/marble
out=$root/docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size=320

shoot() {  # name, mesh, "options for render and export" (preset, up), "options for export only"
  local name=$1 input=$2
  read -r -a common <<< "$3"
  read -r -a only <<< "$4"
  "$marble" export "$input" -o "$work/$name.glb" "${common[@]}" "${only[@]}"
  "$marble" render "$input" "${common[@]}" --width $size --height $size -o "$work/$name-marble.png" > /dev/null
  node "$root/tools/web/shoot.mjs" "$work/$name.glb" "$work/$name-three.png" --width $size --height $size --mode lit --bg 0.19,0.11,0.03
  blender -b --factory-startup -P "$root/tools/blender_marble.py" -- "$work/$name.glb" --render "$work/$name-blender.png" \
    --width $size --height $size --samples 48 > "$work/$name-blender.log" 2>&1 || { cat "$work/$name-blender.log"; exit 1; }
  # marble's default background (0.19, 0.11, 0.03), a display colour, behind Blender's transparent film.
  convert "$work/$name-blender.png" -background "rgb(48,28,8)" -flatten "$work/$name-blender-bg.png"
  convert "$work/$name-marble.png" "$work/$name-three.png" "$work/$name-blender-bg.png" +append "$out/export-$name.png"
  echo "wrote $out/export-$name.png"
}

shoot bunny "$models/bunny.obj" "" "--size 1024"
shoot dragon "$models/dragon.obj" "--up z --preset calacatta" "--size 2048"
# A glTF with its own texture coordinates: an export read back and exported again with --uv-from file.
"$marble" export "$models/teapot.obj" -o "$work/teapot-uv.glb" --size 1024 --preset nero-marquina > /dev/null
shoot teapot "$work/teapot-uv.glb" "--preset nero-marquina" "--uv-from file --size 1024"
