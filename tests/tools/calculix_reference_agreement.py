#!/usr/bin/python3
"""How far feticon's displacements are from CalculiX's own reference output (DECK.dat.ref of
Debian's calculix-ccx-test) on the contact decks that run: the last displacement block of each
printed node set, max over the nodes both print of |u_feticon - u_ref|, over max |u_ref|.

    tests/tools/calculix_reference_agreement.py DECK.inp DECK.dat.ref FETICON_OUT_DIR
prints one JSON line: {"deck", "nodes", "max_abs_u", "max_diff", "relative"}; exit 2 if the two
share no printed node (a reference without displacements, or another NODE PRINT set).
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calculix_dat import parse_dat  # noqa: E402


def last_displacements(dat):
    """{(set, node): (ux, uy, uz)} of the last displacement block of each set."""
    last = {}
    for block in dat["blocks"]:
        if block["kind"] == "displacements":
            last[block["set"]] = block
    return {(name, row[0]): tuple(row[1:4]) for name, block in last.items() for row in block["rows"]}


def main(argv):
    deck, reference, out_dir = argv[1], argv[2], argv[3]
    name = os.path.splitext(os.path.basename(deck))[0]
    ref = last_displacements(parse_dat(reference))
    mine = last_displacements(parse_dat(os.path.join(out_dir, name + ".dat")))
    keys = sorted(set(ref) & set(mine))
    if not keys:
        print(json.dumps({"deck": name, "nodes": 0}))
        return 2
    scale = max(max(abs(v) for v in ref[k]) for k in keys)
    diff = max(max(abs(a - b) for a, b in zip(mine[k], ref[k])) for k in keys)
    print(json.dumps({"deck": name, "nodes": len(keys), "max_abs_u": scale, "max_diff": diff,
                      "relative": diff / scale if scale > 0 else float("inf")}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
