#!/usr/bin/env bash
# Whole-render experiments with the mjray program, in the manner of the original report's §5.6
# and §6.3-6.5: brute force vs uniform grid (-o) vs BVH, render time vs grid size (-g sweep),
# and time vs threads. Each configuration runs REPEAT times (median reported); every run's
# --stats-json goes to bench/results/render.jsonl, the tables to render.md, and the sweep and
# thread CSVs for plot.sh. Takes about 12-15 minutes on 2 busy cores.
#
#   bench/run_render.sh                   # everything
#   PARTS="threads" REPEAT=5 bench/run_render.sh      # one part (compare, sweep, threads)
#
# Scenes: the CS 488 macho-cows scene (17.5k primitives), bench/venus.lua (the original's Venus
# de Milo, 43k triangles), ../shared/bench/mesh.lua (871k-triangle dragon; too slow for brute
# force, and its 200-unit floor box defeats a uniform grid, see docs/performance.md) and its twin
# bench/dragon.lua (same dragon on a small floor) for the grid sweep; the three
# ../shared/bench scenes for the thread scaling.
#
# Environment: BUILD, SHARED, OUT as in run_accel.sh; REPEAT (default 3); LIMIT (seconds after
# which a slow configuration is stopped and reported as "> LIMIT", default 60); JOBS (threads
# for the compare and sweep parts, default 2); PARTS (default "compare sweep threads");
# WAIT_IDLE (seconds to wait before each run for the machine to be ≥ 90 % idle, default 0: the
# idle fraction over the half second before each run is only recorded, as "idle");
# SLOW_REPEAT and SLOW_LIMIT (default 1 and 300) for brute force on the Venus.
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build-bench}
SHARED=${SHARED:-$(cd "$ROOT/../shared" && pwd)}
OUT=${OUT:-$ROOT/bench/results}
REPEAT=${REPEAT:-3}
LIMIT=${LIMIT:-60}
JOBS=${JOBS:-2}
PARTS=${PARTS:-"compare sweep threads"}
WAIT_IDLE=${WAIT_IDLE:-0}
SLOW_REPEAT=${SLOW_REPEAT:-1}
SLOW_LIMIT=${SLOW_LIMIT:-300}

MJRAY=$BUILD/mjray
if [ ! -x "$MJRAY" ]; then
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$BUILD" mjray_app || exit 1
fi

MACHO=$SHARED/corpus/cs488/themarkrizkallah-cs488/A4/Assets/macho-cows.lua
VENUS=$ROOT/bench/venus.lua
MESH=$SHARED/bench/mesh.lua
DRAGON=$ROOT/bench/dragon.lua

mkdir -p "$OUT"
LOG=$OUT/render.jsonl
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# Keep earlier parts' rows when only some parts are rerun.
if [ -f "$LOG" ]; then
  python3 - "$LOG" $PARTS <<'EOF'
import json, sys
path, parts = sys.argv[1], set(sys.argv[2:])
rows = [l for l in open(path) if l.strip() and json.loads(l)["experiment"] not in parts]
open(path, "w").writelines(rows)
EOF
fi
{
  echo "# run_render.sh $(date -u +%Y-%m-%dT%H:%MZ) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
  echo "# git $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'); REPEAT=$REPEAT LIMIT=$LIMIT JOBS=$JOBS PARTS=$PARTS"
  echo "# load before: $(uptime | sed 's/.*load average/load average/')"
} | if [ "$PARTS" = "compare sweep threads" ]; then tee "$OUT/render.meta"; else tee -a "$OUT/render.meta"; fi

