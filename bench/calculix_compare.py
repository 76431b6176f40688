#!/usr/bin/python3
"""feticon and CalculiX on one exported model: reads both codes' results of a case folder
written by bench/calculix.sh and computes every figure with the same code for both.

    bench/calculix_compare.py CASE_DIR          # writes CASE_DIR/comparison.json, prints it

CASE_DIR holds deck/feticon.inp (the export), ccx.rep<i>/ (feticon.frd, feticon.dat, stdout,
time), feticon.rep<i>/ (summary.json, contact_pressure.csv, time) and export.log, and
feticon.meshing/ when bench/calculix.sh also timed a run that makes its mesh (the reps read
theirs from the mesh cache, which the export filled, as ccx reads its mesh from the deck).

Conventions. Both pressures are per deformed area: CalculiX's CPRESS is the penalty pressure
(Cauchy traction) at the slave nodes, extrapolated from its integration points; feticon's is
the nodal normal force over the node's tributary area in the current configuration. In plane
strain (one cell layer) the two nodes through the thickness form one sample (their mean); a
CPE deck's nodes are each a sample.
Hertz figures, against McEwen's p(x) = p0 sqrt(1 - x^2/a^2) with a and p0 from feticon's
summary (they depend on the problem only), use the deformed coordinate x + u_x with large
displacements and the reference x with small ones:
  - peak error: (max nodal pressure - p0) / p0;
  - a_fit: p^2 = A + B x^2 fitted by least squares over the loaded samples (p > 1e-3 max p),
    a = sqrt(-A/B), so a single lightly loaded node does not move it by an element;
  - rms_over_p0: RMS of p - p_McEwen over 400 equidistant points of [0, a], p interpolated
    linearly between samples, divided by p0.
3D (hertz3d): the same figures against Hertz's p(r) = p0 sqrt(1 - r^2/a^2) at the distance r
from the axis (r of x + u in the deformed frame), except that the RMS is over the slave nodes
with r <= a (the nodes are scattered in r; feticon's summary uses the same definition).
Times are the wall clock around each run (bash's EPOCHREALTIME, microseconds; GNU time's %e in
older cases); memory GNU time's maximum resident set size.
"""
import glob
import json
import math
import os
import re
import statistics
import sys

ACTIVE = 1e-3  # a sample is loaded when p > ACTIVE * max p (the one threshold used here)


# CalculiX's C3D8 faces S1..S6 as 0-based positions in the element's node list; the edges
# S1..S4 of a 2D quadrilateral (CPE4, CPS4, CAX4) join corner k to corner k + 1.
C3D8_FACES = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]
QUAD_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0)]


def read_deck(path):
    """Node coordinates {id: (x, y, z)} of the deck (after the slave shift) and the node ids of
    the slave surface of the first *CONTACT PAIR."""
    nodes, elements, surfaces, section, name, slave = {}, {}, {}, None, None, None
    planar, element_type = set(), None
    with open(path) as f:
        for line in f:
            if line.startswith("**"):
                continue
            if line.startswith("*"):
                words = [w.strip() for w in line.strip().split(",")]
                section = words[0].upper()
                name = next((w.split("=")[1] for w in words[1:] if w.upper().startswith("NAME=")), None)
                if section == "*SURFACE":
                    surfaces[name] = []
                element_type = next((w.split("=")[1].upper() for w in words[1:] if w.upper().startswith("TYPE=")), None)
                continue
            v = [t.strip() for t in line.split(",")]
            if section == "*NODE":
                nodes[int(v[0])] = tuple(float(t) for t in v[1:4])
            elif section == "*ELEMENT":
                elements[int(v[0])] = [int(t) for t in v[1:9]]
                if element_type and element_type[:3] in ("CPE", "CPS", "CAX"):
                    planar.add(int(v[0]))
            elif section == "*SURFACE":
                surfaces[name].append((int(v[0]), int(v[1][1:])))
            elif section == "*CONTACT PAIR" and slave is None:
                slave = v[0]
    slave_nodes = set()
    for element, face in surfaces.get(slave, []):
        faces = QUAD_EDGES if element in planar else C3D8_FACES
        slave_nodes.update(elements[element][k] for k in faces[face - 1])
    return nodes, slave_nodes


