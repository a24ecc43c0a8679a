#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (run as root, or with sudo available):
#   bash scripts/quickstart.sh example   set up, build (Release), run parameters/hertz.prm
#                                        (Hertz contact: the closed-form comparison and
#                                        output/hertz/pressure.png)
#   bash scripts/quickstart.sh test      set up, build (Release), run the whole test suite
# Set-up installs only the Debian packages that are missing, so it is quick when
# everything is present. JOBS (default 2) sets the build parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."

what=${1:-}
case "$what" in
  example|test) ;;
  *) echo "usage: bash scripts/quickstart.sh example|test" >&2; exit 2 ;;
esac

packages=(cmake g++ make libdeal.ii-dev libmumps-dev numdiff perl libopenblas0-pthread gnuplot-nox universal-ctags)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "quickstart: installing missing Debian packages: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# deal.II's test runner and mpirun as root (CI and the development shells run as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# mpirun tests (.mpirun=2.output) may run beside another test on 2 cores.
export OMPI_MCA_rmaps_base_oversubscribe=1
# Dense LAPACK (the equilibrium reduction) uses both cores through OpenBLAS.
jobs=${JOBS:-2}

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

if [ "$what" = example ]; then
  # The main example: the paper's Hertz contact, compared with the closed
  # form in the log and drawn against it in output/hertz/pressure.png.
  ./build/hrcontact parameters/hertz.prm
  echo
  echo "quickstart: the contact pressure against Hertz: output/hertz/pressure.png"
  echo "quickstart: in ParaView open output/hertz/solution.vtu (stress, von_mises,"
  echo "            contact_pressure, contact_gap, contact_status)"
else
  # Build every test program first (two at a time), then run them.
  ctest --test-dir build -N > /dev/null
  targets=$(cd build && make help | sed -n 's/^\.\.\. \(tests\.[^ ]*\.release\)$/\1/p' | grep -v '\.test$' || true)
  [ -z "$targets" ] || cmake --build build -j"$jobs" --target $targets
  ctest --test-dir build -j"$jobs" --output-on-failure
fi
