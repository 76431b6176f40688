"""Medians of the `feticon bench` JSON lines in RESULTS/raw (one file per case and
repetition, CASE.rep<i>.json), written as RESULTS/{contact,scalability,weak,mprgp}.csv and as
Markdown tables in RESULTS/tables.md (also printed). Called by bench/run.sh; rerun it alone
to regenerate the tables from the raw files: /usr/bin/python3 bench/summarize.py bench/results
"""
import csv
import json
import statistics
import sys
from collections import defaultdict
from pathlib import Path


def flatten(record, prefix=""):
    """Nested JSON objects as one level of dotted keys."""
    out = {}
    for key, value in record.items():
        if isinstance(value, dict):
            out.update(flatten(value, prefix + key + "."))
        else:
            out[prefix + key] = value
    return out


def medians(raw_dir):
    """Case name -> {key: median over repetitions (numbers) or first value}, plus 'reps'."""
    runs = defaultdict(list)
    for path in sorted(raw_dir.glob("*.rep*.json")):
        text = path.read_text().strip()
        if text:
            runs[path.name.rsplit(".rep", 1)[0]].append(flatten(json.loads(text)))
    cases = {}
    for name, records in runs.items():
        merged = {"reps": len(records)}
        for key in records[0]:
            values = [r[key] for r in records if key in r]
            numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values)
            merged[key] = statistics.median(values) if numeric else values[0]
        cases[name] = merged
    return cases


# Column title -> function of a case's medians.
# Phases inside "total solve" (all but mesh); "other (outer loop)" is the rest of the outer
# loop: residuals, primal recovery, the gathers for the contact search, convergence tests.
INNER_PHASES = ["decomposition", "assembly", "factorization", "preconditioner setup", "explicit operators", "coarse problem",
                "contact search", "dual solve (MPRGP)", "internal forces"]
PHASES = ["mesh"] + INNER_PHASES + ["other (outer loop)", "total solve"]


def phase_seconds(case, phase):
    if phase == "other (outer loop)":
        return case["timings_seconds.total solve"] - sum(phase_seconds(case, p) for p in INNER_PHASES)
    return case.get("timings_seconds." + phase, 0.0)

CONTACT = {
    "size": lambda c: c["case"].split(".")[1],
    "displacements": lambda c: c["displacements"],
    "preconditioner": lambda c: c.get("preconditioner", "none"),
    "operator": lambda c: c.get("dual_operator", "implicit"),
    "DOFs": lambda c: c["degrees_of_freedom"],
    "subdomains": lambda c: c["subdomains"],
    "dual": lambda c: c["dual_size"],
    "outer": lambda c: c["qp.outer_iterations"],
    "MPRGP": lambda c: c["qp.iterations"],
    "F products": lambda c: c["qp.hessian_multiplications"],
    **{phase + " (s)": (lambda p: lambda c: phase_seconds(c, p))(phase) for phase in PHASES},
    "peak MiB": lambda c: c["peak_memory_bytes"] / 2**20,
    "direct assembly (s)": lambda c: c.get("direct.assembly_seconds", ""),
    "direct factorization (s)": lambda c: c.get("direct.factorization_seconds", ""),
    "direct solve (s)": lambda c: c.get("direct.solve_seconds", ""),
    "factor nnz": lambda c: c.get("direct.factor_nonzeros", ""),
    "contact / direct": lambda c: c.get("ratio_contact_to_direct", ""),
    "GAMG set-up + solve (s)": lambda c: (c["gamg.setup_seconds"] + c["gamg.solve_seconds"]
                                          if "gamg.setup_seconds" in c else ""),
    "GAMG CG iterations": lambda c: c.get("gamg.iterations", ""),
    "contact / GAMG": lambda c: c.get("ratio_contact_to_gamg", ""),
    "QP (s)": lambda c: c["qp_seconds"],
    "s / MPRGP iteration": lambda c: c["qp_seconds"] / max(c["qp.iterations"], 1),
    "s / H application": lambda c: c["seconds_per_operator_application"],
    "iteration / H application": lambda c: c["ratio_iteration_to_operator"],
    "s / preconditioner application": lambda c: c.get("seconds_per_preconditioner_application", 0.0),
    "iteration / (H + preconditioner)": lambda c: c.get("ratio_iteration_to_operator_and_preconditioner",
                                                         c["ratio_iteration_to_operator"]),
    "converged": lambda c: c["converged"],
    "reps": lambda c: c["reps"],
}
SCALABILITY = {
    "refinement": lambda c: c["case"].split(".")[1][1:],
    "preconditioner": lambda c: c.get("preconditioner", "none"),
    "operator": lambda c: c.get("dual_operator", "implicit"),
    "DOFs": lambda c: c["degrees_of_freedom"],
    "subdomains": lambda c: c["subdomains"],
    "dual": lambda c: c["dual_size"],
    "MPRGP": lambda c: c["qp.iterations"],
    "F products": lambda c: c["qp.hessian_multiplications"],
    "SMALBE outer": lambda c: c["qp.smalbe_outer_iterations"],
    "dual solve (s)": lambda c: c["timings_seconds.dual solve (MPRGP)"],
    "s / MPRGP iteration": lambda c: c["qp_seconds"] / max(c["qp.iterations"], 1),
    "iteration / H application": lambda c: c["ratio_iteration_to_operator"],
    "iteration / (H + preconditioner)": lambda c: c.get("ratio_iteration_to_operator_and_preconditioner",
                                                         c["ratio_iteration_to_operator"]),
    "reps": lambda c: c["reps"],
}
WEAK = {
    "problem": lambda c: c["case"].split(".")[1],
    "cells per subdomain": lambda c: c["case"].split(".")[2][1:],
    "k": lambda c: c["case"].split(".")[3][1:],
    "partitioner": lambda c: c["case"].split(".")[4],
    "DOFs": lambda c: c["degrees_of_freedom"],
    "subdomains": lambda c: c["subdomains"],
    "dual": lambda c: c["dual_size"],
    "MPRGP": lambda c: c["qp.iterations"],
    "CG / expansion / proportioning": lambda c: "%d / %d / %d" % (c["qp.cg_steps"], c["qp.expansion_steps"],
                                                                  c["qp.proportioning_steps"]),
    "SMALBE outer": lambda c: c["qp.smalbe_outer_iterations"],
    "condition estimate": lambda c: c.get("qp.face_spectrum.condition_estimate"),
    "longest CG run": lambda c: c.get("qp.face_spectrum.cg_steps"),
    "dual solve (s)": lambda c: c["timings_seconds.dual solve (MPRGP)"],
    "contact force (N)": lambda c: c.get("total_normal_force", 0),
    "peak MiB": lambda c: c["peak_memory_bytes"] / 2**20,
    "reps": lambda c: c["reps"],
}
MPRGP = {
    "unknowns": lambda c: c["unknowns"],
    "iterations": lambda c: c["iterations"],
    "CG / expansion / proportioning": lambda c: "%d / %d / %d" % (c["cg_steps"], c["expansion_steps"],
                                                                  c["proportioning_steps"]),
    "operator applications": lambda c: c.get("hessian_multiplications", c.get("operator_applications")),
    "s / iteration": lambda c: c["seconds_per_iteration"],
    "s / application": lambda c: c["operator_seconds_median"],
    "iteration / application": lambda c: c["ratio_iteration_to_operator"],
    "solve / (applications x application)": lambda c: c["ratio_solve_to_applications"],
    "reps": lambda c: c["reps"],
}


