#!/usr/bin/env bash
# How far the dense equilibrium reduction (the paper's null-space path) goes:
# the cantilever of parameters/cantilever.prm on 10k x k cells, for growing k,
# with DGQ1 stresses (STRESS_ELEMENT=Pian-Sumihara for the scene's own), one run each (the wall times of these runs are seconds to minutes, far above
# the noise). Prints a Markdown table: cells, stress dofs, free rows n,
# dim(s0) = m, wall seconds of the whole run, peak resident memory.
#   bash scripts/benchmark-reduction.sh [k ...]      (default: 4 6 8 10 12)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/hrcontact ] || { echo "build first: bash scripts/quickstart.sh example" >&2; exit 1; }
ks=${*:-4 6 8 10 12}
source scripts/run-variant.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| cells | stress dofs | free rows n | dim(s0) m | wall s | peak RSS MiB |"
echo "|---:|---:|---:|---:|---:|---:|"
for k in $ks; do
  run_variant parameters/cantilever.prm "subsection Geometry
  set Grid arguments     = $((10 * k)), $k : 0, -0.5 : 10, 0.5 : true
  set Global refinements = 0
end
subsection Equilibrium reduction
  set Path = null-space
end
subsection Finite elements
  set Stress element = ${STRESS_ELEMENT:-DGQ1}
end" "$tmp"
  printf "| %s | %s | %s | %s | %.1f | %d |\n" "$(get cells)" "$(get stress_dofs)" \
    "$(get free_rows)" "$(get self_equilibrated_stresses)" \
    "$seconds" "$rss_mib"
done
