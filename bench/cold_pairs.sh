#!/usr/bin/env bash
# Two commands' whole-process wall times, each run after IDLE seconds of sleep (default 1.5),
# alternated for N pairs, with each one's median. On a virtual machine whose freshly touched
# memory is slow to fault in, a run right after another finds its memory warm; a user's first
# run after editing a scene, or a run after another program (as in run_povray.sh), does not.
# This measures the latter.
#
#   bench/cold_pairs.sh N 'OLD COMMAND' 'NEW COMMAND'
#   bench/cold_pairs.sh 7 '/tmp/old/mjray --quiet -j 2 -s 4 ../shared/bench/mesh.lua --output /tmp/a.png' \
#                         'build/mjray --quiet -j 2 -s 4 ../shared/bench/mesh.lua --output /tmp/b.png'
set -euo pipefail
if [ $# -ne 3 ]; then
  sed -n '2,11p' "$0" >&2
  exit 2
fi
pairs=$1 old=$2 new=$3 idle=${IDLE:-1.5}
times=$(mktemp)
trap 'rm -f "$times"' EXIT
for ((i = 0; i < pairs; i++)); do
  for which in old new; do
    sleep "$idle"
    command=$old
    [ "$which" = new ] && command=$new
    start=$EPOCHREALTIME
    bash -c "$command" >/dev/null 2>&1 || { echo "cold_pairs.sh: failed: $command" >&2; exit 1; }
    end=$EPOCHREALTIME
    echo "$which $start $end" >>"$times"
  done
done
python3 - "$times" <<'PY'
import statistics, sys
runs = {"old": [], "new": []}
for line in open(sys.argv[1]):
    which, start, end = line.split()
    runs[which].append(float(end) - float(start))
old, new = statistics.median(runs["old"]), statistics.median(runs["new"])
for which in ("old", "new"):
    print(f"{which}: median {statistics.median(runs[which]):.3f} s of {' '.join(f'{t:.3f}' for t in sorted(runs[which]))}")
print(f"old / new: {old / new:.2f}x")
PY
