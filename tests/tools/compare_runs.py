#!/usr/bin/python3
"""Compares two feticon results folders of the same problem run on different numbers of MPI
ranks (or from a deck and the deck `feticon export` writes of it): the iteration records must be
equal (spectrum estimates to 1e-6) and the displacement equal to RTOL relative.

Usage: compare_runs.py RTOL DIR_A DIR_B [--answer]
--answer compares the displacement alone (both converged): a deck written back by `feticon
export` rounds coordinates to 13 digits, which may move a QP's operator products.
The displacement is the global stacked vector (every subdomain's copy of every node) of the
last converged step, read from checkpoint.bin: magic "FETICKP1", then int64 count and that
many float64 values. Its layout is independent of the rank count, so the vectors compare
entry by entry.
"""
import json
import struct
import sys

import numpy


def stacked_displacement(folder):
    with open(folder + "/checkpoint.bin", "rb") as f:
        assert f.read(8) == b"FETICKP1", folder + ": not a feticon checkpoint"
        (count,) = struct.unpack("<q", f.read(8))
        return numpy.frombuffer(f.read(8 * count), dtype="<f8")


def records(folder):
    summary = json.load(open(folder + "/summary.json"))
    assert summary["converged"] is True, folder + " did not converge"
    steps = [(s["outer_iterations"], s["inner_iterations"]) for s in summary["steps"]]
    return summary, steps


def same_counters(x, y):
    """The QP records agree: counters exactly, the spectrum estimates (floats) to 1e-6 relative
    (a deck written back with 13 digits moves them in the last digits)."""
    if isinstance(x, dict) and isinstance(y, dict):
        return x.keys() == y.keys() and all(same_counters(x[k], y[k]) for k in x)
    if isinstance(x, float) and isinstance(y, float):
        return abs(x - y) <= 1e-6 * max(abs(x), abs(y))
    return x == y


def main(rtol, a, b, answer_only=False):
    summary_a, steps_a = records(a)
    summary_b, steps_b = records(b)
    if not answer_only:
        assert steps_a == steps_b, f"iteration counts differ: {steps_a} vs {steps_b}"
        assert same_counters(summary_a["qp"], summary_b["qp"]), \
            f"QP counters differ: {summary_a['qp']} vs {summary_b['qp']}"
    u_a, u_b = stacked_displacement(a), stacked_displacement(b)
    assert u_a.shape == u_b.shape and u_a.size > 0
    difference = numpy.abs(u_a - u_b).max() / numpy.abs(u_a).max()
    assert difference <= rtol, f"displacements differ by {difference:.3e} relative (> {rtol})"
    same = "" if answer_only else f"same iterations {steps_b}, "
    print(f"{b}: {same}displacement difference {difference:.3e} relative "
          f"(ranks {summary_a.get('ranks')} vs {summary_b.get('ranks')})")


if __name__ == "__main__":
    main(float(sys.argv[1]), sys.argv[2], sys.argv[3], "--answer" in sys.argv[4:])
