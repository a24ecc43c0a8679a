#!/usr/bin/env bash
# Peak resident memory per process as the process count grows (issue 17's
# distributed data path): one run per entry, default settings plus the timed
# Q1 floor, so that the floor's own peak on the same mesh and processes is
# in the same run (the high-water mark after the floor stage, mesh and
# DoFHandlers included). One row per run: dofs, the largest process's peak
# after the floor and at the end, the sum over the processes, the contact
# solve and floor seconds (single runs: timings are indicative only).
#   RUNS="hertz:9:1 hertz:9:2 hertz:9:4" bash scripts/memory-per-process.sh
# RUNS entries are scene:refinements:processes (more processes than cores
# are oversubscribed). EXE overrides the executable (e.g. an older build);
# EXTRA_PRM is appended to every generated .prm. As root, Open MPI needs
# OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${EXE:-"$root/build/hrcontact"}
. "$root/scripts/scene-prm.sh"
runs=${RUNS:-"hertz:8:1 hertz:8:2 hertz:8:4"}
# The "peak so far" of a stage in the memory table the run prints.
stage_peak() { grep "^  $1 " "$2" | sed -n 's/.*(peak so far \([0-9]*\)).*/\1/p' | tail -1; }
printf "| scene | ref. | np | dofs | floor peak MB, largest process | peak MB, largest process | peak MB, all processes | contact s | floor s |\n"
printf "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
for run in $runs; do
  IFS=: read -r scene r np <<< "$run"
  out="$work/$scene-$r-$np"
  write_scene_prm "$out.prm" "$scene" "$r" "$out" "set Print timing = true" \
    "set Time the Q1 floor = true"
  mpirun -np "$np" "$exe" "$out.prm" > "$out.log" 2>&1 || { echo "run $run failed: $(tail -1 "$out.log")" >&2; continue; }
  printf "| %s | %s | %s | %s | %s | %s | %.0f | %.1f | %.1f |\n" \
    "$scene" "$r" "$np" "$(get displacement_dofs "$out")" \
    "$(stage_peak "Q1 floor (timed)" "$out.log")" \
    "$(stage_peak "stresses and displacements" "$out.log")" \
    "$(get peak_memory_MB "$out")" "$(get contact_solve_seconds "$out")" \
    "$(get q1_floor_seconds "$out")"
  [ -z "${KEEP_LOGS:-}" ] || cp "$out.log" "$KEEP_LOGS/$scene-$r-$np.log"
done
