#!/usr/bin/env bash
# Automatic increments (issue 65, item 3): a step's initial, minimum and maximum increment.
# 1. CalculiX's cubespring deck (NLGEOM, frictionless) with *STATIC 0.1, 1.: the load factors
#    follow the rule of load_history.hpp (restated in tests/tools/increment_rule.py from the
#    run's own outer iterations) and take fewer than 10 increments; *STATIC, DIRECT takes 10
#    equal ones. Reference: the two end at the same contact force (frictionless contact of
#    elastic bodies does not depend on the path; asserted 1e-6, newton.tolerance, to which each
#    increment's end is converged; measured 3e-15).
# 2. A problem file (large displacements) with `increment: {initial, maximum}` against the same
#    step in `increments: 5`: the rule, and the same contact force (1e-6; measured 1.1e-7).
# 3. Bad input: minimum above the initial increment, in a deck and in a problem file; *STEP, INC=
#    (CalculiX's maximum count of increments, default 100) below the increments the step takes,
#    and INC=0: one line each.
# 4. Friction: the increments grow, but not where slave nodes are tied by equations (below).
# Usage: automatic_increments.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export PYTHONPATH="$src/tests/tools"
settings=(--set output.plots=false --set output.vtu=false)

sed '/^\*STATIC$/{n;s/.*/0.1, 1./}' "$src/tests/data/calculix/cubespring.inp" >"$work/automatic.inp"
sed 's/^\*STATIC$/*STATIC, DIRECT/' "$work/automatic.inp" >"$work/direct.inp"
for deck in automatic direct; do
  "$feticon" run -q "$work/$deck.inp" --output "$work/$deck" "${settings[@]}" 2>/dev/null
done
/usr/bin/python3 - "$work/automatic/summary.json" "$work/direct/summary.json" <<'PY'
import json
import sys

import increment_rule

automatic, direct = (json.load(open(p)) for p in sys.argv[1:])
assert automatic["converged"] and direct["converged"]
# CalculiX's defaults: minimum min(initial, 1e-5 of the step time), maximum the step time.
taken = increment_rule.check(automatic["steps"], 0.0, 0.1, 1e-5, 1.0)
assert len(taken) < 10, taken
assert [round(s["load_factor"], 12) for s in direct["steps"]] == [round(0.1 * k, 12) for k in range(1, 11)]
a, b = automatic["contact"]["total_normal_force"], direct["contact"]["total_normal_force"]
assert abs(a - b) <= 1e-6 * abs(b), (a, b)
print(f"deck: {len(taken)} automatic increments {[round(t, 4) for t in taken]}, force {a:.12g} N; DIRECT 10, {b:.12g} N")
PY

cat >"$work/pressed.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: base,  origin: [0, 0, 0],   lengths: [1, 1, 0.4], cells: [3, 3, 2]}
    - {name: punch, origin: [0.3, 0.3, 0.4], lengths: [0.4, 0.4, 0.4], cells: [2, 2, 2]}
bodies:
  base:  {young: 1e8, poisson: 0.3}
  punch: {young: 1e8, poisson: 0.3}
supports:
  - {set: base_zmin, x: 0, y: 0, z: 0}
  - {set: punch_zmax, x: 0, y: 0, z: -0.005}
contact:
  - {slave: punch_zmin, master: base_zmax}
displacements: large
steps:
  - increment: {initial: 0.2, maximum: 0.6}
YAML
sed 's/increment: {initial: 0.2, maximum: 0.6}/increments: 5/' "$work/pressed.yaml" >"$work/fixed.yaml"
for model in pressed fixed; do
  "$feticon" run -q "$work/$model.yaml" --output "$work/$model" "${settings[@]}"
done
/usr/bin/python3 - "$work/pressed/summary.json" "$work/fixed/summary.json" <<'PY'
import json
import sys

import increment_rule

automatic, fixed = (json.load(open(p)) for p in sys.argv[1:])
taken = increment_rule.check(automatic["steps"], 0.0, 0.2, 0.2e-5, 0.6)
assert len(fixed["steps"]) == 5
a, b = automatic["contact"]["total_normal_force"], fixed["contact"]["total_normal_force"]
assert abs(a - b) <= 1e-6 * abs(b), (a, b)
print(f"problem file: increments {[round(t, 4) for t in taken]}, force {a:.12g} N; 5 fixed: {b:.12g} N")
PY

