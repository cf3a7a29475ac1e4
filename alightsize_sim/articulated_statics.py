"""Quasi-static equilibrium of the articulated leg and its member loads (AFFDL-TR-66-33 eq. 53-61, 96-106).

With the leg's inertia neglected, the cell forces AF1 (upper) and AF2 (lower, return spring included)
fix the ground reaction F at the peg-leg tip and the internal reactions: Q1, Q2 along the lower and
upper parallelogram links (positive pushing the intermediate member outward), R11, R12, R13 at the
fulcrum ring, RA, RB lateral at the upper and lower outboard pivots. Two routes give the same numbers:
the 6x6 system of eq. 96 (solved per position) and the closed form of eq. 59-61 as subroutine FORCE
codes it, followed by back substitution. numpy-vectorized over any broadcastable (alpha, beta, psi).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .articulated_cells import lower_force_components, lower_lever, upper_angle
from .articulated_kinematics import ArticulatedGeometry

UNKNOWNS = ("F1", "F3", "Q2", "Q1", "R11", "R12")     # order of eq. 96


@dataclass(frozen=True)
class Reactions:
    """Ground force F (on the peg leg, S axes) and internal reactions, N; arrays of one shape."""

    F1: np.ndarray
    F2: np.ndarray
    F3: np.ndarray
    Q1: np.ndarray
    Q2: np.ndarray
    R11: np.ndarray
    R12: np.ndarray
    R13: np.ndarray
    RA: np.ndarray
    RB: np.ndarray


@dataclass(frozen=True)
class _Terms:
    sa: np.ndarray
    ca: np.ndarray
    sb: np.ndarray
    cb: np.ndarray
    sp: np.ndarray
    cp: np.ndarray
    se: np.ndarray        # sin(eta)
    ce: np.ndarray
    af1: np.ndarray
    af21: np.ndarray
    af22: np.ndarray
    af23: np.ndarray
    fp4: np.ndarray       # lower cell moment about the ring edge (FORCE)


def _terms(g: ArticulatedGeometry, alpha, beta, psi, af1, af2) -> _Terms:
    alpha, beta, psi, af1, af2 = (np.array(x) for x in   # own copies: compiled code takes no broadcast views
                                  np.broadcast_arrays(*(np.asarray(x, float) for x in (alpha, beta, psi, af1, af2))))
    eta = upper_angle(g, psi)
    af21, af22, af23 = lower_force_components(g, alpha, beta, af2)
    return _Terms(np.sin(alpha), np.cos(alpha), np.sin(beta), np.cos(beta), np.sin(psi), np.cos(psi),
                  np.sin(eta), np.cos(eta), af1, af21, af22, af23, lower_lever(g, alpha) * af2)


def _k10(g: ArticulatedGeometry, t: _Terms):
    """Right side of the intermediate member's moment equation (eq. 58, K10 of eq. 96)."""
    arm = t.ce * (g.AD * np.cos(g.PHI) - g.AG) + t.se * (g.AD * np.sin(g.PHI) + g.AH)
    return (g.AE - g.AP) * t.af21 + g.AO * t.af23 - arm * t.af1


def equilibrium_system(g: ArticulatedGeometry, alpha, beta, psi, af1, af2):
    """(K, k): the matrix and right side of eq. 96, shapes (..., 6, 6) and (..., 6), unknowns UNKNOWNS.

    Rows: eq. 56, 57, 58 (intermediate member: vertical, horizontal, moment about the lower outboard
    pivot), eq. 53, 54 (peg-leg forces), eq. 55 (peg-leg moment about the ring edge, times cos beta).
    """
    t = _terms(g, alpha, beta, psi, af1, af2)
    z, one = np.zeros_like(t.sa), np.ones_like(t.sa)
    k3 = -g.AD * (t.cp * np.cos(g.PHI) + t.sp * np.sin(g.PHI))
    k4 = g.AS * t.cb + g.AO
    k5 = g.AS * t.sa + g.AL * t.ca
    k6 = (g.AL * t.sa - g.AS * t.ca) * t.cb
    K = np.stack([np.stack(r, -1) for r in (
        (z, z, t.sp, t.sp, one, z),
        (z, z, t.cp, t.cp, z, -one),
        (z, z, k3, z, k4, -g.AE * one),
        (one, z, z, z, z, one),
        (z, one, z, z, -one, z),
        (k5, k6, z, z, z, z))], -2)
    k13 = -(g.AS * t.sa + g.AQ * t.ca) * t.af21 - (g.AQ * t.sa - g.AS * t.ca) * t.cb * t.af23
    k = np.stack((t.se * t.af1 + t.af23, t.ce * t.af1 + t.af21, _k10(g, t), -t.af21, -t.af23, k13), -1)
    return K, k


def ground_force(g: ArticulatedGeometry, alpha, beta, psi, af1, af2):
    """(F1, F2, F3), the ground force on the peg leg (closed form eq. 59-61 as coded in FORCE)."""
    return _ground(g, _terms(g, alpha, beta, psi, af1, af2))


def _ground(g: ArticulatedGeometry, t: _Terms):
    return ground_components(g, (t.sa, t.ca, t.sb, t.cb, t.sp, t.cp), (t.se * t.cp - t.ce * t.sp) * t.af1, t.fp4)


