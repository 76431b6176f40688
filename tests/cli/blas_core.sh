#!/usr/bin/env bash
# CLI test of the BLAS kernels feticon runs with (la/blas_core.hpp): OpenBLAS 0.3.21 falls back
# to its Prescott (SSE3) kernels on CPUs it does not know; feticon then runs itself again with
# OPENBLAS_CORETYPE set. Reference: the CPU's own flags in /proc/cpuinfo (AVX2 and FMA: the
# kernels must not be Prescott's) and the user's OPENBLAS_CORETYPE, which must pass untouched.
# Skipped (77) where the BLAS is not OpenBLAS or the CPU has no AVX2.
# Usage: blas_core.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run() { "$feticon" run "$@" -q --overwrite --set hertz.refinement=0.5 --set output.plots=false --set output.vtu=false; }
field() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1/summary.json" "$2"; }
fail() { echo "blas_core: $*"; exit 1; }

flags=$(grep -m1 '^flags' /proc/cpuinfo || true)
[[ " $flags " == *" avx2 "* && " $flags " == *" fma "* ]] || { echo "blas_core: no AVX2/FMA, skipped"; exit 77; }

# 1. As a user starts it: OpenBLAS's own choice, or the better one feticon sets.
env -u OPENBLAS_CORETYPE "$feticon" run -q --overwrite --output "$work/own" --set hertz.refinement=0.5 \
  --set output.plots=false --set output.vtu=false
core=$(field "$work/own" blas_core)
[[ -n "$core" ]] || { echo "blas_core: the BLAS is not OpenBLAS, skipped"; exit 77; }
[[ "$core" != Prescott ]] || fail "ran with OpenBLAS's Prescott kernels on a CPU with AVX2"
[[ $(field "$work/own" converged) == True ]] || fail "the run did not converge"

# 2. The user's OPENBLAS_CORETYPE wins, and the same arguments reach the run.
OPENBLAS_CORETYPE=Haswell run --output "$work/given"
[[ $(field "$work/given" blas_core) == Haswell ]] || fail "OPENBLAS_CORETYPE=Haswell ran $(field "$work/given" blas_core)"
[[ $(field "$work/given" degrees_of_freedom) == $(field "$work/own" degrees_of_freedom) ]] || fail "the arguments changed"
echo "blas_core: $core without OPENBLAS_CORETYPE, Haswell with it"
