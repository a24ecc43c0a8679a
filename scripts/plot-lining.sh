#!/usr/bin/env bash
# Draw the diagrams engineers read for a tunnel_lining run (as the paper's
# Figs 11-12): axial force N and bending moment M along the lining
# (lining.csv), the contact pressure along the extrados (lining-contact.csv)
# and the deformed mid-line, into OUTPUT_DIRECTORY/lining.png.
#   bash scripts/plot-lining.sh output/tunnel
# s is the arc length along the mid-line (N, M) or the extrados (pressure)
# from the crown top. Needs gnuplot (Debian: apt-get install gnuplot-nox).
set -euo pipefail
dir=${1:?usage: plot-lining.sh OUTPUT_DIRECTORY}
sections="$dir/lining.csv"
contact="$dir/lining-contact.csv"
[ -f "$sections" ] || { echo "no $sections: run a tunnel_lining scene first" >&2; exit 1; }
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }
column() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
cs=$(column "$sections" s); cN=$(column "$sections" N); cM=$(column "$sections" M)
cx=$(column "$sections" x); cy=$(column "$sections" y)
cux=$(column "$sections" ux); cuy=$(column "$sections" uy)
# Displacement magnification: the largest displacement drawn as 5 % of the
# lining's extent.
read -r extent umax < <(awk -F, -v x="$cx" -v y="$cy" -v ux="$cux" -v uy="$cuy" \
  'NR>1 { e = sqrt($x*$x + $y*$y); if (e > E) E = e; u = sqrt($ux*$ux + $uy*$uy); if (u > U) U = u }
   END { print E, U }' "$sections")
scale=$(awk -v e="$extent" -v u="$umax" 'BEGIN { print (u > 0) ? 0.05 * e / u : 1 }')
png="$dir/lining.png"
{
  echo "set terminal pngcairo size 1400,1000 font ',11'"
  echo "set output '$png.tmp'"
  echo "set datafile separator ','"
  echo "set multiplot layout 2,2 title 'Tunnel lining ($dir)'"
  echo "set grid; set key top right"
  echo "set xlabel 's along the mid-line from the crown top'"
  echo "set ylabel 'axial force N (tension > 0)'"
  echo "plot '$sections' using $cs:$cN with linespoints pt 7 ps 0.4 title 'N'"
  echo "set ylabel 'bending moment M (> 0: inner fibre in tension)'"
  echo "plot '$sections' using $cs:$cM with linespoints pt 7 ps 0.4 title 'M'"
  if [ -f "$contact" ]; then
    ccs=$(column "$contact" s); cp=$(column "$contact" pressure); cst=$(column "$contact" status)
    # A corner of the extrados (the arcs' joint) carries a concentrated
    # reaction: clip the axis at 1.5 x the largest pressure further than
    # 0.5 from the peak and print the peak instead.
    read -r peak speak rest < <(awk -F, -v s="$ccs" -v p="$cp" \
      'NR>1 { S[NR]=$s; P[NR]=$p; if ($p > M) { M=$p; SM=$s } }
       END { for (i in P) if ((S[i]-SM > 0.5 || SM-S[i] > 0.5) && P[i] > R) R=P[i];
             print M, SM, R }' "$contact")
    if awk -v m="$peak" -v r="$rest" 'BEGIN { exit !(r > 0 && m > 2 * r) }'; then
      echo "set yrange [0:$(awk -v r="$rest" 'BEGIN { print 1.5 * r }')]"
      echo "set label 1 sprintf('peak %.4g at s = %.3g (off scale)', $peak, $speak) at graph 0.02, graph 0.95"
    fi
    echo "set xlabel 's along the extrados from the crown top'"
    echo "set ylabel 'contact pressure (reaction per unit length)'"
    echo "plot '$contact' using $ccs:$cp with lines title 'pressure', \
      '' using $ccs:(strcol($cst) eq 'contact' ? 0 : 1/0) with points pt 7 ps 0.5 title 'pressed nodes'"
  fi
  echo "unset label 1; set autoscale y"
  echo "set size ratio -1; set xlabel 'x'; set ylabel 'y'; set key bottom right"
  echo "plot '$sections' using $cx:$cy with lines lw 1 dt 2 title 'mid-line', \
    '' using (\$$cx + $scale*\$$cux):(\$$cy + $scale*\$$cuy) with lines lw 2 \
    title sprintf('deformed, displacements x %.0f', $scale)"
  echo "unset multiplot"
} | gnuplot
mv "$png.tmp" "$png"
echo "wrote $png"
