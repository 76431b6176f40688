#!/usr/bin/python3
"""A CalculiX deck of a cantilever whose free end is driven by a coupling to a reference node
(tests/cli/couplings.sh): a 1 x 1 square bar along x, length L, nx C3D20 cells (one across),
E = 1e9 Pa, nu = 0, clamped at x = 0; its end face x = L is the surface TIP, the reference node
10000 sits at the face's centre (L, 0.5, 0.5).

    coupled_cantilever_deck.py OUT.inp KIND [L] [nx]
KIND: kinematic-moment (*COUPLING + *KINEMATIC 1-3, a moment M = 1e4 N m about y on DOF 5),
      distributing-force (*COUPLING + *DISTRIBUTING 1-6, an axial force F = 1e6 N on DOF 1),
      rigid-moment (*RIGID BODY of the end face's nodes, REF NODE 10000, ROT NODE 10001, the
      moment on the ROT NODE's DOF 2),
      rigid-rotation (the same rigid body turned 30 degrees about y by its ROT NODE's DOF 2, held,
      under NLGEOM in ten increments: finite rotations).

With nu = 0 pure bending and pure tension have quadratic and linear displacements (no
anticlastic curvature, no lateral contraction), which C3D20 holds exactly: the end rotation
M L / (E I) (I = 1/12 m^4) and the elongation F L / (E A) are the discrete answers too, to the
solver's tolerance.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from c3d20_bar import c3d20_bar  # noqa: E402

E, M, F = 1e9, 1e4, 1e6


def main(argv):
    out, kind = argv[1], argv[2]
    length = float(argv[3]) if len(argv) > 3 else 10.0
    nx = int(argv[4]) if len(argv) > 4 else 10
    nodes, elements, used, label = c3d20_bar(length, nx)
    lines = ["** coupled cantilever (tests/tools/coupled_cantilever_deck.py " + kind + ")", "*NODE"] + nodes
    lines.append(f"10000, {length!r}, 0.5, 0.5")
    if kind.startswith("rigid"):
        lines.append("10001, 0., 0., 0.")
    lines += elements
    lines.append("*NSET, NSET=CLAMP")
    lines += [str(label(*p)) for p in sorted(used) if p[0] == 0]
    lines.append("*NSET, NSET=END")
    lines += [str(label(*p)) for p in sorted(used) if p[0] == 2 * nx]
    lines.append("*NSET, NSET=REF")
    lines.append("10000" + (", 10001" if kind.startswith("rigid") else ""))
    lines += ["*SURFACE, NAME=TIP, TYPE=ELEMENT", f"{nx}, S4"]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", f"{E!r}, 0.0", "*SOLID SECTION, ELSET=BAR, MATERIAL=M"]
    lines += ["*BOUNDARY", "CLAMP, 1, 3"]
    if kind == "kinematic-moment":
        lines += ["*COUPLING, REF NODE=10000, SURFACE=TIP, CONSTRAINT NAME=TIPC", "*KINEMATIC", "1, 3"]
        load = f"10000, 5, {M!r}"
    elif kind == "distributing-force":
        lines += ["*COUPLING, REF NODE=10000, SURFACE=TIP, CONSTRAINT NAME=TIPC", "*DISTRIBUTING", "1, 6"]
        load = f"10000, 1, {F!r}"
    elif kind.startswith("rigid"):
        lines += ["*RIGID BODY, NSET=END, REF NODE=10000, ROT NODE=10001"]
        load = f"10001, 2, {M!r}"
    else:
        sys.exit(f"unknown kind {kind}")
    if kind == "rigid-rotation":
        lines += ["*STEP, NLGEOM", "*STATIC, DIRECT", "0.1, 1.", "*BOUNDARY", "10001, 2, 2, 0.5235987755982988"]
    else:
        lines += ["*STEP", "*STATIC", "*CLOAD", load]
    lines += ["*NODE PRINT, NSET=REF", "U, RF", "*NODE PRINT, NSET=END", "U", "*END STEP"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv)
