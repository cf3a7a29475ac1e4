"""Footpad slip on the terrain (AFFDL-TR-66-33 Sec. V.E.5, eq. 31-37, subroutine SLIP; Sec. V.F for either leg).

The ground force is first computed with the footpad where it was at the last accepted step. If its part FE12
along the surface exceeds the potential friction force (mu_S FE3 while sticking, mu_D FE3 while sliding; eq. 32-34,
FE3 its part along the surface's normal: the terrain plane's, or on a rock's flank or the height field the
relief's, terrain.relief), the footpad slides, kept on the surface (eq. 35-37: in the terrain plane, rising and
falling with the relief), until FE12 = mu_D FE3.

Departure from the report: SLIP varies the leg's tilt alpha at fixed beta. That path is undefined at
alpha = 0 (a leg hanging straight at touchdown, beta undefined) and cannot follow a push across the beta
plane, where it wanders far from the held position looking for a root. Here the footpad moves along a
straight line in the terrain plane (on the relief: its height follows the relief), in the direction the leg
pushes it (-FE12, the direction friction opposes), which is defined whatever the tilt.

A sticking footpad whose static limit is exceeded inside an integration step is held (`hold`) when
mu_S > mu_D: the force would drop from mu_S FE3 to mu_D FE3 there, so the step loop locates the crossing of
the margin mu_S FE3 + FLOOR - FE12 as an event and starts the slide on a step boundary (the FLOOR keeps a
footpad unloading to zero, FE12 and FE3 both ~0, from crossing it at every lift-off).

The report bracketed the crossing but lost runs when the crossing moved near lift-off ("ND", Table 4). Here
the search always brackets: the footpad moves from the held position with growing steps until
FE12 <= mu_D FE3 or it leaves the leg's reach (the main cell, telescoping axial or articulated upper, short of
its permanent set, or no articulated root: the leg would have lifted off; every direction in the plane leaves
the reach within two leg lengths), where it counts as infeasible. Bisection while one end is out of reach,
then Brent's method, closes on the crossing; the answer is always a contact
point within reach on the friction-feasible side, or the edge of the reach (the lift-off event then takes
over).

The slide is a straight line from where the footpad was at the last accepted step, so the footpad's path
is a polygon with a corner at every step; the step loop bounds the error that leaves (the path error
footpad_force returns) like the error of any other position.

A scene whose footpads cannot slip passes no friction (mu None): `contact_force` then holds each footpad
where it touched, and compiled code for such a scene contains no slip search (numba `overload` on mu's type).
"""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.extending import overload

from .footpad_mass import FLOOR, LOCK, PadModel, is_pad, pad_force
from .legs import leg_force, slack
from .terrain import relief
from .vec3 import mv

MAX_EXPAND = 200
MAX_REFINE = 100
MAX_DIP = 24         # golden-section steps: the dip is found to 1e-5 of the interval


def slip_events(mu):
    """Whether stick-to-slip is located as an event: only when the force drops there (mu_S > mu_D; never for
    held footpads, mu None; always for footpads with mass, whose band is located too)."""
    return mu is not None and (isinstance(mu, PadModel) or _drops(mu))


@njit(cache=True)
def _drops(mu):
    return mu[0] > mu[1] * (1.0 + 1e-9)


@overload(slip_events)
def _slip_events(mu):
    if isinstance(mu, types.NoneType):
        return lambda mu: False
    return (lambda mu: True) if is_pad(mu) else _drops.py_func


def slides_by_position(mu, contact, sliding):
    """Whether a footpad on the ground slides by position (massless footpads under friction): its path within a
    step is then a polygon that a step's continuous extension does not follow."""
    return mu is not None and not isinstance(mu, PadModel) and bool(np.any((contact > 0) & (sliding > 0)))


@njit(cache=True)
def _any_slide(mu, contact, sliding):
    for i in range(len(contact)):
        if contact[i] and sliding[i]:
            return True
    return False


@overload(slides_by_position)
def _slides_by_position(mu, contact, sliding):
    if isinstance(mu, types.NoneType) or is_pad(mu):
        return lambda mu, contact, sliding: False
    return _any_slide.py_func


def contact_force(leg, P0, sliding, mu, kin, out, y):
    """footpad_force under friction mu = (mu_S, mu_D, the slide's relative tolerance), with mu None the leg's
    forces with its footpad held at P0 (no slip search), with a footpad_mass.PadModel the footpad where its
    state y puts it (footpad_mass.pad_force); footpad_force's returns and the soil event value (1 but on soil).
    leg: (geo, cells, i, mem, shape), kin: the capsule's (r, R, v, w), out: the arrays written (P, defl, frc,
    rte, X) (see footpad_force)."""
    return (_held if mu is None else _slipping)(leg, P0, sliding, mu, kin, out, y)


