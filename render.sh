#!/usr/bin/env bash
# Set up (packages, build) and render. Usage: ./render.sh [scene.lua] [mjray options]
# Without a scene it renders scenes/showcase.lua into out/showcase.png (with soft shadows and
# anti-aliasing: -s 3 -a 3).
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
if [ $# -gt 0 ] && [[ "$1" == *.lua ]]; then
  exec build/mjray "$@"
fi
exec build/mjray --outdir out -s 3 -a 3 "$@" scenes/showcase.lua
