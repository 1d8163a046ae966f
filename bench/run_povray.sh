#!/usr/bin/env bash
# mjray vs POV-Ray 3.7 on the three benchmark scenes of ../shared/bench (spheres, mesh, glass),
# each with the settings in its header, both on the same number of threads, one after the
# other. Reports the median whole-process wall time of each (what a user waits for: parsing,
# loading, building, tracing, writing) and the ratio, and the CPU time (user + system) that
# says the same on a machine busy with other work. Writes bench/results/povray.jsonl,
# povray.md and povray.csv. Takes about 2-4 minutes on 2 cores.
#
#   bench/run_povray.sh
#   SCENES="spheres mesh" REPEAT=5 THREADS=1 bench/run_povray.sh
#
# ../shared is read-only, so the POV-Ray twins are copied to POVDIR (default
# BUILD/pov-bench), their relative model path is pointed at SHARED/models, and pov/prepare.sh
# writes the dragon's mesh_data.inc there once (about 35 MB, kept for later runs).
# Environment: BUILD, SHARED, OUT as in run_accel.sh; REPEAT (default 3); THREADS (default 2);
# SCENES (default "spheres mesh glass glass-t0.3", the last being glass with mjray's
# --aa-threshold at POV-Ray's 0.3); LIMIT (seconds per run, default 300); WAIT_IDLE
# (seconds to wait before each run for a ≥ 90 % idle machine, default 0 = only record it).
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build-bench}
SHARED=${SHARED:-$(cd "$ROOT/../shared" && pwd)}
OUT=${OUT:-$ROOT/bench/results}
POVDIR=${POVDIR:-$BUILD/pov-bench}
REPEAT=${REPEAT:-3}
THREADS=${THREADS:-2}
SCENES=${SCENES:-"spheres mesh glass glass-t0.3"}
LIMIT=${LIMIT:-300}
WAIT_IDLE=${WAIT_IDLE:-0}

MJRAY=$BUILD/mjray
if [ ! -x "$MJRAY" ]; then
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$BUILD" mjray_app || exit 1
fi
if ! command -v povray >/dev/null; then
  echo "run_povray.sh: povray not found (Debian: apt-get install -y povray)" >&2
  exit 1
fi

# Copy the twins and prepare the dragon's mesh2 include.
mkdir -p "$POVDIR"
cp "$SHARED"/bench/pov/*.pov "$SHARED"/bench/pov/obj2mesh2.py "$SHARED"/bench/pov/prepare.sh "$POVDIR"/
sed -i "s#\.\./\.\./models#$SHARED/models#g" "$POVDIR/prepare.sh"
if [[ " $SCENES " == *" mesh "* ]]; then
  sh "$POVDIR/prepare.sh" || exit 1
fi

mkdir -p "$OUT"
LOG=$OUT/povray.jsonl
: >"$LOG"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
{
  echo "# run_povray.sh $(date -u +%Y-%m-%dT%H:%MZ) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
  echo "# git $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'); $(povray --version 2>&1 | grep -m1 POV-Ray); REPEAT=$REPEAT THREADS=$THREADS"
  echo "# load before: $(uptime | sed 's/.*load average/load average/')"
} | tee "$OUT/povray.meta"

# The settings of each scene's header.
# glass-t0.3 is glass with mjray's anti-aliasing threshold raised from its default 0.1 to 0.3.
# Not POV-Ray's +A0.3: POV-Ray sums the three channels' differences, mjray takes the largest,
# so on grey edges mjray's default 0.1 is the like-for-like setting (docs/performance.md §7).
mjray_options() {
  case $1 in
    spheres) echo "-r 4" ;;
    mesh) echo "-s 4" ;;
    glass) echo "-r 8 -f 8 -s 4 -a 3" ;;
    glass-t0.3) echo "-r 8 -f 8 -s 4 -a 3 --aa-threshold 0.3" ;;
  esac
}
povray_options() {
  case $1 in
    spheres | mesh) echo "+W512 +H512 -A" ;;
    glass | glass-t0.3) echo "+W512 +H512 +A0.3 +AM2 +R3" ;;
  esac
}

# timed SCENE PROGRAM RUN command...: runs the command, records its wall time and exit status.
timed() {
  local scene=$1 program=$2 k=$3
  shift 3
  local start end wall cpu status idle
  idle=$(python3 "$ROOT/bench/results.py" idle "$WAIT_IDLE")
  start=$EPOCHREALTIME
  /usr/bin/time -f '%U %S' -o "$TMP/time" timeout "$LIMIT" "$@" >"$TMP/stdout" 2>"$TMP/stderr"
  status=$?
  end=$EPOCHREALTIME
  wall=$(python3 -c "print(f'{$end - $start:.4f}')")
  cpu=$(tail -1 "$TMP/time" | awk '{ printf "%.3f", $1 + $2 }')
  python3 "$ROOT/bench/results.py" record "$LOG" scene="$scene" program="$program" threads="$THREADS" run="$k" \
    wall="$wall" cpu="$cpu" idle="$idle" status="$status" command="$*"
  if [ "$status" = 0 ]; then
    printf '%-8s %-7s -j%s run %d: %8.3f s wall %8.3f s CPU (idle before: %s)\n' "$scene" "$program" "$THREADS" \
      "$k" "$wall" "$cpu" "$idle"
  else
    printf '%-8s %-7s -j%s run %d: FAILED (exit %s): %s\n' "$scene" "$program" "$THREADS" "$k" "$status" \
      "$(tail -2 "$TMP/stderr" | tr '\n' ' ')"
  fi
}

# The two programs alternate, so that a change of machine load hits both alike.
for scene in $SCENES; do
  for ((k = 1; k <= REPEAT; k++)); do
    # shellcheck disable=SC2046
    timed "$scene" mjray "$k" "$MJRAY" --quiet --allow-read "$SHARED/models" --outdir "$TMP" -j "$THREADS" $(mjray_options "$scene") \
      "$SHARED/bench/${scene%-t0.3}.lua"
    # shellcheck disable=SC2046
    (cd "$POVDIR" && timed "$scene" povray "$k" povray "+I${scene%-t0.3}.pov" "+O${scene%-t0.3}.png" \
      $(povray_options "$scene") "+WT$THREADS" -D)
  done
done

echo "# load after: $(uptime | sed 's/.*load average/load average/')" | tee -a "$OUT/povray.meta"
python3 "$ROOT/bench/results.py" povray "$LOG" "$OUT"
cat "$OUT/povray.md"
