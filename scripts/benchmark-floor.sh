#!/usr/bin/env bash
# The contact solve against the floor, in one run on the same mesh and
# processes (issue 17): Output/Time the Q1 floor (a plain Q1 displacement
# solve assembled from the displacement bilinear form, CG + the same ML AMG)
# and Output/Time a linear elastic solve (the project's own, condensed path),
# with every other setting the scene's default. One row per configuration:
# displacement dofs, multiplier updates, Newton steps, linear solves, CG
# iterations per linear solve (contact, where CG is used) and of the floor,
# seconds of the contact solve, the elastic solve and the floor, the ratios
# to the floor, and the peak memory per process.
#   RUNS="hertz:5:1 hertz:7:1 hertz:7:2" REPEAT=3 bash scripts/benchmark-floor.sh
# RUNS entries are scene:refinements:processes; with REPEAT > 1 the seconds
# are medians. EXTRA_PRM is appended to every generated .prm. Needs a Release
# build in build/; as root, Open MPI needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$root/build/hrcontact"
. "$root/scripts/scene-prm.sh"
runs=${RUNS:-"hertz:5:1 hertz:7:1"}
repeat=${REPEAT:-1}
printf "| scene | ref. | np | dofs | path | solver | updates | Newton | solves | CG it / solve | floor CG it | contact s | elastic s | floor s | contact / floor | elastic / floor | peak MB / process |\n"
printf "|---|---:|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
for run in $runs; do
  IFS=: read -r scene r np <<< "$run"
  out="$work/$scene-$r-$np"
  write_scene_prm "$out.prm" "$scene" "$r" "$out" "set Print timing = false" \
    "set Time the Q1 floor = true" "set Time a linear elastic solve = true"
  : > "$out.times"
  for k in $(seq "$repeat"); do
    mpirun -np "$np" "$exe" "$out.prm" > "$out.log" 2>&1 || { echo "run $run failed: $(tail -1 "$out.log")" >&2; continue 2; }
    echo "$(get contact_solve_seconds "$out") $(get linear_elastic_solve_seconds "$out") $(get q1_floor_seconds "$out")" >> "$out.times"
  done
  c=$(cut -d' ' -f1 "$out.times" | median); e=$(cut -d' ' -f2 "$out.times" | grep . | median || true)
  f=$(cut -d' ' -f3 "$out.times" | median)
  [ -z "$e" ] || e=$(printf '%.2f' "$e")
  solves=$(get linear_solves "$out"); its=$(get linear_iterations "$out")
  solver=$(get linear_solver "$out"); path=$(get solution_path "$out")
  per=$([ "$solver" = cg-amg ] && [ -n "$solves" ] && echo "scale=0; $its / $solves" | bc || echo "–")
  peak=$(echo "scale=0; $(get peak_memory_MB "$out") / $np" | bc)
  printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2f | %s | %.2f | %.1f | %s | %s |\n" \
    "$scene" "$r" "$np" "$(get displacement_dofs "$out")" "$path" "${solver:-dense}" \
    "$(get iterations "$out")" "$(get newton_steps "$out")" "${solves:-–}" "$per" \
    "$(get q1_floor_cg_iterations "$out")" "$c" "${e:-–}" "$f" \
    "$(echo "$c / $f" | bc -l)" "$([ -n "$e" ] && printf '%.1f' "$(echo "$e / $f" | bc -l)" || echo –)" "$peak"
done
