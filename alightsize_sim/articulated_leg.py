"""Articulated leg forces on the capsule (AFFDL-TR-66-33 Sec. V.F, eq. 38-61, subroutine FORCE).

A parallelogram (members AU, upper cell across its diagonal, angle psi) carries at its outboard end a
fulcrum ring in which a peg leg tilts by alpha toward beta (lower cell along its axis, return spring SPRG
with preload PLD). The leg is massless: with its footpad held at P on the terrain, the tip in leg axes S
gives alpha (the root of eq. 41 nearest the last accepted alpha: `nearest_root`), psi (eq. 43) and beta
(eq. 44); the cells' generalized forces fix the ground force F by F . d(tip)/dq = Q_q (eq. 59-61,
`articulated_statics.ground_components`, the same code the loads use). Cell rates come from the same
Jacobian (q' = J^-1 tip'), not from finite differences; the power returned is F . tip', the work rate
taken from the capsule, so the energy audit closes whatever the seat does.

Departure from FORCE at a seated peg leg: FORCE zeroes the horizontal ground force for alpha <= 1e-5
(beta is undefined there) and keeps the vertical one from the upper cell alone, a jump to the full
solution, which needs ~0.3 of the vertical load sideways (AS/AL) just past the seat. Here the two are
blended linearly over alpha in [0, SEAT]: a stiff but finite seat, so forces stay continuous and the
integrator's error control and event location keep working.

Leg data sit in the rows of geo[8] (`ART_FIELDS`): the fifteen `ArticulatedGeometry` values, the initial
psi and the upper cell's free length RHO. Cell 0 is the upper (psi) cell, cell 1 the lower (alpha) cell.
The leg's shape (alpha, beta, psi) of the last accepted step picks the root and, off the ground, is the
stored geometry ZETA (FORCE).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .articulated_cells import lower_deflection, lower_lever, return_spring_force, upper_length, upper_lever
from .articulated_kinematics import ArticulatedGeometry, _sin_psi, footpad, nearest_root
from .articulated_statics import ground_components
from .crush_cell import CellModel, permanent_set
from .terrain import clearance
from .telescoping_leg import cell_force
from .vec3 import cross, mtv, mv

SEAT = 1e-3                   # rad: alpha over which the seated (FORCE alpha <= 1e-5) force blends into the full one
ART_FIELDS = ArticulatedGeometry._fields + ("psi0", "RHO")
N_ART = len(ART_FIELDS)


@dataclass(frozen=True)
class ArticulatedLeg:
    """Leg origin (lower inboard parallelogram pivot, m, principal axes), leg-to-principal matrix (S1
    outward, S3 along the capsule axis), geometry, initial psi (rad) and the upper and lower cells."""

    attach: np.ndarray
    to_body: np.ndarray
    geometry: ArticulatedGeometry
    psi0: float
    upper: CellModel
    lower: CellModel

    @property
    def cells(self) -> tuple[CellModel, ...]:
        return (self.upper, self.lower)

    @property
    def row(self) -> np.ndarray:
        """The leg's row of geo[8]."""
        rho = upper_length(self.geometry, self.psi0)
        return np.array([*self.geometry, self.psi0, rho], float)

    @property
    def reach(self) -> float:
        """A length scale of the leg (m): the slide search's first step is 1e-6 of it."""
        g = self.geometry
        return g.AU + g.AL + g.AS


@njit(cache=True)
def geometry(art, i) -> ArticulatedGeometry:
    r = art[i]
    return ArticulatedGeometry(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9], r[10], r[11], r[12],
                               r[13], r[14])


