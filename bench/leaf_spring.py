#!/usr/bin/python3
"""A pack of stacked leaves (issue 63's assembly yardstick): eight flat steel plates 0.5 x 0.04 x
0.008 m (a quarter model: symmetry planes x = 0 and y = 0), non-matching meshes from one leaf
to the next (60 x 6 x 4 and 50 x 5 x 4 cells times SCALE), the bottom leaf held at its far end
(x = 0.5 m, u_z = 0), 2e5 Pa pressing the top leaf down, seven frictionless mortar pairs, each
upper leaf held by contact alone. Writes the problem file to stdout.

    bench/leaf_spring.py SCALE > leaves.yaml
    build/feticon run leaves.yaml                      # subdomains = auto
    build/feticon export leaves.yaml --format calculix -o deck && ccx -i deck/feticon

SCALE 1: 43 980 DOFs; the DOFs grow as SCALE^3.
"""
import sys


def main(scale):
    leaves, length, width, thickness = 8, 0.5, 0.04, 0.008
    lines = ["problem: custom", "mesh:", "  boxes:"]
    names = [f"leaf{k}" for k in range(leaves)]
    for k, name in enumerate(names):
        base = (60, 6, 4) if k % 2 == 0 else (50, 5, 4)
        cells = [max(1, round(c * scale)) for c in base]
        lines.append(f"    - {{name: {name}, origin: [0, 0, {k * thickness:.6g}], "
                     f"lengths: [{length}, {width}, {thickness}], cells: {cells}}}")
    lines.append("bodies:")
    lines += [f"  {name}: {{young: 2.1e11, poisson: 0.3}}" for name in names]
    lines.append("supports:")
    lines.append(f"  - {{set: {names[0]}_xmax, z: 0}}")
    for name in names:
        lines.append(f"  - {{set: {name}_xmin, x: 0}}")
        lines.append(f"  - {{set: {name}_ymin, y: 0}}")
    lines.append("loads:")
    lines.append(f"  - {{set: {names[-1]}_zmax, traction: [0, 0, -2e5]}}")
    lines.append("contact:")
    lines += [f"  - {{slave: {names[k]}_zmin, master: {names[k - 1]}_zmax}}" for k in range(1, leaves)]
    lines.append("displacements: small")
    print("\n".join(lines))


if __name__ == "__main__":
    main(float(sys.argv[1]) if len(sys.argv) > 1 else 1.0)
