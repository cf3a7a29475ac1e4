"""Legs of any kind behind one interface for the step loop: telescoping (Sec. V.E), articulated (Sec. V.F) or
tripod (inverted tripod and cantilever, tripod_leg.py).

`pack` turns a tuple of legs into the arrays the compiled functions take:
geo = (attach (n,3), to_body (n,3,3), reach (n,), pad_lever (n,), pad angle cosines and sines (n,P,2),
extra cells (n,), small_angle (n,), kind (n,), articulated rows (n, N_ART), tripod legs (n,5,3):
`TripodLeg.packed`) and cells = (deflections (n,C,K), forces (n,C,K), n_points (n,C), k, c, yield force or -1
(n,C)); `with_terrain` puts the packed terrain at geo[9], the tripods then at geo[10].
Cell 0 is the leg's main cell (telescoping axial, articulated upper, tripod primary). A telescoping or
articulated leg lifts off when its main cell goes slack, a tripod where the ground's normal push falls to zero
(`slack`). A leg's shape (n,3) is its (alpha, beta, psi) (a tripod's: its strut lengths) at the last accepted step
on the ground and the stored free geometry off it (psi unused by telescoping legs).

A set of legs packs the arrays of the kinds it lacks (pad angles, articulated rows, tripods) as None: compiled
code then takes only the functions of the kinds present (numba `overload` on geo's type), so a telescoping scene
never compiles the articulated or the tripod leg. Called from Python, the functions test each leg's kind.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.extending import overload

from . import articulated_leg, crush_cell, telescoping_leg, tripod_leg
from .articulated_leg import N_ART, ArticulatedLeg
from .telescoping_leg import TelescopingLeg
from .tripod_leg import TripodLeg

TELESCOPING, ARTICULATED, TRIPOD = 0, 1, 2
MODULES = (telescoping_leg, articulated_leg, tripod_leg)      # by kind


def pack(legs: tuple[TelescopingLeg | ArticulatedLeg | TripodLeg, ...]):
    """(geo, cells) arrays of a set of legs, cell curves padded to a common length (geo without the terrain:
    with_terrain)."""
    n = len(legs)
    n_cell = max(len(leg.cells) for leg in legs)
    n_pad = max([len(leg.pads) for leg in legs if isinstance(leg, TelescopingLeg)] + [1])
    n_pt = max(len(c.curve.deflection) for leg in legs for c in leg.cells)
    angles = np.zeros((n, n_pad, 2))
    cd, cf = np.zeros((n, n_cell, n_pt)), np.zeros((n, n_cell, n_pt))
    cn = np.zeros((n, n_cell), np.int64)
    ck, cc, cy = np.ones((n, n_cell)), np.zeros((n, n_cell)), -np.ones((n, n_cell))
    reach, lever, small = np.zeros(n), np.zeros(n), np.zeros(n, np.int64)
    kind, art, tri = np.zeros(n, np.int64), np.zeros((n, N_ART)), np.zeros((n, 5, 3))
    for i, leg in enumerate(legs):
        if isinstance(leg, TelescopingLeg):
            angles[i, :len(leg.pads), 0] = np.cos(leg.pad_angles)
            angles[i, :len(leg.pads), 1] = np.sin(leg.pad_angles)
            reach[i], lever[i], small[i] = leg.rho, leg.pad_lever, leg.small_angle
        elif isinstance(leg, TripodLeg):
            kind[i], tri[i], reach[i] = TRIPOD, leg.packed, leg.reach
        else:
            kind[i], art[i], reach[i] = ARTICULATED, leg.row, leg.reach
        for j, cell in enumerate(leg.cells):
            d, f, k, c, y = cell.arrays
            cd[i, j, :len(d)], cf[i, j, :len(d)], cn[i, j] = d, f, len(d)
            ck[i, j], cc[i, j], cy[i, j] = k, c, y
    geo = (np.array([leg.attach for leg in legs], float), np.array([leg.to_body for leg in legs], float), reach,
           lever, angles if np.any(kind == TELESCOPING) else None, np.array([len(leg.cells) - 1 for leg in legs],
                                                                             np.int64), small, kind,
           art if np.any(kind == ARTICULATED) else None, tri if np.any(kind == TRIPOD) else None)
    return geo, (cd, cf, cn, ck, cc, cy)


def with_terrain(geo, terrain) -> tuple:
    """geo with the packed terrain (alightsize_sim.terrain.pack) at geo[9], the tripods after it at geo[10]."""
    return (*geo[:9], terrain, *geo[9:])


def initial_shape(legs) -> np.ndarray:
    """(n,3) free shapes at the start: hanging straight, the parallelogram at its initial psi, a tripod's struts
    at their rest lengths."""
    return np.array([leg.rest_lengths if isinstance(leg, TripodLeg) else
                     [0.0, 0.0, leg.psi0 if isinstance(leg, ArticulatedLeg) else 0.0] for leg in legs])


# leg_force's dispatch is inlined at numba IR level (as is footpad_slip.contact_force around it): a call that is
# not inlined passes the ~30 arrays of the packed scene, which cost as much as a telescoping leg's arithmetic.
# Small helpers are left to LLVM's inliner; IR-inlining them inside these bodies multiplied the compile time.
def _present(geo) -> tuple[bool, bool, bool]:
    """Which leg kinds a packed geo's numba type holds (telescoping, articulated, tripod; pack's geo before
    with_terrain holds no tripod at 10)."""
    return tuple(len(geo) > k and not isinstance(geo[k], types.NoneType) for k in (4, 8, 10))


def _pick(geo, mixed, name: str):
    """What compiled code runs for a packed geo's numba type: with one leg kind that kind's function `name`; with
    several, `mixed(functions)` (the per-leg test), each absent kind's function a stub never called."""
    present = _present(geo)
    if sum(present) == 1:
        return getattr(MODULES[present.index(True)], name).py_func
    return mixed(*(getattr(m, name, _STUBS[name]) if p else _STUBS[name] for m, p in zip(MODULES, present)))


