#!/usr/bin/python3
"""Plots of the Hertz benchmark in the style of the seed's Fig. 2.

Usage:
  plot_hertz.py RESULTS_DIR                       pressure of one run vs McEwen
  plot_hertz.py --figure OUT.png --title T DIR... several runs (e.g. five penalties),
                                                  labelled by their summary.json
Reads contact_pressure.csv and summary.json of each folder; writes PNG.
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_run(folder):
    with open(os.path.join(folder, "contact_pressure.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    return rows, summary


def label_of(summary):
    method = summary.get("method", "?")
    if method == "primal_penalty":
        return "primal penalty, eps_n = %.2g N/m" % summary.get("eps_n", float("nan"))
    if method == "dual_penalty":
        return "dual penalty, rho = %g" % summary.get("rho", float("nan"))
    return "SMALBE-M, rho = %g" % summary.get("rho", float("nan"))


def plot(folders, out, title):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    analytic_drawn = False
    for folder in folders:
        rows, summary = read_run(folder)
        x = [1e3 * float(r["x_m"]) for r in rows]
        p = [1e-6 * float(r["pressure_multipliers_Pa"]) for r in rows]
        if not analytic_drawn:
            pa = [1e-6 * float(r["pressure_mcewen_Pa"]) for r in rows]
            ax.plot(x, pa, "k-", lw=2, label="McEwen (analytic)")
            analytic_drawn = True
        ax.plot(x, p, "o-", ms=3, lw=1, label=label_of(summary))
    ax.set_xlim(0, 100)
    ax.set_xlabel("x from the plane of symmetry (mm)")
    ax.set_ylabel("normal contact pressure (MPa)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--figure")
    parser.add_argument("--title", default="Hertz contact: normal pressure")
    args = parser.parse_args()
    out = args.figure or os.path.join(args.folders[0], "hertz_pressure.png")
    plot(args.folders, out, args.title)


if __name__ == "__main__":
    sys.exit(main())
