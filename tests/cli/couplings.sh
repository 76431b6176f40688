#!/usr/bin/env bash
# Reference nodes and couplings (issue 63, item 5; fem/coupling.hpp): *COUPLING with *KINEMATIC
# or *DISTRIBUTING, *RIGID BODY, *DISTRIBUTING COUPLING.
# References:
#  - Closed form (tests/tools/coupled_cantilever_deck.py): a 1 x 1 x 10 m bar of ten C3D20 cells,
#    E = 1e9 Pa, nu = 0, clamped at x = 0, its end face coupled to a reference node at the face's
#    centre. A moment M = 1e4 N m about y (a *KINEMATIC coupling's DOF 5, a *RIGID BODY's ROT
#    NODE DOF 2): beam theory's end rotation M L / (E I) = 1.2e-3 rad and deflection
#    -M L^2 / (2 E I) = -6e-3 m, which C3D20 holds exactly with nu = 0 (pure bending has a
#    quadratic displacement and no anticlastic curvature): to 1e-6 (solver tolerance; measured
#    1.7e-8); the reference node's printed RF is the moment. An axial force F = 1e6 N spread by a
#    *DISTRIBUTING coupling (consistent nodal areas): the end face's u_x = F L / (E A) = 1e-2 m,
#    uniform, to 1e-6. The kinematic bar on 2 MPI ranks with 4 subdomains: the same rotation.
#    Finite rotations: the *RIGID BODY end turned 30 degrees under NLGEOM keeps its face rigid and
#    gives CalculiX 2.20's answer on the same deck (below).
#  - CalculiX's own output (tests/data/calculix, calculix-ccx-test 2.11): beamprb (a *RIGID BODY
#    tip of a C3D20R cantilever under a moment on its ROT NODE) against beamprb.frd.ref, every
#    node, to 1e-5 of max |u| (the .frd's six digits; measured 5.4e-7); distcoup (a *DISTRIBUTING
#    COUPLING spreading a force over nine nodes) against distcoup.dat.ref's reactions of the
#    clamped nodes to 1e-5 of the largest (measured 2.2e-6); beamrb (the tip turned 10 degrees
#    under NLGEOM) against beamrb.dat.ref, reference nodes included, to 1e-6 (measured 1.1e-7).
#  - A problem file's couplings (hex8 bar, nu = 0: uniaxial fields exact): a kinematic coupling
#    holding the end face's reference translation at 1e-3 m transmits E A u / L = 1e5 N to 1e-6
#    (measured 3e-8); a distributing force F gives the end face F L / (E A) to 1e-6.
#  - Bad input, one line each: *COUPLING without *KINEMATIC or *DISTRIBUTING, an unknown surface,
#    a node surface of no element's node,
#    a ROT NODE that an element uses, a node that is the reference node of two couplings, a moment
#    on a solid node, a moment a *KINEMATIC coupling of one direction cannot carry, a *DISTRIBUTING
#    COUPLING set without a DCOUP3D element, ORIENTATION=; in problem files an unknown coupling or
#    kind, no reference point, both surface and nodes, a rotation of 1e300 rad.
#  - feticon export of distcoup's mean coupling, run again: distcoup's answer (at the end).
# Usage: couplings.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
quiet=(-q --set output.plots=false)
data="$src/tests/data/calculix"
deck() { /usr/bin/python3 "$src/tests/tools/coupled_cantilever_deck.py" "$work/$1.inp" "$1"; }

# check FOLDER EXPRESSION BOUND LABEL: |EXPRESSION| <= BOUND, EXPRESSION over summary.json's s.
check() {
  /usr/bin/python3 - "$1/summary.json" "$2" "$3" "$4" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
c = s["couplings"][0]
error = abs(eval(sys.argv[2]))
print(f"{sys.argv[4]}: {error:.3g} (bound {sys.argv[3]})")
sys.exit(0 if error <= float(sys.argv[3]) else 1)
PY
}
EI=$(/usr/bin/python3 -c 'print(1e9 / 12)')

