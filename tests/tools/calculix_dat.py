#!/usr/bin/python3
"""Reads CalculiX .dat files (the *NODE PRINT / *EL PRINT / *CONTACT PRINT output) into plain
dicts / JSON, compares two of them, and sums the applied loads of an .inp deck.

    calculix_dat.py parse   FILE.dat                 # every block, as JSON
    calculix_dat.py summary FILE.dat [--inp DECK]    # reference figures of the last time, JSON
    calculix_dat.py compare A.dat B.dat [--rtol R]   # block by block; exit 1 if any differs
    calculix_dat.py loads   DECK.inp                 # applied load sum per step, JSON

Python use: `from calculix_dat import parse_dat, summary, compare, applied_loads, read_inp`.

.dat layout (ccx 2.11 to 2.20): each block starts with a header line ending in
"... and time T" (e.g. " displacements (vx,vy,vz) for set NALL and time  0.1000000E+01"),
followed by data lines of numbers. The time is the total time (it keeps growing over the
steps; the .dat names no step). parse_dat returns {"blocks": [block, ...]} in file order, each
    {"kind": "displacements", "columns": ["vx","vy","vz"], "set": "NALL", "time": 1.0,
     "rows": [[id, v1, v2, ...], ...]}
Row layouts: node blocks (displacements, forces, velocities, temperatures) [node, values];
integration-point blocks (stresses, strains, ...) [elem, ip, values]; per-element blocks
(internal energy, volume, ...) [elem, value]; node-to-surface contact blocks (contact stress,
relative contact displacement, contact print energy with "slave node") [node, values];
face-to-face ones ("slave element+face") [elem, face, values]; totals blocks ("total force",
"total internal energy", "total contact spring energy", "total number of contact elements")
one row of values without id; "statistics for slave set S, master set M" blocks (CF) a dict
"sections" {subtitle: [values]} instead of rows, with set "S/M". Fortran's 3-digit exponents
("1.234567-100") and NaN are read.

summary() keeps the last block of each (kind, set): displacements per node, force totals over
the printed nodes, and with the deck (--inp) the reactions: per direction, the sum of the
printed forces over the nodes that *BOUNDARY holds in that direction (in any step) -- with
CalculiX's "forces" being the internal nodal forces, this is the support reaction; contact
totals where printed (CF statistics, number of contact elements, spring energy, and max/mean
of the printed contact pressures and normal relative displacements).

applied_loads() sums *CLOAD (node or node set) and *DLOAD P1..P6 on C3D8/C3D8R/C3D8I faces
(resultant = -p * vector area of the face, outward; a positive pressure pushes into the
element), per step with CalculiX's carry-over (loads stay from step to step, OP=NEW clears,
a repeated node/DOF or element/face replaces). Follower effects under NLGEOM are not included
(the resultant is the one of the undeformed faces). Other load labels and element types are
listed under "skipped".
"""
import json
import math
import os
import re
import sys

_NUM = re.compile(r"^[\s+\-0-9.EeDdNnAa]+$")
HEADER = re.compile(r"^\s*(?P<title>[A-Za-z].*?)\s*(?:and\s+)?time\s*(?P<time>[-+0-9.EeDd]+)\s*$")
# ccx 2.11 wrote some headers truncated: "...(elem, integ.pnt.,exx,...) forset EALL" and
# "internal energy density (elem, integ.pnt.,eneset EALL"
FOR_SET = re.compile(r"^(?P<kind>[^(]*?)\s*(?:\((?P<cols>[^)]*?)\)?)?\s*(?:for\s*)?set\s+(?P<set>\S+)\s*$")
FOR_ALL = re.compile(r"^(?P<kind>.*?)\s*(?:\((?P<cols>[^)]*)\))?\s*for\s*all contact elements\s*$")
STATS = re.compile(r"^statistics for slave set (?P<slave>\S+), master set (?P<master>\S+)\s*$")
STATS_SURF = re.compile(r"^statistics for surface set (?P<set>\S+)\s*$")
TOTAL_NOSET = re.compile(r"^(?P<kind>total .*?)\s*for\s*$")


def _float(tok):
    t = tok.strip()
    if t.lower() == "nan":
        return float("nan")
    t = t.replace("D", "E").replace("d", "E")
    try:
        return float(t)
    except ValueError:
        m = re.match(r"^([-+]?\d*\.\d*)([-+]\d{3})$", t)  # Fortran drops the E beyond E+-99
        if m:
            return float(m.group(1) + "E" + m.group(2))
        raise