@njit(cache=True)
def leg_force(geo, cells, i, mem, shape, P, kin, out):
    """Forces of leg i with its footpad held at P (terrain axes) under a capsule moving as kin = (r, R, v, w): at r,
    attitude R (principal -> terrain), velocity v (terrain), rate w (principal), the shape of the last accepted step
    choosing the root. Writes into out = (defl, frc, rte, X) the cell deflections, forces and deflection rates and
    the force X on the capsule (principal axes); returns (power, alpha, beta, psi). Out of reach (no root), the
    upper deflection is written as -1 m (short of any set: the leg lifts off) and the forces and rates are zero."""
    r, R, v, w = kin
    defl, frc, rte, X = out
    attach, L, art = geo[0], geo[1][i], geo[8]
    g = geometry(art, i)
    b0, b1, b2 = mtv(R, P[0] - r[0], P[1] - r[1], P[2] - r[2])     # CG -> footpad, principal axes
    c0, c1, c2 = cross(w[0], w[1], w[2], b0, b1, b2)
    u0, u1, u2 = mtv(R, v[0], v[1], v[2])
    s0, s1, s2 = mtv(L, b0 - attach[i, 0], b1 - attach[i, 1], b2 - attach[i, 2])   # tip, leg axes (ZETP)
    e0, e1, e2 = mtv(L, -c0 - u0, -c1 - u1, -c2 - u2)              # its rate with the footpad held
    alpha = nearest_root(g, s0, s1, s2, shape[0])
    if alpha < 0.0:
        defl[0], defl[1], frc[0], frc[1], rte[0], rte[1] = -1.0, 0.0, 0.0, 0.0, 0.0, 0.0
        X[0], X[1], X[2] = 0.0, 0.0, 0.0
        return 0.0, shape[0], shape[1], shape[2]
    sa, ca = np.sin(alpha), np.cos(alpha)
    sp = min(max(_sin_psi(g, s2, alpha), -1.0), 1.0)
    cp = np.sqrt(1.0 - sp * sp)
    psi = np.arcsin(sp)                                             # eq. 43
    hx = s0 - g.AO - g.AU * cp
    h = np.sqrt(hx * hx + s1 * s1)
    if h > 1e-12 * g.AU:
        beta, cb, sb = np.arctan2(s1, hx), hx / h, s1 / h           # eq. 44
    else:                                                           # tip on the peg-leg axis: beta undefined
        beta = shape[1]
        cb, sb = np.cos(beta), np.sin(beta)
    c18, c20 = g.AS * sa + g.AL * ca, g.AL * sa - g.AS * ca
    # Rates: (e_r . tip', tip'_3) = M (psi', alpha'), M = [[-AU sp cb, C18], [AU cp, C20]] (eq. 38-40 differentiated)
    m11, m21 = -g.AU * sp * cb, g.AU * cp
    det = m11 * c20 - c18 * m21
    er = cb * e0 + sb * e1
    psi_dot = (er * c20 - c18 * e2) / det
    alpha_dot = (m11 * e2 - m21 * er) / det
    lever1 = g.AU * upper_lever(g, psi)                             # d Delta_1 / d psi (eq. 45-46, 49)
    d1 = upper_length(g, psi) - art[i, N_ART - 1]
    rte[0] = lever1 * psi_dot
    f1 = cell_force(cells, i, 0, mem, d1, rte[0])
    lever2 = lower_lever(g, alpha)                                  # d Delta_2 / d alpha (eq. 47-48, FP4)
    d2 = lower_deflection(g, alpha)
    rte[1] = lever2 * alpha_dot
    f2 = cell_force(cells, i, 1, mem, d2, rte[1])
    af2 = f2 + return_spring_force(g, d2)
    x0, x1, x2 = ground_components(g, (sa, ca, sb, cb, sp, cp), lever1 / g.AU * f1, lever2 * af2)   # eq. 59-61
    k = min(alpha / SEAT, 1.0)
    x0, x1, x2 = k * x0, k * x1, k * x2 + (1.0 - k) * lever1 * f1 / (g.AU * cp)   # seated: FORCE's alpha <= 1e-5
    defl[0], defl[1], frc[0], frc[1] = d1, d2, f1, f2
    X[0], X[1], X[2] = mv(L, x0, x1, x2)
    return x0 * e0 + x1 * e1 + x2 * e2, alpha, beta, psi


@njit(cache=True)
def _to_terrain(geo, i, s0, s1, s2, r, R):
    l0, l1, l2 = mv(geo[1][i], s0, s1, s2)
    attach = geo[0]
    x0, x1, x2 = mv(R, attach[i, 0] + l0, attach[i, 1] + l1, attach[i, 2] + l2)
    return r[0] + x0, r[1] + x1, r[2] + x2


@njit(cache=True)
def free_footpad(geo, cells, i, mem, shape, r, R):
    """Terrain position (tuple) of the tip of the stored geometry ZETA = tip(alpha, beta, psi) (FORCE 3.10; cells
    and mem unused: the telescoping leg's interface)."""
    s0, s1, s2 = footpad(geometry(geo[8], i), shape[0], shape[1], shape[2])
    return _to_terrain(geo, i, s0, s1, s2, r, R)


@njit(cache=True)
def lift_shape(geo, cells, i, mem, loaded, main, r, R):
    """Stored geometry at lift-off (FORCE 3.10): the peg leg springs back to alpha = 0 at the lift-off psi if
    its tip clears the terrain there, else the loaded shape (alpha, beta, psi) is kept (main, the upper cell's
    deflection, unused: the telescoping leg's interface)."""
    alpha, beta, psi = loaded
    tip = free_footpad(geo, cells, i, mem, (0.0, beta, psi), r, R)
    if clearance(geo[9], tip[0], tip[1], tip[2]) >= 0.0:
        return 0.0, beta, psi
    return alpha, beta, psi


@njit(cache=True)
def at_set(geo, cells, i, mem, shape):
    """Free shape with the upper cell at least at its permanent set: psi raised (Newton on eq. 46, d Delta_1 / d psi =
    AU upper_lever) where a leg that left the grazing band short of its set is caught on a vertical face, so that it
    does not leave through the band at once."""
    g = geometry(geo[8], i)
    target = geo[8][i, N_ART - 1] + permanent_set(cells[3][i, 0], mem[0, 0], mem[0, 1])
    psi = shape[2]
    if upper_length(g, psi) >= target:
        return shape[0], shape[1], psi
    for _ in range(50):
        gap = target - upper_length(g, psi)
        if abs(gap) <= 1e-12 * target:
            break
        psi += gap / (g.AU * upper_lever(g, psi))
    return shape[0], shape[1], psi


@njit(cache=True)
def ring_clearance(geo, i, psi, r, R):
    """Height above the terrain of the lowest point of the fulcrum ring (radius AS about the peg-leg axis,
    in the S1-S2 plane at S3 = AU sin psi - AE): below zero the intermediate member strikes the terrain
    (FORCE's test at App. VII checks one point of this circle)."""
    g = geometry(geo[8], i)
    c = _to_terrain(geo, i, g.AU * np.cos(psi) + g.AO, 0.0, g.AU * np.sin(psi) - g.AE, r, R)
    m0, m1, m2 = mtv(R, 0.0, 0.0, 1.0)
    n0, n1, _ = mtv(geo[1][i], m0, m1, m2)                        # terrain normal in leg axes
    return c[2] - g.AS * np.sqrt(n0 * n0 + n1 * n1)
