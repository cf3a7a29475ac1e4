"""Readers of a leg's model: crush-cell curves, the articulated leg's geometry (App. III lengths) and its
truss angles. Read and validated at the boundary; SI inside."""

from __future__ import annotations

from math import radians

import numpy as np

from alightsize_sim.articulated_kinematics import ArticulatedGeometry
from alightsize_sim.articulated_statics import TrussAngles
from alightsize_sim.crush_curve import CrushCurve

from alightsize.common.config import Node

LENGTHS = ("AU", "AD", "AS", "AL", "AO", "AE", "AA", "AB", "AG", "AH", "AP", "AQ")
POSITIVE = ("AU", "AD", "AS", "AL")


def _quantities(node: Node, name: str, dim: str) -> list[float]:
    values = node.raw(name)
    if not isinstance(values, list) or len(values) < 2:
        raise node.error(name, f"an array of two or more {dim} quantities", repr(values))
    return [node.parse_quantity(f"{name}[{i}]", v, dim, positive=False) for i, v in enumerate(values)]


def read_curve(node: Node, extra: tuple[str, ...] = ()) -> CrushCurve:
    """A crush curve table (deflection, force, factor, note); with `extra` keys allowed the caller reads
    them and finishes the node."""
    node.allow(("deflection", "force", "factor", "note", *extra))
    d = _quantities(node, "deflection", "length")
    f = _quantities(node, "force", "force")
    factor = node.number("factor", 1.0)
    node.string("note", "")
    if not extra:
        node.finish()
    if len(d) != len(f):
        raise node.error("force", f"as many forces as deflections ({len(d)})", f"{len(f)}")
    if d[0] < 0 or any(b < a for a, b in zip(d, d[1:])):
        raise node.error("deflection", "deflections from 0 upward, never decreasing", repr(node.raw("deflection")))
    if any(x < 0 for x in f):
        raise node.error("force", "forces of 0 or more (a cell never pulls)", repr(node.raw("force")))
    return CrushCurve(tuple(d), tuple(factor * x for x in f))


def read_geometry(node: Node) -> ArticulatedGeometry:
    node.allow(LENGTHS + ("PHI", "return_spring_rate", "return_spring_preload", "note"))
    dims = {k: node.quantity(k, "length") if k in POSITIVE else node.quantity(k, "length", default=0.0, positive=False)
            for k in LENGTHS}
    phi = node.quantity("PHI", "angle", default=0.0, positive=False)
    sprg = node.quantity("return_spring_rate", "spring_rate", default=0.0, positive=False)
    pld = node.quantity("return_spring_preload", "force", default=0.0, positive=False)
    node.string("note", "")
    node.finish()
    if sprg < 0 or pld < 0:
        raise node.error("return_spring_rate", "a return spring rate and preload of 0 or more", f"{sprg}, {pld}")
    return ArticulatedGeometry(PHI=phi, SPRG=sprg, PLD=pld, **dims)


def read_truss(node: Node) -> TrussAngles:
    node.allow(("theta", "gamma", "rho", "note"))
    a = {k: node.quantity(k, "angle") for k in ("theta", "gamma", "rho")}
    node.string("note", "")
    node.finish()
    if not all(0 < v < radians(90) for v in a.values()) or a["gamma"] + a["rho"] >= radians(180):
        raise node.error("theta", "truss angles between 0 and 90 deg",
                         ", ".join(f"{np.degrees(v):.4g} deg" for v in a.values()))
    return TrussAngles(**a)
