#!/usr/bin/env bash
# mjray against Blender's Cycles (Debian 12: apt-get install blender) at equal wall time on the
# box room of bench/cycles_twin.py: each one's error after 1, 2, 5, 10, 20 and 60 s against a
# 4096-sample Cycles reference, mjray's also against its own converged image, and a 1 s sweep
# of photon counts; see bench/cycles_equal_time.py. The references are kept in OUTDIR (Cycles'
# and mjray's take several minutes each on 2 cores); the timed runs take about 4 minutes. Run
# it on an otherwise idle machine: each run records how idle the cores were before it.
#
#   bench/cycles_equal_time.sh [OUTDIR] [GI_PHOTONS]   (defaults: out/cycles_equal_time 200000)
#   bench/cycles_equal_time.sh --smoke [OUTDIR]        one 0.5 s budget, 16-sample references
#
# Environment: MJRAY (default build/mjray); NOISE_THRESHOLD, mjray's under the budgets (default 0.01); SWEEP, the photon counts run at 1 s (default
# "25000 50000 100000 200000"; empty for none); REFERENCE_SAMPLES, Cycles' (default 4096).
set -euo pipefail
cd "$(dirname "$0")/.."
python=/usr/bin/python3  # Debian's, for numpy
if [ "${1:-}" = --smoke ]; then
  out=${2:-out/cycles_equal_time_smoke}
  gi=200000 reference_samples=16 own_spp=16 budgets="0.5" sweep=""
else
  out=${1:-out/cycles_equal_time}
  gi=${2:-200000} reference_samples=${REFERENCE_SAMPLES:-4096} own_spp=4096 budgets="1 2 5 10 20 60"
  sweep=${SWEEP-25000 50000 100000 200000}
fi
mkdir -p "$out"
{
  echo "# cycles_equal_time.sh $(date -u +%Y-%m-%dT%H:%MZ) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
  echo "# git $(git rev-parse --short HEAD 2>/dev/null || echo '?'); $(blender --version 2>/dev/null | head -1); budgets $budgets; --gi $gi"
  echo "# load before: $(uptime | sed 's/.*load average/load average/')"
} | tee "$out/equal_time.meta"
$python bench/cycles_equal_time.py mjray "$out" "$gi" "$own_spp" $budgets
rm -f "$out/mjray_sweep.jsonl"
if [ -n "$sweep" ]; then
  $python bench/cycles_equal_time.py sweep "$out" $sweep
fi
blender -b --factory-startup -P bench/cycles_equal_time.py -- "$out" "$reference_samples" $budgets > "$out/blender.log" 2>&1
$python bench/cycles_equal_time.py compare "$out" "$gi" | tee "$out/equal_time.md"