def read_frd_last(path, block):
    """{node: [values]} of the last result block named `block` (e.g. DISP, CONTACT) in a .frd."""
    result, current, reading = None, None, False
    with open(path) as f:
        for line in f:
            if line.startswith(" -4"):
                reading = line.split()[1] == block
                if reading:
                    current = {}
                continue
            if reading and line.startswith(" -1"):
                node = int(line[3:13])
                text = line[13:].rstrip("\n")
                current[node] = [float(text[k:k + 12]) for k in range(0, len(text), 12) if text[k:k + 12].strip()]
            elif reading and line.startswith(" -3"):
                reading = False
                result = current
    return result or {}


def time_of(path):
    """(wall seconds, max RSS bytes, CPU percent) from a GNU time -f '%e %M %P' file; the wall
    clock from the file `wall` beside it where bench/calculix.sh wrote one (microseconds: GNU
    time's %e has 10 ms steps, 12 % of a 0.08 s run)."""
    with open(path) as f:
        lines = [l for l in f.read().split("\n") if l.strip()]
    wall, rss, cpu = lines[-1].split()
    precise = os.path.join(os.path.dirname(path), "wall")
    if os.path.exists(precise):
        with open(precise) as f:
            wall = f.read().strip()
    return float(wall), 1024 * int(rss), float(cpu.rstrip("%"))


def hertz_figures(samples, a, p0, large, radial=False):
    """samples: [(x_ref, x_def, p)] (r instead of x when radial); figures against McEwen (or
    Hertz's p(r) when radial) in the chosen frame."""
    pts = sorted(((xd if large else xr), p) for xr, xd, p in samples)
    p_max = max(p for _, p in pts)
    loaded = [(x, p) for x, p in pts if p > ACTIVE * p_max]
    n = len(loaded)
    sx = sum(x * x for x, _ in loaded)
    sy = sum(p * p for _, p in loaded)
    sxx = sum(x ** 4 for x, _ in loaded)
    sxy = sum(x * x * p * p for x, p in loaded)
    slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    intercept = (sy - slope * sx) / n
    a_fit = math.sqrt(-intercept / slope) if slope < 0 < intercept else float("nan")

    def interpolate(x):
        for (x0, q0), (x1, q1) in zip(pts, pts[1:]):
            if x0 <= x <= x1:
                return q0 + (q1 - q0) * (x - x0) / (x1 - x0) if x1 > x0 else q0
        return pts[0][1] if x < pts[0][0] else 0.0

    def analytic(x):
        return p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2))

    if radial:
        inside = [(x, p) for x, p in pts if x <= a]
        m = len(inside)
        sq = sum((p - analytic(x)) ** 2 for x, p in inside)
    else:
        m = 400
        sq = sum((interpolate(a * (k + 0.5) / m) - analytic(a * (k + 0.5) / m)) ** 2 for k in range(m))
    return {"frame": "deformed" if large else "reference",
            "p_peak": p_max, "peak_error": (p_max - p0) / p0,
            "a_fit": a_fit, "a_error": (a_fit - a) / a,
            "rms_over_p0": math.sqrt(sq / m) / p0,
            "loaded_samples": n}


def group_plane_strain(rows, plane_strain):
    """Mean of the rows (x_ref, x_def, p) of one reference x (node lines through the thickness)."""
    if not plane_strain:
        return rows
    groups = {}
    for xr, xd, p in rows:
        groups.setdefault(round(xr, 9), []).append((xr, xd, p))
    return [tuple(sum(v[i] for v in g) / len(g) for i in range(3)) for g in groups.values()]


