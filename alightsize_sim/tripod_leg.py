"""Tripod legs: a footpad held by a primary strut and two secondary struts (geometry, kinematics, statics).

Two layouts (body principal axes, m; 3 along the capsule axis, up):

- **inverted tripod** (`secondary_attach` = 0, Viking): the three struts meet at the footpad;
- **cantilever** (0 < `secondary_attach` < 1, Apollo LM): the secondaries brace the primary at a knee a fraction
  s of its rest length up from the footpad; the primary below the knee carries bending.

The primary holds a compression-only crushable cartridge; each secondary one cartridge crushed in compression
and one in tension (the LM's struts held aluminium honeycomb cartridges: NASA TN D-6850, Rogers 1972). In
the cantilever the primary strokes below the knee (the LM's inner cylinder slides into the outer one, which the
secondaries brace: our reading of Rogers 1972), so the hardpoint-knee distance a = (1 - s) L0 is fixed and the
overhang Lp - a shrinks as the primary strokes.

Assumptions (valid for quasi-static loads on a massless leg): ball joints at the hardpoints, the knee and the
footpad (no moment enters or leaves there); the secondaries are two-force members (Hibbeler, Statics, sec. 6.5,
space trusses); the primary is a rigid beam pinned at its hardpoint (free to spin about its own axis, so it
carries no torsion); small deflections of the members themselves (equilibrium on the current geometry, the
struts' lengths changing only through their cartridges). Strut forces are tension positive, lengths L =
(primary Lp, secondary l1, l2), the footpad P. Virtual work closes: F . dP = sum T_i dL_i (Hibbeler, Statics,
sec. 11.2), so the strut forces are T = G^-T F with G = dL/dP, and the footpad force of given strut forces is
G^T T. The kinematics are scalar, allocation-free compiled functions on the leg's packed array (`packed`: the
hardpoints, the rest lengths, and knee offset, secondary_attach, branch), which the simulator's leg functions
below call too (the leg's row of geo[10], docs/simulator.md); the numpy functions here wrap them.

In the simulator the leg is massless with its footpad held at P (the slip search or the footpad's state places
it): the strut lengths follow from P in closed form, the five cell deflections and rates from them and G, and the
force on the capsule is X = G^T T, whose power X . (footpad velocity relative to the body) equals the cells'
power exactly (virtual work), so the energy audit closes with no extra term. The leg's shape is its three strut
lengths (on the ground those of the last accepted step; in the air those it left with: a free leg whose struts
sit between their compression and tension sets is a mechanism, and keeps them). It lifts off where the ground's
normal push falls to zero (`slack`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numba import njit

from .crush_cell import CellModel, permanent_set
from .telescoping_leg import cell_force
from .terrain import bearing_normal
from .vec3 import cross, mtv, mv

MIN_DET = 0.02   # least |u . (e1 x e2)| of the strut directions at the joint (1 when orthogonal, 0 when coplanar)


def _unit(v: np.ndarray) -> tuple[np.ndarray, float]:
    n = float(np.linalg.norm(v))
    return v / n, n


def _point(name: str, value, shape=(3,)) -> np.ndarray:
    a = np.array(value, float)
    if a.shape != shape or not np.all(np.isfinite(a)):
        raise ValueError(f"{name}: expected finite coordinates of shape {shape} (m), got {value!r}")
    return a


@dataclass(frozen=True)
class TripodLeg:
    """A primary hardpoint, two secondary hardpoints (rows of a (2, 3) array) and the footpad at rest (m,
    principal axes); `secondary_attach` s (0: inverted tripod, 0 < s < 1: cantilever knee at s of the primary's
    rest length up from the footpad); the primary cartridge (compression only), each secondary's compression
    and tension cartridges; the footpad's diameter (m) and mass (kg, 0 for the massless limit)."""

    primary_hardpoint: np.ndarray
    secondary_hardpoints: np.ndarray
    footpad: np.ndarray
    secondary_attach: float
    primary: CellModel
    secondary_compression: tuple[CellModel, CellModel]
    secondary_tension: tuple[CellModel, CellModel]
    footpad_diameter: float
    footpad_mass: float = 0.0

    def __post_init__(self):
        set_ = object.__setattr__
        set_(self, "primary_hardpoint", _point("primary_hardpoint", self.primary_hardpoint))
        set_(self, "secondary_hardpoints", _point("secondary_hardpoints", self.secondary_hardpoints, (2, 3)))
        set_(self, "footpad", _point("footpad", self.footpad))
        s = self.secondary_attach
        if not 0.0 <= s < 1.0:
            raise ValueError(f"secondary_attach: expected 0 (inverted tripod) or a fraction in (0, 1) of the "
                             f"primary up from the footpad (cantilever knee), got {s!r}")
        if len(self.secondary_compression) != 2 or len(self.secondary_tension) != 2:
            raise ValueError("secondary_compression, secondary_tension: expected one cell per secondary strut (two)")
        if not self.footpad_diameter > 0:
            raise ValueError(f"footpad_diameter: expected > 0 m, got {self.footpad_diameter!r}")
        if not self.footpad_mass >= 0:
            raise ValueError(f"footpad_mass: expected >= 0 kg (0: massless), got {self.footpad_mass!r}")
        if not self.rest_primary_length > 0:
            raise ValueError("footpad: coincides with primary_hardpoint (a primary strut of zero length)")
        joint = "knee" if self.is_cantilever else "footpad"
        for i in range(2):
            if not self.rest_lengths[i + 1] > 0:
                raise ValueError(f"secondary_hardpoints[{i}]: coincides with the {joint} (a strut of zero length)")
        det = _triple(self, self.footpad)
        if abs(det) < MIN_DET:
            raise ValueError(f"secondary_hardpoints: the struts meet the {joint} nearly coplanar (|u . (e1 x e2)| = "
                             f"{abs(det):.3g} < {MIN_DET}): the leg would have no stiffness across their plane")
        if self.is_cantilever and self.primary.curve.deflection[-1] >= s * self.rest_primary_length:
            raise ValueError(f"primary: its curve runs to {self.primary.curve.deflection[-1]:.4g} m of stroke, at or "
                             f"past the knee ({s * self.rest_primary_length:.4g} m up from the footpad)")

    @property
    def attach(self) -> np.ndarray:
        """The primary hardpoint: where the leg stands round the capsule (its azimuth orders the legs)."""
        return self.primary_hardpoint

    @property
    def to_body(self) -> np.ndarray:
        """Leg axes to principal axes: a tripod's leg axes are the principal axes."""
        return np.eye(3)

    @property
    def reach(self) -> float:
        """A length scale of the leg (m): its primary's rest length."""
        return self.rest_primary_length

    @property
    def is_cantilever(self) -> bool:
        return self.secondary_attach > 0.0

    @property
    def hardpoints(self) -> np.ndarray:
        """(3, 3): primary, secondary 1, secondary 2 hardpoints."""
        return np.vstack((self.primary_hardpoint, self.secondary_hardpoints))

    @cached_property
    def rest_primary_length(self) -> float:
        return float(np.linalg.norm(self.footpad - self.primary_hardpoint))

    @property
    def knee_offset(self) -> float:
        """Hardpoint-to-knee distance a = (1 - s) L0 (m); the whole primary for an inverted tripod."""
        return (1.0 - self.secondary_attach) * self.rest_primary_length

    @cached_property
    def rest_lengths(self) -> np.ndarray:
        """Strut lengths at rest (Lp, l1, l2), m."""
        return self.packed[3].copy()

    @cached_property
    def branch(self) -> float:
        """+1 or -1: the side of the hardpoints' plane (normal (A1 - Ap) x (A2 - Ap)) the joint lies on at rest;
        the kinematics keep it (the branch below the body)."""
        return float(self.packed[4, 2])

    @property
    def cells(self) -> tuple[CellModel, ...]:
        """The five cells in `cell_deflections` order: primary, then each secondary's compression and tension."""
        c, t = self.secondary_compression, self.secondary_tension
        return (self.primary, c[0], t[0], c[1], t[1])

    @cached_property
    def packed(self) -> np.ndarray:
        """(5, 3): the hardpoints (primary, secondaries), the rest lengths (Lp, l1, l2) and (knee offset a,
        secondary_attach, branch): what the compiled kinematics take."""
        t = np.zeros((5, 3))
        t[:3] = self.hardpoints
        t[4, 0], t[4, 1] = self.knee_offset, self.secondary_attach
        t[3] = strut_lengths_at(t, *self.footpad)
        t[4, 2] = trilateration_side(t, *junction_at(t, *self.footpad))
        return t


