#!/usr/bin/env bash
# Friction through the input and output files (issue 39, item 4): a problem file's contact pair
# `friction: {model: coulomb, coefficient: 0.3}`, `feticon export` writing it as *FRICTION, and
# `feticon run` of that deck and of CalculiX's friction2.inp blocks with their *FRICTION.
# References: the problem-file run itself (the deck's contact pressures agree with it to 1e-6 of
# the peak, the QP tolerance, as in deck_round_trip.sh); the upper block is held along x by
# friction alone, so the frictionless run of the same deck is refused (a free rigid-body
# motion) while the Coulomb run converges; summary.json of each run shows the law its pair ran.
# Usage: deck_friction.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
quiet=(-q --set output.plots=false --set output.vtu=false)

# Plane strain: a 1 x 0.25 block pressed (p = 1e8 Pa) on a clamped 1 x 1 block and sheared by
# q = 0.2 p < mu p along x, non-matching meshes (5 against 4 cells).
cat > "$work/blocks.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: lower, origin: [0, 0, 0], lengths: [1, 1, 0.1], cells: [4, 4, 1]}
    - {name: upper, origin: [0, 1, 0], lengths: [1, 0.25, 0.1], cells: [5, 2, 1]}
bodies:
  lower: {young: 2e11, poisson: 0.3}
  upper: {young: 2e11, poisson: 0.3}
plane_strain: true
supports:
  - {set: lower_ymin, x: 0, y: 0}
loads:
  - {set: upper_ymax, traction: [2e7, -1e8, 0]}
contact:
  - {slave: upper_ymin, master: lower_ymax, friction: {model: coulomb, coefficient: 0.3}}
subdomains: 4
displacements: small
YAML

expect_coulomb() { # RESULTS_DIR
  /usr/bin/python3 -c "import json, sys
f = json.load(open('$1/summary.json'))['contact']['pairs'][0]['friction']
sys.exit(0 if f['model'] == 'coulomb' and f['coefficient'] == 0.3 else 1)" ||
    { echo "FAIL $1: summary.json's pair does not say coulomb, 0.3"; grep -A4 friction "$1/summary.json"; exit 1; }
}
converged() {
  /usr/bin/python3 -c "import json, sys; sys.exit(0 if json.load(open('$1/summary.json'))['converged'] else 1)" ||
    { echo "FAIL $1: not converged"; exit 1; }
}

"$feticon" run "$work/blocks.yaml" -o "$work/yaml" "${quiet[@]}"
converged "$work/yaml"
expect_coulomb "$work/yaml"

# The export writes *FRICTION (mu and a stick slope) under the interaction.
"$feticon" export "$work/blocks.yaml" --format calculix --overclosure 0 -o "$work/deck" > /dev/null
grep -A1 '^\*FRICTION' "$work/deck/feticon.inp" | tail -n 1 | grep -q '^3.000000000000e-01, [0-9.e+]*$' ||
  { echo "FAIL: the exported deck has no *FRICTION line 'mu, stick slope'"; exit 1; }

# The deck reads back as Coulomb's law with mu = 0.3 and gives the problem file's answer.
"$feticon" run "$work/deck/feticon.inp" -o "$work/from-deck" "${quiet[@]}" --set subdomains=4 2> /dev/null
converged "$work/from-deck"
expect_coulomb "$work/from-deck"
/usr/bin/python3 - "$work/yaml" "$work/from-deck" <<'PY'
import csv, sys
a, b = sys.argv[1:]
pa, pb = ([float(r["pressure_multipliers_Pa"]) for r in csv.DictReader(open(f"{d}/contact_pressure.csv"))] for d in (a, b))
assert len(pa) == len(pb) and pa, "different slave surfaces"
worst = max(abs(x - y) for x, y in zip(pa, pb)) / max(pa)
print(f"blocks with Coulomb friction: {len(pa)} slave nodes, deck against problem file {worst:.2g} of the peak")
assert worst < 1e-6, "the deck's answer differs"
PY

# Without friction nothing holds the upper block along x: the run is refused.
if "$feticon" run "$work/deck/feticon.inp" -o "$work/frictionless" "${quiet[@]}" --set subdomains=4 \
  --set contact.friction.model=none 2> "$work/err"; then
  echo "FAIL: the frictionless run of the sheared blocks converged"; exit 1
fi
grep -q "free to move\|rigid-body motion" "$work/err" || { echo "FAIL: frictionless run:"; cat "$work/err"; exit 1; }

# Tresca has no CalculiX keyword: export refuses it in one line.
if "$feticon" export "$work/blocks.yaml" --format calculix -o "$work/tresca" --set contact.friction.model=tresca \
  --set contact.friction.slip_bound=1e7 > /dev/null 2> "$work/err"; then
  echo "FAIL: Tresca friction was exported"; exit 1
fi
[[ $(wc -l < "$work/err") -eq 1 ]] && grep -q "Tresca friction (contact pair 0) has no CalculiX" "$work/err" ||
  { echo "FAIL: Tresca export:"; cat "$work/err"; exit 1; }

# Two blocks of CalculiX's friction2.inp (tests/data/calculix_results/two_blocks_dat.inp, its
# friction removed there) with *FRICTION after the penalty law again: two NLGEOM steps.
sed '/^\*SURFACE BEHAVIOR/{n;s/$/\n*FRICTION\n0.3, 1e6/}' "$src/tests/data/calculix_results/two_blocks_dat.inp" \
  > "$work/blocks.inp"
"$feticon" run "$work/blocks.inp" -o "$work/blocks" "${quiet[@]}" 2> /dev/null
converged "$work/blocks"
expect_coulomb "$work/blocks"
grep -q "stick slope 1e6 of \*FRICTION" "$work/blocks/summary.json" || { echo "FAIL: no stick slope warning"; exit 1; }
grep -q "written as 0" "$work/blocks/summary.json" || { echo "FAIL: no warning on the .frd/.dat shear"; exit 1; }
echo "deck_friction: all checks passed"