# run EXPERIMENT SCENE_NAME VARIANT THREADS SCENE_FILE [mjray options...]
# Renders REPEAT times (stopping at the first run over LIMIT seconds) and records each run.
# Returns 1 when a run was stopped.
run() {
  local experiment=$1 name=$2 variant=$3 threads=$4 scene=$5
  shift 5
  local k status start end wall cpu idle
  for ((k = 1; k <= REPEAT; k++)); do
    rm -f "$TMP/stats.json"
    idle=$(python3 "$ROOT/bench/results.py" idle "$WAIT_IDLE")
    start=$EPOCHREALTIME
    /usr/bin/time -f '%U %S' -o "$TMP/time" timeout "$LIMIT" "$MJRAY" --quiet --allow-read "$SHARED/models" --outdir "$TMP" \
      --stats-json "$TMP/stats.json" -j "$threads" "$@" "$scene" >/dev/null 2>"$TMP/stderr"
    status=$?
    end=$EPOCHREALTIME
    wall=$(python3 -c "print(f'{$end - $start:.4f}')")
    cpu=$(tail -1 "$TMP/time" | awk '{ printf "%.3f", $1 + $2 }')
    if [ "$status" = 124 ]; then
      python3 "$ROOT/bench/results.py" record "$LOG" experiment="$experiment" scene="$name" variant="$variant" \
        threads="$threads" run="$k" timed_out=true limit="$LIMIT" idle="$idle" options="$*"
      printf '%-8s %-12s %-10s -j%s  stopped after %s s\n' "$experiment" "$name" "$variant" "$threads" "$LIMIT"
      return 1
    elif [ "$status" != 0 ]; then
      printf '%-8s %-12s %-10s -j%s  FAILED (exit %s): %s\n' "$experiment" "$name" "$variant" "$threads" "$status" \
        "$(tail -1 "$TMP/stderr")"
      return 2
    fi
    python3 "$ROOT/bench/results.py" record "$LOG" experiment="$experiment" scene="$name" variant="$variant" \
      threads="$threads" run="$k" wall="$wall" cpu="$cpu" idle="$idle" options="$*" --stats "$TMP/stats.json"
    printf '%-8s %-12s %-10s -j%s  run %d: %7.3f s wall %7.3f s CPU (idle before: %s)\n' "$experiment" "$name" \
      "$variant" "$threads" "$k" "$wall" "$cpu" "$idle"
  done
  return 0
}

# --- 1. brute force vs grid (-o) vs BVH ----------------------------------------------------
if [[ " $PARTS " == *" compare "* ]]; then
  for scene in macho-cows venus; do
    file=$MACHO
    [ "$scene" = venus ] && file=$VENUS
    run compare "$scene" bvh "$JOBS" "$file" --accel bvh
    run compare "$scene" grid-o "$JOBS" "$file" -o
  done
  run compare macho-cows none "$JOBS" "$MACHO" -g 0
  # Brute force on the Venus takes 1-2 minutes: SLOW_REPEAT runs (default 1) with SLOW_LIMIT.
  REPEAT=$SLOW_REPEAT LIMIT=$SLOW_LIMIT run compare venus none "$JOBS" "$VENUS" -g 0
  # mesh.lua: brute force would take hours (871k triangles × ~4.4M rays), so it is not run;
  # the grid is tried once, with the LIMIT.
  run compare mesh bvh "$JOBS" "$MESH" -s 4 --accel bvh
  REPEAT=1 run compare mesh grid-o "$JOBS" "$MESH" -s 4 -o
  run compare dragon bvh "$JOBS" "$DRAGON" -s 4 --accel bvh
  run compare dragon grid-o "$JOBS" "$DRAGON" -s 4 -o
fi

# --- 2. render time vs grid size ------------------------------------------------------------
# Largest grids first: once a size is stopped by LIMIT, every smaller one would be slower still.
# The dragon runs with one shadow ray per hit (-s 1) so that more of the small sizes finish.
if [[ " $PARTS " == *" sweep "* ]]; then
  for scene in macho-cows dragon; do
    file=$MACHO
    opts=()
    if [ "$scene" = dragon ]; then file=$DRAGON; opts=(-s 1); fi
    run sweep "$scene" bvh "$JOBS" "$file" "${opts[@]}" --accel bvh
    run sweep "$scene" grid-o "$JOBS" "$file" "${opts[@]}" -o
    for g in 256 128 64 32 16 8 4 2 1; do
      run sweep "$scene" "g=$g" "$JOBS" "$file" "${opts[@]}" -g "$g" || break
    done
  done
fi

# --- 3. time vs threads ----------------------------------------------------------------------
if [[ " $PARTS " == *" threads "* ]]; then
  for j in 1 2; do
    run threads spheres bvh "$j" "$SHARED/bench/spheres.lua" -r 4
    run threads mesh bvh "$j" "$MESH" -s 4
    run threads glass bvh "$j" "$SHARED/bench/glass.lua" -r 8 -f 8 -s 4 -a 3
  done
fi

echo "# load after: $(uptime | sed 's/.*load average/load average/')" | tee -a "$OUT/render.meta"
python3 "$ROOT/bench/results.py" render "$LOG" "$OUT"
cat "$OUT/render.md"