def _triple(leg: TripodLeg, P: np.ndarray) -> float:
    """u . (e1 x e2): the primary's and the secondaries' unit vectors at the joint (0 when coplanar)."""
    return fold_at(leg.packed, *np.asarray(P, float))


@njit(cache=True)
def _unit3(x0, x1, x2):
    """(unit vector, length) of x; the zero vector for a zero x."""
    n = np.sqrt(x0 * x0 + x1 * x1 + x2 * x2)
    if n == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    return x0 / n, x1 / n, x2 / n, n


@njit(cache=True)
def junction_at(t, p0, p1, p2):
    """The joint (tuple) for the footpad at (p0, p1, p2), leg packed as t (`TripodLeg.packed`): the footpad
    itself (inverted tripod, t[4, 1] = 0) or the knee, a = t[4, 0] from the primary hardpoint along the primary."""
    if t[4, 1] <= 0.0:
        return p0, p1, p2
    u0, u1, u2, _ = _unit3(p0 - t[0, 0], p1 - t[0, 1], p2 - t[0, 2])
    a = t[4, 0]
    return t[0, 0] + a * u0, t[0, 1] + a * u1, t[0, 2] + a * u2


@njit(cache=True)
def strut_lengths_at(t, p0, p1, p2):
    """Inverse kinematics (Lp, l1, l2) for the footpad at (p0, p1, p2)."""
    j0, j1, j2 = junction_at(t, p0, p1, p2)
    return (_unit3(p0 - t[0, 0], p1 - t[0, 1], p2 - t[0, 2])[3], _unit3(j0 - t[1, 0], j1 - t[1, 1], j2 - t[1, 2])[3],
            _unit3(j0 - t[2, 0], j1 - t[2, 1], j2 - t[2, 2])[3])


