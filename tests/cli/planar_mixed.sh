#!/usr/bin/env bash
# Decks mixing 2D formulations (issue 64): CPS / CPE cells beside CAX cells, each body its own
# formulation, a plane section's thickness per full circle as CalculiX's solidsections.f has it.
# 1. a CPS4 plate (thickness 0.01 m) and a CAX4 ring (1 <= r <= 2 m) in one deck, apart, each
#    pulled by an edge pressure sigma = 1e8 Pa (nu = 0.3): the plate's top u_y = sigma L / E and
#    its width's contraction nu sigma w / E (plane stress), the ring's u_y = sigma h / E and
#    u_r = -nu sigma r / E (uniaxial), to 1e-9; the .dat's total reaction is that of both for
#    1/180 of the full circle (CalculiX prints a model with CAX cells so):
#    sigma (w t + pi (2^2 - 1^2)) / 180 to the .dat's 7 digits; `feticon export` writes the CPS4 and CAX4 blocks again
#    and the deck it writes gives the same displacements;
# 2. CalculiX's `bolt` (tests/data/calculix/bolt.inp: a CPS8R bolt, thickness 110.4584, through
#    two CAX8R plates, three NODE TO SURFACE pairs of node surfaces, an EXPONENTIAL law, NLGEOM)
#    with its own law (contact.law=deck, the master face's area for the nodes of its node
#    surfaces, as CalculiX): within 5e-3 of max |u| of CalculiX's bolt.dat.ref (measured
#    2.7e-3); with hard contact it runs and converges; on 2 MPI ranks the same displacements as
#    on 1 to 1e-8 of max |u|.
# Usage: planar_mixed.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3

# ---- 1. a plane-stress plate and an axisymmetric ring in one deck ----------------------------
cat >"$work/mixed.inp" <<'DECK'
*NODE, NSET=NALL
1, 3, 0, 0
2, 3.5, 0, 0
3, 4, 0, 0
4, 3, 1, 0
5, 3.5, 1, 0
6, 4, 1, 0
11, 1, 0, 0
12, 1.5, 0, 0
13, 2, 0, 0
14, 1, 1, 0
15, 1.5, 1, 0
16, 2, 1, 0
*ELEMENT, TYPE=CPS4, ELSET=PLATE
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*ELEMENT, TYPE=CAX4, ELSET=RING
11, 11, 12, 15, 14
12, 12, 13, 16, 15
*NSET, NSET=BOTTOM
1, 2, 3, 11, 12, 13
*MATERIAL, NAME=STEEL
*ELASTIC
2e11, 0.3
*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL
0.01
*SOLID SECTION, ELSET=RING, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
BOTTOM, 2, 2, 0
1, 1, 1, 0
*DLOAD
1, P3, -1e8
2, P3, -1e8
11, P3, -1e8
12, P3, -1e8
*NODE PRINT, NSET=NALL
U
*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY
RF
*END STEP
DECK
"$feticon" run "$work/mixed.inp" --output "$work/mixed" >"$work/mixed.log" 2>&1 || { cat "$work/mixed.log"; exit 1; }
check_mixed() { # DAT
  "$py" - "$1" <<'PY'
import math, sys
text = open(sys.argv[1]).read().split("\n")
u = {int(l.split()[0]): [float(v) for v in l.split()[1:]] for l in text
     if l.strip() and l.split()[0].isdigit() and len(l.split()) == 4}
E, nu, sigma = 2e11, 0.3, 1e8
checks = [("plate top u_y", u[5][1], sigma * 1 / E), ("plate width's contraction", u[3][0], -nu * sigma * 1 / E),
          ("ring top u_y", u[15][1], sigma * 1 / E), ("ring u_r at r = 2", u[16][0], -nu * sigma * 2 / E),
          ("ring u_r at r = 1", u[11][0], -nu * sigma * 1 / E)]
for name, got, want in checks:
    print(f"{name}: {got:.9e} m, closed form {want:.9e} m")
    assert abs(got / want - 1) < 1e-9, name + " off the closed form"
total = [l for l in text if l.strip() and not l.split()[0].isdigit() and "e" in l.lower() and len(l.split()) == 3]
ry = float(total[-1].split()[1])
want = sigma * (1 * 0.01 + math.pi * (2 ** 2 - 1 ** 2)) / 180
print(f"total reaction {ry:.9e} N, sigma (w t + pi (b^2 - a^2)) / 180 = {want:.9e} N")
assert abs(-ry / want - 1) < 2e-7, "reaction off the closed form (the .dat prints 7 digits)"
PY
}
check_mixed "$work/mixed/mixed.dat"
"$feticon" export "$work/mixed.inp" --format calculix --output "$work/export" >"$work/export.log" 2>&1 ||
  { cat "$work/export.log"; exit 1; }
