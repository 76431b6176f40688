#!/usr/bin/env bash
# Temperatures (issue 65, item 4). A block held at its top and heated rests on a base held at
# its bottom (frictionless, symmetry planes x = 0 and y = 0): the stress is uniaxial in both,
# sigma = -E alpha dT L_block / (L_block + L_base), and the contact force sigma A
# (reference: that series formula; mortar rows carry a uniform stress exactly across the
# non-matching faces). alpha = 1.2e-5, T_0 = 20, the block at 120 then 70: 3e7 N, then 1.5e7 N.
# 1. the problem file (initial_temperature, temperatures per step, expansion per body);
# 2. its CalculiX deck (feticon export: *EXPANSION, *INITIAL CONDITIONS, *TEMPERATURE, OP=NEW)
#    through the deck reader: the .dat's base reactions at both step ends. CalculiX 2.20 on
#    this deck prints 2.903226E+07 and 1.451626E+07 N: the series formula with its penalty
#    law's compliance 1 / K (K = 6e12 Pa/m) added to (L_block + L_base) / E, 3.2 % less;
# 3. model changes (issue 65, item 6): the deck with the pair removed in step 2 (*MODEL CHANGE,
#    TYPE=CONTACT PAIR, REMOVE: the block expands into the base, reaction 0) and added back in a
#    step 3 like step 2 (1.5e7 N again: small displacements do not depend on the path).
#    CalculiX 2.20 on this deck: 2.903226E+07, 2.6E-22, 1.451612E+07 N;
# 4. bad input: a temperature below absolute zero, an *EXPANSION outside a material, a
#    *TEMPERATURE on an undefined node set, a *MODEL CHANGE of a pair no *CONTACT PAIR
#    defines: one line each.
# Usage: thermal.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat >"$work/heat.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: base,  origin: [0, 0, -0.5], lengths: [0.5, 0.5, 0.5], cells: [4, 4, 4]}
    - {name: block, origin: [0, 0, 0],    lengths: [0.5, 0.5, 0.5], cells: [3, 3, 3]}
bodies:
  base:  {young: 2e11, poisson: 0.3, expansion: 1.2e-5}
  block: {young: 2e11, poisson: 0.3, expansion: 1.2e-5}
supports:
  - {set: base_zmin, z: 0}
  - {set: base_xmin, x: 0}
  - {set: base_ymin, y: 0}
  - {set: block_zmax, z: 0}
  - {set: block_xmin, x: 0}
  - {set: block_ymin, y: 0}
contact:
  - {slave: block_zmin, master: base_zmax}
initial_temperature: 20
steps:
  - temperatures: [{body: block, value: 120}]
  - temperatures: [{body: block, value: 70}]
subdomains: 4
displacements: small
YAML
# qp.force_rtol = 0: the QP to qp.rtol alone, so the force is exact to 1e-7.
settings=(--set output.plots=false --set qp.rtol=1e-10 --set qp.force_rtol=0)
"$feticon" run -q "$work/heat.yaml" --output "$work/file" "${settings[@]}"
/usr/bin/python3 - "$work/file/summary.json" <<'PY'
import json
import sys

s = json.load(open(sys.argv[1]))
assert s["converged"], s.get("reason")
force = s["contact"]["total_normal_force"]
assert abs(force / 1.5e7 - 1) < 1e-7, force
print(f"problem file: contact force {force:.10g} N at dT = 50 K (1.5e7 N)")
PY

"$feticon" export "$work/heat.yaml" --format calculix --output "$work/deck" >/dev/null
grep -q '^\*EXPANSION$' "$work/deck/feticon.inp"
grep -q '^\*INITIAL CONDITIONS, TYPE=TEMPERATURE$' "$work/deck/feticon.inp"
[ "$(grep -c '^\*TEMPERATURE, OP=NEW$' "$work/deck/feticon.inp")" -eq 2 ]
"$feticon" run -q "$work/deck/feticon.inp" --output "$work/deckrun" "${settings[@]}" 2>/dev/null
/usr/bin/python3 - "$work/deckrun/feticon.dat" <<'PY'
import re
import sys

