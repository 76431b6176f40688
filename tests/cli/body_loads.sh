#!/usr/bin/env bash
# A block resting on another under its own weight (issue 65, item 5): gravity is the only load
# of the upper block, so the contact must carry its weight, rho g V = 7850 * 9.81 * 0.125 N
# (reference: the load itself; the FETI solve conserves it to the solver's tolerance). Small
# and large displacements (dead load on the reference configuration).
# Usage: body_loads.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat >"$work/problem.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: base,  origin: [0, 0, -0.5], lengths: [1.0, 1.0, 0.5], cells: [6, 6, 3]}
    - {name: block, origin: [0, 0, 0],    lengths: [0.5, 0.5, 0.5], cells: [4, 4, 4]}
bodies:
  base:  {young: 2e11, poisson: 0.3, density: 7850}
  block: {young: 2e11, poisson: 0.3, density: 7850}
supports:
  - {set: base_zmin, x: 0, y: 0, z: 0}
  - {set: block_xmin, x: 0}            # symmetry planes: the block cannot slide or turn
  - {set: block_ymin, y: 0}
  - {set: base_xmin, x: 0}
  - {set: base_ymin, y: 0}
loads:
  - {gravity: [0, 0, -9.81], body: block}
contact:
  - {slave: block_zmin, master: base_zmax}
subdomains: 4
qp.rtol: 1e-10
YAML
for displacements in small large; do
  "$feticon" run -q "$work/problem.yaml" --output "$work/$displacements" --set displacements=$displacements \
    --set output.plots=false
  /usr/bin/python3 - "$work/$displacements/summary.json" "$displacements" <<'PY'
import json
import sys

s = json.load(open(sys.argv[1]))
weight = 7850 * 9.81 * 0.5 ** 3
force = s["contact"]["total_normal_force"]
assert s["converged"], s.get("reason")
assert abs(force / weight - 1) < 1e-6, (sys.argv[2], force, weight)
print(f"{sys.argv[2]} displacements: contact force {force:.9g} N, weight {weight:.9g} N")
PY
done
# Bad input: a body load on a body without density names the load.
sed 's/block: {young: 2e11, poisson: 0.3, density: 7850}/block: {young: 2e11, poisson: 0.3}/' \
  "$work/problem.yaml" >"$work/no_density.yaml"
if "$feticon" run -q "$work/no_density.yaml" --output "$work/bad" 2>"$work/err.txt"; then
  echo "a gravity load without density ran"
  exit 1
fi
grep -q "loads.0: body block has no density" "$work/err.txt"
# The same model as a CalculiX deck with *DENSITY and *DLOAD GRAV (feticon export writes the
# mesh, supports and pair; the export shifts the floating block 2.5 mm into the base, which the
# contact pushes back): the contact carries the weight again. CalculiX 2.20 on this deck: the
# reaction of base_zmin is 9.626063E+03 N.
sed '/^loads:/,/gravity/d' "$work/problem.yaml" >"$work/unloaded.yaml"
"$feticon" export "$work/unloaded.yaml" --format calculix --output "$work/deck" >/dev/null
/usr/bin/python3 - "$work/deck/feticon.inp" "$work/grav.inp" "$work/grav_no_density.inp" <<'PY'
import sys

lines = open(sys.argv[1]).read().split("\n")
with_density, without = [], []
i = 0
while i < len(lines):
    line = lines[i]
    if line.startswith("*ELASTIC"):
        with_density += [line, lines[i + 1], "*DENSITY", "7850."]
        without += [line, lines[i + 1]]
        i += 2
        continue
    if line.startswith("*CLOAD"):
        line = "*DLOAD\nB_block, GRAV, 9.81, 0., 0., -1."
    with_density.append(line)
    without.append(line)
    i += 1
open(sys.argv[2], "w").write("\n".join(with_density))
open(sys.argv[3], "w").write("\n".join(without))
PY
"$feticon" run -q "$work/grav.inp" --output "$work/grav" --set output.plots=false 2>/dev/null
/usr/bin/python3 - "$work/grav/summary.json" <<'PY'
import json
import sys

s = json.load(open(sys.argv[1]))
weight = 7850 * 9.81 * 0.5 ** 3
force = s["contact"]["total_normal_force"]
assert s["converged"] and abs(force / weight - 1) < 1e-6, (force, weight)
print(f"deck with *DLOAD GRAV: contact force {force:.9g} N, weight {weight:.9g} N")
PY
if "$feticon" run -q "$work/grav_no_density.inp" --output "$work/bad_deck" 2>"$work/err.txt"; then
  echo "a deck's GRAV without *DENSITY ran"
  exit 1
fi
grep -q "\*DLOAD GRAV: body .* has no density" "$work/err.txt"
echo "body loads: the contact carries the block's weight"
