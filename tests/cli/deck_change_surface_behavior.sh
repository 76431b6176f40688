#!/usr/bin/env bash
# *CHANGE SURFACE BEHAVIOR (issue 65, item 6) on CalculiX's changesurfbeh deck (tests/data/
# calculix: two cubes, PRESSURE-OVERCLOSURE=TIED in step 1 while the upper cube's top is pulled
# up 0.1, LINEAR contact from step 2 on): the pair is a tie in step 1 and a contact pair in
# step 2. References: step 2 is CalculiX's own answer, the upper cube lifted 0.1 as a rigid body
# and the lower one back at rest (CalculiX 2.20's .frd, changesurfbeh.frd.ref: u = 0 and
# (0, 0, 0.1); asserted 1e-9, measured 6.6e-11); step 1 transmits the pull through the tie
# (the upper cube's bottom nodes at the lower cube's top, u_z equal to 1e-9). Step 1 is not
# CalculiX's: its TIED law ties across the surfaces only and lets them slide by the *FRICTION
# stick slope (its slave nodes slide 0.026 of 0.1 inward), feticon ties every direction.
# Also: *CHANGE SURFACE BEHAVIOR without its *SURFACE BEHAVIOR, or outside a step: one line.
# Usage: deck_change_surface_behavior.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
deck="$src/tests/data/calculix/changesurfbeh.inp"
cp "$deck" "$work/changesurfbeh.inp"
"$feticon" run -q "$work/changesurfbeh.inp" --output "$work/run" --set output.plots=false 2>/dev/null
/usr/bin/python3 - "$work/run/changesurfbeh.frd" "$src/tests/data/calculix/changesurfbeh.frd.ref" <<'PY'
import sys

import numpy


def disp_blocks(path):
    """Every DISP block of a .frd: rows (label, u1, u2, u3) sorted by label."""
    blocks, inside = [], False
    for line in open(path):
        if line.startswith(" -4  DISP"):
            blocks.append([])
            inside = True
        elif inside and line.startswith(" -1"):
            blocks[-1].append((int(line[3:13]), *(float(line[13 + 12 * k : 25 + 12 * k]) for k in range(3))))
        elif inside and line.startswith(" -3"):
            inside = False
    return [numpy.array(sorted(b)) for b in blocks]


ours, ccx = disp_blocks(sys.argv[1]), disp_blocks(sys.argv[2])
assert len(ours) == 2 and len(ccx) == 2, (len(ours), len(ccx))
lifted = numpy.zeros((16, 3))
lifted[8:, 2] = 0.1  # nodes 9-16: the upper cube
assert numpy.abs(ours[1][:, 1:] - lifted).max() <= 1e-9, ours[1]
step2 = numpy.abs(ours[1][:, 1:] - ccx[1][:, 1:]).max()
assert step2 <= 1e-9, step2
u = {int(row[0]): row[1:] for row in ours[0]}
top = [u[n][2] for n in (3, 4, 7, 8)]  # the lower cube's top face
bottom = [u[n][2] for n in (9, 10, 13, 14)]  # the upper cube's bottom, tied to it
assert min(top) > 0.02 and max(abs(b - top[0]) for b in bottom + top) <= 1e-9, (top, bottom)
step1 = numpy.abs(ours[0][:, 1:] - ccx[0][:, 1:]).max()
print(f"step 2: {step2:.1e} from CalculiX (rigid lift of 0.1); step 1: tie carries u_z = {top[0]:.5f} "
      f"(CalculiX {ccx[0][2][3]:.5f}, its tangentially sliding tie; max difference {step1:.3f})")
PY

source "$src/tests/tools/expect_deck_error.sh" # expect_error NAME PATTERN
sed 's/^\*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=LINEAR$/*FRICTION/' "$deck" >"$work/alone.inp"
expect_error alone "needs its \*SURFACE BEHAVIOR next"
sed '/^\*STEP,NLGEOM$/i *CHANGE SURFACE BEHAVIOR,INTERACTION=SI1' "$deck" >"$work/outside.inp"
expect_error outside "belongs inside a \*STEP"
echo "deck_change_surface_behavior: ok"
