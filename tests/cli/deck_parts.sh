#!/usr/bin/env bash
# Abaqus/CAE decks (issue 63, item 7): tests/data/abaqus/assembly_two_blocks.inp, two parts, two
# instances (one translated and turned 90 degrees), sets and surfaces in the parts and in the
# assembly (INSTANCE=, INTERNAL, GENERATE), names qualified by instance, a frictionless pair
# between the non-matching meshes. The top is pressed down 1e-3 on rollers.
# References:
# - exact: both blocks in uniaxial compression, strain e = -1e-3 / 1 (total height 1, one E),
#   u = (-nu e (x - x0), -nu e (y - y0), e z) with the rollers at x0 = 0, y0 = 0 in BASE and at
#   x0 = 1, y0 = 0 in TOP-1 (its part's y = 0 and x = 0 faces, turned there by the instance's
#   rotation), at every node's model coordinates as this script places them (its own reading of
#   the parts and the *INSTANCE lines: translation, then rotation about the axis a-b). Within
#   1e-6 of max |u| (the .dat's 7 digits; dual mortar passes the patch test).
# - the same model flattened (this script writes it: one *NODE and *ELEMENT list, plain sets,
#   other labels): every node's displacement to 1e-9 of max |u|.
# - 2 MPI ranks: the same MPRGP steps and displacements.
# Usage: deck_parts.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
deck="$src/tests/data/abaqus/assembly_two_blocks.inp"
options=(--set output.plots=false --set output.vtu=false --set qp.rtol=1e-10 --set qp.force_rtol=0)

# The flattened model: written from the parts deck by this script, then run like the original.
/usr/bin/python3 - "$deck" "$work/flat.inp" "$work/placed.json" <<'PY'
import json, math, sys
deck, flat_path, placed_path = sys.argv[1:]
parts, instances, part, where = {}, [], None, None
for raw in open(deck):
    line = raw.strip()
    if line.startswith("**") or not line:
        continue
    if line.startswith("*"):
        key = [f.strip() for f in line[1:].split(",")]
        name = key[0].upper()
        params = {k.split("=")[0].strip().upper(): (k.split("=")[1].strip().upper() if "=" in k else "") for k in key[1:]}
        if name == "PART":
            part = parts.setdefault(params["NAME"], {"nodes": {}, "elements": []})
        elif name == "END PART":
            part = None
        elif name == "INSTANCE":
            instances.append({"name": params["NAME"], "part": params["PART"], "lines": []})
        where = (name, part)
        continue
    fields = [f.strip() for f in line.split(",")]
    if where[0] == "NODE" and where[1] is not None:
        where[1]["nodes"][int(fields[0])] = [float(v) for v in fields[1:4]]
    elif where[0] == "ELEMENT" and where[1] is not None:
        where[1]["elements"].append([int(v) for v in fields])
    elif where[0] == "INSTANCE":
        instances[-1]["lines"].append([float(v) for v in fields])

def place(x, lines):
    """Abaqus's *INSTANCE: translate, then rotate about the axis from a to b (right hand)."""
    if not lines:
        return x
    x = [x[k] + lines[0][k] for k in range(3)]
    if len(lines) < 2:
        return x
    a, b, angle = lines[1][0:3], lines[1][3:6], math.radians(lines[1][6])
    k = [b[i] - a[i] for i in range(3)]
    n = math.sqrt(sum(v * v for v in k))
    k = [v / n for v in k]
    p = [x[i] - a[i] for i in range(3)]
    kxp = [k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0]]
    kp = sum(k[i] * p[i] for i in range(3))
    return [a[i] + p[i] * math.cos(angle) + kxp[i] * math.sin(angle) + k[i] * kp * (1 - math.cos(angle))
            for i in range(3)]

