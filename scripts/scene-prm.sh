# Sourced by the benchmark scripts (needs $root): Open MPI's settings for
# root and oversubscription, one OpenMP thread for timing, a work directory
# $work removed at exit, and write_scene_prm: the .prm of one run, a scene
# of parameters/ at a refinement, its results into a directory, with the
# given Output entries and $EXTRA_PRM appended; median (of the numbers on
# stdin, one a line) and get KEY DIR (a value of DIR/summary.txt).
#   write_scene_prm FILE SCENE REFINEMENTS OUTPUT_DIR ["set Key = value" ...]
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
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
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
get() { sed -n "s/^$1 = //p" "$2/summary.txt"; }
