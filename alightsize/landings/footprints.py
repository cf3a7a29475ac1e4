"""Where the footpads went: the terrain features each leg met and a plan view of the footprints on the terrain."""

from __future__ import annotations

import numpy as np

from alightsize_sim.landing import Result, Scene
from alightsize_sim.terrain import BOX, HEIGHT_FIELD, HEMISPHERE, STEP, features_along
from alightsize_sim.terrain import pack as pack_terrain

KIND_NAMES = {STEP: "step", HEMISPHERE: "hemisphere rock", BOX: "box rock", HEIGHT_FIELD: "height field"}


def features_met(scene: Scene, res: Result) -> list[list[str]]:
    """Per leg, the features under its footpad while on the ground, in the order first met ("step 1",
    "hemisphere rock 2", "height field"; "plane" for the bare ground; numbered from 1 in the scene's order)."""
    packed = pack_terrain(scene.terrain)
    out = []
    for i in range(len(scene.legs)):
        on = res.contact[:, i] > 0
        kinds, indices = features_along(packed, np.ascontiguousarray(res.footpad[on, i, :2]))
        pairs = np.stack([kinds, indices], axis=1)
        _, first = np.unique(pairs, axis=0, return_index=True)
        met = []
        for kind, index in pairs[np.sort(first)]:
            if kind < 0:
                name = "plane"
            else:
                name = KIND_NAMES[kind] if kind == HEIGHT_FIELD else f"{KIND_NAMES[kind]} {index + 1}"
            if name not in met:
                met.append(name)
        out.append(met)
    return out


def plot_footprints(scene: Scene, res: Result, ax) -> None:
    """Plan view in terrain axes: the height field shaded, steps (edge, raised side hatched), rocks outlined, each
    leg's footpad track on the ground (its colour) with its first touchdown marked, and the CG track."""
    import matplotlib.patches as mp
    ter = scene.terrain
    tracks = [res.footpad[res.contact[:, i] > 0, i, :2] for i in range(len(scene.legs))]
    pts = np.vstack([t for t in tracks if len(t)] + [res.y[:, :2]])
    lo, hi = pts.min(axis=0) - 0.5, pts.max(axis=0) + 0.5
    f = ter.height_field
    if f is not None:
        ny, nx = f.z.shape
        ax.imshow(f.z, origin="lower", extent=(f.x0, f.x0 + (nx - 1) * f.dx, f.y0, f.y0 + (ny - 1) * f.dy),
                  cmap="Greys", alpha=0.5)
    span = float(np.hypot(*(hi - lo)))
    for k, s in enumerate(ter.steps):
        d = np.array([np.cos(np.radians(s.direction_deg)), np.sin(np.radians(s.direction_deg))])
        left = np.array([-d[1], d[0]])
        a, b = np.array([s.x, s.y]) - span * d, np.array([s.x, s.y]) + span * d
        ax.plot(*np.c_[a, b], color="k", lw=1.2)
        ax.add_patch(mp.Polygon([a, b, b + 0.15 * span * left, a + 0.15 * span * left], closed=True, fill=False,
                                hatch="//", lw=0, edgecolor="0.6"))
        ax.annotate(f"step {k + 1}: {s.height * 1000:+.0f} mm", (s.x, s.y), fontsize=7)
    for k, r in enumerate(ter.hemispheres):
        ax.add_patch(mp.Circle((r.x, r.y), r.radius, fill=False, color="k", lw=1.0))
        ax.annotate(f"rock {k + 1}", (r.x, r.y), fontsize=7, ha="center")
    for k, b in enumerate(ter.boxes):
        ax.add_patch(mp.Rectangle((b.x - b.length / 2, b.y - b.width / 2), b.length, b.width, angle=b.yaw_deg,
                                  rotation_point="center", fill=False, color="k", lw=1.0))
        ax.annotate(f"box {k + 1}", (b.x, b.y), fontsize=7, ha="center")
    for i, t in enumerate(tracks):
        if len(t):
            ax.plot(t[:, 0], t[:, 1], color=f"C{i}", lw=1.5, label=f"leg {i + 1}")
            ax.plot(*t[0], "o", color=f"C{i}", ms=4)
    ax.plot(res.y[:, 0], res.y[:, 1], "k--", lw=0.8, label="CG")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("terrain x, m")
    ax.set_ylabel("terrain y, m")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
