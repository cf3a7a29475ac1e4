"""Footpads with mass sliding on the terrain: their in-plane motion is state (departure from AFFDL-TR-66-33
Sec. V.E.5, whose massless footpad slides by a root search at every evaluation).

Each footpad of mass m moves in the terrain plane. A leg on the ground is in one of three modes (`sliding`):
STICK (0): the footpad is held where it is; it starts to slide when the leg's in-plane push FE12 exceeds the
static limit mu_S FE3 (eq. 33-34), located as an event. SLIDE (1): m u' = push - mu_D FE3 u/|u| (eq. 35-37
with the footpad's inertia). BAND (2): |u| below `band` (Karnopp 1985: friction in a small velocity band
balances the push up to the dynamic limit), m u' = push - clamp(push, mu_D FE3); a footpad touching down or
starting to slide starts here, and leaves it at twice the band (hysteresis, LEAVE). Entering or leaving the
band is a located event, so the friction force is smooth inside every step and the Runge-Kutta keeps its
order; a banded footpad whose push falls to the dynamic limit sticks (its velocity, below LEAVE x band, is
dropped: the kinetic energy lost counts as friction).

The massless leg passes the ground force X to the capsule. The cells deform at the footpad's velocity
relative to the capsule (the leg's rate is computed with v - u); the capsule loses cells' power - fe . u
(fe = R X, terrain axes), the footpad gains -fe . u and friction takes -G . u. The footpad's weight is not
modelled: its mass only gives the slide inertia (the capsule's mass includes it).

On rigid ground a footpad slides on the terrain's relief (a rock's flank, the height field; terrain.relief): its
height follows the relief and u has the rise u3 = -(n1 u1 + n2 u2) / n3, push and friction are taken along the
surface and FE3 along its normal n, and the footpad, massless across the plane, has the normal force N that
balances its forces along the terrain's normal (_friction; it pulls where the leg lifts the footpad off a flank
while the leg stays on the ground), so that they do work only through its in-plane motion and the audit above
holds. On the plane all of this is the plane's. Where friction locks a climb
(n3 - mu_D t3 at LOCK, t its direction: N would grow without bound), or on the ground at a rock's foot, a
sliding footpad is caught and held as on a face (ground_event).

On soil (`PadModel.area` > 0; alightsize_sim.soil) a footpad also sinks along the terrain normal. Its sinkage s
and rate w are state, with two modes located as events: HELD (w = 0: the soil carries the leg's push FE3 as
long as it is below the bearing force R(s) = A p(s)) and SINKING (m w' = FE3 - R(s), from the moment FE3
exceeds R(s) until w falls to zero; the soil is plastic and gives nothing back). In 1-D the velocity meets zero
exactly, so no band is needed. Friction stays mu FE3 (the massless limit: the footpad's normal inertia does not
relieve it), and a footpad sliding while sunk also plows: Rankine's passive resistance F_p(s) adds to the
friction limit (static and dynamic). The capsule's extra power is + FE3 w; the soil takes R w and the plowing
share of the slide's work. A footpad
that touched down on a rock, or on a face, stays on rigid ground (mode RIGID). A footpad touches down at rest
(its impact momentum goes with the capsule's mass, as on rigid ground).

State: y[NB + 4i : NB + 4i + 4] = footpad i's (x, y, u_x, u_y) in terrain axes, y[NB + 4n] the friction work,
y[NB + 4n + 1] the work the legs take beyond their cells' (an articulated leg's return spring and seat blend;
zero for a telescoping leg), y[NB + 4n + 2 + C i + j] the work of cell j's damper (the step loop adds the exact
rate-free work at each accepted step), so that the energy audit checks every term it reports. On soil, the
last 4n + 1 entries are per footpad (s, w, the surface height z0 where it touched, its mode), then the soil's
work; a mode is a discrete flag with zero rate, so the Runge-Kutta carries it unchanged.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np
from numba import njit, types
from numba.extending import overload

from . import crush_cell
from .legs import leg_force
from .rigid_body import quat_matrix
from .soil import normal_force, plowing_force, sinkage_depth, sinkage_work
from .terrain import BOX, HEMISPHERE, features_at, foot_distance, height, relief
from .vec3 import mv

NB = 14            # body states before the footpads'
FACE, STICK, SLIDE, BAND = -1, 0, 1, 2   # FACE: held on a vertical face it met (any friction model)
STARTED = 3        # BAND, entered from STICK by a located slip start: it does not stick again before the step loop
                   # has made a step longer than event_tol (landing_kernel), since the start is located up to
                   # event_tol short of the static limit, where the push may still be within the dynamic one
FLOOR = 1e-6       # N: in-plane force below this never starts a slide (round-off at zero load)
LEAVE = 2.0        # a banded footpad slides at LEAVE x band, a sliding one enters the band at band (hysteresis:
                   # footpads at the band's edge, coupled through the capsule, cannot switch back and forth at once)
SINK_BAND = 1e-6   # a sinking footpad whose speed turned negative stops only under a push this much below R(s)
LOCK = 0.05        # n3 - mu_D t3 below this (a push up a flank steeper than friction lets it climb) counts as this
FOOT_TOL = 1e-4    # m: a footpad on soil whose event is located this near a rock's foot has slid into it (50 m/s x
                   # the largest event_tol a scene takes)

RIGID, HELD, SINKING = -1.0, 0.0, 1.0     # soil modes of a footpad on the ground

PadModel = namedtuple("PadModel", "mu_s mu_d mass band soil area diameter held")
"""Static and dynamic friction, footpad mass (kg), Karnopp band (m/s), the soil (alightsize_sim.soil.Soil.packed
as a tuple), the footpad's bearing area (m^2; 0: rigid ground, no soil) and diameter (m; round footpads), and
whether footpads are held in the plane (non-slip friction: they only sink)."""


def pad_model(mu_s: float, mu_d: float, mass: float, band: float, soil=None, diameter: float = 0.0,
              held: bool = False) -> PadModel:
    """A PadModel of floats for round footpads of the given diameter; without a soil (None) the ground is rigid.
    `held`: the friction is the report's non-slip device (landing.holds), so a footpad never slides in the plane,
    as on rigid ground; it still sinks into the soil. A friction limit of 1e6 FE3 taken literally slides a footpad
    only as its load FE3 passes through zero, where that limit's rate mu_D dFE3/du through the cells' dampers
    makes the slide's band a stiff system (mu_D c / m ~ 2e9 1/s for the 1966 legs' 4,400 N s/m and 5 lb)."""
    packed = tuple(float(x) for x in soil.packed) if soil is not None else (0.0,) * 6
    d = float(diameter) if soil is not None else 0.0
    return PadModel(float(mu_s), float(mu_d), float(mass), float(band), packed, np.pi * d * d / 4.0, d, bool(held))


def is_pad(mu) -> bool:
    """Whether a numba type of the friction argument is a PadModel."""
    return isinstance(mu, types.BaseNamedTuple) and mu.instance_class is PadModel


def n_states(n: int, C: int, soil: bool = False) -> int:
    """Length of the state vector with n footpads that have mass on legs of up to C cells (on soil or not)."""
    return NB + 4 * n + 2 + n * C + (4 * n + 1 if soil else 0)


@njit(cache=True, inline="always")
def _sink_at(y, n, i):
    """Index of footpad i's soil block (s, w, z0, mode) in y (on soil only); the soil's work is y[-1]."""
    return len(y) - 4 * n - 1 + 4 * i


@njit(cache=True)
def _bearing(mu, s):
    """R(s): the soil's bearing force on the round footpad at sinkage s (N); Bekker's b is its radius."""
    return normal_force(mu.soil, mu.area, 0.5 * mu.diameter, s)


@njit(cache=True)
def _plow(mu, y, i, n):
    """F_p: footpad i's plowing resistance at its sinkage (0 on rigid ground). It adds to a friction limit that
    stays on the leg's push FE3 also while the footpad sinks (the massless limit: the footpad's normal inertia
    does not relieve its friction, so a footpad starting to sink into soil that bears nothing yet is not
    flung sideways)."""
    if mu.area > 0.0:
        k = _sink_at(y, n, i)
        if y[k + 3] != RIGID:
            return plowing_force(mu.soil, mu.diameter, y[k])
    return 0.0


def has_mass(mu):
    """Whether the footpads have mass (mu a PadModel): their dampers' work is then integrated as state, not summed
    by the trapezoid rule at accepted steps."""
    return isinstance(mu, PadModel)


@overload(has_mass)
def _has_mass(mu):
    return (lambda mu: True) if is_pad(mu) else (lambda mu: False)


@njit(cache=True)
def pad_force(leg, P0, sliding, mu, kin, out, y):
    """Leg i's forces with its footpad at P0 (held) or where its state puts it (sliding, sunk); returns the
    tuple of footpad_slip.contact_force (whose arguments it takes: leg = (geo, cells, i, mem, shape), kin = (r, R,
    v, w), out = (P, defl, frc, rte, X)): (mode, cells' power, alpha, beta, psi, slip event value, 0, 0, soil
    event value). The slip event value is the static margin mu_S FE3 + F_p + FLOOR - FE12 while it sticks,
    |u| - band while it slides and LEAVE band - |u| in the band; the soil's is R(s) + FLOOR - FE3 while held, w
    while sinking (1 on rigid ground)."""
    geo, cells, i, mem, shape = leg
    r, R, v, w = kin
    P, defl, frc, rte, X = out
    n = cells[2].shape[0]
    o = NB + 4 * i
    P[0], P[1], P[2] = P0[0], P0[1], P0[2]
    u0 = u1 = u2 = 0.0
    if sliding > STICK:
        P[0], P[1], u0, u1 = y[o], y[o + 1], y[o + 2], y[o + 3]
    nrm = _normal(mu, geo[9], y, i, n, P[0], P[1])
    if sliding != FACE and not nrm[3]:                          # on soil
        k = _sink_at(y, n, i)
        P[2], u2 = y[k + 2] - y[k], -y[k + 1]
    rise = 0.0
    if sliding > STICK and nrm[3]:                              # on rigid ground it slides on the relief
        P[2] = P0[2] + relief(geo[9], P[0], P[1])[0] - relief(geo[9], P0[0], P0[1])[0]
        rise = -(nrm[0] * u0 + nrm[1] * u1) / nrm[2]
        u2 = rise
    power, alpha, beta, psi = leg_force(geo, cells, i, mem, shape, P, (r, R, (v[0] - u0, v[1] - u1, v[2] - u2), w),
                                        (defl, frc, rte, X))
    if sliding == FACE:
        return sliding, power, alpha, beta, psi, 1.0, 0.0, 0.0, 1.0
    fe = mv(R, X[0], X[1], X[2])
    if sliding == STICK and mu.held:
        g = 1.0
    elif sliding == STICK:
        load, p0, p1, p2 = _split(fe, nrm)
        g = mu.mu_s * max(load, 0.0) + _plow(mu, y, i, n) + FLOOR - np.sqrt(p0 * p0 + p1 * p1 + p2 * p2)  # eq. 33
    else:
        speed = np.sqrt(u0 * u0 + u1 * u1 + rise * rise)
        g = speed - mu.band if sliding == SLIDE else LEAVE * mu.band - speed
    if not nrm[3]:                                              # on soil; one sliding is caught at a rock's foot
        ground = _sink_event(mu, y, i, n, fe[2])
        if sliding > STICK:
            ground = min(ground, foot_distance(geo[9], P[0], P[1]))
    elif sliding > STICK:
        ground = _climb(mu, geo[9], nrm, P[0], P[1], u0, u1, rise)
    else:
        ground = 1.0
    return sliding, power, alpha, beta, psi, g, 0.0, 0.0, ground


@njit(cache=True)
def _climb(mu, terrain, nrm, x, yy, u0, u1, u2):
    """Relief event value of a footpad sliding on rigid ground at (x, yy) with velocity u along the surface of normal
    nrm. On a rock's flank (or the height field's relief) n3 - mu_D t3 - LOCK, t the direction of u, which falls to
    zero where friction locks the climb (the normal force fe3 / (n3 - mu_D t3) of a footpad massless across the
    plane would have to grow without bound), and it is caught there (ground_event); on flat ground its distance to
    the nearest rock's foot, so that one sliding into a rock's 85 deg foot, which it can climb only with mu_D below
    0.04, is caught where it meets it."""
    if relief(terrain, x, yy)[0] != 0.0 or nrm[2] < 1.0:
        s = np.sqrt(u0 * u0 + u1 * u1 + u2 * u2)
        return nrm[2] - mu.mu_d * u2 / s - LOCK if s > 0.0 else nrm[2] - LOCK
    return foot_distance(terrain, x, yy)


@njit(cache=True)
def _normal(mu, terrain, y, i, n, x, yy):
    """(n0, n1, n2, rigid): the unit normal footpad i (of n) at (x, yy) bears on, and whether it is on rigid ground
    (no soil, or a rock): there the terrain's relief (the plane where there is none), on soil the plane's."""
    if mu.area > 0.0 and y[_sink_at(y, n, i) + 3] != RIGID:
        return 0.0, 0.0, 1.0, False
    _, n0, n1, n2 = relief(terrain, x, yy)
    return n0, n1, n2, True


@njit(cache=True)
def _split(fe, nrm):
    """(N, p0, p1, p2): the normal part fe . n of the leg's force fe on the capsule and the leg's push along the
    surface on the footpad, -(fe - N n)."""
    load = fe[0] * nrm[0] + fe[1] * nrm[1] + fe[2] * nrm[2]
    return load, load * nrm[0] - fe[0], load * nrm[1] - fe[1], load * nrm[2] - fe[2]


@njit(cache=True)
def _sink_event(mu, y, i, n, fe2):
    """Footpad i's soil event value: R(s) + FLOOR - FE3 while the soil holds it, w while it sinks, else 1."""
    if mu.area > 0.0:
        k = _sink_at(y, n, i)
        if y[k + 3] == HELD:
            return _bearing(mu, y[k]) + FLOOR - fe2
        if y[k + 3] == SINKING:
            return y[k + 1]
    return 1.0