@overload(contact_force, inline="always")
def _contact_force(leg, P0, sliding, mu, kin, out, y):
    if isinstance(mu, types.NoneType):
        return _held
    return pad_force.py_func if is_pad(mu) else _slipping


def _held(leg, P0, sliding, mu, kin, out, y):
    geo, cells, i, mem, shape = leg
    P, defl, frc, rte, X = out
    P[0], P[1], P[2] = P0[0], P0[1], P0[2]
    power, alpha, beta, psi = leg_force(geo, cells, i, mem, shape, P, kin, (defl, frc, rte, X))
    return 0, power, alpha, beta, psi, 1.0, 0.0, 0.0, 1.0


def _slipping(leg, P0, sliding, mu, kin, out, y):
    sl, power, alpha, beta, psi, margin, deficit, path = footpad_force(leg, P0, sliding, slip_events(mu), mu, kin,
                                                                       out)
    return sl, power, alpha, beta, psi, margin, deficit, path, 1.0


@njit(cache=True, inline="always")
def _ground(leg, kin, out):
    """(FE12, FE3, FT1, FT2, cells' power, alpha, beta, psi) with the footpad at P (out = (P, defl, frc, rte, X), the
    leg's forces written to the others): the ground force's parts along the surface and normal to it (eq. 31-32
    with the normal of the terrain's relief under P, the terrain plane's where there is none) and the in-plane
    components of its part along the surface. Inlined (numba IR) into the slide's search (_at): as a call it
    unpacked the leg's ~30 arrays again at each evaluation, and numba counts a reference to each (9-20 % slower)."""
    geo, cells, i, mem, shape = leg
    R = kin[1]
    P, defl, frc, rte, X = out
    power, alpha, beta, psi = leg_force(geo, cells, i, mem, shape, P, kin, (defl, frc, rte, X))
    fe = mv(R, X[0], X[1], X[2])                                # eq. 31
    _, n0, n1, n2 = relief(geo[9], P[0], P[1])
    fe3 = fe[0] * n0 + fe[1] * n1 + fe[2] * n2
    t0, t1, t2 = fe[0] - fe3 * n0, fe[1] - fe3 * n1, fe[2] - fe3 * n2
    return np.sqrt(t0 * t0 + t1 * t1 + t2 * t2), fe3, t0, t1, power, alpha, beta, psi   # eq. 32


@njit(cache=True, inline="always")
def _place(terrain, P0, d0, d1, s, P):
    """P = the footpad moved by s along the in-plane direction d from P0, on the terrain's relief: its height
    changes as the relief's (on the plane, a step or a box top it keeps its height)."""
    P[0], P[1] = P0[0] + s * d0, P0[1] + s * d1
    P[2] = P0[2] + relief(terrain, P[0], P[1])[0] - relief(terrain, P0[0], P0[1])[0]


@njit(cache=True, inline="always")
def _push(t0, t1):
    """In-plane unit direction of the leg's push on the footpad along the surface, -(FT1, FT2) / |.|."""
    th = np.sqrt(t0 * t0 + t1 * t1)
    return (-t0 / th, -t1 / th) if th > 0.0 else (0.0, 0.0)


@njit(cache=True)
def _at(sl, s):
    """Excess FE12 - mu FE3 and force scale with the footpad moved by s along d from P0; False out of the leg's
    reach. sl: the slide, (leg, kin, out, mu, P0, d0, d1) (_slide).
    On a rock's flank, or leaving one, the excess counts the push along the path only (across the foot of
    a rock the normal turns, and a push there may drive the footpad back), and where the path climbs a flank
    steeper than friction lets a footpad climb (n3 - mu t3 <= LOCK, t its direction: a rock's foot,
    footpad_mass._climb) the flank holds the footpad: the excess there is -1. On the plane, where the leg's push
    has turned against the path the footpad is out of reach: sliding on, it would work against the leg, storing in
    its cells energy the capsule never gave (a touchdown slide of a metre in a free fall, crushing the pads)."""
    leg, kin, out, mu, P0, d0, d1 = sl
    geo, cells, i, mem, _ = leg
    P, defl, _, _, X = out
    _place(geo[9], P0, d0, d1, s, P)
    fe12, fe3, t0, t1, _, _, _, _ = _ground(leg, kin, out)
    if slack(geo, cells, i, mem, defl, X, P, kin[1]) < 0.0:
        return -1.0, 0.0, False
    _, n0, n1, n2 = relief(geo[9], P[0], P[1])
    if n2 < 1.0 or relief(geo[9], P0[0], P0[1])[3] < 1.0:
        rise = -(n0 * d0 + n1 * d1) / n2                        # the relief's slope along d
        m = np.sqrt(1.0 + rise * rise)
        if n2 - mu * rise / m <= LOCK:
            return -1.0, fe12 + abs(fe3), True
        along = -(t0 * d0 + t1 * d1 - (t0 * n0 + t1 * n1) / n2 * rise) / m   # the push along the path (FT . n = 0)
        return along - mu * max(fe3, 0.0), fe12 + abs(fe3), True
    if t0 * d0 + t1 * d1 > 0.0:                 # the push turned against the path: no further in reach (see above)
        return -1.0, 0.0, False
    return fe12 - mu * max(fe3, 0.0), fe12 + abs(fe3), True


