"""Articulated leg (parallelogram + peg leg) footpad kinematics, AFFDL-TR-66-33 Sec. V.F.

Forward position eq. 38-40 as corrected in GUIDE.md (subroutine FORCE); inverse from a footpad
position to (alpha, beta, psi) by a scalar equation in alpha whose roots are all bracketed, then the
root nearest the previous alpha is taken (as SINALP does with its quartic eq. 41), so the solution
never jumps to another branch at a root crossing. SI units, angles in radians, numpy-vectorized.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit
from scipy.optimize import brentq, minimize_scalar


class ArticulatedGeometry(NamedTuple):
    """Lengths (m) and angle (rad) of Fig. 22-25, FORTRAN names (GUIDE.md table).

    AU parallelogram member, AO peg-leg axis offset from the lower outboard pivot, AS fulcrum-ring lever
    arm, AL peg-leg height, AE drop from the lower outboard pivot to the ring plane; AD pivot spacing at
    angle PHI from vertical; AA, AB inboard and AH, AG outboard offsets of the upper cell; AP, AQ the
    lower cell's attachments above and below the ring plane; SPRG, PLD return spring rate (N/m) and
    preload (N). Only the first five enter the footpad kinematics. A named tuple of floats, so the
    compiled simulator takes the same object as the vectorized loads code.
    """

    AU: float
    AO: float
    AS: float
    AL: float
    AE: float
    AD: float = 0.0
    AA: float = 0.0
    AB: float = 0.0
    AG: float = 0.0
    AH: float = 0.0
    AP: float = 0.0
    AQ: float = 0.0
    PHI: float = 0.0
    SPRG: float = 0.0
    PLD: float = 0.0


@njit(cache=True)
def tip_radius(g: ArticulatedGeometry, alpha):
    """Horizontal reach of the peg-leg tip about its axis, AS - AS cos(alpha) + AL sin(alpha) (eq. 38-39)."""
    return g.AS * (1 - np.cos(alpha)) + g.AL * np.sin(alpha)


@njit(cache=True)
def footpad(g: ArticulatedGeometry, alpha, beta, psi):
    """Footpad position (S1', S2', S3') in the leg frame (eq. 38-40, FORCE)."""
    r = tip_radius(g, alpha)
    return (g.AU * np.cos(psi) + g.AO + r * np.cos(beta),
            r * np.sin(beta),
            g.AU * np.sin(psi) - g.AE - g.AS * np.sin(alpha) - g.AL * np.cos(alpha))


@njit(cache=True)
def _sin_psi(g, s3, alpha):
    """sin(psi) from the vertical equation: (AS sin a + AL cos a + S3 + AE) / AU (FORCE)."""
    return (g.AS * np.sin(alpha) + g.AL * np.cos(alpha) + s3 + g.AE) / g.AU


@njit(cache=True)
def residual_slope(g: ArticulatedGeometry, s0: float, s1: float, s2: float, alpha: float) -> tuple[float, float]:
    """(F, dF/dalpha) of `residual_at` (NaN where |sin psi| > 1 or the slope is unbounded, cos psi = 0):
    dF/da = 2 (S1 - AO - AU cos psi) AU sin psi (d sin psi/da) / cos psi - 2 r dr/da (eq. 38-40 differentiated)."""
    sp = _sin_psi(g, s2, alpha)
    if abs(sp) > 1.0:
        return np.nan, np.nan
    sa, ca = np.sin(alpha), np.cos(alpha)
    cp = np.sqrt(1.0 - sp * sp)
    u = s0 - g.AO - g.AU * cp
    r = tip_radius(g, alpha)
    f = u * u + s1 * s1 - r * r
    if cp == 0.0:
        return f, np.nan
    return f, 2.0 * u * sp * (g.AS * ca - g.AL * sa) / cp - 2.0 * r * (g.AS * sa + g.AL * ca)


@njit(cache=True)
def residual_at(g: ArticulatedGeometry, s0: float, s1: float, s2: float, alpha: float) -> float:
    """F(alpha) = (S1 - AO - AU cos psi)^2 + S2^2 - r(alpha)^2 for the footpad (s0, s1, s2): zero at a
    consistent alpha, NaN where the vertical equation has no psi (|sin psi| > 1). Its roots are those of the
    report's quartic eq. 41 without the extraneous ones squaring adds."""
    return residual_slope(g, s0, s1, s2, alpha)[0]


def residual(g: ArticulatedGeometry, s, alpha):
    """`residual_at` over an array of alpha."""
    a = np.asarray(alpha, float)
    out = np.array([residual_at(g, float(s[0]), float(s[1]), float(s[2]), float(x)) for x in a.ravel()])
    return out.reshape(a.shape) if a.ndim else float(out[0])


ALPHA_MAX = np.pi / 2       # eq. 42: alpha in [0, pi/2]


@njit(cache=True)
def nearest_root(g: ArticulatedGeometry, s0: float, s1: float, s2: float, alpha_prev: float,
                 tol: float = 1e-13) -> float:
    """The root of F nearest alpha_prev in [0, ALPHA_MAX], or -1 if there is none (out of reach): steps
    doubling from alpha_prev on both sides until F changes sign (the nearer crossing wins; the first step is
    twice the Newton distance from alpha_prev, at most 1e-3 rad), then Newton's method kept inside the bracket
    (rtsafe, Press et al., Numerical Recipes 3rd ed. sec. 9.4). The simulator's SINALP: it follows one branch
    through a crossing of the quartic's roots, since F has no extraneous roots; a double root (two roots
    meeting and vanishing) is not found."""
    a0 = min(max(alpha_prev, 0.0), ALPHA_MAX)
    f0, d0 = residual_slope(g, s0, s1, s2, a0)
    if f0 == 0.0:
        return a0
    up_a, up_f, dn_a, dn_f = a0, f0, a0, f0
    up, dn = a0 < ALPHA_MAX, a0 > 0.0
    step = 1e-3
    if np.isfinite(d0) and d0 != 0.0:
        step = min(step, max(2.0 * abs(f0 / d0), 1e3 * tol))
    lo = hi = -1.0
    f_lo = f_hi = 0.0
    for _ in range(64):
        if not (up or dn):
            return -1.0
        best = np.inf
        if up:
            a = min(up_a + step, ALPHA_MAX)
            f = residual_at(g, s0, s1, s2, a)
            if np.isfinite(f) and np.isfinite(up_f) and f * up_f <= 0.0:
                best = up_a - a0 + (a - up_a) * up_f / (up_f - f) if up_f != f else a - a0
                lo, hi, f_lo, f_hi = up_a, a, up_f, f
            elif not np.isfinite(f) and np.isfinite(up_f):
                up = False
            up_a, up_f = a, f
            up = up and a < ALPHA_MAX
        if dn:
            a = max(dn_a - step, 0.0)
            f = residual_at(g, s0, s1, s2, a)
            if np.isfinite(f) and np.isfinite(dn_f) and f * dn_f <= 0.0:
                dist = a0 - dn_a + (dn_a - a) * dn_f / (dn_f - f) if dn_f != f else a0 - a
                if dist < best:
                    best = dist
                    lo, hi, f_lo, f_hi = a, dn_a, f, dn_f
            elif not np.isfinite(f) and np.isfinite(dn_f):
                dn = False
            dn_a, dn_f = a, f
            dn = dn and a > 0.0
        if best < np.inf:
            break
        step *= 2.0
    if lo < 0.0:
        return -1.0
    if f_lo == 0.0:
        return lo
    if f_hi == 0.0:
        return hi
    neg, pos = (lo, hi) if f_lo < 0.0 else (hi, lo)              # F(neg) < 0 < F(pos)
    x = hi - f_hi * (hi - lo) / (f_hi - f_lo)
    dx = dx_old = hi - lo
    f, df = residual_slope(g, s0, s1, s2, x)
    for _ in range(100):
        if not (np.isfinite(f) and np.isfinite(df)) or ((x - pos) * df - f) * ((x - neg) * df - f) > 0.0 \
                or abs(2.0 * f) > abs(dx_old * df):
            dx_old, dx = dx, 0.5 * (pos - neg)                  # Newton leaves the bracket or is slow: bisect
            x = neg + dx
        else:
            dx_old, dx = dx, f / df
            x -= dx
        if abs(dx) <= tol:
            return x
        f, df = residual_slope(g, s0, s1, s2, x)
        if f < 0.0:
            neg = x
        elif f > 0.0:
            pos = x
        elif f == 0.0:
            return x
    return x


class Unreachable(ValueError):
    """No (alpha, beta, psi) in range places the footpad at the given point."""


def roots(g: ArticulatedGeometry, s, alpha_max: float, samples: int = 256, tol: float = 1e-13) -> list[float]:
    """All alpha in [0, alpha_max] with F(alpha) = 0: sign changes bracketed (brentq) plus double roots
    (grazing minima of |F|), so two roots that meet and cross are both found."""
    a = np.linspace(0.0, alpha_max, samples)
    f = residual(g, s, a)
    scale = g.AU ** 2
    found = []
    for i in range(samples - 1):
        f0, f1 = f[i], f[i + 1]
        if not (np.isfinite(f0) and np.isfinite(f1)):
            continue
        if f0 == 0:
            found.append(a[i])
        elif f0 * f1 < 0:
            found.append(brentq(lambda x: residual(g, s, x), a[i], a[i + 1], xtol=1e-15, rtol=1e-15))
    # Double roots: |F| has an interior local minimum without a sign change.
    af = np.abs(f)
    for i in range(1, samples - 1):
        if np.isfinite(af[i - 1:i + 2]).all() and af[i] <= af[i - 1] and af[i] <= af[i + 1] \
                and f[i - 1] * f[i + 1] > 0 and f[i - 1] * f[i] > 0:
            m = minimize_scalar(lambda x: abs(residual(g, s, x)), bounds=(a[i - 1], a[i + 1]), method="bounded",
                                options={"xatol": 1e-14})
            if abs(m.fun) < tol * scale:
                found.append(float(m.x))
    if f[-1] == 0:
        found.append(alpha_max)
    return sorted(set(float(x) for x in found))


def inverse(g: ArticulatedGeometry, s, alpha_max: float, alpha_prev: float | None = None,
            beta_prev: float = 0.0, psi_range: tuple[float, float] = (-np.pi / 2, np.pi / 2)):
    """(alpha, beta, psi) placing the footpad at s; the root nearest `alpha_prev` (smallest alpha when None).

    At alpha = 0 the tip lies on the peg-leg axis and beta is undefined: `beta_prev` is returned (0 by
    default), so a history stays continuous and never holds NaN.
    """
    cands = []
    for a in roots(g, s, alpha_max):
        psi = float(np.arcsin(np.clip(_sin_psi(g, s[2], a), -1, 1)))
        if psi_range[0] - 1e-12 <= psi <= psi_range[1] + 1e-12:
            cands.append((a, psi))
    if not cands:
        raise Unreachable(f"footpad {tuple(map(float, s))} is out of reach for alpha in [0, {alpha_max}]")
    ref = 0.0 if alpha_prev is None else alpha_prev
    a, psi = min(cands, key=lambda c: abs(c[0] - ref))
    r = tip_radius(g, a)
    if r <= 1e-12 * g.AU:
        beta = beta_prev
    else:
        beta = float(np.arctan2(s[1], s[0] - g.AO - g.AU * np.cos(psi)))
    return a, beta, psi


def quartic(g: ArticulatedGeometry, s):
    """Coefficients (highest power first) of the quartic in sin(alpha) of eq. 41, as FORCE forms them
    (C70 ... C74). Squaring twice adds extraneous roots, which can cross the true one along a path: the
    hazard the report's deflation guards against and the bracketed `roots` above never meets."""
    c21, c31 = s[0] - g.AO, s[2] + g.AE
    c16 = 2 * g.AS * (g.AL + c31)
    c17 = -2 * (g.AS ** 2 - g.AL * c31)
    c20sq, c19sq = c21 ** 2, s[1] ** 2
    c18 = 2 * g.AS ** 2 + g.AL ** 2 - g.AU ** 2 + c31 ** 2 - c19sq + c20sq
    c25 = c17 ** 2 - 4 * g.AS ** 2 * c20sq
    c26 = c16 ** 2 - 4 * g.AL ** 2 * c20sq
    c27 = 2 * c16 * c17 + 8 * g.AS * g.AL * c20sq
    c28 = 2 * c16 * c18 - 8 * g.AS * g.AL * c20sq
    c29 = 2 * c17 * c18 + 8 * g.AS ** 2 * c20sq
    c35 = 4 * (g.AS ** 2 - c19sq) * c20sq - c18 ** 2
    c2625, c2535 = c26 - c25, c25 - c35
    return (c2625 ** 2 + c27 ** 2, 2 * (c28 * c2625 + c27 * c29), 2 * c2625 * c2535 + c28 ** 2 + c29 ** 2 - c27 ** 2,
            2 * (c28 * c2535 - c27 * c29), c2535 ** 2 - c29 ** 2)
