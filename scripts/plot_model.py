#!/usr/bin/python3
"""The pictures of a run: model.png (the deformed surface coloured by von Mises stress) and
contact.png (each contact pair's slave surface coloured by contact pressure, sliding nodes
marked). feticon runs this after every run with plots on (app/model_picture.hpp writes DATA).

Usage: plot_model.py DATA_DIR RESULTS_DIR

Only the surface is drawn: the boundary triangles facing the viewer, sorted back to front
(painter's algorithm) and filled flat, so a model of a million DOFs draws in seconds.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402


def view_basis(plane_strain):
    """Rows: the screen's right and up and the direction towards the viewer."""
    if plane_strain:  # the cross-section, seen from +z
        return np.eye(3)
    azimuth, elevation = np.radians(-60.0), np.radians(25.0)
    toward = np.array([np.cos(elevation) * np.cos(azimuth), np.cos(elevation) * np.sin(azimuth),
                       np.sin(elevation)])
    right = np.cross([0.0, 0.0, 1.0], toward)
    right /= np.linalg.norm(right)
    up = np.cross(toward, right)
    return np.vstack([right, up, toward])


def visible_sorted(points, faces):
    """Faces (rows of corners, a triangle's fourth -1) facing the viewer, back to front: the
    outward normal of the first three corners points towards +depth."""
    p = points[faces[:, :3]]
    normal_depth = np.cross(p[:, 1, :2] - p[:, 0, :2], p[:, 2, :2] - p[:, 0, :2])
    keep = np.nonzero(normal_depth > 0)[0]
    order = np.argsort(p[keep, :, 2].mean(axis=1))
    return keep[order]


def displacement_scale(reference, displacement, large):
    """1 for large displacements (the true deformed shape); else a factor that makes the
    largest displacement 5 % of the model's size, as post-processors do."""
    if large:
        return 1.0
    size = np.ptp(reference, axis=0).max()
    largest = np.linalg.norm(displacement, axis=1).max() if len(displacement) else 0.0
    return 1.0 if largest == 0.0 else 0.05 * size / largest


def draw_surface(ax, screen, faces, values, cmap, label, edges):
    order = visible_sorted(screen, faces)
    shown = faces[order]
    # A triangle repeats its last corner: every polygon has four vertices, one array.
    shown = np.where(shown < 0, shown[:, 2:3], shown)
    polygons = screen[shown][:, :, :2]
    collection = PolyCollection(polygons, array=values[order], cmap=cmap,
                                edgecolors=(0.2, 0.2, 0.2) if edges else "face", linewidths=0.15 if edges else 0.3,
                                antialiaseds=False)
    ax.add_collection(collection)
    ax.set_xlim(polygons[:, :, 0].min(), polygons[:, :, 0].max())
    ax.set_ylim(polygons[:, :, 1].min(), polygons[:, :, 1].max())
    ax.set_aspect("equal")
    plt.colorbar(collection, ax=ax, label=label, shrink=0.8)
    return collection


def model_picture(data, meta, out_dir):
    reference, displacement = data["reference"], data["displacement"]
    large = meta["large_displacements"]
    scale = displacement_scale(reference, displacement, large)
    basis = view_basis(meta["plane_strain"])
    screen = (reference + scale * displacement) @ basis.T
    fig, ax = plt.subplots(figsize=(8, 6.5))
    faces = data["faces"]
    stress_scale, stress_unit, _, _ = units(meta)
    draw_surface(ax, screen, faces, stress_scale * data["von_mises"], "viridis", f"von Mises stress ({stress_unit})",
                 edges=len(faces) < 20000)
    ax.set_axis_off()
    shape = "deformed shape (true scale, large displacements)" if large else \
        f"deformed shape, displacements x {scale:.3g}"
    view = "cross-section seen from +z" if meta["plane_strain"] else "surface"
    ax.set_title(f"{meta['problem']}: {shape}\n{view}, von Mises stress of each cell", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "model.png"), dpi=110)
    plt.close(fig)


def surface_frame(points):
    """Axes of the best-fit plane of the points: two in-plane directions, then the normal."""
    centred = points - points.mean(axis=0)
    _, _, axes = np.linalg.svd(centred, full_matrices=False)
    return axes


