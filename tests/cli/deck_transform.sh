#!/usr/bin/env bash
# *TRANSFORM (issue 63, item 7): supports and concentrated forces along nodes' local axes.
# 1. Rotation invariance (exact): a punch on a base with a frictionless pair, on rollers, the
#    base pulled by a prescribed u_x = 2e-4 at its x = 1 face, the punch pressed by *CLOAD; the
#    same deck turned 30 degrees about z with its supports and forces given in a rectangular
#    *TRANSFORM along the turned axes (skew rows, a non-zero prescribed value). Reference: the
#    unturned run; u_turned = R u at every node to 1e-6 of max |u| (the .dat's 7 digits; QP rtol
#    1e-10), and the local components of the turned run (GLOBAL=NO, marked L) the unturned run's;
#    on 1 and 2 MPI ranks, and through `feticon export` (its per-node *TRANSFORM, TYPE=R).
# 2. Lame (cylindrical *TRANSFORM): a thick ring, a = 1, b = 2, plane strain, internal pressure
#    p = 1e6, as a 30-degree sector from 10 to 40 degrees whose sides hold u_theta = 0 in a
#    cylindrical system about z. Reference: Lame's u_r(r) = (1 + nu) p a^2 / (E (b^2 - a^2))
#    ((1 - 2 nu) r + b^2 / r), u_theta = 0. C3D20 cells, 4 x 2 and 8 x 4: 7.9e-5 and 5.4e-6 of
#    max u_r (the discretization error, falling at least as h^3), u_theta below 1e-9.
# Usage: deck_transform.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
src="$2"
work="$(mktemp -d)"
trap "rm -rf $work" EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"
options=(--set output.plots=false --set output.vtu=false --set qp.rtol=1e-10 --set qp.force_rtol=0)

/usr/bin/python3 - "$work" <<'PY'
import math, sys
work = sys.argv[1]

def box(first, origin, lengths, cells, rotate):
    """Hex8 grid nodes (label -> x) and elements, turned by `rotate` radians about z."""
    nx, ny, nz = cells
    c, s = math.cos(rotate), math.sin(rotate)
    nodes, elements = {}, []
    label = lambda i, j, k: first + i + (nx + 1) * (j + (ny + 1) * k)
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                x = [origin[0] + lengths[0] * i / nx, origin[1] + lengths[1] * j / ny, origin[2] + lengths[2] * k / nz]
                nodes[label(i, j, k)] = (c * x[0] - s * x[1], s * x[0] + c * x[1], x[2]), tuple(x)
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                elements.append([label(i, j, k), label(i + 1, j, k), label(i + 1, j + 1, k), label(i, j + 1, k),
                                 label(i, j, k + 1), label(i + 1, j, k + 1), label(i + 1, j + 1, k + 1),
                                 label(i, j + 1, k + 1)])
    return nodes, elements

