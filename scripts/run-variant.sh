# Sourced by the benchmark scripts: run a scene with overrides, timed.
#   run_variant SCENE.prm "parameter file lines" WORKDIR
# writes WORKDIR/run.prm (include SCENE + the given lines + quiet
# output into WORKDIR/out), runs it, and sets: summary (path of summary.txt),
# seconds (wall time), rss_mib (peak resident memory). get KEY reads the
# summary, calc EXPR evaluates arithmetic (scientific notation allowed).
run_variant() {
  local scene=$1 overrides=$2 work=$3
  cat > "$work/run.prm" <<PRM
include $PWD/$scene
$overrides
subsection Output
  set Output directory = $work/out
  set Write solution   = false
  set Print timing     = false
end
PRM
  local start end
  start=$(date +%s.%N)
  /usr/bin/time -f "%M" -o "$work/rss" ./build/hrcontact "$work/run.prm" > "$work/log"
  end=$(date +%s.%N)
  summary="$work/out/summary.txt"
  seconds=$(calc "$end - $start")
  rss_mib=$(( $(cat "$work/rss") / 1024 ))
}
get() { sed -n "s/^$1 = //p" "$summary"; }
calc() { awk "BEGIN { print $1 }"; }