@njit(cache=True)
def _friction(mode, mu_d, plow, fe, nrm, u0, u1, u2):
    """(G0, G1, G2, N): ground friction on a moving footpad (velocity u along the surface of normal nrm) and the
    surface's normal force N, under the leg's force fe on the capsule (eq. 35-37), its limit mu_D N plus the
    plowing force. The footpad is massless across the plane: N holds the footpad's forces in balance along the
    plane's normal, so that they do work only through its in-plane motion (on the plane N = FE3). Karnopp's band
    (Karnopp 1985): friction balances the push along the surface up to the limit."""
    load, p0, p1, p2 = _split(fe, nrm)
    if mode == SLIDE:
        s = np.sqrt(u0 * u0 + u1 * u1 + u2 * u2)
        if not s > 0.0:
            return 0.0, 0.0, 0.0, load
        t0, t1, t2 = u0 / s, u1 / s, u2 / s
        normal = _across(fe[2] + plow * t2, nrm[2], nrm[2] - mu_d * t2)
        limit = mu_d * max(normal, 0.0) + plow
        return -limit * t0, -limit * t1, -limit * t2, normal
    p = np.sqrt(p0 * p0 + p1 * p1 + p2 * p2)
    if p <= mu_d * max(load, 0.0) + plow or nrm[2] - mu_d * p2 / p <= LOCK:   # Karnopp: friction balances the
        return -p0, -p1, -p2, load                                           # push (or locks a climb)
    t0, t1, t2 = p0 / p, p1 / p, p2 / p
    normal = _across(load * nrm[2] - (p - plow) * t2, nrm[2], nrm[2] - mu_d * t2)
    limit = mu_d * max(normal, 0.0) + plow
    return -limit * t0, -limit * t1, -limit * t2, normal


