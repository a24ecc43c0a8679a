#!/usr/bin/env bash
# The error bound's cost against the floor, in one run on the same mesh
# (issue 52: "the bound costs <= 1 elastic solve"): parameters/
# cantilever-error-bound.prm at the given refinements with Output/Time the
# Q1 floor, serially; medians of REPEAT runs of error_bound_seconds and
# q1_floor_seconds, their ratio, and the effectivity index.
#   REPEAT=5 bash scripts/benchmark-error-bound.sh [REFINEMENTS...]
# Defaults: 4 5 6. Needs a Release build in build/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$root/build/hrcontact"
. "$root/scripts/scene-prm.sh"
repeat=${REPEAT:-3}
refinements=${*:-4 5 6}
printf "| refinements | cells | displacement dofs | bound s | floor s | bound / floor | effectivity |\n"
printf "|---:|---:|---:|---:|---:|---:|---:|\n"
for r in $refinements; do
  out="$work/r$r"
  write_scene_prm "$out.prm" cantilever-error-bound "$r" "$out" \
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
  printf "| %s | %s | %s | %.3f | %.3f | %.2f | %.3f |\n" "$r" "$(get cells "$out")" \
    "$(get displacement_dofs "$out")" "$b" "$f" "$(awk -v b="$b" -v f="$f" 'BEGIN { print b / f }')" \
    "$(get effectivity_index "$out")"
done
