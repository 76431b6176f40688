#!/usr/bin/env bash
# Friction on the sphere (issue 39, docs/friction.md "At a/R = 0.015"): Cattaneo-Mindlin's
# figures at Q/(mu P) = 0.3, 0.6, 0.9 with Coulomb mu = 0.3 and large displacements, the half
# model of hertz3d with the normal load in --load-steps steps and Q in one. The default is the
# docs' case: R = 0.2 m with the cap and the block doubled (16.6 and 26.6 contact radii), 15
# cells across 2a (refinement 0.63, 80 331 DOFs), 16 load steps: about 150 s a run.
#
#   bench/friction3d.sh
#   bench/friction3d.sh --radius 0.1 --cap 0.025 --block 0.04 --refinement 0.794   # a/R 0.024
#   FETICON=build/feticon bench/friction3d.sh --refinement 0.3 --load-steps 2  # a quick look
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=${FETICON:-$root/build/feticon}
radius=0.2
cap=0.05
block=0.08
refinement=0.63
load_steps=16
while [[ $# -gt 0 ]]; do
  case $1 in
    --radius) radius=$2; shift 2 ;;
    --cap) cap=$2; shift 2 ;;
    --block) block=$2; shift 2 ;;
    --refinement) refinement=$2; shift 2 ;;
    --load-steps) load_steps=$2; shift 2 ;;
    *) echo "bench/friction3d.sh: unknown argument $1" >&2; exit 1 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
force=20000 # hertz3d.load, N on the whole sphere

echo "| Q/(mu P) | c computed / analytic (mm) | shear RMS / mu p0 | symmetric | antisymmetric | tangential reaction - Q | Hertz peak, a, RMS / p0 | MPRGP steps | wall |"
echo "|---|---|---|---|---|---|---|---|---|"
for ratio in 0.3 0.6 0.9; do
  q=$(/usr/bin/python3 -c "print($ratio * 0.3 * $force)")
  start=$(date +%s.%N)
  "$feticon" run --output "$work/cm" --overwrite --set problem=hertz3d --set "load_steps=$load_steps" \
    --set "hertz3d.radius=$radius" --set "hertz3d.cap_radius=$cap" --set "hertz3d.block_radius=$block" \
    --set "hertz3d.refinement=$refinement" --set contact.friction.model=coulomb \
    --set contact.friction.coefficient=0.3 --set "hertz3d.tangential_load=$q" > /dev/null 2>&1
  wall=$(/usr/bin/python3 -c "import time; print('%.0f' % (time.time() - $start))")
  /usr/bin/python3 - "$work/cm/summary.json" "$ratio" "$wall" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
h = s["hertz"]
f = h["friction"]
c, ca = f["stick_half_width_computed"], f["stick_half_width_analytic"]
print("| %s | %.3f / %.3f (%+.2f %%) | %.2f %% | %.2f %% | %.2f %% | %.1e Q | %+.2f %%, %+.2f %%, %.2f %% | %d | %s s |" % (
    sys.argv[2], 1e3 * c, 1e3 * ca, 100 * (c / ca - 1), 100 * f["shear_rms_error_over_mu_p0"],
    100 * f["shear_symmetric_rms_error_over_mu_p0"], 100 * f["shear_antisymmetric_rms_over_mu_p0"],
    f["tangential_reaction_error"], 100 * (h["p_peak_computed"] / h["p0_analytic"] - 1),
    100 * (h["a_computed"] / h["a_analytic"] - 1), 100 * h["rms_error_over_p0"], s["qp"]["iterations"], sys.argv[3]))
PY
done