for kind in kinematic-moment rigid-moment; do
  deck $kind
  "$feticon" run "$work/$kind.inp" -o "$work/$kind" "${quiet[@]}" 2> /dev/null
  check "$work/$kind" "c['rotation'][1] / (1e4 * 10 / $EI) - 1" 1e-6 "$kind: end rotation vs M L / (E I)"
  check "$work/$kind" "c['displacement'][2] / (-1e4 * 100 / (2 * $EI)) - 1" 1e-6 "$kind: deflection vs -M L^2 / (2 E I)"
  check "$work/$kind" "c['moment'][1] / 1e4 - 1" 1e-9 "$kind: the reference node's moment vs M"
done
# The .dat prints the reference node (and the ROT NODE's rotation) as CalculiX does.
grep -q "^     10001 .* 1.200000E-03 " "$work/rigid-moment/rigid-moment.dat"
grep -q "^     10001 .* 1.000000E+04 " "$work/rigid-moment/rigid-moment.dat"

# Finite rotations: the rigid end turned 30 degrees about y under NLGEOM (ten increments). The
# end face stays rigid (every distance between its nodes to 5e-6, the .dat's digits; linear rows
# would stretch it by theta^2 / 2 = 0.137) and the reference node's
# displacement and moment are CalculiX 2.20's on the same deck (-4.539797e-01, -2.557848e+00 m,
# 4.358234e+06 N m, 2026-12-03) to 1e-6 (its seven digits; measured 1.3e-8); the arc of beam
# theory, L (sin t / t - 1) = -0.4507 and -L (1 - cos t) / t = -2.5587, to 1 %.
deck rigid-rotation
"$feticon" run "$work/rigid-rotation.inp" -o "$work/rotation" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 - "$work/rotation/rigid-rotation.dat" "$work/rigid-rotation.inp" "$src/tests/tools" <<'PY'
import itertools, math, sys
sys.path.insert(0, sys.argv[3])
from calculix_dat import parse_dat
blocks = parse_dat(sys.argv[1])["blocks"]
last = lambda kind, name: [b for b in blocks if b["kind"] == kind and b["set"] == name][-1]["rows"]
ref = {r[0]: r[1:] for r in last("displacements", "REF")}
moment = {r[0]: r[1:] for r in last("forces", "REF")}[10001][1]
theta = math.radians(30)
assert abs(ref[10001][1] - theta) <= 1e-7, ref[10001]  # the .dat's seven digits
checks = [("u_x", ref[10000][0], -4.539797e-01), ("u_z", ref[10000][2], -2.557848e+00), ("moment", moment, 4.358234e+06)]
for name, mine, ccx in checks:
    print(f"rigid-rotation: reference {name} {mine:.7e} against CalculiX's {ccx:.7e}")
    assert abs(mine / ccx - 1) <= 1e-6, name
arc = (10 * (math.sin(theta) / theta - 1), -10 * (1 - math.cos(theta)) / theta)
assert abs(ref[10000][0] / arc[0] - 1) <= 1e-2 and abs(ref[10000][2] / arc[1] - 1) <= 1e-2, arc
nodes, reading = {}, False
for line in open(sys.argv[2]):
    if line.startswith("*"):
        reading = line.upper().startswith("*NODE") and "PRINT" not in line.upper()
        continue
    if reading:
        f = line.split(",")
        nodes[int(f[0])] = [float(v) for v in f[1:4]]
end = {r[0]: [x + u for x, u in zip(nodes[r[0]], r[1:])] for r in last("displacements", "END")}
change = max(abs(math.dist(end[a], end[b]) / math.dist(nodes[a], nodes[b]) - 1)
             for a, b in itertools.combinations(end, 2))
# The .dat's seven digits: 5e-7 m on a coordinate, on distances of 0.5 m at least.
print(f"rigid-rotation: the end face's distances change by {change:.2g} (bound 5e-6; linear rows: 0.137)")
assert change <= 5e-6
PY

# ... and the same MPRGP steps and answer with 4 subdomains on 1 and 2 MPI ranks.
for np in 1 2; do
  mpirun --oversubscribe -np $np "$feticon" run "$work/rigid-rotation.inp" -o "$work/rotation_np$np" "${quiet[@]}" \
    --set subdomains=4 2> /dev/null
