#!/usr/bin/python3
"""Writes a CalculiX input deck of two stacked hex8 boxes for bench/deck_read.sh: each box
NX x NY x NZ C3D8 cells on a unit-spaced grid, the upper one resting on the lower one; node
and element sets, a surface-to-surface contact pair (upper box's bottom on the lower box's
top), *BOUNDARY on the lower box's bottom (fixed) and the upper box's top (pressed down by
0.01 with x and y held), and a *DLOAD pressure on the upper box's top.

With --stop-after-reading a second pair line names the slave surface as its own master:
feticon refuses it once the mesh, sets and surfaces are built, so that a run of the deck
measures reading alone, before the solver allocates anything.

Usage: make_big_deck.py OUT.inp [--cells NX NY NZ] [--stop-after-reading]
       (default cells 99 99 49: 2 x 100x100x50 = 1 000 000 nodes)
"""
import argparse
import sys


def write_box(out, first_node, first_cell, cells, z0):
    nx, ny, nz = cells
    px, py = nx + 1, ny + 1

    def node(i, j, k):
        return first_node + i + px * (j + py * k)

    out.write("*NODE, NSET=N%d\n" % first_node)
    lines = []
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                lines.append("%d, %.6f, %.6f, %.6f\n" % (node(i, j, k), i, j, z0 + k))
            if len(lines) > 100000:
                out.writelines(lines)
                lines = []
    out.writelines(lines)
    out.write("*ELEMENT, TYPE=C3D8, ELSET=E%d\n" % first_cell)
    lines = []
    cell = first_cell
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                n = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                     node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                     node(i, j + 1, k + 1)]
                lines.append("%d, %s\n" % (cell, ", ".join(map(str, n))))
                cell += 1
            if len(lines) > 100000:
                out.writelines(lines)
                lines = []
    out.writelines(lines)
    n_nodes = px * py * (nz + 1)
    n_cells = nx * ny * nz
    bottom = [first_cell + i + nx * j for j in range(ny) for i in range(nx)]
    top = [first_cell + i + nx * (j + ny * (nz - 1)) for j in range(ny) for i in range(nx)]
    bottom_nodes = [node(i, j, 0) for j in range(py) for i in range(px)]
    top_nodes = [node(i, j, nz) for j in range(py) for i in range(px)]
    return n_nodes, n_cells, bottom, top, bottom_nodes, top_nodes


def write_set(out, keyword, members):
    out.write(keyword + "\n")
    for s in range(0, len(members), 16):
        out.write(", ".join(map(str, members[s:s + 16])) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out")
    parser.add_argument("--cells", type=int, nargs=3, default=[99, 99, 49])
    parser.add_argument("--stop-after-reading", action="store_true")
    args = parser.parse_args()
    cells = args.cells
    with open(args.out, "w") as out:
        out.write("*HEADING\nbench/make_big_deck.py: two stacked boxes of %d x %d x %d cells\n" % tuple(cells))
        n_lower, c_lower, lower_bottom, lower_top, lower_bottom_nodes, _ = write_box(out, 1, 1, cells, 0.0)
        n_upper, c_upper, upper_bottom, upper_top, _, upper_top_nodes = write_box(
            out, n_lower + 1, c_lower + 1, cells, float(cells[2]))
        write_set(out, "*NSET, NSET=FIXED", lower_bottom_nodes)
        write_set(out, "*NSET, NSET=PRESSED", upper_top_nodes)
        write_set(out, "*ELSET, ELSET=LOWER_TOP", lower_top)
        write_set(out, "*ELSET, ELSET=UPPER_BOTTOM", upper_bottom)
        write_set(out, "*ELSET, ELSET=UPPER_TOP", upper_top)
        out.write("*ELSET, ELSET=EALL\nE1, E%d\n" % (c_lower + 1))
        out.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n")
        out.write("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n")
        # C3D8 faces: S1 is the bottom (nodes 1-2-3-4), S2 the top (5-8-7-6).
        out.write("*SURFACE, NAME=MASTER\nLOWER_TOP, S2\n")
        out.write("*SURFACE, NAME=SLAVE\nUPPER_BOTTOM, S1\n")
        out.write("*SURFACE INTERACTION, NAME=SI1\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n")
        out.write("*CONTACT PAIR, INTERACTION=SI1, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n")
        if args.stop_after_reading:
            out.write("SLAVE, SLAVE\n")
        out.write("*BOUNDARY\nFIXED, 1, 3\nPRESSED, 1, 2\nPRESSED, 3, 3, -0.01\n")
        out.write("*STEP\n*STATIC\n*DLOAD\nUPPER_TOP, P2, 10.\n*END STEP\n")
    print("%s: %d nodes, %d C3D8 cells" % (args.out, n_lower + n_upper, c_lower + c_upper),
          file=sys.stderr)


if __name__ == "__main__":
    main()
