"""Telescoping leg forces on the capsule (AFFDL-TR-66-33 Sec. V.E, eq. 12-30).

A massless leg pivots at its attachment b; an axial cell shortens with the leg and rotational pads at
lever AS resist its tilt alpha toward beta. With the footpad at P on the terrain, the deflection vector
d = P - attachment (leg axes, eq. 16) gives al, alpha, beta (eq. 17-19), the deflections (eq. 20-21, exact
or small-angle) and the cell forces; the ground force on the leg, which the massless leg passes to the
capsule at the footpad, is X = -AF1 u + F_alpha e_alpha + F_beta e_beta (eq. 25-27) with F_alpha, F_beta
the pads' generalized forces over the lever al, so that X . dd equals the cells' work exactly (energy
closes). Cell rates come from the kinematics, not finite differences.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import crush_cell
from .crush_cell import CellModel


@dataclass(frozen=True)
class TelescopingLeg:
    """Attachment b (m, principal axes), leg-to-principal matrix L, length rho, pad lever AS (m), pad angles
    gamma_j (rad, leg axes), the axial cell and one cell per pad."""

    attach: np.ndarray
    to_body: np.ndarray
    rho: float
    pad_lever: float
    pad_angles: tuple[float, ...]
    axial: CellModel
    pads: tuple[CellModel, ...]
    small_angle: bool = False

    @property
    def cells(self) -> tuple[CellModel, ...]:
        return (self.axial, *self.pads)


@dataclass(frozen=True)
class LegLoad:
    """One leg's state at an instant: force on the capsule (principal axes) and where it acts, the
    terrain-normal ground force, deflections, cell forces and rates, the cells' power."""

    force: np.ndarray
    point: np.ndarray
    normal: float
    deflections: np.ndarray
    forces: np.ndarray
    power: float
    al: float
    alpha: float
    beta: float


def _frame(alpha: float, beta: float):
    ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
    return (np.array([sa * cb, sa * sb, -ca]), np.array([ca * cb, ca * sb, sa]), np.array([-sb, cb, 0.0]))


def leg_load(leg: TelescopingLeg, memory: np.ndarray, P: np.ndarray, r: np.ndarray, R: np.ndarray,
             v: np.ndarray, omega: np.ndarray) -> LegLoad:
    """Forces of a leg whose footpad is held at P (terrain) by a capsule at r, attitude R, velocity v, rate
    omega (principal axes). memory: (n_cells, 2) committed (dmax, fmax) of axial then pad cells."""
    p = R.T @ (P - r) - leg.attach                      # attachment -> footpad, principal axes
    pdot = -np.cross(omega, p + leg.attach) - R.T @ v
    d, ddot = leg.to_body.T @ p, leg.to_body.T @ pdot   # leg axes (eq. 16)
    al = float(np.linalg.norm(d))
    horiz = float(np.hypot(d[0], d[1]))
    alpha = float(np.arctan2(horiz, -d[2]))             # eq. 17-19
    beta = float(np.arctan2(d[1], d[0])) if horiz > 0 else 0.0
    u, ea, eb = _frame(alpha, beta)
    al_dot = float(u @ ddot)
    alpha_dot = float(ea @ ddot) / al
    beta_dot = float(eb @ ddot) / horiz if horiz > 0 else 0.0     # al sin(alpha) = horiz
    n = 1 + len(leg.pads)
    delta, rate, f = np.empty(n), np.empty(n), np.empty(n)
    delta[0], rate[0] = leg.rho - al, -al_dot                        # eq. 20
    g = np.asarray(leg.pad_angles) - beta
    tilt, tilt_rate = (alpha, 1.0) if leg.small_angle else (np.sin(alpha), np.cos(alpha))
    delta[1:] = leg.pad_lever * tilt * np.cos(g)                     # eq. 21
    rate[1:] = leg.pad_lever * (tilt_rate * np.cos(g) * alpha_dot + tilt * np.sin(g) * beta_dot)
    for j, cell in enumerate(leg.cells):
        dd, ff, k, c, y = cell.arrays
        f[j] = crush_cell.force(dd, ff, k, c, y, memory[j, 0], memory[j, 1], delta[j], rate[j])
    pads = f[1:]
    # Generalized pad forces over the footpad's lever arms: Q_alpha / al and Q_beta / (al sin alpha).
    f_alpha = float(np.sum(pads * leg.pad_lever * tilt_rate * np.cos(g))) / al              # eq. 23
    ratio = alpha / np.sin(alpha) if (leg.small_angle and alpha > 0) else 1.0            # T(alpha) / sin(alpha)
    f_beta = float(np.sum(pads * leg.pad_lever * np.sin(g))) * ratio / al                # eq. 24
    x_leg = -f[0] * u + f_alpha * ea + f_beta * eb                   # eq. 25-27
    force = leg.to_body @ x_leg
    return LegLoad(force, p + leg.attach, float((R @ force)[2]), delta, f, float(f @ rate), al, alpha, beta)


def axial_set(leg: TelescopingLeg, memory: np.ndarray) -> float:
    """Permanent set of the axial cell (m)."""
    return crush_cell.permanent_set(leg.axial.k, memory[0, 0], memory[0, 1])


def axial_deflection(leg: TelescopingLeg, P: np.ndarray, r: np.ndarray, R: np.ndarray) -> float:
    """Delta_1 = rho - al of a leg whose footpad is held at P (eq. 16-17, 20), without the forces."""
    return leg.rho - float(np.linalg.norm(R.T @ (P - r) - leg.attach))


def free_footpad(leg: TelescopingLeg, memory: np.ndarray, tilt: tuple[float, float], r: np.ndarray,
                 R: np.ndarray) -> np.ndarray:
    """Unloaded footpad position in terrain axes (eq. 13-15): length rho less the axial permanent set, at the
    tilt (alpha, beta) the leg had when it last left the ground."""
    length = leg.rho - axial_set(leg, memory)
    u, _, _ = _frame(*tilt)
    return r + R @ (leg.attach + leg.to_body @ (length * u))