done
/usr/bin/python3 - "$work/rotation_np1/summary.json" "$work/rotation_np2/summary.json" <<'PY'
import json, sys
one, two = (json.load(open(p)) for p in sys.argv[1:])
print(f"rigid-rotation, 4 subdomains: {one['qp']['iterations']} and {two['qp']['iterations']} MPRGP steps on 1 and 2 ranks")
assert one["qp"]["iterations"] == two["qp"]["iterations"]
assert one["couplings"] == two["couplings"]
PY

mpirun --oversubscribe -np 2 "$feticon" run "$work/kinematic-moment.inp" -o "$work/mpi" "${quiet[@]}" \
  --set subdomains=4 2> /dev/null
check "$work/mpi" "c['rotation'][1] / (1e4 * 10 / $EI) - 1" 1e-6 "2 ranks, 4 subdomains: end rotation"

deck distributing-force
"$feticon" run "$work/distributing-force.inp" -o "$work/distributing" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 - "$work/distributing/distributing-force.dat" "$src/tests/tools" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from calculix_dat import parse_dat
block = [b for b in parse_dat(sys.argv[1])["blocks"] if b["kind"] == "displacements" and b["set"] == "END"][-1]
error = max(abs(row[1] / 1e-2 - 1) for row in block["rows"])
print(f"distributing force: end face u_x vs F L / (E A): {error:.3g} (bound 1e-6)")
sys.exit(0 if error <= 1e-6 else 1)
PY

"$feticon" run "$data/beamprb.inp" -o "$work/beamprb" "${quiet[@]}" 2> /dev/null
source "$src/tests/tools/expect_agreement.sh"
agreement "$data/beamprb.inp" "$data/beamprb.frd.ref" "$work/beamprb" 1e-5 within 261
# beamrb: the *RIGID BODY tip turned 10 degrees about z by its ROT NODE under NLGEOM (finite
# rotations): CalculiX's .dat.ref, every node and the reference nodes, to 1e-6 (measured 1.1e-7).
"$feticon" run "$data/beamrb.inp" -o "$work/beamrb" "${quiet[@]}" 2> /dev/null
agreement "$data/beamrb.inp" "$data/beamrb.dat.ref" "$work/beamrb" 1e-6 within 263
"$feticon" run "$data/distcoup.inp" -o "$work/distcoup" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 - "$work/distcoup/distcoup.dat" "$data/distcoup.dat.ref" "$src/tests/tools" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from calculix_dat import parse_dat
mine, ref = ({r[0]: r[1:] for r in parse_dat(p)["blocks"][0]["rows"]} for p in sys.argv[1:3])
scale = max(abs(v) for row in ref.values() for v in row)
error = max(abs(a - b) for n in ref for a, b in zip(mine[n], ref[n])) / scale
print(f"distcoup: reactions {error:.3g} of the largest from CalculiX's .dat.ref (bound 1e-5)")
sys.exit(0 if error <= 1e-5 and len(mine) == len(ref) == 21 else 1)
PY

# A problem file's couplings: a 10 x 1 x 1 m hex8 bar (E = 1e9 Pa, nu = 0: uniaxial fields are
# exact) whose end face a kinematic coupling pulls by a held reference translation of 1e-3 m:
# the reference node's force E A u / L = 1e5 N to 1e-6; a distributing coupling's force 1e5 N:
# the end face's u_x = F L / (E A) = 1e-3 m to 1e-6.
cat > "$work/bar.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: bar, origin: [0, 0, 0], lengths: [10, 1, 1], cells: [10, 2, 2]}
bodies:
  bar: {young: 1e9, poisson: 0}
couplings:
  - {name: tip, kind: kinematic, surface: bar_xmax, reference: [10, 0.5, 0.5]}
supports:
  - {set: bar_xmin, x: 0, y: 0, z: 0}
  - {coupling: tip, x: 1e-3}
displacements: small
YAML
"$feticon" run "$work/bar.yaml" -o "$work/yaml_kinematic" "${quiet[@]}" 2> /dev/null
check "$work/yaml_kinematic" "c['force'][0] / 1e5 - 1" 1e-6 "problem file, kinematic: force vs E A u / L"
sed -e 's/kind: kinematic, surface/kind: distributing, surface/' -e '/coupling: tip, x:/d' "$work/bar.yaml" \
  > "$work/bar_distributing.yaml"
