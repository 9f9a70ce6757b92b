#!/usr/bin/env bash
# Installs the Debian packages in tools/deps.txt that are missing, then configures and
# builds marble into build/ (Release). Safe to run again: it only does what is missing.
# Usage: tools/setup.sh [extra cmake -D options]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mapfile -t wanted < <(grep -v '^\s*#' "$root/tools/deps.txt" | sed '/^\s*$/d')
missing=()
for p in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm comes inside some nodejs packages (NodeSource's) and as a package of its own in Debian's
# (tools/deps.txt): ask for Debian's only where no npm is installed.
command -v npm > /dev/null || missing+=(npm)
if ((${#missing[@]})); then
  if [[ $(id -u) -ne 0 ]]; then
    echo "marble needs these Debian packages; install them as root, then run this again:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$root/build" -j"$(nproc)"
# The export tests check files with the Khronos glTF-Validator (npm; tools/setup-web-tools.sh).
"$root/tools/setup-web-tools.sh"
