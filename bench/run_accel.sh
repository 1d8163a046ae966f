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
# each run for a ≥ 90 % idle machine; default 0 = only record the idle fraction).
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

BENCH=$BUILD/mjray-bench
if [ ! -x "$BENCH" ]; then
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$BUILD" mjray_bench
fi

mkdir -p "$OUT"
LOG=$OUT/accel.jsonl
: >"$LOG"
{
  echo "# run_accel.sh $(date -u +%Y-%m-%dT%H:%MZ) on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
  echo "# git $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'); REPEAT=$REPEAT"
  echo "# load before: $(uptime | sed 's/.*load average/load average/')"
} | tee "$OUT/accel.meta"

# Accelerators innermost, so that a change of machine load hits them alike.
for mesh in $MESHES; do
  for kind in $KINDS; do
    for j in $THREADS; do
      for accel in $ACCELS; do
        extra=()
        [ "$accel" = grid ] && extra=(--grid-optimal)
        [ "$accel" = none ] && extra=(--max-rays "$MAX_RAYS_NONE")
        idle=$(python3 "$ROOT/bench/results.py" idle "$WAIT_IDLE")
        line=$("$BENCH" --mesh "$SHARED/models/$mesh" --accel "$accel" --rays "$kind" --threads "$j" \
               --repeat "$REPEAT" "${extra[@]}")
        python3 - "$line" "$idle" "$LOG" <<'EOF'
import json, sys
r = json.loads(sys.argv[1])
r["idle"] = float(sys.argv[2])
with open(sys.argv[3], "a") as f:
    f.write(json.dumps(r) + "\n")
print(f"{r['mesh'].split('/')[-1]:24} {r['ray_kind']:10} -j{r['threads']} {r['accel']:6} "
      f"build {r['build_seconds']:8.4f} s  {r['bytes_per_triangle']:6.1f} B/tri  "
      f"{r['rays_per_second'] / 1e6:7.2f} Mrays/s  hits {r['hits']}  (idle before {r['idle']:.2f})")
EOF
      done
    done
  done
done

echo "# load after: $(uptime | sed 's/.*load average/load average/')" | tee -a "$OUT/accel.meta"
python3 "$ROOT/bench/results.py" accel "$LOG" "$OUT"
cat "$OUT/accel.md"