printf 'loads:\n  - {coupling: tip, force: [1e5, 0, 0]}\n' >> "$work/bar_distributing.yaml"
"$feticon" run "$work/bar_distributing.yaml" -o "$work/yaml_distributing" "${quiet[@]}" 2> /dev/null
/usr/bin/python3 - "$work/yaml_distributing/step_001.vtu" "$src/tests/tools" <<'PY'
import sys
import numpy
sys.path.insert(0, sys.argv[2])
import read_vtu
arrays = read_vtu.point_data(sys.argv[1])
u, end = arrays["displacement"], arrays["set_bar_xmax"] > 0
error = numpy.abs(u[end, 0] / 1e-3 - 1).max()
print(f"problem file, distributing: end face u_x vs F L / (E A): {error:.3g} (bound 1e-6, {end.sum()} nodes)")
sys.exit(0 if error <= 1e-6 and end.sum() == 9 else 1)
PY

# Plane strain: a 10 x 1 CPE4 strip (20 x 2 cells, nu = 0) clamped at x = 0, its end a *RIGID
# BODY (rank 3 in the plane) under a moment of 1e3 N m on the ROT NODE's DOF 3: the end rotation
# and the reference node's u_y of CalculiX 2.20 on the same deck (1.066667e-4 rad, 5.333333e-4 m,
# 2026-12-03; CPE4's shear locking leaves beam theory's 1.2e-4 rad 11 % away) to 1e-6.
/usr/bin/python3 - "$work/strip.inp" <<'PY'
import sys
nx, ny = 20, 2
label = lambda i, j: j * (nx + 1) + i + 1
lines = ["*NODE"] + [f"{label(i, j)}, {i * 0.5}, {j * 0.5}, 0.0" for j in range(ny + 1) for i in range(nx + 1)]
lines += ["10000, 10.0, 0.5, 0.0", "10001, 0, 0, 0", "*ELEMENT, TYPE=CPE4, ELSET=EALL"]
cells = [(i, j) for j in range(ny) for i in range(nx)]
lines += [f"{e + 1}, {label(i, j)}, {label(i + 1, j)}, {label(i + 1, j + 1)}, {label(i, j + 1)}" for e, (i, j) in enumerate(cells)]
lines += ["*NSET, NSET=CLAMP"] + [str(label(0, j)) for j in range(ny + 1)]
lines += ["*NSET, NSET=END"] + [str(label(nx, j)) for j in range(ny + 1)] + ["*NSET, NSET=REF", "10000, 10001"]
lines += ["*MATERIAL, NAME=M", "*ELASTIC", "1e9, 0.0", "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "1.0", "*BOUNDARY",
          "CLAMP, 1, 2", "*RIGID BODY, NSET=END, REF NODE=10000, ROT NODE=10001", "*STEP", "*STATIC", "*CLOAD",
          "10001, 3, 1000.", "*NODE PRINT, NSET=REF", "U, RF", "*END STEP"]
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
PY
"$feticon" run "$work/strip.inp" -o "$work/strip" "${quiet[@]}" 2> /dev/null
check "$work/strip" "c['rotation'][2] / 1.066667e-4 - 1" 1e-6 "plane strain rigid body: end rotation vs CalculiX's"
check "$work/strip" "c['displacement'][1] / 5.333333e-4 - 1" 1e-6 "plane strain rigid body: u_y vs CalculiX's"

# feticon export writes the couplings (reference nodes, *COUPLING with *KINEMATIC or
# *DISTRIBUTING, their supports and loads on DOFs 1-6): a hex8 bar (nu = 0.3) whose end a
# kinematic coupling loads by a force and a moment and whose side a distributing coupling loads
# by a force and a moment, then in a second step the end's reference translation and rotation
# held. The exported deck's run gives the problem file's reference motions and forces to 1e-9
# (the same model: measured 0 apart at qp.rtol 1e-12), and CalculiX 2.20's printed U of the end's
# reference node on that deck agrees with feticon's to 1e-5 of its largest component (its six
# digits).
cat > "$work/exported.yaml" <<'YAML'
problem: custom
mesh:
  boxes:
    - {name: bar, origin: [0, 0, 0], lengths: [10, 1, 1], cells: [20, 2, 2]}
