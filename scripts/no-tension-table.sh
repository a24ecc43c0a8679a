#!/bin/bash
# The no-tension scenes with the cone at the Gauss points (the scene's
# Stress constraint iteration/Method, or EXTRA_PRM's), one row per
# refinement: cells, displacement dofs, material Newton steps, the stress
# errors against the closed form (the manufactured piers) and the wall time.
#   scripts/no-tension-table.sh [BUILD_DIR] [SCENE] [REFINEMENTS...]
# Defaults: build, no-tension-manufactured-pier, 2 3 4 5 6.
# EXTRA_PRM (text) is appended to every run's parameters.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
scene=${2:-no-tension-manufactured-pier}
shift $(($# > 2 ? 2 : $#))
refinements=${*:-2 3 4 5 6}
source "$root/scripts/scene-prm.sh"
exe=$(cd "$build" && pwd)/hrcontact
echo "| cells | displacement dofs | material Newton steps | last model stress change | stress error L2 | stress error max | wall time (s) | outcome |"
echo "|---|---|---|---|---|---|---|---|"
for r in $refinements; do
  dir=$work/r$r
  write_scene_prm "$work/r$r.prm" "$scene" "$r" "$dir"
  if "$exe" "$work/r$r.prm" > "$work/r$r.log" 2>&1; then
    outcome=converged
  else
    outcome="exit $?: $(tail -1 "$work/r$r.log" | cut -c1-80)"
  fi
  if [ -f "$dir/summary.txt" ]; then
    echo "| $(get cells "$dir") | $(get displacement_dofs "$dir") | $(get material_newton_steps "$dir") | $(get material_stress_change "$dir") | $(get stress_error_l2 "$dir") | $(get stress_error_max "$dir") | $(get wall_time "$dir") | $outcome |"
  else
    steps=$(grep -c "^  material step [0-9]*:" "$work/r$r.log" || true)
    echo "| $r refinements | | $((steps + 1)) | | | | | $outcome |"
  fi
done
