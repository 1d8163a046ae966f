#!/usr/bin/env bash
# Issue 15's experiment for processes: whole-process wall and CPU time of mjray and of mpirun -np R
# mjray-mpi -j T on ../shared/bench/glass.lua and mesh.lua, for R = 1..4 ranks (beyond the
# machine's cores they are oversubscribed), with each rank's load, build and bytes sent from
# --stats-json. Every run's JSON goes to bench/results/mpi.jsonl, the table to mpi.md and
# mpi.csv (for plot.sh); bench/mpi_model.py turns the measured costs into the efficiency model.
#
#   bench/run_mpi.sh                       # REPEAT=3 (median), both scenes
#   SCENES=glass REPEAT=5 WAIT_IDLE=30 bench/run_mpi.sh
#
# Environment: BUILD (default build/, needs mjray and mjray-mpi), SHARED, OUT, REPEAT,
# SCENES ("glass mesh"), CONFIGS (R:T pairs; R=0 means plain mjray), WAIT_IDLE as in
# run_render.sh (seconds to wait before each run for a >= 90 %-idle machine; default 0: only
# recorded).
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build}
SHARED=${SHARED:-$(cd "$ROOT/../shared" && pwd)}
OUT=${OUT:-$ROOT/bench/results}
REPEAT=${REPEAT:-3}
SCENES=${SCENES:-"glass mesh"}
CONFIGS=${CONFIGS:-"0:1 0:2 1:2 2:1 1:1 2:2 3:1 4:1"}
WAIT_IDLE=${WAIT_IDLE:-0}

[ -x "$BUILD/mjray" ] && [ -x "$BUILD/mjray-mpi" ] || { echo "run_mpi.sh: build mjray and mjray-mpi into $BUILD first" >&2; exit 1; }
MPIRUN=(mpirun --quiet --oversubscribe)
[ "$(id -u)" -eq 0 ] && MPIRUN+=(--allow-run-as-root)

declare -A OPTIONS=([glass]="-r 8 -f 8 -s 4 -a 3" [mesh]="-s 4" [spheres]="-r 4")
mkdir -p "$OUT"
LOG=$OUT/mpi.jsonl
: > "$LOG"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
{
  echo "# run_mpi.sh $(date -u +%Y-%m-%dT%H:%MZ) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
  echo "# git $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'); REPEAT=$REPEAT CONFIGS=$CONFIGS; $(mpirun --version | head -1)"
  echo "# load before: $(uptime | sed 's/.*load average/load average/')"
} | tee "$OUT/mpi.meta"

# Open MPI's fixed cost: mpirun starting R ranks that initialise and finalise MPI and do nothing
# else (mjray-mpi --version), recorded as scene "launch".
for ranks in 1 2 4; do
  for ((k = 1; k <= REPEAT; k++)); do
    idle=$(python3 "$ROOT/bench/results.py" idle "$WAIT_IDLE")
    start=$EPOCHREALTIME
    "${MPIRUN[@]}" -np "$ranks" "$BUILD/mjray-mpi" --version >/dev/null 2>&1
    status=$?
    end=$EPOCHREALTIME
    wall=$(python3 -c "print(round($end - $start, 4))")
    python3 "$ROOT/bench/results.py" record "$LOG" experiment=mpi scene=launch np="$ranks" j=1 run="$k" wall="$wall" \
      status="$status" idle="$idle"
    printf 'launch ranks=%s run %d: %6.3f s  idle %s\n' "$ranks" "$k" "$wall" "$idle" >&2
  done
done

for name in $SCENES; do
  scene=$SHARED/bench/$name.lua
  read -r -a opts <<<"${OPTIONS[$name]}"
  reference=""
  for config in $CONFIGS; do
    ranks=${config%:*}
    threads=${config#*:}
    for ((k = 1; k <= REPEAT; k++)); do
      rm -rf "$TMP/out" "$TMP/stats.json"
      idle=$(python3 "$ROOT/bench/results.py" idle "$WAIT_IDLE")
      if [ "$ranks" -eq 0 ]; then
        cmd=("$BUILD/mjray")
      else
        cmd=("${MPIRUN[@]}" -np "$ranks" "$BUILD/mjray-mpi")
      fi
      start=$EPOCHREALTIME
      /usr/bin/time -f '%U %S' -o "$TMP/time" "${cmd[@]}" --quiet --allow-read "$SHARED/models" -j "$threads" "${opts[@]}" --outdir "$TMP/out" --stats-json "$TMP/stats.json" "$scene" \
        >/dev/null 2>"$TMP/stderr"
      status=$?
      end=$EPOCHREALTIME
      image=$(sha256sum "$TMP/out/$name.png" 2>/dev/null | cut -c1-16)
      [ -z "$reference" ] && reference=$image
      same=$([ "$image" = "$reference" ] && echo true || echo false)
      wall=$(python3 -c "print(round($end - $start, 4))")
      cpu=$(awk '{print $1 + $2}' "$TMP/time" 2>/dev/null | tail -1)
      python3 "$ROOT/bench/results.py" record "$LOG" experiment=mpi scene="$name" np="$ranks" j="$threads" \
        run="$k" wall="$wall" cpu="${cpu:-0}" status="$status" idle="$idle" same_image="$same" --stats "$TMP/stats.json"
      printf '%-6s ranks=%s -j %s run %d: %6.3f s  idle %s  same image: %s\n' "$name" "$ranks" "$threads" "$k" "$wall" \
        "$idle" "$same" >&2
      [ "$status" -eq 0 ] || cat "$TMP/stderr" >&2
    done
  done
done
python3 "$ROOT/bench/results.py" mpi "$LOG" "$OUT"