@njit(cache=True)
def _stub_leg_force(geo, cells, i, mem, shape, P, kin, out):
    return 0.0, 0.0, 0.0, 0.0


@njit(cache=True)
def _stub_footpad(geo, cells, i, mem, shape, r, R):
    return np.nan, np.nan, np.nan


@njit(cache=True)
def _stub_lift(geo, cells, i, mem, loaded, main, r, R):
    return loaded[0], loaded[1], loaded[2]


@njit(cache=True)
def _stub_slack(geo, cells, i, mem, defl, X, P, R):
    return 0.0


@njit(cache=True)
def _stub_at_set(geo, cells, i, mem, shape):
    return shape[0], shape[1], shape[2]


_STUBS = {"leg_force": _stub_leg_force, "free_footpad": _stub_footpad, "lift_shape": _stub_lift,
          "slack": _stub_slack, "at_set": _stub_at_set}


def _kind(geo, i) -> int:
    return 0 if geo[7][i] == TELESCOPING else 1 if geo[7][i] == ARTICULATED else 2


def leg_force(geo, cells, i, mem, shape, P, kin, out):
    """Forces of leg i with its footpad held at P under a capsule moving as kin = (r, R, v, w), written into
    out = (defl, frc, rte, X) (see the kind's module); returns (cells' power, alpha, beta, psi) (a tripod: its strut
    lengths for the last three)."""
    return MODULES[_kind(geo, i)].leg_force(geo, cells, i, mem, shape, P, kin, out)


def _mixed_leg_force(tel, art, tri):
    def mixed(geo, cells, i, mem, shape, P, kin, out):
        if geo[7][i] == ARTICULATED:
            return art(geo, cells, i, mem, shape, P, kin, out)
        if geo[7][i] == TRIPOD:
            return tri(geo, cells, i, mem, shape, P, kin, out)
        return tel(geo, cells, i, mem, shape, P, kin, out)
    return mixed


@overload(leg_force, inline="always")
def _leg_force(geo, cells, i, mem, shape, P, kin, out):
    return _pick(geo, _mixed_leg_force, "leg_force")


@njit(cache=True, inline="always")
def main_set(cells, i, mem):
    """Permanent set of the leg's main cell (m): short of it the leg is slack and lifts off."""
    return crush_cell.permanent_set(cells[3][i, 0], mem[0, 0], mem[0, 1])


def slack(geo, cells, i, mem, defl, X, P, R):
    """How far leg i is from lifting off (m; it lifts off where this falls through zero): its main cell's
    deflection beyond its set (telescoping, articulated), the ground's normal push over the primary's unloading
    rate (tripod: tripod_leg.slack), from the leg's deflections defl and force X at its footpad P."""
    if geo[7][i] == TRIPOD:
        return tripod_leg.slack(geo, cells, i, mem, defl, X, P, R)
    return defl[0] - main_set(cells, i, mem)


