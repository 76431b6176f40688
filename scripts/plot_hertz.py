#!/usr/bin/python3
"""Plots of a results folder (and of several, in the style of the seed's Fig. 2).

Usage:
  plot_hertz.py RESULTS_DIR                       contact_pressure.png (against McEwen for
                                                  hertz, against Hertz's p(r) for hertz3d)
                                                  and iterations.png; with friction
                                                  shear_traction.png (against Cattaneo-
                                                  Mindlin for hertz with a tangential load)
  plot_hertz.py --figure OUT.png --title T DIR... pressure of several runs (e.g. five
                                                  penalties), labelled by their summary.json
Reads contact_pressure.csv, history.csv and summary.json; writes PNG.
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
    return "SMALBE-M, rho = %g, %s displacements" % (summary.get("rho", float("nan")),
                                                     summary.get("displacements", "?"))


def plot(folders, out, title):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    analytic_drawn = False
    for folder in folders:
        rows, summary = read_run(folder)
        # Older folders name the analytic column after McEwen.
        analytic_key = "pressure_analytic_Pa" if "pressure_analytic_Pa" in rows[0] else "pressure_mcewen_Pa"
        deformed = summary.get("hertz", {}).get("frame") == "deformed" and "x_deformed_m" in rows[0]
        # 3D results (one row per node, y varies): plot against the distance from the z axis.
        three_d = summary.get("problem") == "hertz3d" or len({r.get("y_m", "0") for r in rows}) > 1
        if three_d:
            xk, yk = ("x_deformed_m", "y_deformed_m") if deformed else ("x_m", "y_m")
            x = [1e3 * (float(r[xk]) ** 2 + float(r[yk]) ** 2) ** 0.5 for r in rows]
            ax.set_xlabel("distance from the axis%s (mm)" % (", deformed" if deformed else ""))
        else:
            # Large displacements: pressure and McEwen's profile at the deformed x + u_x.
            x = [1e3 * float(r["x_deformed_m" if deformed else "x_m"]) for r in rows]
            if deformed:
                ax.set_xlabel("deformed x + u_x (mm)")
        p = [1e-6 * float(r["pressure_multipliers_Pa"]) for r in rows]
        pa = [1e-6 * float(r[analytic_key]) for r in rows]
        if not analytic_drawn and any(pa):
            if three_d:
                a = 1e3 * summary["hertz"]["a_analytic"]
                p0 = 1e-6 * summary["hertz"]["p0_analytic"]
                rs = [a * 1.2 * k / 200 for k in range(201)]
                ax.plot(rs, [p0 * max(0.0, 1 - (r / a) ** 2) ** 0.5 for r in rs], "k-", lw=2,
                        label="Hertz (analytic)")
                ax.set_xlim(0, 2 * a)
            else:
                ax.plot(x, pa, "k-", lw=2, label="McEwen (analytic)")
                ax.set_xlim(-100 if min(x) < 0 else 0, 100)  # the full model with a tangential load
            analytic_drawn = True
        ax.plot(x, p, "o" if three_d else "o-", ms=3, lw=1, label=label_of(summary))
    if not ax.get_xlabel():
        ax.set_xlabel("x (mm)")
    ax.set_ylabel("normal contact pressure (MPa)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print("wrote", out)


def plot_shear(folder):
    """Shear traction along x of a run with friction, sliding node lines marked, against
    Cattaneo-Mindlin's when the run compared with it."""
    rows, summary = read_run(folder)
    if "shear_x_Pa" not in rows[0]:
        return
    friction = summary.get("hertz", {}).get("friction")
    x = [1e3 * float(r["x_m"]) for r in rows]
    q = [1e-6 * float(r["shear_x_Pa"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    if friction:
        ax.plot(x, [1e-6 * float(r["shear_analytic_x_Pa"]) for r in rows], "k-", lw=2,
                label="Cattaneo-Mindlin, c = %.1f mm" % (1e3 * friction["stick_half_width_analytic"]))
        a = 1e3 * summary["hertz"]["a_analytic"]
        ax.set_xlim(-1.5 * a, 1.5 * a)
    ax.plot(x, q, "o-", ms=3, lw=1, label="feticon")
    slid = [(xi, qi) for xi, qi, r in zip(x, q, rows) if r["slip"] == "1"]
    if slid:
        ax.plot([s[0] for s in slid], [s[1] for s in slid], "rx", ms=5, label="sliding")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("shear traction on the slave surface, along x (MPa)")
    title = "Friction"
    if friction:
        title = "Cattaneo-Mindlin, mu = %g: c computed %.1f mm" % (
            friction["coefficient"], 1e3 * friction["stick_half_width_computed"])
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(folder, "shear_traction.png")
    fig.savefig(out, dpi=130)
    print("wrote", out)


def plot_history(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    n = range(1, len(rows) + 1)
    ax.bar(n, [int(r["mprgp_iterations"]) for r in rows], color="tab:blue", alpha=0.6)
    ax.set_xlabel("outer iteration (all load steps)")
    ax.set_ylabel("MPRGP steps", color="tab:blue")
    right = ax.twinx()
    right.semilogy(n, [max(float(r["displacement_change"]), 1e-16) for r in rows], "ko-", ms=3)
    right.set_ylabel("|du| / |u|")
    ax.set_title("Iterations")
    fig.tight_layout()
    out = os.path.join(folder, "iterations.png")
    fig.savefig(out, dpi=130)
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--figure")
    parser.add_argument("--title", default="Normal contact pressure")
    args = parser.parse_args()
    if args.figure:
        plot(args.folders, args.figure, args.title)
        return
    plot(args.folders, os.path.join(args.folders[0], "contact_pressure.png"), args.title)
    plot_history(args.folders[0])
    plot_shear(args.folders[0])


if __name__ == "__main__":
    sys.exit(main())
