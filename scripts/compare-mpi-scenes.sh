#!/bin/bash
# Run every scene of parameters/ serially and under `mpirun -np N` (default
# 2) and compare their result files with scripts/compare-results.py (values to
# 1e-6 of their scale; timings skipped). Both on the condensed path: several
# processes always take it (the dense null-space path is the serial
# reference, and tests/paths_agree compares the two).
#   bash scripts/compare-mpi-scenes.sh [N] [SCENE ...]
# Needs the built executable in build/. As root, Open MPI needs
# OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
n=${1:-2}
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=($(cd "$root/parameters" && ls *.prm | sed 's/\.prm$//'))
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
status=0
printf "%-22s %9s %9s %s\n" scene "serial s" "np $n s" "result files"
for scene in "${scenes[@]}"; do
  for run in serial parallel; do
    mkdir -p "$work/$scene/$run"
    cat > "$work/$scene/$run.prm" <<PRM
include $root/parameters/$scene.prm
subsection Equilibrium reduction
  set Path = condensed
end
subsection Output
  set Output directory = $work/$scene/$run
  set Print timing = false
end
PRM
    cmd=("$root/build/hrcontact" "$work/$scene/$run.prm")
    [ $run = parallel ] && cmd=(mpirun -np "$n" "${cmd[@]}")
    start=$(date +%s.%N)
    "${cmd[@]}" > "$work/$scene/$run.log" 2>&1
    echo $? > "$work/$scene/$run.rc"
    echo "$(date +%s.%N) - $start" | bc > "$work/$scene/$run.seconds"
  done
  verdict="same"
  if [ "$(cat "$work/$scene/serial.rc")" != "$(cat "$work/$scene/parallel.rc")" ]; then
    verdict="DIFFERENT exit codes"
  else
    python3 "$root/scripts/compare-results.py" "$work/$scene/serial" \
      "$work/$scene/parallel" > "$work/$scene/compare.txt" ||
      verdict="DIFFERENT: $(head -1 "$work/$scene/compare.txt")"
    [ -f "$work/$scene/serial/solution.vtu" ] && [ ! -f "$work/$scene/parallel/solution.pvtu" ] &&
      verdict="$verdict, no solution.pvtu"
  fi
  [ "${verdict%% *}" = same ] || status=1
  printf "%-22s %9.2f %9.2f %s (exit %s)\n" "$scene" "$(cat "$work/$scene/serial.seconds")" \
    "$(cat "$work/$scene/parallel.seconds")" "$verdict" "$(cat "$work/$scene/serial.rc")"
done
echo "runs kept in $work"
exit $status
