#!/usr/bin/python3
"""The contact pressure under the Hertz sphere above first yield (issue 66's acceptance; run by
bench/hertz_first_yield.sh --calculix): feticon's and CalculiX's .frd of the identical deck, the
pressure (CONTACT block, CPRESS) of every slave node against its distance r from the contact
axis (the z axis: hertz3d's quarter model), and Hertz's elastic p0 sqrt(1 - r^2 / a^2) beside
them. Prints the peaks, the contact radii (the largest r with p > 0), the largest and RMS
difference of the two codes over the nodes within 1.2 a (relative to p0), and each code's
departure from the elastic profile (the flattening that yield makes).

With the elastic runs' .frd files too, the change yield makes at each node (plastic minus
elastic pressure) in one code against the other: that cancels what the codes' contact
discretizations differ by in both runs.

Usage: hertz_plastic_profile.py DECK FETICON.frd CALCULIX.frd A P0 [FETICON_ELASTIC.frd CALCULIX_ELASTIC.frd]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from calculix_compare import read_frd_last  # noqa: E402


def node_coordinates(deck):
    nodes, reading = {}, False
    for line in open(deck):
        if line.startswith("*"):
            upper = line.upper()
            reading = upper.startswith("*NODE") and "PRINT" not in upper and "FILE" not in upper
            continue
        if reading:
            f = line.split(",")
            nodes[int(f[0])] = tuple(float(v) for v in f[1:4])
    return nodes


def profile(frd, nodes):
    """{node: (r, p)} of every node with a pressure."""
    contact = read_frd_last(frd, "CONTACT")
    return {n: (math.hypot(nodes[n][0], nodes[n][1]), v[3]) for n, v in contact.items() if v[3] > 0}


def main(deck, feticon_frd, calculix_frd, a, p0):
    nodes = node_coordinates(deck)
    mine, theirs = profile(feticon_frd, nodes), profile(calculix_frd, nodes)
    elastic = lambda r: p0 * math.sqrt(max(0.0, 1 - (r / a) ** 2))
    for name, prof in (("feticon", mine), ("CalculiX", theirs)):
        r_peak, peak = max(prof.values(), key=lambda rp: rp[1])
        departure = max(abs(p - elastic(r)) for r, p in prof.values() if r <= 1.2 * a) / p0
        print(f"{name}: peak {peak / p0:.4f} p0 at r = {r_peak / a:.3f} a, contact radius "
              f"{max(r for r, p in prof.values()) / a:.3f} a, largest departure from the elastic profile "
              f"{departure:.3f} p0 ({len(prof)} nodes)")
    # Node by node (the same deck) within 1.2 a, a node pressed in one code only counting its pressure.
    radius = lambda n: math.hypot(nodes[n][0], nodes[n][1])
    pressed = sorted(n for n in set(mine) | set(theirs) if radius(n) <= 1.2 * a)
    differences = [mine.get(n, (0, 0.0))[1] - theirs.get(n, (0, 0.0))[1] for n in pressed]
    rms = math.sqrt(sum(d * d for d in differences) / len(differences))
    worst = max(range(len(pressed)), key=lambda k: abs(differences[k]))
    print(f"feticon - CalculiX over {len(pressed)} nodes within 1.2 a: RMS {rms / p0:.4f} p0, largest "
          f"{differences[worst] / p0:+.4f} p0 at r = {radius(pressed[worst]) / a:.3f} a")


def yield_change(deck, plastic, elastic, a, p0):
    """Plastic minus elastic pressure per node, feticon's against CalculiX's."""
    nodes = node_coordinates(deck)
    pressure = lambda frd: {n: p for n, (r, p) in profile(frd, nodes).items()}
    change = [{n: pl.get(n, 0.0) - el.get(n, 0.0) for n in set(pl) | set(el)}
              for pl, el in ((pressure(plastic[k]), pressure(elastic[k])) for k in range(2))]
    radius = lambda n: math.hypot(nodes[n][0], nodes[n][1])
    pressed = sorted(n for n in set(change[0]) | set(change[1]) if radius(n) <= 1.2 * a)
    differences = [change[0].get(n, 0.0) - change[1].get(n, 0.0) for n in pressed]
    rms = math.sqrt(sum(d * d for d in differences) / len(differences))
    on_axis = min(pressed, key=radius)
    print(f"yield's change of the pressure (plastic - elastic): on the axis feticon {change[0].get(on_axis, 0.0) / p0:+.4f} "
          f"p0, CalculiX {change[1].get(on_axis, 0.0) / p0:+.4f} p0; the codes' changes differ by RMS {rms / p0:.4f} p0, "
          f"largest {max(differences, key=abs) / p0:+.4f} p0 over {len(pressed)} nodes within 1.2 a")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]))
    if len(sys.argv) == 8:
        yield_change(sys.argv[1], sys.argv[2:4], sys.argv[6:8], float(sys.argv[4]), float(sys.argv[5]))
