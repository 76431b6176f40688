#!/usr/bin/env bash
# Pretension sections (*PRE-TENSION SECTION, fem/coupling.hpp): the section's nodes doubled and
# the two sides joined by rows, the gap along the normal the reference node's DOF 1.
# References:
#  - A 1 x 1 x 10 m C3D20 bar (E = 1e9 Pa, nu = 0; tests/tools/pretension_bar_deck.py), held in
#    x at both ends, cut at mid-length: uniform tension, so a force F = 1e6 N on DOF 1 opens the
#    gap q = F L / (E A) = 0.01 m (1e-6; the right end's reaction is F), and a held gap q = 0.01 m
#    needs the force E A q / L = 1e6 N (1e-6). With NLGEOM and the normal given, CalculiX 2.20's
#    gap on the same deck, 9.985040e-3 m, to its printed digits. The same answer on 2 MPI ranks.
#  - CalculiX's pret2 (two CAX8 cells, a gap of 0.01 held; tests/data/calculix/pret2.inp with
#    *NODE FILE added): ccx 2.20's displacements of every node (pret2.frd.ref) within 2e-4 of max
#    |u| (measured 5e-5: CalculiX solves CAX8 as expanded C3D20R cells), the new nodes numbered
#    as CalculiX numbers them.
#  - feticon export of the bar (normal given) and of pret2, run again: their decks' answers
#    (difference 0); a load on a doubled node (the bar's weight) is refused in one line.
#  - Bad input, one line each: ELEMENT= (a beam pretension), a node surface, no NODE=, a
#    reference node that an element uses, a NODE= beyond 64-bit integers (a fuzz mutant's
#    "stoll"), a zero normal.
# Usage: pretension.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false)
tools="$src/tests/tools"

for kind in force gap normal; do
  /usr/bin/python3 "$tools/pretension_bar_deck.py" "$work/$kind.inp" "$kind"
  "$feticon" run "$work/$kind.inp" -o "$work/$kind" "${quiet[@]}" 2> /dev/null
done
mpirun --oversubscribe -np 2 "$feticon" run "$work/force.inp" -o "$work/np2" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 "$tools/compare_runs.py" 1e-10 "$work/force" "$work/np2"
/usr/bin/python3 - "$work" "$tools" <<'PY'
import json, sys
work, tools = sys.argv[1], sys.argv[2]
sys.path.insert(0, tools)
from calculix_dat import parse_dat

def printed(kind):
    """The reference node's U1 and RF1 and the right end's total RF1 in the run's .dat."""
    blocks = parse_dat(f"{work}/{kind}/{kind}.dat")["blocks"]
    u = next(b for b in blocks if b["kind"] == "displacements")["rows"][0][1]
    rf = next(b for b in blocks if b["kind"] == "forces")["rows"][0][1]
    total = next(b for b in blocks if b["kind"] == "total force")["rows"][0][0]
    return u, rf, total

def close(what, value, reference, rtol):
    assert abs(value - reference) <= rtol * abs(reference), f"{what}: {value} against {reference}"
    print(f"{what}: {value:.7g} (reference {reference:.7g}, within {rtol:g})")

u, rf, total = printed("force")
close("force: gap F L / (E A)", u, 0.01, 1e-6)
close("force: right end's reaction", total, 1e6, 1e-6)
s = json.load(open(f"{work}/force/summary.json"))
coupling = s["couplings"][0]
assert coupling["kind"] == "pretension", coupling
close("force: summary.json section force", coupling["force"][0], 1e6, 1e-6)
u, rf, total = printed("gap")
close("gap: held", u, 0.01, 1e-12)
close("gap: section force E A q / L", rf, 1e6, 1e-6)
u, rf, total = printed("normal")
close("NLGEOM: gap against CalculiX 2.20", u, 9.985040e-3, 6e-7)
PY
"$feticon" run "$src/tests/data/calculix/pret2.inp" -o "$work/pret2" "${quiet[@]}" 2> /dev/null
source "$tools/expect_agreement.sh"
agreement "$src/tests/data/calculix/pret2.inp" "$src/tests/data/calculix/pret2.frd.ref" "$work/pret2" 2e-4 within 16

# feticon export writes a pretension section as its faces (of the cells that took the doubled
# nodes) and *PRE-TENSION SECTION, the deck's nodes without the doubled ones (CalculiX doubles them
# again): the exported bar (3D, its normal given) and pret2 (CAX8) run to their decks' answers.
for deck in "$work/normal.inp" "$src/tests/data/calculix/pret2.inp"; do
  name=$(basename "$deck" .inp)
  "$feticon" export "$deck" --format calculix -o "$work/$name-deck" > /dev/null
  grep -q '^\*PRE-TENSION SECTION, SURFACE=PRETENSION_1, NODE=' "$work/$name-deck/feticon.inp"
  "$feticon" run "$work/$name-deck/feticon.inp" -o "$work/$name-exported" "${quiet[@]}" 2> /dev/null
  /usr/bin/python3 "$tools/compare_runs.py" 1e-9 "$work/$name" "$work/$name-exported" --answer
done
# ... and refuses a load on a doubled node (the bar's weight: GRAV's nodal forces), which a deck
# cannot name.
sed -e 's/^\*ELASTIC$/*DENSITY\n7800.\n&/' -e 's/^\*CLOAD$/*DLOAD\nBAR, GRAV, 9.81, 0., 0., -1.\n&/' \
  "$work/force.inp" > "$work/weight.inp"
source "$tools/expect_deck_error.sh"
expect_export_error "$work/weight.inp" weight "calculix export: a load names node [0-9]*, which a pretension section doubled"

# Bad input: one line naming what is wrong, exit 1.
bad() {
  local name=$1 pattern=$2
  shift 2
  sed "$@" "$work/force.inp" > "$work/$name.inp"
  expect_error "$name" "$pattern"
}
bad beam "ELEMENT= (a pretension through a beam element) is not implemented" \
  -e 's/^\*PRE-TENSION SECTION, SURFACE=CUT, NODE=10000/*PRE-TENSION SECTION, ELEMENT=1, NODE=10000/'
bad node_surface "is a node surface; a pretension section is element faces" \
  -e 's/^\*SURFACE, NAME=CUT, TYPE=ELEMENT/*SURFACE, NAME=CUT, TYPE=NODE/' -e 's/^5, S4$/1/'
bad no_node "needs NODE=" -e 's/^\*PRE-TENSION SECTION, SURFACE=CUT, NODE=10000/*PRE-TENSION SECTION, SURFACE=CUT/'
bad element_node "NODE 1 belongs to an element" -e 's/NODE=10000/NODE=1/'
bad huge_node "NODE=9223372036854775808 is not a node number" -e 's/NODE=10000/NODE=9223372036854775808/'
bad zero_normal "the normal of a pretension section must be a nonzero vector" \
  -e 's/^\*PRE-TENSION SECTION, SURFACE=CUT, NODE=10000/&\n0., 0., 0./'