@njit(cache=True)
def length_jacobian_at(t, p0, p1, p2):
    """G = dL/dP at the footpad (p0, p1, p2), row by row as a 9-tuple. Inverted tripod: the unit strut vectors
    u, e1, e2 (hardpoint to footpad). Cantilever: dLp/dP = u, dl_i/dP = (a/Lp) (e_i - (e_i . u) u), since the
    knee moves by (a/Lp) (I - u u^T) dP."""
    u0, u1, u2, Lp = _unit3(p0 - t[0, 0], p1 - t[0, 1], p2 - t[0, 2])
    j0, j1, j2 = junction_at(t, p0, p1, p2)
    a0, a1, a2, _ = _unit3(j0 - t[1, 0], j1 - t[1, 1], j2 - t[1, 2])
    b0, b1, b2, _ = _unit3(j0 - t[2, 0], j1 - t[2, 1], j2 - t[2, 2])
    if t[4, 1] <= 0.0:
        return u0, u1, u2, a0, a1, a2, b0, b1, b2
    k = t[4, 0] / Lp
    ca, cb = a0 * u0 + a1 * u1 + a2 * u2, b0 * u0 + b1 * u1 + b2 * u2
    return (u0, u1, u2, k * (a0 - ca * u0), k * (a1 - ca * u1), k * (a2 - ca * u2), k * (b0 - cb * u0),
            k * (b1 - cb * u1), k * (b2 - cb * u2))


