"""Footpad slip on the terrain (AFFDL-TR-66-33 Sec. V.E.5, eq. 31-37, subroutine SLIP).

The ground force is first computed with the footpad where it was at the last accepted step. If its in-plane
part FE12 exceeds the potential friction force (mu_S FE3 while sticking, mu_D FE3 while sliding; eq. 32-34),
the footpad slides: as in the report, the leg's tilt alpha is varied at fixed beta, with the footpad kept in
the terrain plane (eq. 35-37), until FE12 = mu_D FE3.

The report bracketed the crossing but lost runs when the crossing moved near lift-off ("ND", Table 4). Here
the search always brackets: alpha moves from the held position in the direction the leg pushes the
footpad, with growing steps, until FE12 <= mu_D FE3 or the leg's ray leaves the terrain. Along that path the
leg either meets the friction cone or unloads (both forces vanish as the footpad runs toward the horizon,
where FE12 = mu_D FE3 = 0), so a sign change exists; false position with the Illinois modification then
closes on it. The answer is always a valid contact point on the friction-feasible side of the crossing.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .telescoping_leg import ground_point, leg_force
from .vec3 import mv

MAX_EXPAND = 60
MAX_REFINE = 100


@njit(cache=True)
def _ground(geo, cells, i, mem, P, r, R, v, w, defl, frc, X):
    """(FE12, FE3, FE1, FE2, cells' power, alpha, beta) with the footpad at P."""
    power, alpha, beta, _ = leg_force(geo, cells, i, mem, P, r, R, v, w, defl, frc, X)
    fe = mv(R, X[0], X[1], X[2])                                # eq. 31
    return np.sqrt(fe[0] * fe[0] + fe[1] * fe[1]), fe[2], fe[0], fe[1], power, alpha, beta   # eq. 32


@njit(cache=True)
def _at(geo, cells, i, mem, mu, alpha, beta, r, R, v, w, P, defl, frc, X):
    """Excess and scale with the footpad where the ray (alpha, beta) meets the terrain; valid flag."""
    if not ground_point(geo, i, alpha, beta, r, R, P):
        return -1.0, 0.0, False
    fe12, fe3, _, _, _, _, _ = _ground(geo, cells, i, mem, P, r, R, v, w, defl, frc, X)
    return fe12 - mu * max(fe3, 0.0), fe12 + abs(fe3), True


@njit(cache=True)
def footpad_force(geo, cells, i, mem, P0, sliding, mu_s, mu_d, r, R, v, w, P, defl, frc, X, tol=1e-12):
    """Footpad position P and the leg's forces (written to defl, frc, X) with friction; returns
    (sliding 0/1, cells' power, alpha, beta). P0 is the footpad at the last accepted step."""
    P[:] = P0
    fe12, fe3, fe1, fe2, power, alpha0, beta = _ground(geo, cells, i, mem, P, r, R, v, w, defl, frc, X)
    if fe12 <= (mu_d if sliding else mu_s) * max(fe3, 0.0):    # eq. 33-34: holds
        return 0, power, alpha0, beta
    h0 = fe12 - mu_d * max(fe3, 0.0)
    if h0 <= 0.0:                                               # static limit exceeded, dynamic one not
        return 1, power, alpha0, beta
    # Direction of the slide: the leg's in-plane push on the footpad, along the alpha path.
    Pa, Pb = np.empty(3), np.empty(3)
    eps = 1e-7
    ok_a = ground_point(geo, i, alpha0 + eps, beta, r, R, Pa)
    ok_b = ground_point(geo, i, alpha0 - eps, beta, r, R, Pb)
    sgn = 1.0
    if ok_a and ok_b and -(fe1 * (Pa[0] - Pb[0]) + fe2 * (Pa[1] - Pb[1])) < 0.0:
        sgn = -1.0
    # Expand until the excess changes sign (or the ray leaves the terrain).
    a_lo, h_lo = alpha0, h0
    step = 1e-4
    a_hi, h_hi, ok_hi = alpha0, h0, True
    for _ in range(MAX_EXPAND):
        a_hi = alpha0 + sgn * step
        h_hi, _, ok_hi = _at(geo, cells, i, mem, mu_d, a_hi, beta, r, R, v, w, P, defl, frc, X)
        if h_hi <= 0.0:
            break
        a_lo, h_lo = a_hi, h_hi
        step *= 4.0
    # Refine: bisection while an end is off the terrain, then Illinois false position.
    side = 0
    for _ in range(MAX_REFINE):
        if abs(a_hi - a_lo) <= tol:
            break
        if ok_hi:
            a_m = a_hi - h_hi * (a_hi - a_lo) / (h_hi - h_lo)
            if not (min(a_lo, a_hi) < a_m < max(a_lo, a_hi)):
                a_m = 0.5 * (a_lo + a_hi)
        else:
            a_m = 0.5 * (a_lo + a_hi)
        h_m, scale_m, ok_m = _at(geo, cells, i, mem, mu_d, a_m, beta, r, R, v, w, P, defl, frc, X)
        if ok_m and abs(h_m) <= tol * (scale_m + 1.0):
            a_lo, a_hi, h_hi, ok_hi = a_m, a_m, h_m, True
            break
        if h_m > 0.0:
            a_lo, h_lo = a_m, h_m
            if side == 1 and ok_hi:
                h_hi *= 0.5
            side = 1
        else:
            a_hi, h_hi, ok_hi = a_m, h_m, ok_m
            if side == -1:
                h_lo *= 0.5
            side = -1
    a_end = a_hi if ok_hi else a_lo
    ground_point(geo, i, a_end, beta, r, R, P)
    _, _, _, _, power, alpha, beta_end = _ground(geo, cells, i, mem, P, r, R, v, w, defl, frc, X)
    return 1, power, alpha, beta_end
