"""The mesh part of a CalculiX deck of a quarter of a thick ring (a <= r <= b, 0 <= theta <=
pi / 2) in CPE4 cells, nr across and nt around, for the plane-strain cylinder tests
(tests/cli/fbar.sh, fbar_plastic.sh): *NODE, *ELEMENT (ELSET=RING) and the node sets XAXIS and
YAXIS (the symmetry edges), INNER (r = a) and OUTER (r = b). Node (i, j), i across and j
around, is nid(nr, i, j); cell (i, j)'s edge 4-1 (face P4) lies at r = a where i = 0."""
import math


def nid(nr, i, j):
    return 1 + j * (nr + 1) + i


def cell(nr, i, j):
    return 1 + j * nr + i


def mesh_lines(a, b, nr, nt):
    lines = ["*NODE, NSET=NALL"]
    for j in range(nt + 1):
        t = 0.5 * math.pi * j / nt
        for i in range(nr + 1):
            r = a + (b - a) * i / nr
            lines.append(f"{nid(nr, i, j)}, {r * math.cos(t):.15g}, {r * math.sin(t):.15g}, 0")
    lines.append("*ELEMENT, TYPE=CPE4, ELSET=RING")
    for j in range(nt):
        for i in range(nr):
            lines.append(f"{cell(nr, i, j)}, {nid(nr, i, j)}, {nid(nr, i + 1, j)}, "
                         f"{nid(nr, i + 1, j + 1)}, {nid(nr, i, j + 1)}")
    lines += ["*NSET, NSET=XAXIS"] + [f"{nid(nr, i, 0)}," for i in range(nr + 1)]
    lines += ["*NSET, NSET=YAXIS"] + [f"{nid(nr, i, nt)}," for i in range(nr + 1)]
    lines += ["*NSET, NSET=INNER"] + [f"{nid(nr, 0, j)}," for j in range(nt + 1)]
    lines += ["*NSET, NSET=OUTER"] + [f"{nid(nr, nr, j)}," for j in range(nt + 1)]
    return lines


def inner_pressure(nr, nt, p):
    """*DLOAD lines of a pressure p on the edge at r = a."""
    return [f"{cell(nr, 0, j)}, P4, {p}" for j in range(nt)]