def calculix_run(folder, deck_nodes, slave_nodes, plane_strain):
    wall, rss, cpu = time_of(os.path.join(folder, "time"))
    with open(os.path.join(folder, "stdout")) as f:
        log = f.read()
    eq = re.search(r"number of equations\s*\n\s*(\d+)", log)
    increments = len(re.findall(r"increment \d+ attempt 1", log))
    frd = os.path.join(folder, "feticon.frd")
    disp = read_frd_last(frd, "DISP")
    contact = read_frd_last(frd, "CONTACT")
    rows, shear = [], []
    for node in slave_nodes:
        values = contact.get(node, [0.0] * 6)
        x = deck_nodes[node]
        if plane_strain:
            rows.append((x[0], x[0] + disp[node][0], values[3]))  # CPRESS is the 4th component
            shear.append((x[0], values[3], abs(values[4])))  # CSHEAR1, along the slave face's first tangent
        else:  # distance from the z axis
            rows.append((math.hypot(x[0], x[1]), math.hypot(x[0] + disp[node][0], x[1] + disp[node][1]), values[3]))
    # Reactions: *NODE PRINT TOTALS=ONLY of every support set, last increment.
    with open(os.path.join(folder, "feticon.dat")) as f:
        dat = f.read()
    totals = {}
    for name, body in re.findall(r"total force \(fx,fy,fz\) for set (\S+) and time\s+\S+\s*\n\s*\n?\s*([^\n]+)", dat):
        totals[name] = [float(v) for v in body.split()]
    return {"seconds": wall, "peak_memory_bytes": rss, "cpu_percent": cpu,
            "equations": int(eq.group(1)) if eq else None, "increments": increments,
            "reactions": totals}, group_plane_strain(rows, plane_strain), group_plane_strain(shear, plane_strain)


def feticon_run(folder, plane_strain):
    wall, rss, cpu = time_of(os.path.join(folder, "time"))
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    rows, shear = [], []
    with open(os.path.join(folder, "contact_pressure.csv")) as f:
        head = f.readline().strip().split(",")
        for line in f:
            r = dict(zip(head, (float(v) for v in line.split(","))))
            if "shear_x_Pa" in r:
                shear.append((r["x_m"], r["pressure_multipliers_Pa"], abs(r["shear_x_Pa"])))
            if plane_strain or "y_deformed_m" not in r:
                rows.append((r["x_m"], r["x_deformed_m"], r["pressure_multipliers_Pa"]))
            else:  # distance from the z axis
                rows.append((math.hypot(r["x_m"], r["y_m"]), math.hypot(r["x_deformed_m"], r["y_deformed_m"]),
                             r["pressure_multipliers_Pa"]))
    qp = summary.get("qp", {})
    return {"seconds": wall, "peak_memory_bytes": rss, "cpu_percent": cpu,
            "degrees_of_freedom": summary["degrees_of_freedom"], "nodes": summary["nodes"],
            "subdomains": summary["subdomains"], "converged": summary["converged"],
            "outer_iterations": sum(s["outer_iterations"] for s in summary.get("steps", [])),
            "mprgp_iterations": qp.get("iterations"), "hessian_multiplications": qp.get("hessian_multiplications"),
            "total_normal_force": summary.get("contact", {}).get("total_normal_force"),
            "mesh_from_cache": summary.get("mesh_from_cache", False)}, rows, summary, shear


def cattaneo_mindlin_figures(shear, friction, a, p0):
    """Both codes' stick-zone half-width and shear RMS from (x, p, |q|) node lines with the same
    rule: a loaded line sticks where |q| < 0.99 mu p (CalculiX's penalty friction has no stick
    flag), c = half the span of the central sticking run, RMS of |q| - |q_CM| over [-a, a] / (mu p0)."""
    mu, c = friction["coefficient"], friction["stick_half_width_analytic"]

    def q_cm(x):
        if abs(x) >= a:
            return 0.0
        q = mu * p0 * math.sqrt(1 - (x / a) ** 2)
        if abs(x) < c:
            q -= mu * p0 * (c / a) * math.sqrt(1 - (x / c) ** 2)
        return q

    rows = sorted(shear)
    peak = max(p for _, p, _ in rows)
    loaded = [(x, p, q) for x, p, q in rows if p > 1e-3 * peak]
    centre = min(range(len(loaded)), key=lambda k: abs(loaded[k][0]))
    stick = lambda k: loaded[k][2] < 0.99 * mu * loaded[k][1]  # noqa: E731
    lo = hi = centre
    while lo > 0 and stick(lo - 1):
        lo -= 1
    while hi + 1 < len(loaded) and stick(hi + 1):
        hi += 1
    left = 0.5 * (loaded[lo - 1][0] + loaded[lo][0]) if lo > 0 else loaded[lo][0]
    right = 0.5 * (loaded[hi][0] + loaded[hi + 1][0]) if hi + 1 < len(loaded) else loaded[hi][0]
    within = [(x, q) for x, _, q in rows if abs(x) <= a]
    rms = math.sqrt(sum((q - q_cm(x)) ** 2 for x, q in within) / len(within)) / (mu * p0)
    return {"stick_half_width": 0.5 * (right - left), "stick_half_width_analytic": c,
            "shear_rms_over_mu_p0": rms}


