#!/usr/bin/env bash
# Issue 4's scaling table: the contact solve against one linear elastic solve
# on the same mesh and processes, measured in the same run (Output/Time a
# linear elastic solve), for the condensed path with CG + AMG and for the
# null-space path, serially and under mpirun. One table row per
# configuration: displacement dofs, multiplier updates, Newton steps, CG
# iterations, contact-solve seconds, linear elastic seconds, their ratio and
# the peak resident memory summed over the processes.
#   bash scripts/benchmark-scaling.sh                       # default set
#   RUNS="hertz:7:condensed:2 block-3d-contact:3:condensed:1" REPEAT=3 \
#     bash scripts/benchmark-scaling.sh
# EXTRA_PRM is appended to every generated .prm, e.g.
#   EXTRA_PRM=$'subsection Augmented Lagrangian\n  set Iteration scheme = diagonal\nend'
# RUNS entries are scene:refinements:path:processes. With REPEAT > 1 each
# configuration runs that often and the seconds are medians (the other
# columns do not change between repetitions). Needs a Release build in
# build/; as root, Open MPI needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$root/build/hrcontact"
runs=${RUNS:-"hertz:4:null-space:1 hertz:5:condensed:1 hertz:5:condensed:2 hertz:7:condensed:1 hertz:7:condensed:2"}
repeat=${REPEAT:-1}
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
printf "| scene | ref. | path | processes | displacement dofs | updates | Newton steps | CG iterations | contact solve s | linear elastic solve s | ratio | peak MB (all processes) |\n"
printf "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
for run in $runs; do
  IFS=: read -r scene r path np <<< "$run"
  out="$work/$scene-$r-$path-$np"
  {
    echo "include $root/parameters/$scene.prm"
    echo "subsection Geometry"; echo "  set Global refinements = $r"; echo "end"
    echo "subsection Equilibrium reduction"; echo "  set Path = $path"; echo "end"
    echo "subsection Linear solver"; echo "  set Solver = cg-amg"; echo "end"
    echo "subsection Output"; echo "  set Output directory = $out"; echo "  set Write solution = false"
    echo "  set Print timing = false"
    [ "$path" = condensed ] && echo "  set Time a linear elastic solve = true"
    echo "end"
    echo "${EXTRA_PRM:-}"
  } > "$out.prm"
  cmd=("$exe" "$out.prm")
  [ "$np" -gt 1 ] && cmd=(mpirun -np "$np" "${cmd[@]}")
  : > "$out.contact"; : > "$out.elastic"
  for ((k = 0; k < repeat; ++k)); do
    "${cmd[@]}" > "$out.log" 2>&1 || { echo "run failed: $out.log" >&2; cat "$out.log" >&2; exit 1; }
    get() { grep "^$1 = " "$out/summary.txt" | sed 's/.* = //'; }
    get contact_solve_seconds >> "$out.contact"
    (get linear_elastic_solve_seconds || echo nan) >> "$out.elastic"
  done
  contact=$(median < "$out.contact")
  elastic=$(median < "$out.elastic")
  ratio=$(awk -v c="$contact" -v e="$elastic" 'BEGIN { print (e == "nan" || e == 0) ? "–" : sprintf("%.1f", c / e) }')
  elastic_text=$(awk -v e="$elastic" 'BEGIN { print (e == "nan") ? "–" : sprintf("%.2f", e) }')
  printf "| %s | %s | %s | %s | %s | %s | %s | %s | %.2f | %s | %s | %.0f |\n" \
    "$scene" "$r" "$path" "$np" "$(get displacement_dofs)" "$(get iterations)" \
    "$(get newton_steps)" "$(get linear_iterations || echo –)" "$contact" \
    "$elastic_text" "$ratio" "$(get peak_memory_MB)"
done