@njit(cache=True)
def fold_at(t, p0, p1, p2):
    """u . (e1 x e2) at the joint for the footpad at (p0, p1, p2): 0 when the struts meet there coplanar."""
    u0, u1, u2, _ = _unit3(p0 - t[0, 0], p1 - t[0, 1], p2 - t[0, 2])
    j0, j1, j2 = junction_at(t, p0, p1, p2)
    a0, a1, a2, _ = _unit3(j0 - t[1, 0], j1 - t[1, 1], j2 - t[1, 2])
    b0, b1, b2, _ = _unit3(j0 - t[2, 0], j1 - t[2, 1], j2 - t[2, 2])
    return u0 * (a1 * b2 - a2 * b1) + u1 * (a2 * b0 - a0 * b2) + u2 * (a0 * b1 - a1 * b0)


@njit(cache=True)
def trilateration_side(c, x0, x1, x2):
    """+1 or -1: the side of the plane of the centres c[0:3] (normal (c1 - c0) x (c2 - c0)) the point x lies on
    (0 on it)."""
    n0 = (c[1, 1] - c[0, 1]) * (c[2, 2] - c[0, 2]) - (c[1, 2] - c[0, 2]) * (c[2, 1] - c[0, 1])
    n1 = (c[1, 2] - c[0, 2]) * (c[2, 0] - c[0, 0]) - (c[1, 0] - c[0, 0]) * (c[2, 2] - c[0, 2])
    n2 = (c[1, 0] - c[0, 0]) * (c[2, 1] - c[0, 1]) - (c[1, 1] - c[0, 1]) * (c[2, 0] - c[0, 0])
    return np.sign(n0 * (x0 - c[0, 0]) + n1 * (x1 - c[0, 1]) + n2 * (x2 - c[0, 2]))


@njit(cache=True)
def trilaterate_at(c, r0, r1, r2, branch):
    """The point (tuple) at distances (r0, r1, r2) from the centres c[0:3] on the `branch` side of their plane:
    subtracting the sphere equations pairwise gives its coordinates in the centres' plane, the first equation
    its height. NaN when the spheres do not meet."""
    ex0, ex1, ex2, d = _unit3(c[1, 0] - c[0, 0], c[1, 1] - c[0, 1], c[1, 2] - c[0, 2])
    w0, w1, w2 = c[2, 0] - c[0, 0], c[2, 1] - c[0, 1], c[2, 2] - c[0, 2]
    i = ex0 * w0 + ex1 * w1 + ex2 * w2
    ey0, ey1, ey2, j = _unit3(w0 - i * ex0, w1 - i * ex1, w2 - i * ex2)
    ez0, ez1, ez2 = ex1 * ey2 - ex2 * ey1, ex2 * ey0 - ex0 * ey2, ex0 * ey1 - ex1 * ey0
    x = (r0 * r0 - r1 * r1 + d * d) / (2.0 * d)
    y = (r0 * r0 - r2 * r2 + i * i + j * j - 2.0 * i * x) / (2.0 * j)
    z2 = r0 * r0 - x * x - y * y
    if z2 < 0.0:
        return np.nan, np.nan, np.nan
    z = branch * np.sqrt(z2)
    return (c[0, 0] + x * ex0 + y * ey0 + z * ez0, c[0, 1] + x * ex1 + y * ey1 + z * ez1,
            c[0, 2] + x * ex2 + y * ey2 + z * ez2)


@njit(cache=True)
def footpad_at(t, Lp, l1, l2):
    """Forward kinematics (tuple): the footpad for strut lengths (Lp, l1, l2), NaN where none (the spheres do
    not meet, or a cantilever primary at or above its knee). The joint is the intersection of the spheres about
    the hardpoints, radii (Lp or a, l1, l2), on the rest branch; the cantilever's footpad is then Lp along the
    primary through the knee."""
    cant = t[4, 1] > 0.0
    a = t[4, 0]
    j0, j1, j2 = trilaterate_at(t, a if cant else Lp, l1, l2, t[4, 2])
    if not cant:
        return j0, j1, j2
    if not Lp > a:
        return np.nan, np.nan, np.nan
    k = Lp / a
    return t[0, 0] + k * (j0 - t[0, 0]), t[0, 1] + k * (j1 - t[0, 1]), t[0, 2] + k * (j2 - t[0, 2])


