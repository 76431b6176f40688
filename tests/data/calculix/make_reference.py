#!/usr/bin/python3
"""Writes reference.json of this folder: for each CalculiX test deck kept here, the figures a
feticon test can compare with, and checks that the installed ccx reproduces the package's
.dat.ref.

    make_reference.py [--no-ccx] [--out FILE]     (default FILE: reference.json beside this)

Per deck:
  model          node/element counts, steps, contact pair kind, *SURFACE BEHAVIOR law;
  applied_load   sum of *CLOAD and *DLOAD resultants per step (calculix_dat.applied_loads);
  ref            from the .dat.ref (CalculiX 2.11, Debian calculix-ccx-test 2.11-1.1):
                 final displacements of the printed nodes, reaction (sum of the printed nodal
                 forces over the nodes *BOUNDARY holds, per direction) when forces are printed,
                 totals (energies) when printed;
  ccx            with ccx installed (Debian calculix-ccx 2.20): the block-by-block comparison of
                 its .dat with the .dat.ref, and figures from a second run of the deck with
                 "*NODE PRINT,NSET=Nall,TOTALS=YES / U,RF" and "*CONTACT PRINT / CSTR,CDIS,CNUM"
                 (face-to-face pairs also "*CONTACT PRINT,SLAVE=..,MASTER=.. / CF") added to
                 the last step: reaction, per-body support reactions, contact pressures, the
                 normal relative displacement CDIS (|CDIS| is the penetration), number of
                 contact elements, contact force;
  penalty        the law, the penetration the law gives at the printed pressures, and its
                 ratio to the largest printed displacement (what exact contact removes);
  exact_contact  with numpy: exact_contact_estimate.py's linear exact-contact solution at the
                 printed nodes (contact force, displacement at the most displaced node, and the
                 relative L2 difference from the .dat.ref displacements).
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import calculix_dat as cd  # noqa: E402

DECKS = ["contact1", "contact3", "contact6", "contactenergy", "cubespring"]
ORIGIN = "Debian package calculix-ccx-test 2.11-1.1, /usr/share/doc/calculix-ccx-test/examples/test/"


def sig(x, n=7):
    if isinstance(x, float):
        if math.isnan(x) or x == 0.0:
            return x
        return float("%.*e" % (n - 1, x))
    if isinstance(x, (list, tuple)):
        return [sig(v, n) for v in x]
    if isinstance(x, dict):
        return {k: sig(v, n) for k, v in x.items()}
    return x


def model_info(path):
    cards = cd._cards(path)
    deck = cd.read_inp(path)
    etypes = {}
    for _, (t, _) in deck["elements"].items():
        etypes[t] = etypes.get(t, 0) + 1
    info = {"nodes": len(deck["nodes"]), "elements": etypes, "steps": len(deck["steps"]) - 1,
            "nlgeom": any("NLGEOM" in s.get("params", {}) for s in deck["steps"][1:]),
            "pairs": [], "laws": []}
    for kw, params, data in cards:
        if kw == "CONTACT PAIR":
            info["pairs"].append({"type": str(params.get("TYPE", "NODE TO SURFACE")).upper(),
                                  "slave": data[0][0], "master": data[0][1]})
        elif kw == "SURFACE BEHAVIOR":
            law = str(params.get("PRESSURE-OVERCLOSURE")).upper()
            vals = [float(v) for f in data for v in f if v != ""]
            info["laws"].append({"law": law, "values": vals})
        elif kw == "ELASTIC":
            info.setdefault("elastic", []).append([float(v) for v in data[0] if v != ""])
    return info


def law_penetration(law, p, face_to_face):
    """Overclosure d at pressure p for CalculiX's law (ccx manual, node-to-face penalty contact):
    exponential p = p0 exp(beta d), beta = ln(100)/c0; linear node-to-face
    p = K d (1/2 + atan(d/eps)/pi), eps = pi sigma_inf / K; linear face-to-face p = K d."""
    v = law["values"]
    if law["law"] == "EXPONENTIAL":
        c0, p0 = v[0], v[1]
        return c0 * math.log(p / p0) / math.log(100.0)
    if law["law"] == "LINEAR":
        K = v[0]
        if face_to_face or len(v) < 2:
            return p / K
        eps = math.pi * v[1] / K
        lo, hi = -1.0, 1.0
        for _ in range(200):  # bisection on the monotone law
            mid = 0.5 * (lo + hi)
            if K * mid * (0.5 + math.atan(mid / eps) / math.pi) < p:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)
    if law["law"] == "TABULAR":
        pts = list(zip(v[0::2], v[1::2]))  # (pressure, overclosure)
        for (p1, d1), (p2, d2) in zip(pts, pts[1:]):
            if p1 <= p <= p2:
                return d1 + (d2 - d1) * (p - p1) / (p2 - p1)
    return None


def bodies(deck):
    """Connected element groups (sharing nodes): [set of node ids]."""
    parent = {}

    def find(a):
        while parent.setdefault(a, a) != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for _, (_, conn) in deck["elements"].items():
        for n in conn[1:]:
            ra, rb = find(conn[0]), find(n)
            if ra != rb:
                parent[ra] = rb
    groups = {}
    for _, (_, conn) in deck["elements"].items():
        groups.setdefault(find(conn[0]), set()).update(conn)
    return sorted(groups.values(), key=min)


def run_ccx(path, workdir, extra=None):
    name = os.path.splitext(os.path.basename(path))[0]
    text = open(path, encoding="latin-1").read()
    if extra:
        i = text.upper().rfind("*END STEP")
        text = text[:i] + extra + text[i:]
        name += "_print"
    with open(os.path.join(workdir, name + ".inp"), "w", encoding="latin-1") as f:
        f.write(text)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    r = subprocess.run(["ccx", "-i", name], cwd=workdir, env=env, capture_output=True, text=True)
    dat = os.path.join(workdir, name + ".dat")
    if r.returncode != 0 or not os.path.exists(dat):
        raise RuntimeError("ccx failed on %s: %s" % (name, r.stdout[-2000:]))
    return dat


def deck_reference(name, use_ccx):
    inp = os.path.join(HERE, name + ".inp")
    ref = os.path.join(HERE, name + ".dat.ref")
    deck = cd.read_inp(inp)
    info = model_info(inp)
    out = {"deck": name + ".inp", "dat_ref": name + ".dat.ref", "origin": ORIGIN, "model": info}
    out["applied_load"] = cd.applied_loads(deck)
    s = cd.summary(ref, deck)
    disp = next(iter(s.get("displacements", {}).values()))
    out["ref"] = {"time": disp["time"], "displacements": disp["nodes"]}
    if "forces" in s:
        out["ref"]["reaction"] = next(iter(s["forces"].values()))["reaction"]
    if "totals" in s:
        out["ref"]["totals"] = {k: v["values"] for k, v in s["totals"].items()}
    umax = max(math.sqrt(sum(c * c for c in u)) for u in disp["nodes"].values())
    out["ref"]["max_abs_displacement"] = umax
    f2f = all(p["type"] == "SURFACE TO SURFACE" for p in info["pairs"])
    if use_ccx:
        work = tempfile.mkdtemp(prefix="ccx_" + name + "_")
        try:
            shutil.copy(inp, work)
            dat = run_ccx(os.path.join(work, name + ".inp"), work)
            ok, lines = cd.compare(cd.parse_dat(ref), cd.parse_dat(dat), rtol=1e-5)
            pair = info["pairs"][0]
            extra = "*NODE PRINT,NSET=Nall,TOTALS=YES\nU,RF\n*CONTACT PRINT\nCSTR,CDIS,CNUM\n"
            if f2f:
                extra += "*CONTACT PRINT,SLAVE=%s,MASTER=%s\nCF\n" % (pair["slave"], pair["master"])
            dat2 = run_ccx(os.path.join(work, name + ".inp"), work, extra)
            s2 = cd.summary(dat2, deck)
            parsed = {r[0]: r[1:4] for b in cd.parse_dat(dat2)["blocks"] if b["kind"] == "forces" for r in b["rows"]}
            version = subprocess.run(["ccx", "-v"], capture_output=True, text=True).stdout.strip()
        finally:
            shutil.rmtree(work, ignore_errors=True)
        c = {"version": version, "same_as_ref_rtol_1e-5": ok, "compare": lines}
        forces = next(iter(s2["forces"].values()))
        c["reaction"] = forces["reaction"]
        # per body: support reaction (printed forces at held nodes) + applied loads on it
        held = cd.constrained_nodes(deck)
        c["bodies"] = []
        for nodes in bodies(deck):
            c["bodies"].append({"nodes": len(nodes), "first_node": min(nodes),
                                "support_reaction": [sum(parsed[n][d - 1] for n in held[d] if n in nodes)
                                                     for d in (1, 2, 3)]})
        ct = s2.get("contact", {})
        if "contact stress" in ct:
            c["contact_pressure"] = {k: ct["contact stress"][k] for k in ("min", "max", "mean", "count")}
        if "relative contact displacement" in ct:
            c["cdis_normal"] = {k: ct["relative contact displacement"][k] for k in ("min", "max", "mean")}
        tot = s2.get("totals", {})
        if "total number of contact elements" in tot:
            c["contact_elements"] = int(tot["total number of contact elements"]["values"][0])
        for key, st in s2.get("contact_statistics", {}).items():
            sec = {k.split(" (")[0].split("(")[0].strip(): v for k, v in st.items() if k != "time"}
            c["contact_force_CF"] = {"pair": key, "total_surface_force": sec.get("total surface force", [])[:3],
                                     "area_normal_shear": sec.get("area, normal force", [])}
        out["ccx"] = c
        if "contact_pressure" in c:
            law = info["laws"][0]
            pen = {q: law_penetration(law, c["contact_pressure"][q], f2f) for q in ("min", "max", "mean")}
            out["penalty"] = {"law": law, "penetration_from_law": pen,
                              "penetration_cdis_max": max(abs(c["cdis_normal"]["min"]), abs(c["cdis_normal"]["max"])),
                              "penetration_over_max_displacement": pen["max"] / umax}
    try:
        import exact_contact_estimate as ex
        u, f = ex.solve(inp)
        num = sum((disp["nodes"][k][i] - u[int(k)][i]) ** 2 for k in disp["nodes"] for i in range(3))
        den = sum(disp["nodes"][k][i] ** 2 for k in disp["nodes"] for i in range(3))
        worst = max(disp["nodes"], key=lambda k: sum(v * v for v in disp["nodes"][k]))
        out["exact_contact"] = {"contact_force_total": sum(f.values()),
                                "node": int(worst), "u_ref": disp["nodes"][worst], "u_exact": u[int(worst)],
                                "relative_L2_difference_ref_vs_exact": math.sqrt(num / den)}
    except ImportError:
        pass
    return sig(out)


def main(argv):
    use_ccx = "--no-ccx" not in argv and shutil.which("ccx") is not None
    path = argv[argv.index("--out") + 1] if "--out" in argv else os.path.join(HERE, "reference.json")
    sys.path.insert(0, HERE)
    res = {"generated_by": "tests/data/calculix/make_reference.py", "decks": {}}
    for name in DECKS:
        res["decks"][name] = deck_reference(name, use_ccx)
        print(name, "done", file=sys.stderr)
    with open(path, "w") as f:
        json.dump(res, f, indent=1, sort_keys=False)
        f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