def zoom_to_contact(ax, screen, pressure):
    """Limits around the nodes that carry pressure (with a margin of half their extent) when they
    cover a small part of the surface: the contact zone of a Hertz-like contact is tiny."""
    loaded = pressure > 1e-3 * pressure.max() if pressure.max() > 0 else np.zeros(len(pressure), bool)
    if not loaded.any():
        return
    low, high = screen[loaded, :2].min(axis=0), screen[loaded, :2].max(axis=0)
    extent = np.ptp(screen[:, :2], axis=0)
    if np.prod(high - low) > 0.25 * np.prod(extent):
        return
    margin = 0.5 * (high - low).max() + 1e-12
    ax.set_xlim(low[0] - margin, high[0] + margin)
    ax.set_ylim(low[1] - margin, high[1] + margin)
    ax.set_xlabel(ax.get_xlabel() + ", zoomed to the loaded nodes")


def contact_picture(data, meta, out_dir):
    pairs = meta["pairs"]
    if not pairs:
        return
    reference, pressure, slip = data["reference"], data["pressure"], data["slip"]
    triangles, pair_of = data["contact_triangles"], data["contact_pair"]
    stress_scale, stress_unit, length_scale, length_unit = units(meta)
    shown = pairs[:6]
    fig, axes = plt.subplots(1, len(shown), figsize=(6.5 * len(shown), 5.5), squeeze=False)
    for p, ax in enumerate(axes[0]):
        mine = triangles[pair_of == p]
        nodes = np.unique(mine)
        if len(nodes) == 0:
            ax.set_axis_off()
            continue
        if meta["plane_strain"]:  # the slave curve: pressure along its in-plane direction
            frame = surface_frame(reference[nodes][:, :2])
            s = reference[nodes][:, :2] @ frame[0]
            order = np.argsort(s)
            ax.plot(length_scale * s[order], stress_scale * pressure[nodes][order], ".-", ms=3, label="pressure")
            if len(slip):
                ax.plot(length_scale * (slip[:, :2] @ frame[0]), np.zeros(len(slip)), "c|", ms=8,
                        label="sliding nodes")
                ax.legend(loc="upper right", fontsize=8)
            ax.set_xlabel(f"position along the slave surface ({length_unit})")
            ax.set_ylabel(f"contact pressure ({stress_unit})")
        else:  # the slave surface flattened onto its best-fit plane, seen from its normal
            frame = surface_frame(reference[nodes])
            screen = length_scale * (reference @ frame.T)
            tri = Triangulation(screen[nodes, 0], screen[nodes, 1], np.searchsorted(nodes, mine))
            image = ax.tripcolor(tri, stress_scale * pressure[nodes], shading="gouraud", cmap="inferno")
            plt.colorbar(image, ax=ax, label=f"contact pressure ({stress_unit})", shrink=0.8)
            if len(slip):
                sliding = length_scale * (slip @ frame.T)
                ax.plot(sliding[:, 0], sliding[:, 1], "c.", ms=2, label="sliding nodes")
                ax.legend(loc="upper right", fontsize=8)
            ax.set_aspect("equal")
            ax.set_xlabel(f"in-plane coordinate ({length_unit})")
            ax.set_ylabel(f"in-plane coordinate ({length_unit})")
            zoom_to_contact(ax, screen[nodes], pressure[nodes])
        ax.set_title(f"pair {p}: {pairs[p]}\npeak {stress_scale * pressure[nodes].max():.4g} {stress_unit}",
                     fontsize=10)
    if len(pairs) > len(shown):
        fig.suptitle(f"the first {len(shown)} of {len(pairs)} pairs", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "contact.png"), dpi=110)
    plt.close(fig)


def units(meta):
    """Stress scale and label, length scale and label: SI models in MPa and mm, a deck's in its
    own units (CalculiX decks have none fixed)."""
    if meta["si_units"]:
        return 1e-6, "MPa", 1e3, "mm"
    return 1.0, "deck's units", 1.0, "deck's units"


def main():
    data_dir, out_dir = sys.argv[1], sys.argv[2]
    with open(os.path.join(data_dir, "meta.json")) as f:
        meta = json.load(f)
    names = ["reference", "displacement", "faces", "von_mises", "contact_triangles", "contact_pair", "pressure",
             "slip"]
    data = {name: np.load(os.path.join(data_dir, name + ".npy")) for name in names}
    if data["slip"].ndim == 1:
        data["slip"] = data["slip"].reshape(-1, 3)
    model_picture(data, meta, out_dir)
    contact_picture(data, meta, out_dir)


if __name__ == "__main__":
    main()