def _numeric_line(line):
    s = line.strip()
    if not s:
        return None
    toks = s.split()
    try:
        return [_float(t) for t in toks]
    except ValueError:
        return None


def _header(line):
    """(kind, columns, set, time, id_columns) of a block header, or None."""
    m = HEADER.match(line.rstrip())
    if not m:
        return None
    title = re.sub(r"\s+", " ", m.group("title")).strip()
    time = _float(m.group("time"))
    cols = []
    setname = None
    kind = title
    if STATS.match(title):
        mm = STATS.match(title)
        kind, setname = "statistics", mm.group("slave") + "/" + mm.group("master")
    elif STATS_SURF.match(title):
        kind, setname = "surface statistics", STATS_SURF.match(title).group("set")
    elif TOTAL_NOSET.match(title):
        kind = TOTAL_NOSET.match(title).group("kind")
    else:
        for rx in (FOR_SET, FOR_ALL):
            mm = rx.match(title)
            if mm:
                kind = mm.group("kind").strip()
                cols = [c.strip() for c in (mm.group("cols") or "").split(",") if c.strip()]
                setname = mm.groupdict().get("set")
                break
        else:
            if title.endswith(" for"):
                kind = title[:-4].strip()
    # "energy)for all" is printed without a blank in ccx: strip leftovers
    kind = re.sub(r"\s*for$", "", kind).strip()
    ids = []
    for c in ("elem", "element", "integ.pnt.", "slave node", "slave element+face"):
        if c in cols:
            ids.append(c)
    values = [c for c in cols if c not in ids]
    if "slave element+face" in ids:
        ids = ["elem", "face"]
    elif "slave node" in ids:
        ids = ["node"]
    elif "integ.pnt." in ids:
        ids = ["elem", "ip"]
    elif ids:
        ids = ["elem"]
    elif not kind.startswith("total") and kind not in ("statistics", "surface statistics"):
        ids = ["node"]
    return kind, ids, values, setname, time


def parse_dat(path):
    """All blocks of a .dat file, in file order (see the module doc)."""
    blocks = []
    cur = None
    sub = None
    with open(path, encoding="latin-1") as f:
        for line in f:
            h = _header(line)
            if h:
                kind, ids, values, setname, time = h
                cur = {"kind": kind, "ids": ids, "columns": values, "set": setname, "time": time}
                if kind in ("statistics", "surface statistics"):
                    cur["sections"] = {}
                else:
                    cur["rows"] = []
                blocks.append(cur)
                sub = None
                continue
            if cur is None:
                continue
            # A node with a *TRANSFORM printed in its local system ends its row with " L"
            # (printoutnode.f); the row is local, the numbers are read the same.
            local = line.rstrip().endswith(" L")
            nums = _numeric_line(line.rstrip()[:-2] if local else line)
            if nums is None:
                if line.strip() and "sections" in cur:
                    sub = re.sub(r"\s+", " ", line.strip())
                    cur["sections"][sub] = []
                continue
            if "sections" in cur:
                if sub is not None:
                    cur["sections"][sub].extend(nums)
                continue
            row = [int(v) if k < len(cur["ids"]) else v for k, v in enumerate(nums)]
            cur["rows"].append(row)
    return {"file": os.path.basename(path), "blocks": blocks}


def _last_blocks(dat):
    last = {}
    for b in dat["blocks"]:
        last[(b["kind"], b["set"])] = b
    return last


# ----------------------------------------------------------------------------- deck reading
C3D8_FACES = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]
HEX8 = ("C3D8", "C3D8R", "C3D8I")


def _cards(path):
    """[(KEYWORD, {PARAM: value}, [data lines as lists of fields])], following *INCLUDE."""
    out = []
    cur = None
    with open(path, encoding="latin-1") as f:
        for raw in f:
            line = raw.rstrip("\r\n")
            if line.startswith("**") or not line.strip():
                continue
            if line.startswith("*"):
                parts = [p.strip() for p in line[1:].split(",")]
                kw = re.sub(r"\s+", " ", parts[0].upper())
                params = {}
                for p in parts[1:]:
                    if p:
                        a, _, b = p.partition("=")
                        params[a.strip().upper()] = b.strip() if _ else True
                if kw == "INCLUDE":
                    out.extend(_cards(os.path.join(os.path.dirname(path), params["INPUT"])))
                    cur = None
                    continue
                cur = (kw, params, [])
                out.append(cur)
            elif cur is not None:
                cur[2].append([t.strip() for t in line.split(",")])
    return out