# feticon's labels: each instance's shifted past the largest label of those before it.
placed, offset, flat_nodes, flat_elements = {}, 0, [], []
for inst in instances:
    p = parts[inst["part"]]
    for label, x in p["nodes"].items():
        placed[label + offset] = {"instance": inst["name"], "x": place(x, inst["lines"])}
    inst["offset"] = offset
    offset += max(p["nodes"])
# Flattened: BASE's labels as they are, TOP-1's from 1001 (not feticon's numbering).
flat_label = {}
for inst in instances:
    p, shift = parts[inst["part"]], (0 if inst["name"] == "BASE" else 1000)
    for label, x in p["nodes"].items():
        flat_label[label + inst["offset"]] = label + shift
        flat_nodes.append(f"{label + shift}, " + ", ".join(repr(v) for v in place(x, inst["lines"])))
    for e in p["elements"]:
        flat_elements.append(", ".join(str(v + shift) for v in e))
def node_set(name, labels):
    return [f"*NSET, NSET={name}"] + [f"{l}," for l in labels]
lines = ["*NODE, NSET=NALL"] + flat_nodes + ["*ELEMENT, TYPE=C3D8, ELSET=EALL"] + flat_elements
base = parts["BLOCK"]["nodes"]
lines += node_set("BXMIN", [l for l, x in base.items() if x[0] == 0])
lines += node_set("BYMIN", [l for l, x in base.items() if x[1] == 0])
lines += node_set("BZMIN", [l for l, x in base.items() if x[2] == 0])
punch = parts["PUNCH"]["nodes"]
lines += node_set("TXMIN", [1000 + l for l, x in punch.items() if x[0] == 0])
lines += node_set("TYMIN", [1000 + l for l, x in punch.items() if x[1] == 0])
lines += node_set("TZMAX", [1000 + l for l, x in punch.items() if x[2] == 0.5])
lines += ["*ELSET, ELSET=TBOT", "1001, 1002, 1003, 1004, 1005, 1006, 1007, 1008, 1009",
          "*ELSET, ELSET=BTOP", "5, 6, 7, 8",
          "*SURFACE, NAME=S, TYPE=ELEMENT", "TBOT, S1", "*SURFACE, NAME=M, TYPE=ELEMENT", "BTOP, S2",
          "*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3", "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
          "*SURFACE INTERACTION, NAME=I", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
          "*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE", "S, M",
          "*STEP", "*STATIC", "*BOUNDARY", "BZMIN, 3, 3", "BXMIN, 1, 1", "BYMIN, 2, 2", "TXMIN, 2, 2",
          "TYMIN, 1, 1", "TZMAX, 3, 3, -0.001", "1020, 1, 1", "*NODE PRINT, NSET=NALL", "U", "*END STEP"]
open(flat_path, "w").write("\n".join(lines) + "\n")
json.dump({"placed": placed, "flat_label": flat_label}, open(placed_path, "w"))
PY

run() { # NAME DECK [mpirun prefix...]
  local name="$1" input="$2"
  shift 2
  "$@" "$feticon" run "$input" -o "$work/$name" "${options[@]}" > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; exit 1; }
}
run parts "$deck"
run flat "$work/flat.inp"
runs=(parts)
if command -v mpirun > /dev/null; then
  run two "$deck" timeout 300 mpirun --oversubscribe -np 2
  runs+=(two)
fi
/usr/bin/python3 - "$src" "$work" "${runs[@]}" <<'PY'
import json, sys
src, work, *runs = sys.argv[1:]
sys.path.insert(0, src + "/tests/tools")
from calculix_dat import parse_dat
info = json.load(open(f"{work}/placed.json"))
placed = {int(k): v for k, v in info["placed"].items()}
flat_label = {int(k): v for k, v in info["flat_label"].items()}
def last_u(path):
    blocks = [b for b in parse_dat(path)["blocks"] if b["kind"] == "displacements"]
    return {int(r[0]): r[1:4] for r in blocks[-1]["rows"]}
