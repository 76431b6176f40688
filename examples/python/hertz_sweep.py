#!/usr/bin/python3
"""feticon from Python: the Hertz benchmark, then a sweep of its load against Hertz's formula.

Run from a build tree (the module is built by the test command, or `cmake --build build
--target _feticon`):
    PYTHONPATH=build/python /usr/bin/python3 examples/python/hertz_sweep.py [--out DIR]
or after `cmake --install build` with no PYTHONPATH. Writes DIR/hertz_sweep.png (default: the
current folder) and prints one line per load.
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import feticon

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default=".", help="folder for hertz_sweep.png")
parser.add_argument("--loads", type=int, default=5, help="number of line loads in the sweep")
args = parser.parse_args()

# 1. The benchmark as the main job runs it: no files, the results in memory.
result = feticon.run()
hertz = result.summary["hertz"]
print(f"Hertz benchmark: p_peak {hertz['p_peak_computed']:.6e} Pa, analytic p0 {hertz['p0_analytic']:.6e} Pa, "
      f"{result.summary['qp']['iterations']} MPRGP iterations, {result.displacements.shape[0]} nodes")

# 2. The pressure along the contact of that run, from the contact columns.
contact = result.pair_pressure(0)

# 3. The sweep: p0 grows as sqrt(Q) (Hertz: p0 = sqrt(Q E* / (pi R))).
loads = np.linspace(1e8, 4e8, args.loads)
computed, analytic = [], []
for q in loads:
    r = feticon.run(settings={"hertz.line_load": q})
    computed.append(r.summary["hertz"]["p_peak_computed"])
    analytic.append(r.summary["hertz"]["p0_analytic"])
    print(f"Q = {q:.3e} N/m: p_peak {computed[-1]:.6e} Pa, Hertz p0 {analytic[-1]:.6e} Pa, "
          f"difference {(computed[-1] - analytic[-1]) / analytic[-1]:+.2%}")

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot(contact["x"] * 1e3, contact["pressure"] / 1e6, "o", ms=3, label="feticon (multipliers)")
left.set_xlabel("x (mm)")
left.set_ylabel("contact pressure (MPa)")
left.set_title("Hertz benchmark, Q = 4e8 N/m")
left.legend()
right.plot(loads, np.array(analytic) / 1e6, "-", label="Hertz's formula")
right.plot(loads, np.array(computed) / 1e6, "o", label="feticon")
right.set_xlabel("line load Q (N/m)")
right.set_ylabel("peak pressure p0 (MPa)")
right.set_title("load sweep")
right.legend()
fig.tight_layout()
path = os.path.join(args.out, "hertz_sweep.png")
fig.savefig(path, dpi=120)
print(f"wrote {path}")
