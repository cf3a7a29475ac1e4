"""Quasi-static member-load envelopes of the articulated leg (AFFDL-TR-66-33 App. III, Tables 14-22).

Both cells stroke at the loads their curves give at each leg position; every member load is evaluated
over a grid of (alpha, beta, psi) at once (numpy) and each member's largest tension and compression are
kept with the position where they occur. Positions where a cell has stroked past the end of its
crushing plateau (bottomed) are left out by default, as the report sweeps "stroking of the upper and
lower absorbers at their crushing load". Ties go to the smallest psi, then alpha, then beta, in grid
order. Combined envelopes (Tables 21-22) keep the extreme over several configurations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from alightsize_sim.articulated_cells import lower_deflection, return_spring_force, upper_deflection
from alightsize_sim.articulated_kinematics import ArticulatedGeometry
from alightsize_sim.articulated_statics import MEMBERS, TrussAngles, member_loads, reactions
from alightsize_sim.crush_curve import CrushCurve

# Member labels as Tables 14-22 print them (mirror-image members in parentheses).
MEMBER_LABELS = {"PL1": "PL1, (PL3)", "PL2": "PL2, (PL6)", "PU1": "PU1, (PU2)", "R1213": "R12/13", "F": "F (ground)"}


@dataclass(frozen=True)
class Grid:
    """Sweep grid, radians: alpha and beta values, psi step (psi runs from each case's initial to final)."""

    alpha: tuple[float, ...]
    beta: tuple[float, ...]
    psi_step: float
    include_bottomed: bool = False

    def psi(self, start: float, stop: float) -> np.ndarray:
        n = int(np.floor((stop - start) / self.psi_step + 1e-9))
        return start + self.psi_step * np.arange(n + 1)

    def size(self, start: float, stop: float) -> int:
        return len(self.alpha) * len(self.beta) * len(self.psi(start, stop))


def default_grid() -> Grid:
    """alpha 0-45 deg by 1, beta -175..180 deg by 5 (the tables' (-180, 180] convention), psi by 1 deg."""
    return Grid(tuple(np.radians(np.arange(0, 46))), tuple(np.radians(np.arange(-175, 181, 5))), np.radians(1.0))


@dataclass(frozen=True)
class LegCase:
    """One configuration: geometry, truss angles, cell curves and the psi range swept."""

    name: str
    geometry: ArticulatedGeometry
    truss: TrussAngles
    upper: CrushCurve
    lower: CrushCurve
    psi_initial: float
    psi_final: float


@dataclass(frozen=True)
class Extreme:
    value: float                           # N
    at: tuple[float, ...]                  # alpha, beta, psi (rad); () where a landing's tripod load peaked
    configuration: str


@dataclass(frozen=True)
class MemberEnvelope:
    member: str
    tension: Extreme | None
    compression: Extreme | None


def _cells(case: LegCase, alpha, psi):
    """(AF1, AF2, stroking): cell forces from the loading curves (return spring added to AF2, FORCE) and
    whether neither cell has passed the end of its crushing plateau; each deflection computed once."""
    g = case.geometry
    d1 = upper_deflection(g, psi, case.psi_initial)
    d2 = lower_deflection(g, alpha)
    af1 = case.upper.loading_force(d1)
    af2 = case.lower.loading_force(d2) + return_spring_force(g, d2)
    stroking = (d1 <= case.upper.bottoming * (1 + 1e-12)) & (d2 <= case.lower.bottoming * (1 + 1e-12))
    return af1, af2, stroking


def cell_forces(case: LegCase, alpha, psi):
    """(AF1, AF2) at the given positions from the loading curves."""
    return _cells(case, alpha, psi)[:2]


def member_fields(case: LegCase, grid: Grid):
    """(psi, alpha, beta) axes and every member's load over them, arrays shaped (n_psi, n_alpha, n_beta);
    NaN at positions left out (a cell bottomed, unless the grid includes them). ValueError when no position
    is left, or a member is not finite at one that is."""
    psi = grid.psi(case.psi_initial, case.psi_final)
    alpha, beta = np.asarray(grid.alpha), np.asarray(grid.beta)
    P, A, B = psi[:, None, None], alpha[None, :, None], beta[None, None, :]
    af1, af2, stroking = _cells(case, A, P)
    loads = member_loads(reactions(case.geometry, A, B, P, af1, af2), case.truss)
    shape = (len(psi), len(alpha), len(beta))
    keep = np.ones(shape, bool) if grid.include_bottomed else np.broadcast_to(stroking, shape)
    if not keep.any():
        raise ValueError(f"no grid position of configuration {case.name!r} has both cells on their crushing plateau")
    fields = {}
    for m in MEMBERS:
        f = np.broadcast_to(loads[m], shape)
        if not np.all(np.isfinite(f[keep])):
            raise ValueError(f"member {m} is not finite somewhere on the grid of configuration {case.name!r}")
        fields[m] = np.where(keep, f, np.nan)
    return (psi, alpha, beta), fields


def _extreme(field: np.ndarray, axes, pick, config: str) -> Extreme:
    i = np.unravel_index(int(pick(field)), field.shape)
    psi, alpha, beta = (ax[k] for ax, k in zip(axes, i))
    return Extreme(float(field[i]), (float(alpha), float(beta), float(psi)), config)


def envelope(case: LegCase, grid: Grid) -> tuple[MemberEnvelope, ...]:
    """Each member's maximum tension (> 0) and compression (< 0) over the grid, with positions."""
    axes, fields = member_fields(case, grid)
    return tuple(MemberEnvelope(m,
                                _extreme(f, axes, np.nanargmax, case.name) if np.nanmax(f) > 0 else None,
                                _extreme(f, axes, np.nanargmin, case.name) if np.nanmin(f) < 0 else None)
                 for m, f in fields.items())


def combine(envelopes: list[tuple[MemberEnvelope, ...]]) -> tuple[MemberEnvelope, ...]:
    """Combined envelope (Tables 21-22): per member the largest tension and compression of any case;
    ties go to the earlier case."""
    out = []
    for rows in zip(*envelopes):
        ten = [r.tension for r in rows if r.tension is not None]
        com = [r.compression for r in rows if r.compression is not None]
        out.append(MemberEnvelope(
            rows[0].member,
            max(ten, key=lambda e: e.value) if ten else None,
            min(com, key=lambda e: e.value) if com else None))
    return tuple(out)