@njit(cache=True)
def _across(z, n2, lever):
    """N: the surface's normal force on a moving footpad, massless across the plane, that balances its forces
    there: N (n3 - mu_D t3) = z (z: fe3 and the plowing force's part across the plane; `lever`: n3 - mu_D t3, at
    least LOCK) while N pushes. Where the leg lifts the footpad off a flank it climbs (z < 0) while the leg stays
    on the ground, the surface holds the footpad without friction, N = z / n3 < 0: a zero N would leave the lift
    unbalanced across the plane while the relief moves the footpad across it, so that its in-plane kinetic energy
    would miss the power fe3 u3 (111 W for a 4.3 kg footpad climbing a rock at 0.3 m/s under a 346 N lift)."""
    return z / max(lever, LOCK) if z >= 0.0 else z / n2


def pad_rates(S, W, power, R, y, dy):
    """Footpad state derivatives into dy, given the legs' state and the power they take from the capsule at
    held footpads; returns the power the footpads take beyond that (-fe . u summed). A no-op returning 0 without
    footpad mass. S, W: the step loop's bundles (landing_kernel): the landing (its friction mu, cells, cell memory,
    contact flags, footpad modes and terrain) and the legs' state at y (their forces and cell deflections, forces
    and rates)."""
    if isinstance(S.mu, PadModel):
        return _rates(S, W, power, R, y, dy)
    return 0.0