def junction(leg: TripodLeg, P) -> np.ndarray:
    """Where the secondaries meet the primary for the footpad at P: the footpad itself (inverted tripod) or the
    knee, a = (1 - s) L0 from the hardpoint along the primary (cantilever)."""
    return np.array(junction_at(leg.packed, *np.asarray(P, float)))


def strut_lengths(leg: TripodLeg, P) -> np.ndarray:
    """Inverse kinematics: (Lp, l1, l2) for the footpad at P (m)."""
    return np.array(strut_lengths_at(leg.packed, *np.asarray(P, float)))


def footpad_position(leg: TripodLeg, lengths) -> np.ndarray:
    """Forward kinematics: the footpad for strut lengths (Lp, l1, l2) (footpad_at)."""
    L = np.asarray(lengths, float)
    P = np.array(footpad_at(leg.packed, L[0], L[1], L[2]))
    if not np.all(np.isfinite(P)):
        if leg.is_cantilever and not L[0] > leg.knee_offset:
            raise ValueError(f"primary length {L[0]:.6g} m: at or above the knee ({leg.knee_offset:.6g} m from the "
                             "hardpoint)")
        raise ValueError(f"strut lengths {tuple(L)} m do not meet: no position of the joint")
    return P


def length_jacobian(leg: TripodLeg, P) -> np.ndarray:
    """G = dL/dP (3 x 3) at the footpad P (length_jacobian_at)."""
    return np.array(length_jacobian_at(leg.packed, *np.asarray(P, float))).reshape(3, 3)


def footpad_jacobian(leg: TripodLeg, lengths) -> np.ndarray:
    """d(footpad)/d(Lp, l1, l2) (3 x 3) = G^-1 at the footpad those lengths give."""
    return np.linalg.inv(length_jacobian(leg, footpad_position(leg, lengths)))


@dataclass(frozen=True)
class StrutForces:
    """Strut forces (N, tension positive) for a force at the footpad: the primary's cartridge (the primary below
    the knee), the secondaries, the primary between its hardpoint and the knee (the cartridge's force for an
    inverted tripod); the bending moment in the primary at the knee (N m, 0 for an inverted tripod); and the
    force of the leg on the body at each hardpoint (rows: primary, secondary 1, secondary 2; they sum to F)."""

    primary: float
    secondaries: np.ndarray
    primary_upper: float
    knee_moment: float
    hardpoint_forces: np.ndarray


def strut_forces(leg: TripodLeg, F, P=None) -> StrutForces:
    """Equilibrium of the massless leg under a force F (N, principal axes) on the footpad at P (rest if None).

    Inverted tripod (method of joints at the footpad, Hibbeler, Statics, sec. 6.5): F = Tp u + T1 e1 + T2 e2,
    a 3 x 3 system in the unit vectors from the hardpoints to the footpad.
    Cantilever: moments about the primary's hardpoint pin, a u x (T1 e1 + T2 e2) = Lp u x F, whose two
    components across u give T1 = (Lp/a) u . (F x e2) / D, T2 = (Lp/a) u . (e1 x F) / D, D = u . (e1 x e2)
    (e_i from the secondary hardpoints to the knee); the cartridge below the knee carries Tp = F . u, the primary
    above it (F - T1 e1 - T2 e2) . u; the knee moment is |F_perp| (Lp - a) (`bending_moment`)."""
    P = leg.footpad if P is None else np.asarray(P, float)
    F = np.asarray(F, float)
    u, Lp = _unit(P - leg.primary_hardpoint)
    j = junction(leg, P)
    e1, e2 = (_unit(j - h)[0] for h in leg.secondary_hardpoints)
    if not leg.is_cantilever:
        T = np.linalg.solve(np.column_stack((u, e1, e2)), F)
        return StrutForces(T[0], T[1:], T[0], 0.0, T[:, None] * np.array([u, e1, e2]))
    a = leg.knee_offset
    d = u @ np.cross(e1, e2)
    t1 = Lp / a * (u @ np.cross(F, e2)) / d
    t2 = Lp / a * (u @ np.cross(e1, F)) / d
    on_pin = F - t1 * e1 - t2 * e2
    perp = np.linalg.norm(F - (F @ u) * u)
    return StrutForces(F @ u, np.array([t1, t2]), on_pin @ u, perp * (Lp - a), np.array([on_pin, t1 * e1, t2 * e2]))


