#!/usr/bin/env bash
# Steps and amplitudes (issue 65, items 1 and 2). A block pressed on a base (frictionless):
# 1. a problem file whose first step follows an amplitude up and down, (0, 0), (0.5, 1),
#    (1, 0.4), in 4 increments and whose second step ramps to another load: the contact force
#    at the end is that load times the contact area (reference: equilibrium);
# 2. the same model as a CalculiX deck (feticon export) with *AMPLITUDE and *CLOAD, AMPLITUDE=,
#    small displacements: at every printed time the .dat's total reaction of the base is the
#    load at that level, and the lateral reactions are affine in it (frictionless linear
#    contact is path independent; the unloading increments included; the export's initial
#    overlap is the constant part). CalculiX 2.20 on this
#    deck prints the same base totals, 5.000000E+05, 1.000000E+06, 7.000000E+05, 4.000000E+05 N.
# 3. bad input: an undefined amplitude and a table with decreasing times, one line each.
# Usage: amplitudes.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
model='problem: custom
mesh:
  boxes:
    - {name: base,  origin: [0, 0, -0.5], lengths: [1.0, 1.0, 0.5], cells: [4, 4, 2]}
    - {name: block, origin: [0, 0, 0],    lengths: [0.5, 0.5, 0.5], cells: [3, 3, 3]}
bodies:
  base:  {young: 2e11, poisson: 0.3}
  block: {young: 2e11, poisson: 0.3}
supports:
  - {set: base_zmin, x: 0, y: 0, z: 0}
  - {set: block_xmin, x: 0}
  - {set: block_ymin, y: 0}
contact:
  - {slave: block_zmin, master: base_zmax}
subdomains: 4
qp.rtol: 1e-10'
cat >"$work/steps.yaml" <<YAML
$model
amplitudes:
  updown: [[0, 0], [0.5, 1], [1, 0.4]]
steps:
  - loads: [{set: block_zmax, traction: [0, 0, -4e6], amplitude: updown}]
    increments: 4
  - loads: [{set: block_zmax, traction: [0, 0, -2e6]}]
    increments: 2
YAML
"$feticon" run -q "$work/steps.yaml" --output "$work/steps" --set output.plots=false
/usr/bin/python3 - "$work/steps/summary.json" <<'PY'
import json
import sys

s = json.load(open(sys.argv[1]))
assert s["converged"], s.get("reason")
factors = [step["load_factor"] for step in s["steps"]]
assert factors == [0.25, 0.5, 0.75, 1.0, 1.5, 2.0], factors
force = s["contact"]["total_normal_force"]
assert abs(force / 5e5 - 1) < 1e-8, force
print(f"problem file: load factors {factors}, final contact force {force:.10g} N (2e6 Pa x 0.25 m^2)")
PY

# The deck: the model exported with its load, then the amplitude added.
cat >"$work/single.yaml" <<YAML
$model
loads:
  - {set: block_zmax, traction: [0, 0, -4e6]}
displacements: small
YAML
"$feticon" export "$work/single.yaml" --format calculix --output "$work/deck" >/dev/null
/usr/bin/python3 - "$work/deck/feticon.inp" "$work/amp.inp" <<'PY'
import re
import sys

s = open(sys.argv[1]).read()
s = s.replace("*STEP", "*AMPLITUDE, NAME=UPDOWN\n0., 0., 0.5, 1., 1., 0.4\n*STEP", 1)
s = s.replace("*CLOAD\n", "*CLOAD, AMPLITUDE=UPDOWN\n", 1)
s = re.sub(r"\*STATIC\n[^\n]*\n", "*STATIC, DIRECT\n0.25, 1.\n", s, count=1)
open(sys.argv[2], "w").write(s)
PY
"$feticon" run -q "$work/amp.inp" --output "$work/amp" --set output.plots=false --set qp.rtol=1e-10 2>/dev/null
/usr/bin/python3 - "$work/amp/amp.dat" <<'PY'
import re
import sys

text = open(sys.argv[1]).read()
blocks = re.findall(r"total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", text)
base = {float(t): float(fz) for name, t, fx, fy, fz in blocks if name == "N_BASE_ZMIN"}
lateral = {float(t): float(fy) for name, t, fx, fy, fz in blocks if name == "N_BLOCK_XMIN"}
level = {0.25: 0.5, 0.5: 1.0, 0.75: 0.7, 1.0: 0.4}
assert sorted(base) == sorted(level), base
for t, a in level.items():
    # The .dat prints 7 digits: the bar is its rounding.
    assert abs(base[t] - a * 1e6) <= 5e-7 * a * 1e6, (t, base[t], a)
    # Affine in the level (the export presses the floating block into the base by a few mm
    # before any load), through the values at 0.5 and 1: to the solver's force tolerance,
    # 1e-7 of the load (measured 1.8e-2 N at 0.75 and 0.25).
    slope = (lateral[1.0] - lateral[0.5]) / (0.4 - 1.0)
    assert abs(lateral[t] - (lateral[0.5] + slope * (a - 1.0))) <= 1e-7 * 1e6, (t, lateral, slope)
print("deck: base reaction", [base[t] for t in sorted(base)], "N; lateral", [lateral[t] for t in sorted(lateral)])
PY

# Bad input: one line naming the file and what is wrong.
sed 's/amplitude: updown/amplitude: downup/' "$work/steps.yaml" >"$work/undefined.yaml"
if "$feticon" run -q "$work/undefined.yaml" --output "$work/bad1" 2>"$work/err1.txt"; then
  echo "an undefined amplitude ran"
  exit 1
fi
grep -q "steps.0.loads.0.amplitude: no amplitude 'downup' in amplitudes; it has: updown" "$work/err1.txt"
sed 's/^0., 0., 0.5, 1., 1., 0.4$/0., 0., 0.5, 1., 0.25, 0.4/' "$work/amp.inp" >"$work/decreasing.inp"
if "$feticon" run -q "$work/decreasing.inp" --output "$work/bad2" 2>"$work/err2.txt"; then
  echo "an amplitude with decreasing times ran"
  exit 1
fi
grep -q "decreasing.inp:[0-9]*: \*AMPLITUDE UPDOWN: the amplitude's times decrease at point 3" "$work/err2.txt"
[ "$(wc -l <"$work/err1.txt")" -eq 1 ] && [ "$(wc -l <"$work/err2.txt")" -eq 1 ]
echo "bad input: $(cat "$work/err1.txt"); $(cat "$work/err2.txt")"