def _set_items(data, generate):
    items = []
    for fields in data:
        fields = [t for t in fields if t != ""]
        if generate:
            a, b = int(fields[0]), int(fields[1])
            s = int(fields[2]) if len(fields) > 2 else 1
            items.extend(range(a, b + 1, s))
        else:
            items.extend(fields)
    return items


def read_inp(path):
    """Nodes, elements (type, nodes), node and element sets, *BOUNDARY entries per step and
    the load cards (CLOAD / DLOAD) per step of a deck: the part of a deck this tool needs."""
    nodes, elements, nsets, elsets = {}, {}, {}, {}
    steps = [{"cload": [], "dload": [], "boundary": []}]  # index 0: model data (before *STEP)
    cur_type = None
    for kw, params, data in _cards(path):
        if kw == "NODE":
            for f in data:
                nid = int(f[0])
                nodes[nid] = tuple(float(v) if v else 0.0 for v in (f[1:4] + ["0", "0"])[:3])
            if "NSET" in params:
                nsets.setdefault(params["NSET"].upper(), []).extend(int(f[0]) for f in data)
        elif kw == "ELEMENT":
            cur_type = params.get("TYPE", "").upper()
            vals = [int(v) for f in data for v in f if v != ""]
            npe = {"C3D8": 8, "C3D8R": 8, "C3D8I": 8, "C3D20": 20, "C3D20R": 20, "C3D10": 10,
                   "C3D4": 4, "C3D6": 6, "C3D15": 15}.get(cur_type)
            if npe is None:  # one element per line
                for f in data:
                    v = [int(x) for x in f if x != ""]
                    elements[v[0]] = (cur_type, v[1:])
                ids = [int(f[0]) for f in data]
            else:
                ids = []
                for k in range(0, len(vals), npe + 1):
                    elements[vals[k]] = (cur_type, vals[k + 1:k + 1 + npe])
                    ids.append(vals[k])
            if "ELSET" in params:
                elsets.setdefault(params["ELSET"].upper(), []).extend(ids)
        elif kw in ("NSET", "ELSET"):
            name = params[kw].upper()
            items = _set_items(data, "GENERATE" in params)
            target = nsets if kw == "NSET" else elsets
            lst = target.setdefault(name, [])
            for it in items:
                if isinstance(it, int) or re.match(r"^-?\d+$", str(it)):
                    lst.append(int(it))
                else:
                    lst.extend(target.get(str(it).upper(), []))
        elif kw == "STEP":
            steps.append({"cload": [], "dload": [], "boundary": [], "params": params})
        elif kw == "CLOAD":
            steps[-1]["cload"].append(("OP=NEW" if str(params.get("OP", "")).upper() == "NEW" else None, data))
        elif kw == "DLOAD":
            steps[-1]["dload"].append(("OP=NEW" if str(params.get("OP", "")).upper() == "NEW" else None, data))
        elif kw == "BOUNDARY":
            steps[-1]["boundary"].append((params, data))
    return {"nodes": nodes, "elements": elements, "nsets": nsets, "elsets": elsets, "steps": steps}


def _node_list(deck, ref):
    if re.match(r"^-?\d+$", ref):
        return [int(ref)]
    return deck["nsets"].get(ref.upper(), [])


def _elem_list(deck, ref):
    if re.match(r"^-?\d+$", ref):
        return [int(ref)]
    return deck["elsets"].get(ref.upper(), [])


def _sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def face_vector_area(deck, elem, face):
    """Outward vector area of face S<face> (1..6) of a hex8 element: half the cross product of
    the diagonals, exact for a bilinear quadrilateral; oriented away from the element centroid."""
    _, conn = deck["elements"][elem]
    x = [deck["nodes"][n] for n in conn[:8]]
    f = [x[k] for k in C3D8_FACES[face - 1]]
    a = _cross(_sub(f[2], f[0]), _sub(f[3], f[1]))
    a = [0.5 * v for v in a]
    c_el = [sum(p[i] for p in x) / 8 for i in range(3)]
    c_f = [sum(p[i] for p in f) / 4 for i in range(3)]
    if sum(a[i] * (c_f[i] - c_el[i]) for i in range(3)) < 0:
        a = [-v for v in a]
    return a


