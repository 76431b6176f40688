#!/usr/bin/python3
"""feticon's answer to one of CalculiX's contact test decks (tests/data/calculix), checked
against two references that nobody on feticon wrote into feticon:

  exact   an independent exact-contact solve of the same deck (tests/data/calculix/
          exact_contact_estimate.py: dense numpy hex8, node-to-surface, active set by the
          multipliers' sign): feticon must agree to `--exact-rtol` of max |u|;
  ccx     CalculiX's reference output (DECK.dat.ref): it differs by the penetration its
          penalty law allows, so |u_feticon - u_ccx| must stay below a few times the
          penetration CalculiX printed (reference.json: penalty.penetration_cdis_max);
and equilibrium: the contact force equals the independent solve's, and where the deck prints
RF, the reactions at the supports balance the applied load.

    check_calculix_example.py DECK_NAME FETICON_OUTPUT_FOLDER [--exact-rtol R] [--force-rtol R] [--json]
(defaults 1e-6: a small-displacement run; with NLGEOM the exact solve, which is linear, is no
reference, and the caller loosens both)
Exit 1 with the figures on stderr if a check fails; the figures as one JSON line with --json.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data", "calculix")
sys.path.insert(0, HERE)
sys.path.insert(0, DATA)
from calculix_dat import parse_dat, read_inp, summary, applied_loads  # noqa: E402
import exact_contact_estimate  # noqa: E402


def last_displacements(dat):
    """{node label: (ux, uy, uz)} of the last displacement blocks of a parsed .dat."""
    out = {}
    for b in dat["blocks"]:
        if b["kind"] == "displacements":
            out.update({r[0]: r[1:4] for r in b["rows"]})
    return out


def main(argv):
    name, folder = argv[1], argv[2]
    exact_rtol = float(argv[argv.index("--exact-rtol") + 1]) if "--exact-rtol" in argv else 1e-6
    force_rtol = float(argv[argv.index("--force-rtol") + 1]) if "--force-rtol" in argv else 1e-6
    deck_path = os.path.join(DATA, name + ".inp")
    reference = json.load(open(os.path.join(DATA, "reference.json")))["decks"][name]
    mine = last_displacements(parse_dat(os.path.join(folder, name + ".dat")))
    ccx = last_displacements(parse_dat(os.path.join(DATA, name + ".dat.ref")))
    exact_u, exact_forces = exact_contact_estimate.solve(deck_path)
    nodes = sorted(set(mine) & set(ccx))
    if not nodes:
        print(f"{name}: no printed displacement in both feticon's .dat and the reference", file=sys.stderr)
        return 1
    scale = max(max(abs(v) for v in exact_u[n]) for n in nodes)
    err_exact = max(max(abs(a - b) for a, b in zip(mine[n], exact_u[n])) for n in nodes) / scale
    diff_ccx = max(max(abs(a - b) for a, b in zip(mine[n], ccx[n])) for n in nodes)
    penetration = reference["penalty"]["penetration_cdis_max"]
    run = json.load(open(os.path.join(folder, "summary.json")))
    force = run["contact"]["total_normal_force"]
    exact_force = sum(exact_forces.values())
    figures = {"deck": name, "nodes_compared": len(nodes), "max_abs_u": scale,
               "error_vs_exact_over_max_u": err_exact, "diff_vs_ccx": diff_ccx,
               "ccx_penetration": penetration, "diff_vs_ccx_over_penetration": diff_ccx / penetration,
               "contact_force": force, "contact_force_exact": exact_force,
               "mprgp_steps": run["qp"].get("iterations")}
    failures = []
    if err_exact > exact_rtol:
        failures.append(f"error against the exact-contact solve {err_exact:.3g} > {exact_rtol:g} of max |u|")
    if diff_ccx > 3 * penetration + exact_rtol * scale:
        failures.append(f"difference to CalculiX {diff_ccx:.3g} m > 3 x its penetration {penetration:.3g} m")
    if abs(force - exact_force) > force_rtol * abs(exact_force):
        failures.append(f"contact force {force:.9g} N differs from the exact solve's {exact_force:.9g} N")
    deck = read_inp(deck_path)
    forces = summary(os.path.join(folder, name + ".dat"), deck).get("forces", {})
    applied = applied_loads(deck)["steps"][-1]["total"]
    for setname, entry in forces.items():
        if all(entry["reaction_nodes_printed"][d] == entry["reaction_nodes_held"][d] for d in range(3)):
            imbalance = max(abs(r + a) for r, a in zip(entry["reaction"], applied))
            figures["reaction_imbalance"] = imbalance
            if imbalance > 1e-6 * max(abs(a) for a in applied):
                failures.append(f"reactions {entry['reaction']} do not balance the applied load {applied}")
    if "--json" in argv:
        print(json.dumps(figures))
    for f in failures:
        print(f"{name}: {f}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
