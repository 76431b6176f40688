#!/usr/bin/python3
"""The table "feticon and CalculiX on identical meshes" of docs/benchmarks.md from the case
folders of bench/calculix.sh (their comparison.json).

    bench/calculix_table.py bench/results/calculix      # prints Markdown, writes table.md there
"""
import json
import os
import sys

ORDER = ["hertz-small-60", "hertz-large-60", "hertz-small-120", "hertz-large-120",
         "hertz-small-240", "hertz-large-240", "punch", "sphere", "sphere-large",
         "hertz-large-120-tensor", "hertz3d-small-r1", "hertz3d-large-r1", "hertz3d-small-r1.4",
         "hertz3d-large-r1.4"]


def pct(v):
    return "" if v is None else "%.2f %%" % (100 * v)


def row(c):
    f, x = c["feticon"], c["calculix"]
    fh, xh = f.get("hertz", {}), x.get("hertz", {})
    runs = len(f["seconds_all"])
    m = c.get("feticon_meshing")
    # The reps read a mesh Gmsh made from the mesh cache; "meshing": one run that makes it.
    fs = "%.2f" % f["seconds"] + (" / %.2f" % m["seconds"] if m and f.get("mesh_from_cache") else "")
    ratio = "**%.2f**" % c["time_ratio_calculix_over_feticon"]
    if m and f.get("mesh_from_cache"):
        ratio += " / %.2f" % c["time_ratio_calculix_over_feticon_meshing"]
    return "| {case} | {nodes:,} | {eq:,} | {xs:.1f} | {fs} | {ratio} | {xm:.0f} / {fm:.0f} | {xp} / {fp} | {xr} / {fr} | {xa} / {fa} | {it} | {runs} |".format(
        case=c["case"], nodes=f["nodes"], eq=x["equations"] or 0,
        xs=x["seconds"], fs=fs, ratio=ratio,
        xm=x["peak_memory_bytes"] / 2 ** 20, fm=f["peak_memory_bytes"] / 2 ** 20,
        xp=pct(xh.get("peak_error")) or "%.4g" % x["peak_pressure"],
        fp=pct(fh.get("peak_error")) or "%.4g" % f["peak_pressure"],
        xr=pct(xh.get("rms_over_p0")), fr=pct(fh.get("rms_over_p0")),
        xa=pct(xh.get("a_error")), fa=pct(fh.get("a_error")),
        it="%d / %d" % (f["outer_iterations"], f["mprgp_iterations"] or 0), runs=runs)


def main(folder):
    cases = {}
    for name in os.listdir(folder):
        path = os.path.join(folder, name, "comparison.json")
        if os.path.exists(path):
            with open(path) as fh:
                c = json.load(fh)
            if c.get("feticon") and c.get("calculix"):
                cases[name] = c
    names = [n for n in ORDER if n in cases] + sorted(n for n in cases if n not in ORDER)
    lines = ["| case | nodes | CalculiX equations | CalculiX s | feticon s (mesh cached / meshing) "
             "| CalculiX / feticon time (mesh cached / meshing) "
             "| memory MiB (CalculiX / feticon) | peak p error or peak p (CalculiX / feticon) "
             "| RMS error / p0 | half-width error | feticon outer / MPRGP steps | runs |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    lines += [row(cases[n]) for n in names]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(folder, "table.md"), "w") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: bench/calculix_table.py FOLDER")
    main(sys.argv[1])
