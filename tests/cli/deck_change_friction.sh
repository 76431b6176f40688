#!/usr/bin/env bash
# *CHANGE FRICTION between steps (issue 65, item 6): tests/data/calculix/change_friction.inp, a
# block pressed by 100 MPa on 1 mm^2 onto a base (N = 100 N) and pushed along x by its top
# nodes, Coulomb mu = 0.3 in step 2 and mu = 0.1 in step 3 after *CHANGE FRICTION. Reference:
# sliding, the top nodes' reaction along x is mu N: 30 N and 10 N, to 1e-3 (measured 6e-5 and
# 1e-6; CalculiX 2.20 on the same deck with a 1e7 penalty and a 1e6 stick slope: 30.01 N, 9.991
# N), on 1 and 2 MPI ranks alike; without the change step 3 would stay at 30 N. (The 2-rank run
# hung before: a rank that owned no friction disc ran MPRGP while the other ran MPGP.)
# Usage: deck_change_friction.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
export OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
deck="$src/tests/data/calculix/change_friction.inp"
options=(--set output.plots=false --set output.vtu=false --set subdomains=4)
"$feticon" run "$deck" -o "$work/one" "${options[@]}" > "$work/one.log" 2>&1 || { cat "$work/one.log"; exit 1; }
runs=(one)
if command -v mpirun > /dev/null; then
  timeout 300 mpirun --oversubscribe -np 2 "$feticon" run "$deck" -o "$work/two" "${options[@]}" \
    > "$work/two.log" 2>&1 || { cat "$work/two.log"; exit 1; }
  runs+=(two)
fi
/usr/bin/python3 - "$src" "$work" "${runs[@]}" <<'PY'
import sys
src, work, *runs = sys.argv[1:]
sys.path.insert(0, src + "/tests/tools")
from calculix_dat import parse_dat
for run in runs:
    totals = [b for b in parse_dat(f"{work}/{run}/change_friction.dat")["blocks"] if b["kind"] == "total force"]
    assert len(totals) == 3, f"{run}: {len(totals)} total force blocks, expected one per step"
    fx = [b["rows"][0][0] for b in totals]
    print(f"{run} rank(s): reaction along x {fx[1]:.6g} N (mu 0.3), {fx[2]:.6g} N (mu 0.1 after *CHANGE FRICTION)")
    assert abs(fx[1] - 30) <= 0.03 and abs(fx[2] - 10) <= 0.01, "the reactions are not mu N"
PY
echo "deck_change_friction: ok"
