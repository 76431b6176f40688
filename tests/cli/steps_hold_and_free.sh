#!/usr/bin/env bash
# A step may hold other DOFs than the step before (issue 65, item 1; a deck's *BOUNDARY, OP=NEW):
# a block pressed on a base (large displacements, frictionless) by a prescribed u_z on its top
# (step 1), then held by a traction with the top free (step 2), then by u_z = -6 mm on the top
# again, the traction kept (step 3). References:
# 1. the ramp rule (CalculiX's spcmatch.f): a DOF held anew ramps from its displacement at the
#    step's start, so at step 3's first increment (of 2) every top node has u_z = (u_z at the end
#    of step 2 - 6 mm) / 2 (asserted 1e-15 m; measured 1.8e-16 with the QP at rtol 1e-12, which
#    meets the Dirichlet rows to round-off; 5.8e-9 m at the default 1e-8);
# 2. frictionless contact of elastic bodies does not depend on the path: steps 1-2 end at the
#    contact force of step 2's model alone, steps 1-3 at step 3's model alone (asserted 1e-6,
#    the outer tolerance);
# 3. the exported deck (*BOUNDARY, OP=NEW) gives the problem file's answer, and so do 2 MPI ranks.
# Usage: steps_hold_and_free.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export PYTHONPATH="$src/tests/tools"
settings=(--set output.plots=false --set qp.rtol=1e-12 --set qp.force_rtol=0) # Dirichlet rows met to round-off
model() { # model SUPPORTS... : the mesh, bodies and contact, then the given lines
  cat <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: base,  origin: [0, 0, 0],   lengths: [1, 1, 0.4], cells: [4, 4, 2]}
    - {name: block, origin: [0.3, 0.3, 0.4], lengths: [0.5, 0.5, 0.4], cells: [2, 2, 2]}
bodies:
  base:  {young: 1e8, poisson: 0.3}
  block: {young: 1e8, poisson: 0.3}
contact:
  - {slave: block_zmin, master: base_zmax}
subdomains: 4
displacements: large
YAML
  printf '%s\n' "$@"
}
held=("  - {set: base_zmin, x: 0, y: 0, z: 0}" "  - {set: block_xmin, x: 0}" "  - {set: block_ymin, y: 0}")
steps=("steps:" "  - increments: 2"
  "  - supports:" "${held[@]/#/    }" "    loads: [{set: block_zmax, traction: [0, 0, -2e5]}]" "    increments: 2")
model "supports:" "${held[@]}" "  - {set: block_zmax, z: -0.004}" "${steps[@]}" >"$work/two.yaml"
model "supports:" "${held[@]}" "  - {set: block_zmax, z: -0.004}" "${steps[@]}" "  - supports:" "${held[@]/#/    }" \
  "      - {set: block_zmax, z: -0.006}" "    increments: 2" >"$work/three.yaml"
model "supports:" "${held[@]}" "loads: [{set: block_zmax, traction: [0, 0, -2e5]}]" >"$work/pressed.yaml"
model "supports:" "${held[@]}" "  - {set: block_zmax, z: -0.006}" "loads: [{set: block_zmax, traction: [0, 0, -2e5]}]" \
  >"$work/held.yaml"
for run in two three pressed held; do
  "$feticon" run -q "$work/$run.yaml" --output "$work/$run" "${settings[@]}"
done
"$feticon" export "$work/three.yaml" --format calculix --output "$work/deck" >/dev/null
grep -q '^\*BOUNDARY, OP=NEW$' "$work/deck/feticon.inp"
"$feticon" run -q "$work/deck/feticon.inp" --output "$work/deckrun" "${settings[@]}" 2>/dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun --oversubscribe -np 2 "$feticon" run -q "$work/three.yaml" --output "$work/ranks" "${settings[@]}"
/usr/bin/python3 - "$work" <<'PY'
import json
import sys

import numpy
import read_vtu

work = sys.argv[1]
summary = {run: json.load(open(f"{work}/{run}/summary.json")) for run in ("two", "three", "pressed", "held", "deckrun", "ranks")}
assert all(s["converged"] for s in summary.values())
three = summary["three"]
assert [round(s["load_factor"], 12) for s in three["steps"]] == [0.5, 1, 1.5, 2, 2.5, 3], three["steps"]


def top_uz(path):
    arrays = read_vtu.point_data(path)
    u, top = arrays["displacement"], arrays["set_block_zmax"] > 0
    assert top.sum() == 9, top.sum()
    return u[top, 2]


start, half = top_uz(f"{work}/three/step_004.vtu"), top_uz(f"{work}/three/step_005.vtu")
assert numpy.abs(half - (start - 0.006) / 2).max() <= 1e-15, (start, half)
print(f"ramp: top u_z {start.mean():.6e} m at step 2's end, {half.mean():.6e} m halfway to -6e-3 m")
force = {run: s["contact"]["total_normal_force"] for run, s in summary.items()}
for path, alone in (("two", "pressed"), ("three", "held")):
    assert abs(force[path] / force[alone] - 1) <= 1e-6, (path, force[path], alone, force[alone])
for other in ("deckrun", "ranks"):
    assert abs(force[other] / force["three"] - 1) <= 1e-6, (other, force[other], force["three"])
print("contact forces:", {k: f"{v:.9g}" for k, v in force.items()})
PY