def footpad_force(leg: TripodLeg, T, P=None) -> np.ndarray:
    """Force on the footpad (N) that the strut forces T = (Tp, T1, T2) (tension positive) hold in equilibrium
    at P (rest if None): G^T T, the inverse of `strut_forces` (virtual work)."""
    P = leg.footpad if P is None else P
    return length_jacobian(leg, P).T @ np.asarray(T, float)


def bending_moment(leg: TripodLeg, F, x, P=None):
    """Bending moment magnitude (N m) in the primary at distances x (m) from its footpad end, for a force F on
    the footpad at P (rest if None). Inverted tripod: 0 (a two-force member). Cantilever: the overhang below the
    knee, M = |F_perp| x for x <= b = Lp - a (free body of the tip); above the knee it falls linearly to the
    pin, M = |F_perp| b (Lp - x) / a, since the secondaries' resultant across u is -(Lp/a) F_perp. Every force
    across the primary is parallel to F_perp, so it bends in the plane of u and F_perp."""
    P = leg.footpad if P is None else np.asarray(P, float)
    F = np.asarray(F, float)
    x = np.asarray(x, float)
    u, Lp = _unit(P - leg.primary_hardpoint)
    if np.any(x < 0) or np.any(x > Lp):
        raise ValueError(f"x: expected distances from the footpad within the primary's length [0, {Lp:.6g}] m")
    if not leg.is_cantilever:
        return np.zeros_like(x)
    a = leg.knee_offset
    b = Lp - a
    perp = np.linalg.norm(F - (F @ u) * u)
    return np.where(x <= b, perp * x, perp * b * (Lp - x) / a)


def cell_deflections(leg: TripodLeg, lengths) -> np.ndarray:
    """Deflections (m) of the five cells in `TripodLeg.cells` order: the primary's shortening, then for each
    secondary its shortening (compression cell) and its lengthening (tension cell); a cell pushes only at
    positive deflection, so Tp = -f0, T1 = f2 - f1, T2 = f4 - f3 from the cell forces f."""
    d = leg.rest_lengths - np.asarray(lengths, float)
    return np.array([d[0], d[1], -d[1], d[2], -d[2]])


