"""Loads config: leg geometry, truss angles, sweep grid, configurations with their cell curves, combined
envelopes and the telescoping free body. Read and validated at the boundary; everything SI inside."""

from __future__ import annotations

import re
from dataclasses import dataclass
from math import radians
from pathlib import Path

import numpy as np

from alightsize_sim.articulated_kinematics import ArticulatedGeometry
from alightsize_sim.articulated_statics import TrussAngles

from alightsize.common.config import Node, load_toml
from alightsize.model.legs import LENGTHS, read_curve, read_geometry, read_truss
from alightsize.loads.envelopes import Grid, LegCase, default_grid
from alightsize.loads.telescoping import TelescopingLeg

NAME = re.compile(r"[A-Za-z0-9_.-]{1,31}")     # used in file and sheet names


@dataclass(frozen=True)
class LoadsConfig:
    path: Path
    title: str
    units: str
    grid: Grid
    cases: tuple[LegCase, ...]
    combined: tuple[tuple[str, tuple[str, ...]], ...]
    telescoping: TelescopingLeg | None


def _range(node: Node, name: str, lo: float, hi: float) -> tuple[float, ...]:
    r = node.table(name)
    r.allow(("from", "to", "step"))
    start, stop = r.quantity("from", "angle", positive=False), r.quantity("to", "angle", positive=False)
    step = r.quantity("step", "angle")
    r.finish()
    if not (lo - 1e-12 <= start <= stop <= hi + 1e-12):
        raise r.error("to", f"{np.degrees(lo):g} deg <= from <= to <= {np.degrees(hi):g} deg",
                      f"from {np.degrees(start):g} to {np.degrees(stop):g} deg")
    n = int(np.floor((stop - start) / step + 1e-9))
    return tuple(start + step * np.arange(n + 1))


def _grid(node: Node | None) -> Grid:
    if node is None:
        return default_grid()
    node.allow(("alpha", "beta", "psi_step", "bottomed"))
    base = default_grid()
    alpha = _range(node, "alpha", 0.0, radians(90)) if node.has("alpha") else base.alpha
    beta = _range(node, "beta", radians(-360), radians(360)) if node.has("beta") else base.beta
    step = node.quantity("psi_step", "angle", default=base.psi_step)
    bottomed = node.string("bottomed", "exclude", choices=("exclude", "include"))
    node.finish()
    return Grid(alpha, beta, step, bottomed == "include")


def _name(node: Node) -> str:
    name = node.string("name")
    if not NAME.fullmatch(name):
        raise node.error("name", "1-31 letters, digits, '_', '.' or '-' (it names files and sheets)", repr(name))
    return name


def _case(node: Node, geometry: ArticulatedGeometry | None, truss: TrussAngles | None, where: Node) -> LegCase:
    node.allow(("name", "note", "psi_initial", "psi_final", "upper", "lower", "length_scale",
                "return_spring_rate", "return_spring_preload"))
    if geometry is None or truss is None:
        raise where.error("geometry" if geometry is None else "truss", "a [geometry] and a [truss] table for the "
                          "articulated configurations", "none")
    name = _name(node)
    node.string("note", "")
    p0 = node.quantity("psi_initial", "angle", positive=False)
    p1 = node.quantity("psi_final", "angle", positive=False)
    if not (radians(-90) < p0 < p1 < radians(90)):
        raise node.error("psi_final", "-90 deg < psi_initial < psi_final < 90 deg",
                         f"{np.degrees(p0):g} and {np.degrees(p1):g} deg")
    scale = node.number("length_scale", 1.0)
    g = geometry._replace(**{k: scale * getattr(geometry, k) for k in LENGTHS})
    g = g._replace(SPRG=node.quantity("return_spring_rate", "spring_rate", default=g.SPRG, positive=False),
                PLD=node.quantity("return_spring_preload", "force", default=g.PLD, positive=False))
    if g.SPRG < 0 or g.PLD < 0:
        raise node.error("return_spring_rate", "a return spring rate and preload of 0 or more", f"{g.SPRG}, {g.PLD}")
    upper, lower = read_curve(node.table("upper")), read_curve(node.table("lower"))
    node.finish()
    return LegCase(name, g, truss, upper, lower, p0, p1)


def _telescoping(node: Node) -> TelescopingLeg:
    node.allow(("axial_crush", "rotational_crush", "pad_lever", "length", "bearing_length", "friction", "note"))
    leg = TelescopingLeg(node.quantity("axial_crush", "force"), node.quantity("rotational_crush", "force"),
                         node.quantity("pad_lever", "length"), node.quantity("length", "length"),
                         node.quantity("bearing_length", "length"), node.number("friction", positive=False))
    node.string("note", "")
    node.finish()
    if leg.pad_lever >= leg.length:
        raise node.error("pad_lever", f"a pad lever shorter than the leg ({leg.length:.4g} m)",
                         f"{leg.pad_lever:.4g} m")
    if not 0 <= leg.friction < 1:
        raise node.error("friction", "a friction coefficient in [0, 1)", f"{leg.friction}")
    return leg


def read_loads(path: str | Path, root: Node | None = None) -> LoadsConfig:
    """Read and validate a loads config (or the tables `root` holds, e.g. derived from a lander file);
    problems are InputErrors naming file and key path."""
    path = Path(path)
    root = load_toml(path) if root is None else root
    root.allow(("loads", "report", "geometry", "truss", "grid", "configuration", "combined", "telescoping"))
    head = root.table("loads", optional=True)
    title = head.string("title", path.stem) if head else path.stem
    if head:
        head.finish()
    rep = root.table("report", optional=True)
    units = rep.string("units", "US", choices=("US", "SI")) if rep else "US"
    if rep:
        rep.finish()
    geometry = read_geometry(root.table("geometry")) if root.has("geometry") else None
    truss = read_truss(root.table("truss")) if root.has("truss") else None
    grid = _grid(root.table("grid", optional=True))
    cases = tuple(_case(n, geometry, truss, root) for n in root.tables("configuration", optional=True))
    names = [c.name for c in cases]
    dup = next((n for n in names if names.count(n) > 1), None)
    if dup:
        raise root.error("configuration", "configuration names unique", f"{dup!r} twice")
    combined = []
    for n in root.tables("combined", optional=True):
        n.allow(("name", "configurations", "note"))
        name, members = _name(n), n.strings("configurations")
        n.string("note", "")
        n.finish()
        missing = [m for m in members if m not in names]
        if missing or not members:
            raise n.error("configurations", "names of configurations in this file (" + ", ".join(names) + ")",
                          repr(missing or members))
        if name in names or name in [c[0] for c in combined]:
            raise n.error("name", "a name not used by a configuration or another combination", repr(name))
        combined.append((name, tuple(members)))
    tele = _telescoping(root.table("telescoping")) if root.has("telescoping") else None
    root.finish()
    if not cases and tele is None:
        raise root.error("configuration", "at least one [[configuration]] or a [telescoping] table", "neither")
    return LoadsConfig(path, title, units, grid, cases, tuple(combined), tele)
