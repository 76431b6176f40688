#!/usr/bin/python3
"""What exact (non-penetrating, frictionless) contact gives on the small decks of this folder:
a linear, small-displacement solve, independent of feticon and of CalculiX, to size the
penalty effect of CalculiX's answers. Not a reference for feticon's own discretization.

    exact_contact_estimate.py DECK.inp            # nodal displacements and contact forces
    exact_contact_estimate.py DECK.inp penalty k  # same, contact as linear springs of
                                                  # stiffness k per slave node (checking)

Model: hex8 (C3D8/C3D8R/C3D8I all as full 2x2x2 Gauss trilinear), isotropic *ELASTIC per
*SOLID SECTION; *BOUNDARY (all steps), *EQUATION, *CLOAD and *DLOAD P1..P6 of the last step
(pressure as p*A/4 per face node: exact for flat parallelogram faces, which is what these
decks have). Contact: node-to-surface for every *CONTACT PAIR, the slave nodes (node surface,
or the nodes of the slave faces) projected once onto the closest master face of the reference
configuration; constraint n.(u_s - u_m(xi)) >= -g0 with g0 the initial signed gap (negative
for an initial overlap, which is pushed out in full); active set by the multipliers' sign.
Needs numpy (/usr/bin/python3 on Debian: python3-numpy).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from calculix_dat import (C3D8_FACES, _cards, _elem_list, _node_list,  # noqa: E402
                          face_vector_area, read_inp)

_G = 1 / math.sqrt(3)
_NAT = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                 [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], float)


def hex8_stiffness(X, E, nu):
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    D = np.zeros((6, 6))
    D[:3, :3] = lam
    D[range(3), range(3)] += 2 * mu
    D[range(3, 6), range(3, 6)] = mu
    K = np.zeros((24, 24))
    for g in [(a, b, c) for a in (-_G, _G) for b in (-_G, _G) for c in (-_G, _G)]:
        dN = np.zeros((8, 3))
        for a in range(8):
            xi, eta, ze = _NAT[a]
            dN[a] = [xi * (1 + eta * g[1]) * (1 + ze * g[2]), eta * (1 + xi * g[0]) * (1 + ze * g[2]),
                     ze * (1 + xi * g[0]) * (1 + eta * g[1])]
        dN /= 8
        J = dN.T @ X
        dNx = dN @ np.linalg.inv(J).T
        B = np.zeros((6, 24))
        for a in range(8):
            bx, by, bz = dNx[a]
            B[0, 3 * a], B[1, 3 * a + 1], B[2, 3 * a + 2] = bx, by, bz
            B[3, 3 * a], B[3, 3 * a + 1] = by, bx
            B[4, 3 * a], B[4, 3 * a + 2] = bz, bx
            B[5, 3 * a + 1], B[5, 3 * a + 2] = bz, by
        K += B.T @ D @ B * np.linalg.det(J)
    return K


def _model(path):
    deck = read_inp(path)
    mats, section, eqs, pairs, surfs, mat = {}, {}, [], [], {}, None
    for kw, params, data in _cards(path):
        if kw == "MATERIAL":
            mat = params["NAME"].upper()
        elif kw == "ELASTIC":
            mats[mat] = (float(data[0][0]), float(data[0][1]))
        elif kw == "SOLID SECTION":
            for e in deck["elsets"][params["ELSET"].upper()]:
                section[e] = params["MATERIAL"].upper()
        elif kw == "EQUATION":
            k = 0
            while k < len(data):
                n = int(data[k][0])
                flat, k = [], k + 1
                while len(flat) < 3 * n:
                    flat += [v for v in data[k] if v != ""]
                    k += 1
                eqs.append([(int(flat[3 * t]), int(flat[3 * t + 1]), float(flat[3 * t + 2])) for t in range(n)])
        elif kw == "SURFACE":
            name = params["NAME"].upper()
            if str(params.get("TYPE", "ELEMENT")).upper() == "NODE":
                surfs[name] = ("node", [n for f in data for n in _node_list(deck, f[0])])
            else:
                surfs[name] = ("elem", [(e, int(f[1].strip()[1:])) for f in data for e in _elem_list(deck, f[0])])
        elif kw == "CONTACT PAIR":
            pairs.append((data[0][0].upper(), data[0][1].upper()))
    return deck, mats, section, eqs, pairs, surfs


def _face_nodes(deck, e, f):
    conn = deck["elements"][e][1]
    return [conn[k] for k in C3D8_FACES[f - 1]]


def _project(xs, Xf):
    """Local coordinates and shape values of the orthogonal projection of xs on a bilinear face."""
    c = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], float)
    s = np.zeros(2)
    for _ in range(50):
        N = 0.25 * (1 + c[:, 0] * s[0]) * (1 + c[:, 1] * s[1])
        dN = np.stack([0.25 * c[:, 0] * (1 + c[:, 1] * s[1]), 0.25 * c[:, 1] * (1 + c[:, 0] * s[0])], 1)
        T = dN.T @ Xf
        ds = np.linalg.solve(T @ T.T, T @ (xs - N @ Xf))
        s += ds
        if np.abs(ds).max() < 1e-14:
            break
    return s, 0.25 * (1 + c[:, 0] * s[0]) * (1 + c[:, 1] * s[1])


def solve(path, penalty=None):
    """({node: u}, {slave node: normal contact force}) of the deck (see the module doc)."""
    deck, mats, section, eqs, pairs, surfs = _model(path)
    ids = sorted(deck["nodes"])
    pos = {n: i for i, n in enumerate(ids)}
    ndof = 3 * len(ids)
    X = np.array([deck["nodes"][n] for n in ids])
    K, F = np.zeros((ndof, ndof)), np.zeros(ndof)
    for e, (_, conn) in deck["elements"].items():
        dofs = [3 * pos[n] + d for n in conn for d in range(3)]
        K[np.ix_(dofs, dofs)] += hex8_stiffness(X[[pos[n] for n in conn]], *mats[section[e]])
    last = deck["steps"][-1]
    for _, data in last["cload"]:
        for f in data:
            for n in _node_list(deck, f[0]):
                F[3 * pos[n] + int(f[1]) - 1] += float(f[2])
    for _, data in last["dload"]:
        for f in data:
            for e in _elem_list(deck, f[0]):
                face = int(f[1].strip()[1:])
                a = np.array(face_vector_area(deck, e, face))
                for n in _face_nodes(deck, e, face):
                    F[3 * pos[n]:3 * pos[n] + 3] -= float(f[2]) * a / 4
    rows, rhs = [], []
    for step in deck["steps"]:
        for _, data in step["boundary"]:
            for f in data:
                first = int(f[1])
                last_dof = int(f[2]) if len(f) > 2 and f[2] else first
                value = float(f[3]) if len(f) > 3 and f[3] else 0.0
                for n in _node_list(deck, f[0]):
                    for d in range(first, last_dof + 1):
                        r = np.zeros(ndof)
                        r[3 * pos[n] + d - 1] = 1
                        rows.append(r)
                        rhs.append(value)
    for terms in eqs:
        r = np.zeros(ndof)
        for n, d, c in terms:
            r[3 * pos[n] + d - 1] += c
        rows.append(r)
        rhs.append(0.0)
    cands = []  # (slave node, constraint row r, initial gap g0): r.u + g0 >= 0
    for slave, master in pairs:
        kind, items = surfs[slave]
        snodes = items if kind == "node" else sorted({n for e, f in items for n in _face_nodes(deck, e, f)})
        for s in snodes:
            best = None
            for e, face in surfs[master][1]:
                fn = _face_nodes(deck, e, face)
                Xf = X[[pos[n] for n in fn]]
                loc, N = _project(X[pos[s]], Xf)
                if np.all(np.abs(loc) <= 1 + 1e-9):
                    a = np.array(face_vector_area(deck, e, face))
                    nrm = a / np.linalg.norm(a)  # outward of the master body
                    gap = float(nrm @ (X[pos[s]] - N @ Xf))
                    if best is None or abs(gap) < abs(best[2]):
                        r = np.zeros(ndof)
                        r[3 * pos[s]:3 * pos[s] + 3] += nrm
                        for k, m in enumerate(fn):
                            r[3 * pos[m]:3 * pos[m] + 3] -= N[k] * nrm
                        best = (s, r, gap)
            if best:
                cands.append(best)
    if penalty is not None:
        for s, r, gap in cands:
            K += penalty * np.outer(r, r)
            F -= penalty * gap * r
        active = []
    else:
        active = list(range(len(cands)))
    scale = np.abs(np.diag(K)).mean()
    for _ in range(100):
        C = np.array(rows + [cands[i][1] for i in active])
        g = np.array(rhs + [-cands[i][2] for i in active])
        A = np.block([[K, scale * C.T], [scale * C, np.zeros((len(C), len(C)))]])
        sol = np.linalg.lstsq(A, np.concatenate([F, scale * g]), rcond=None)[0]
        u, lam = sol[:ndof], scale * sol[ndof + len(rows):]
        if penalty is not None:
            break
        tol = 1e-12 * max(1.0, np.abs(lam).max() if len(lam) else 1.0)
        new = [i for k, i in enumerate(active) if -lam[k] >= -tol]
        new += [i for i in range(len(cands)) if i not in active and cands[i][1] @ u + cands[i][2] < -1e-14]
        if sorted(new) == sorted(active):
            break
        active = sorted(new)
    disp = {n: u[3 * pos[n]:3 * pos[n] + 3].tolist() for n in ids}
    if penalty is not None:
        forces = {s: max(0.0, -penalty * float(r @ u + gap)) for s, r, gap in cands}
    else:
        forces = {cands[i][0]: float(-lam[k]) for k, i in enumerate(active)}
    return disp, forces


if __name__ == "__main__":
    k = float(sys.argv[3]) if len(sys.argv) > 3 and sys.argv[2] == "penalty" else None
    u, f = solve(sys.argv[1], k)
    for n in sorted(u):
        print("%8d %14.6e %14.6e %14.6e" % (n, *u[n]))
    print("contact forces:", " ".join("%d:%.6g" % (n, v) for n, v in sorted(f.items())),
          " total %.6g" % sum(f.values()))
