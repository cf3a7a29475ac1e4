"""Legs of any kind behind one interface for the step loop: telescoping (Sec. V.E) or articulated (Sec. V.F).

`pack` turns a tuple of legs into the arrays the compiled functions take:
geo = (attach (n,3), to_body (n,3,3), reach (n,), pad_lever (n,), pad angle cosines and sines (n,P,2),
extra cells (n,), small_angle (n,), kind (n,), articulated rows (n, N_ART)) and
cells = (deflections (n,C,K), forces (n,C,K), n_points (n,C), k, c, yield force or -1 (n,C)).
Cell 0 is the leg's main cell (telescoping axial, articulated upper): the leg lifts off when it goes slack.
A leg's shape (n,3) is its (alpha, beta, psi) at the last accepted step on the ground and the stored free
geometry off it (psi unused by telescoping legs).

A set of legs of one kind packs the other kind's arrays (pad angles, articulated rows) as None: compiled
code then takes that kind's functions alone (numba `overload` on geo's type), so a telescoping scene never
compiles the articulated leg and vice versa. Called from Python, the functions test each leg's kind.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.extending import overload

from . import articulated_leg, crush_cell, telescoping_leg
from .articulated_leg import N_ART, ArticulatedLeg
from .telescoping_leg import TelescopingLeg

TELESCOPING, ARTICULATED = 0, 1


def pack(legs: tuple[TelescopingLeg | ArticulatedLeg, ...]):
    """(geo, cells) arrays of a set of legs, cell curves padded to a common length."""
    n = len(legs)
    n_cell = max(len(leg.cells) for leg in legs)
    n_pad = max([len(leg.pads) for leg in legs if isinstance(leg, TelescopingLeg)] + [1])
    n_pt = max(len(c.curve.deflection) for leg in legs for c in leg.cells)
    angles = np.zeros((n, n_pad, 2))
    cd, cf = np.zeros((n, n_cell, n_pt)), np.zeros((n, n_cell, n_pt))
    cn = np.zeros((n, n_cell), np.int64)
    ck, cc, cy = np.ones((n, n_cell)), np.zeros((n, n_cell)), -np.ones((n, n_cell))
    reach, lever, small = np.zeros(n), np.zeros(n), np.zeros(n, np.int64)
    kind, art = np.zeros(n, np.int64), np.zeros((n, N_ART))
    for i, leg in enumerate(legs):
        if isinstance(leg, TelescopingLeg):
            angles[i, :len(leg.pads), 0] = np.cos(leg.pad_angles)
            angles[i, :len(leg.pads), 1] = np.sin(leg.pad_angles)
            reach[i], lever[i], small[i] = leg.rho, leg.pad_lever, leg.small_angle
        else:
            kind[i], art[i], reach[i] = ARTICULATED, leg.row, leg.reach
        for j, cell in enumerate(leg.cells):
            d, f, k, c, y = cell.arrays
            cd[i, j, :len(d)], cf[i, j, :len(d)], cn[i, j] = d, f, len(d)
            ck[i, j], cc[i, j], cy[i, j] = k, c, y
    geo = (np.array([leg.attach for leg in legs], float), np.array([leg.to_body for leg in legs], float), reach,
           lever, angles if np.any(kind == TELESCOPING) else None, np.array([len(leg.cells) - 1 for leg in legs],
                                                                             np.int64), small, kind,
           art if np.any(kind == ARTICULATED) else None)
    return geo, (cd, cf, cn, ck, cc, cy)


def initial_shape(legs) -> np.ndarray:
    """(n,3) free shapes at the start: hanging straight, the parallelogram at its initial psi."""
    return np.array([[0.0, 0.0, leg.psi0 if isinstance(leg, ArticulatedLeg) else 0.0] for leg in legs])


# leg_force's dispatch is inlined at numba IR level (as is footpad_slip.contact_force around it): a call that is
# not inlined passes the ~30 arrays of the packed scene, which cost as much as a telescoping leg's arithmetic.
# Small helpers are left to LLVM's inliner; IR-inlining them inside these bodies multiplied the compile time.
def _pick(geo, mixed, name: str):
    """What compiled code runs for a packed geo's numba type: `mixed` (the per-leg test) when it holds both leg
    kinds, else the one kind's function `name` (the other kind's arrays are None)."""
    tel, art = not isinstance(geo[4], types.NoneType), not isinstance(geo[8], types.NoneType)
    if tel and art:
        return mixed
    return getattr(articulated_leg if art else telescoping_leg, name).py_func


def leg_force(geo, cells, i, mem, shape, P, r, R, v, w, defl, frc, rte, X):
    """Forces of leg i with its footpad held at P (see the kind's module); returns (cells' power, alpha, beta,
    psi)."""
    if geo[7][i] == ARTICULATED:
        return articulated_leg.leg_force(geo, cells, i, mem, shape, P, r, R, v, w, defl, frc, rte, X)
    return telescoping_leg.leg_force(geo, cells, i, mem, shape, P, r, R, v, w, defl, frc, rte, X)


@overload(leg_force, inline="always")
def _leg_force(geo, cells, i, mem, shape, P, r, R, v, w, defl, frc, rte, X):
    return _pick(geo, leg_force, "leg_force")


@njit(cache=True, inline="always")
def main_set(cells, i, mem):
    """Permanent set of the leg's main cell (m): short of it the leg is slack and lifts off."""
    return crush_cell.permanent_set(cells[3][i, 0], mem[0, 0], mem[0, 1])


def free_footpad(geo, cells, i, mem, shape, r, R):
    """Terrain position (tuple) of a free leg's footpad: its stored geometry."""
    if geo[7][i] == ARTICULATED:
        return articulated_leg.free_footpad(geo, cells, i, mem, shape, r, R)
    return telescoping_leg.free_footpad(geo, cells, i, mem, shape, r, R)


@overload(free_footpad)
def _free_footpad(geo, cells, i, mem, shape, r, R):
    return _pick(geo, free_footpad, "free_footpad")


def at_set(geo, cells, i, mem, shape):
    """A free leg's shape with its main cell at least at its permanent set (see the kind's module)."""
    if geo[7][i] == ARTICULATED:
        return articulated_leg.at_set(geo, cells, i, mem, shape)
    return telescoping_leg.at_set(geo, cells, i, mem, shape)


@overload(at_set)
def _at_set(geo, cells, i, mem, shape):
    return _pick(geo, at_set, "at_set")


def lift_shape(geo, cells, i, mem, alpha, beta, psi, main, r, R):
    """Stored free geometry of a leg lifting off with the given shape and main-cell deflection (see the kind's
    module)."""
    if geo[7][i] == ARTICULATED:
        return articulated_leg.lift_shape(geo, cells, i, mem, alpha, beta, psi, main, r, R)
    return telescoping_leg.lift_shape(geo, cells, i, mem, alpha, beta, psi, main, r, R)


@overload(lift_shape)
def _lift_shape(geo, cells, i, mem, alpha, beta, psi, main, r, R):
    return _pick(geo, lift_shape, "lift_shape")


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
