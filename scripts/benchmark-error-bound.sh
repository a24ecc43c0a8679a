#!/usr/bin/env bash
# The error bound's cost against the floor, in one run on the same mesh
# (issue 52: "the bound costs <= 1 elastic solve"): a scene (SCENE, default
# cantilever-error-bound; signorini-error-bound, hertz with its Error bound
# switched on) at the given refinements with Output/Time the Q1 floor,
# serially; medians of REPEAT runs of error_bound_seconds and
# q1_floor_seconds, their ratio, and the effectivity index (where the scene
# has a reference).
#   REPEAT=5 [SCENE=NAME] bash scripts/benchmark-error-bound.sh [REFINEMENTS...]
# Defaults: 4 5 6. Needs a Release build in build/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$root/build/hrcontact"
. "$root/scripts/scene-prm.sh"
repeat=${REPEAT:-3}
refinements=${*:-4 5 6}
scene=${SCENE:-cantilever-error-bound}
# Hertz and other scenes without the bound in their file: switch it on.
export EXTRA_PRM="${EXTRA_PRM:-}
subsection Postprocess
  set Error bound = true
  set Pressure plot = false
end"
printf "| refinements | cells | displacement dofs | bound s | floor s | bound / floor | effectivity |\n"
printf "|---:|---:|---:|---:|---:|---:|---:|\n"
for r in $refinements; do
  out="$work/r$r"
  write_scene_prm "$out.prm" "$scene" "$r" "$out" \
    "set Print timing = false" "set Time the Q1 floor = true"
  : > "$out.bound"
  : > "$out.floor"
  for k in $(seq "$repeat"); do
    "$exe" "$out.prm" > "$out.log" 2>&1 || { echo "run r$r failed: $(tail -1 "$out.log")" >&2; continue 2; }
    get error_bound_seconds "$out" >> "$out.bound"
    get q1_floor_seconds "$out" >> "$out.floor"
  done
  b=$(median < "$out.bound")
  f=$(median < "$out.floor")
  eff=$(get effectivity_index "$out")
  eff=$([ -n "$eff" ] && printf "%.3f" "$eff" || echo "-")
  printf "| %s | %s | %s | %.3f | %.3f | %.2f | %s |\n" "$r" "$(get cells "$out")" \
    "$(get displacement_dofs "$out")" "$b" "$f" "$(awk -v b="$b" -v f="$f" 'BEGIN { print b / f }')" \
    "$eff"
done
