#!/usr/bin/env bash
# Condensed path: sparse direct (UMFPACK) against CG + Trilinos ML AMG with
# the rigid-body modes, and what reusing the AMG hierarchy between Newton
# steps and warm-starting CG buy. Runs each configuration on the given scenes
# and refinement levels and prints one table row per run (wall seconds of the
# whole run, linear solves, CG iterations, AMG set-ups, seconds in set-ups and
# in solves, peak memory).
#   bash scripts/benchmark-linear-solver.sh                  # default set
#   SCENES="hertz:5 tunnel:4" bash scripts/benchmark-linear-solver.sh
# Needs a Release build in build/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$root/build/hrcontact"
scenes=${SCENES:-"hertz:5 hertz:7 tunnel:4 tunnel:5"}
configs=${CONFIGS:-"direct cg-amg:fresh:cold cg-amg:fresh:warm cg-amg:reuse:cold cg-amg:reuse:warm"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "| scene | refinements | displacement dofs | solver | reuse AMG | warm start | Newton steps | CG iterations | AMG set-ups | set-up s | linear s (incl. set-up) | run s | peak MB |\n"
printf "|---|---:|---:|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n"
for sc in $scenes; do
  scene=${sc%%:*}; r=${sc##*:}
  for cfg in $configs; do
    IFS=: read -r solver reuse warm <<< "$cfg"
    out="$work/$scene-$r-${cfg//:/-}"
    {
      echo "include $root/parameters/$scene.prm"
      echo "subsection Geometry"; echo "  set Global refinements = $r"; echo "end"
      echo "subsection Equilibrium reduction"; echo "  set Path = condensed"; echo "end"
      echo "subsection Linear solver"
      echo "  set Solver = $solver"
      [ "$solver" = cg-amg ] && echo "  set Reuse preconditioner = $([ "$reuse" = reuse ] && echo true || echo false)"
      [ "$solver" = cg-amg ] && echo "  set Warm start = $([ "$warm" = warm ] && echo true || echo false)"
      echo "end"
      echo "subsection Output"; echo "  set Output directory = $out"; echo "  set Write solution = false"
      echo "  set Print timing = false"; echo "end"
    } > "$out.prm"
    /usr/bin/time -f "%e %M" -o "$out.time" "$exe" "$out.prm" > "$out.log" 2>&1 || { echo "run failed: $out.log" >&2; cat "$out.log" >&2; exit 1; }
    get() { grep "^$1 = " "$out/summary.txt" | sed 's/.* = //'; }
    # Set-up and solve seconds do not overlap: the linear solver's time is
    # their sum.
    linear=$(awk -v a="$(get linear_setup_seconds)" -v b="$(get linear_solve_seconds)" 'BEGIN { print a + b }')
    read -r wall mem < "$out.time"
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2f | %.2f | %.1f | %.0f |\n" \
      "$scene" "$r" "$(get displacement_dofs)" "$solver" "${reuse:--}" "${warm:--}" \
      "$(get newton_steps)" "$(get linear_iterations)" "$(get preconditioner_setups)" \
      "$(get linear_setup_seconds)" "$linear" "$wall" "$((mem / 1024))"
  done
done