text = open(sys.argv[1]).read()
blocks = re.findall(r"total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", text)
base = {float(t): float(fz) for name, t, fx, fy, fz in blocks if name == "N_BASE_ZMIN"}
expected = {1.0: 3e7, 2.0: 1.5e7}
assert sorted(base) == sorted(expected), base
for t, f in expected.items():
    assert abs(base[t] - f) <= 5e-7 * f, (t, base[t], f)  # the .dat's 7 digits
print("deck: base reactions", [base[t] for t in sorted(base)], "N")
PY

deck="$work/deck/feticon.inp"
/usr/bin/python3 - "$deck" "$work/change.inp" <<'PY'
import sys

s = open(sys.argv[1]).read()
second = s.index("*STEP", s.index("*END STEP"))
pair = "*MODEL CHANGE, TYPE=CONTACT PAIR, {}\nS_block_zmin, S_base_zmax\n*BOUNDARY"
step = s[second:]
open(sys.argv[2], "w").write(
    s[:second] + step.replace("*BOUNDARY", pair.format("REMOVE"), 1) + step.replace("*BOUNDARY", pair.format("ADD"), 1))
PY
"$feticon" run -q "$work/change.inp" --output "$work/change" "${settings[@]}" 2>/dev/null
/usr/bin/python3 - "$work/change/change.dat" <<'PY'
import re
import sys

text = open(sys.argv[1]).read()
blocks = re.findall(r"total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", text)
base = {float(t): float(fz) for name, t, fx, fy, fz in blocks if name == "N_BASE_ZMIN"}
assert sorted(base) == [1.0, 2.0, 3.0], base
assert abs(base[1.0] - 3e7) <= 5e-7 * 3e7 and abs(base[3.0] - 1.5e7) <= 5e-7 * 1.5e7, base
assert abs(base[2.0]) <= 1e-6 * 3e7, base  # no pair: no reaction but round-off
print("model change: base reactions", [base[t] for t in sorted(base)], "N")
PY

# Bad input: one line naming file, line and what is wrong.
expect_error() {
  local name="$1" pattern="$2" file="$3"
  if "$feticon" run -q "$file" --output "$work/bad_$name" 2>"$work/err_$name"; then
    echo "FAIL $name ran"
    exit 1
  fi
  if ! grep -q "$pattern" "$work/err_$name" || [ "$(wc -l <"$work/err_$name")" -ne 1 ]; then
    echo "FAIL $name: $(cat "$work/err_$name")"
    exit 1
  fi
  echo "bad input ($name): $(cat "$work/err_$name")"
}
sed '0,/^126, 1.200000000000e+02$/s//126, -300/' "$deck" >"$work/cold.inp"
expect_error cold "cold.inp:[0-9]*:[0-9]*: \*TEMPERATURE: the temperature is -300: not finite or below absolute zero" "$work/cold.inp"
awk '/^\*MATERIAL/ && !done {print "*EXPANSION"; print "1e-5"; done = 1} {print}' "$deck" >"$work/early.inp"
expect_error early "early.inp:[0-9]*: \*EXPANSION comes before any \*MATERIAL" "$work/early.inp"
sed '0,/^126, 1.200000000000e+02$/s//NOWHERE, 120/' "$deck" >"$work/unknown.inp"
expect_error unknown "unknown.inp:[0-9]*.*NOWHERE" "$work/unknown.inp"
sed 's/^S_block_zmin, S_base_zmax$/S_block_zmin, S_lid/' "$work/change.inp" >"$work/nopair.inp"
sed -i '0,/^S_block_zmin, S_lid$/s//S_block_zmin, S_base_zmax/' "$work/nopair.inp"
expect_error nopair "nopair.inp:[0-9]*: \*MODEL CHANGE: no \*CONTACT PAIR has slave S_BLOCK_ZMIN and master S_LID" \
  "$work/nopair.inp"