def tripod_from_params(footpad_radius: float, hardpoint_radius: float, hardpoint_height: float, *,
                       secondary_spread: float, primary: CellModel, secondary_compression: CellModel,
                       secondary_tension: CellModel, footpad_diameter: float, primary_angle: float | None = None,
                       footpad_height: float | None = None, secondary_attach: float = 0.0,
                       secondary_height: float | None = None, secondary_radius: float | None = None,
                       azimuth: float = 0.0, footpad_mass: float = 0.0) -> TripodLeg:
    """A leg in the half-plane at `azimuth` (rad, from principal axis 1 toward 2): primary hardpoint at
    `hardpoint_radius` from the capsule axis and `hardpoint_height` along it (m), footpad at `footpad_radius`
    and either `footpad_height` or the primary's angle from the capsule axis `primary_angle` (rad, outward,
    in (0, pi/2)); secondary hardpoints at azimuth +-`secondary_spread` (rad, in (0, pi)) about the leg's, at
    `secondary_radius` and `secondary_height` (the primary hardpoint's if None); both secondaries get the same
    cells."""
    if not footpad_radius > 0:
        raise ValueError(f"footpad_radius: expected > 0 m, got {footpad_radius!r}")
    if not hardpoint_radius > 0:
        raise ValueError(f"hardpoint_radius: expected > 0 m (hardpoints on the axis are collinear), got "
                         f"{hardpoint_radius!r}")
    if (primary_angle is None) == (footpad_height is None):
        raise ValueError("primary_angle, footpad_height: expected exactly one of them")
    if primary_angle is not None:
        if not 0 < primary_angle < np.pi / 2:
            raise ValueError(f"primary_angle: expected in (0, pi/2) rad from the capsule axis, got {primary_angle!r}")
        if not footpad_radius > hardpoint_radius:
            raise ValueError("primary_angle: an outward primary needs footpad_radius > hardpoint_radius (give "
                             "footpad_height for a vertical or inward primary)")
        footpad_height = hardpoint_height - (footpad_radius - hardpoint_radius) / np.tan(primary_angle)
    if not footpad_height < hardpoint_height:
        raise ValueError(f"footpad_height: expected below hardpoint_height ({hardpoint_height!r} m), got "
                         f"{footpad_height!r}")
    if not 0 < secondary_spread < np.pi:
        raise ValueError(f"secondary_spread: expected in (0, pi) rad, got {secondary_spread!r}")
    zs = hardpoint_height if secondary_height is None else secondary_height
    rs = hardpoint_radius if secondary_radius is None else secondary_radius
    if not rs > 0:
        raise ValueError(f"secondary_radius: expected > 0 m, got {rs!r}")

    def on_circle(radius, angle, height):
        return np.array([radius * np.cos(angle), radius * np.sin(angle), height])

    return TripodLeg(on_circle(hardpoint_radius, azimuth, hardpoint_height),
                     np.array([on_circle(rs, azimuth + sign * secondary_spread, zs) for sign in (1, -1)]),
                     on_circle(footpad_radius, azimuth, footpad_height), secondary_attach, primary,
                     (secondary_compression, secondary_compression), (secondary_tension, secondary_tension),
                     footpad_diameter, footpad_mass)


@njit(cache=True)
def leg_force(geo, cells, i, mem, shape, P, kin, out):
    """Forces of tripod leg i (packed as geo[10][i]) with its footpad held at P (terrain axes) under a capsule
    moving as kin = (r, R, v, w): at r, attitude R (principal -> terrain), velocity v (terrain), rate w (principal);
    `shape` is unused. Writes into out = (defl, frc, rte, X) the five cell deflections (`cell_deflections`), forces
    and rates and the force X = G^T T on the capsule (principal axes), T = (-f0, f2 - f1, f4 - f3); returns (cells'
    power, Lp, l1, l2): the strut lengths are the leg's shape."""
    r, R, v, w = kin
    defl, frc, rte, X = out
    t = geo[10][i]
    b0, b1, b2 = mtv(R, P[0] - r[0], P[1] - r[1], P[2] - r[2])     # CG -> footpad, principal axes
    c0, c1, c2 = cross(w[0], w[1], w[2], b0, b1, b2)
    s0, s1, s2 = mtv(R, v[0], v[1], v[2])
    e0, e1, e2 = -c0 - s0, -c1 - s1, -c2 - s2                       # its rate with the footpad held
    Lp, l1, l2 = strut_lengths_at(t, b0, b1, b2)
    g = length_jacobian_at(t, b0, b1, b2)
    dp = g[0] * e0 + g[1] * e1 + g[2] * e2                          # dL/dt = G (footpad rate)
    d1 = g[3] * e0 + g[4] * e1 + g[5] * e2
    d2 = g[6] * e0 + g[7] * e1 + g[8] * e2
    x0, x1, x2 = t[3, 0] - Lp, t[3, 1] - l1, t[3, 2] - l2
    defl[0], defl[1], defl[2], defl[3], defl[4] = x0, x1, -x1, x2, -x2
    rte[0], rte[1], rte[2], rte[3], rte[4] = -dp, -d1, d1, -d2, d2
    power = 0.0
    for j in range(5):
        frc[j] = cell_force(cells, i, j, mem, defl[j], rte[j])
        power += frc[j] * rte[j]
    tp, t1, t2 = -frc[0], frc[2] - frc[1], frc[4] - frc[3]
    X[0] = g[0] * tp + g[3] * t1 + g[6] * t2
    X[1] = g[1] * tp + g[4] * t1 + g[7] * t2
    X[2] = g[2] * tp + g[5] * t1 + g[8] * t2
    return power, Lp, l1, l2


