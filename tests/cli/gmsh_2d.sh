#!/usr/bin/env bash
# 2D Gmsh meshes in problem files (issue 64, item 5): bodies as physical surfaces, edge sets as
# physical curves, mesh.formulation and mesh.thickness. The mesh, written here in MSH 2.2: two
# stacked blocks x in [0, 0.5], the lower y in [-0.4, 0] with 4 x 4 quadrangles, the upper y in
# [0, 0.4] with 5 x 3 written clockwise (Gmsh orients a surface's cells by its normal; the
# reader turns them counter-clockwise), boundary lines in either direction. Pressure p on the
# top, the bottom on rollers, a dual mortar pair between the non-matching blocks. The exact
# solution is uniaxial stress:
#   axisymmetric (a column on the axis x = 0): contact force p pi R^2, top settlement 2 H p / E;
#   plane strain (thickness 0.1, x = 0 held along x): force p R t, settlement 2 H p (1 - nu^2) / E;
# both to 1e-7 (the QP's tolerance; read from the VTU by tests/tools/read_vtu.py). Then bad
# input, one line each: 2D cells without mesh.formulation, a formulation for 3D boxes, a
# thickness in axisymmetry, an unknown formulation, a curve that bounds no body; bodies without
# supports, loads or contact (each alone in its subdomain: no dual row).
# Usage: gmsh_2d.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
tools="$2/tests/tools"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3

"$py" - "$work/blocks.msh" <<'PY'
import sys
R, H = 0.5, 0.4
nodes, elements = [], []
def block(y0, nx, ny, surface, clockwise, curves):
    first = len(nodes) + 1
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((R * i / nx, y0 + H * j / ny))
    at = lambda i, j: first + j * (nx + 1) + i
    for j in range(ny):
        for i in range(nx):
            q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
            elements.append((3, surface, [q[0], q[3], q[2], q[1]] if clockwise else q))
    bottom, top, axis = curves
    for i in range(nx):
        elements.append((1, bottom, [at(i, 0), at(i + 1, 0)]))
        elements.append((1, top, [at(i + 1, ny), at(i, ny)]))
    for j in range(ny):
        elements.append((1, axis, [at(0, j), at(0, j + 1)]))
block(-H, 4, 4, 1, False, (3, 4, 7))
block(0, 5, 3, 2, True, (5, 6, 8))
names = [(2, 1, "lower"), (2, 2, "upper"), (1, 3, "bottom"), (1, 4, "lower_top"), (1, 5, "upper_bottom"),
         (1, 6, "top"), (1, 7, "lower_axis"), (1, 8, "upper_axis")]
out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(names))]
out += [f'{d} {t} "{n}"' for d, t, n in names] + ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
out += [f"{k + 1} {x:.17g} {y:.17g} 0" for k, (x, y) in enumerate(nodes)]
out += ["$EndNodes", "$Elements", str(len(elements))]
out += [f"{k + 1} {t} 2 {g} {g} " + " ".join(map(str, n)) for k, (t, g, n) in enumerate(elements)]
open(sys.argv[1], "w").write("\n".join(out + ["$EndElements"]) + "\n")
PY

problem() { # MESH-LINES SUPPORT-LINES
  printf '%s\n' "problem: custom" "mesh:" "  file: blocks.msh" "$1" "bodies:" \
    "  lower: {young: 2e11, poisson: 0.3}" "  upper: {young: 2e11, poisson: 0.3}" \
    "supports:" "  - {set: bottom, y: 0}" "$2" "loads:" "  - {set: top, traction: [0, -1e7, 0]}" \
    "contact:" "  - {slave: upper_bottom, master: lower_top, formulation: mortar}" \
    "displacements: small" "qp:" "  rtol: 1e-11" "  force_rtol: 0" "output:" "  plots: false"
}
problem "  formulation: axisymmetric" "" >"$work/axi.yaml"
problem "$(printf '  formulation: plane_strain\n  thickness: 0.1')" \
  "$(printf '  - {set: lower_axis, x: 0}\n  - {set: upper_axis, x: 0}')" >"$work/strain.yaml"
for case in axi strain; do
  "$feticon" run "$work/$case.yaml" --output "$work/$case" >"$work/$case.log" 2>&1 || { cat "$work/$case.log"; exit 1; }