def block_deck(angle):
    """Base 1 x 1 x 0.5 (3 x 3 x 2) under a punch 0.5 x 0.5 x 0.5 (2 x 2 x 2) at (0.25, 0.25)."""
    base, base_cells = box(1, (0, 0, 0), (1, 1, 0.5), (3, 3, 2), angle)
    punch, punch_cells = box(1001, (0.25, 0.25, 0.5), (0.5, 0.5, 0.5), (2, 2, 2), angle)
    nodes = {**base, **punch}
    out = ["*NODE, NSET=NALL"] + [f"{n}, {x[0]!r}, {x[1]!r}, {x[2]!r}" for n, (x, _) in nodes.items()]
    out += ["*ELEMENT, TYPE=C3D8, ELSET=EALL"]
    out += [", ".join(str(v) for v in [e + 1] + cell) for e, cell in enumerate(base_cells)]
    out += [", ".join(str(v) for v in [e + 1001] + cell) for e, cell in enumerate(punch_cells)]
    def nset(name, test, pool):
        return [f"*NSET, NSET={name}"] + [f"{n}," for n, (_, x) in pool.items() if test(x)]
    out += nset("BXMIN", lambda x: x[0] == 0, base) + nset("BYMIN", lambda x: x[1] == 0, base)
    out += nset("BZMIN", lambda x: x[2] == 0, base) + nset("BXMAX", lambda x: x[0] == 1, base)
    out += nset("PXMIN", lambda x: x[0] == 0.25, punch) + nset("PYMIN", lambda x: x[1] == 0.25, punch)
    out += nset("PTOP", lambda x: x[2] == 1.0, punch)
    out += ["*ELSET, ELSET=BTOP"] + [f"{e + 1}," for e in range(9, 18)]
    out += ["*ELSET, ELSET=PBOT"] + [f"{e + 1001}," for e in range(4)]
    out += ["*SURFACE, NAME=M, TYPE=ELEMENT", "BTOP, S2", "*SURFACE, NAME=S, TYPE=ELEMENT", "PBOT, S1"]
    if angle != 0:
        c, s = math.cos(angle), math.sin(angle)
        out += ["*TRANSFORM, NSET=NALL, TYPE=R", f"{c!r}, {s!r}, 0., {-s!r}, {c!r}, 0."]
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3", "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
            "*SURFACE INTERACTION, NAME=I", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
            "*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE", "S, M",
            "*STEP", "*STATIC", "*BOUNDARY", "BXMIN, 1, 1", "BYMIN, 2, 2", "BZMIN, 3, 3", "BXMAX, 1, 1, 2e-4",
            "PXMIN, 1, 1", "PYMIN, 2, 2", "*CLOAD"]
    top = [n for n, (_, x) in punch.items() if x[2] == 1.0]
    out += [f"{n}, 3, -10." for n in top] + [f"{top[0]}, 1, 3.", f"{top[-1]}, 2, -2."]
    out += ["*NODE PRINT, NSET=NALL, GLOBAL=YES", "U", "*NODE PRINT, NSET=PTOP", "U", "*END STEP"]
    return "\n".join(out) + "\n"

open(f"{work}/block.inp", "w").write(block_deck(0.0))
open(f"{work}/turned.inp", "w").write(block_deck(math.radians(30)))

def ring_deck(nr, nt, cyclic=False):
    """Quadratic (C3D20) sector 10..40 degrees of the ring a = 1, b = 2, one cell layer 0.1 thick;
    its sides hold u_theta, or (cyclic) are tied as one of 12 sectors with one node held."""
    a, b, t0, t1, h = 1.0, 2.0, math.radians(10), math.radians(40), 0.1
    nodes, index = [], {}
    def node(i, j, k):  # i, j on the doubled grid (quadratic cells), k = 0, 1, 2
        key = (i, j, k)
        if key not in index:
            r, t = a + (b - a) * i / (2 * nr), t0 + (t1 - t0) * j / (2 * nt)
            index[key] = len(index) + 1
            nodes.append((index[key], r * math.cos(t), r * math.sin(t), h * k / 2, r))
        return index[key]
    cells = []
    for i in range(nr):
        for j in range(nt):
            I, J = 2 * i, 2 * j
            corners = [(I, J), (I + 2, J), (I + 2, J + 2), (I, J + 2)]
            mids = [(I + 1, J), (I + 2, J + 1), (I + 1, J + 2), (I, J + 1)]
            c = [node(p, q, 0) for p, q in corners] + [node(p, q, 2) for p, q in corners]
            c += [node(p, q, 0) for p, q in mids] + [node(p, q, 2) for p, q in mids]
            c += [node(p, q, 1) for p, q in corners]
            cells.append(c)
    out = ["*NODE, NSET=NALL"] + [f"{n}, {x!r}, {y!r}, {z!r}" for n, x, y, z, _ in nodes]
    out += ["*ELEMENT, TYPE=C3D20, ELSET=EALL"]
    for e, c in enumerate(cells):
        out += [", ".join(str(v) for v in [e + 1] + c[:15]) + ",", ", ".join(str(v) for v in c[15:])]
    sides = sorted(n for (i, j, k), n in index.items() if j in (0, 2 * nt))
    out += ["*NSET, NSET=SIDES"] + [f"{n}," for n in sides]
    out += ["*ELSET, ELSET=INNER"] + [f"{e * nt + j + 1}," for e in [0] for j in range(nt)]
    held = "SIDES, 2, 2"
    if cyclic:
        out += ["*NSET, NSET=IND"] + [f"{n}," for (i, j, k), n in sorted(index.items()) if j == 0]
        out += ["*NSET, NSET=DEP"] + [f"{n}," for (i, j, k), n in sorted(index.items()) if j == 2 * nt]
        out += ["*NSET, NSET=ONE", f"{index[(0, 0, 0)]},", "*SURFACE, NAME=SIND, TYPE=NODE", "IND",
                "*SURFACE, NAME=SDEP, TYPE=NODE", "DEP", "*TIE, NAME=CS, CYCLIC SYMMETRY, POSITION TOLERANCE=1e-6",
                "SDEP, SIND", "*CYCLIC SYMMETRY MODEL, N=12", "0., 0., 0., 0., 0., 1."]
        held = "ONE, 2, 2"
    out += ["*TRANSFORM, NSET=NALL, TYPE=C", "0., 0., 0., 0., 0., 1.",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", "2e11, 0.3", "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
            "*STEP", "*STATIC", "*BOUNDARY", "NALL, 3, 3", held, "*DLOAD", "INNER, P6, 1e6",
            "*NODE PRINT, NSET=NALL", "U", "*END STEP"]
    name = f"cyclic{nr}" if cyclic else f"ring{nr}"
    open(f"{work}/{name}.inp", "w").write("\n".join(out) + "\n")
    with open(f"{work}/{name}.radius", "w") as f:
        for n, _, _, _, r in nodes:
            f.write(f"{n} {r!r}\n")

