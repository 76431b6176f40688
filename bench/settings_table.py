#!/usr/bin/python3
"""The table of issue 40's auto settings: for each model swept by bench/settings_sweep.sh with
`--counts auto,... --preconditioners auto,...`, the median wall time of every given point, the
best of them, and auto's choice and time against it.

    bench/settings_table.py DIR     # the NAME.tsv files of settings_sweep.sh
"""
import collections
import csv
import pathlib
import statistics
import sys


def medians(path, auto):
    """(subdomains, preconditioner) -> (median wall, median steps, peak MiB, dofs) of the auto
    runs of a TSV, or of the others."""
    points = collections.defaultdict(list)
    for row in csv.DictReader(open(path), delimiter="\t"):
        if (row["subdomains_asked"] == "auto") == auto:
            points[(int(row["subdomains"]), row["preconditioner"])].append(row)
    out = {}
    for key, rows in points.items():
        out[key] = (statistics.median(float(r["wall_s"]) for r in rows),
                    statistics.median(int(r["steps"]) for r in rows),
                    max(int(r["peak_mib"]) for r in rows), int(rows[0]["dofs"]))
    return out


def main(folder):
    print("| model | DOFs | best of the sweep (wall, median of 3) | auto's choice | auto (wall) | auto / best |")
    print("|---|---|---|---|---|---|")
    for path in sorted(pathlib.Path(folder).glob("*.tsv")):
        sweep, auto = medians(path, False), medians(path, True)
        if not sweep or not auto:
            continue
        (count, preconditioner), best = min(sweep.items(), key=lambda kv: kv[1][0])
        for (auto_count, auto_preconditioner), chosen in auto.items():
            print(f"| {path.stem} | {best[3]} | {count} {preconditioner}: {best[0]:.2f} s, {best[1]} steps, "
                  f"{best[2]} MiB | {auto_count} {auto_preconditioner} | {chosen[0]:.2f} s, {chosen[1]} steps, "
                  f"{chosen[2]} MiB | {chosen[0] / best[0]:.2f} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
