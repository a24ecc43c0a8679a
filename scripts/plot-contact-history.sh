#!/usr/bin/env bash
# Draw contact-history.csv (written when Output/Tracked contact nodes is set)
# as a PNG like the paper's Fig. 14: normal displacement w_n, reaction p_n and
# the compliance alpha of the tracked nodes at each multiplier update.
#   bash scripts/plot-contact-history.sh output/hertz-history
# Needs gnuplot (Debian: apt-get install gnuplot-nox).
set -euo pipefail
dir=${1:?usage: plot-contact-history.sh OUTPUT_DIRECTORY}
csv="$dir/contact-history.csv"
[ -f "$csv" ] || { echo "no $csv: set Output/Tracked contact nodes and run the scene" >&2; exit 1; }
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }
nodes=$(tail -n +2 "$csv" | cut -d, -f2 | sort -un)
column() { head -1 "$csv" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
cw=$(column w_n); cp=$(column p_n); ca=$(column alpha)
png="$dir/contact-history.png"
{
  echo "set terminal pngcairo size 1500,450 font ',11'"
  echo "set output '$png.tmp'"
  echo "set datafile separator ','"
  echo "set multiplot layout 1,3 title 'Augmented Lagrangian history of tracked contact nodes ($dir)'"
  echo "set xlabel 'multiplier update k'; set grid; set key bottom right"
  echo "set ylabel 'normal displacement w_n'"
  printf "plot "
  sep=""
  for n in $nodes; do
    label=$(awk -F, -v n="$n" 'NR>1 && $2==n {printf "node %s (x = %.4g)", n, $3; exit}' "$csv")
    printf "%s'%s' using 1:(\$2==%s ? \$${cw} : 1/0) with linespoints title '%s'" "$sep" "$csv" "$n" "$label"
    sep=", "
  done
  echo
  echo "set ylabel 'reaction p_n (compressive < 0)'"
  printf "plot "
  sep=""
  for n in $nodes; do
    printf "%s'%s' using 1:(\$2==%s ? \$${cp} : 1/0) with linespoints title 'node %s'" "$sep" "$csv" "$n" "$n"
    sep=", "
  done
  echo
  echo "set ylabel 'compliance alpha'; set logscale y"
  echo "plot '$csv' using 1:(\$2==1 ? \$${ca} : 1/0) with linespoints title 'alpha'"
  echo "unset multiplot"
} | gnuplot
mv "$png.tmp" "$png"
echo "wrote $png"