nu, e = 0.3, -1e-3
exact = {}
for label, p in placed.items():
    x, y, z = p["x"]
    x0 = 0.0 if p["instance"] == "BASE" else 1.0
    exact[label] = (-nu * e * (x - x0), -nu * e * y, e * z)
scale = max(max(abs(v) for v in u) for u in exact.values())
flat = last_u(f"{work}/flat/flat.dat")
steps = []
for run in runs:
    u = last_u(f"{work}/{run}/assembly_two_blocks.dat")
    assert set(u) == set(exact), f"{run}: printed nodes {sorted(set(u) ^ set(exact))[:5]} differ from the placed ones"
    error = max(max(abs(a - b) for a, b in zip(u[n], exact[n])) for n in u) / scale
    flat_diff = max(max(abs(a - b) for a, b in zip(u[n], flat[flat_label[n]])) for n in u) / scale
    summary = json.load(open(f"{work}/{run}/summary.json"))
    assert summary["converged"], run + ": not converged"
    steps.append(summary["qp"]["iterations"])
    print(f"assembly_two_blocks on {run}: max |u - u_exact| / max |u| = {error:.1e}, "
          f"flattened deck {flat_diff:.1e}, contact force {summary['contact']['total_normal_force']:.9g}, "
          f"{steps[-1]} MPRGP steps")
    assert error <= 1e-6, "the blocks are not in uniaxial compression: the instances are not placed as Abaqus does"
    assert flat_diff <= 1e-9, "the parts deck and its flattened model differ"
assert len(set(steps)) == 1, f"MPRGP steps differ between rank counts: {steps}"
PY

# Bad parts and instances: one line naming the deck line and what is wrong.
source "$src/tests/tools/expect_deck_error.sh" # expect_error NAME PATTERN
mutate() { # NAME SED-SCRIPT
  sed "$2" "$deck" > "$work/$1.inp"
}
mutate undefined_part 's/part=PUNCH/part=NOZZLE/'
expect_error undefined_part "undefined_part.inp:[0-9]*: \*INSTANCE: no \*PART 'NOZZLE' is defined before it"
mutate plain_label 's/^TOP-1.20, 1, 1/20, 1, 1/'
expect_error plain_label "plain_label.inp:[0-9]*:1: \*BOUNDARY: node 20: in a deck of parts and instances a node or element is named by its instance"
mutate unknown_instance_label 's/^TOP-1.20, 1, 1/TOP-1.99, 1, 1/'
expect_error unknown_instance_label "\*BOUNDARY: node 99 is not defined (by a \*NODE before this line, in instance TOP-1)"
mutate no_end_part '0,/^\*End Part/{/^\*End Part/d}'
expect_error no_end_part "no_end_part.inp:[0-9]*: \*PART: the \*PART at .*no_end_part.inp:17 has no \*END PART before it"
mutate same_axis_points 's/0.5,          0.5,           1.,          90./0.5,          0.5,           0.,          90./'
expect_error same_axis_points "same_axis_points.inp:[0-9]*: \*INSTANCE: the rotation axis needs two different points a and b"
mutate material_in_part '0,/^\*Solid Section/s/^\*Solid Section/*Material, name=X\n*Solid Section/'
expect_error material_in_part "\*MATERIAL inside the \*PART at .*: a part holds nodes, elements, sets, surfaces and sections"
mutate instance_twice 's/name=TOP-1, part=PUNCH/name=BASE, part=PUNCH/'
expect_error instance_twice "\*INSTANCE: instance BASE is defined twice"
mutate no_end_instance '0,/^\*End Instance/{/^\*End Instance/d}'
expect_error no_end_instance "\*INSTANCE: the \*INSTANCE at .*no_end_instance.inp:[0-9]* has no \*END INSTANCE before it"
mutate node_in_assembly 's/^\*End Assembly/*Node\n 1, 0., 0., 0.\n*End Assembly/'
expect_error node_in_assembly "\*NODE: nodes and elements outside the parts (the assembly's reference points) are not implemented by feticon"
echo "bad parts and instances: one line each"
