#!/usr/bin/env bash
# `feticon export` of amplitudes (issue 63, export): *AMPLITUDE (TIME=TOTAL TIME, SHIFTX,
# SHIFTY), *BOUNDARY / *CLOAD / *TEMPERATURE, AMPLITUDE= per group, *STATIC in the step's own time.
# 1. a block pressed on a base by a traction that follows an amplitude up and down in step 1
#    and a total-time amplitude with shifts in step 2 (time 2), frictionless, large displacements:
#    the deck's run gives the problem file's displacements at every increment (to 1e-8 of max
#    |u|; measured 7e-10, the QP tolerance), and its .dat's base reaction at each time is the
#    traction times the area times a(t) (equilibrium, 7 printed digits);
# 2. a steel bar (no contact, small displacements) pulled by a prescribed end displacement with an
#    amplitude, then heated (*TEMPERATURE with a total-time amplitude) and pulled sideways by a
#    traction with it: the .dat's end reaction at every time is the closed form of the uniform
#    state A (E (u / L - alpha T) + nu sigma_y) (7 digits); the deck run equals the problem file's.
#    CalculiX 2.20 on this deck prints -4.000000E+06 and -1.215500E+05 N at the two step ends.
# 3. a load that goes from an amplitude to a ramp between steps (CalculiX ramps from its last
#    value, feticon from the loads without amplitude), and a node direction loaded by two amplitude
#    groups in one step (CalculiX's forcadd.f refuses it): one line each.
# Usage: export_amplitudes.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cat >"$work/block.yaml" <<'YAML'
problem: custom
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
qp.rtol: 1e-10
amplitudes:
  updown: [[0, 0], [0.5, 1], [1, 0.4]]
  later: {points: [[0, 0], [1, 1], [2, 0.5], [3, 0.2], [4, 1], [5, 2]], time: total, shift_x: 0.5, shift_y: 0.1}
steps:
  - loads: [{set: block_zmax, traction: [0, 0, -4e6], amplitude: updown}]
    increments: 4
  - loads: [{set: block_zmax, traction: [0, 0, -2e6], amplitude: later}, {set: block_xmax, traction: [-1e5, 0, 0]}]
    increments: 3
    time: 2
YAML
cat >"$work/bar.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: bar, origin: [0, 0, 0], lengths: [1, 0.2, 0.2], cells: [4, 1, 1]}
bodies:
  bar: {young: 2e11, poisson: 0.3, expansion: 1.2e-5}
displacements: small
amplitudes:
  wave: [[0, 0], [0.5, 1], [1, -0.5]]
  heat: {points: [[0, 0], [1, 1], [2, 0.25]], time: total, shift_y: 0.1}
steps:
  - supports:
      - {set: bar_xmin, x: 0}
      - {set: bar_ymin, y: 0}
      - {set: bar_zmin, z: 0}
      - {set: bar_xmax, x: 1e-3, amplitude: wave}
    increments: 4
  - supports:
      - {set: bar_xmin, x: 0}
      - {set: bar_ymin, y: 0}
      - {set: bar_zmin, z: 0}
      - {set: bar_xmax, x: 2e-3, amplitude: wave}
    temperatures: [{value: 80, amplitude: heat}]
    loads: [{set: bar_ymax, traction: [0, 1e6, 0], amplitude: heat}]
    increments: 3
    time: 0.75
YAML
for model in block bar; do
  "$feticon" run -q "$work/$model.yaml" -o "$work/$model" --set output.plots=false
  "$feticon" export "$work/$model.yaml" --format calculix --overclosure 0 -o "$work/$model-deck" >/dev/null
  "$feticon" run -q "$work/$model-deck/feticon.inp" -o "$work/$model-from-deck" --set output.plots=false \
    --set subdomains="$(/usr/bin/python3 -c "import json; print(json.load(open('$work/$model/summary.json'))['subdomains'])")" \
    --set qp.rtol=1e-10 2>/dev/null
done
grep -q '^\*AMPLITUDE, NAME=A_later, TIME=TOTAL TIME, SHIFTX=5.000000000000e-01, SHIFTY=1.000000000000e-01$' \
  "$work/block-deck/feticon.inp"
