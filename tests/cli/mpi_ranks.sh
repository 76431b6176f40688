#!/usr/bin/env bash
# Distributed FETI (issue 6): the Hertz problem with large displacements (two load steps, 8
# subdomains) on 1, 2 and 4 MPI ranks (oversubscribed on 2 cores). Reference: the 1-rank
# run; the 2- and 4-rank runs must take the same iterations and give displacements equal to
# 1e-10 relative (tests/tools/compare_runs.py). Also: one VTU piece per rank joined by a
# .pvtu that lists them all and covers every cell once (read with the independent reader
# tests/tools/read_vtu.py), and an error on one rank ends all ranks with its message. The
# same 1- against 2-rank comparison with partitioner=rcb, and on hertz3d with single-precision
# factors.
# Usage: mpi_ranks.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
# One BLAS thread on every rank count (the ranks set it themselves when there are several).
export OPENBLAS_NUM_THREADS=1
# Sanitizer build: Open MPI's components leak what they allocate and are unloaded before the
# leak check, so the leaks cannot be told from feticon's; the one-rank tests check leaks.
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
# run N [NAME SETTINGS...]: N ranks, results in $work/npN (or $work/NAME)
run() {
  local n=$1 name=${2:-np$1}
  shift $(($# < 2 ? $# : 2))
  mpirun --oversubscribe -np "$n" "$feticon" run -q --output "$work/$name" --set subdomains=8 "$@"
}

for n in 1 2 4; do run "$n"; done
for n in 2 4; do /usr/bin/python3 "$source_dir/tests/tools/compare_runs.py" 1e-10 "$work/np1" "$work/np$n"; done
# Coordinate bisection: every rank computes the same partition.
for n in 1 2; do run "$n" "rcb$n" --set partitioner=rcb; done
/usr/bin/python3 "$source_dir/tests/tools/compare_runs.py" 1e-10 "$work/rcb1" "$work/rcb2"
# Single-precision factors (3D default): every rank rounds its subdomains' factors alike.
for n in 1 2; do
  run "$n" "single$n" --set problem=hertz3d --set hertz3d.refinement=0.8 \
    --set dual.factor_precision=single --set dual.operator=implicit --set output.vtu=false --set output.plots=false
done
/usr/bin/python3 "$source_dir/tests/tools/compare_runs.py" 1e-10 "$work/single1" "$work/single2"

# Pieces: step_001.pvtu (the default's one load step) names 4 pieces; together they hold every cell of the 1-rank VTU once.
[[ $(grep -c "<Piece Source=" "$work/np4/step_001.pvtu") -eq 4 ]]
grep -q 'file="step_001.pvtu"' "$work/np4/solution.pvd"
/usr/bin/python3 - "$source_dir/tests/tools" "$work" <<'PY'
import json, subprocess, sys
tools, work = sys.argv[1:]
def cells(path):
    out = subprocess.run(["/usr/bin/python3", tools + "/read_vtu.py", path], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)["NumberOfCells"]
whole = cells(work + "/np1/step_001.vtu")
pieces = sum(cells(f"{work}/np4/step_001_rank{r:03d}.vtu") for r in range(4))
assert pieces == whole, (pieces, whole)
PY

# An error on rank 1 only (its piece of step 1 cannot be written: a folder is in the way)
# ends every rank, with the message and the rank, instead of hanging.
mkdir -p "$work/fail/step_001_rank001.vtu"
if timeout 120 mpirun --oversubscribe -np 2 "$feticon" run -q --output "$work/fail" --set subdomains=8 \
    2> "$work/err"; then
  echo "a failed write on rank 1 did not fail the run"; exit 1
fi
grep -q "feticon: error (rank 1):" "$work/err" || { cat "$work/err"; exit 1; }

# More ranks than subdomains (Hertz: one per body at least, so 2) is a clear error.
if mpirun --oversubscribe -np 3 "$feticon" run -q --output "$work/few" --set subdomains=1 \
    --set hertz.refinement=0.5 2> "$work/err2"; then
  echo "3 ranks on 2 subdomains succeeded"; exit 1
fi
grep -q "subdomains: use at least one subdomain per rank" "$work/err2" || { cat "$work/err2"; exit 1; }
echo "mpi_ranks: ok"
