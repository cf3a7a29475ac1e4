"""Run-termination tests: the energy stability criterion and quiescence of motion (AFFDL-TR-66-33 Sec. V.H,
eq. 89-95, subroutine QUIMOT; the quiescence test of the main program, statements 378-401).

All functions take floats and numpy arrays only and are compiled with numba (NUMBA_DISABLE_JIT=1 runs
them as plain Python). SI units; terrain axes (epsilon) unless stated; ``R`` takes principal-axis (eta)
components to terrain components, as in `alightsize_sim.landing`.

Energy criterion (eq. 89-95)
----------------------------
For the edge through adjacent footpads i, i+1 the report compares the present rate about the edge,

    gamma_dot = |r_dot| / h + |omega|                                   (eq. 89)

with the critical rate that brings the capsule to the edge (delta = 0) with nothing to spare,

    gamma_dot_cr^2 = 2 m g h [1 - sin(tau + Theta)] / (m h^2 + A)       (eq. 93)

where h is the normal from the CG to the edge, tau the angle of h below the body x1-x2 plane, Theta the
nutation angle (roll axis to vertical) and A the transverse moment of inertia. The capsule is stable when
gamma_dot < gamma_dot_cr for *every* adjacent pair (QUIMOT counts ISET up to 4); it then prints both rates
and ends the run. We return that comparison as an energy margin per edge, in joules:

    margin = m g * (rise of the CG to pass over the edge)  -  (1/2)(I_e + m h^2) gamma_dot^2

(margin > 0 <=> gamma_dot < gamma_dot_cr.) Readings chosen where the report is loose or misprinted:

* Geometry from terrain-axis footpads. The report forms h and tau in body axes (eq. 94-95) and then adds
  the *unsigned* nutation Theta = arcsin(sqrt(sin^2 Y + cos^2 Y sin^2 P)) (QUIMOT / BOUNCE), i.e. it assumes
  for every edge that the capsule leans toward that edge, in the plane normal to it, with the edge
  horizontal. Exact only for the edge being leaned over; conservative for the others. We use the true
  geometry: with e the unit edge direction, hvec the perpendicular from the edge to the CG (|hvec| = h) and
  up = -g/|g|, the CG circles the edge on radius h and its highest point is h |up_perp|, with
  up_perp = up - (up.e) e. Rise = h |up_perp| - hvec.up = |up_perp| h (1 - cos delta), delta being the
  angle of hvec from up_perp. On level ground with the report's assumptions |up_perp| = 1 and
  cos delta = sin(tau + Theta): identical to eq. 93. It also covers sloping edges (terrain slope, pads at
  different heights), which the report's planar figure 30 does not.
* CG beyond the edge. QUIMOT skips an edge when |tau + Theta| >= 90 deg (it is then never counted stable);
  eq. 93 itself is even in delta and would wrongly give a positive energy. We sign the rise: when the CG
  lies outside the vertical plane through the edge (hvec . (e x up) > 0 for pads ordered counter-clockwise
  seen from above) the potential term is -(rise), so the margin is negative and continuous through delta = 0.
  The pad ordering sense is detected from the signed area of the pad polygon seen from above; with two pads
  (or collinear pads) the two orientations of the one edge are both returned, i.e. both sides are checked.
* Moment of inertia. Eq. 90-93 use A (the transverse principal moment; the telescoping QUIMOT listing
  reads "+AL" on a continuation line, which is the OCR of "+A1", cf. the articulated QUIMOT). We use the
  moment about the CG axis parallel to the edge, I_e = sum_k I_k (R^T e)_k^2, which equals A for an
  axisymmetric capsule whenever the edge is normal to the roll axis (the report's geometry).
* Rate about the edge. Eq. 89 is the report's deliberate upper bound (|v|/h and |omega| added as if v lay in
  the plane of Fig. 30 and omega were parallel to the edge). For a body truly pivoting on the edge at rate w
  (v = w e x hvec, omega = w e) it gives 2 w, i.e. four times the pivot kinetic energy; it also bounds the
  whole kinetic energy from above. This is the default (``conservative=True``), as in the report.
  ``conservative=False`` uses instead the angular momentum about the edge, which the pads' contact impulses
  at the edge cannot change: H_e = e . (R (I omega) + m hvec x v), KE = H_e^2 / (2 (I_e + m h^2)); exact
  (= (1/2)(I_e + m h^2) w^2) for pure pivoting. Both are unsigned (rotation toward the inside also counts),
  as the report's |.| is.
* Elastic energy. The absorber spring terms of eq. 90-92 are dropped, as the report does after eq. 92.
* Which pads. QUIMOT uses all four legs' footpads, placed with the largest rotational deflection and
  shortest axial length reached so far (COMMON /ST/ = ALM, ALMIN of FORCE) at the fixed azimuths -135, -45,
  45, 135 deg; it is called every 50 accepted steps after t = 0.05 s (only when NSTOP = 1) and at every
  recontact computed by BOUNCE. Which pads to pass, and when, is the caller's choice here.

Tipping. The report never declares "tipped" from the energy criterion: an edge with gamma_dot >=
gamma_dot_cr only means "potentially unstable, continue". A run is ended as tumbled when the nutation angle
exceeds the input critical angle (cos P cos Y <= cos Theta_crit, statement 367 of the main program);
`tipped_by_nutation` is that test. `tipped_by_energy` is the "potentially unstable" flag (some margin < 0).

Quiescence of motion (main program, statements 378-401; not part of QUIMOT despite the name)
------------------------------------------------------------------------------------------------
At impact QUIVEL = 0.025 (|m v3| + |(A w1, B w2)|) and QUIVEX = 0.025 (m |(v1, v2)| + |C w3|), v in
terrain axes (v3 normal to the terrain), w body rates. At each step in ground contact (the step is skipped
while |acceleration| = 1 g, i.e. free flight) with NSTOP = 1: if the present "normal" sum exceeds QUIVEL,
PERIOD = DLT (restart); else if PERIOD < TAUS * TAU, PERIOD += DLT; else the run ends - "quiescence of
motion" if the "tangential" sum <= QUIVEX, otherwise "stable position, check RD(1), RD(2), OMEG(3)" (it may
still slide or spin). PERIOD is thus the time since the last step with motion above the threshold. TAU =
pi sqrt(M / SLOPE(1)), SLOPE(1) being the unloading spring rate of one leg's axial cell: pi sqrt(m/k) =
2 pi sqrt(m / (4 k)), the full period of the capsule bouncing on its four legs in parallel. TAUS is an
input (Appendix VIII: "the number of periods of oscillation ... through which the quiescence of motion
criteria must be satisfied").

The two sums add linear and angular momentum, so their ratio to the reference depends on the length unit
(the report's is the foot): ``length_unit`` (m) reproduces the report's weighting; 0.3048 by default.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .vec3 import cross, mtv, mv

FOOT = 0.3048
QUIESCENCE_FRACTION = 0.025                 # AFFDL-TR-66-33 main program, QUIVEL / QUIVEX = .025 * (...)


@njit(cache=True)
def _orientation(pads: np.ndarray, up) -> float:
    """+1 if the pads run counter-clockwise seen from above (or are degenerate: 2 or collinear), else -1."""
    n = pads.shape[0]
    area = 0.0
    scale = 0.0
    for i in range(n):
        j = (i + 1) % n
        c = cross(pads[i, 0] - pads[0, 0], pads[i, 1] - pads[0, 1], pads[i, 2] - pads[0, 2],
                  pads[j, 0] - pads[0, 0], pads[j, 1] - pads[0, 1], pads[j, 2] - pads[0, 2])
        area += c[0] * up[0] + c[1] * up[1] + c[2] * up[2]
        for k in range(3):
            scale = max(scale, abs(pads[i, k] - pads[0, k]))
    return -1.0 if area < -1e-12 * scale * scale else 1.0


@njit(cache=True)
def edge_geometry(r, p_i, p_j, up, sense: float):
    """(e, hvec, h, signed rise) of the edge p_i -> p_j: unit direction, perpendicular from the edge to the
    CG (both 3-tuples), its length and the CG rise to pass over the edge (negative: the CG is already beyond
    it). Scalar arithmetic on 3-vectors (arrays or tuples).

    sense = +1 for pads counter-clockwise seen from above (outward normal e x up), -1 for clockwise.
    """
    d0, d1, d2 = p_j[0] - p_i[0], p_j[1] - p_i[1], p_j[2] - p_i[2]
    dn = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    e = (d0 / dn, d1 / dn, d2 / dn)
    q0, q1, q2 = r[0] - p_i[0], r[1] - p_i[1], r[2] - p_i[2]
    s = q0 * e[0] + q1 * e[1] + q2 * e[2]
    hvec = (q0 - s * e[0], q1 - s * e[1], q2 - s * e[2])
    h = math.sqrt(hvec[0] ** 2 + hvec[1] ** 2 + hvec[2] ** 2)
    # AFFDL-TR-66-33 eq. 93 generalised: rise = h |up_perp| - hvec.up = |up_perp| h (1 - cos delta)
    ue = up[0] * e[0] + up[1] * e[1] + up[2] * e[2]
    up_perp = math.sqrt((up[0] - ue * e[0]) ** 2 + (up[1] - ue * e[1]) ** 2 + (up[2] - ue * e[2]) ** 2)
    rise = h * up_perp - (hvec[0] * up[0] + hvec[1] * up[1] + hvec[2] * up[2])
    rise = max(rise, 0.0)                      # rounding: the top of the circle is never below the CG
    n0, n1, n2 = cross(e[0], e[1], e[2], up[0], up[1], up[2])
    if sense * (hvec[0] * n0 + hvec[1] * n1 + hvec[2] * n2) > 0.0:   # beyond the vertical plane through the edge
        rise = -rise
    return e, hvec, h, rise


@njit(cache=True)
def tipping_margins(r: np.ndarray, v: np.ndarray, R: np.ndarray, omega: np.ndarray, body: tuple[float, np.ndarray],
                    gravity: np.ndarray, pads: np.ndarray, conservative: bool = True) -> np.ndarray:
    """Energy margin (J) against toppling over each edge (pads[k], pads[(k+1) % n]), k = 0..n-1.

    margin = m |g| rise - (1/2)(I_e + m h^2) gamma_dot^2; > 0: the capsule cannot topple over that edge.
    r, v: CG position and velocity (terrain axes); R: principal -> terrain; omega: body rates (principal);
    body: (mass, principal moments (3,)); gravity (terrain axes, m/s^2); pads: (n, 3) footpads, n >= 2, in order
    around the capsule (either sense). conservative: eq. 89 rate (report) or angular momentum about the edge.
    Degenerate edges (coincident pads, or the CG on the edge line) get -inf (never counted stable).
    """
    mass, inertia = body
    n = pads.shape[0]
    out = np.empty(n)
    g = math.sqrt(gravity[0] ** 2 + gravity[1] ** 2 + gravity[2] ** 2)
    up = (-gravity[0] / g, -gravity[1] / g, -gravity[2] / g)
    sense = _orientation(pads, up)
    speed = math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2)
    spin = math.sqrt(omega[0] ** 2 + omega[1] ** 2 + omega[2] ** 2)
    h_cg = mv(R, inertia[0] * omega[0], inertia[1] * omega[1], inertia[2] * omega[2])   # about the CG, terrain
    for k in range(n):
        p_i = pads[k]
        p_j = pads[(k + 1) % n]
        if not (p_j[0] != p_i[0] or p_j[1] != p_i[1] or p_j[2] != p_i[2]):
            out[k] = -np.inf
            continue
        e, hvec, h, rise = edge_geometry(r, p_i, p_j, up, sense)
        if h <= 0.0:
            out[k] = -np.inf
            continue
        eb = mtv(R, e[0], e[1], e[2])
        i_e = inertia[0] * eb[0] ** 2 + inertia[1] * eb[1] ** 2 + inertia[2] * eb[2] ** 2
        i_edge = i_e + mass * h * h            # parallel axes
        if conservative:
            gamma_dot = speed / h + spin       # AFFDL-TR-66-33 eq. 89
            ke = 0.5 * i_edge * gamma_dot * gamma_dot   # AFFDL-TR-66-33 eq. 90 (rotational term)
        else:
            c = cross(hvec[0], hvec[1], hvec[2], v[0], v[1], v[2])
            # angular momentum about the edge
            h_e = e[0] * (h_cg[0] + mass * c[0]) + e[1] * (h_cg[1] + mass * c[1]) + e[2] * (h_cg[2] + mass * c[2])
            ke = 0.5 * h_e * h_e / i_edge
        out[k] = mass * g * rise - ke          # AFFDL-TR-66-33 eq. 92-93 as an energy balance
    return out


@njit(cache=True)
def stable_by_energy(margins: np.ndarray) -> bool:
    """Every adjacent pair satisfies the criterion (QUIMOT: ISET = 4, gamma_dot < gamma_dot_cr strictly)."""
    for k in range(margins.shape[0]):
        if not margins[k] > 0.0:
            return False
    return True


@njit(cache=True)
def hanging_margin(r: np.ndarray, v: np.ndarray, omega: np.ndarray, body: tuple[float, np.ndarray],
                   gravity: np.ndarray, edge: tuple[np.ndarray, np.ndarray], foot, clear: float) -> float:
    """Energy margin (J) of a leg hanging clear of the ground (its free footpad `foot` at height `clear` > 0
    above the ground under it) beside the support edge = (a, b) through the footpads of its grounded neighbours,
    for a capsule of body = (mass, principal moments (3,)) at r moving at v, omega (principal axes):
    the work against gravity to turn the capsule about that edge until the footpad touches, less the whole
    kinetic energy. Positive: the capsule cannot bring the leg down (first order in the small turn; the
    kinetic energy is all counted, translation included, so conservative). Not positive when the turn lowers
    the CG (the capsule falls onto that leg), the footpad lies on the edge's line or a and b coincide."""
    mass, inertia = body
    a, b = edge
    span = math.sqrt((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2 + (b[2] - a[2]) ** 2)
    if not span > 0.0:
        return -1.0
    e0, e1, e2 = (b[0] - a[0]) / span, (b[1] - a[1]) / span, (b[2] - a[2]) / span
    df = cross(e0, e1, e2, foot[0] - a[0], foot[1] - a[1], foot[2] - a[2])   # footpad displacement per radian
    if not abs(df[2]) >= 1e-12:
        return -1.0
    turn = clear / -df[2]                              # signed angle (rad) that lands the footpad
    c = cross(e0, e1, e2, r[0] - a[0], r[1] - a[1], r[2] - a[2])
    rise = -(gravity[0] * c[0] + gravity[1] * c[1] + gravity[2] * c[2]) * turn   # work per unit mass
    kinetic = 0.5 * mass * (v[0] ** 2 + v[1] ** 2 + v[2] ** 2) + 0.5 * (
        inertia[0] * omega[0] ** 2 + inertia[1] * omega[1] ** 2 + inertia[2] * omega[2] ** 2)
    return mass * rise - kinetic


@njit(cache=True)
def tipped_by_energy(margins: np.ndarray) -> bool:
    """Some edge has energy to spare to topple over it (or the CG is beyond it): the report's "potentially
    unstable, continue the run", not a verdict of tumbling (see `tipped_by_nutation`)."""
    for k in range(margins.shape[0]):
        if margins[k] < 0.0:
            return True
    return False


@njit(cache=True)
def nutation_angle(R: np.ndarray, gravity: np.ndarray) -> float:
    """Angle (rad) between the roll axis (principal x3) and the vertical; AFFDL-TR-66-33 Sec. V.H, Theta."""
    c = -(R[0, 2] * gravity[0] + R[1, 2] * gravity[1] + R[2, 2] * gravity[2]) / np.linalg.norm(gravity)
    return math.acos(min(1.0, max(-1.0, c)))


@njit(cache=True)
def tipped_by_nutation(R: np.ndarray, gravity: np.ndarray, theta_critical: float) -> bool:
    """The report's tumbling verdict: cos Theta = cos P cos Y <= cos Theta_crit (main program, stmt 367)."""
    c = -(R[0, 2] * gravity[0] + R[1, 2] * gravity[1] + R[2, 2] * gravity[2]) / np.linalg.norm(gravity)
    return not c > math.cos(theta_critical)


@njit(cache=True)
def report_edge_geometry(xi_i: np.ndarray, xi_j: np.ndarray) -> tuple[float, float]:
    """(h, tau) of QUIMOT from body-axis CG->footpad vectors (AFFDL-TR-66-33 eq. 94-95, as coded).

    Eq. 94 as printed divides by -4 |zeta(i+1)|^2; QUIMOT (both versions) divides by -4 |zeta(i+1) -
    zeta(i)|^2, which is the correct distance from the CG to the edge line. In eta (eq. 95) QUIMOT uses the
    unsigned distance D = sqrt(|zeta(i)|^2 - h^2) from pad i to the foot of h, i.e. assumes the foot lies on
    the side of pad i+1; we use the signed distance, which is the same whenever that holds.
    """
    xim = np.dot(xi_i, xi_i)
    d = xi_j - xi_i
    dxi = np.dot(d, d)
    h2 = xim + (xim + dxi - np.dot(xi_j, xi_j)) ** 2 / (-4.0 * dxi)     # AFFDL-TR-66-33 eq. 94 (QUIMOT)
    h = math.sqrt(max(h2, 0.0))
    t = -np.dot(xi_i, d) / math.sqrt(dxi)                                # signed D of QUIMOT
    eta = xi_i[2] + t * d[2] / math.sqrt(dxi)                          # AFFDL-TR-66-33 eq. 95, eta_i
    tau = math.asin(min(1.0, max(-1.0, -eta / h)))                     # AFFDL-TR-66-33 eq. 95
    return h, tau


@njit(cache=True)
def report_critical_rate(mass: float, a: float, g: float, h: float, tau: float, theta: float) -> float:
    """gamma_dot_cr of eq. 93 (rad/s); -1 when |tau + Theta| >= 90 deg (QUIMOT skips the edge)."""
    if abs(tau + theta) >= 0.5 * math.pi:
        return -1.0
    return math.sqrt(2.0 * mass * g * h * (1.0 - math.sin(tau + theta)) / (mass * h * h + a))  # eq. 93


@njit(cache=True)
def leg_oscillation_period(mass: float, leg_stiffness: float, n_legs: int = 4) -> float:
    """Period (s) of the capsule bouncing on n legs in parallel, 2 pi sqrt(m / (n k)).

    For four legs this is the listing's TAU = PI*SQRT(M/SLOPE(1)) (FORCE of both simulations), SLOPE(1)
    being the unloading rate k of one leg's axial cell.
    """
    return 2.0 * math.pi * math.sqrt(mass / (n_legs * leg_stiffness))   # TAU = PI*SQRT(M/SLOPE(1))


@njit(cache=True)
def quiescence_momenta(v: np.ndarray, omega: np.ndarray, mass: float, inertia: np.ndarray,
                       length_unit: float = FOOT) -> tuple[float, float]:
    """(normal, tangential) motion sums of the quiescence test, in kg length_unit/s.

    normal = m |v3| + |(A w1, B w2)|, tangential = m |(v1, v2)| + |C w3| (main program: RRD, RRDX and, at
    impact, QUIVEL, QUIVEX), v in terrain axes, omega body rates (principal), each term expressed with
    lengths in ``length_unit`` metres so that their mixture weighs as in the report (feet by default).
    """
    lin = 1.0 / length_unit
    ang = lin * lin
    normal = mass * abs(v[2]) * lin + math.sqrt((inertia[0] * omega[0]) ** 2
                                                 + (inertia[1] * omega[1]) ** 2) * ang   # RRD
    tangential = mass * math.sqrt(v[0] ** 2 + v[1] ** 2) * lin + abs(inertia[2] * omega[2]) * ang  # RRDX
    return normal, tangential


@njit(cache=True)
def quiescence_update(dt: float, momentum_now: float, momentum_ref: float, quiet_time: float,
                      period: float, taus: float, in_contact: bool = True,
                      fraction: float = QUIESCENCE_FRACTION) -> tuple[float, bool]:
    """One accepted step of the quiescence test (main program, statements 378-390): (quiet_time, quiet).

    dt: the step just accepted (s); momentum_now / momentum_ref: the "normal" sum of `quiescence_momenta`
    now and at impact; quiet_time: the running PERIOD (0 at the start), the time since the last step whose
    motion exceeded fraction * momentum_ref; period: TAU (`leg_oscillation_period`); taus: TAUS.
    quiet becomes True at the first quiet step with quiet_time >= taus * period; the run then ends (check
    `lateral_quiet` to tell "quiescence of motion" from "stable, but may still slide or spin").
    Steps in free flight (in_contact False) neither advance nor reset the count, as in the listing.
    """
    if not in_contact:
        return quiet_time, False
    if momentum_now > fraction * momentum_ref:       # 385 PERIOD=DLT
        return dt, False
    if quiet_time >= taus * period:                  # 380 -> 400: terminate
        return quiet_time, True
    return quiet_time + dt, False                    # 390 PERIOD=PERIOD+DLT


@njit(cache=True)
def lateral_quiet(tangential_now: float, tangential_ref: float,
                  fraction: float = QUIESCENCE_FRACTION) -> bool:
    """Tangential sum within fraction of its impact value (RRDX <= QUIVEX: "quiescence of motion")."""
    return tangential_now <= fraction * tangential_ref