@overload(pad_rates)
def _pad_rates(S, W, power, R, y, dy):
    if is_pad(S.field_dict["mu"]):
        return _rates
    return lambda S, W, power, R, y, dy: 0.0


def _rates(S, W, power, R, y, dy):
    mu, cells, mem, contact, sliding, terrain = S.mu, S.cells, S.mem, S.contact, S.sliding, S.geo[9]
    Xt, dt, ft, rt = W.Xt, W.dt, W.ft, W.rt
    n, C = len(contact), ft.shape[1]
    cd, cf, cn, ck, _, cy = cells
    extra, lost, other, sunk = 0.0, 0.0, power, 0.0
    for i in range(n):
        o = NB + 4 * i
        for j in range(C):
            d = NB + 4 * n + 2 + C * i + j
            dy[d] = 0.0
            if contact[i] and cn[i, j] > 0:
                m = cn[i, j]
                static = crush_cell.force(cd[i, j, :m], cf[i, j, :m], ck[i, j], 0.0, cy[i, j], (mem[i, j, 0],
                                          mem[i, j, 1]), dt[i, j], 0.0)
                dy[d] = (ft[i, j] - static) * rt[i, j]
                other -= ft[i, j] * rt[i, j]
        dy[o] = dy[o + 1] = dy[o + 2] = dy[o + 3] = 0.0
        on = contact[i] and sliding[i] != FACE
        fe = mv(R, Xt[i, 0], Xt[i, 1], Xt[i, 2]) if on else (0.0, 0.0, 0.0)
        if mu.area > 0.0:
            p_soil, p_capsule = _sink_rates(mu, y, dy, i, n, fe[2], on)
            sunk += p_soil
            extra += p_capsule
        if on and sliding[i] > STICK:
            u0, u1 = y[o + 2], y[o + 3]
            plow = _plow(mu, y, i, n)
            nrm = _normal(mu, terrain, y, i, n, y[o], y[o + 1])
            u2 = -(nrm[0] * u0 + nrm[1] * u1) / nrm[2] if nrm[3] else 0.0   # its rise along the relief
            g0, g1, g2, normal = _friction(sliding[i], mu.mu_d, plow, fe, nrm, u0, u1, u2)
            dy[o], dy[o + 1] = u0, u1
            dy[o + 2] = (g0 - fe[0] + normal * nrm[0]) / mu.mass
            dy[o + 3] = (g1 - fe[1] + normal * nrm[1]) / mu.mass
            extra -= fe[0] * u0 + fe[1] * u1 + fe[2] * u2
            limit = mu.mu_d * max(normal, 0.0) + plow
            share = plow / limit if limit > 0.0 else 0.0          # the plowing part of the slide's resistance
            work = g0 * u0 + g1 * u1 + g2 * u2
            lost -= (1.0 - share) * work
            sunk -= share * work
    dy[NB + 4 * n], dy[NB + 4 * n + 1] = lost, other
    if mu.area > 0.0:
        dy[len(y) - 1] = sunk
    return extra