def applied_loads(deck):
    """Per step: the sum of the concentrated loads and the pressure resultants (see module doc)."""
    if isinstance(deck, str):
        deck = read_inp(deck)
    cl, dl = {}, {}  # (node, dof) -> value ; (elem, label) -> value
    out = []
    skipped = set()
    for k, st in enumerate(deck["steps"][1:], start=1):
        for op, data in st["cload"]:
            if op:
                cl = {}
            for f in data:
                for n in _node_list(deck, f[0]):
                    cl[(n, int(f[1]))] = float(f[2]) if len(f) > 2 and f[2] else 0.0
        for op, data in st["dload"]:
            if op:
                dl = {}
            for f in data:
                label = f[1].upper()
                for e in _elem_list(deck, f[0]):
                    dl[(e, label)] = float(f[2]) if len(f) > 2 and f[2] else 0.0
        fc = [0.0, 0.0, 0.0]
        for (n, dof), v in cl.items():
            if 1 <= dof <= 3:
                fc[dof - 1] += v
            else:
                skipped.add("CLOAD dof %d" % dof)
        fp = [0.0, 0.0, 0.0]
        area = 0.0
        for (e, label), p in dl.items():
            m = re.match(r"^P([1-6])$", label)
            etype = deck["elements"].get(e, ("?", None))[0]
            if not m or etype not in HEX8:
                skipped.add("DLOAD %s on %s" % (label, etype))
                continue
            a = face_vector_area(deck, e, int(m.group(1)))
            area += math.sqrt(sum(v * v for v in a))
            for i in range(3):
                fp[i] -= p * a[i]
        out.append({"step": k, "cload_sum": fc, "dload_resultant": fp,
                    "dload_loaded_area": area,
                    "total": [fc[i] + fp[i] for i in range(3)]})
    return {"steps": out, "skipped": sorted(skipped)}


def constrained_nodes(deck):
    """{dof (1..3): set of nodes} held by *BOUNDARY in any step (zero or prescribed value)."""
    held = {1: set(), 2: set(), 3: set()}
    for st in deck["steps"]:
        for params, data in st["boundary"]:
            for f in data:
                if not f or not f[0]:
                    continue
                first = int(f[1]) if len(f) > 1 and f[1] else 1
                last = int(f[2]) if len(f) > 2 and f[2] else first
                for n in _node_list(deck, f[0]):
                    for d in range(first, last + 1):
                        if d in held:
                            held[d].add(n)
    return held


# ----------------------------------------------------------------------------- summary / compare
def summary(dat, deck=None):
    """Reference figures of the last block of each kind (see module doc)."""
    if isinstance(dat, str):
        dat = parse_dat(dat)
    if isinstance(deck, str):
        deck = read_inp(deck)
    res = {"file": dat["file"], "times": sorted({b["time"] for b in dat["blocks"]})}
    last = _last_blocks(dat)
    for (kind, setname), b in last.items():
        key = kind if setname is None else "%s [%s]" % (kind, setname)
        if kind == "displacements":
            res.setdefault("displacements", {})[setname] = {
                "time": b["time"], "nodes": {str(r[0]): r[1:4] for r in b["rows"]}}
        elif kind == "forces":
            tot = [sum(r[i] for r in b["rows"]) for i in (1, 2, 3)]
            entry = {"time": b["time"], "sum_over_printed_nodes": tot}
            if deck is not None:
                held = constrained_nodes(deck)
                rows = {r[0]: r for r in b["rows"]}
                entry["reaction"] = [sum(rows[n][d] for n in held[d] if n in rows) for d in (1, 2, 3)]
                entry["reaction_nodes_printed"] = [len([n for n in held[d] if n in rows]) for d in (1, 2, 3)]
                entry["reaction_nodes_held"] = [len(held[d]) for d in (1, 2, 3)]
            res.setdefault("forces", {})[setname] = entry
        elif kind.startswith("total"):
            res.setdefault("totals", {})[key] = {"time": b["time"], "values": b["rows"][0] if b["rows"] else []}
        elif kind in ("statistics", "surface statistics"):
            res.setdefault("contact_statistics", {})[setname] = {"time": b["time"], **b["sections"]}
        elif kind in ("contact stress", "relative contact displacement", "contact print energy"):
            nid = len(b["ids"])
            col = [r[nid] for r in b["rows"]]
            entry = {"time": b["time"], "count": len(col)}
            if col:
                entry.update({"max": max(col), "min": min(col), "mean": sum(col) / len(col)})
            res.setdefault("contact", {})[kind] = entry
    return res