ring_deck(4, 2)
ring_deck(8, 4)
ring_deck(8, 4, cyclic=True)
PY

run() { # NAME DECK [prefix command...]
  local name="$1" input="$2"
  shift 2
  "$@" "$feticon" run "$input" -o "$work/$name" "${options[@]}" > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; exit 1; }
}
run block "$work/block.inp"
run turned "$work/turned.inp"
"$feticon" export "$work/turned.inp" --format calculix --overclosure 0 -o "$work/exported" > /dev/null
sed -i '0,/^\*END STEP/s//*NODE PRINT, NSET=NALL, GLOBAL=YES\nU\n*END STEP/' "$work/exported/feticon.inp"
run exported "$work/exported/feticon.inp"
runs=(turned exported)
if command -v mpirun > /dev/null; then
  run two "$work/turned.inp" timeout 300 mpirun --oversubscribe -np 2
  runs+=(two)
fi
run ring4 "$work/ring4.inp"
run ring8 "$work/ring8.inp"
run cyclic8 "$work/cyclic8.inp"
# The cyclic symmetry tie exported (*TIE, CYCLIC SYMMETRY and its *CYCLIC SYMMETRY MODEL; the export
# wrote a plain tie before 2026-12-04): the exported deck's run is cyclic8's, the same iterations, to 1e-9.
"$feticon" export "$work/cyclic8.inp" --format calculix --overclosure 0 -o "$work/cyclic8-deck" > /dev/null
grep -q '^\*CYCLIC SYMMETRY MODEL, N=12, TIE=TIE_CS$' "$work/cyclic8-deck/feticon.inp"
run cyclic8x "$work/cyclic8-deck/feticon.inp"
/usr/bin/python3 "$src/tests/tools/compare_runs.py" 1e-9 "$work/cyclic8" "$work/cyclic8x"

/usr/bin/python3 - "$src" "$work" "${runs[@]}" <<'PY'
import json, math, sys
src, work, *runs = sys.argv[1:]
sys.path.insert(0, src + "/tests/tools")
from calculix_dat import parse_dat

def blocks(path, kind="displacements"):
    return [b for b in parse_dat(path)["blocks"] if b["kind"] == kind]

base = {int(r[0]): r[1:4] for r in blocks(f"{work}/block/block.dat")[0]["rows"]}
scale = max(max(abs(v) for v in u) for u in base.values())
c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
# The exported deck numbers the nodes 1.. in the order the deck gave them.
reading, node_block = [], False
for line in open(f"{work}/turned.inp"):
    if line.startswith("*"):
        node_block = line.startswith("*NODE,")
    elif node_block:
        reading.append(int(line.split(",")[0]))
