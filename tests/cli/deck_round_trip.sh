#!/usr/bin/env bash
# Round trip through the input deck (issue 37): `feticon export` of a problem, then
# `feticon run feticon.inp`, gives the answer of `feticon run` on the problem itself. Reference:
# the original run; the deck holds the same mesh, materials, supports, the tractions as their
# consistent nodal forces and plane strain as u_z = 0 on every node, so the contact pressures
# and the contact force agree to the QP tolerance (1e-6 of the peak; measured 3e-10 on Hertz).
# --overclosure 0: the model as it is (the shift is for CalculiX's penalty contact). With Coulomb
# friction the deck's *FRICTION alone gives the deck run its mu.
# Usage: deck_round_trip.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
check() { # name, then the problem arguments
  local name="$1"
  shift
  "$feticon" run "$@" -o "$work/$name-original" -q --set output.plots=false --set output.vtu=false
  "$feticon" export "$@" --format calculix --overclosure 0 -o "$work/$name-deck" > /dev/null
  "$feticon" run "$work/$name-deck/feticon.inp" -o "$work/$name-from-deck" -q --set output.plots=false \
    --set output.vtu=false --set subdomains="$(/usr/bin/python3 -c "import json; print(json.load(open('$work/$name-original/summary.json'))['subdomains'])")" 2> /dev/null
  /usr/bin/python3 - "$name" "$work/$name-original" "$work/$name-from-deck" <<'PY'
import csv, json, sys
name, a, b = sys.argv[1:]
sa, sb = (json.load(open(f"{d}/summary.json")) for d in (a, b))
pa, pb = ([float(r["pressure_multipliers_Pa"]) for r in csv.DictReader(open(f"{d}/contact_pressure.csv"))] for d in (a, b))
peak = max(pa)
worst = max(abs(x - y) for x, y in zip(pa, pb)) / peak
force = abs(sa["contact"]["total_normal_force"] / sb["contact"]["total_normal_force"] - 1)
print(f"{name}: {len(pa)} pressure samples, max difference {worst:.2g} of the peak, contact force {force:.2g}")
assert sa["converged"] and sb["converged"]
assert len(pa) == len(pb), "different slave surfaces"
assert worst < 1e-6 and force < 1e-6, f"{name}: the deck's answer differs"
PY
}
check hertz-large --set hertz.refinement=0.5
check hertz-small --set hertz.refinement=0.5 --set displacements=small
check hertz3d --set problem=hertz3d --set hertz3d.refinement=0.5 --set displacements=small
check punch "$src/examples/flat_punch/problem.yaml"
# Coulomb friction: the export writes *FRICTION, the deck run takes mu from it alone.
check punch-coulomb "$src/examples/flat_punch/problem.yaml" --set contact.friction.model=coulomb \
  --set contact.friction.coefficient=0.3
check sphere "$src/examples/sphere_on_block/problem.yaml" --set displacements=small

# A step whose loads take their values at once (`ramp: false`, *STEP, AMPLITUDE=STEP): a J2 bar
# pulled beyond yield in two increments, then unloaded to a third of the load at once in two
# more. Reference: the problem file's run, every increment's displacement to 1e-9 of the largest
# (measured 4e-15). Before, the deck ramped that step (its first increment 1 % of max u apart).
cat > "$work/at_once.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: bar, origin: [0, 0, 0], lengths: [1, 0.2, 0.2], cells: [4, 1, 1]}
bodies:
  bar: {young: 2e11, poisson: 0.3, plastic: [[2.5e8, 0], [1.25e9, 1]]}
supports:
  - {set: bar_xmin, x: 0}
  - {set: bar_ymin, y: 0}
  - {set: bar_zmin, z: 0}
steps:
  - loads: [{set: bar_xmax, traction: [3e8, 0, 0]}]
    increments: 2
  - loads: [{set: bar_xmax, traction: [1e8, 0, 0]}]
    increments: 2
    ramp: false
displacements: small
YAML
"$feticon" run "$work/at_once.yaml" -o "$work/at_once" -q --set output.plots=false
"$feticon" export "$work/at_once.yaml" --format calculix -o "$work/at_once-deck" > /dev/null
grep -q '^\*STEP, AMPLITUDE=STEP' "$work/at_once-deck/feticon.inp"
"$feticon" run "$work/at_once-deck/feticon.inp" -o "$work/at_once-from-deck" -q --set output.plots=false 2> /dev/null
/usr/bin/python3 - "$work/at_once" "$work/at_once-from-deck" "$src/tests/tools" <<'PY'
import sys
import numpy
sys.path.insert(0, sys.argv[3])
import read_vtu
for step in range(1, 5):
    a, b = (read_vtu.point_data(f"{d}/step_{step:03d}.vtu")["displacement"] for d in sys.argv[1:3])
    difference = numpy.abs(a - b).max() / numpy.abs(a).max()
    print(f"at once, increment {step}: max u {numpy.abs(a).max():.6e} m, the deck's {difference:.2g} apart")
    assert difference <= 1e-9, "the deck's step is not the problem file's"