done
"$py" - "$work" "$tools" <<'PY'
import json, math, os, sys
import xml.etree.ElementTree as ElementTree
import numpy
work, tools = sys.argv[1:]
sys.path.insert(0, tools)
import read_vtu
R, H, p, E, nu, t = 0.5, 0.4, 1e7, 2e11, 0.3, 0.1

def point_arrays(path):
    root = ElementTree.parse(path).getroot()
    header = numpy.dtype("<" + read_vtu.TYPES[root.get("header_type", "UInt32")])
    piece = root.find("UnstructuredGrid/Piece")
    read = lambda e: read_vtu.read_array(e, root.get("byte_order", "LittleEndian"), header)
    points = read(piece.find("Points/DataArray")).reshape(-1, 3)
    u = next(read(e) for e in piece.findall("PointData/DataArray") if e.get("Name") == "displacement")
    return points, u.reshape(-1, 3)

for case, force, strain in (("axi", p * math.pi * R * R, p / E), ("strain", p * R * t, p * (1 - nu * nu) / E)):
    s = json.load(open(os.path.join(work, case, "summary.json")))
    assert s["converged"], case
    assert s["degrees_of_freedom"] == 2 * (25 + 24), s["degrees_of_freedom"]  # 2 unknowns a node
    f = s["contact"]["total_normal_force"]
    points, u = point_arrays(os.path.join(work, case, "step_001.vtu"))
    top = numpy.isclose(points[:, 1], H)
    settlement = numpy.max(numpy.abs(u[top, 1] / (-2 * H * strain) - 1))
    print(f"{case}: contact force {f:.10e} N (exact {force:.10e}, {f / force - 1:+.1e}); "
          f"top settlement off 2 H eps by {settlement:.1e} at {top.sum()} nodes")
    assert abs(f / force - 1) < 1e-7, case
    assert settlement < 1e-7, case
PY

expect_error() { # NAME PATTERN FILE
  if "$feticon" run "$3" --output "$work/bad_$1" >"$work/bad_$1.log" 2>&1; then
    echo "$1: accepted"; exit 1
  fi
  [ "$(grep -c "^feticon: error" "$work/bad_$1.log")" -eq 1 ] || { cat "$work/bad_$1.log"; exit 1; }
  grep -q "$2" "$work/bad_$1.log" || { echo "$1:"; cat "$work/bad_$1.log"; exit 1; }
  echo "$1: $(grep "^feticon: error" "$work/bad_$1.log")"
}
problem "" "" >"$work/none.yaml"
expect_error no_formulation "give mesh.formulation" "$work/none.yaml"
problem "  formulation: axisymmetric
  thickness: 0.1" "" >"$work/axi_thickness.yaml"
expect_error axi_thickness "not for an axisymmetric model" "$work/axi_thickness.yaml"
problem "  formulation: plane_stres" "" >"$work/typo.yaml"
expect_error typo "none of plane_strain" "$work/typo.yaml"
printf '%s\n' "problem: custom" "mesh:" "  formulation: plane_strain" "  boxes:" \
  "    - {name: b, origin: [0, 0, 0], lengths: [1, 1, 1], cells: [1, 1, 1]}" \
  "bodies:" "  b: {young: 2e11, poisson: 0.3}" >"$work/boxes.yaml"
expect_error boxes_3d "needs a mesh of 2D cells" "$work/boxes.yaml"
# Bodies, nothing else (fuzz seed 76, mutant 5631: a YAML document break cut the file there):
# each body alone in its subdomain, no dual row at all; the explicit operators of a subdomain
# without boundary crashed (SIGSEGV), now the rigid-body check says what is wrong.
printf '%s\n' "problem: custom" "mesh: {file: blocks.msh, formulation: axisymmetric}" "bodies:" \
  "  lower: {young: 2e11, poisson: 0.3}" "  upper: {young: 2e11, poisson: 0.3}" >"$work/floating.yaml"
expect_error floating "do not suppress every rigid-body motion" "$work/floating.yaml"
# The first line of "bottom" from node 1 to node 7, the diagonal of the first cell: no edge.
sed 's/^\(.* 1 2 3 3 \)1 2$/\11 7/' "$work/blocks.msh" >"$work/diagonal.msh"
grep -q " 1 2 3 3 1 7$" "$work/diagonal.msh"
sed 's/blocks.msh/diagonal.msh/' "$work/axi.yaml" >"$work/diagonal.yaml"
expect_error diagonal "is not a face of any cell" "$work/diagonal.yaml"
