#!/usr/bin/python3
"""First yield under a Hertz sphere (issue 66's acceptance): from a feticon run of the
exported hertz3d deck, the largest von Mises stress over the block's integration points
(.dat *EL PRINT S) and where it is; Johnson (Contact Mechanics, 6.2; nu = 0.3): first yield at
p0 = 1.60 Y, at depth 0.48 a on the axis. With a plastic run's .dat (*EL PRINT PEEQ) it also
prints the yielded points.

Usage: hertz_first_yield.py DECK DAT A P0
"""
import math
import re
import sys

deck, dat, a, p0 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])

nodes, elements = {}, {}
section = None
for line in open(deck):
    if line.startswith("*"):
        section = "node" if line.upper().startswith("*NODE") and "PRINT" not in line.upper() and "FILE" not in line.upper() else (
            "element" if line.upper().startswith("*ELEMENT") else None)
        continue
    if section == "node":
        f = line.split(",")
        nodes[int(f[0])] = tuple(float(v) for v in f[1:4])
    elif section == "element":
        f = [int(v) for v in line.replace(",", " ").split()]
        elements[f[0]] = f[1:]

# ccx's integration point j of a C3D8 is feticon's point [0, 1, 3, 2, 4, 5, 7, 6][j], at
# +-1/sqrt(3) towards the corner of that number (VTK order = ccx's node order).
corners = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
feticon_point = [0, 1, 3, 2, 4, 5, 7, 6]
g = 1 / math.sqrt(3)


def point(element, j):
    xi = [g * c for c in corners[feticon_point[j - 1]]]
    x = [0.0, 0.0, 0.0]
    for n, r in zip(elements[element], corners):
        w = (1 + r[0] * xi[0]) * (1 + r[1] * xi[1]) * (1 + r[2] * xi[2]) / 8
        for k in range(3):
            x[k] += w * nodes[n][k]
    return x


text = open(dat).read()
block = re.search(r"stresses \(elem, integ\.pnt\.,sxx,syy,szz,sxy,sxz,syz\) for set B_BLOCK and time\s+\S+\n\n((?:.+\n)+)", text)
best = (0, None)
for line in block.group(1).splitlines():
    f = line.split()
    sxx, syy, szz, sxy, sxz, syz = (float(v) for v in f[2:8])
    mises = math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * (sxy**2 + sxz**2 + syz**2))
    if mises > best[0]:
        best = (mises, (int(f[0]), int(f[1])))
x = point(*best[1])
print(f"largest von Mises {best[0]:.5e} Pa at element {best[1][0]} point {best[1][1]}: r = {math.hypot(x[0], x[1]) / a:.3f} a, "
      f"depth {-x[2] / a:.3f} a (Johnson 0.48 a)")
print(f"first yield at p0 = {p0 / best[0]:.4f} Y (Johnson 1.60 Y: {p0 / best[0] / 1.60 - 1:+.2%})")
peeq = re.findall(r"equivalent plastic strain \(elem, integ\.pnt\.,pe\)for set B_BLOCK and time\s+\S+\n\n((?:.+\n)+)", text)
if peeq:
    yielded = [(float(l.split()[2]), int(l.split()[0]), int(l.split()[1])) for l in peeq[-1].splitlines() if float(l.split()[2]) > 0]
    print(f"{len(yielded)} yielded points")
    if yielded:
        e, el, j = max(yielded)
        x = point(el, j)
        depths = [-point(el_, j_)[2] / a for _, el_, j_ in yielded]
        print(f"largest PEEQ {e:.3e} at r = {math.hypot(x[0], x[1]) / a:.3f} a, depth {-x[2] / a:.3f} a; yielded depths "
              f"{min(depths):.3f} a to {max(depths):.3f} a")
