#!/usr/bin/python3
"""The last DISP block of a .frd against the displacement of a feticon VTU, node by node (the
.frd lists nodes in mesh order, as the VTU points are): equal to the .frd's printed digits
(%12.5E of the value rounded to float: relative 5e-6, plus the float's subnormal floor).

    frd_vs_vtu.py RUN.frd step_001.vtu       exit 1 if a value differs
"""
import sys


import read_vtu


def frd_displacements(path):
    """[(label, d1, d2, d3)] of the last DISP block."""
    blocks, rows, inside = [], None, False
    for line in open(path):
        if line.startswith(" -4  DISP"):
            rows, inside = [], True
            blocks.append(rows)
        elif inside and line.startswith(" -1"):
            rows.append((int(line[3:13]), *(float(line[13 + 12 * k:25 + 12 * k]) for k in range(3))))
        elif inside and line.startswith(" -3"):
            inside = False
    if not blocks:
        sys.exit(f"{path}: no DISP block")
    return blocks[-1]


def vtu_displacements(path):
    arrays = read_vtu.point_data(path)
    if "displacement" not in arrays:
        sys.exit(f"{path}: no displacement array")
    return arrays["displacement"]


def main(frd, vtu):
    printed = frd_displacements(frd)
    exact = vtu_displacements(vtu)
    assert len(printed) == len(exact), f"{len(printed)} .frd nodes, {len(exact)} VTU points"
    worst = 0.0
    for (label, *d), u in zip(printed, exact):
        for a, b in zip(d, u):
            worst = max(worst, abs(a - b) / (5.01e-6 * abs(b) + 1e-37))
    print(f"{len(printed)} nodes: largest difference {worst:.3g} of the printed precision")
    return 0 if worst <= 1 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
