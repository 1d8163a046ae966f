#!/usr/bin/env bash
# Set up (packages, build) and render. Usage: ./render.sh [mjray options] [scene.lua] [mjray options]
# The scene and every file name are taken relative to the folder you run it from; options may
# come before or after the scene. Without a scene it renders scenes/showcase.lua into
# out/showcase.png of the repository (with soft shadows and anti-aliasing: -s 3 -a 3; your
# options win over those).
# MJRAY_BINARY=path skips the setup and runs that mjray instead (for tests).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mjray="${MJRAY_BINARY:-}"
if [ -z "$mjray" ]; then
  "$repo/scripts/setup.sh"
  mjray="$repo/build/mjray"
fi
for arg in "$@"; do
  if [[ "$arg" == *.lua ]]; then
    exec "$mjray" "$@"
  fi
done
exec "$mjray" --outdir "$repo/out" -s 3 -a 3 "$@" "$repo/scenes/showcase.lua"
