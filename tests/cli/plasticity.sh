#!/usr/bin/env bash
# J2 plasticity (issue 66, items 2, 3 and 6). A block (J2, sigma_y = 250 MPa, H = 1 GPa) is
# pressed 2 mm by a stiff platen through a frictionless pair, then released to 1.5 mm
# (tests/verification/test_plastic_compression.cpp has the closed form of every increment):
# 1. the problem file: converged, the VTU holds equivalent_plastic_strain, the contact force at
#    the end the series model's 1.33820254e7 N (elastic unloading from 6.31828222e7 N);
# 2. its CalculiX deck (feticon export: *PLASTIC, *EL FILE PE, *EL PRINT PEEQ) through the deck
#    reader: the platen's reactions at every increment and PEEQ of every point against the
#    series model, the .frd's PE block. CalculiX 2.20 on this deck prints reactions 6.251933E+07,
#    6.285092E+07, 6.318266E+07 and 1.340666E+07 N (closed form 6.25194855e7, 6.28511539e7,
#    6.31828222e7, 1.33820254e7) and PEEQ 7.732E-05, 1.4037E-03, 2.7307E-03 (2.731289e-3): its
#    penalty law (K = 8e14 Pa/m) lets the platen in by sigma / K = 3.1e-7 m, which the block's
#    plastic strain gives up, and adds 1 / K to the unloading compliance (+0.18 %);
# 3. restart: the checkpoint after step 1 (of a one-step copy) continues to the uninterrupted
#    run's answer, bitwise (the J2 states are in the checkpoint);
# 4. two MPI ranks give the one-rank answer;
# 5. bad input: decreasing plastic strains, a first plastic strain that is not 0, combined
#    hardening, a temperature-dependent table, thermal expansion of a plastic body with NLGEOM
#    (finite-strain J2 has no thermal strain: tests/cli/plasticity_nlgeom.sh): one line each.
# Usage: plasticity.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat >"$work/press.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: block,  origin: [0, 0, 0],   lengths: [0.5, 0.5, 0.5], cells: [3, 3, 3]}
    - {name: platen, origin: [0, 0, 0.5], lengths: [0.5, 0.5, 0.2], cells: [4, 4, 2]}
bodies:
  block:  {young: 2e11, poisson: 0.3, plastic: [[2.5e8, 0], [1.25e9, 1]]}
  platen: {young: 2e13, poisson: 0.3}
supports:
  - {set: block_zmin, z: 0}
  - {set: block_xmin, x: 0}
  - {set: block_ymin, y: 0}
  - {set: platen_xmin, x: 0}
  - {set: platen_ymin, y: 0}
  - {set: platen_zmax, z: -0.002}
contact:
  - {slave: platen_zmin, master: block_zmax}
steps:
  - increments: 3
  - supports:
      - {set: block_zmin, z: 0}
      - {set: block_xmin, x: 0}
      - {set: block_ymin, y: 0}
      - {set: platen_xmin, x: 0}
      - {set: platen_ymin, y: 0}
      - {set: platen_zmax, z: -0.0015}
    increments: 1
subdomains: 4
displacements: small
YAML
settings=(--set output.plots=false --set qp.rtol=1e-10 --set qp.force_rtol=0)
"$feticon" run -q "$work/press.yaml" --output "$work/file" "${settings[@]}"
grep -q 'Name="equivalent_plastic_strain"' "$work/file/step_004.vtu"
/usr/bin/python3 - "$work/file/summary.json" <<'PY'
import json
import sys

s = json.load(open(sys.argv[1]))
assert s["converged"], s.get("reason")
force = s["contact"]["total_normal_force"]
assert abs(force / 1.33820254e7 - 1) < 1e-5, force  # the verification test's tolerance
print(f"problem file: contact force {force:.9g} N after unloading (1.33820254e7 N)")
PY

"$feticon" export "$work/press.yaml" --format calculix --output "$work/deck" >/dev/null
grep -q '^\*PLASTIC$' "$work/deck/feticon.inp"
"$feticon" run -q "$work/deck/feticon.inp" --output "$work/deckrun" "${settings[@]}" 2>/dev/null
grep -q '^ -4  PE          1    1$' "$work/deckrun/feticon.frd"
/usr/bin/python3 - "$work/deckrun/feticon.dat" <<'PY'
import re
import sys

text = open(sys.argv[1]).read()
blocks = re.findall(r"total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", text)
platen = {round(float(t), 4): -float(fz) for name, t, fx, fy, fz in blocks if name == "N_PLATEN_ZMAX"}
# The series model at every increment (ccx prints each), as the verification test has it.
expected = {0.3333: 6.25194855e7, 0.6667: 6.28511539e7, 1.0: 6.31828222e7, 2.0: 1.33820254e7}
assert sorted(platen) == sorted(expected), platen
for t, f in expected.items():
    assert abs(platen[t] - f) <= 1e-5 * 6.31828222e7, (t, platen[t], f)
