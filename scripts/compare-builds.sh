#!/bin/bash
# Run every scene of parameters/ with two builds of hrcontact and require
# identical result files, to the last printed digit: a restructuring must not
# change a number. Timings (wall_time, *seconds*, peak_memory_MB, the seconds
# column of history.csv, timed log lines) and the date in the .vtu header are
# the only lines allowed to differ.
#   bash scripts/compare-builds.sh OLD_EXECUTABLE [NEW_EXECUTABLE] [SCENE ...]
# NEW_EXECUTABLE defaults to build/hrcontact. Build the old one from another
# checkout, e.g. `git worktree add ../old main && cmake -S ../old -B
# ../old/build && cmake --build ../old/build -j2`.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
old=${1:?usage: compare-builds.sh OLD_EXECUTABLE [NEW_EXECUTABLE] [SCENE ...]}
new=${2:-$root/build/hrcontact}
# The runs change directory: the executables by absolute path.
absolute() { case "$1" in /*) echo "$1" ;; */*) echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" ;; *) echo "$1" ;; esac; }
old=$(absolute "$old")
new=$(absolute "$new")
shift 2 2>/dev/null || shift
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=($(cd "$root/parameters" && ls *.prm | sed 's/\.prm$//'))
work=$(mktemp -d)
status=0
# Drop what is allowed to differ: timing keys, and the last (seconds) column
# of history.csv.
normalise() {
  local f=$1
  case "$(basename "$f")" in
    summary.txt) grep -v -E '^(wall_time|peak_memory_MB|[a-z_]*seconds[a-z_]*) =' "$f" ;;
    history.csv) sed 's/,[^,]*$//' "$f" ;;
    *.vtu | *.pvtu) grep -v '^#This file was generated' "$f" ;;
    *) cat "$f" ;;
  esac
}
printf "%-22s %s\n" scene verdict
for scene in "${scenes[@]}"; do
  for run in old new; do
    # The same file name and a relative output directory, so that the logs
    # of the two runs can be compared line by line.
    mkdir -p "$work/$scene/$run"
    cat > "$work/$scene/$run/$scene.prm" <<PRM
include $root/parameters/$scene.prm
subsection Output
  set Output directory = results
  set Print timing = false
end
PRM
    exe=$old
    [ $run = new ] && exe=$new
    (cd "$work/$scene/$run" && "$exe" "$scene.prm" > ../$run.log 2>&1)
    echo $? > "$work/$scene/$run.rc"
  done
  verdict="same"
  if [ "$(cat "$work/$scene/old.rc")" != "$(cat "$work/$scene/new.rc")" ]; then
    verdict="DIFFERENT exit codes"
  else
    a=$(cd "$work/$scene/old/results" && find . -type f | sort)
    b=$(cd "$work/$scene/new/results" && find . -type f | sort)
    if [ "$a" != "$b" ]; then
      verdict="DIFFERENT files"
    else
      for f in $a; do
        if ! cmp -s <(normalise "$work/$scene/old/results/$f") \
          <(normalise "$work/$scene/new/results/$f"); then
          verdict="DIFFERENT: $f"
          break
        fi
      done
    fi
    # The printed log too, but for the timing lines.
    if [ "$verdict" = same ] && ! cmp -s \
      <(grep -v -E 'seconds| s$| s\)|time' "$work/$scene/old.log") \
      <(grep -v -E 'seconds| s$| s\)|time' "$work/$scene/new.log"); then
      verdict="same files, log differs"
    fi
  fi
  [ "$verdict" = same ] || status=1
  printf "%-22s %s (exit %s)\n" "$scene" "$verdict" "$(cat "$work/$scene/old.rc")"
done
echo "runs kept in $work"
exit $status
