"""Telescoping leg free body for the worst loading (AFFDL-TR-66-33 App. III, first part).

Two adjacent rotational pads crush together (beta midway between them) while the axial cell crushes:
the side load P1 at the footpad and P2 at the pads; the lower tube's moment and shear reacted over a
bearing length chi by triangular (w2) and uniform (w1) distributions; sliding friction P4 on them; the
axial cell sees P3 = AF1 - P4.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import sqrt


@dataclass(frozen=True)
class TelescopingLeg:
    """SI inputs: axial and rotational crush loads (N), pad lever a (m), leg length rho (m), bearing
    length chi (m), sliding friction coefficient mu."""

    axial_crush: float
    rotational_crush: float
    pad_lever: float
    length: float
    bearing_length: float
    friction: float


def side_loads(leg: TelescopingLeg) -> tuple[float, float]:
    """(P1, P2): P1 = sqrt(2) AF2 a / rho, P2 = sqrt(2) AF2 (1 - a / rho) (App. III)."""
    moment = sqrt(2.0) * leg.rotational_crush
    return moment * leg.pad_lever / leg.length, moment * (1.0 - leg.pad_lever / leg.length)


def sliding_loads(leg: TelescopingLeg, p1: float) -> dict[str, float]:
    """Bearing distributions and friction for a footpad side load P1 (App. III):
    w2 = 6 P1 (rho - a) / chi^2 (peak of the triangular distributions, 6M/chi^2), w1 = P1 / chi,
    P4 = mu (w1 chi + 0.5 w2 chi), P3 = AF1 - P4."""
    chi = leg.bearing_length
    w2 = 6.0 * p1 * (leg.length - leg.pad_lever) / chi ** 2
    w1 = p1 / chi
    p4 = leg.friction * (w1 * chi + 0.5 * w2 * chi)
    return {"w1": w1, "w2": w2, "P4": p4, "P3": leg.axial_crush - p4}


def free_body(leg: TelescopingLeg) -> dict[str, float]:
    """P1, P2 (N), w1, w2 (N/m), P4, P3 (N) of the App. III free body."""
    p1, p2 = side_loads(leg)
    return {"P1": p1, "P2": p2, **sliding_loads(leg, p1)}
