#!/usr/bin/env bash
# A Ramberg-Osgood scene solved by the stress code and, in the same run, the
# way a displacement code must (Output/Compare with a displacement code:
# Newton on the Q1 displacements, the law inverted at every Gauss point), on
# the same mesh, supports and linear solver (issue 18). One row per run:
# displacement dofs, Newton steps of both, the most local steps a Gauss
# point's inversion took, both solves' seconds, their ratio, and the largest
# difference of the displacements.
#   RUNS="ramberg-osgood-beam:4 cantilever-ro:6" REPEAT=3 bash scripts/compare-displacement-code.sh
# RUNS entries are scene:refinements; cantilever-ro is parameters/cantilever.prm
# with the Ramberg-Osgood law of doc/materials.md (a = 3/7, sigma_0 = 40 MPa,
# n = 5), DGQ1 stresses and the condensed path. With REPEAT > 1 the seconds
# and the ratio are medians. Needs a Release build in build/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$root/build/hrcontact"
. "$root/scripts/scene-prm.sh"
runs=${RUNS:-"ramberg-osgood-beam:4 cantilever-ro:4"}
repeat=${REPEAT:-1}
printf "| scene | ref. | dofs | stress code Newton | displacement code Newton | local steps (max) | stress code s | displacement code s | displacement / stress | max displacement difference |\n"
printf "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
for run in $runs; do
  IFS=: read -r name r <<< "$run"
  scene=$name
  extra=""
  if [ "$name" = cantilever-ro ]; then
    scene=cantilever
    extra="subsection Material
  set Model = Ramberg-Osgood
  set Ramberg-Osgood coefficient = 3/7
  set Ramberg-Osgood reference stress = 40e6
  set Ramberg-Osgood exponent = 5
end
subsection Finite elements
  set Stress element = DGQ1
end
subsection Equilibrium reduction
  set Path = condensed
end"
  fi
  out="$work/$name-$r"
  EXTRA_PRM="$extra" write_scene_prm "$out.prm" "$scene" "$r" "$out" \
    "set Print timing = false" "set Compare with a displacement code = true"
  : > "$out.times"
  for k in $(seq "$repeat"); do
    "$exe" "$out.prm" > "$out.log" 2>&1 || { echo "run $run failed: $(tail -1 "$out.log")" >&2; continue 2; }
    echo "$(get stress_code_seconds "$out") $(get displacement_code_seconds "$out") $(get displacement_code_to_solve "$out")" >> "$out.times"
  done
  s=$(cut -d' ' -f1 "$out.times" | median); d=$(cut -d' ' -f2 "$out.times" | median)
  q=$(cut -d' ' -f3 "$out.times" | median)
  printf "| %s | %s | %s | %s | %s | %s | %.2f | %.2f | %.2f | %.1e |\n" "$name" "$r" \
    "$(get displacement_dofs "$out")" "$(get material_newton_steps "$out")" \
    "$(get displacement_code_newton_steps "$out")" "$(get displacement_code_local_steps "$out")" \
    "$s" "$d" "$q" "$(get displacement_code_difference "$out")"
done
