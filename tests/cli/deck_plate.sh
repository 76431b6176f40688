#!/usr/bin/env bash
# Zero-energy modes besides the rigid motions (decomposition::zero_energy_modes): CalculiX's
# plate (tests/data/calculix/plate.inp: two CPS8R cells, one a body, pressed together through a
# surface-to-surface pair, NLGEOM) has one hourglass mode in each cell's stiffness, which
# stopped its run at the factorization ("not positive definite"). Its kernel is now taken from
# the matrix. Reference: CalculiX's own .dat.ref (ccx 2.11): displacements within 1e-3 of max
# |u| with hard contact (measured 2.9e-4: the penetration of the deck's law K = 1e8 that hard
# contact leaves out) and 3e-4 with contact.law=deck (measured 1.1e-4); hard contact is
# beyond 1e-4, so the deck's law is what closes the gap. The same iterations and displacement
# on 2 MPI ranks, and the warning that names the modes; SET= on an output request warns.
# Usage: deck_plate.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false)
data="$src/tests/data/calculix"

source "$src/tests/tools/expect_agreement.sh"
check() { agreement "$data/plate.inp" "$data/plate.dat.ref" "$@"; }

"$feticon" run "$data/plate.inp" -o "$work/hard" "${quiet[@]}" 2> /dev/null
check "$work/hard" 1e-3
check "$work/hard" 1e-4 beyond
"$feticon" run "$data/plate.inp" -o "$work/law" "${quiet[@]}" --set contact.law=deck 2> /dev/null
check "$work/law" 3e-4
grep -q "1 zero-energy mode(s) besides its rigid-body motions" "$work/hard/summary.json" ||
  { echo "deck_plate.sh: the warning naming the zero-energy modes is missing" >&2; exit 1; }
mpirun --oversubscribe -np 2 "$feticon" run "$data/plate.inp" -o "$work/np2" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-10 "$work/hard" "$work/np2"
# SET= on an output request (thread.inp's *CONTACT PRINT) is no CalculiX parameter: a warning,
# as CalculiX gives, not a refusal.
sed 's/^\*NODE PRINT,NSET=Nall,/*NODE PRINT,NSET=Nall,SET=Nall,/' "$data/plate.inp" > "$work/plate_set.inp"
"$feticon" run "$work/plate_set.inp" -o "$work/set" "${quiet[@]}" 2> /dev/null
grep -q "SET= is no parameter of \*NODE PRINT" "$work/set/summary.json" ||
  { echo "deck_plate.sh: SET= on *NODE PRINT did not warn" >&2; exit 1; }