@njit(cache=True)
def _sink_rates(mu, y, dy, i, n, fe2, on):
    """Footpad i's soil block rates into dy (zero unless it is on the ground and sinking: s' = w,
    m w' = FE3 - R(s)); returns (the soil's power R w, the capsule's extra power FE3 w)."""
    k = _sink_at(y, n, i)
    dy[k] = dy[k + 1] = dy[k + 2] = dy[k + 3] = 0.0
    if not (on and y[k + 3] == SINKING):
        return 0.0, 0.0
    w, bearing = y[k + 1], _bearing(mu, y[k])
    dy[k], dy[k + 1] = w, (fe2 - bearing) / mu.mass
    return bearing * w, fe2 * w


def pad_switch(mu, y, i, P, sliding, down, fe, terrain):
    """A leg touching down (down) or lifting off: its footpad starts at rest where it touched (a held face
    excepted, in the band), on the soil unless on a rock or a face; back in the hole it left it bears on the
    soil there as that soil was left (plastic: held until the push passes R(s)). One lifting off drops its
    velocity in the plane (its kinetic energy counts as friction) and leaves its hole; one that was sinking (the
    leg unloaded as the footpad ran ahead into the soil) first sinks on to the depth at which the soil has taken
    its kinetic energy (soil.sinkage_depth), as the soil alone then stops it (its weight is not modelled). fe
    is the leg's force on the capsule (terrain axes) just computed with the footpad at P. A no-op without footpad
    mass."""
    if isinstance(mu, PadModel):
        _switch(mu, y, i, P, sliding, down, fe, terrain)


