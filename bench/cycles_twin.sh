#!/usr/bin/env bash
# mjray's global illumination against Blender's Cycles (Debian 12: apt-get install blender) on a
# diffuse box room described once in bench/cycles_twin.py: total over direct light on the back
# wall, and red over green beside the red wall, each as mjray and Cycles give it. Not run by CI.
#
#   bench/cycles_twin.sh [OUTDIR] [CYCLES_SAMPLES] [GI_PHOTONS]   (defaults: out/cycles_twin 1024 400000)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/cycles_twin}
samples=${2:-1024}
photons=${3:-400000}
mkdir -p "$out"
python3 bench/cycles_twin.py lua "$out/twin.lua"
build/mjray --quiet --gi "$photons" --output "$out/mjray_total.ppm" "$out/twin.lua"
build/mjray --quiet --output "$out/mjray_direct.ppm" "$out/twin.lua"
blender -b --factory-startup -P bench/cycles_twin.py -- "$out" "$samples" > "$out/blender.log" 2>&1
python3 bench/cycles_twin.py compare "$out" | tee "$out/ratios.jsonl"
