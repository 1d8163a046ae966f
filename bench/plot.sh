#!/usr/bin/env bash
# Turns the CSV files that run_accel.sh, run_render.sh, run_povray.sh and run_mpi.sh leave in bench/results
# into the PNG plots of docs/performance.md (docs/perf_*.png). Needs gnuplot (Debian:
# apt-get install -y gnuplot-nox). Plots whose CSV is missing are skipped.
#
#   bench/plot.sh
#
# Environment: OUT (results folder, default bench/results), DOCS (default docs).
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=${OUT:-$ROOT/bench/results}
DOCS=${DOCS:-$ROOT/docs}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
command -v gnuplot >/dev/null || { echo "plot.sh: gnuplot not found (apt-get install -y gnuplot-nox)" >&2; exit 1; }
mkdir -p "$DOCS"

TERM_PNG="set terminal pngcairo size 900,560 font 'DejaVu Sans,11' noenhanced"

# --- speed-up vs threads ---------------------------------------------------------------------
if [ -f "$OUT/threads.csv" ]; then
  # scene threads speed-up(render) speed-up(wall), relative to each scene's 1-thread row.
  awk -F, 'NR > 1 { if ($2 == 1) { w1[$1] = $3; r1[$1] = $4 } rows[NR] = $0 }
           END { for (i in rows) { split(rows[i], f, ","); print f[1], f[2], r1[f[1]] / f[4], w1[f[1]] / f[3] } }' \
    "$OUT/threads.csv" | sort -k1,1 -k2,2n >"$TMP/threads.dat"
  scenes=$(cut -d' ' -f1 "$TMP/threads.dat" | uniq | tr '\n' ' ')
  maxj=$(sort -k2,2n "$TMP/threads.dat" | tail -1 | cut -d' ' -f2)
  printf '2 1.85\n' >"$TMP/target.dat"
  plots="x title 'ideal' dt 2 lc rgb '#888888', '$TMP/target.dat' using 1:2 with points pt 3 ps 3 lw 2 lc rgb '#cc0000' title 'target at -j 2 (1.85x)'"
  colours=("#1f77b4" "#d62728" "#2ca02c" "#9467bd" "#ff7f0e")
  i=0
  for s in $scenes; do
    c=${colours[$((i % 5))]}
    plots+=", '$TMP/threads.dat' using 2:(strcol(1) eq '$s' ? \$3 : 1/0) with linespoints lw 2 pt 7 lc rgb '$c' title '$s (render)'"
    plots+=", '$TMP/threads.dat' using 2:(strcol(1) eq '$s' ? \$4 : 1/0) with linespoints lw 1 dt 4 pt 6 lc rgb '$c' title '$s (whole process)'"
    i=$((i + 1))
  done
  gnuplot <<EOF
$TERM_PNG
set output '$DOCS/perf_threads.png'
set title 'Speed-up vs threads (bvh; median of runs)'
set xlabel 'threads (-j)'
set ylabel 'speed-up over -j 1'
set xrange [0.9:$maxj + 0.1]
set xtics 1
set yrange [0.8:$maxj + 0.2]
set key top left
set grid
plot $plots
EOF
  echo "wrote $DOCS/perf_threads.png"
fi

# --- mjray-mpi: measured speed-up vs ranks x threads, and the model for 1-512 nodes -----------
if [ -f "$OUT/mpi.csv" ] && [ -f "$OUT/mpi_model.csv" ]; then
  # scene workers(ranks x threads) speed-up label, for the mjray-mpi rows (ranks > 0)
  awk -F, 'NR > 1 && $2 > 0 { print $1, $2 * $3, $5, $2 "x" $3 }' "$OUT/mpi.csv" | sort -k1,1 -k2,2n >"$TMP/mpi.dat"
  awk -F, 'NR > 1 && $2 == 0 { print $1, $3, $5 }' "$OUT/mpi.csv" | sort -k1,1 -k2,2n >"$TMP/mjray.dat"
  scenes=$(cut -d' ' -f1 "$TMP/mpi.dat" | uniq | tr '\n' ' ')
  colours=("#1f77b4" "#d62728" "#2ca02c" "#9467bd" "#ff7f0e")
  left="(x < 2 ? x : 2) title 'ideal on 2 cores' dt 2 lc rgb '#888888'"
  i=0
  for s in $scenes; do
    c=${colours[$((i % 5))]}
    left+=", '$TMP/mpi.dat' using 2:(strcol(1) eq '$s' ? \$3 : 1/0):4 with labels offset 0,0.8 font ',8' tc rgb '$c' notitle"
    left+=", '$TMP/mpi.dat' using 2:(strcol(1) eq '$s' ? \$3 : 1/0) with points pt 7 ps 1.4 lc rgb '$c' title '$s mjray-mpi (ranks x threads)'"
    left+=", '$TMP/mjray.dat' using 2:(strcol(1) eq '$s' ? \$3 : 1/0) with points pt 6 ps 2 lw 2 lc rgb '$c' title '$s mjray -j N'"
    i=$((i + 1))
  done
  columns=$(head -1 "$OUT/mpi_model.csv" | awk -F, '{ print NF }')
  right=""
  for ((k = 2; k <= columns; k++)); do
    c=${colours[$(((k - 2) / 2 % 5))]}
    dash=$([ $((k % 2)) -eq 0 ] && echo 1 || echo 2)
    right+="${right:+, }'$OUT/mpi_model.csv' using 1:(100*\$$k) with linespoints lw 2 dt $dash pt 7 lc rgb '$c' title columnheader($k)"
  done
  gnuplot <<EOF