@overload(pad_switch)
def _pad_switch(mu, y, i, P, sliding, down, fe, terrain):
    return _switch if is_pad(mu) else (lambda mu, y, i, P, sliding, down, fe, terrain: None)


def _switch(mu, y, i, P, sliding, down, fe, terrain):
    o, n = NB + 4 * i, len(sliding)
    _stop(mu, y, i, n)
    if mu.area > 0.0:
        _soil_switch(mu, y, i, P, sliding[i] == FACE, down, fe, terrain)
    if down:
        y[o], y[o + 1] = P[i, 0], P[i, 1]
        if sliding[i] != FACE:
            sliding[i] = STICK if mu.held else BAND


@njit(cache=True)
def _soil_switch(mu, y, i, P, face, down, fe, terrain):
    """pad_switch's part on soil, before the footpad's position is set (it still marks its hole; P (n, 3): the
    footpads)."""
    n = len(P)
    k = _sink_at(y, n, i)
    if y[k + 3] == SINKING and y[k + 1] > 0.0:          # left sinking: the soil stops it where it takes its energy
        e = 0.5 * mu.mass * y[k + 1] ** 2
        b = 0.5 * mu.diameter
        y[k] = sinkage_depth(mu.soil, mu.area, b, sinkage_work(mu.soil, mu.area, b, y[k]) + e)
        y[len(y) - 1] += e
    y[k + 1] = 0.0
    y[k + 3] = RIGID
    if not down:
        return
    if face:          # caught on a face (a riser, a rock's side, its hole's wall): held, rigid; its hole, kept,
        return        # moves under it (a footpad leaving a face over its hole's wall can land in the hole again)
    kind = features_at(terrain, P[i, 0], P[i, 1])[0]
    rock = kind == HEMISPHERE or kind == BOX
    # Fresh ground unless it landed in its hole: within its radius, on the hole's bottom (not a lower level).
    if rock or _hole(mu, y, i, n, P[i, 0], P[i, 1], np.inf, terrain) > P[i, 2] + 1e-12:
        y[k], y[k + 2] = 0.0, P[i, 2]
    if rock:                                                            # rocks are rigid
        return
    y[k + 3] = SINKING if fe[2] > _bearing(mu, y[k]) + FLOOR else HELD


def pad_ground(mu, y, i, n, terrain, x, yy):
    """Height of the ground under leg i's free footpad (of n) at (x, yy): the terrain's surface, or on soil the
    bottom of the hole the footpad left when its centre is over it (not where a rock stands)."""
    top = height(terrain, x, yy)
    return _hole(mu, y, i, n, x, yy, top, terrain) if isinstance(mu, PadModel) else top


@overload(pad_ground)
def _pad_ground(mu, y, i, n, terrain, x, yy):
    if is_pad(mu):
        return lambda mu, y, i, n, terrain, x, yy: _hole(mu, y, i, n, x, yy, height(terrain, x, yy), terrain)
    return lambda mu, y, i, n, terrain, x, yy: height(terrain, x, yy)


