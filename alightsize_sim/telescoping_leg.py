"""Telescoping leg forces on the capsule (AFFDL-TR-66-33 Sec. V.E, eq. 12-30).

A massless leg pivots at its attachment b; an axial cell shortens with the leg and rotational pads at
lever AS resist its tilt alpha toward beta. With the footpad at P on the terrain, the deflection vector
d = P - attachment (leg axes, eq. 16) gives al, alpha, beta (eq. 17-19), the deflections (eq. 20-21, exact
or small-angle) and the cell forces; the ground force on the leg, which the massless leg passes to the
capsule at the footpad, is X = -AF1 u + F_alpha e_alpha + F_beta e_beta (eq. 25-27) with F_alpha, F_beta
the pads' generalized forces over the lever al, so that X . dd equals the cells' work exactly (energy
closes). Cell rates come from the kinematics, not finite differences.

`TelescopingLeg` describes a leg; `legs.pack` turns a set of legs into the arrays the compiled functions take
(geo[2] is the length rho, geo[5] the number of pads).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from . import crush_cell
from .crush_cell import CellModel
from .vec3 import cross, mtv, mv


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

    def __post_init__(self):
        if len(self.pads) != len(self.pad_angles):
            raise ValueError("one pad cell per pad angle")
        if not (self.rho > 0 and self.pad_lever >= 0):
            raise ValueError("leg length must be > 0 and pad lever >= 0")

    @property
    def cells(self) -> tuple[CellModel, ...]:
        return (self.axial, *self.pads)


@njit(cache=True)
def leg_frame(alpha, beta):
    """Unit vectors u (attachment -> footpad), e_alpha, e_beta in leg axes (eq. 17-19), as tuples."""
    ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
    return (sa * cb, sa * sb, -ca), (ca * cb, ca * sb, sa), (-sb, cb, 0.0)


@njit(cache=True)
def cell_force(cells, i, j, mem, delta, rate):
    """Force of cell j of leg i at deflection delta and rate, given its committed memory."""
    cd, cf, cn, ck, cc, cy = cells
    m = cn[i, j]
    return crush_cell.force(cd[i, j, :m], cf[i, j, :m], ck[i, j], cc[i, j], cy[i, j], (mem[j, 0], mem[j, 1]),
                            delta, rate)


@njit(cache=True)
def leg_force(geo, cells, i, mem, shape, P, kin, out):
    """Forces of leg i with its footpad held at P (terrain axes) under a capsule moving as kin = (r, R, v, w): at r,
    attitude R (principal -> terrain), velocity v (terrain), rate w (principal); `shape` is unused (the articulated
    leg's interface). Writes into out = (defl, frc, rte, X) the deflections, cell forces, deflection rates and the
    force X on the capsule (principal axes); returns (cells' power, alpha, beta, 0)."""
    r, R, v, w = kin
    defl, frc, rte, X = out
    attach, to_body, rho, pad_lever, angles, n_pads, small = geo[0], geo[1], geo[2], geo[3], geo[4], geo[5], geo[6]
    a0, a1, a2 = attach[i, 0], attach[i, 1], attach[i, 2]
    L = to_body[i]
    b0, b1, b2 = mtv(R, P[0] - r[0], P[1] - r[1], P[2] - r[2])     # CG -> footpad, principal axes
    c0, c1, c2 = cross(w[0], w[1], w[2], b0, b1, b2)
    s0, s1, s2 = mtv(R, v[0], v[1], v[2])
    d0, d1, d2 = mtv(L, b0 - a0, b1 - a1, b2 - a2)                 # leg axes (eq. 16)
    e0, e1, e2 = mtv(L, -c0 - s0, -c1 - s1, -c2 - s2)              # its rate with the footpad held
    al = np.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    horiz = np.sqrt(d0 * d0 + d1 * d1)
    alpha = np.arctan2(horiz, -d2)                                  # eq. 17-19
    beta = np.arctan2(d1, d0) if horiz > 0.0 else 0.0
    sa, ca = horiz / al, -d2 / al                                   # leg_frame(alpha, beta) without the trig
    cb, sb = (d0 / horiz, d1 / horiz) if horiz > 0.0 else (1.0, 0.0)
    u, ea, eb = (sa * cb, sa * sb, -ca), (ca * cb, ca * sb, sa), (-sb, cb, 0.0)
    delta = rho[i] - al                                             # eq. 20
    rate = -(u[0] * e0 + u[1] * e1 + u[2] * e2)
    defl[0], rte[0] = delta, rate
    frc[0] = cell_force(cells, i, 0, mem, delta, rate)
    power = frc[0] * rate
    alpha_dot = (ea[0] * e0 + ea[1] * e1 + ea[2] * e2) / al
    beta_dot = (eb[0] * e0 + eb[1] * e1) / horiz if horiz > 0.0 else 0.0   # al sin(alpha) = horiz
    if small[i]:
        tilt, tilt_rate = alpha, 1.0
        ratio = alpha / sa if alpha > 0.0 else 1.0      # T(alpha) / sin(alpha)
    else:
        tilt, tilt_rate, ratio = sa, ca, 1.0
    q_alpha, q_beta = 0.0, 0.0
    for j in range(n_pads[i]):
        cj, sj = angles[i, j, 0], angles[i, j, 1]
        cg, sg = cj * cb + sj * sb, sj * cb - cj * sb               # cos, sin of (gamma_j - beta)
        dj = pad_lever[i] * tilt * cg                               # eq. 21
        rj = pad_lever[i] * (tilt_rate * cg * alpha_dot + tilt * sg * beta_dot)
        fj = cell_force(cells, i, j + 1, mem, dj, rj)
        defl[j + 1], frc[j + 1], rte[j + 1] = dj, fj, rj
        power += fj * rj
        q_alpha += fj * pad_lever[i] * tilt_rate * cg               # eq. 23: generalized forces of the pads
        q_beta += fj * pad_lever[i] * sg                            # eq. 24
    fa, fb = q_alpha / al, q_beta * ratio / al
    X[0], X[1], X[2] = mv(L, -frc[0] * u[0] + fa * ea[0] + fb * eb[0], -frc[0] * u[1] + fa * ea[1] + fb * eb[1],
                          -frc[0] * u[2] + fa * ea[2])              # eq. 25-27
    return power, alpha, beta, 0.0


@njit(cache=True)
def axial_set(cells, i, mem):
    """Permanent set of the axial cell (m)."""
    return crush_cell.permanent_set(cells[3][i, 0], mem[0, 0], mem[0, 1])


@njit(cache=True)
def footpad_at(geo, i, length, alpha, beta, r, R):
    """Terrain position (tuple) of leg i's footpad at length and leg-axes direction (alpha, beta) (eq. 13-15)."""
    attach, to_body = geo[0], geo[1]
    u = leg_frame(alpha, beta)[0]
    l0, l1, l2 = mv(to_body[i], length * u[0], length * u[1], length * u[2])
    x0, x1, x2 = mv(R, attach[i, 0] + l0, attach[i, 1] + l1, attach[i, 2] + l2)
    return r[0] + x0, r[1] + x1, r[2] + x2


@njit(cache=True)
def free_footpad(geo, cells, i, mem, shape, r, R):
    """Unloaded footpad in terrain axes (eq. 13): length rho less the axial permanent set, at the tilt the
    leg had when it last left the ground; shape = (alpha, beta, held), held the axial compression beyond the
    set the leg had as it left (lift_shape), which it keeps in the air."""
    return footpad_at(geo, i, geo[2][i] - axial_set(cells, i, mem) - shape[2], shape[0], shape[1], r, R)


@njit(cache=True)
def aim(geo, cells, i, mem, T, r, R):
    """Free shape (alpha, beta, held) of leg i whose footpad is at T (terrain axes): free_footpad's inverse."""
    attach, L = geo[0], geo[1]
    b0, b1, b2 = mtv(R, T[0] - r[0], T[1] - r[1], T[2] - r[2])
    d0, d1, d2 = mtv(L[i], b0 - attach[i, 0], b1 - attach[i, 1], b2 - attach[i, 2])     # leg axes (eq. 16)
    horiz = np.sqrt(d0 * d0 + d1 * d1)
    return (np.arctan2(horiz, -d2), np.arctan2(d1, d0) if horiz > 0.0 else 0.0,
            geo[2][i] - axial_set(cells, i, mem) - np.sqrt(horiz * horiz + d2 * d2))   # eq. 17-20


@njit(cache=True)
def at_set(geo, cells, i, mem, shape):
    """Free shape with the axial cell at least at its permanent set (no compression short of it held): a leg that left
    the grazing band short of its set is caught on a vertical face at its set, so that it does not leave at once."""
    return shape[0], shape[1], max(shape[2], 0.0)


@njit(cache=True)
def lift_shape(geo, cells, i, mem, loaded, main, r, R):
    """Stored free geometry of a leg lifting off at tilt loaded = (alpha, beta, psi) (leg_force's shape) with axial
    deflection `main` (psi, r, R unused: the articulated leg's interface): the tilt and the compression beyond its
    set it still held, so that its free footpad starts where it left the terrain, not below it, and its touchdown
    can be found. That compression is zero at a lift-off located where the leg goes slack, positive at a jump of its
    event function (a slide leaving the leg's reach), negative for a leg leaving the grazing band short of its set
    (it keeps its length)."""
    return loaded[0], loaded[1], main - axial_set(cells, i, mem)

