#!/usr/bin/env bash
# Accelerator benchmark: mjray's BVH and uniform grid (-o size) side by side with Embree, on
# meshes from 6k to 871k triangles, for primary, incoherent and shadow rays, on 1 and 2
# threads. Writes bench/results/accel.jsonl (one mjray-bench line per run), accel.md (tables)
# and accel.csv (for plot.sh). Takes about 5-10 minutes on 2 cores.
#
#   bench/run_accel.sh                       # everything
#   MESHES="small/teapot.obj" THREADS=1 REPEAT=3 bench/run_accel.sh     # a quick look
#
# Environment: BUILD (build folder, default build-bench), SHARED (default ../shared), OUT
# (results folder, default bench/results), MESHES (paths under $SHARED/models), ACCELS
# (default "bvh grid embree"; "none" runs brute force on MAX_RAYS_NONE rays), KINDS, THREADS,
# REPEAT (builds and traces per run; the median is reported), WAIT_IDLE (seconds to wait before
# each run for a ≥ 90 % idle machine; default 0 = only record the idle fraction), RETRY_BUSY
# (default 1: runs that started on a busy machine are repeated once at the end), KEEP (1: keep
# the rows of earlier runs in accel.jsonl and replace only those rerun, e.g. to redo one mesh).
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build-bench}
SHARED=${SHARED:-$(cd "$ROOT/../shared" && pwd)}
OUT=${OUT:-$ROOT/bench/results}
MESHES=${MESHES:-"small/teapot.obj medium/armadillo.obj small/bunny.obj large/dragon_vrip_res2.obj large/dragon_vrip.obj"}
ACCELS=${ACCELS:-"bvh grid embree"}
KINDS=${KINDS:-"primary incoherent shadow"}
THREADS=${THREADS:-"1 2"}
REPEAT=${REPEAT:-5}
MAX_RAYS_NONE=${MAX_RAYS_NONE:-20000}
WAIT_IDLE=${WAIT_IDLE:-0}
RETRY_BUSY=${RETRY_BUSY:-1}
KEEP=${KEEP:-0}

BENCH=$BUILD/mjray-bench
if [ ! -x "$BENCH" ]; then
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$BUILD" mjray_bench
fi

mkdir -p "$OUT"
LOG=$OUT/accel.jsonl
[ "$KEEP" = 1 ] || : >"$LOG"
{
  echo "# run_accel.sh $(date -u +%Y-%m-%dT%H:%MZ) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
  echo "# git $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'); REPEAT=$REPEAT KEEP=$KEEP MESHES=$MESHES KINDS=$KINDS THREADS=$THREADS ACCELS=$ACCELS"
  echo "# load before: $(uptime | sed 's/.*load average/load average/')"
} | if [ "$KEEP" = 1 ]; then tee -a "$OUT/accel.meta"; else tee "$OUT/accel.meta"; fi

# bench MESH KIND THREADS ACCEL: one mjray-bench run, recorded in $LOG with the idle fraction
# of the machine just before it (a rerun replaces the earlier row). Returns 1 when the machine
# was busy (< 90 % idle), so that the run can be repeated at the end.
bench() {
  local mesh=$1 kind=$2 j=$3 accel=$4 extra=() idle line
  [ "$accel" = grid ] && extra=(--grid-optimal)
  [ "$accel" = none ] && extra=(--max-rays "$MAX_RAYS_NONE")
  idle=$(python3 "$ROOT/bench/results.py" idle "$WAIT_IDLE")
  line=$("$BENCH" --mesh "$SHARED/models/$mesh" --accel "$accel" --rays "$kind" --threads "$j" \
         --repeat "$REPEAT" "${extra[@]}") || return 2
  python3 - "$line" "$idle" "$LOG" <<'EOF'
import json, sys
r = json.loads(sys.argv[1])
r["idle"] = float(sys.argv[2])
key = lambda x: (x["mesh"], x["ray_kind"], x["threads"], x["accel"])
rows = [json.loads(l) for l in open(sys.argv[3]) if l.strip()]
rows = [x for x in rows if key(x) != key(r)] + [r]
with open(sys.argv[3], "w") as f:
    f.writelines(json.dumps(x) + "\n" for x in rows)
print(f"{r['mesh'].split('/')[-1]:24} {r['ray_kind']:10} -j{r['threads']} {r['accel']:6} "
      f"build {r['build_seconds']:8.4f} s  {r['bytes_per_triangle']:6.1f} B/tri  "
      f"{r['rays_per_second'] / 1e6:7.2f} Mrays/s  hits {r['hits']}  (idle before {r['idle']:.2f})")
EOF
  python3 -c "import sys; sys.exit(0 if $idle >= 0.9 else 1)"
}

# Accelerators innermost, so that a change of machine load hits them alike.
busy=()
for mesh in $MESHES; do
  for kind in $KINDS; do
    for j in $THREADS; do
      for accel in $ACCELS; do
        bench "$mesh" "$kind" "$j" "$accel" || busy+=("$mesh $kind $j $accel")
      done
    done
  done
done
# Runs that started on a busy machine get one more try (RETRY_BUSY=0 to skip).
if [ "$RETRY_BUSY" = 1 ] && [ ${#busy[@]} -gt 0 ]; then
  echo "# repeating ${#busy[@]} runs that started on a busy machine"
  for run in "${busy[@]}"; do
    # shellcheck disable=SC2086
    bench $run || true
  done
fi

echo "# load after: $(uptime | sed 's/.*load average/load average/')" | tee -a "$OUT/accel.meta"
python3 "$ROOT/bench/results.py" accel "$LOG" "$OUT"
cat "$OUT/accel.md"