def fmt(value):
    if isinstance(value, float):
        return "%.3g" % value if abs(value) < 1e4 else "%.0f" % value
    return str(value)


def table(title, columns, cases, results, csv_name, groups=None):
    """Writes all columns to csv_name; returns Markdown tables, one per group of column
    titles (all columns in one table by default), so that wide tables stay readable."""
    rows = [{title: f(case) for title, f in columns.items()} for case in cases]
    with open(results / csv_name, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(columns.keys())
        writer.writerows([row.values() for row in rows])
    text = ""
    for i, group in enumerate(groups or [list(columns)]):
        lines = ["### " + title + (" (%d/%d)" % (i + 1, len(groups)) if groups else ""), "",
                 "| " + " | ".join(group) + " |", "|" + "---|" * len(group)]
        lines += ["| " + " | ".join(fmt(row[c]) for c in group) + " |" for row in rows]
        text += "\n".join(lines) + "\n\n"
    return text


CONTACT_GROUPS = [
    ["size", "displacements", "preconditioner", "operator", "DOFs", "subdomains", "dual", "outer", "MPRGP", "F products", "peak MiB",
     "converged", "reps"],
    ["size", "displacements", "preconditioner", "operator"] + [phase + " (s)" for phase in PHASES],
    ["size", "displacements", "preconditioner", "total solve (s)", "direct assembly (s)", "direct factorization (s)",
     "direct solve (s)", "factor nnz", "contact / direct", "GAMG set-up + solve (s)", "GAMG CG iterations",
     "contact / GAMG"],
    ["size", "displacements", "preconditioner", "operator", "MPRGP", "QP (s)", "s / MPRGP iteration", "s / H application",
     "s / preconditioner application", "iteration / H application", "iteration / (H + preconditioner)"],
]


def main():
    results = Path(sys.argv[1] if len(sys.argv) > 1 else "bench/results")
    if not (results / "raw").is_dir():
        sys.exit("summarize.py: no %s/raw (run bench/run.sh first)" % results)
    cases = medians(results / "raw")
    for name, case in cases.items():
        case["case"] = name
    size_order = {"10k": 0, "100k": 1, "1M": 2}
    contact = sorted((c for n, c in cases.items() if n.startswith("contact.")),
                     key=lambda c: (size_order.get(c["case"].split(".")[1], 9), c["case"].split(".")[2] != "small",
                                    c.get("preconditioner", ""), c.get("dual_operator", "")))
    scalability = sorted((c for n, c in cases.items() if n.startswith("scalability.")),
                         key=lambda c: (c.get("preconditioner", ""), float(c["case"].split(".")[1][1:])))
    weak = sorted((c for n, c in cases.items() if n.startswith("weak.")),
                  key=lambda c: (c["case"].split(".")[1] != "punch", -int(c["case"].split(".")[2][1:]), c["case"].split(".")[4],
                                 int(c["case"].split(".")[3][1:])))
    mprgp = [c for n, c in sorted(cases.items()) if n.startswith("mprgp.")]
    text = ""
    if contact:
        text += table("Hertz: FETI contact solve against the bonded direct solve (medians)", CONTACT, contact,
                      results, "contact.csv", CONTACT_GROUPS)
    if scalability:
        text += table("Numerical scalability, 256 cells per subdomain (medians)", SCALABILITY,
                             scalability, results, "scalability.csv")
    if weak:
        text += table("Weak scaling: flat punch, cells x k, fixed cells per subdomain (medians)", WEAK, weak,
                      results, "weak.csv")
    if mprgp:
        text += table("MPRGP alone, 2D obstacle QP (medians)", MPRGP, mprgp, results, "mprgp.csv")
    text = text.rstrip("\n") + "\n"
    (results / "tables.md").write_text(text)
    print(text, end="")


if __name__ == "__main__":
    main()
