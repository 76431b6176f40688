#!/usr/bin/env bash
# CalculiX's friction1 and friction2 (tests/data/calculix; C3D8 blocks pressed together, NLGEOM,
# Coulomb friction) with hard contact.
# friction1: matching meshes put every slave node on a side two master faces share; the closest
# face was chosen by round-off and changed at every outer iteration, which cycled between two
# iterates 6e-6 apart (relative) until the step failed. Now a tie goes to the smaller face id:
# its one load step converges in at most 6 outer iterations (measured 5), the same on 2 MPI
# ranks, and the contact force is the pressure's resultant 25 N within 1e-4 (measured 5.1e-5:
# the follower pressure acts on the deformed face, whose area the blocks' lateral strain changes).
# friction2: the pressed block is dragged along y by its slave nodes (held along y, free along x)
# to +1, -1, then +1 with mu lowered from 0.2 to 0.1; in that fourth step every friction row
# slides, which left the block's x motion undetermined and stopped the run. The sliding rows now
# decide the rigid motions the active rows leave free (dual/primal_recovery.hpp): all four steps
# run, the contact pressures within 1e-3 of CalculiX's friction2.dat.ref (measured 2.5e-4), the
# displacements within 1e-4 of max |u| from ccx 2.20's on the same deck (friction2.frd.ref,
# measured 3.2e-5), the contact force the 100 N load, the same on 2 MPI ranks.
# Usage: deck_friction_slides.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false --set output.vtu=false)
data="$src/tests/data/calculix"
source "$src/tests/tools/expect_agreement.sh"

contact_force() {
  /usr/bin/python3 - "$1/summary.json" "$2" "$3" "$4" <<'PY'
import json, sys
summary, load, bound, outer = json.load(open(sys.argv[1])), float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
assert summary["converged"], summary.get("reason")
force = summary["contact"]["total_normal_force"]
assert abs(force - load) <= bound * load, (force, load)
iterations = max(s["outer_iterations"] for s in summary["steps"])
assert iterations <= outer, iterations
print(f"{sys.argv[1]}: contact force {force:.10g} N against {load:g} N, at most {iterations} outer iterations a step")
PY
}

for deck in friction1 friction2; do
  "$feticon" run "$data/$deck.inp" -o "$work/$deck" "${quiet[@]}" 2> /dev/null
  mpirun --oversubscribe -np 2 "$feticon" run "$data/$deck.inp" -o "$work/${deck}_np2" "${quiet[@]}" 2> /dev/null
  /usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/$deck" "$work/${deck}_np2" | cut -c1-160
done
contact_force "$work/friction1" 25 1e-4 6
contact_force "$work/friction2" 100 1e-9 6
agreement "$data/friction2.inp" "$data/friction2.dat.ref" "$work/friction2" 1e-3
agreement "$data/friction2.inp" "$data/friction2.frd.ref" "$work/friction2" 1e-4
echo "deck_friction_slides: all checks passed"