@njit(cache=True)
def _dip(sl, a, h_a, b):
    """Golden-section search for the lowest excess between a (excess h_a > 0) and b, stopping at the first
    point where it is not positive; returns (lo, h_lo, s, h_s): that point and the left end of the search's
    last bracket (excess positive, in reach), so that [lo, s] brackets a crossing when h_s <= 0."""
    k = 0.3819660112501051
    c, d = a + k * (b - a), b - k * (b - a)
    hc, _, okc = _at(sl, c)
    hd, _, okd = _at(sl, d)
    for _ in range(MAX_DIP):
        if okc and hc <= 0.0:
            return a, h_a, c, hc
        if okd and hd <= 0.0:
            return c, hc, d, hd
        if not okd or hc < hd:
            b, d, hd, okd = d, c, hc, okc
            c = a + k * (b - a)
            hc, _, okc = _at(sl, c)
        else:
            a, h_a, c, hc, okc = c, hc, d, hd, okd
            d = b - k * (b - a)
            hd, _, okd = _at(sl, d)
    return a, h_a, c, hc if okc else 1.0


@njit(cache=True)
def _refine(sl, s_lo, h_lo, s_hi, h_hi, ok_hi, tol: float) -> tuple[float, bool]:
    """Close the bracket [s_lo, s_hi] (excess h_lo > 0; h_hi <= 0, or s_hi out of reach) to tol of the reach, or
    until the excess is within tol of the force scale: bisection while the far end is out of reach, then
    Brent's method (Brent 1973, ch. 4: inverse quadratic interpolation, secant or bisection; steps of at least
    the tolerance, so the bracket closes). Returns (s, ok): the crossing on its friction-feasible side, or the
    edge of the reach (ok False) when no crossing is in reach."""
    geo, _, i, _, _ = sl[0]
    xtol = tol * geo[2][i]                                      # the leg's reach
    while not ok_hi and s_hi - s_lo > xtol:
        s_m = 0.5 * (s_lo + s_hi)
        h_m, _, ok_m = _at(sl, s_m)
        if ok_m and h_m > 0.0:
            s_lo, h_lo = s_m, h_m
        elif ok_m:
            s_hi, h_hi, ok_hi = s_m, h_m, True
        else:
            s_hi = s_m
    if not ok_hi:
        return s_lo, False
    a, fa, b, fb, ok_b = s_lo, h_lo, s_hi, h_hi, True
    c, fc, ok_c = a, fa, True
    e = d = b - a
    for _ in range(MAX_REFINE):
        if fb * fc > 0.0:
            c, fc, ok_c = a, fa, True
            e = d = b - a
        if abs(fc) < abs(fb):
            a, fa, b, fb, c, fc, ok_b, ok_c = b, fb, c, fc, b, fb, ok_c, ok_b
        xm = 0.5 * (c - b)
        if abs(xm) <= xtol or fb == 0.0:
            break
        if abs(e) >= xtol and abs(fa) > abs(fb):
            sr = fb / fa
            if a == c:
                p, q = 2.0 * xm * sr, 1.0 - sr
            else:
                q, rr = fa / fc, fb / fc
                p = sr * (2.0 * xm * q * (q - rr) - (b - a) * (rr - 1.0))
                q = (q - 1.0) * (rr - 1.0) * (sr - 1.0)
            if p > 0.0:
                q = -q
            p = abs(p)
            if 2.0 * p < min(3.0 * xm * q - abs(xtol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = xm
        else:
            d = e = xm
        a, fa = b, fb
        b += d if abs(d) > xtol else (xtol if xm > 0.0 else -xtol)
        fb, scale, ok_b = _at(sl, b)
        if ok_b and abs(fb) <= tol * (scale + 1.0):
            return b, True
    if ok_b and fb <= 0.0:
        return b, True
    return c, ok_c


@njit(cache=True)
def footpad_force(leg, P0, sliding, hold, mu, kin, out):
    """Footpad position P and the leg's forces (written to out = (P, defl, frc, rte, X)) with friction mu = (mu_S,
    mu_D, tol), the slide closed to tol (relative), for leg = (geo, cells, i, mem, shape) under a capsule moving as
    kin = (r, R, v, w); returns (sliding 0/1, cells' power, alpha, beta, psi, static margin mu_S FE3 + FLOOR - FE12
    at P0, reach deficit, path error). P0 is the footpad at the last accepted step; with `hold` a sticking footpad
    stays at P0 whatever the margin. The reach deficit (m) is 0 unless the slide ended at the edge of the leg's
    reach with friction still exceeded: then it is the excess there over the main cell's unloading rate, so that its
    compression less the deficit falls through zero continuously when the last feasible position leaves the reach
    (the leg lifts off there). The path error (m) estimates how far the straight slide from P0 ends from a path that
    turns with the leg's push: half the slide times the change of the push direction along it (the sagitta of a
    uniformly turning path), the step loop's error control for the footpad position."""
    mu_s, mu_d, tol = mu[0], mu[1], mu[2]
    P = out[0]
    P[0], P[1], P[2] = P0[0], P0[1], P0[2]
    fe12, fe3, fe1, fe2, power, alpha, beta, psi = _ground(leg, kin, out)
    if sliding < 0:                                             # held on a vertical face (FACE)
        return sliding, power, alpha, beta, psi, 1.0, 0.0, 0.0
    margin = mu_s * max(fe3, 0.0) + FLOOR - fe12 if not sliding else 1.0   # watched only while it sticks
    if (hold and not sliding) or fe12 <= (mu_d if sliding else mu_s) * max(fe3, 0.0) + FLOOR:   # eq. 33-34
        return 0, power, alpha, beta, psi, margin, 0.0, 0.0
    h0 = fe12 - mu_d * max(fe3, 0.0)
    if h0 <= 0.0:                                               # static limit exceeded, dynamic one not
        return 1, power, alpha, beta, psi, 1.0, 0.0, 0.0
    return _slide(leg, kin, out, P0, mu_d, tol, _push(fe1, fe2), h0)


@njit(cache=True)
def _slide(leg, kin, out, P0, mu_d, tol, push, h0):
    """The slide: the footpad moved from P0 along the leg's push (in-plane unit direction) until FE12 = mu_D FE3
    (see footpad_force). leg: (geo, cells, i, mem, shape), kin: the capsule's (r, R, v, w), out: the arrays
    written (P, defl, frc, rte, X)."""
    geo, cells, i, _, _ = leg
    P = out[0]
    d0, d1 = push
    sl = (leg, kin, out, mu_d, P0, d0, d1)                      # _at's slide
    # Expand until the excess changes sign or the footpad leaves the leg's reach: steps growing fourfold, or
    # just past the secant's root when that is nearer, so that the nearest crossing (the one continuous with
    # the held position) is not stepped over.
    reach = geo[2][i]
    s_prev, h_prev, s_lo, h_lo = 0.0, h0, 0.0, h0
    step = 1e-6 * reach
    s_hi, h_hi, ok_hi = 0.0, h0, True
    for _ in range(MAX_EXPAND):
        s_hi = s_lo + step
        aimed = h_lo < h_prev
        if aimed:
            root = s_lo + h_lo * (s_lo - s_prev) / (h_prev - h_lo)
            aimed = root < s_hi
            s_hi = min(s_hi, s_lo + 1.2 * (root - s_lo))
        h_hi, _, ok_hi = _at(sl, s_hi)
        if h_hi <= 0.0:
            break
        turned = h_lo < h_prev and h_hi > h_lo
        if aimed or turned:
            # The secant promised a crossing and h came back positive, or h fell and rose again (the samples
            # bracket a minimum in (s_prev, s_hi)): a narrow dip may lie in between (a pad unloading to zero;
            # an articulated tip crossing its peg-leg axis, where alpha passes through the seat). Golden-section
            # search for its bottom.
            a, h_a = (s_prev, h_prev) if turned else (s_lo, h_lo)
            a, h_a, s_m, h_m = _dip(sl, a, h_a, s_hi)
            if h_m <= 0.0:
                s_lo, h_lo, s_hi, h_hi, ok_hi = a, h_a, s_m, h_m, True
                break
        s_prev, h_prev, s_lo, h_lo = s_lo, h_lo, s_hi, h_hi
        step = 4.0 * (s_lo - s_prev)
    s_end, ok_hi = _refine(sl, s_lo, h_lo, s_hi, h_hi, ok_hi, tol)
    _place(geo[9], P0, d0, d1, s_end, P)
    fe12, fe3, t0, t1, power, alpha, beta, psi = _ground(leg, kin, out)
    deficit = 0.0 if ok_hi else max(fe12 - mu_d * max(fe3, 0.0), 0.0) / cells[3][i, 0]
    e0, e1 = _push(t0, t1)
    path = 0.5 * s_end * np.hypot(d0 - e0, d1 - e1) if fe12 > FLOOR else 0.0
    return 1, power, alpha, beta, psi, 1.0, deficit, path