for run in runs:
    found = blocks(f"{work}/{run}/{'feticon' if run == 'exported' else 'turned'}.dat")
    turned = {int(r[0]): r[1:4] for r in found[0]["rows"]}  # GLOBAL=YES
    if run == "exported":
        turned = {reading[n - 1]: u for n, u in turned.items()}
    assert set(turned) == set(base), f"{run}: other nodes printed"
    error = max(max(abs(a - b) for a, b in zip(turned[n], (c * u[0] - s * u[1], s * u[0] + c * u[1], u[2])))
                for n, u in base.items()) / scale
    # The second request (GLOBAL=NO, CalculiX's default) prints local components: the unturned ones.
    local_error = 0.0
    if run != "exported":
        local = {int(r[0]): r[1:4] for r in found[1]["rows"]}
        local_error = max(max(abs(a - b) for a, b in zip(local[n], base[n])) for n in local) / scale
    summary = json.load(open(f"{work}/{run}/summary.json"))
    print(f"turned block ({run}): max |u - R u_unturned| / max |u| = {error:.1e}, local components {local_error:.1e}, "
          f"contact force {summary['contact']['total_normal_force']:.9g}")
    # The .dat prints 7 digits: a rotated value carries up to 5e-7 of its size in rounding.
    assert error <= 1e-6 and local_error <= 1e-6, "the turned model is not the unturned one turned"
marks = [line for line in open(f"{work}/turned/turned.dat") if line.rstrip().endswith(" L")]
assert marks, "no row of the local request is marked L"

E, nu, p, a, b = 2e11, 0.3, 1e6, 1.0, 2.0
exact = lambda r: (1 + nu) * p * a * a / (E * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r)
errors = []
for name in ("ring4", "ring8", "cyclic8"):
    nr = int(name[-1])
    radius = {int(l.split()[0]): float(l.split()[1]) for l in open(f"{work}/{name}.radius")}
    u = {int(r[0]): r[1:4] for r in blocks(f"{work}/{name}/{name}.dat")[0]["rows"]}
    umax = max(exact(r) for r in radius.values())
    # Local components (cylindrical): u_r, u_theta, u_z.
    err_r = max(abs(u[n][0] - exact(radius[n])) for n in u) / umax
    err_t = max(abs(u[n][1]) for n in u) / umax
    errors.append(err_r)
    print(f"Lame sector ({name}), {nr} x {nr // 2} C3D20: max |u_r - Lame| / max u_r = {err_r:.2e}, "
          f"max |u_theta| / max u_r = {err_t:.1e}")
    assert err_t <= 1e-9, "the sector turns: u_theta is not held"
# Measured 7.9e-5 and 5.4e-6: quadratic cells, nodal error falling as h^3 to h^4.
assert errors[1] <= 1e-5, "the finer sector is farther from Lame than its discretization error"
# The cyclic symmetry tie (its sides u_dep = R u_ind, one node held) gives the same axisymmetric
# answer as the sides held along u_theta: the same discretization, to the solver's tolerance.
assert abs(errors[2] - errors[1]) <= 1e-7, "the cyclic symmetry sector is not the held sector"
assert errors[1] < errors[0] / 8, "the error does not fall with the mesh size as quadratic cells' does"
PY

# Bad *TRANSFORM lines: one line naming the deck line.
source "$src/tests/tools/expect_deck_error.sh" # expect_error NAME PATTERN
sed 's/^0., 0., 0., 0., 0., 1.$/0., 0., 0., 0., 0., 0./' "$work/ring4.inp" > "$work/same_points.inp"
expect_error same_points "same_points.inp:[0-9]*: \*TRANSFORM: the cylinder axis needs two different points a and b"
sed 's/^\*TRANSFORM, NSET=NALL, TYPE=C/*TRANSFORM, NSET=NALL, TYPE=S/' "$work/ring4.inp" > "$work/spherical.inp"
expect_error spherical "spherical.inp:[0-9]*: \*TRANSFORM: TYPE=S is not implemented by feticon"
sed 's/^\*TRANSFORM, NSET=NALL, TYPE=C/*TRANSFORM, NSET=NOSUCH, TYPE=C/' "$work/ring4.inp" > "$work/no_set.inp"
expect_error no_set "no_set.inp:[0-9]*: \*TRANSFORM: no node set 'NOSUCH' is defined"
sed 's/^0\.8660254037844387, 0\.49999999999999994, 0\., .*$/1., 0., 0., 2., 0., 0./' "$work/turned.inp" > "$work/on_axis.inp"
expect_error on_axis "on_axis.inp:[0-9]*: \*TRANSFORM: point b lies on the local x axis"
if "$feticon" run -q "$work/turned.inp" -o "$work/penalty" --set method=primal_penalty > "$work/penalty.log" 2>&1; then
  echo "primal_penalty ran supports along local axes"; exit 1
fi
grep -q "supports act along local axes (\*TRANSFORM), which method = primal_penalty does not model" "$work/penalty.log"
echo "bad *TRANSFORM decks: one line each"
