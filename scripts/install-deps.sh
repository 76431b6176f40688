#!/usr/bin/env bash
# Installs the Debian packages feticon builds and runs with, only those missing.
# Called by scripts/run-main.sh and scripts/run-tests.sh; safe to call repeatedly.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev          # dense/sparse containers, element algebra
  libsuitesparse-dev     # CHOLMOD factorizations
  libblas-dev            # cblas.h and libblas.so: dense symmetric products (la/symmetric_product.hpp)
  liblapack-dev          # dense Cholesky and inverse of the explicit operators (la/schur_complement.hpp)
  libopenblas0-pthread   # optimized BLAS behind CHOLMOD and those (else netlib reference BLAS)
  libmetis-dev           # graph partitioning
  openmpi-bin libopenmpi-dev  # MPI: subdomains distributed over ranks
  libyaml-cpp-dev        # problem files
  libcli11-dev           # command line
  nlohmann-json3-dev     # summary.json and the qp JSON report
  libgtest-dev           # tests
  gmsh libgmsh-dev       # mesh::read_gmsh (Gmsh C++ API) and examples/*/make_mesh.*
  python3-matplotlib python3-numpy  # plots (used through /usr/bin/python3)
  pybind11-dev python3-dev          # the Python module (python/)
  time                   # /usr/bin/time: the time and memory limits of the bad-input tests
  clang-format-14        # tests/cli/code_style.sh: the format of .clang-format
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "feticon: installing missing packages: ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