@njit(cache=True)
def _hole(mu, y, i, n, x, yy, top, terrain):
    """min(top, the bottom of footpad i's hole) when (x, yy) is within its radius of the hole's centre and no rock
    stands there (rocks are rigid: a hole in the soil beside one does not reach into it)."""
    if mu.area > 0.0:
        k, o = _sink_at(y, n, i), NB + 4 * i
        if y[k] > 0.0 and (x - y[o]) ** 2 + (yy - y[o + 1]) ** 2 < 0.25 * mu.diameter ** 2:
            kind = features_at(terrain, x, yy)[0]
            if kind != HEMISPHERE and kind != BOX:
                return min(top, y[k + 2] - y[k])
    return top


def pad_release(mu, y, n, e):
    """Add the energy e (J) the struts of a leg lifting off give up (tripod_leg.lift_shape) to the friction work:
    it goes with the footpad's in-plane motion, which a lift-off drops (_stop). A no-op without footpad mass, whose
    audit counts what the cells do not keep as the interface's."""
    if isinstance(mu, PadModel):
        y[NB + 4 * n] += e


@overload(pad_release)
def _pad_release(mu, y, n, e):
    if not is_pad(mu):
        return lambda mu, y, n, e: None

    def add(mu, y, n, e):
        y[NB + 4 * n] += e
    return add


def taken(mu, y, y1, n, C):
    """Energy the legs took from the capsule over the step y -> y1 as the state holds it (J; the energy audit's
    terms, landing.simulate), as differences (no round-off of the running totals): without footpad mass all of
    it (the legs' work y[13]); with mass the friction, leg-other, damper and soil work and the footpads' kinetic
    energy, the cells' rate-free work not included (it is not state)."""
    if not isinstance(mu, PadModel):
        return y1[13] - y[13]
    return _taken(mu, y, y1, n, C)


@overload(taken)
def _taken_ov(mu, y, y1, n, C):
    if not is_pad(mu):
        return lambda mu, y, y1, n, C: y1[13] - y[13]
    return lambda mu, y, y1, n, C: _taken(mu, y, y1, n, C)


@njit(cache=True)
def _taken(mu, y, y1, n, C):
    k = NB + 4 * n
    e, dv2 = 0.0, 0.0
    for c in range(k, k + 2 + n * C):
        e += y1[c] - y[c]
    for i in range(n):
        for c in range(NB + 4 * i + 2, NB + 4 * i + 4):
            dv2 += (y1[c] - y[c]) * (y1[c] + y[c])
    if mu.area > 0.0:
        e += y1[-1] - y[-1]
        for i in range(n):
            c = _sink_at(y, n, i) + 1
            dv2 += (y1[c] - y[c]) * (y1[c] + y[c])
    return e + 0.5 * mu.mass * dv2


@njit(cache=True)
def _stop(mu, y, i, n):
    """Footpad i brought to rest in the plane, its kinetic energy there added to the friction work."""
    o = NB + 4 * i
    y[NB + 4 * n] += 0.5 * mu.mass * (y[o + 2] ** 2 + y[o + 3] ** 2)
    y[o + 2] = y[o + 3] = 0.0


def pad_event(mu, y, i, P, sliding, Xt, terrain):
    """A slip event of leg i (returns True: the forces change); without footpad mass a sticking footpad
    starts to slide."""
    return (_event if isinstance(mu, PadModel) else _start)(mu, y, i, P, sliding, Xt, terrain)


@overload(pad_event)
def _pad_event(mu, y, i, P, sliding, Xt, terrain):
    return _event if is_pad(mu) else _start


def _start(mu, y, i, P, sliding, Xt, terrain):
    sliding[i] = 1
    return True


def _event(mu, y, i, P, sliding, Xt, terrain):
    """STICK -> BAND (STARTED: the static limit is passed, the footpad starts from rest); BAND -> SLIDE; SLIDE -> BAND,
    or STICK when the push is within the dynamic limit there."""
    if sliding[i] == STICK:
        sliding[i] = STARTED
    elif sliding[i] == BAND or sliding[i] == STARTED:
        sliding[i] = SLIDE
    else:
        sliding[i] = BAND
        _settle(mu, y, i, P, sliding, Xt, terrain)
    return True