PY

# A deck's *EQUATIONs are written back (before 2026-12-04 the export dropped them: fricloop's
# exported deck then ended 22 % of max |u| away from the deck's run). CalculiX's contact1 (two
# blocks whose faces *EQUATION keeps flat): the exported deck's run is the deck's, the same
# iterations, difference 0.
"$feticon" export "$src/tests/data/calculix/contact1.inp" --format calculix --overclosure 0 -o "$work/contact1-deck" > /dev/null
grep -q '^\*EQUATION$' "$work/contact1-deck/feticon.inp"
"$feticon" run "$src/tests/data/calculix/contact1.inp" -o "$work/contact1" -q --set output.plots=false 2> /dev/null
"$feticon" run "$work/contact1-deck/feticon.inp" -o "$work/contact1-from-deck" -q --set output.plots=false 2> /dev/null
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/contact1" "$work/contact1-from-deck"

# ADJUST is written back (the export dropped it: punch1's ADJUST=0.005 moves its slave nodes onto
# the punch first, without which CalculiX's answer is 4.1 times larger, docs/contact.md): the
# exported deck's run is punch1's, the same outer and QP iterations, displacements to 1e-9
# (measured 1.3e-12: the last digits of the written coordinates).
"$feticon" export "$src/tests/data/calculix/punch1.inp" --format calculix --overclosure 0 -o "$work/punch1-deck" > /dev/null
grep -q '^\*CONTACT PAIR, INTERACTION=SI_1, ADJUST=5.000000000000e-03, TYPE=SURFACE TO SURFACE$' "$work/punch1-deck/feticon.inp"
"$feticon" run "$src/tests/data/calculix/punch1.inp" -o "$work/punch1" -q --set output.plots=false 2> /dev/null
"$feticon" run "$work/punch1-deck/feticon.inp" -o "$work/punch1-from-deck" -q --set output.plots=false 2> /dev/null
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/punch1" "$work/punch1-from-deck"

# A node-to-surface LINEAR law keeps its tension sigma_inf (the export wrote 0, which the reader
# takes for CalculiX's default E / 70 000): contact6 with sigma_inf = 30 (its 3 is that default),
# contact.law=deck: the exported deck's run is the deck's, difference 0 (with 0 written: 3.2e-4).
sed 's/^1.E9,3.$/1.E9,30./' "$src/tests/data/calculix/contact6.inp" > "$work/contact6.inp"
"$feticon" export "$work/contact6.inp" --format calculix --overclosure 0 -o "$work/contact6-deck" > /dev/null
grep -A1 'PRESSURE-OVERCLOSURE=LINEAR' "$work/contact6-deck/feticon.inp" | grep -q '^1.000000000000e+09, 3.000000000000e+01$'
"$feticon" run "$work/contact6.inp" -o "$work/contact6" -q --set output.plots=false --set contact.law=deck 2> /dev/null
"$feticon" run "$work/contact6-deck/feticon.inp" -o "$work/contact6-from-deck" -q --set output.plots=false \
  --set contact.law=deck 2> /dev/null
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/contact6" "$work/contact6-from-deck"

# A pair that *CHANGE SURFACE BEHAVIOR turns from TIED to contact (CalculiX's changesurfbeh; a tie
# and a pair inside feticon, each out of force where the other is in) is one *CONTACT PAIR again,
# TIED in step 1 and LINEAR from step 2 (the export refused it before 2026-12-04): the exported
# deck's run is the deck's (difference 0; CalculiX 2.20 on the exported deck reproduces
# changesurfbeh.frd.ref to 8.5e-14).
"$feticon" export "$src/tests/data/calculix/changesurfbeh.inp" --format calculix --overclosure 0 \
  -o "$work/changesurfbeh-deck" > /dev/null
grep -q '^\*CHANGE SURFACE BEHAVIOR, INTERACTION=SI_1$' "$work/changesurfbeh-deck/feticon.inp"
! grep -q '^\*TIE' "$work/changesurfbeh-deck/feticon.inp"
for deck in "$src/tests/data/calculix/changesurfbeh.inp" "$work/changesurfbeh-deck/feticon.inp"; do
  "$feticon" run "$deck" -o "$work/csb-$(basename "$(dirname "$deck")")" -q --set output.plots=false \
    --set contact.law=deck --set subdomains=2 2> /dev/null
done
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/csb-calculix" "$work/csb-changesurfbeh-deck" --answer