set terminal pngcairo size 1200,520 font 'DejaVu Sans,11' noenhanced
set output '$DOCS/perf_mpi.png'
set multiplot layout 1,2
set datafile separator whitespace
set title 'Measured here: whole-process speed-up over mjray -j 1'
set xlabel 'ranks x threads per rank (threads for mjray)'
set ylabel 'speed-up'
set xrange [0.5:4.5]
set xtics 1
set yrange [0:*]
set key top left font ',9'
set grid
plot $left
set datafile separator ','
set title 'Model: parallel efficiency on N nodes'
set xlabel 'nodes'
set ylabel 'efficiency (%)'
set logscale x 2
set xtics (1, 2, 4, 8, 16, 32, 64, 128, 256, 512)
set xrange [0.9:600]
set yrange [0:105]
set key bottom left font ',9'
plot $right
unset multiplot
EOF
  echo "wrote $DOCS/perf_mpi.png"
fi

# --- time vs grid size -----------------------------------------------------------------------
sweeps=$(ls "$OUT"/sweep_*.csv 2>/dev/null || true)
if [ -n "$sweeps" ]; then
  plots=""
  colours=("#1f77b4" "#d62728" "#2ca02c" "#9467bd")
  i=0
  for f in $sweeps; do
    name=$(basename "$f" .csv)
    name=${name#sweep_}
    c=${colours[$((i % 4))]}
    bvh=$(awk -F, '$4 == 2 { print $2 }' "$f")
    [ -n "$plots" ] && plots+=", "
    plots+="'$f' using 1:(\$4 == 0 ? \$2 : 1/0) with linespoints lw 2 pt 7 lc rgb '$c' title '$name: -g N'"
    plots+=", '$f' using 1:(\$4 == 1 ? \$2 : 1/0) with points pt 9 ps 2.5 lc rgb '$c' title '$name: -o (3 cbrt N)'"
    [ -n "$bvh" ] && plots+=", $bvh with lines dt 2 lc rgb '$c' title '$name: bvh'"
    i=$((i + 1))
  done
  gnuplot <<EOF
$TERM_PNG
set output '$DOCS/perf_grid_sweep.png'
set datafile separator ','
set title 'Whole-render time vs grid size (-j 2; median; sizes past the time limit not shown)'
set xlabel 'voxels per axis (-g N)'
set ylabel 'seconds (whole process)'
set logscale xy
set xrange [0.8:320]
set xtics (1, 2, 4, 8, 16, 32, 64, 128, 256)
set key bottom left box opaque
set grid
plot $plots
EOF
  echo "wrote $DOCS/perf_grid_sweep.png"
fi

# --- accelerators vs Embree ------------------------------------------------------------------
if [ -f "$OUT/accel.csv" ]; then
  # label bvh/embree grid/embree, for each thread count
  for j in $(awk -F, 'NR > 1 { print $4 }' "$OUT/accel.csv" | sort -un); do
    awk -F, -v j="$j" 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
         $4 == j { printf "%s/%s %.4f %.4f\n", $1, $3, $col["bvh_mrays"] / $col["embree_mrays"],
                   $col["grid_mrays"] / $col["embree_mrays"] }' "$OUT/accel.csv" >"$TMP/accel_$j.dat"
  done
  nj=0
  accel_plots=""
  for f in "$TMP"/accel_*.dat; do
    j=${f##*_}
    j=${j%.dat}
    nj=$((nj + 1))
    accel_plots+="set title 'Rays/s relative to Embree 3 (rtcIntersect1, rtcOccluded1), -j $j; higher is better'
plot '$f' using 2:xtic(1) title 'bvh' lc rgb '#1f77b4', '' using 3 title 'grid (-o)' lc rgb '#ff7f0e', \\
     0.8 with lines dt 2 lw 2 lc rgb '#cc0000' title 'bvh target 0.8', 1 with lines lc rgb '#444444' title 'Embree'
"
  done
  gnuplot <<EOF
$TERM_PNG
set terminal pngcairo size 1200,$((400 * nj)) font 'DejaVu Sans,11' noenhanced
set output '$DOCS/perf_accel.png'
set multiplot layout $nj,1
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set yrange [0:*]
set grid y
set ylabel 'ratio to Embree'
set key outside top center horizontal
set rmargin 8
set xtics rotate by -30 font ',9'
$accel_plots
unset multiplot
EOF
  echo "wrote $DOCS/perf_accel.png"
fi

# --- mjray vs POV-Ray ------------------------------------------------------------------------
if [ -f "$OUT/povray.csv" ]; then
  awk -F, 'NR > 1 { printf "%s(-j%s) %.4f %.4f\n", $1, $2, $3, $4 }' "$OUT/povray.csv" >"$TMP/povray.dat"
  gnuplot <<EOF
$TERM_PNG
set output '$DOCS/perf_povray.png'
set title 'Whole-process wall time, mjray vs POV-Ray 3.7 (median; lower is better)'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set yrange [0:*]
set grid y
set ylabel 'seconds'
set key top left
plot '$TMP/povray.dat' using 2:xtic(1) title 'mjray' lc rgb '#1f77b4', '' using 3 title 'POV-Ray 3.7' lc rgb '#2ca02c'
EOF
  echo "wrote $DOCS/perf_povray.png"
fi