def median_run(runs):
    """The run of median wall time, with the median and all times."""
    ordered = sorted(runs, key=lambda r: r["seconds"])
    out = dict(ordered[(len(ordered) - 1) // 2])
    out["seconds_all"] = [r["seconds"] for r in runs]
    out["seconds"] = statistics.median(out["seconds_all"])
    return out


def main(case):
    deck = os.path.join(case, "deck", "feticon.inp")
    deck_nodes, slave_nodes = read_deck(deck)
    with open(deck) as f:
        text = f.read()
    plane_strain = re.search(r"^NALL, 3, 3", text, re.M) is not None or "TYPE=CPE" in text
    load = [0.0, 0.0, 0.0]
    in_cload = False
    for line in text.split("\n"):
        if line.startswith("*"):
            in_cload = line.startswith("*CLOAD")
            if line.startswith("*CLOAD, OP=NEW"):  # a later step's loads replace the last step's
                load = [0.0, 0.0, 0.0]
        elif in_cload and line.strip():
            node, dof, value = line.split(",")
            load[int(dof) - 1] += float(value)

    fet_runs, fet_rows, summary, fet_shear = [], None, None, None
    for d in sorted(glob.glob(os.path.join(case, "feticon.rep*"))):
        r, fet_rows, summary, fet_shear = feticon_run(d, plane_strain)
        fet_runs.append(r)
    ccx_runs, ccx_rows, ccx_shear = [], None, None
    for d in sorted(glob.glob(os.path.join(case, "ccx.rep*"))):
        r, ccx_rows, ccx_shear = calculix_run(d, deck_nodes, slave_nodes, plane_strain)
        ccx_runs.append(r)
    out = {"case": os.path.basename(os.path.normpath(case)), "applied_load_N": load,
           "feticon": median_run(fet_runs) if fet_runs else None,
           "calculix": median_run(ccx_runs) if ccx_runs else None}
    large = summary is not None and summary.get("displacements") == "large"
    for name, rows in (("feticon", fet_rows), ("calculix", ccx_rows)):
        if rows and out[name]:
            out[name]["peak_pressure"] = max(p for _, _, p in rows)
            if summary and "hertz" in summary:
                h = summary["hertz"]
                radial = summary.get("problem") == "hertz3d"
                out[name]["hertz"] = hertz_figures(rows, h["a_analytic"], h["p0_analytic"], large, radial)
                if large:
                    out[name]["hertz_reference_frame"] = hertz_figures(rows, h["a_analytic"], h["p0_analytic"],
                                                                       False, radial)
    friction = (summary or {}).get("hertz", {}).get("friction")
    for name, shear in (("feticon", fet_shear), ("calculix", ccx_shear)):
        if friction and shear and out[name]:
            h = summary["hertz"]
            out[name]["cattaneo_mindlin"] = cattaneo_mindlin_figures(shear, friction, h["a_analytic"],
                                                                     h["p0_analytic"])
    meshing = os.path.join(case, "feticon.meshing")
    if os.path.isdir(meshing):
        out["feticon_meshing"] = feticon_run(meshing, plane_strain)[0]
    if out["feticon"] and out["calculix"]:
        out["time_ratio_calculix_over_feticon"] = out["calculix"]["seconds"] / out["feticon"]["seconds"]
        if "feticon_meshing" in out:
            out["time_ratio_calculix_over_feticon_meshing"] = (out["calculix"]["seconds"] /
                                                               out["feticon_meshing"]["seconds"])
        out["memory_ratio_calculix_over_feticon"] = (out["calculix"]["peak_memory_bytes"] /
                                                     out["feticon"]["peak_memory_bytes"])
        out["peak_pressure_difference"] = (out["calculix"]["peak_pressure"] / out["feticon"]["peak_pressure"] - 1)
    with open(os.path.join(case, "comparison.json"), "w") as f:
        json.dump(out, f, indent=2)
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: bench/calculix_compare.py CASE_DIR")
    main(sys.argv[1])
