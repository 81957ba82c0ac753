#!/usr/bin/env bash
# Installs every dependency of Signorini from Debian's package archive.
# Idempotent: when everything is present it returns at once without touching apt.
#
#     scripts/install-deps.sh [--bench]
#
# --bench also installs what optional benchmark programs compare against: IPOPT with MUMPS
# (bench/ipopt.py).
set -euo pipefail

packages=(
  build-essential cmake make pkg-config
  trilinos-all-dev            # Teuchos, Tpetra, Belos, MueLu, Ifpack2, Amesos2, Zoltan2, ...
  libptscotch-dev libscotch-dev  # named by Debian's Trilinos CMake config
  libopenmpi-dev openmpi-bin
  libmetis-dev
  libsuitesparse-dev          # CHOLMOD: the coarsest multigrid level's Cholesky factorization
  libopenblas0-serial         # optimised BLAS for CHOLMOD (serial: MPI runs one rank per core)
  libgmsh-dev gmsh            # Gmsh SDK (mesh reading) and CLI (test meshes)
  libmuparser-dev             # user expressions for loads, gaps, displacements
  libboost-dev                # Boost.Geometry's R-tree: the master facets near each slave facet
  libcgal-dev                 # CGAL's Delaunay triangulations: the coarse grids of a mesh read as is
  libgtest-dev                # unit tests
  clang libclang-rt-14-dev    # the sanitizer build and the libFuzzer targets (make sanitize)
  valgrind                    # the memcheck run in the test suite
  doxygen                     # API reference (make doc)
  universal-ctags             # the function length lint (tests/lint/function_length.py)
  python3 python3-numpy python3-matplotlib python3-meshio  # scripts and output checks
  python3-dev pybind11-dev python3-scipy  # the Python module (python/) and its test
)
for arg in "$@"; do
  case "$arg" in
    --bench) packages+=(coinor-libipopt-dev) ;;  # IPOPT and MUMPS (bench/ipopt.py)
    *) echo "install-deps: unknown option $arg (known: --bench)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