bodies:
  bar: {young: 1e9, poisson: 0.3}
couplings:
  - {name: tip, kind: kinematic, surface: bar_xmax, reference: [10, 0.5, 0.5]}
  - {name: side, kind: distributing, surface: bar_ymax, reference: [5, 1, 0.5], moments: [x, y, z]}
steps:
  - supports: [{set: bar_xmin, x: 0, y: 0, z: 0}]
    loads: [{coupling: tip, moment: [0, 1e4, 0], force: [0, 0, 1e3]}, {coupling: side, force: [0, 2e3, 0], moment: [1e3, 0, 0]}]
  - supports: [{set: bar_xmin, x: 0, y: 0, z: 0}, {coupling: tip, x: 2e-3, ry: 1e-4}]
    loads: [{coupling: side, force: [0, -1e3, 0]}]
displacements: small
YAML
tight=(--set qp.rtol=1e-12 --set qp.force_rtol=0)
"$feticon" run "$work/exported.yaml" -o "$work/exported_yaml" "${quiet[@]}" "${tight[@]}" 2> /dev/null
"$feticon" export "$work/exported.yaml" --format calculix -o "$work/exported" > /dev/null
grep -q '^\*COUPLING, REF NODE=190, SURFACE=COUPLING_1' "$work/exported/feticon.inp"
grep -q '^\*DISTRIBUTING' "$work/exported/feticon.inp"
"$feticon" run "$work/exported/feticon.inp" -o "$work/exported_deck" "${quiet[@]}" "${tight[@]}" 2> /dev/null
/usr/bin/python3 - "$work/exported_yaml/summary.json" "$work/exported_deck/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(f))["couplings"] for f in sys.argv[1:3])
values = lambda cs: [v for c in cs for key in ("displacement", "rotation", "force", "moment") for v in c[key]]
scale = max(abs(v) for v in values(a))
difference = max(abs(x - y) for x, y in zip(values(a), values(b))) / scale
print(f"export: the deck's reference motions and forces vs the problem file's: {difference:.2g} (bound 1e-9)")
sys.exit(0 if len(a) == len(b) == 2 and difference <= 1e-9 else 1)
PY
if command -v ccx > /dev/null; then
  (cd "$work/exported" && ccx -i feticon > ccx.log 2>&1)
  /usr/bin/python3 - "$work/exported/feticon.dat" "$work/exported_deck/feticon.dat" "$src/tests/tools" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from calculix_dat import parse_dat
def tip(path):  # the end's reference node (190) in each step's displacement block
    blocks = [b for b in parse_dat(path)["blocks"] if b["kind"].startswith("displacements")]
    return [next(r[1:] for r in b["rows"] if r[0] == 190) for b in blocks]
ccx, mine = tip(sys.argv[1]), tip(sys.argv[2])
worst = max(max(abs(a - b) for a, b in zip(x, y)) / max(abs(v) for v in y) for x, y in zip(ccx, mine))
print(f"export: CalculiX's end reference node against feticon's on the deck, {len(ccx)} steps: {worst:.2g} of max (bound 1e-5)")
sys.exit(0 if len(ccx) == len(mine) == 2 and worst <= 1e-5 else 1)
PY
fi

# Bad input: one line naming what is wrong, non-zero exit.
bad() { # FILE (NAME.inp or NAME.yaml in $work), PATTERN
  local name="${1%.*}" pattern="$2"
  if "$feticon" run "$work/$1" -o "$work/bad_$name" "${quiet[@]}" 2> "$work/$name.err"; then
    echo "$name: accepted"; exit 1
  fi
  [[ $(wc -l < "$work/$name.err") -eq 1 ]] || { echo "$name: not one line"; cat "$work/$name.err"; exit 1; }
  grep -q "$pattern" "$work/$name.err" || { echo "$name: unexpected message"; cat "$work/$name.err"; exit 1; }
  echo "$name: $(cat "$work/$name.err")"
}
base="$work/kinematic-moment.inp"
sed -e '/^\*KINEMATIC/,+1d' "$base" > "$work/no_kinematic.inp"
bad no_kinematic.inp "needs its \*KINEMATIC or \*DISTRIBUTING next"
sed -e 's/SURFACE=TIP,/SURFACE=NOSUCH,/' "$base" > "$work/unknown_surface.inp"
bad unknown_surface.inp "SURFACE=NOSUCH names no \*SURFACE"
sed -e 's/SURFACE=TIP,/SURFACE=LONELY,/' -e 's/^\*SURFACE, NAME=TIP, TYPE=ELEMENT$/*SURFACE, NAME=LONELY, TYPE=NODE\n10000\n&/' \
  "$base" > "$work/lonely_node_surface.inp"
