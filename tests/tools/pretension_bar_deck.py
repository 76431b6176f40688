#!/usr/bin/python3
"""A CalculiX deck of a bar with a pretension section (tests/cli/pretension.sh): a 1 x 1 square
bar along x, length L = 10 m, nx = 10 C3D20 cells (one across), E = 1e9 Pa, nu = 0; the face
x = 0 held in x, y and z, the face x = L in x; a *PRE-TENSION SECTION at x = L / 2 (face S4 of
cell nx / 2, normal +x away from it) with reference node 10000.

    pretension_bar_deck.py OUT.inp KIND
KIND: force (a pretension force F = 1e6 N on the reference node's DOF 1),
      gap (the section's gap held at q = 0.01 m by *BOUNDARY on DOF 1),
      normal (as force, the normal given on the keyword's line, and NLGEOM).

Both ends held in x, the bar carries the pretension as uniform tension: sigma_xx = F / A and
the gap q = F L / (E A) (0.01 m for F = 1e6 N), or the reaction E A q / L for a held gap; with
nu = 0 the stress is uniaxial and C3D20 holds the linear displacement exactly.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from c3d20_bar import c3d20_bar  # noqa: E402

E, F, Q = 1e9, 1e6, 0.01


def main(argv):
    out, kind = argv[1], argv[2]
    length, nx = 10.0, 10
    nodes, elements, used, label = c3d20_bar(length, nx)
    lines = ["** bar with a pretension section (tests/tools/pretension_bar_deck.py " + kind + ")", "*NODE"] + nodes
    lines.append("10000, 0., 0., 0.")
    lines += elements
    lines.append("*NSET, NSET=LEFT")
    lines += [str(label(*p)) for p in sorted(used) if p[0] == 0]
    lines.append("*NSET, NSET=RIGHT")
    lines += [str(label(*p)) for p in sorted(used) if p[0] == 2 * nx]
    lines += ["*NSET, NSET=REF", "10000"]
    lines += ["*SURFACE, NAME=CUT, TYPE=ELEMENT", f"{nx // 2}, S4"]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", f"{E!r}, 0.0", "*SOLID SECTION, ELSET=BAR, MATERIAL=M"]
    lines += ["*PRE-TENSION SECTION, SURFACE=CUT, NODE=10000"]
    if kind == "normal":
        lines.append("1., 0., 0.")
    lines += ["*BOUNDARY", "LEFT, 1, 3", "RIGHT, 1, 1"]
    lines += ["*STEP, NLGEOM" if kind == "normal" else "*STEP", "*STATIC"]
    if kind == "gap":
        lines += ["*BOUNDARY", f"10000, 1, 1, {Q!r}"]
    elif kind in ("force", "normal"):
        lines += ["*CLOAD", f"10000, 1, {F!r}"]
    else:
        sys.exit(f"unknown kind {kind}")
    lines += ["*NODE PRINT, NSET=REF", "U, RF", "*NODE PRINT, NSET=RIGHT, TOTALS=ONLY", "RF", "*END STEP"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv)
