# Sourced by the benchmark scripts (needs $root): write the .prm of one run,
# a scene of parameters/ at a refinement, its results into a directory, with
# the given Output entries and $EXTRA_PRM appended.
#   write_scene_prm FILE SCENE REFINEMENTS OUTPUT_DIR ["set Key = value" ...]
write_scene_prm() {
  local file=$1 scene=$2 r=$3 out=$4
  shift 4
  {
    echo "include $root/parameters/$scene.prm"
    echo "subsection Geometry"; echo "  set Global refinements = $r"; echo "end"
    echo "subsection Output"; echo "  set Output directory = $out"; echo "  set Write solution = false"
    for line in "$@"; do echo "  $line"; done
    echo "end"
    echo "${EXTRA_PRM:-}"
  } > "$file"
}
