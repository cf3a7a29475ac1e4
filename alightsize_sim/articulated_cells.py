"""Articulated-leg crush cells: deflections, lines of action and lever arms (AFFDL-TR-66-33 Sec. V.F.2-3).

The upper (parallelogram, psi) cell runs from the inboard point (AA, AB) to the outboard point offset
(AH, AG) from the upper outboard pivot; it lengthens as psi rises. The lower (peg-leg, alpha) cell runs
along the peg-leg axis from AP above the ring plane to AQ below it; it lengthens as the peg leg tilts
about the ring edge. Positive deflection crushes a cell. numpy-vectorized, SI units, radians.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .articulated_kinematics import ArticulatedGeometry


@njit(cache=True)
def upper_cell_vector(g: ArticulatedGeometry, psi):
    """(St1, St3), the upper cell from its inboard to its outboard end (eq. 45)."""
    return (g.AU * np.cos(psi) - g.AD * np.sin(g.PHI) - g.AA - g.AH,
            g.AU * np.sin(psi) + g.AD * np.cos(g.PHI) - g.AB - g.AG)


@njit(cache=True)
def upper_length(g: ArticulatedGeometry, psi):
    """|St| (eq. 46); its value at the initial psi is the undeflected length RHO."""
    s1, s3 = upper_cell_vector(g, psi)
    return np.hypot(s1, s3)


@njit(cache=True)
def upper_deflection(g: ArticulatedGeometry, psi, psi0):
    """Delta_1 = |St(psi)| - |St(psi0)| (eq. 46)."""
    return upper_length(g, psi) - upper_length(g, psi0)


@njit(cache=True)
def upper_angle(g: ArticulatedGeometry, psi):
    """eta (the report's gamma), the upper cell's angle from S1 (eq. 49)."""
    s1, s3 = upper_cell_vector(g, psi)
    return np.arctan2(s3, s1)


@njit(cache=True)
def upper_lever(g: ArticulatedGeometry, psi):
    """d Delta_1 / d psi / AU = sin(eta - psi): the upper cell force per unit cell force, normal to the
    links at the outboard pivot (FORCE, KONFIG = 1: C25 = SE * AF(1))."""
    return np.sin(upper_angle(g, psi) - psi)


@njit(cache=True)
def lower_cell_vector(g: ArticulatedGeometry, alpha):
    """(h, v): horizontal reach along beta and vertical component of Sp (eq. 47)."""
    return (g.AS - g.AS * np.cos(alpha) + g.AQ * np.sin(alpha),
            -g.AP - g.AS * np.sin(alpha) - g.AQ * np.cos(alpha))


@njit(cache=True)
def lower_deflection(g: ArticulatedGeometry, alpha):
    """Delta_2 = |Sp| - (AP + AQ) (eq. 48)."""
    h, v = lower_cell_vector(g, alpha)
    return np.hypot(h, v) - (g.AP + g.AQ)


def lower_force_components(g: ArticulatedGeometry, alpha, beta, af2):
    """(AF21, AF22, AF23), the lower cell force on the peg leg in S axes (eq. 50-52)."""
    h, v = lower_cell_vector(g, alpha)
    k = af2 / np.hypot(h, v)
    return -h * np.cos(beta) * k, -h * np.sin(beta) * k, -v * k


@njit(cache=True)
def lower_lever(g: ArticulatedGeometry, alpha):
    """d Delta_2 / d alpha: the lower cell's moment arm about the ring edge (FORCE: FP4 / AF(2))."""
    sa, ca = np.sin(alpha), np.cos(alpha)
    c16 = g.AS * ca - g.AQ * sa
    c30 = g.AS * sa + g.AQ * ca
    h, v = lower_cell_vector(g, alpha)
    return (c16 * g.AP + c30 * g.AS) / np.hypot(h, v)


@njit(cache=True)
def return_spring_force(g: ArticulatedGeometry, delta2):
    """The light peg-leg return spring at lower-cell deflection delta2, SPRG * Delta_2 + PLD, added to the
    lower cell force (FORCE)."""
    return g.SPRG * delta2 + g.PLD