peeq = re.findall(r"equivalent plastic strain \(elem, integ\.pnt\.,pe\)for set B_BLOCK and time\s+\S+\n\n((?:\s+\d+\s+\d+\s+\S+\n)+)", text)
closed = [7.794206e-05, 1.404615e-03, 2.731289e-03, 2.731289e-03]
assert len(peeq) == len(closed), len(peeq)
for block, eqps in zip(peeq, closed):
    values = [float(line.split()[2]) for line in block.strip().splitlines()]
    # 1e-5 of the strain (the verification test's tolerance), the .dat's 7 digits
    assert len(values) == 27 * 8 and all(abs(v - eqps) < 4e-8 + 5e-7 * eqps for v in values), (eqps, min(values), max(values))
print("deck: platen reactions", [platen[t] for t in sorted(platen)], "N; PEEQ of all 216 points the closed form's")
PY

# Restart: a copy of the problem with step 1 alone writes the checkpoint; given the two-step
# problem's effective settings, --restart continues it (the same load history up to there).
/usr/bin/python3 - "$work/press.yaml" "$work/first.yaml" <<'PY'
import sys

text = open(sys.argv[1]).read()
open(sys.argv[2], "w").write(text[: text.index("  - supports:")] + "subdomains: 4\ndisplacements: small\n")
PY
"$feticon" run -q "$work/first.yaml" --output "$work/restart" "${settings[@]}"
cp "$work/file/problem.yaml" "$work/restart/problem.yaml" # the run to continue: the two-step problem
"$feticon" run -q --restart "$work/restart"
/usr/bin/python3 - "$work/file/summary.json" "$work/restart/summary.json" <<'PY'
import json
import sys

whole, continued = (json.load(open(p)) for p in sys.argv[1:])
assert continued["converged"], continued.get("reason")
a, b = whole["contact"]["total_normal_force"], continued["contact"]["total_normal_force"]
assert a == b, (a, b)  # bitwise: the same states, the same QPs
print(f"restart: contact force {b:.12g} N, the uninterrupted run's")
PY

# Two MPI ranks (the J2 states of each rank's subdomains gathered to both): the one-rank answer.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun --oversubscribe -np 2 "$feticon" run -q "$work/press.yaml" --output "$work/ranks" "${settings[@]}"
grep -q 'Name="equivalent_plastic_strain"' "$work/ranks/step_004.pvtu"
/usr/bin/python3 - "$work/file/summary.json" "$work/ranks/summary.json" <<'PY'
import json
import sys

one, two = (json.load(open(p)) for p in sys.argv[1:])
assert [s["outer_iterations"] for s in one["steps"]] == [s["outer_iterations"] for s in two["steps"]]
a, b = one["contact"]["total_normal_force"], two["contact"]["total_normal_force"]
assert abs(a - b) <= 1e-12 * a, (a, b)
print(f"2 ranks: contact force {b:.12g} N, outer iterations as on one rank")
PY

deck="$work/deck/feticon.inp"
source "$(dirname "$0")/../tools/expect_deck_error.sh" # expect_error NAME PATTERN
sed 's/^1\.250000000000e+09, 1\.000000000000e+00$/1.25e9, 0/' "$deck" >"$work/decreasing.inp"
expect_error decreasing "equivalent plastic strains must increase"
sed 's/^2\.500000000000e+08, 0\.000000000000e+00$/2.5e8, 0.01/' "$deck" >"$work/nonzero.inp"
expect_error nonzero "first equivalent plastic strain is 0.01, not 0"
sed 's/^\*PLASTIC$/*PLASTIC, HARDENING=COMBINED/' "$deck" >"$work/combined.inp"
expect_error combined "HARDENING=COMBINED is not implemented"
sed 's/^\(2\.500000000000e+08, 0\.000000000000e+00\)$/\1, 20/; s/^\(1\.250000000000e+09, 1\.000000000000e+00\)$/\1, 100/' "$deck" >"$work/temperatures.inp"
expect_error temperatures "temperature-dependent plastic tables"
sed 's/^\*STEP, INC=100$/*STEP, NLGEOM, INC=100/; s/^\*PLASTIC$/*EXPANSION\n1.2e-5\n*PLASTIC/' "$deck" >"$work/nlgeom.inp"
expect_error nlgeom "thermal strain in J2 plasticity is implemented at small strain only"
echo "bad input: five one-line errors"
