"""The compiled step loop of a landing (AFFDL-TR-66-33 Sec. V; the report used Runge-Kutta-Merson).

State y = (r, v terrain axes; q principal -> terrain; omega principal axes; W the work the legs took from the
capsule). Dormand-Prince 5(4) with error control (or fixed steps) advances it; the error control also bounds the
path error of sliding footpads (footpad_slip). Discrete memory lives in arrays the caller owns and changes only
when a step is accepted (`_commit`): cell maxima, footpad positions and slip state, contact flags. Touchdown,
lift-off, stick-to-slip, a cell's turn from loading to unloading (its largest stroke) and its passing a corner of
its loading curve are located to `event_tol` seconds: first on the step's continuous extension (leg evaluations
only), where the step is accepted just short of the crossing when its stages saw one smooth law, else by real
trial steps aimed just short of it, the step accepted before it; a trial step that fails the error test rejects
the step. When no leg touches an axisymmetric capsule a step is the closed-form free flight (eq. 62-88) instead.
The loop returns to the caller on a status: the end time, a full history buffer, or an outcome it detects
(bottoming, tip angle, body contact, quiescence, the energy criterion).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from . import crush_cell
from .borrow import borrowed
from .bundle import bundler
from .footpad_mass import BAND as PAD_BAND
from .footpad_mass import (FACE, FLOOR, STARTED, ground_event, has_mass, pad_event, pad_ground, pad_rates, taken,
                           pad_release, pad_settle, pad_switch)
from .footpad_slip import contact_force, slides_by_position, slip_events
from .rigid_body import free_flight, quat_matrix, quat_rate
from .stability import hanging_margin, quiescence_momenta, quiescence_update, stable_by_energy, tipping_margins
from .legs import TELESCOPING, TRIPOD, at_set, folded, free_footpad, leg_force, lift_shape, member_strike, slack
from .telescoping_leg import aim
from .terrain import FACE_GAP, bearing_normal, clearance
from .vec3 import cross, mtv, mv

# Dormand-Prince 5(4).
A = np.array([[0, 0, 0, 0, 0, 0], [1 / 5, 0, 0, 0, 0, 0], [3 / 40, 9 / 40, 0, 0, 0, 0],
              [44 / 45, -56 / 15, 32 / 9, 0, 0, 0], [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0, 0],
              [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0],
              [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]])
B5 = np.array([35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0])
B4 = np.array([5179 / 57600, 0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40])
D = np.array([-12715105075 / 11282082432, 0, 87487479700 / 32700410799, -10690763975 / 1880347072,
              701980252875 / 199316789632, -1453857185 / 822651844, 69997945 / 29380423])   # dense output (CONTD5)

# Statuses returned to the caller.
END, BUFFER, BOTTOMED, TIPPED, BODY, QUIET, FAILED, STABLE, MEMBER, FOLDED = 0, 2, 3, 4, 5, 6, 7, 8, 9, 10
# Controls (float array).
C_TFINAL, C_RTOL, C_ATOL, C_FIXED, C_MAXSTEP, C_EVENTTOL, C_STOPBOTTOM, C_TIPCOS, C_CLEAR, C_FLIGHT, \
    C_QUIET_FRAC, C_TAUS, C_PERIOD, C_ENERGY_T, C_BAND = range(15)
# Counters (int array).
K_STEPS, K_REJECTED, K_RHS, K_HIST, K_EVENTS, K_TRIALS = range(6)
# Leg state columns of the work array mt: static margin, reach deficit, alpha, beta, psi, footpad path error, soil
# event value.
N_MT = 7
# Run scalars (float array): step size, quiescence clock, reference momentum, first bottoming (t, leg, cell), the
# leg whose intermediate member struck the terrain, since when a capsule with a leg in the air has held stable.
S_H, S_QUIET, S_MOMENTUM, S_BOT_T, S_BOT_LEG, S_BOT_CELL, S_STRUCK, S_HANG, S_EREF = range(9)

MAX_STALL = 100     # accepted steps in a row that do not advance time before the run is declared failed
GTOL = 1e-12       # m: a contact event function this close above zero counts as there
ARM = 1e-7          # m: a leg's next switch is armed once it is this far from its last one
LOCKED = -1         # armed[i]: a leg that left at once on touching, or at the edge of its reach still pushed beyond the
                    # friction cone, touches again only the band past zero
FRESH = -2          # armed[i]: a leg that has just touched down; leaving before a step longer than event_tol, LOCKED
BANDED = -3         # armed[i]: a leg that left short of its set (the grazing band) touches again the band past zero
TOUCH = 2           # armed[i]: a leg placed on the surface before the run, which touches down as the run starts
TOUCHED = 2         # sliding[i]: a massless footpad that has just touched down, sliding on mu_D until its first commit
BAND = 1e-4         # m: the default grazing band (ctl[C_BAND]): an unarmed leg on the ground lifts off only this far
                    # past zero, where it carries no force (grazing contact never chatters); see _events
GRAZE_SPEED = 50.0  # m/s: the band must take a footpad this fast more than event_tol to cross (Controls)
PATH_FLOOR = 100.0  # event_tol: steps this short or shorter skip the footpad path error (_error_norm)
ENERGY_RATE = 1.0   # 1/s: a step's energy defect may be rtol x this x the landing's energy scale per second
                    # (_error_norm): a landing of 1 s at rtol 1e-6 then closes its audit within 1e-6
ENERGY_FLOOR = 10.0  # event_tol: steps this short or shorter skip the energy test (a step at an event, whose
                     # defect need not fall with h; a leg touching and leaving at every step takes 1e-6 s steps)
ROUND_OFF = 1e-13   # of the landing's energy scale: a step's energy defect this small passes (the cells' work from
                    # their curves' antiderivatives, kJ, carries round-off of 1e-12 J; at rtol 1e-10 and 1e-10 s
                    # steps the defect no longer falls with h)

# Compiled functions that only compiled code calls (they take bundles, which Python cannot build): no Python or C
# wrapper is compiled for them.
_inner = njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
# The step loop's phases, each called once per step: inlined into `run` (numba IR), which measured 4-7 % faster on
# the 5 lb footpad scene than calls.
_phase = njit(cache=True, inline="always", no_cpython_wrapper=True, no_cfunc_wrapper=True)
# The step loop's functions take their arrays as bundles (bundle.py): S, the landing (its scene and memory; `run`
# takes them in LANDING.fields order); W, the legs' state at one evaluation (new_work); T, the step's scratch;
# H, the record (`run`'s history, in HISTORY.fields order).
LANDING = bundler("geo cells mass inertia gravity mu bottoming up body order mem contact P sliding shape armed cev "
                  "energy last ctl cnt run_state")
WORK = bundler("Pt slt dt ft Xt mt rt")
STEP = bundler("K y1 err g_prev g1 g_lo y_lo yt gm ga gb")
HISTORY = bundler("t y dy d f X P c")


@njit(cache=True)
def _copy1(dst, src):
    """dst[:] = src for 1-D arrays, as a plain loop (numba compiles slice assignment many times slower)."""
    for k in range(dst.shape[0]):
        dst[k] = src[k]


@njit(cache=True)
def _copy2(dst, src):
    """dst[:, :] = src for 2-D arrays, as a plain loop."""
    for k in range(dst.shape[0]):
        for m in range(dst.shape[1]):
            dst[k, m] = src[k, m]


@njit(cache=True)
def new_work(n, C):
    """Leg state arrays of one evaluation for n legs of up to C cells (Pt, slt, dt, ft, Xt, mt, rt)."""
    return (np.zeros((n, 3)), np.zeros(n, np.int64), np.zeros((n, C)), np.zeros((n, C)), np.zeros((n, 3)),
            np.zeros((n, N_MT)), np.zeros((n, C)))


SCRATCH_WORK = 11   # new_scratch's leg-state set at the current point (`work`), which the caller's Python shares


@njit(cache=True)
def new_scratch(n, C, ny):
    """The step loop's working arrays, owned by its caller (run borrows them): stages K, the step's end, its error,
    event values (before, after, at the bracket's lower end), the state there and at a trial point, the search's
    values (at the point, the bracket's ends) and two leg-state sets (work, at the lower end)."""
    n_g = n_events(n, C)
    return (np.zeros((7, ny)), np.empty(ny), np.empty(ny), np.empty(n_g), np.empty(n_g), np.empty(n_g), np.empty(ny),
            np.empty(ny), np.empty(n_g), np.empty(n_g), np.empty(n_g), new_work(n, C), new_work(n, C))


@njit(cache=True)
def n_events(n, C):
    """Number of event functions for n legs of up to C cells (see _events)."""
    return (3 + 3 * C) * n


@njit(cache=True)
def cell_events(cells, mem):
    """Event memory of every cell (n, C, 3): whether its turn to unloading is watched (set while it loads, its
    deflection a new maximum and rising), the index of the next corner of its loading curve past its
    maximum (the curve's length when none is left) and whether it is beyond its permanent set (loaded: set at
    touchdown, flipped where it crosses the set)."""
    n, C = mem.shape[0], mem.shape[1]
    cev = np.zeros((n, C, 3), np.int64)
    for i in range(n):
        for j in range(C):
            cev[i, j, 1] = _next_corner(cells, i, j, mem[i, j, 0], 0)
    return cev


@njit(cache=True)
def _next_corner(cells, i, j, x, k):
    """Index from k on of the first point of cell (i, j)'s loading curve beyond deflection x."""
    m = cells[2][i, j]
    while k < m and cells[0][i, j, k] <= x:
        k += 1
    return k


@njit(cache=True)
def cell_event(cells, cev, which, n):
    """A located cell event `which` (index into the event functions, >= 3n): a turn stops watching the cell; a
    corner moves the cell on to the curve's next corner; a crossing of its permanent set flips its side."""
    C = cev.shape[1]
    c = which - 3 * n
    if c < n * C:
        cev[c // C, c % C, 0] = 0
    elif c < 2 * n * C:
        c -= n * C
        i, j = c // C, c % C
        cev[i, j, 1] = _next_corner(cells, i, j, cells[0][i, j, cev[i, j, 1]], cev[i, j, 1])
    else:
        c -= 2 * n * C
        cev[c // C, c % C, 2] = 1 - cev[c // C, c % C, 2]


@_inner
def _legs(S, W, y, R):
    """Footpad, slip state, forces and mt = (static margin, reach deficit, alpha, beta, psi, footpad path error,
    soil event value)
    of every leg at state y (mu = mu_S, mu_D, the slide's relative tolerance; None: footpads held; a
    footpad_mass.PadModel: footpads with mass, placed by y) into the leg state W; returns the cells' power."""
    geo, cells, mu, mem, contact, P, sliding, shape = S.geo, S.cells, S.mu, S.mem, S.contact, S.P, S.sliding, S.shape
    Pt, slt, dt, ft, Xt, mt, rt = W.Pt, W.slt, W.dt, W.ft, W.Xt, W.mt, W.rt
    r, v, w = y[0:3], (y[3], y[4], y[5]), y[10:13]
    power = 0.0
    for i in range(len(contact)):
        if contact[i]:
            sl, pw, mt[i, 2], mt[i, 3], mt[i, 4], mt[i, 0], mt[i, 1], mt[i, 5], mt[i, 6] = contact_force(
                (geo, cells, i, mem[i], shape[i]), P[i], sliding[i], mu, (r, R, v, w),
                (Pt[i], dt[i], ft[i], rt[i], Xt[i]), y)
            slt[i] = sl
            power += pw
        else:
            mt[i, 5] = 0.0
    return power


@_inner
def _rhs(S, y, dy, W):
    """dy/dt: eq. 3-5 in terrain axes, Euler's equations 6-8 in principal axes, quaternion rate, leg work (and
    the footpads' motion and friction work when they have mass: footpad_mass); the leg state into W."""
    mass, inertia, gravity, contact = S.mass, S.inertia, S.gravity, S.contact
    Pt, Xt = W.Pt, W.Xt
    R = quat_matrix(y[6:10])
    power = _legs(S, W, y, R)
    power += pad_rates(S, W, power, R, y, dy)
    F0 = F1 = F2 = M0 = M1 = M2 = 0.0
    for i in range(len(contact)):
        if contact[i]:
            p0, p1, p2 = mtv(R, Pt[i, 0] - y[0], Pt[i, 1] - y[1], Pt[i, 2] - y[2])
            m0, m1, m2 = cross(p0, p1, p2, Xt[i, 0], Xt[i, 1], Xt[i, 2])
            F0, F1, F2 = F0 + Xt[i, 0], F1 + Xt[i, 1], F2 + Xt[i, 2]
            M0, M1, M2 = M0 + m0, M1 + m1, M2 + m2
    a0, a1, a2 = mv(R, F0, F1, F2)
    w0, w1, w2 = y[10], y[11], y[12]
    h0, h1, h2 = cross(w0, w1, w2, inertia[0] * w0, inertia[1] * w1, inertia[2] * w2)
    dy[0], dy[1], dy[2] = y[3], y[4], y[5]
    dy[3], dy[4], dy[5] = gravity[0] + a0 / mass, gravity[1] + a1 / mass, gravity[2] + a2 / mass
    quat_rate(y[6:10], y[10:13], dy[6:10])
    dy[10], dy[11], dy[12] = (M0 - h0) / inertia[0], (M1 - h1) / inertia[1], (M2 - h2) / inertia[2]   # eq. 6-8
    dy[13] = power


@njit(cache=True)
def rhs(arrays, y, dy, work):
    """_rhs for Python: arrays as `run` takes them, work new_work's."""
    _rhs(LANDING(*borrowed(arrays)), y, dy, WORK(*borrowed(work)))


@_inner
def _events(S, y, W, g, band):
    """Event functions g ((3 + 3C) n); an event is a crossing of zero from above. g[i]: leg i's free footpad height
    (in the air) or main-cell compression beyond its set (legs.slack) less the reach deficit (on the ground, from
    the leg state at y). An unarmed leg on the ground lifts off only `band` past zero (ctl[C_BAND];
    0.0 for the raw values, a float so that numba compiles one version, not one per literal flag): its main cell
    is then short of its set, where it carries no force, so a footpad grazing the terrain stays put at zero force
    until it clearly leaves instead of switching every step. Not so for a footpad slid to the edge of its reach
    (deficit > 0): it still carries force, beyond the friction cone, so it leaves at once. A leg in the air keeps
    the shape it left with, its footpad where it left the terrain. One that left at its set touches down at zero
    (GTOL past it, above the round-off of that footpad's height), with its cells as they were in the air; one that
    left the band short of its set (BANDED) touches only the band past zero, where its main cell is back at its
    set: either way re-contact brings no force step, and results do not depend on the band. A LOCKED leg (one that
    left at once on touching) touches only `band` past zero too.
    g[n + i]: a sticking footpad's static margin mu_S FE3 + FLOOR - FE12 (N) when stick-to-slip is an event (for
    footpads with mass, a sliding one's distance from its Karnopp band, m/s), else the constant 1. g[2n + i]: a
    footpad's soil event (footpad_mass: R(s) + FLOOR - FE3 while the soil holds it, its sinking rate while it
    sinks), else 1. g[3n + C i + j]: the deflection rate of cell j of leg i while its turn is watched
    (cell_events); g[(3 + C) n + C i + j]: its next loading-curve corner less its deflection (on the ground;
    else 1); g[(3 + 2C) n + C i + j]: a tripod's cell's deflection less its permanent set while beyond it, the set
    less its deflection while short of it (on the ground; else 1): where its force leaves or meets zero, a kink
    located as a corner is (the secondaries pass from compression to tension through both their cells' sets; the
    other kinds' main cell leaves or meets its set where its leg lifts off or touches down).
    Locating these keeps every step's forces smooth: the largest stroke, which sets the unloading branch and the
    bottoming margin, is then found to event_tol, not sampled at step points."""
    geo, cells, mu, mem, contact, shape, armed, cev = S.geo, S.cells, S.mu, S.mem, S.contact, S.shape, S.armed, S.cev
    dt, rt, mt = W.dt, W.rt, W.mt
    n, C = len(contact), mem.shape[1]
    R = quat_matrix(y[6:10])
    located = slip_events(mu)
    for i in range(n):
        if contact[i]:
            g[i] = slack(geo, cells, i, mem[i], dt[i], W.Xt[i], W.Pt[i], R) - mt[i, 1]
            if armed[i] == FRESH and S.sliding[i] == FACE:   # caught on a face: held for a step (_accept)
                g[i] = max(g[i], 0.0)
        else:
            foot = free_footpad(geo, cells, i, mem[i], shape[i], y[0:3], R)
            g[i] = foot[2] - pad_ground(mu, y, i, n, geo[9], foot[0], foot[1])
        if contact[i]:
            if armed[i] <= 0 and mt[i, 1] <= 0.0:
                g[i] += band
        elif _past_band(S, i):
            g[i] += band
        elif armed[i] == 0:
            g[i] += min(band, GTOL)
        g[n + i] = mt[i, 0] if located and contact[i] else 1.0
        g[2 * n + i] = mt[i, 6] if contact[i] else 1.0
        for j in range(C):
            c = C * i + j
            g[3 * n + c] = rt[i, j] if contact[i] and cev[i, j, 0] else 1.0
            k = cev[i, j, 1]
            g[(3 + C) * n + c] = cells[0][i, j, k] - dt[i, j] if contact[i] and k < cells[2][i, j] else 1.0
            if contact[i] and geo[7][i] == TRIPOD and j <= geo[5][i]:
                beyond = dt[i, j] - crush_cell.permanent_set(cells[3][i, j], mem[i, j, 0], mem[i, j, 1])
                g[(3 + 2 * C) * n + c] = beyond if cev[i, j, 2] else -beyond
            else:
                g[(3 + 2 * C) * n + c] = 1.0


@_inner
def _past_band(S, i):
    """Whether leg i in the air touches down only the band past zero (LOCKED or BANDED)."""
    return S.armed[i] == LOCKED or S.armed[i] == BANDED


@njit(cache=True)
def events(arrays, y, work, g, band):
    """_events for Python (arrays as `run` takes them)."""
    _events(LANDING(*borrowed(arrays)), y, WORK(*borrowed(work)), g, band)


@njit(cache=True)
def _first(g_prev, g):
    """Index of the event function crossing zero from above earliest (linear estimate), -1 if none."""
    best, which = np.inf, -1
    for k in range(len(g)):
        if g_prev[k] > 0.0 and g[k] <= 0.0:
            theta = g_prev[k] / (g_prev[k] - g[k])
            if theta <= best:
                best, which = theta, k
    return which


@njit(cache=True)
def _fly(y, h, inertia, gravity, out):
    """out = the state h after y in free flight, closed form (eq. 62-88)."""
    r, v, q, w = free_flight(y[0:3], y[3:6], y[6:10], y[10:13], inertia, gravity, h)
    for c in range(3):
        out[c], out[3 + c], out[10 + c] = r[c], v[c], w[c]
    for c in range(4):
        out[6 + c] = q[c]
    for c in range(13, len(y)):
        out[c] = y[c]


@_inner
def _stage(S, y, h, K, y1, err, W, flight):
    """One Dormand-Prince step of size h from y with K[0] = f(y): y1, the error estimate, K[6] = f(y1); the
    work arrays are left holding the legs at y1 (the last stage is evaluated there). With `flight` (no leg
    on the ground, axisymmetric body) the step is the closed form of eq. 62-88, exact."""
    if flight:
        _fly(y, h, S.inertia, S.gravity, y1)
        for c in range(len(y)):
            err[c] = 0.0
        _rhs(S, y1, K[6], W)
        return
    yi = y1                                                     # stage state, overwritten below
    for s in range(1, 7):
        for c in range(len(y)):
            acc = y[c]
            for j in range(s):
                acc += h * A[s, j] * K[j, c]
            yi[c] = acc
        _rhs(S, yi, K[s], W)
    for c in range(len(y)):
        acc, e = y[c], 0.0
        for j in range(7):
            acc += h * B5[j] * K[j, c]
            e += h * (B5[j] - B4[j]) * K[j, c]
        y1[c], err[c] = acc, e


@_inner
def _commit(S, y, W, g):
    """Accept state y: arm legs clear of their last switch, move footpads, keep the legs' shapes, start slides
    where the static margin is gone, add the step's work and update cell memory (_commit_cells). Returns whether a
    slide started (the forces at y change)."""
    geo, mu, contact, P, sliding, shape, armed = S.geo, S.mu, S.contact, S.P, S.sliding, S.shape, S.armed
    Pt, slt, Xt, mt = W.Pt, W.slt, W.Xt, W.mt
    _events(S, y, W, g, 0.0)
    started = False
    for i in range(len(contact)):
        if (armed[i] == 0 or armed[i] == BANDED) and g[i] > ARM:
            armed[i] = 1
        if not contact[i]:
            continue
        for c in range(3):
            P[i, c], shape[i, c] = Pt[i, c], mt[i, 2 + c]
        sliding[i] = slt[i]
        if mt[i, 0] < 0.0:          # eq. 33: a held footpad past mu_S slides (with mass: a band crossing missed)
            started = pad_event(mu, y, i, P, sliding, Xt, geo[9]) or started
        elif pad_settle(mu, y, i, P, sliding, Xt, geo[9]):
            started = True
        _commit_cells(S, W, i, True)
    return started


@_inner
def _commit_cells(S, W, i, damped):
    """Add the work of leg i's cells since their last commit and update their memory, from the leg state W.
    energy (n, C): each cell's work, exact for the rate-free force, the damper's by the trapezoid rule in its
    deflection when `damped` (footpads with mass integrate it as state): not over a massless footpad's slide that
    jumped, which takes no time (the damper's force times that jump would count work it never did), and never
    negative: a damper only dissipates. Its force follows the leg's rate with the footpad held; where a massless
    footpad slides, the deflection can fall while that rate rises, and the product, up to -280 J in a landing
    (docs/notes/simulator-log.md), is the slide's work (the interface's remainder), not the damper's. last (n,
    2C + 1): deflections, damper forces and a flag that they are set; cev the cells' event memory (cell_events)."""
    cells, mem, cev, energy, last = S.cells, S.mem, S.cev, S.energy, S.last
    dt, ft, rt = W.dt, W.ft, W.rt
    cd, cf, cn, ck, cc, cy = cells
    C = mem.shape[1]
    known = last[i, 2 * C] > 0.0
    # A massless footpad sliding moves only at accepted steps; within a step its cells' rates are those with the
    # footpad held, and a slide that ends where that rate is nil would make its turn an event at every step start.
    held_rate = S.sliding[i] > 0 and not has_mass(S.mu)
    for j in range(1 + S.geo[5][i]):
        m = cn[i, j]
        d, f = cd[i, j, :m], cf[i, j, :m]
        delta = dt[i, j]
        damper = ft[i, j] - crush_cell.force(d, f, ck[i, j], 0.0, cy[i, j], (mem[i, j, 0], mem[i, j, 1]), delta, 0.0)
        if known:
            energy[i, j] += crush_cell.static_work(d, f, ck[i, j], cy[i, j], mem[i, j, 0], mem[i, j, 1], last[i, j],
                                                   delta)
            if damped and not has_mass(S.mu):
                energy[i, j] += max(0.5 * (damper + last[i, C + j]) * (delta - last[i, j]), 0.0)
        if delta > mem[i, j, 0]:                  # a new largest stroke: watch its turn while it rises
            cev[i, j, 0] = delta > ARM and rt[i, j] > 0.0 and not held_rate
        elif delta < mem[i, j, 0]:
            cev[i, j, 0] = 0
        mem[i, j, 0], mem[i, j, 1] = crush_cell.commit(d, f, cy[i, j], mem[i, j, 0], mem[i, j, 1], delta)
        cev[i, j, 1] = _next_corner(cells, i, j, mem[i, j, 0], cev[i, j, 1])
        last[i, j], last[i, C + j] = delta, damper
    last[i, 2 * C] = 1.0


@njit(cache=True)
def stage(arrays, y, h, K, y1, err, work, flight):
    """_stage for Python (arrays as `run` takes them)."""
    _stage(LANDING(*borrowed(arrays)), y, h, K, y1, err, WORK(*borrowed(work)), flight)


@njit(cache=True)
def commit(arrays, y, work, g):
    """_commit for Python (arrays as `run` takes them)."""
    return _commit(LANDING(*borrowed(arrays)), y, WORK(*borrowed(work)), g)


@njit(cache=True)
def _leg_force_call(geo, cells, i, mem, shape, P, kin, out):
    """legs.leg_force as a call, for the rare paths (a touchdown, a lift-off): the step's paths inline it."""
    return leg_force(geo, cells, i, mem, shape, P, kin, out)


@_inner
def _switch(S, y, which, W):
    """Touchdown (the footpad holds where it landed) or lift-off (the shape is stored for recontact: eq. 13,
    FORCE's ZETA)."""
    geo, cells, mu, mem, contact, P, sliding, shape = S.geo, S.cells, S.mu, S.mem, S.contact, S.P, S.sliding, S.shape
    armed, last = S.armed, S.last
    dt, ft, Xt, rt = W.dt, W.ft, W.Xt, W.rt
    R = quat_matrix(y[6:10])
    locked, fresh = _past_band(S, which), armed[which] == FRESH
    armed[which] = FRESH
    C = mem.shape[1]
    v = (y[3], y[4], y[5])
    if contact[which]:
        _, alpha, beta, psi = _leg_force_call(geo, cells, which, mem[which], shape[which], P[which],
                                              (y[0:3], R, v, y[10:13]), (dt[which], ft[which], rt[which], Xt[which]))
        contact[which] = 0
        if fresh or W.mt[which, 1] > 0.0:       # left on touching, or at the edge of its reach still pushed: LOCKED
            armed[which] = LOCKED
        else:
            gone = slack(geo, cells, which, mem[which], dt[which], Xt[which], P[which], R)
            # BANDED: left the band short of its set, where its main cell carries no force. A tripod's struts hold
            # its footpad where they left it: touching again the band past zero, moved up by it onto the surface,
            # they would be stroked by the band (18 kN at 1.8e8 N/m), an energy from nothing given back as it
            # leaves again; it touches at zero.
            armed[which] = BANDED if gone < 0.0 and geo[7][which] != TRIPOD else 0
        pad_switch(mu, y, which, P, sliding, False, mv(R, Xt[which, 0], Xt[which, 1], Xt[which, 2]), geo[9])
        shape[which, 0], shape[which, 1], shape[which, 2] = lift_shape(geo, cells, which, mem[which],
                                                                       (alpha, beta, psi), dt[which, 0], y[0:3], R)
        if geo[7][which] == TELESCOPING:
            _clear(S, y, which, R)
        elif geo[7][which] == TRIPOD:
            _relax(S, y, which, R, (alpha, beta, psi), W)
        last[which, 2 * C] = 0.0
    else:
        pad = free_footpad(geo, cells, which, mem[which], shape[which], y[0:3], R)
        top = pad_ground(mu, y, which, len(contact), geo[9], pad[0], pad[1])
        # A footpad touching down on the surface sits on it; one whose clearance jumped (swept into a step's
        # riser or a box's side) is caught on that face where it is and held there until it lifts off. A LOCKED or
        # BANDED footpad touches only the band inside the surface (located within half of it below 50 m/s at the
        # default event_tol and band): still above it, it met a face at the surface.
        band = S.ctl[C_BAND]
        on_face = pad[2] - top > (-0.5 * band if locked else FACE_GAP)
        if on_face:             # one that left short of its set is caught at its set, the band from leaving
            caught = at_set(geo, cells, which, mem[which], shape[which])
            if caught[2] != shape[which, 2]:
                shape[which, 0], shape[which, 1], shape[which, 2] = caught
                pad = free_footpad(geo, cells, which, mem[which], shape[which], y[0:3], R)
        # A massless telescoping footpad touching the band past zero (LOCKED, BANDED) stays where its leg put it,
        # within the band below the surface: raised onto it, its main cell would jump by the band (18 kN at 1.8e8
        # N/m), an energy from nothing given back as it leaves again.
        inside = locked and not has_mass(mu) and geo[7][which] == TELESCOPING
        P[which, 0], P[which, 1], P[which, 2] = pad[0], pad[1], pad[2] if on_face or inside else top
        contact[which] = 1
        sliding[which] = FACE if on_face else TOUCHED           # (re)contact slides on mu_D (eq. 33)
        _leg_force_call(geo, cells, which, mem[which], shape[which], P[which], (y[0:3], R, v, y[10:13]),
                        (dt[which], ft[which], rt[which], Xt[which]))
        pad_switch(mu, y, which, P, sliding, True, mv(R, Xt[which, 0], Xt[which, 1], Xt[which, 2]), geo[9])
        for j in range(C):
            last[which, j], last[which, C + j] = dt[which, j], 0.0
            S.cev[which, j, 2] = dt[which, j] > crush_cell.permanent_set(cells[3][which, j], mem[which, j, 0],
                                                                         mem[which, j, 1])
        last[which, 2 * C] = 1.0


@_inner
def _lifted(S, y, i, R, shape):
    """Height above the ground under it of leg i's free footpad with the shape `shape` (set as leg i's); -inf where
    no footpad has that shape (struts that cannot meet)."""
    for c in range(3):
        S.shape[i, c] = shape[c]
    foot = free_footpad(S.geo, S.cells, i, S.mem[i], S.shape[i], y[0:3], R)
    if not (np.isfinite(foot[0]) and np.isfinite(foot[1]) and np.isfinite(foot[2])):
        return -np.inf
    return foot[2] - pad_ground(S.mu, y, i, len(S.contact), S.geo[9], foot[0], foot[1])


@_inner
def _glide(S, y, i, R, W, frame, a, b):
    """(F . t, F . u): the surface components of leg i's rate-free force F on the capsule (terrain axes; W its leg
    state) with its footpad at P + a t + b u, frame = (P, t, u), t and u unit directions along the surface (its
    shape: the strut lengths there)."""
    P, t, u = frame
    Q = np.empty(3)
    for c in range(3):
        Q[c] = P[c] + a * t[c] + b * u[c]
    zero = (0.0, 0.0, 0.0)
    _, S.shape[i, 0], S.shape[i, 1], S.shape[i, 2] = _leg_force_call(
        S.geo, S.cells, i, S.mem[i], S.shape[i], Q, (y[0:3], R, zero, zero), (W.dt[i], W.ft[i], W.rt[i], W.Xt[i]))
    f0, f1, f2 = mv(R, W.Xt[i, 0], W.Xt[i, 1], W.Xt[i, 2])
    return f0 * t[0] + f1 * t[1] + f2 * t[2], f0 * u[0] + f1 * u[1] + f2 * u[2]


@_inner
def _relax(S, y, i, R, loaded, W):
    """A tripod leg lifting off with the strut lengths `loaded` takes the free shape that unloads it, as a massless
    leg in the air carries no force: its struts unloaded (lift_shape) where that keeps its footpad from sinking
    into the ground (where its touchdown could not be found); else the footpad glides along the surface to where
    the struts push only normal to it (the least strut energy on it, found by Newton's method: the leg then
    touches down again at once, pushing); else it keeps `loaded`. The cells' static work from their lift-off
    deflections to those of that shape is added to theirs, and what they give up (the energy of the footpad's
    in-plane motion, which the massless leg drops) to the friction work (footpad_mass.pad_release)."""
    cells, mem = S.cells, S.mem
    before = W.dt[i].copy()
    free = (S.shape[i, 0], S.shape[i, 1], S.shape[i, 2])
    floor = min(_lifted(S, y, i, R, loaded), 0.0) - 0.5 * GTOL       # round-off below it still finds the ground
    if _lifted(S, y, i, R, free) < floor:
        _lifted(S, y, i, R, loaded)
        foot = free_footpad(S.geo, cells, i, mem[i], S.shape[i], y[0:3], R)
        P = np.array((foot[0], foot[1], foot[2]))
        n0, n1, n2 = bearing_normal(S.geo[9], P[0], P[1], P[2])
        t0, t1, t2 = (1.0, 0.0, 0.0) if abs(n0) < 0.9 else (0.0, 1.0, 0.0)
        d = t0 * n0 + t1 * n1 + t2 * n2
        t = np.array((t0 - d * n0, t1 - d * n1, t2 - d * n2))
        t /= np.sqrt(t[0] ** 2 + t[1] ** 2 + t[2] ** 2)
        u = np.array(cross(n0, n1, n2, t[0], t[1], t[2]))
        frame, a, b, h = (P, t, u), 0.0, 0.0, 1e-8
        for _ in range(12):
            fa, fb = _glide(S, y, i, R, W, frame, a, b)
            if abs(fa) + abs(fb) <= FLOOR:
                break
            j00, j10 = _glide(S, y, i, R, W, frame, a + h, b)     # Jacobian by forward differences
            j01, j11 = _glide(S, y, i, R, W, frame, a, b + h)
            j00, j10, j01, j11 = (j00 - fa) / h, (j10 - fb) / h, (j01 - fa) / h, (j11 - fb) / h
            det = j00 * j11 - j01 * j10
            if det == 0.0:
                break
            a -= (j11 * fa - j01 * fb) / det
            b -= (j00 * fb - j10 * fa) / det
        _glide(S, y, i, R, W, frame, a, b)
        free = (S.shape[i, 0], S.shape[i, 1], S.shape[i, 2])
        if _lifted(S, y, i, R, free) < floor:
            free = loaded
    if _strain(S, y, i, R, W, free, before, False) > 0.0:     # never more strain energy than it left with
        free = loaded
    pad_release(S.mu, y, len(S.contact), -_strain(S, y, i, R, W, free, before, True))


@_inner
def _strain(S, y, i, R, W, shape, before, add):
    """The static work of leg i's cells from deflections `before` to those of its free shape `shape` (set as leg
    i's; W holds the leg state there), added to their work if `add`."""
    cd, cf, cn, ck, cc, cy = S.cells
    _lifted(S, y, i, R, shape)
    foot = free_footpad(S.geo, S.cells, i, S.mem[i], S.shape[i], y[0:3], R)
    _leg_force_call(S.geo, S.cells, i, S.mem[i], S.shape[i], np.array(foot), (y[0:3], R, (y[3], y[4], y[5]),
                    y[10:13]), (W.dt[i], W.ft[i], W.rt[i], W.Xt[i]))
    total = 0.0
    for j in range(1 + S.geo[5][i]):
        m = cn[i, j]
        w = crush_cell.static_work(cd[i, j, :m], cf[i, j, :m], ck[i, j], cy[i, j], S.mem[i, j, 0], S.mem[i, j, 1],
                                   before[j], W.dt[i, j])
        if add:
            S.energy[i, j] += w
        total += w
    return total


@_inner
def _clear(S, y, i, R):
    """A telescoping leg lifting off with its free footpad below the ground under it is re-aimed in the air at the
    nearest point within FACE_GAP of it that is clear, so that its touchdown can be found: up along its own axis, or
    straight up where the ground rises along its lean (a footpad caught in the corner of its hole in the soil and a
    rock's foot), else sideways out of a face (a footpad held on a step's riser or a box's side, a located overshoot of
    micrometres into the feature; radii FACE_GAP 4^-m, 16 directions). The leg lands again with at most that much more
    compression beyond its set: bounded by the gap the face test grants a footpad on the surface (a 1 mm force step
    stores 7 J at the report's unloading rate 1.46e7 N/m; a micrometre, 1e-5 J). Deeper (no clear point within FACE_GAP:
    a footpad inside a feature, up to its height below the top), the leg keeps its lengths as loaded, as a tripod leg
    does: aiming it at the top would land it there compressed by that height, the force and elastic energy of that
    stroke created from nothing and given back by its cell."""
    n = len(S.contact)
    foot = free_footpad(S.geo, S.cells, i, S.mem[i], S.shape[i], y[0:3], R)
    # A LOCKED or BANDED leg touches only the band past zero: a footpad within half of it below the ground (one
    # that touched down there and was held inside) is found and stays where it is. One deeper is raised to GTOL
    # above that half, so that a face it meets next is told from the band by _switch (at the half exactly, its
    # round-off read a jump into a rock's side as the band: 4,608 touch-and-leave steps at one instant).
    floor = GTOL - 0.5 * S.ctl[C_BAND] if _past_band(S, i) else 0.0
    gap = foot[2] - pad_ground(S.mu, y, i, n, S.geo[9], foot[0], foot[1]) - floor
    if gap >= 0.0:
        return
    target = (foot[0], foot[1], foot[2] - gap)
    # Raised along its own axis (shortened, its tilt kept) where the ground under the moved point lets it clear: a
    # tilted leg re-aimed straight up turns a little, and its pad cells, in the air, touch down again stroked by that
    # turn, work never done (a pad cell deep in its bottoming branch gave back 2.6 kJ over 2,000 raises). Over higher
    # ground (a rock's flank rising along the leg's lean) it is raised straight up.
    a0, a1, a2 = mv(R, S.geo[0][i, 0], S.geo[0][i, 1], S.geo[0][i, 2])
    l0, l1, up = y[0] + a0 - foot[0], y[1] + a1 - foot[1], y[2] + a2 - foot[2]   # footpad to attachment
    if up > 0.1 * np.sqrt(l0 ** 2 + l1 ** 2 + up ** 2):
        s = -gap / up
        x, yy = foot[0] + s * l0, foot[1] + s * l1
        if foot[2] - gap >= pad_ground(S.mu, y, i, n, S.geo[9], x, yy) + floor:
            target = (x, yy, foot[2] - gap)
    if gap < -FACE_GAP:
        found = False
        radius = FACE_GAP * 4.0 ** -7
        while not found and radius <= FACE_GAP:
            for k in range(16):
                x, yy = foot[0] + radius * np.cos(k * np.pi / 8.0), foot[1] + radius * np.sin(k * np.pi / 8.0)
                if foot[2] > pad_ground(S.mu, y, i, n, S.geo[9], x, yy) + floor:
                    target, found = (x, yy, foot[2]), True
                    break
            radius *= 4.0
        if not found:
            return
    S.shape[i, 0], S.shape[i, 1], S.shape[i, 2] = aim(S.geo, S.cells, i, S.mem[i], target, y[0:3], R)


@njit(cache=True)
def switch(arrays, y, which, work):
    """_switch for Python (arrays as `run` takes them)."""
    _switch(LANDING(*borrowed(arrays)), y, which, WORK(*borrowed(work)))


@_inner
def _monitor(S, y, t, dt_step):
    """Outcome checks after an accepted step; a status or -1."""
    geo, mass, inertia, gravity, bottoming, up, body = S.geo, S.mass, S.inertia, S.gravity, S.bottoming, S.up, S.body
    order, mem, contact, P, shape, ctl, run = S.order, S.mem, S.contact, S.P, S.shape, S.ctl, S.run_state
    R = quat_matrix(y[6:10])
    n = len(contact)
    for i in range(n):
        if contact[i] and run[S_BOT_T] < 0.0:
            for j in range(1 + geo[5][i]):
                if mem[i, j, 0] > bottoming[i, j]:
                    run[S_BOT_T], run[S_BOT_LEG], run[S_BOT_CELL] = t, i, j
    if run[S_BOT_T] >= 0.0 and ctl[C_STOPBOTTOM] > 0.0:
        return BOTTOMED
    u0, u1, u2 = mv(R, up[0], up[1], up[2])
    gn = np.sqrt(gravity[0] ** 2 + gravity[1] ** 2 + gravity[2] ** 2)
    if -(u0 * gravity[0] + u1 * gravity[1] + u2 * gravity[2]) / gn <= ctl[C_TIPCOS]:
        return TIPPED                                          # nutation past the critical angle (stmt 367)
    struck = member_strike(geo, contact, shape, y[0:3], R)
    if struck >= 0:
        run[S_STRUCK] = struck
        return MEMBER
    flat = folded(geo, contact, P, y[0:3], R)
    if flat >= 0:
        run[S_STRUCK] = flat
        return FOLDED
    for b in range(body.shape[0]):
        p0, p1, p2 = mv(R, body[b, 0], body[b, 1], body[b, 2])
        if clearance(geo[9], y[0] + p0, y[1] + p1, y[2] + p2) < ctl[C_CLEAR]:
            return BODY
    on_ground = 0
    for i in range(n):
        on_ground += contact[i]
    if ctl[C_TAUS] > 0.0:                                      # quiescence of motion (main program 378-390)
        normal, _ = quiescence_momenta(y[3:6], y[10:13], mass, inertia)
        run[S_QUIET], quiet = quiescence_update(dt_step, normal, run[S_MOMENTUM], run[S_QUIET], ctl[C_PERIOD],
                                                ctl[C_TAUS], on_ground > 0, ctl[C_QUIET_FRAC])
        if quiet:
            return QUIET
    # Energy criterion (QUIMOT), only once the CG has stopped approaching the terrain, so that the peak
    # strokes and accelerations are complete when it ends the run (the report checked from t = 0.05 s on).
    # It is judged over the polygon of the footpads on the ground (at least three, in their order round the
    # capsule). With a leg in the air (a lander resting on three legs of four on a slope) the capsule must
    # also be unable to bring that leg down (stability.hanging_margin) and have held so for one full bounce
    # (2 x period, pi sqrt(m / k)): not a bounce that lifts it again. No touchdown, and none of its loads,
    # then comes after the run ends.
    if ctl[C_ENERGY_T] >= 0.0 and t >= ctl[C_ENERGY_T] and on_ground >= 3 and (on_ground < n or y[5] >= 0.0):
        pads = np.empty((on_ground, 3))
        k = 0
        for m in range(n):
            if contact[order[m]]:
                pads[k, 0], pads[k, 1], pads[k, 2] = P[order[m], 0], P[order[m], 1], P[order[m], 2]
                k += 1
        margins = tipping_margins(y[0:3], y[3:6], R, y[10:13], (mass, inertia), gravity, pads, True)
        if on_ground == n:
            if stable_by_energy(margins):                       # eq. 89-95 (QUIMOT) for every adjacent pair
                return STABLE
        elif stable_by_energy(margins) and _hanging_clear(S, y, R):
            if run[S_HANG] < 0.0:
                run[S_HANG] = t
            if t - run[S_HANG] >= 2.0 * ctl[C_PERIOD] and y[5] >= 0.0:
                return STABLE
            return -1
    run[S_HANG] = -1.0
    return -1


@_inner
def _hanging_clear(S, y, R):
    """Every leg in the air is clear of the ground under it (the terrain, or the hole its footpad left in soil)
    and cannot be brought down by the capsule's kinetic energy about the edge through its grounded neighbours
    (in their order round the capsule)."""
    geo, cells, mass, inertia, gravity, mu = S.geo, S.cells, S.mass, S.inertia, S.gravity, S.mu
    order, mem, contact, P, shape = S.order, S.mem, S.contact, S.P, S.shape
    n = len(contact)
    for m in range(n):
        i = order[m]
        if contact[i]:
            continue
        a, b = m, m
        while not contact[order[a]]:
            a = (a - 1) % n
        while not contact[order[b]]:
            b = (b + 1) % n
        foot = free_footpad(geo, cells, i, mem[i], shape[i], y[0:3], R)
        ground = pad_ground(mu, y, i, n, geo[9], foot[0], foot[1])
        if not (foot[2] > ground and hanging_margin(y[0:3], y[3:6], y[10:13], (mass, inertia), gravity,
                                                    (P[order[a]], P[order[b]]), foot, foot[2] - ground) > 0.0):
            return False                                                                  # NaN: not clear
    return True


@_inner
def _error_norm(S, y, y1, err, W, weight, h):
    """RMS of the step's error estimate over atol + rtol max(|y|, |y1|) (Hairer, Norsett and Wanner, Solving ODEs I,
    eq. II.4.11), or the largest sliding footpad's path error over atol + rtol x its leg's reach if larger; NaN
    stays NaN. A path error counts in proportion to its leg's ground force over the capsule's weight (at most
    fully): a footpad that carries little cannot move the capsule much, however its path strays, and its push
    direction is ill-defined as its load goes to zero. Steps of PATH_FLOOR x event_tol or less skip the path
    error: there it no longer falls as h^2 (a slide that jumps, the friction cone folding near zero normal load;
    a push direction that turns by a finite angle within a tiny slide), so shorter steps would not reduce it.
    Steps longer than ENERGY_FLOOR x event_tol also keep the energy audit: their defect (_energy_defect) within
    ENERGY_RATE x rtol x the landing's energy scale per second of step (and its round-off)."""
    ctl, reach, mt, Xt = S.ctl, S.geo[2], W.mt, W.Xt
    e = 0.0
    for c in range(len(y)):
        e += (err[c] / (ctl[C_ATOL] + ctl[C_RTOL] * max(abs(y[c]), abs(y1[c])))) ** 2
    e = np.sqrt(e / len(y))
    if h > ENERGY_FLOOR * ctl[C_EVENTTOL]:
        scale = S.run_state[S_EREF]
        e = max(e, abs(_energy_defect(S, y, y1, W)) / (ENERGY_RATE * ctl[C_RTOL] * scale * h + ROUND_OFF * scale))
    if h <= PATH_FLOOR * ctl[C_EVENTTOL]:
        return e
    for i in range(mt.shape[0]):
        load = min(np.sqrt(Xt[i, 0] ** 2 + Xt[i, 1] ** 2 + Xt[i, 2] ** 2) / weight, 1.0)
        e = max(e, load * mt[i, 5] / (ctl[C_ATOL] + ctl[C_RTOL] * reach[i]))
    return e


@_inner
def _energy_defect(S, y, y1, W):
    """What the capsule gave up over the step y -> y1 less what its legs took (J): the energy audit
    (landing.simulate) over one step, the cells' rate-free work exact from their last commit (W at y1)."""
    m, inertia, g = S.mass, S.inertia, S.gravity
    d = 0.0
    for c in range(3):                       # differences of squares as (a - b)(a + b): round-off of the step's
        d += (0.5 * m * (y[3 + c] - y1[3 + c]) * (y[3 + c] + y1[3 + c]) + m * g[c] * (y1[c] - y[c])   # change only
              + 0.5 * inertia[c] * (y[10 + c] - y1[10 + c]) * (y[10 + c] + y1[10 + c]))
    n, C = S.mem.shape[0], S.mem.shape[1]
    d -= taken(S.mu, y, y1, n, C)
    if has_mass(S.mu):
        cd, cf, cn, ck, cc, cy = S.cells
        mem, last = S.mem, S.last
        for i in range(n):
            if S.contact[i] and last[i, 2 * C] > 0.0:
                for j in range(1 + S.geo[5][i]):
                    k = cn[i, j]
                    d -= crush_cell.static_work(cd[i, j, :k], cf[i, j, :k], ck[i, j], cy[i, j], mem[i, j, 0],
                                                mem[i, j, 1], last[i, j], W.dt[i, j])
    return d


@njit(cache=True)
def _shrink(e):
    """Step factor after a rejection with error norm e (0.2 when e is not finite)."""
    return max(0.2, 0.9 * e ** -0.2) if np.isfinite(e) else 0.2


@njit(cache=True)
def _dense(y0, y1, K, h, theta, out):
    """Dormand-Prince's continuous extension of a step at fraction theta (fourth order; the event search's
    guide): the cubic Hermite of (y0, f0, y1, f1) plus theta^2 (1 - theta)^2 h sum(d_i k_i) (Hairer, Norsett
    and Wanner 1993, Sec. II.6, CONTD5)."""
    s = 1.0 - theta
    for c in range(len(y0)):
        d = y1[c] - y0[c]
        r3 = h * K[0, c] - d
        r4 = d - h * K[6, c] - r3
        r5 = h * (D[0] * K[0, c] + D[2] * K[2, c] + D[3] * K[3, c] + D[4] * K[4, c] + D[5] * K[5, c]
                  + D[6] * K[6, c])
        out[c] = y0[c] + theta * (d + s * (r3 + theta * (r4 + s * r5)))


@_inner
def _guide(S, W, T, y, h, j, tol, flight):
    """The earliest crossing on the step's continuous extension (in free flight, where the step computes no
    stages, the closed form itself), found by Illinois false position with one leg evaluation per point (no
    integration): (time estimate, slope of the crossing function there, its index)."""
    y1, K, g_prev, yt, gm, ga, gb = T.y1, T.K, T.g_prev, T.yt, T.gm, T.ga, T.gb
    a, b, side = 0.0, h, 0
    _copy1(ga, g_prev)
    _copy1(gb, T.g1)
    fa, fb = ga[j], gb[j]
    for _ in range(60):
        if b - a <= tol:
            break
        m = b - fb * (b - a) / (fb - fa) if fb != fa else 0.5 * (a + b)
        if not (a < m < b):
            m = 0.5 * (a + b)
        if flight:
            _fly(y, m, S.inertia, S.gravity, yt)
        else:
            _dense(y, y1, K, h, m / h, yt)
        _legs(S, W, yt, quat_matrix(yt[6:10]))
        _events(S, yt, W, gm, S.ctl[C_BAND])
        k = _first(g_prev, gm)
        if k >= 0:
            if k != j:
                j, fa, side = k, ga[k], 0
            b = m
            _copy1(gb, gm)
            fb = gb[j]
            if side == -1:
                fa *= 0.5
            side = -1
        else:
            a = m
            _copy1(ga, gm)
            fa = ga[j]
            if side == 1:
                fb *= 0.5
            side = 1
    slope = (gb[j] - ga[j]) / (b - a) if b > a else -1.0
    return a + ga[j] / max(-slope, 1e-300) if ga[j] > 0.0 else a, min(slope, -1e-300), j


@_inner
def _on_extension(S, T, W_lo, y, h, s):
    """Whether the step's continuous extension at s (0 < s < h) lies before every crossing: then T.y_lo, T.g_lo
    and the leg state W_lo hold it. For the events whose switch waits for the step's end (touchdown, lift-off,
    stick-to-slip, the soil's) every stage saw one smooth law and the extension is as accurate at the event as
    the step itself (fourth order): no trial step is needed there. A cell turning inside a step loads along its
    curve until its stroke falls below the step's starting maximum, which near the turn's flat top only a
    step's last stages reach, shallowly: measured on the closed-form drop, its largest stroke converges as with
    trial steps. Not so at a corner of a loading curve, a kink the stages straddle (on the closed-form drop at
    rtol 1e-4 and 5 ms steps, the extension put the largest stroke 1.8e-4 m off, trial steps 6e-8 m), nor for a
    footpad sliding by position (footpad_slip), whose path has a corner at every step."""
    if not 0.0 < s < h:
        return False
    ys = T.y_lo
    _dense(y, T.y1, T.K, h, s / h, ys)
    _legs(S, W_lo, ys, quat_matrix(ys[6:10]))
    _events(S, ys, W_lo, T.g_lo, S.ctl[C_BAND])
    return _first(T.g_prev, T.g_lo) < 0


@_inner
def _record(H, k, t, y, S, W):
    """History row k: time, state, the legs' deflections, forces and ground forces (NaN, 0 off the ground),
    footpads and contact flags (the caller writes the derivative)."""
    contact, dt, ft, Xt = S.contact, W.dt, W.ft, W.Xt
    H.t[k] = t
    _copy1(H.y[k], y)
    for i in range(len(contact)):
        on = contact[i] > 0
        for c in range(dt.shape[1]):
            H.d[k, i, c], H.f[k, i, c] = (dt[i, c], ft[i, c]) if on else (np.nan, 0.0)
        for c in range(3):
            H.X[k, i, c] = Xt[i, c] if on else 0.0
    _copy2(H.P[k], S.P)
    _copy1(H.c[k], contact)


@_inner
def _copy_work(src, dst):
    """Copy the leg state of one evaluation (footpads, slip, deflections, forces, margins, rates)."""
    _copy2(dst.Pt, src.Pt)
    _copy1(dst.slt, src.slt)
    _copy2(dst.dt, src.dt)
    _copy2(dst.ft, src.ft)
    _copy2(dst.Xt, src.Xt)
    _copy2(dst.mt, src.mt)
    _copy2(dst.rt, src.rt)


@_inner
def _start(S, T, W, H, y, t):
    """Before the first step: legs marked TOUCH touch down, K[0] = f(y), an empty record gets its first row and
    T.g_prev the event values at y."""
    armed, cnt, K = S.armed, S.cnt, T.K
    for i in range(len(armed)):
        if armed[i] == TOUCH:
            _switch(S, y, i, W)
    _rhs(S, y, K[0], W)
    if cnt[K_HIST] == 0:
        _record(H, 0, t, y, S, W)
        _copy1(H.dy[0], K[0])
        cnt[K_HIST] = 1
    cnt[K_RHS] += 1
    _events(S, y, W, T.g_prev, S.ctl[C_BAND])


@_phase
def _try_step(S, T, W, y, h, law, e):
    """One embedded step of size h from y (T.y1, T.err, T.K; W at y1) and its error norm (e unchanged when the
    step is not error-controlled): (whether it passes the error test, the norm). law: (fixed steps, free flight,
    the capsule's weight)."""
    fixed, flight, weight = law
    _stage(S, y, h, T.K, T.y1, T.err, W, flight)
    S.cnt[K_RHS] += 6
    if not (fixed or flight):
        e = _error_norm(S, y, T.y1, T.err, W, weight, h)
        if not e <= 1.0:
            return False, e
    return True, e


@_inner
def _locate(S, T, W, W_lo, y, h, j, law):
    """The earliest event j crossing within the step of size h: located first on the step's continuous extension
    (_guide); the step is accepted there, just short of it, when its stages saw one smooth law (_on_extension);
    else by real trial steps aimed just short of it (Newton with the interpolant's slope, Illinois on the real
    bracket if that stalls); the function followed is the one crossing first in the current bracket. The step is
    accepted at the lower end, before the crossing, and that one function switched there (a leg touching at the
    same instant follows in the next step): every stage of the accepted step then saw the forces before it, also
    where the crossing is a jump (a slide leaving its reach). The search ends when the bracket or the secant's
    distance from its lower end is within event_tol, or when the function there is within its tolerance of zero
    (a footpad slid to the edge of its reach sits at zero until it lifts off: no secant can place that crossing).
    Each trial step passes the error test too, or the step is rejected: a shorter step can meet a jump the full
    one missed (a slip search that misses the dip near the peg-leg axis and slides far). Returns (the event, the
    accepted step, the last trial step, its error norm); when that norm passes, T.y1 and W hold the state the
    step is accepted at (K[6] its derivative when the step is empty). law: as _try_step's."""
    fixed, flight, weight = law
    K, y1, err, g_prev, g1, g_lo, y_lo = T.K, T.y1, T.err, T.g_prev, T.g1, T.g_lo, T.y_lo
    mu, contact, sliding, ctl, cnt = S.mu, S.contact, S.sliding, S.ctl, S.cnt
    n = S.mem.shape[0]
    band = ctl[C_BAND]
    cnt[K_EVENTS] += 1
    tol = ctl[C_EVENTTOL]
    est, slope, j = _guide(S, W, T, y, h, j, 0.1 * tol, flight)
    lo, hi, side, mid, a_hi, newton, e_trial = 0.0, h, 0, -1.0, g1[j], 0, 0.0
    # Legs touching, leaving or turning together: the next ones switch at the step's start, no search (not
    # a friction switch, whose new law may cross back at once).
    smooth = j < (3 + S.mem.shape[1]) * n and not (flight or slides_by_position(mu, contact, sliding))
    s = est - 0.5 * tol
    if smooth and s <= 0.0 and (j < n or j >= 3 * n):
        lo = hi = 0.0
    elif smooth and _on_extension(S, T, W_lo, y, h, s):
        lo = hi = s
    _copy1(g_lo, g_prev)
    f_lo, f_hi = g_prev[j], g1[j]
    while hi - lo > tol:
        if lo > 0.0 and (g_lo[j] <= (FLOOR if n <= j < 2 * n else GTOL) or g_lo[j] <= -slope * tol
                         or g_lo[j] * (hi - lo) <= tol * (g_lo[j] - a_hi)):
            break
        # Aim just short of the crossing: first from the interpolant, then Newton from the nearer
        # real end with the interpolant's slope; Illinois on the real bracket if that stalls.
        mid = est - 0.5 * tol
        if newton >= 4 or not (lo < mid < hi):
            mid = hi - f_hi * (hi - lo) / (f_hi - f_lo) if f_hi != f_lo else 0.5 * (lo + hi)
        if not (lo < mid < hi):
            mid = 0.5 * (lo + hi)
        _stage(S, y, mid, K, y1, err, W, flight)
        cnt[K_RHS] += 6
        cnt[K_TRIALS] += 1
        if not (fixed or flight):
            e_trial = _error_norm(S, y, y1, err, W, weight, mid)
            if not e_trial <= 1.0:                 # the trial step itself fails the error test
                return j, lo, mid, e_trial
        _events(S, y1, W, g1, band)
        k = _first(g_prev, g1)
        newton += 1
        if k >= 0:
            if k != j:
                j, f_lo, side, newton = k, g_lo[k], 0, 4
            hi, f_hi, a_hi = mid, g1[j], g1[j]
            est = hi + g1[j] / -slope
            if side == -1:
                f_lo *= 0.5
            side = -1
        else:
            lo, f_lo = mid, g1[j]
            _copy1(g_lo, g1)
            _copy1(y_lo, y1)
            _copy_work(W, W_lo)
            est = lo + g1[j] / -slope
            if side == 1:
                f_hi *= 0.5
            side = 1
    if lo == 0.0:                              # the crossing is within event_tol of the start
        _copy1(y1, y)
        _rhs(S, y1, K[6], W)
        cnt[K_RHS] += 1
    else:
        _copy1(y1, y_lo)
        _copy_work(W_lo, W)
    return j, lo, mid, e_trial


@_inner
def _apply(S, W, y, g, forced):
    """Commit the accepted state y (_commit) and the located event `forced` that is not a leg's touchdown or
    lift-off (a cell's turn or corner, a footpad's soil or slip event; -1: none): whether the forces at y changed."""
    n = S.mem.shape[0]
    changed = _commit(S, y, W, g)
    if forced >= 3 * n:
        cell_event(S.cells, S.cev, forced, n)
    elif forced >= 2 * n:
        changed = ground_event(S.mu, y, forced - 2 * n, S.sliding, S.geo[9])
    elif forced >= n:
        changed = pad_event(S.mu, y, forced - n, S.P, S.sliding, W.Xt, S.geo[9])
    return changed


@_phase
def _accept(S, T, W, H, y, t, h_acc, forced):
    """Accept the step of h_acc ending at time t in state T.y1 (W the legs there): y takes it, memory and the
    event `forced` are committed, the record gets its row, K[0] and T.g_prev the derivative and event values at
    y after the event."""
    K, g_prev = T.K, T.g_prev
    contact, P, sliding, armed, ctl, cnt = S.contact, S.P, S.sliding, S.armed, S.ctl, S.cnt
    band = ctl[C_BAND]
    n = S.mem.shape[0]
    Pt, slt = W.Pt, W.slt
    if h_acc > ctl[C_EVENTTOL]:                    # a step past event_tol: legs that touched are no longer FRESH,
        for i in range(n):                         # slides that started may stick again (footpad_mass.STARTED)
            if armed[i] == FRESH:
                armed[i] = 0
            if sliding[i] == STARTED:
                sliding[i] = PAD_BAND
    _copy1(y, T.y1)
    qn = np.sqrt(y[6] ** 2 + y[7] ** 2 + y[8] ** 2 + y[9] ** 2)
    for c in range(6, 10):
        y[c] /= qn
    cnt[K_STEPS] += 1
    # A massless footpad's slide does not stop in a step of event_tol or less: where its last slide ended its push
    # sits at the dynamic limit, so such a step (an event at its start) reads it as stopped, and two slides then
    # restarted each other at one instant. It stops in the first longer step that finds its push below the limit.
    # Not so a footpad that has just touched down (TOUCHED), which slides on mu_D only until its first commit;
    # after that its slides go by this rule too, even before its first step longer than event_tol (two legs
    # touching together at a free-play cell's corner traded a slide at one instant while both were FRESH).
    short = h_acc <= ctl[C_EVENTTOL] and slides_by_position(S.mu, contact, sliding)
    jumped = 0                                     # which legs' slides jumped (bits)
    before = sliding.copy() if short else sliding
    changed = _apply(S, W, y, T.g1, forced)
    if short:
        for i in range(n):
            if contact[i] and before[i] == 1 and sliding[i] == 0:
                sliding[i] = 1
    k = cnt[K_HIST]                                # record as committed (a switching leg: before it)
    if k > 0 and t <= H.t[k - 1]:
        k -= 1                                     # an event at the start of a step replaces its record
    _record(H, k, t, y, S, W)
    if forced < 0 and not changed:
        _copy1(K[0], K[6])                        # first same as last: memory updates keep the force
    else:
        if 0 <= forced < n:
            _switch(S, y, forced, W)
        _rhs(S, y, K[0], W)
        cnt[K_RHS] += 1
        # A slide that jumps here (it starts with mu_S > mu_D, or a touchdown) starts the next step where it
        # lands, so that the step's slide and its path error vanish with h.
        for i in range(n):
            if contact[i] and slt[i]:
                jumped |= 1 << i
                P[i, 0], P[i, 1], P[i, 2] = Pt[i, 0], Pt[i, 1], Pt[i, 2]
    _copy1(H.dy[k], K[0])
    cnt[K_HIST] = k + 1
    _events(S, y, W, g_prev, band)
    # A footpad that is out of reach from the start (a touchdown or slide start leaving it beyond the
    # friction cone at the edge of its reach) never crosses zero from above: it leaves now.
    # It stays LOCKED until it touches again (the band past zero), whatever its height: a touchdown is located
    # to within event_tol, so the footpad may hang above the terrain by more than ARM, and re-arming it
    # there would let it touch and leave again at the same instant.
    # So does a footpad caught on a vertical face that its leg pulls off it: _events holds it there for its
    # first step (FRESH), since one dragged along the face, its footpad pulled off it by the drag while its free
    # footpad still moves into the face, would otherwise touch and leave again at one instant without end.
    # A massless footpad's slide that jumped here (no step, no work of the capsule) is committed as a step of its
    # own (footpads with mass are placed by their state, not by P): its cells' static work (the slide stops where
    # the leg's push turns against its path, so it never adds to their energy) and no damper work (it takes no
    # time). Uncommitted, a leg leaving at once kept the jump's stroke and gave it back after its next touchdown
    # (a grazing touchdown whose slide ran centimetres to the edge of its reach).
    for i in range(n):
        if contact[i] and jumped >> i & 1 and not has_mass(S.mu):
            _leg_force_call(S.geo, S.cells, i, S.mem[i], S.shape[i], P[i], (y[0:3], quat_matrix(y[6:10]),
                            (y[3], y[4], y[5]), y[10:13]), (W.dt[i], W.ft[i], W.rt[i], W.Xt[i]))
            _commit_cells(S, W, i, False)
    for i in range(n):
        if contact[i] and (W.mt[i, 1] > 0.0 or sliding[i] == FACE) and g_prev[i] <= 0.0:
            _switch(S, y, i, W)
            armed[i] = LOCKED
            _rhs(S, y, K[0], W)
            cnt[K_RHS] += 1
            _copy1(H.dy[k], K[0])
            _events(S, y, W, g_prev, band)


@_phase
def _next_h(S, h, e, j, fixed, flight):
    """The next step's size after an accepted step of (tried) size h, error norm e, event j (-1: none); kept in
    run_state[S_H] unless in free flight."""
    ctl, run_state = S.ctl, S.run_state
    if fixed:
        h = ctl[C_FIXED]
    elif flight:
        h = run_state[S_H]
    elif j < 0:
        h = min(ctl[C_MAXSTEP], h * min(5.0, 0.9 * max(e, 1e-10) ** -0.2))
    if not flight:
        run_state[S_H] = h
    return h


@njit(cache=True)
def run(arrays, y, t, history, scratch):
    """Advance the landing from (t, y) until t_final or a status; y, t and every memory array are updated in
    place. arrays: the landing's (LANDING's fields in order), history: the record's (HISTORY's fields in order:
    t, y, dy, cell deflections and forces, ground forces, footpads, contact flags), scratch: new_scratch's.
    Legs marked TOUCH touch down first, and an empty record gets its first row. Returns (status, t). Every
    array is used through a view without reference counts (borrow.py): the caller holds them all for the call."""
    K, y1, err, g_prev, g1, g_lo, y_lo, yt, gm, ga, gb, work, work_lo = borrowed(scratch)
    S, T = LANDING(*borrowed(arrays)), STEP(K, y1, err, g_prev, g1, g_lo, y_lo, yt, gm, ga, gb)
    W, W_lo, H, y = WORK(*work), WORK(*work_lo), HISTORY(*borrowed(history)), borrowed(y)
    ctl, cnt, gravity = S.ctl, S.cnt, S.gravity
    _start(S, T, W, H, y, t)
    weight = S.mass * np.sqrt(gravity[0] ** 2 + gravity[1] ** 2 + gravity[2] ** 2)
    fixed = ctl[C_FIXED] > 0.0
    h = ctl[C_FIXED] if fixed else S.run_state[S_H]
    t_final = ctl[C_TFINAL]
    e = 1.0
    stalled = 0
    while t < t_final - 1e-15:
        if not np.isfinite(h) or h < 1e-14:
            return FAILED, t
        flight = ctl[C_FLIGHT] > 0.0 and np.sum(S.contact) == 0
        if flight:
            h = ctl[C_MAXSTEP]
        h_free = h
        h = min(h, t_final - t)
        law = (fixed, flight, weight)
        passed, e = _try_step(S, T, W, y, h, law, e)
        if not passed:
            cnt[K_REJECTED] += 1
            h *= _shrink(e)
            continue
        _events(S, y1, W, g1, ctl[C_BAND])
        j = _first(g_prev, g1)
        forced, h_acc = -1, h
        if j >= 0:
            j, h_acc, mid, e_trial = _locate(S, T, W, W_lo, y, h, j, law)
            if not e_trial <= 1.0:
                cnt[K_REJECTED] += 1
                h = mid * _shrink(e_trial)
                continue
            forced = j
        # Watchdog: accepted steps that no longer advance time (a switching function crossing back and forth
        # at one instant) end the run as failed instead of looping.
        stalled = stalled + 1 if h_acc <= 1e-13 * max(1.0, abs(t)) else 0
        if stalled > MAX_STALL:
            return FAILED, t
        t += h_acc
        _accept(S, T, W, H, y, t, h_acc, forced)
        h = _next_h(S, h, e, j, fixed, flight)
        # A step cut short to end at t_final (a remainder of 1e-15 s at worst) does not shrink the next call's
        # first step (below 1e-14 s it would end that call as failed at once).
        if h_free > h_acc and j < 0 and not (fixed or flight):
            h = max(h, h_free)
            S.run_state[S_H] = h
        status = _monitor(S, y, t, h_acc)
        if status >= 0:
            return status, t
        if cnt[K_HIST] >= len(H.t):
            return BUFFER, t
    return END, t
