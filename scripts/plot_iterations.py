#!/usr/bin/python3
"""Seed Fig. 3a/3b and the tables of the rho sweeps, from the folders of seed-figures.sh.

Usage: plot_iterations.py FIGURES_DIR
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RHOS = [1, 10, 100, 1000, 10000]


def load(folder):
    path = os.path.join(folder, "summary.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        summary = json.load(f)
    with open(os.path.join(folder, "history.csv")) as f:
        history = list(csv.DictReader(f))
    return summary, history


def table(out, prefix, title):
    print("\n" + title)
    print("%8s %12s %10s %10s %10s %9s %12s %10s" % ("rho", "feasibility", "p_peak/p0", "MPRGP", "CG", "expansion",
                                                     "products", "dual s"))
    for rho in RHOS:
        run = load(os.path.join(out, "%s_%d" % (prefix, rho)))
        if run is None:
            print("%8g   (failed)" % rho)
            continue
        s, _ = run
        q, h = s["qp"], s.get("hertz", {})
        print("%8g %12.2e %10.4f %10d %10d %9d %12d %10.2f" % (
            rho, s["contact"]["feasibility_error"], h.get("p_peak_computed", 0) / h.get("p0_analytic", 1),
            q["iterations"], q["cg_steps"], q["expansion_steps"], q["hessian_multiplications"],
            s["timings_seconds"].get("dual solve (MPRGP)", 0)))


def main():
    out = sys.argv[1]
    table(out, "dual", "Small displacements, dual penalty (MPRGP on problem (9))")
    table(out, "smalbe", "Small displacements, SMALBE-M")
    table(out, "large_dual", "Large displacements, dual penalty")
    table(out, "large_smalbe", "Large displacements, SMALBE-M")

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for prefix, style in (("large_smalbe", "o-"), ("large_dual", "s--")):
        run = load(os.path.join(out, "%s_1" % prefix))
        if run is None:
            continue
        _, history = run
        steps = [int(h["mprgp_iterations"]) for h in history]
        ax.plot(range(1, len(steps) + 1), steps, style,
                label=("SMALBE-M" if prefix == "large_smalbe" else "dual penalty") + ", rho = 1")
    ax.set_xlabel("outer iteration (all load steps)")
    ax.set_ylabel("MPRGP steps")
    ax.set_title("Inner iterations per outer cycle (seed Fig. 3a)")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig3a_inner_iterations.png"), dpi=130)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for prefix, style, label in (("large_smalbe", "o-", "SMALBE-M"), ("large_dual", "s--", "dual penalty")):
        xs, ys = [], []
        for rho in RHOS:
            run = load(os.path.join(out, "%s_%d" % (prefix, rho)))
            if run is not None and run[0]["converged"]:
                xs.append(rho)
                ys.append(run[0]["qp"]["iterations"])
        ax.semilogx(xs, ys, style, label=label)
    ax.set_xlabel("rho (dimensionless, F scaled by ||PFP||)")
    ax.set_ylabel("total MPRGP steps (all load steps)")
    ax.set_title("Iterations against the dual penalty (seed Fig. 3b)")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig3b_rho_sweep.png"), dpi=130)
    print("\nwrote fig3a_inner_iterations.png and fig3b_rho_sweep.png in", out)


if __name__ == "__main__":
    sys.exit(main())