def ground_event(mu, y, i, sliding, terrain):
    """A soil or relief event of leg i (returns True). On soil a held footpad starts to sink; a sinking one stops
    (its kinetic energy, from a speed within the event tolerance of zero, goes to the soil). On rigid ground a
    sliding footpad that meets a flank it cannot climb, or a rock's foot, is caught there as on a face (FACE), its
    kinetic energy counted as friction. Never without footpad mass."""
    return isinstance(mu, PadModel) and _ground_event(mu, y, i, sliding, terrain)


@overload(ground_event)
def _ground_event_overload(mu, y, i, sliding, terrain):
    return _ground_event.py_func if is_pad(mu) else (lambda mu, y, i, sliding, terrain: False)


@njit(cache=True)
def _ground_event(mu, y, i, sliding, terrain):
    n, o = len(sliding), NB + 4 * i
    if mu.area > 0.0:
        k = _sink_at(y, n, i)
        if y[k + 3] != RIGID:
            # The soil's event, unless the footpad slid to a rock's foot (located within FOOT_TOL of it).
            if sliding[i] <= STICK or not foot_distance(terrain, y[o], y[o + 1]) < FOOT_TOL:
                return _sink(mu, y, i, n)
            if y[k + 3] == SINKING:                             # its sinking stops: its kinetic energy to the soil
                y[len(y) - 1] += 0.5 * mu.mass * y[k + 1] ** 2
                y[k + 1] = 0.0
            y[k + 3] = RIGID
    _stop(mu, y, i, n)
    sliding[i] = FACE
    return True


@njit(cache=True)
def _sink(mu, y, i, n):
    k = _sink_at(y, n, i)
    if y[k + 3] == HELD:
        y[k + 3] = SINKING
    elif y[k + 3] == SINKING:
        y[len(y) - 1] += 0.5 * mu.mass * y[k + 1] ** 2
        y[k + 1] = 0.0
        y[k + 3] = HELD
    return True


def pad_settle(mu, y, i, P, sliding, Xt, terrain):
    """After an accepted step: a banded footpad whose push is below the dynamic limit sticks where it is
    (returns whether it did): a footpad touching down slides on mu_D like the massless one (eq. 33). On soil,
    a mode its event missed is caught up: a held footpad pushed past R(s) sinks, a sinking one at w < 0 stops
    once its push is below R(s) by SINK_BAND (one that has just started, located to within event_tol before
    its push reached R(s), may turn back for a moment). A no-op without footpad mass."""
    return isinstance(mu, PadModel) and _settle(mu, y, i, P, sliding, Xt, terrain)


@overload(pad_settle)
def _pad_settle(mu, y, i, P, sliding, Xt, terrain):
    return _settle.py_func if is_pad(mu) else (lambda mu, y, i, P, sliding, Xt, terrain: False)


@njit(cache=True)
def _settle(mu, y, i, P, sliding, Xt, terrain):
    n = len(sliding)
    if sliding[i] != BAND and not (mu.area > 0.0 and sliding[i] != FACE):
        return False
    fe = mv(quat_matrix(y[6:10]), Xt[i, 0], Xt[i, 1], Xt[i, 2])
    changed = False
    if mu.area > 0.0 and sliding[i] != FACE:
        k = _sink_at(y, n, i)
        bearing = _bearing(mu, y[k])
        if (y[k + 3] == HELD and fe[2] > bearing + FLOOR) or \
                (y[k + 3] == SINKING and y[k + 1] < 0.0 and fe[2] < (1.0 - SINK_BAND) * bearing - FLOOR):
            changed = _sink(mu, y, i, n)
    if sliding[i] != BAND:
        return changed
    o = NB + 4 * i
    nrm = _normal(mu, terrain, y, i, n, y[o], y[o + 1])
    load, p0, p1, p2 = _split(fe, nrm)
    p = np.sqrt(p0 * p0 + p1 * p1 + p2 * p2)
    held = p < mu.mu_d * load + _plow(mu, y, i, n) or (p > 0.0 and nrm[2] - mu.mu_d * p2 / p <= LOCK)   # or locked
    if not held or load <= 0.0:                                 # unloaded: in the band
        return changed
    _stop(mu, y, i, n)
    P[i, 0], P[i, 1] = y[o], y[o + 1]                     # its height as the step loop last placed it
    sliding[i] = STICK
    return True