def _main_slack(geo, cells, i, mem, defl, X, P, R):
    return defl[0] - main_set(cells, i, mem)


def _mixed_slack(tel, art, tri):
    def mixed(geo, cells, i, mem, defl, X, P, R):
        if geo[7][i] == TRIPOD:
            return tri(geo, cells, i, mem, defl, X, P, R)
        return defl[0] - main_set(cells, i, mem)
    return mixed


@overload(slack, inline="always")
def _slack(geo, cells, i, mem, defl, X, P, R):
    if not _present(geo)[2]:
        return _main_slack
    return _pick(geo, _mixed_slack, "slack")


def free_footpad(geo, cells, i, mem, shape, r, R):
    """Terrain position (tuple) of a free leg's footpad: its stored geometry."""
    return MODULES[_kind(geo, i)].free_footpad(geo, cells, i, mem, shape, r, R)


def _mixed_footpad(tel, art, tri):
    def mixed(geo, cells, i, mem, shape, r, R):
        if geo[7][i] == ARTICULATED:
            return art(geo, cells, i, mem, shape, r, R)
        if geo[7][i] == TRIPOD:
            return tri(geo, cells, i, mem, shape, r, R)
        return tel(geo, cells, i, mem, shape, r, R)
    return mixed


@overload(free_footpad)
def _free_footpad(geo, cells, i, mem, shape, r, R):
    return _pick(geo, _mixed_footpad, "free_footpad")


def at_set(geo, cells, i, mem, shape):
    """A free leg's shape with its main cell at least at its permanent set (see the kind's module)."""
    return MODULES[_kind(geo, i)].at_set(geo, cells, i, mem, shape)


def _mixed_at_set(tel, art, tri):
    def mixed(geo, cells, i, mem, shape):
        if geo[7][i] == ARTICULATED:
            return art(geo, cells, i, mem, shape)
        if geo[7][i] == TRIPOD:
            return tri(geo, cells, i, mem, shape)
        return tel(geo, cells, i, mem, shape)
    return mixed


@overload(at_set)
def _at_set(geo, cells, i, mem, shape):
    return _pick(geo, _mixed_at_set, "at_set")


def lift_shape(geo, cells, i, mem, loaded, main, r, R):
    """Stored free geometry of a leg lifting off with the shape leg_force gave, loaded = (alpha, beta, psi), and
    main-cell deflection `main` (see the kind's module)."""
    return MODULES[_kind(geo, i)].lift_shape(geo, cells, i, mem, loaded, main, r, R)


def _mixed_lift(tel, art, tri):
    def mixed(geo, cells, i, mem, loaded, main, r, R):
        if geo[7][i] == ARTICULATED:
            return art(geo, cells, i, mem, loaded, main, r, R)
        if geo[7][i] == TRIPOD:
            return tri(geo, cells, i, mem, loaded, main, r, R)
        return tel(geo, cells, i, mem, loaded, main, r, R)
    return mixed


@overload(lift_shape)
def _lift_shape(geo, cells, i, mem, loaded, main, r, R):
    return _pick(geo, _mixed_lift, "lift_shape")


def member_strike(geo, contact, shape, r, R):
    """Index of an articulated leg on the ground whose fulcrum ring is below the terrain, or -1."""
    for i in range(len(contact)):
        if contact[i] and geo[7][i] == ARTICULATED and articulated_leg.ring_clearance(geo, i, shape[i, 2], r, R) < 0.0:
            return i
    return -1


@overload(member_strike)
def _member_strike(geo, contact, shape, r, R):
    if isinstance(geo[8], types.NoneType):                 # no articulated leg: no member can strike
        return lambda geo, contact, shape, r, R: -1
    return member_strike


def folded(geo, contact, P, r, R):
    """Index of a tripod leg on the ground whose struts fold flat at its joint (|u . (e1 x e2)| below
    tripod_leg.MIN_DET with its footpad at P), or -1."""
    for i in range(len(contact)):
        if contact[i] and geo[7][i] == TRIPOD and tripod_leg.fold(geo, i, P[i], r, R) < tripod_leg.MIN_DET:
            return i
    return -1


@overload(folded)
def _folded(geo, contact, P, r, R):
    if not _present(geo)[2]:                               # no tripod: none can fold
        return lambda geo, contact, P, r, R: -1
    return folded
