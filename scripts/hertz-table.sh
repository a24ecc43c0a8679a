#!/usr/bin/env bash
# Hertz refinement table for doc/contact.md: parameters/hertz.prm at the given
# numbers of global refinements (default 1 2 3 4), one run each. Columns:
# cells, displacement and stress dofs, contact half width a and peak pressure
# p0 with their errors against Hertz, multiplier updates, Newton steps, wall
# seconds of the whole run, peak resident memory.
#   bash scripts/hertz-table.sh [refinements ...]
# HERTZ_PATH=null-space|condensed|automatic (default automatic) picks the
# Newton-step path (Equilibrium reduction/Path).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/hrcontact ] || { echo "build first: bash scripts/quickstart.sh example" >&2; exit 1; }
source scripts/run-variant.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
path=${HERTZ_PATH:-automatic}
echo "| refinements | path | cells | u dofs | stress dofs | a (mm) | error a | p0 (GPa) | error p0 | updates | Newton steps | wall s | peak RSS MiB |"
echo "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for r in ${*:-1 2 3 4}; do
  run_variant parameters/hertz.prm "subsection Geometry
  set Global refinements = $r
end
subsection Equilibrium reduction
  set Path = $path
end" "$tmp"
  printf "| %s | %s | %s | %s | %s | %.4f | %+.2f %% | %.3f | %+.2f %% | %s | %s | %.1f | %d |\n" \
    "$r" "$(get solution_path)" "$(get cells)" "$(get displacement_dofs)" "$(get stress_dofs)" \
    "$(calc "$(get contact_half_width) * 1000")" \
    "$(calc "$(get relative_error_half_width) * 100")" \
    "$(calc "$(get peak_pressure) / 1e9")" \
    "$(calc "$(get relative_error_peak_pressure) * 100")" \
    "$(get iterations)" "$(get newton_steps)" \
    "$seconds" "$rss_mib"
done
