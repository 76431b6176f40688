#!/usr/bin/env bash
# Linear equations (*EQUATION) under MPI: the verification test LinearEquationsMpi on 2 ranks
# (tests/verification/test_linear_equations.cpp; skipped there without an MPI launcher). Two
# bodies tied by a three-term equation and a two-term one, 4 subdomains, the equation rows
# shared by both ranks. Reference: the same solve on one rank in the same process (same
# iterations, displacements to 1e-12) and a direct solve with the equations eliminated (1e-8).
# Usage: mpi_equations.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
verification="$(dirname "$feticon")/tests/verification"
[[ -x $verification ]] || { echo "no $verification (FETICON_BUILD_TESTS off?)"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
export OPENBLAS_NUM_THREADS=1
# Sanitizer build: Open MPI's leaks cannot be told from feticon's (as in mpi_ranks.sh).
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
if ! timeout 300 mpirun --oversubscribe -np 2 "$verification" --gtest_filter='LinearEquationsMpi.*' --gtest_color=no > "$out" 2>&1; then
  cat "$out"
  exit 1
fi
# Both ranks ran the test (a skip would also report OK: look for the comparison line).
if [[ $(grep -c "^\[       OK \] LinearEquationsMpi.TwoRanksMatchOneRank" "$out") -ne 2 ||
      $(grep -c "of 2: |u_2 - u_1|/|u_1|" "$out") -ne 2 ]]; then
  cat "$out"
  exit 1
fi
grep "of 2: |u_2 - u_1|/|u_1|" "$out"
echo "mpi_equations: ok"