# 4. Friction (tests/data/calculix/change_friction.inp: a block pressed with 100 N onto a base and
#    pushed along x, Coulomb mu = 0.3, then 0.1) with step 2 at *STATIC 0.1, 1.: its increments
#    grow by the rule; with an *EQUATION that ties two slave nodes' z (their normal rows then
#    depend on it, and the normal multipliers are not unique: fricloop) they stay at 0.1, with
#    one warning. Reference for both: the block slides, so the top nodes' reaction along x is
#    mu N = 30 N and 10 N (to 1e-3, as tests/cli/deck_change_friction.sh).
/usr/bin/python3 - "$src/tests/data/calculix/change_friction.inp" "$work" <<'PY'
import sys
deck, work = sys.argv[1:]
first, step1, step2, step3 = open(deck).read().split("*STEP\n*STATIC\n")
grown = first + "*STEP\n*STATIC\n" + step1 + "*STEP\n*STATIC\n0.1, 1.\n" + step2 + "*STEP\n*STATIC\n" + step3
open(f"{work}/friction.inp", "w").write(grown)
at = grown.index("*STEP")
open(f"{work}/tied.inp", "w").write(grown[:at] + "*EQUATION\n2\n1001,3,1.,1002,3,-1.\n" + grown[at:])
PY
for deck in friction tied; do
  "$feticon" run "$work/$deck.inp" --output "$work/$deck" "${settings[@]}" >"$work/$deck.log" 2>&1 || { cat "$work/$deck.log"; exit 1; }
done
grep -q "2 slave nodes of pairs with friction are tied by equations" "$work/tied.log" || { cat "$work/tied.log"; exit 1; }
if grep -q "tied by equations" "$work/friction.log"; then echo "friction: a warning about tied slave nodes"; exit 1; fi
/usr/bin/python3 - "$work" <<'PY'
import json
import sys

import increment_rule
from calculix_dat import parse_dat

work = sys.argv[1]
for deck in ("friction", "tied"):
    summary = json.load(open(f"{work}/{deck}/summary.json"))
    assert summary["converged"], deck
    steps = [s for s in summary["steps"] if 1 < s["load_factor"] <= 2 + 1e-12]
    if deck == "friction":
        taken = increment_rule.check(steps, 1.0, 0.1, 1e-5, 1.0)
        assert len(taken) < 10, taken
    else:
        taken = [s["load_factor"] - 1 for s in steps]
        assert all(abs(t - 0.1 * k) <= 1e-12 for t, k in zip(taken, range(1, 11))) and len(taken) == 10, taken
    totals = [b for b in parse_dat(f"{work}/{deck}/{deck}.dat")["blocks"] if b["kind"] == "total force"]
    fx = [b["rows"][0][0] for b in totals]  # one block an increment: step 2's last, then step 3's
    assert len(fx) == len(taken) + 2 and abs(fx[-2] - 30) <= 0.03 and abs(fx[-1] - 10) <= 0.01, fx
    print(f"{deck}: step 2 in {len(taken)} increments {[round(t, 4) for t in taken]}; reactions {fx[-2]:.6g}, {fx[-1]:.6g} N")
PY

source "$src/tests/tools/expect_deck_error.sh" # expect_error NAME PATTERN
sed '/^\*STATIC$/{n;s/.*/0.1, 1., 0.2/}' "$work/automatic.inp" >"$work/minimum.inp"
expect_error minimum "minimum.inp:[0-9]*: \*STATIC: the increments need 0 < minimum <= initial <= maximum, given 0.2, 0.1, 1"
sed 's/increment: {initial: 0.2, maximum: 0.6}/increment: {initial: 0.2, minimum: 0.3}/' "$work/pressed.yaml" >"$work/minimum.yaml"
if "$feticon" run -q "$work/minimum.yaml" --output "$work/bad" >"$work/yaml.log" 2>&1; then
  echo "minimum above initial accepted"
  exit 1
fi
grep -q "steps.0.increment needs 0 < minimum <= initial <= maximum" "$work/yaml.log" || { cat "$work/yaml.log"; exit 1; }
# *STEP, INC=3 (CalculiX's limit; default 100): the 6 increments the deck takes are too many.
sed 's/^\*STEP,NLGEOM$/*STEP,NLGEOM,INC=3/' "$work/automatic.inp" >"$work/limited.inp"
expect_error limited "step 1 needs more than its 3 increments (\*STEP, INC=; CalculiX's default 100)"
sed 's/^\*STEP,NLGEOM$/*STEP,NLGEOM,INC=0/' "$work/automatic.inp" >"$work/zeroinc.inp"
expect_error zeroinc "INC=0 must be a whole number of increments >= 1"
echo "bad input: one line each"