@njit(cache=True)
def ground_components(g: ArticulatedGeometry, trig, c25, fp4):
    """(F1, F2, F3) at the sines and cosines trig = (sin alpha, cos alpha, sin beta, cos beta, sin psi, cos psi),
    from the upper cell's force normal to the links, C25 = sin(eta - psi) AF1, and the lower cell's moment about
    the ring edge FP4 (eq. 59-61 as FORCE codes them; scalars or arrays). They are the virtual-work equilibrium
    F . d(tip)/dq = generalized cell force for q = psi, alpha, beta."""
    sa, ca, sb, cb, sp, cp = trig
    c18 = g.AS * sa + g.AL * ca
    c20 = g.AL * sa - g.AS * ca
    c17 = 1.0 / (sp * cb * c20 + cp * c18)
    f1 = (cp * fp4 - c20 * c25) * cb * c17
    f3 = (sp * fp4 * cb + c18 * c25) * c17
    f2 = (fp4 - c20 * f3) * sb / c18
    return f1, f2, f3


def _lateral(g: ArticulatedGeometry, t: _Terms, f2, r11):
    """R13 (eq. 98), RA (eq. 99), RB (eq. 100)."""
    r13 = -f2 - t.af22
    ra = ((g.AP - g.AE) * t.af22 + g.AS * t.sb * r11 - g.AE * r13) / (g.AD * np.cos(g.PHI))
    return r13, ra, -ra + t.af22 + r13


def reactions(g: ArticulatedGeometry, alpha, beta, psi, af1, af2, method: str = "closed") -> Reactions:
    """All reactions at the given positions and cell forces.

    method "closed": eq. 59-61 then back substitution through eq. 53, 54, 56-58 (fast, vectorized);
    method "matrix": the 6x6 system of eq. 96-97 solved position by position (the cross-check).
    """
    t = _terms(g, alpha, beta, psi, af1, af2)
    f1, f2, f3 = _ground(g, t)
    if method == "matrix":
        K, k = equilibrium_system(g, alpha, beta, psi, af1, af2)
        x = np.linalg.solve(K, k[..., None])[..., 0]
        f1, f3, q2, q1, r11, r12 = (x[..., i] for i in range(6))
        c18 = g.AS * t.sa + g.AL * t.ca
        f2 = (t.fp4 - (g.AL * t.sa - g.AS * t.ca) * f3) * t.sb / c18        # eq. 61
    elif method == "closed":
        r12 = -t.af21 - f1                                                  # eq. 53
        r11 = f3 + t.af23                                                   # eq. 54
        total = t.sp * (t.se * t.af1 + t.af23 - r11) + t.cp * (t.ce * t.af1 + t.af21 + r12)  # eq. 56, 57
        k3 = -g.AD * (t.cp * np.cos(g.PHI) + t.sp * np.sin(g.PHI))
        q2 = (_k10(g, t) - (g.AS * t.cb + g.AO) * r11 + g.AE * r12) / k3   # eq. 58
        q1 = total - q2
    else:
        raise ValueError(f"method must be 'closed' or 'matrix', not {method!r}")
    r13, ra, rb = _lateral(g, t, f2, r11)
    return Reactions(f1, f2, f3, q1, q2, r11, r12, r13, ra, rb)


def residuals(g: ArticulatedGeometry, alpha, beta, psi, af1, af2, r: Reactions):
    """Eq. 96 residuals K x - k of a solution, shape (..., 6)."""
    K, k = equilibrium_system(g, alpha, beta, psi, af1, af2)
    x = np.stack([r.F1, r.F3, r.Q2, r.Q1, r.R11, r.R12], -1)
    return (K @ x[..., None])[..., 0] - k


@dataclass(frozen=True)
class TrussAngles:
    """Member angles (rad) of the parallelogram trusses: theta of the upper triangle (Fig. 104), gamma
    and rho of the lower assembly (Fig. 105)."""

    theta: float
    gamma: float
    rho: float


MEMBERS = ("PL1", "PL2", "PU1", "RA", "RB", "Q1", "Q2", "R1213", "R11", "R123", "F")


def member_loads(r: Reactions, truss: TrussAngles) -> dict[str, np.ndarray]:
    """Member loads of Tables 14-22 (eq. 101-106; tension positive for PU, PL). PU2, PL3 and PL6 are the
    mirror images of PU1, PL1 and PL2 (RA, RB reversed) and share their envelopes. F: the ground force's magnitude
    |F| at the footpad, the resultant of the leg's attachment forces on the body (its outrigger's load)."""
    st, ct = np.sin(truss.theta), np.cos(truss.theta)
    sg, cg = np.sin(truss.gamma), np.cos(truss.gamma)
    sr, cr = np.sin(truss.rho), np.cos(truss.rho)
    d = 2.0 * np.sin(truss.gamma + truss.rho)
    return {
        "PL1": (-r.Q1 * sg + r.RB * cg) / d,                                # eq. 103
        "PL2": (-r.Q1 * sr + r.RB * cr) / d,                                # eq. 105
        "PU1": (-r.Q2 * st + r.RA * ct) / (2.0 * st * ct),                  # eq. 101
        "RA": r.RA,
        "RB": r.RB,
        "Q1": r.Q1,
        "Q2": r.Q2,
        "R1213": np.hypot(r.R12, r.R13),
        "R11": r.R11,
        "R123": np.sqrt(r.R11 ** 2 + r.R12 ** 2 + r.R13 ** 2),
        "F": np.sqrt(r.F1 ** 2 + r.F2 ** 2 + r.F3 ** 2),
    }