grep -q "TYPE=CPS4" "$work/export/feticon.inp" && grep -q "TYPE=CAX4" "$work/export/feticon.inp" ||
  { echo "the export lost a formulation"; grep "^\*ELEMENT" "$work/export/feticon.inp"; exit 1; }
"$feticon" run "$work/export/feticon.inp" --output "$work/exported" >"$work/exported.log" 2>&1 ||
  { cat "$work/exported.log"; exit 1; }
"$py" "$source_dir/tests/tools/compare_runs.py" 1e-9 "$work/mixed" "$work/exported"

# ---- 2. CalculiX's bolt -----------------------------------------------------------------------
deck="$source_dir/tests/data/calculix/bolt.inp"
for law in deck hard; do
  "$feticon" run "$deck" --output "$work/bolt_$law" --set contact.law=$law --set output.plots=false \
    >"$work/bolt_$law.log" 2>&1 || { cat "$work/bolt_$law.log"; exit 1; }
  "$py" -c "import json, sys; assert json.load(open(sys.argv[1]))['converged'], 'bolt ($law) not converged'" \
    "$work/bolt_$law/summary.json"
done
"$py" "$source_dir/tests/tools/calculix_reference_agreement.py" "$deck" "$source_dir/tests/data/calculix/bolt.dat.ref" \
  "$work/bolt_deck" | "$py" -c "import json, sys
f = json.load(sys.stdin)
print(f'bolt, contact.law=deck: max |u - u_ref| / max |u_ref| = {f[\"relative\"]:.3e} over {f[\"nodes\"]} nodes')
assert f['nodes'] == 1203 and f['relative'] < 5e-3, 'bolt off CalculiX'"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
mpirun --oversubscribe -np 2 "$feticon" run "$deck" --output "$work/bolt_mpi" --set contact.law=deck \
  --set output.plots=false >"$work/bolt_mpi.log" 2>&1 || { cat "$work/bolt_mpi.log"; exit 1; }
"$py" "$source_dir/tests/tools/compare_runs.py" 1e-8 "$work/bolt_deck" "$work/bolt_mpi"
# feticon export keeps bolt's node surfaces (TYPE=NODE: the law on the master face's area there);
# the exported deck's run is the deck's to 2e-3 of max |u| (measured 4.0e-4, the outer loop's
# tolerance: 5e-10 with tolerances of 1e-10; written as element faces they were 3.2e-2 apart).
"$feticon" export "$deck" --format calculix --overclosure 0 -o "$work/bolt_export" >/dev/null
[ "$(grep -c '^\*SURFACE, NAME=S_[A-Z]*, TYPE=NODE$' "$work/bolt_export/feticon.inp")" -eq 3 ]
"$feticon" run "$work/bolt_export/feticon.inp" --output "$work/bolt_exported" --set contact.law=deck \
  --set output.plots=false >"$work/bolt_exported.log" 2>&1 || { cat "$work/bolt_exported.log"; exit 1; }
"$py" - "$work/bolt_deck" "$work/bolt_exported" "$source_dir/tests/tools" <<'PY'
import glob
import sys

import numpy

sys.path.insert(0, sys.argv[3])
import read_vtu

a, b = (read_vtu.point_data(sorted(glob.glob(d + "/step_*.vtu"))[-1])["displacement"] for d in sys.argv[1:3])
difference = numpy.abs(a - b).max() / numpy.abs(a).max()
print(f"bolt exported and run again: {difference:.2g} of max |u| from the deck's run")
assert difference < 2e-3, "the exported bolt is another model"
PY
echo "planar_mixed: ok"
