#!/usr/bin/env bash
# Installs the Debian 12 packages rotlie's build uses (idempotent: installed packages are skipped).
#   scripts/install-deps.sh                 everything (symbolic side, CLI, reports, tests, benchmarks)
#   scripts/install-deps.sh --numeric-only  what the numeric-only preset needs: no GiNaC, no CLN
#   scripts/install-deps.sh --fuzz          everything, plus clang and libFuzzer for the fuzz preset
set -euo pipefail

numeric=(
  g++ cmake make
  libboost-dev libboost-test-dev # Boost.Math, Multiprecision float128 (libquadmath comes with g++), Boost.Test
  libhwy-dev                     # Highway: the exact free flow of many bodies vectorised, AVX2/AVX-512 chosen at run time
)
symbolic=(
  pkg-config libginac-dev libcln-dev # lie/, bch/, solver/
  libeigen3-dev                  # solver/ (eigenvalues)
  libgsl-dev                     # bench/ only: GSL against Boost.Math for the exact flow (the libraries do not use it)
  libcli11-dev nlohmann-json3-dev # apps/rotlie, reports/
  liblzma-dev xz-utils           # the full-resolution maps shipped xz-compressed (data/)
  libopenmpi-dev openmpi-bin     # rotlie map over MPI ranks (optional: without them it runs as one process)
  lammps                         # liquid water side by side with LAMMPS (optional: the comparison is skipped without lmp)
  libbenchmark-dev               # bench/
  gnuplot-nox                    # report figures
)
python=(                         # python/: the rotlie Python package (Debian's /usr/bin/python3, 3.11)
  python3-dev pybind11-dev python3-pybind11 # the extension (find_package(Python), find_package(pybind11 CONFIG))
  python3-numpy                  # arrays in and out
  python3-setuptools python3-venv python3-wheel # pip install . in a venv, offline (--no-build-isolation)
  python3-pytest                 # tests/python
  python3-matplotlib             # examples/python (Agg backend)
  python3-sympy                  # optional: remainder terms as SymPy expressions
)

# lammps/: the fix styles rigid/sier2/small, rigid/sier4/small and lmp_rotlie (optional: skipped without
# them); the headers liblammps-dev lacks come from Debian's source package (lammps/fetch-headers.sh)
# python3-lammps: LAMMPS's Python module, for the loader's route from Python (lammps/tests/loader_test.cpp)
lammps=(liblammps-dev lammps-examples dpkg-dev python3-lammps)  # lmp itself is in symbolic

case "${1:-}" in
  "") packages=("${numeric[@]}" "${symbolic[@]}" "${python[@]}" "${lammps[@]}") ;;
  --numeric-only) packages=("${numeric[@]}") ;;
  --fuzz) packages=("${numeric[@]}" "${symbolic[@]}" "${python[@]}" "${lammps[@]}" clang libclang-rt-14-dev) ;;  # fuzz/: libFuzzer
  *) echo "install-deps: error: unknown option '$1' (--numeric-only or --fuzz)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
else
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "install-deps: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# lammps/: LAMMPS's own headers of the installed version (quick when already there)
if [ "${1:-}" != "--numeric-only" ]; then
  "$(dirname "$0")/../lammps/fetch-headers.sh"
fi
