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
