"""Footpads with mass sliding on the terrain: their in-plane motion is state (departure from AFFDL-TR-66-33
Sec. V.E.5, whose massless footpad slides by a root search at every evaluation).

Each footpad of mass m moves in the terrain plane. A leg on the ground is in one of three modes (`sliding`):
STICK (0): the footpad is held where it is; it starts to slide when the leg's in-plane push FE12 exceeds the
static limit mu_S FE3 (eq. 33-34), located as an event. SLIDE (1): m u' = push - mu_D FE3 u/|u| (eq. 35-37
with the footpad's inertia). BAND (2): |u| below `band` (Karnopp 1985: friction in a small velocity band
balances the push up to the dynamic limit), m u' = push - clamp(push, mu_D FE3); a footpad touching down or
starting to slide starts here. Entering or leaving the band is a located event, so the friction force is
smooth inside every step and the Runge-Kutta keeps its order; a banded footpad whose push falls to the
dynamic limit sticks (its velocity, at most `band`, is dropped: the kinetic energy lost counts as friction).

The massless leg passes the ground force X to the capsule. The cells deform at the footpad's velocity
relative to the capsule (the leg's rate is computed with v - u); the capsule loses cells' power - fe . u
(fe = R X, terrain axes), the footpad gains -fe . u and friction takes -G . u. The footpad's weight is not
modelled: its mass only gives the slide inertia (the capsule's mass includes it).

State: y[NB + 4i : NB + 4i + 4] = footpad i's (x, y, u_x, u_y) in terrain axes, y[NB + 4n] the friction work,
y[NB + 4n + 1] the work the legs take beyond their cells' (an articulated leg's return spring and seat blend;
zero for a telescoping leg), y[NB + 4n + 2 + C i + j] the work of cell j's damper (the step loop adds the exact
rate-free work at each accepted step), so that the energy audit checks every term it reports.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np
from numba import njit, types
from numba.extending import overload

from . import crush_cell
from .legs import leg_force
from .rigid_body import quat_matrix
from .vec3 import mv

NB = 14            # body states before the footpads'
FACE, STICK, SLIDE, BAND = -1, 0, 1, 2   # FACE: held on a vertical face it met (any friction model)
FLOOR = 1e-6       # N: in-plane force below this never starts a slide (round-off at zero load)

PadModel = namedtuple("PadModel", "mu_s mu_d mass band")
"""Static and dynamic friction, footpad mass (kg) and Karnopp band (m/s)."""


def is_pad(mu) -> bool:
    """Whether a numba type of the friction argument is a PadModel."""
    return isinstance(mu, types.NamedUniTuple) and mu.instance_class is PadModel


def n_states(n: int, C: int) -> int:
    """Length of the state vector with n footpads that have mass on legs of up to C cells."""
    return NB + 4 * n + 2 + n * C


def integrates_dampers(mu):
    """Whether the cells' damper work is integrated as state (footpads with mass), not summed by the trapezoid
    rule at accepted steps."""
    return isinstance(mu, PadModel)


@overload(integrates_dampers)
def _integrates_dampers(mu):
    return (lambda mu: True) if is_pad(mu) else (lambda mu: False)


@njit(cache=True)
def pad_force(geo, cells, i, mem, shape, P0, sliding, mu, r, R, v, w, P, defl, frc, rte, X, y):
    """Leg i's forces with its footpad at P0 (held) or where its state puts it (sliding); returns the same
    tuple as footpad_slip.footpad_force: (mode, cells' power, alpha, beta, psi, event value, 0, 0). The event
    value is the static margin mu_S FE3 + FLOOR - FE12 while it sticks, |u| - band while it slides and
    band - |u| in the band."""
    if sliding <= STICK:                                        # sticking, or held on a face (FACE)
        P[0], P[1], P[2] = P0[0], P0[1], P0[2]
        vr = (v[0], v[1], v[2])
    else:
        o = NB + 4 * i
        P[0], P[1], P[2] = y[o], y[o + 1], P0[2]
        vr = (v[0] - y[o + 2], v[1] - y[o + 3], v[2])
    power, alpha, beta, psi = leg_force(geo, cells, i, mem, shape, P, r, R, vr, w, defl, frc, rte, X)
    if sliding == FACE:
        g = 1.0
    elif sliding == STICK:
        fe = mv(R, X[0], X[1], X[2])
        g = mu.mu_s * max(fe[2], 0.0) + FLOOR - np.sqrt(fe[0] * fe[0] + fe[1] * fe[1])    # eq. 33
    else:
        speed = np.hypot(y[NB + 4 * i + 2], y[NB + 4 * i + 3])
        g = speed - mu.band if sliding == SLIDE else mu.band - speed
    return sliding, power, alpha, beta, psi, g, 0.0, 0.0


@njit(cache=True)
def _friction(mu, mode, fe0, fe1, fe2, u0, u1):
    """Ground friction (G0, G1) on a moving footpad under the leg's force fe on the capsule (eq. 35-37)."""
    limit = mu.mu_d * max(fe2, 0.0)
    if mode == SLIDE:
        s = np.hypot(u0, u1)
        return (-limit * u0 / s, -limit * u1 / s) if s > 0.0 else (0.0, 0.0)
    p0, p1 = -fe0, -fe1                                         # the leg's push on the footpad
    p = np.hypot(p0, p1)
    if p <= limit:                                              # Karnopp: friction balances the push
        return fe0, fe1
    return -limit * p0 / p, -limit * p1 / p


def pad_rates(mu, cells, mem, contact, sliding, Xt, dt, ft, rt, power, R, y, dy):
    """Footpad state derivatives into dy, given the legs' state and the power they take from the capsule at
    held footpads; returns the power the footpads take beyond that (-fe . u summed). A no-op returning 0 without
    footpad mass."""
    if isinstance(mu, PadModel):
        return _rates(mu, cells, mem, contact, sliding, Xt, dt, ft, rt, power, R, y, dy)
    return 0.0


@overload(pad_rates)
def _pad_rates(mu, cells, mem, contact, sliding, Xt, dt, ft, rt, power, R, y, dy):
    if is_pad(mu):
        return _rates
    return lambda mu, cells, mem, contact, sliding, Xt, dt, ft, rt, power, R, y, dy: 0.0


def _rates(mu, cells, mem, contact, sliding, Xt, dt, ft, rt, power, R, y, dy):
    n, C = len(contact), ft.shape[1]
    cd, cf, cn, ck, _, cy = cells
    extra, lost, other = 0.0, 0.0, power
    for i in range(n):
        o = NB + 4 * i
        for j in range(C):
            k = NB + 4 * n + 2 + C * i + j
            dy[k] = 0.0
            if contact[i] and cn[i, j] > 0:
                m = cn[i, j]
                static = crush_cell.force(cd[i, j, :m], cf[i, j, :m], ck[i, j], 0.0, cy[i, j], mem[i, j, 0],
                                          mem[i, j, 1], dt[i, j], 0.0)
                dy[k] = (ft[i, j] - static) * rt[i, j]
                other -= ft[i, j] * rt[i, j]
        if contact[i] and sliding[i] > STICK:
            fe = mv(R, Xt[i, 0], Xt[i, 1], Xt[i, 2])
            u0, u1 = y[o + 2], y[o + 3]
            g0, g1 = _friction(mu, sliding[i], fe[0], fe[1], fe[2], u0, u1)
            dy[o], dy[o + 1] = u0, u1
            dy[o + 2], dy[o + 3] = (g0 - fe[0]) / mu.mass, (g1 - fe[1]) / mu.mass
            extra -= fe[0] * u0 + fe[1] * u1
            lost -= g0 * u0 + g1 * u1
        else:
            dy[o] = dy[o + 1] = dy[o + 2] = dy[o + 3] = 0.0
    dy[NB + 4 * n], dy[NB + 4 * n + 1] = lost, other
    return extra


def pad_switch(mu, y, i, P, sliding, down):
    """A leg touching down (down) or lifting off: its footpad starts at rest where it touched, in the band; one
    lifting off drops its velocity (its kinetic energy counts as friction). A no-op without footpad mass."""
    if isinstance(mu, PadModel):
        _switch(mu, y, i, P, sliding, down)


@overload(pad_switch)
def _pad_switch(mu, y, i, P, sliding, down):
    return _switch if is_pad(mu) else (lambda mu, y, i, P, sliding, down: None)


def _switch(mu, y, i, P, sliding, down):
    o = NB + 4 * i
    _stop(mu, y, i, len(sliding))
    if down:
        y[o], y[o + 1] = P[i, 0], P[i, 1]
        sliding[i] = BAND


@njit(cache=True)
def _stop(mu, y, i, n):
    """Footpad i brought to rest, its kinetic energy added to the friction work."""
    o = NB + 4 * i
    y[NB + 4 * n] += 0.5 * mu.mass * (y[o + 2] ** 2 + y[o + 3] ** 2)
    y[o + 2] = y[o + 3] = 0.0


def pad_event(mu, y, i, P, sliding, Xt):
    """A slip event of leg i (returns True: the forces change); without footpad mass a sticking footpad
    starts to slide."""
    return (_event if isinstance(mu, PadModel) else _start)(mu, y, i, P, sliding, Xt)


@overload(pad_event)
def _pad_event(mu, y, i, P, sliding, Xt):
    return _event if is_pad(mu) else _start


def _start(mu, y, i, P, sliding, Xt):
    sliding[i] = 1
    return True


def _event(mu, y, i, P, sliding, Xt):
    """STICK -> BAND (the static limit is passed: the footpad starts from rest); BAND -> SLIDE; SLIDE -> BAND,
    or STICK when the push is within the dynamic limit there."""
    if sliding[i] == STICK:
        sliding[i] = BAND
    elif sliding[i] == BAND:
        sliding[i] = SLIDE
    else:
        sliding[i] = BAND
        _settle(mu, y, i, P, sliding, Xt)
    return True


def pad_settle(mu, y, i, P, sliding, Xt):
    """After an accepted step: a banded footpad whose push is below the dynamic limit sticks where it is
    (returns whether it did): a footpad touching down slides on mu_D like the massless one (eq. 33). A no-op
    without footpad mass."""
    return isinstance(mu, PadModel) and _settle(mu, y, i, P, sliding, Xt)


@overload(pad_settle)
def _pad_settle(mu, y, i, P, sliding, Xt):
    return _settle.py_func if is_pad(mu) else (lambda mu, y, i, P, sliding, Xt: False)


@njit(cache=True)
def _settle(mu, y, i, P, sliding, Xt):
    if sliding[i] != BAND:
        return False
    fe = mv(quat_matrix(y[6:10]), Xt[i, 0], Xt[i, 1], Xt[i, 2])
    if not np.hypot(fe[0], fe[1]) < mu.mu_d * fe[2]:          # unloaded (touching down) it stays in the band
        return False
    o = NB + 4 * i
    _stop(mu, y, i, len(sliding))
    P[i, 0], P[i, 1] = y[o], y[o + 1]                     # its height as the step loop last placed it
    sliding[i] = STICK
    return True
