#!/bin/bash
# The smallest thickness of the self-weight no-tension arch
# (parameters/masonry-arch.prm without its point load, mean radius 4.7)
# that the Gauss-point discretisation carries, by bisection on t/R with the
# scene's default method (the interior point, its Stress tolerance
# automatic: 1e-4): a run that converges is admissible, one that
# stops with "no admissible stress field" is not; anything else ends the
# bisection of that mesh as inconclusive. One line per refinement: the
# bracket, its midpoint, and the Newton steps at the admissible end.
#   scripts/arch-min-thickness.sh [BUILD_DIR] [REFINEMENTS] [LOW HIGH WIDTH]
# Defaults: build, "2 3 4", 0.09 0.18 0.004 (so +-0.002).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
refinements=${2:-2 3 4}
low0=${3:-0.09}
high0=${4:-0.18}
width=${5:-0.004}
source "$root/scripts/scene-prm.sh"
exe=$(cd "$build" && pwd)/hrcontact
# run T_OVER_R REFINEMENTS: prints converged, refused or failed, and steps
run() {
  read -r Ri Ro < <(awk -v tr="$1" 'BEGIN { t = tr * 4.7; printf "%.10g %.10g\n", 4.7 - t / 2, 4.7 + t / 2 }')
  sed -e "s/Ri = 4.1, Ro = 5/Ri = $Ri, Ro = $Ro/" -e "s/: 4.1 : 5 :/: $Ri : $Ro :/" \
      -e "s/P = 5e4/P = 0/" -e "s/Global refinements = 3/Global refinements = $2/" \
      "$root/parameters/masonry-arch.prm" > "$work/arch.prm"
  printf "subsection Output\n  set Write solution = false\n  set Output directory = %s\nend\n" "$work/out" >> "$work/arch.prm"
  rm -rf "$work/out"
  if "$exe" "$work/arch.prm" > "$work/arch.log" 2>&1; then
    echo "converged $(sed -n 's/^material_newton_steps = //p' "$work/out/summary.txt")"
  elif grep -q "no admissible" "$work/arch.log"; then
    echo "refused 0"
  else
    echo "failed 0"
  fi
}
echo "| refinements | cells along the axis | smallest admissible t/R | largest refused t/R | minimum t/R | Newton steps at the smallest admissible |"
echo "|---|---|---|---|---|---|"
for r in $refinements; do
  low=$low0 high=$high0 steps=
  read -r outcome n < <(run "$high" "$r")
  [ "$outcome" = converged ] || { echo "| $r | $((12 << r)) | t/R = $high: $outcome | | | |"; continue; }
  steps=$n
  while awk -v a="$low" -v b="$high" -v w="$width" 'BEGIN { exit !(b - a > w) }'; do
    mid=$(awk -v a="$low" -v b="$high" 'BEGIN { printf "%.6g", (a + b) / 2 }')
    read -r outcome n < <(run "$mid" "$r")
    case $outcome in
      converged) high=$mid steps=$n ;;
      refused) low=$mid ;;
      *) echo "| $r | $((12 << r)) | $high | $low | inconclusive at $mid | |"; continue 2 ;;
    esac
  done
  echo "| $r | $((12 << r)) | $high | $low | $(awk -v a="$low" -v b="$high" 'BEGIN { printf "%.3f", (a + b) / 2 }') | $steps |"
done
