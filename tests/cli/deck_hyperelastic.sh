#!/usr/bin/env bash
# *HYPERELASTIC, NEO HOOKE through a deck (issue 66, item 4): tests/data/calculix/rubber_block.inp,
# a rubber block compressed by 30 % by a platen 1e7 times stiffer through frictionless contact in 5
# increments; the *STEP has no NLGEOM, which the hyperelastic material turns on (CalculiX's rule).
# Reference: the closed form of the uniaxial series model (Neo-Hooke's principal Cauchy stress,
# lateral stress zero; the platen St Venant-Kirchhoff in uniaxial stress) at each increment, to
# 1e-5 of the force (measured 3e-9 to 7e-7). CalculiX 2.20 on the same deck (its penalty
# K = 2e16 Pa/m): -19.05328, -40.88730, -66.34075, -96.59566, -133.3609 N; feticon -19.05328,
# -40.88730, -66.34075, -96.59563, -133.3610 N. On 1 and 2 MPI ranks alike.
# Usage: deck_hyperelastic.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
export OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
deck="$src/tests/data/calculix/rubber_block.inp"
options=(--set output.plots=false --set output.vtu=false --set subdomains=2)
"$feticon" run "$deck" -o "$work/one" "${options[@]}" > "$work/one.log" 2>&1 || { cat "$work/one.log"; exit 1; }
grep -q "large displacements" "$work/one.log" || { echo "the hyperelastic deck did not run with large displacements"; exit 1; }
runs=(one)
if command -v mpirun > /dev/null; then
  timeout 300 mpirun --oversubscribe -np 2 "$feticon" run "$deck" -o "$work/two" "${options[@]}" \
    > "$work/two.log" 2>&1 || { cat "$work/two.log"; exit 1; }
  runs+=(two)
fi
/usr/bin/python3 - "$src" "$work" "${runs[@]}" <<'PY'
import math
import sys
src, work, *runs = sys.argv[1:]
sys.path.insert(0, src + "/tests/tools")
from calculix_dat import parse_dat

c10, d1 = 0.5e6, 4e-8           # the deck's *HYPERELASTIC, NEO HOOKE
steel, plate_h, plate_w = 2e13, 0.002, 0.014
block_h, block_w = 0.01, 0.01

def bisect(f, low, high):       # f increasing; 64 halvings reach round-off
    for _ in range(64):
        mid = 0.5 * (low + high)
        low, high = (low, mid) if f(mid) > 0 else (mid, high)
    return 0.5 * (low + high)

def cauchy(stretches):          # Neo-Hooke: 2 C10 / J dev(Bb) + 2 / D1 (J - 1) I, principal
    J = math.prod(stretches)
    b = [J ** (-2 / 3) * s * s for s in stretches]
    return [2 * c10 / J * (bi - sum(b) / 3) + 2 / d1 * (J - 1) for bi in b]

def nominal(l):                 # uniaxial stress: lateral stretch where sigma_yy = 0
    m = bisect(lambda m: cauchy([l, m, m])[1], 0.2, 5)
    return cauchy([l, m, m])[0] * m * m

def force(depth):               # compression positive
    def press(F):
        lb = bisect(lambda l: F + nominal(l) * block_w**2, 0.3, 1)
        lp = bisect(lambda l: F + l * steel * (l * l - 1) / 2 * plate_w**2, 0.9, 1)
        return block_h * (1 - lb) + plate_h * (1 - lp)
    return bisect(lambda F: press(F) - depth, 0, 1e4)

expected = [force(0.003 * k / 5) for k in range(1, 6)]
for run in runs:
    blocks = [b for b in parse_dat(f"{work}/{run}/rubber_block.dat")["blocks"]
              if b["kind"] == "total force" and b["set"] == "N_PLATEN_ZMAX"]
    fz = [-b["rows"][0][2] for b in blocks]
    assert len(fz) == 5, f"{run}: {len(fz)} increments, expected 5"
    for k, (f, e) in enumerate(zip(fz, expected)):
        print(f"{run} rank(s), increment {k + 1}: platen force {f:.7g} N, closed form {e:.7g} N ({(f - e) / expected[-1]:+.1e})")
        assert abs(f - e) <= 1e-5 * expected[-1], "the force is not the closed form's"
PY

# Bad input: one line naming file and line (or the body), non-zero exit.
source "$(dirname "$0")/../tools/expect_deck_error.sh" # expect_error NAME PATTERN
law='^5\.000000000000e+05, 4\.000000000000e-08$'
grep -q "$law" "$deck" || { echo "the deck's *HYPERELASTIC line changed"; exit 1; }
sed "s/$law/-5e5, 4e-8/" "$deck" >"$work/c10.inp"
expect_error c10 "c10.inp:82: \*HYPERELASTIC: material M_BLOCK: C10 = -500000 must be positive"
sed "s/$law/5e5, 0/" "$deck" >"$work/d1.inp"
expect_error d1 "D1 = 0 must be positive"
sed 's/^\*HYPERELASTIC, NEO HOOKE$/*HYPERELASTIC, OGDEN, N=1/' "$deck" >"$work/ogden.inp"
expect_error ogden "parameter OGDEN is not implemented"
sed 's/^\*HYPERELASTIC, NEO HOOKE$/*HYPERELASTIC, POLYNOMIAL, N=2/' "$deck" >"$work/n2.inp"
expect_error n2 "N=2 is not implemented"
sed 's/^\*HYPERELASTIC, NEO HOOKE$/*ELASTIC\n1e6, 0.45\n*HYPERELASTIC, NEO HOOKE/' "$deck" >"$work/both.inp"
expect_error both "has \*ELASTIC or \*HYPERELASTIC already"
sed "s/$law/5e5, 4e-8\n*PLASTIC\n1e5, 0/" "$deck" >"$work/plastic.inp"
expect_error plastic "plasticity of a hyperelastic material is not implemented"
if "$feticon" run -q "$deck" --output "$work/small" --set displacements=small >"$work/small.log" 2>&1; then
  echo "small: the run did not fail"; exit 1
fi
grep -q "body 'B_BLOCK' is hyperelastic, which needs large displacements" "$work/small.log" \
  || { cat "$work/small.log"; exit 1; }
echo "bad input: seven one-line errors"
echo "deck_hyperelastic: ok"