bad lonely_node_surface.inp "\*SURFACE LONELY has no faces"
sed -e 's/ROT NODE=10001/ROT NODE=1/' "$work/rigid-moment.inp" > "$work/rot_node_in_cell.inp"
bad rot_node_in_cell.inp "ROT NODE 1 belongs to an element"
sed -e '/^\*KINEMATIC/{n;s/$/\n*COUPLING, REF NODE=10000, SURFACE=TIP\n*KINEMATIC\n1, 3/}' "$base" > "$work/two_references.inp"
bad two_references.inp "node 10000 is a reference node of"
sed -e 's/^10000, 5, /1, 5, /' "$base" > "$work/moment_on_solid.inp"
bad moment_on_solid.inp "which is no reference node"
sed -e '/^\*KINEMATIC/{n;s/.*/1/}' -e 's/^10000, 5, /10000, 4, /' "$base" > "$work/moment_not_carried.inp"
bad moment_not_carried.inp "does not carry"
printf '*DISTRIBUTING COUPLING, ELSET=BAR\n1, 1.\n' > "$work/insert.txt"
sed -e "/^\*BOUNDARY/e cat $work/insert.txt" "$base" > "$work/no_dcoup3d.inp"
bad no_dcoup3d.inp "no set of one DCOUP3D element"
sed -e 's/CONSTRAINT NAME=TIPC/CONSTRAINT NAME=TIPC, ORIENTATION=OR1/' "$base" > "$work/orientation.inp"
bad orientation.inp "ORIENTATION= (a coupling in a local system) is not implemented"
# ... and in problem files.
sed -e 's/coupling: tip, x:/coupling: nosuch, x:/' "$work/bar.yaml" > "$work/unknown_coupling.yaml"
bad unknown_coupling.yaml "no coupling 'nosuch'"
sed -e 's/kind: kinematic/kind: rigid/' "$work/bar.yaml" > "$work/unknown_kind.yaml"
bad unknown_kind.yaml "must be kinematic, distributing or pretension"
sed -e 's/surface: bar_xmax, reference: \[10, 0.5, 0.5\]/surface: bar_xmax/' "$work/bar.yaml" > "$work/no_reference.yaml"
bad no_reference.yaml "reference must be"
sed -e 's/surface: bar_xmax,/surface: bar_xmax, nodes: bar_xmax,/' "$work/bar.yaml" > "$work/surface_and_nodes.yaml"
bad surface_and_nodes.yaml "needs one of surface"
sed -e 's/coupling: tip, x: 1e-3/coupling: tip, rx: 1e300/' "$work/bar.yaml" > "$work/huge_rotation.yaml"
bad huge_rotation.yaml "non-finite residual"
# A mean coupling exported (its DCOUP3D element and *DISTRIBUTING COUPLING with the weights): the
# deck's run is distcoup's to 1e-9 with the same iterations (measured: difference 0); CalculiX
# 2.20 on the exported deck gives the displacements of feticon's .frd to 1.1e-6 of max |u|.
"$feticon" export "$data/distcoup.inp" --format calculix -o "$work/exported" > /dev/null
grep -q '^\*DISTRIBUTING COUPLING, ELSET=MEAN_1$' "$work/exported/feticon.inp"
"$feticon" run "$work/exported/feticon.inp" -o "$work/exported-run" "${quiet[@]}" \
  --set subdomains="$(/usr/bin/python3 -c "import json; print(json.load(open('$work/distcoup/summary.json'))['subdomains'])")" 2> /dev/null
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/distcoup" "$work/exported-run"
