#!/usr/bin/python3
"""How far feticon's displacements are from CalculiX's own reference output (DECK.dat.ref or
DECK.frd.ref of Debian's calculix-ccx-test) on the contact decks that run: the last displacement
block of each printed node set (.dat) or the last DISP block (.frd, every node), max over the
nodes both print of |u_feticon - u_ref|, over max |u_ref|.

    tests/tools/calculix_reference_agreement.py DECK.inp DECK.dat.ref FETICON_OUT_DIR
    tests/tools/calculix_reference_agreement.py DECK.inp DECK.frd.ref FETICON_OUT_DIR
prints one JSON line: {"deck", "nodes", "max_abs_u", "max_diff", "relative", "quantity"}. A
.dat.ref without displacements (some decks print contact output only) is compared by the
contact pressures of its last node-to-face "contact stress" block instead (quantity
"pressure": max |p_feticon - p_ref| over max |p_ref|, slave nodes both print). Exit 2 if the
two share no printed node.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calculix_dat import parse_dat  # noqa: E402
from frd_vs_vtu import frd_displacements  # noqa: E402


def last_displacements(dat):
    """{(set, node): (ux, uy, uz)} of the last displacement block of each set."""
    last = {}
    for block in dat["blocks"]:
        if block["kind"] == "displacements":
            last[block["set"]] = block
    return {(name, row[0]): tuple(row[1:4]) for name, block in last.items() for row in block["rows"]}


def last_pressures(dat):
    """{slave node: pressure} of the last node-to-face contact stress block."""
    last = {}
    for block in dat["blocks"]:
        if block["kind"] == "contact stress" and block.get("rows") and len(block["rows"][0]) == 4:
            last = {row[0]: (row[1],) for row in block["rows"]}
    return last


def main(argv):
    deck, reference, out_dir = argv[1], argv[2], argv[3]
    quantity = "displacement"
    name = os.path.splitext(os.path.basename(deck))[0]
    if reference.endswith(".frd.ref"):
        ref = {row[0]: row[1:] for row in frd_displacements(reference)}
        mine = {row[0]: row[1:] for row in frd_displacements(os.path.join(out_dir, name + ".frd"))}
    else:
        ref_dat, mine_dat = parse_dat(reference), parse_dat(os.path.join(out_dir, name + ".dat"))
        ref, mine = last_displacements(ref_dat), last_displacements(mine_dat)
        if not ref:
            quantity = "pressure"
            ref, mine = last_pressures(ref_dat), last_pressures(mine_dat)
    keys = sorted(set(ref) & set(mine))
    if not keys:
        print(json.dumps({"deck": name, "nodes": 0}))
        return 2
    scale = max(max(abs(v) for v in ref[k]) for k in keys)
    diff = max(max(abs(a - b) for a, b in zip(mine[k], ref[k])) for k in keys)
    print(json.dumps({"deck": name, "nodes": len(keys), "max_abs_u": scale, "max_diff": diff,
                      "relative": diff / scale if scale > 0 else float("inf"), "quantity": quantity}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