@njit(cache=True)
def free_footpad(geo, cells, i, mem, shape, r, R):
    """Terrain position (tuple) of the footpad of tripod leg i whose struts have the lengths `shape` (cells and
    mem unused: the telescoping leg's interface)."""
    f0, f1, f2 = footpad_at(geo[10][i], shape[0], shape[1], shape[2])
    x0, x1, x2 = mv(R, f0, f1, f2)
    return r[0] + x0, r[1] + x1, r[2] + x2


@njit(cache=True)
def lift_shape(geo, cells, i, mem, loaded, main, r, R):
    """Free geometry of a tripod leg lifting off with the strut lengths `loaded` (Lp, l1, l2; leg_force's shape):
    each strut at the length nearest to it where its cells carry no force (a cell's deflection at most its
    permanent set), as a massless leg in the air carries none (X = G^T T = 0 gives T = 0). A footpad with mass
    leaves the ground with its in-plane inertia still on the struts; the elastic energy they then give up goes
    with the footpad's in-plane motion, which a lift-off drops (footpad_mass.pad_switch). main, r, R unused: the
    other kinds' interface."""
    t = geo[10][i]
    k, m = cells[3][i], mem
    x0 = min(t[3, 0] - loaded[0], permanent_set(k[0], m[0, 0], m[0, 1]))
    x1 = min(max(t[3, 1] - loaded[1], -permanent_set(k[2], m[2, 0], m[2, 1])), permanent_set(k[1], m[1, 0], m[1, 1]))
    x2 = min(max(t[3, 2] - loaded[2], -permanent_set(k[4], m[4, 0], m[4, 1])), permanent_set(k[3], m[3, 0], m[3, 1]))
    return t[3, 0] - x0, t[3, 1] - x1, t[3, 2] - x2


@njit(cache=True)
def at_set(geo, cells, i, mem, shape):
    """A free tripod leg is caught on a vertical face with its stored strut lengths: it lifts off at zero normal
    push (`slack`), never short of a set within the grazing band (the other kinds' interface)."""
    return shape[0], shape[1], shape[2]


@njit(cache=True)
def slack(geo, cells, i, mem, defl, X, P, R):
    """The ground's normal push on tripod leg i's footpad over its primary's unloading rate (m): the leg lifts off
    where it falls through zero, the footpad pulled off the terrain (the normal of the surface under P, or of the
    vertical face a footpad caught beside it is held on: terrain.bearing_normal; X the force on the capsule,
    principal axes)."""
    f0, f1, f2 = mv(R, X[0], X[1], X[2])
    n0, n1, n2 = bearing_normal(geo[9], P[0], P[1], P[2])
    return (f0 * n0 + f1 * n1 + f2 * n2) / cells[3][i, 0]


@njit(cache=True)
def fold(geo, i, P, r, R):
    """|u . (e1 x e2)| at tripod leg i's joint with its footpad at P (terrain axes): below MIN_DET the struts
    fold flat (no stiffness across their plane; the trilateration's branch could flip). 0 for a cantilever whose
    primary has stroked to its knee (the inner cylinder at the end of its travel: no footpad below the knee)."""
    t = geo[10][i]
    b0, b1, b2 = mtv(R, P[0] - r[0], P[1] - r[1], P[2] - r[2])
    if t[4, 1] > 0.0 and not strut_lengths_at(t, b0, b1, b2)[0] > t[4, 0]:
        return 0.0
    return abs(fold_at(t, b0, b1, b2))


def strut_axial_forces(forces: np.ndarray) -> np.ndarray:
    """Strut axial forces (N, tension positive; primary, secondary 1, secondary 2) from the five cell forces in
    `TripodLeg.cells` order (last axis): T = (-f0, f2 - f1, f4 - f3)."""
    f = np.asarray(forces, float)
    return np.stack((-f[..., 0], f[..., 2] - f[..., 1], f[..., 4] - f[..., 3]), axis=-1)
