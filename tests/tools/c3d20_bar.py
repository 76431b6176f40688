"""The mesh of a 1 x 1 square bar along x of length `length` in nx C3D20 cells, one across
(tests/tools/coupled_cantilever_deck.py, pretension_bar_deck.py): its *NODE and *ELEMENT lines.
Nodes lie on a lattice of half-cells, i along x, j along y, k along z (label 9 i + 3 j + k + 1);
`nodes` gives their lattice points, so that callers can pick faces by i."""


def c3d20_bar(length, nx, element_type="C3D20", elset="BAR"):
    """(node lines, element lines, lattice points used) for the bar."""
    h = length / nx

    def label(i, j, k):
        return i * 9 + j * 3 + k + 1

    corners = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
    cells, used = [], set()
    for e in range(nx):
        local = [(2 * e + a, b, c) for a, b, c in corners]
        mids = [tuple((p + q) // 2 for p, q in zip(local[s], local[t])) for s, t in edges]
        cells.append([label(*p) for p in local + mids])
        used.update(local + mids)
    nodes = [f"{label(*p)}, {p[0] * h / 2!r}, {p[1] / 2!r}, {p[2] / 2!r}" for p in sorted(used, key=lambda p: label(*p))]
    elements = [f"*ELEMENT, TYPE={element_type}, ELSET={elset}"]
    for n, cell in enumerate(cells):
        elements.append(f"{n + 1}, " + ", ".join(map(str, cell[:15])) + ",")
        elements.append(", ".join(map(str, cell[15:])))
    return nodes, elements, used, label