grep -q '^\*BOUNDARY, AMPLITUDE=A_wave$' "$work/bar-deck/feticon.inp"
grep -q '^\*TEMPERATURE, AMPLITUDE=A_heat$' "$work/bar-deck/feticon.inp"
/usr/bin/python3 - "$work" "$src/tests/tools" <<'PY'
import re
import sys

import numpy

work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
import read_vtu


def table(points, t, shift_x=0.0, shift_y=0.0):
    times, values = zip(*points)
    return float(numpy.interp(t - shift_x, times, values)) + shift_y


def totals(dat, name):
    text = open(dat).read()
    found = re.findall(r"total force \(fx,fy,fz\) for set " + name + r" and time\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", text)
    return [(float(t), numpy.array([float(fx), float(fy), float(fz)])) for t, fx, fy, fz in found]


for model, steps in (("block", 7), ("bar", 7)):
    worst = 0.0
    for k in range(1, steps + 1):
        a, b = (read_vtu.point_data(f"{work}/{d}/step_{k:03d}.vtu")["displacement"] for d in (model, model + "-from-deck"))
        worst = max(worst, numpy.abs(a - b).max() / numpy.abs(a).max())
    print(f"{model}: the deck's displacements at its {steps} increments {worst:.2g} of max |u| from the problem file's")
    assert worst <= 1e-8, model

# The block: base reaction = traction x 0.25 m^2 x a(t); step 1 in step time, step 2 in total time.
updown = [(0, 0), (0.5, 1), (1, 0.4)]
later = [(0, 0), (1, 1), (2, 0.5), (3, 0.2), (4, 1), (5, 2)]
base = totals(f"{work}/block-from-deck/feticon.dat", "N_BASE_ZMIN")
assert len(base) == 7, base
for t, force in base:
    expected = 4e6 * 0.25 * table(updown, t) if t <= 1 + 1e-9 else 2e6 * 0.25 * table(later, t, 0.5, 0.1)
    assert abs(force[2] - expected) <= 5e-7 * abs(expected), (t, force, expected)
print("block: base reactions", [f"{f[2]:.7g}" for _, f in base], "N at the times", [round(t, 4) for t, _ in base])

# The bar: uniform state, sigma_y = the traction, sigma_x = E (u / L - alpha T) + nu sigma_y.
wave = [(0, 0), (0.5, 1), (1, -0.5)]
heat = [(0, 0), (1, 1), (2, 0.25)]
end = totals(f"{work}/bar-from-deck/feticon.dat", "N_BAR_XMAX")
assert len(end) == 7, end
for t, force in end:
    if t <= 1 + 1e-9:
        u, temperature, sigma_y = 1e-3 * table(wave, t), 0.0, 0.0
    else:
        level = table(heat, t, 0.0, 0.1)
        u, temperature, sigma_y = 2e-3 * table(wave, t - 1), 80 * level, 1e6 * level
    expected = 0.04 * (2e11 * (u - 1.2e-5 * temperature) + 0.3 * sigma_y)
    assert abs(force[0] - expected) <= 5e-7 * max(abs(expected), 1e5), (t, force, expected)
print("bar: end reactions", [f"{f[0]:.7g}" for _, f in end], "N")
PY

# A load that trades its amplitude for the ramp between steps: one line.
sed 's/{set: block_zmax, traction: \[0, 0, -2e6\], amplitude: later}/{set: block_zmax, traction: [0, 0, -2e6]}/' \
  "$work/block.yaml" >"$work/switch.yaml"
source "$src/tests/tools/expect_deck_error.sh"
expect_export_error "$work/switch.yaml" switch \
  "calculix export: step 2: node [0-9]*, direction 3 is loaded without amplitude, in step 1 with"
# Loads of two groups on one node direction (the top's traction follows an amplitude, a shear on
# the side without one shares the top edge's nodes in z): one line, which a deck cannot say.
sed 's/^  - loads: \[{set: block_zmax, traction: \[0, 0, -4e6\], amplitude: updown}\]$/  - loads: [{set: block_zmax, traction: [0, 0, -4e6], amplitude: updown}, {set: block_xmax, traction: [0, 0, -1e5]}]/' \
  "$work/block.yaml" >"$work/two_groups.yaml"
grep -q 'block_xmax, traction: \[0, 0, -1e5\]' "$work/two_groups.yaml"
expect_export_error "$work/two_groups.yaml" two_groups \
  "calculix export: step 1: node [0-9]*, direction 3 is loaded by loads of two amplitudes"
