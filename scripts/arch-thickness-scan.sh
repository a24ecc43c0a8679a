#!/bin/bash
# The self-weight no-tension arch (parameters/masonry-arch.prm without its
# point load, mean radius 4.7) with the cone in closed form at the Gauss
# points, over thicknesses t/R and refinements: one line per run with the
# outcome (converged, "no admissible stress field", not converged in 300
# Newton steps), the steps, the last model stress error and the wall time.
#   scripts/arch-thickness-scan.sh [BUILD_DIR] [REFINEMENTS] [T_OVER_R...]
# Defaults: build, "2 3 4", 0.10 0.11 0.12 0.13 0.14 0.16 0.18.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
refinements=${2:-2 3 4}
shift $(($# > 2 ? 2 : $#))
ratios=${*:-0.10 0.11 0.12 0.13 0.14 0.16 0.18}
source "$root/scripts/scene-prm.sh"
exe=$(cd "$build" && pwd)/hrcontact
echo "| refinements | t/R | outcome | Newton steps | last model stress error | wall time (s) |"
echo "|---|---|---|---|---|---|"
for r in $refinements; do
  for tr in $ratios; do
    read -r Ri Ro < <(awk -v tr="$tr" 'BEGIN { t = tr * 4.7; printf "%.10g %.10g\n", 4.7 - t / 2, 4.7 + t / 2 }')
    sed -e "s/Ri = 4.1, Ro = 5/Ri = $Ri, Ro = $Ro/" -e "s/: 4.1 : 5 :/: $Ri : $Ro :/" \
        -e "s/P = 5e4/P = 0/" -e "s/Global refinements = 3/Global refinements = $r/" \
        "$root/parameters/masonry-arch.prm" > "$work/arch.prm"
    printf "subsection Stress constraint iteration\n  set Method = closed-form projection\n  set Stress tolerance = 1e-6\nend\nsubsection Material iteration\n  set Maximum steps = 300\nend\nsubsection Output\n  set Write solution = false\n  set Output directory = %s\nend\n" "$work/out" >> "$work/arch.prm"
    start=$(date +%s.%N)
    "$exe" "$work/arch.prm" > "$work/arch.log" 2>&1 || true
    end=$(date +%s.%N)
    outcome=converged
    grep -q "no admissible" "$work/arch.log" && outcome="no admissible stress field"
    grep -q "no convergence" "$work/arch.log" && outcome="not converged"
    steps=$(grep -c "^  material step [0-9]*:" "$work/arch.log" || true)
    last=$(grep "^  material step [0-9]*:" "$work/arch.log" | tail -1 | awk '{ print $NF }')
    echo "| $r | $tr | $outcome | $((steps + 1)) | $last | $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }') |"
  done
done
