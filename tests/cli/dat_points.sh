#!/usr/bin/env bash
# *EL PRINT S at CalculiX's integration points for every cell type whose points feticon's rules
# have (app/calculix_results.cpp, dat_points): the points of each element, as many and in the
# order CalculiX prints them, 2D cells as the 3D elements CalculiX expands them into.
# References: CalculiX's own .dat.ref (ccx 2.11) of planestrain (CPE4: C3D8's 8 points) and
# planestrain2 (CPE8: C3D20's 27), printed stresses to 1e-9 of the largest (measured 8e-11,
# 2e-12); contact3 (C3D8, contact.law=deck) to 1e-7 (measured 9e-9); plate (CPS8R: C3D20R's 8,
# contact.law=deck) to 5e-3 (measured 2.4e-3: CalculiX's expanded plane stress element has
# szz 9e-3 and the deck's penalty contact). Every point of every element is compared, so a
# wrong order, count or component fails.
# And the reactions of an axisymmetric model per 2-degree wedge, as CalculiX prints them (below).
# Usage: dat_points.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
data="$src/tests/data/calculix"

for case in "planestrain 1e-9" "planestrain2 1e-9" "contact3 1e-7 --set contact.law=deck" \
  "plate 5e-3 --set contact.law=deck"; do
  read -r deck bound options <<< "$case"
  # shellcheck disable=SC2086
  "$feticon" run "$data/$deck.inp" -o "$work/$deck" -q --set output.plots=false $options 2> /dev/null
  /usr/bin/python3 - "$data/$deck.dat.ref" "$work/$deck/$deck.dat" "$bound" "$src/tests/tools" <<'PY'
import sys
reference, mine, bound = sys.argv[1], sys.argv[2], float(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from calculix_dat import parse_dat

def points(path):
    blocks = [b for b in parse_dat(path)["blocks"] if b["kind"].startswith("stresses")]
    assert blocks, f"{path}: no stresses printed"
    return {(row[0], row[1]): row[2:] for row in blocks[-1]["rows"]}

ref, got = points(reference), points(mine)
assert set(ref) == set(got), f"points differ: {sorted(set(ref) ^ set(got))[:5]}"
scale = max(max(abs(v) for v in values) for values in ref.values())
diff = max(max(abs(a - b) for a, b in zip(got[k], ref[k])) for k in ref)
print(f"{reference.split('/')[-1]}: {len(ref)} points, stresses within {diff / scale:.2g} of the largest (bound {bound:g})")
sys.exit(0 if diff <= bound * scale else 1)
PY
done

# An axisymmetric model's reactions in the .dat are CalculiX's, those of the 2-degree wedge it
# expands CAX cells into: 1/180 of the full circle. tests/data/calculix/cax_ring.inp is a ring
# in uniaxial stress, so its held face carries E eps pi (r_o^2 - r_i^2) = 1.8849556e8 N on the
# full circle (closed form; linear cells reproduce it), 1.0471976e6 N printed, to the printed
# 7 digits. CalculiX 2.20 prints 1.046985e6 on the same deck (2.0e-4 lower: its wedge's
# discretization; 2026-12-04).
"$feticon" run "$data/cax_ring.inp" -o "$work/cax_ring" -q --set output.plots=false 2> /dev/null
/usr/bin/python3 - "$work/cax_ring/cax_ring.dat" "$src/tests/tools" <<'PY'
import math, sys
sys.path.insert(0, sys.argv[2])
from calculix_dat import parse_dat
totals = [b for b in parse_dat(sys.argv[1])["blocks"] if b["kind"] == "total force"]
printed = totals[-1]["rows"][0][1]
sector = 2e11 * 1e-4 * math.pi * (2 ** 2 - 1 ** 2) / 180
print(f"cax_ring.dat: total reaction {printed:.7e} N, the closed form's 2-degree wedge {sector:.7e} N")
sys.exit(0 if abs(printed / sector - 1) <= 5e-7 else 1)
PY
