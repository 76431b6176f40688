#!/usr/bin/python3
"""A CalculiX deck from Gmsh's Abaqus export, as a CalculiX user prepares one: a deck written
by other tools than feticon, for the test that feticon reads such decks (issue 37).

Gmsh (`gmsh MESH.msh -0 -format inp`) writes *NODE, the volume cells as C3D8 and every
physical surface as CPS4 elements, with an *ELSET per physical group. CalculiX takes no
surface elements for contact or pressure; the usual preprocessing (and this script) replaces
each physical surface by a *SURFACE of the C3D8 faces it covers (S1-S6 by the CalculiX manual's
C3D8 face table) and an *NSET of its nodes, drops the CPS4 elements, and appends the model
data given in MODEL_TAIL (materials, sections, supports, contact, step).

    gmsh_inp_to_calculix.py GMSH.inp MODEL_TAIL.inp OUT.inp
"""
import sys

# CalculiX C3D8 faces S1..S6 as 0-based local nodes (CalculiX manual, C3D8).
FACES = [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]


def cards(lines):
    """(keyword line, [data lines]) in order."""
    out = []
    for line in lines:
        if line.startswith("**") or not line.strip():
            continue
        if line.startswith("*"):
            out.append((line.rstrip("\n"), []))
        elif out:
            out[-1][1].append(line.rstrip("\n"))
    return out


def numbers(data):
    return [int(v) for line in data for v in line.split(",") if v.strip()]


def main(gmsh_inp, tail, out_path):
    nodes_text, solids, quads, named = [], {}, {}, {}
    solid_text = []
    for key, data in cards(open(gmsh_inp)):
        head = key.upper().replace(" ", "")
        if head.startswith("*NODE"):
            nodes_text = data
        elif head.startswith("*ELEMENT"):
            kind = head.split("TYPE=")[1].split(",")[0]
            rows = [[int(v) for v in line.split(",") if v.strip()] for line in data]
            if kind == "C3D8":
                solid_text.append((key, data))
                solids.update({r[0]: r[1:] for r in rows})
            elif kind == "CPS4":
                quads.update({r[0]: r[1:] for r in rows})
        elif head.startswith("*ELSET"):
            named[key.split("=")[1].strip()] = numbers(data)
    face_of = {}
    for element, conn in solids.items():
        for k, face in enumerate(FACES):
            face_of[tuple(sorted(conn[i] for i in face))] = (element, k + 1)
    with open(out_path, "w") as out:
        out.write("*HEADING\nGmsh export of %s, surfaces made by gmsh_inp_to_calculix.py\n*NODE\n" % gmsh_inp)
        out.write("\n".join(nodes_text) + "\n")
        for key, data in solid_text:
            out.write(key + "\n" + "\n".join(data) + "\n")
        for name, members in named.items():
            if all(m in solids for m in members):
                out.write("*ELSET, ELSET=%s\n" % name)
                out.write("".join("%d,\n" % m for m in members))
            elif all(m in quads for m in members):
                out.write("*SURFACE, NAME=%s, TYPE=ELEMENT\n" % name)
                for m in members:
                    element, face = face_of[tuple(sorted(quads[m]))]
                    out.write("%d, S%d\n" % (element, face))
                out.write("*NSET, NSET=%s_N\n" % name)
                out.write("".join("%d,\n" % n for n in sorted({n for m in members for n in quads[m]})))
        out.write(open(tail).read())


if __name__ == "__main__":
    main(*sys.argv[1:4])