def _flat(b):
    if "sections" in b:
        return [v for k in sorted(b["sections"]) for v in b["sections"][k]]
    return [v for r in b["rows"] for v in r]


def compare(a, b, rtol=1e-4):
    """Block-by-block comparison of two parsed .dat files, matched by (kind, set, occurrence).
    A block differs when max |a - b| > rtol * max(|a|, |b|) over the block (ids compared
    exactly; NaN equals NaN). Returns (ok, [report lines])."""
    if isinstance(a, str):
        a = parse_dat(a)
    if isinstance(b, str):
        b = parse_dat(b)

    def keyed(d):
        seen, out = {}, {}
        for blk in d["blocks"]:
            k = (blk["kind"], blk["set"])
            seen[k] = seen.get(k, 0) + 1
            out[k + (seen[k],)] = blk
        return out

    ka, kb = keyed(a), keyed(b)
    ok = True
    lines = []
    for k in list(ka) + [k for k in kb if k not in ka]:
        name = "%s [%s] #%d" % k
        if k not in ka or k not in kb:
            ok = False
            lines.append("%s: only in %s" % (name, a["file"] if k in ka else b["file"]))
            continue
        ba, bb = ka[k], kb[k]
        if ba["time"] != bb["time"]:
            lines.append("%s: time %g vs %g" % (name, ba["time"], bb["time"]))
        if "rows" in ba:
            nid = len(ba["ids"])
            ida = [tuple(r[:nid]) for r in ba["rows"]]
            idb = [tuple(r[:nid]) for r in bb["rows"]]
            if ida != idb:
                ok = False
                lines.append("%s: rows differ (%d vs %d rows)" % (name, len(ida), len(idb)))
                continue
            va = [v for r in ba["rows"] for v in r[nid:]]
            vb = [v for r in bb["rows"] for v in r[nid:]]
        else:
            va, vb = _flat(ba), _flat(bb)
        if len(va) != len(vb):
            ok = False
            lines.append("%s: %d vs %d values" % (name, len(va), len(vb)))
            continue
        pairs = [(x, y) for x, y in zip(va, vb) if not (math.isnan(x) and math.isnan(y))]
        scale = max([abs(x) for x, _ in pairs] + [abs(y) for _, y in pairs] + [0.0])
        diff = max([abs(x - y) for x, y in pairs] + [0.0])
        rel = diff / scale if scale > 0 else (0.0 if diff == 0 else math.inf)
        bad = rel > rtol or any(math.isnan(x) != math.isnan(y) for x, y in zip(va, vb))
        ok = ok and not bad
        lines.append("%s: max |diff| %.3e, block max %.3e, relative %.2e %s"
                     % (name, diff, scale, rel, "DIFFERS" if bad else "ok"))
    return ok, lines


def main(argv):
    if len(argv) < 3 or argv[1] not in ("parse", "summary", "compare", "loads"):
        print(__doc__)
        return 2
    cmd = argv[1]
    if cmd == "parse":
        json.dump(parse_dat(argv[2]), sys.stdout, indent=1)
    elif cmd == "summary":
        deck = argv[argv.index("--inp") + 1] if "--inp" in argv else None
        json.dump(summary(argv[2], deck), sys.stdout, indent=1)
    elif cmd == "loads":
        json.dump(applied_loads(argv[2]), sys.stdout, indent=1)
    elif cmd == "compare":
        rtol = float(argv[argv.index("--rtol") + 1]) if "--rtol" in argv else 1e-4
        ok, lines = compare(argv[2], argv[3], rtol)
        print("\n".join(lines))
        print("same within rtol %g" % rtol if ok else "DIFFERENT (rtol %g)" % rtol)
        return 0 if ok else 1
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
