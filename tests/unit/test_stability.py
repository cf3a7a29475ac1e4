"""Energy stability criterion (eq. 89-95, QUIMOT) and quiescence of motion (main program, stmts 378-401).

Tolerances. Closed-form cases are a handful of floating-point operations on O(1) numbers, so they must
agree to rel 1e-12 (double precision leaves ~1e-15 per operation; 1e-12 leaves room for the cancellation in
h - H). The brute-force rotation check is limited by the optimiser's angle tolerance (1e-10 rad -> height
error ~ h 1e-20, far below) and by cancellation, so rel 1e-9. Sign flips are probed 1e-6 either side of the
critical value: there the margin moves by ~2e-6 of the potential energy, nine orders above rounding.
"""

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from alightsize_sim import stability as st

G = 9.80665
M = 120.0
INERTIA = np.array([30.0, 35.0, 20.0])
I3 = np.eye(3)
ZERO = np.zeros(3)
DOWN = np.array([0.0, 0.0, -G])


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rodrigues(axis, angle):
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


def box_pads(a, b):
    """Four pads counter-clockwise seen from above: edges x = a, y = b, x = -a, y = -b."""
    return np.array([[a, -b, 0.0], [a, b, 0.0], [-a, b, 0.0], [-a, -b, 0.0]])


def at_rest(r, pads, gravity=DOWN, R=I3):
    return st.tipping_margins(r, ZERO, R, ZERO, (M, INERTIA), gravity, pads)


def test_box_at_rest_margin_is_weight_times_rise_of_cg():
    a, b, H = 0.6, 0.9, 0.8
    m = at_rest(np.array([0.0, 0.0, H]), box_pads(a, b))
    ra, rb = math.hypot(a, H) - H, math.hypot(b, H) - H
    assert m == pytest.approx(M * G * np.array([ra, rb, ra, rb]), rel=1e-12)
    # Clockwise order gives the same edges (sense is detected from the polygon's signed area).
    m_cw = at_rest(np.array([0.0, 0.0, H]), box_pads(a, b)[::-1].copy())
    assert sorted(m_cw) == pytest.approx(sorted(m), rel=1e-12)
    assert st.stable_by_energy(m) and not st.tipped_by_energy(m)


def test_cg_outside_the_support_polygon_gives_negative_margin():
    a, b, H, c = 0.6, 0.9, 0.8, 0.1
    m = at_rest(np.array([a + c, 0.0, H]), box_pads(a, b))
    # Over edge x = a the CG is c beyond: the signed rise is -(sqrt(c^2 + H^2) - H).
    assert m[0] == pytest.approx(-M * G * (math.hypot(c, H) - H), rel=1e-12)
    assert m[0] < 0 and m[1] > 0 and m[2] > 0 and m[3] > 0
    assert st.tipped_by_energy(m) and not st.stable_by_energy(m)
    # Just inside the same edge: positive again, and the margin is continuous through zero.
    m_in = at_rest(np.array([a - c, 0.0, H]), box_pads(a, b))
    assert m_in[0] == pytest.approx(M * G * (math.hypot(c, H) - H), rel=1e-12)


def test_slope_margin_and_the_critical_slope():
    """Downhill edge y = -b on a slope gamma: rise = h (1 - cos(phi - gamma)), phi = atan(b / H)."""
    b, H = 0.7, 0.9
    pads = box_pads(0.6, b)
    h, phi = math.hypot(b, H), math.atan2(b, H)

    def margins(gamma):
        g = G * np.array([0.0, -math.sin(gamma), -math.cos(gamma)])
        return at_rest(np.array([0.0, 0.0, H]), pads, gravity=g)

    for gamma in (0.0, 0.2, 0.5, 0.8, 1.0):
        expected = h * (1 - math.cos(phi - gamma)) * (1 if gamma <= phi else -1)
        assert margins(gamma)[3] == pytest.approx(M * G * expected, rel=1e-12, abs=1e-9)
    assert margins(phi * (1 - 1e-6))[3] > 0 > margins(phi * (1 + 1e-6))[3]


def test_sloping_edge_rise_matches_brute_force_rotation():
    rng = np.random.default_rng(7)
    for _ in range(20):
        p_i, p_j = rng.normal(size=3), rng.normal(size=3)
        r = rng.normal(size=3)
        gravity = G * rng.normal(size=3)
        gravity *= G / np.linalg.norm(gravity)
        up = -gravity / G
        m = st.tipping_margins(r, ZERO, I3, ZERO, (M, INERTIA), gravity, np.array([p_i, p_j]))
        e = (p_j - p_i) / np.linalg.norm(p_j - p_i)

        def height(t):
            return -(p_i + rodrigues(e, t) @ (r - p_i)) @ up

        grid = np.linspace(-math.pi, math.pi, 2001)
        t0 = grid[np.argmin([height(t) for t in grid])]
        best = minimize_scalar(height, bounds=(t0 - 0.01, t0 + 0.01), method="bounded",
                               options={"xatol": 1e-10})
        rise = -best.fun - r @ up
        # The two orientations of the one edge: one sees the CG inside, the other beyond.
        assert abs(m[0]) == pytest.approx(M * G * rise, rel=1e-9, abs=1e-9)
        assert m[0] == pytest.approx(-m[1], rel=1e-12, abs=1e-9)


def pivot_case(w, conservative):
    """Capsule pivoting on edge x = a (along y) at rate w, tilted about x so I_e = B cos^2 + C sin^2."""
    a, b, H, beta = 0.6, 0.9, 0.8, 0.3
    R = rot_x(beta)
    e = np.array([0.0, 1.0, 0.0])
    hvec = np.array([-a, 0.0, H])
    v = w * np.cross(e, hvec)
    omega = R.T @ (w * e)
    m = st.tipping_margins(np.array([0.0, 0.2, H]), v, R, omega, (M, INERTIA), DOWN, box_pads(a, b),
                           conservative)
    i_e = INERTIA[1] * math.cos(beta) ** 2 + INERTIA[2] * math.sin(beta) ** 2
    i_edge = i_e + M * (a * a + H * H)
    pe = M * G * (math.hypot(a, H) - H)
    return m[0], pe, i_edge


def test_pivoting_about_an_edge_momentum_ke_and_critical_rate():
    w = 0.7
    margin, pe, i_edge = pivot_case(w, conservative=False)
    assert pe - margin == pytest.approx(0.5 * i_edge * w * w, rel=1e-12)       # KE = 1/2 I_edge w^2
    w_c = math.sqrt(2 * pe / i_edge)
    assert abs(pivot_case(w_c, False)[0]) < 1e-12 * pe
    assert pivot_case(w_c * (1 - 1e-6), False)[0] > 0 > pivot_case(w_c * (1 + 1e-6), False)[0]


def test_pivoting_about_an_edge_report_eq89_rate_is_doubled():
    """Eq. 89 adds |v|/h and |omega|: for pure pivoting that is 2 w, so the critical w halves."""
    w = 0.7
    margin, pe, i_edge = pivot_case(w, conservative=True)
    assert pe - margin == pytest.approx(0.5 * i_edge * (2 * w) ** 2, rel=1e-12)
    w_c = 0.5 * math.sqrt(2 * pe / i_edge)
    assert abs(pivot_case(w_c, True)[0]) < 1e-12 * pe
    assert pivot_case(w_c * (1 - 1e-6), True)[0] > 0 > pivot_case(w_c * (1 + 1e-6), True)[0]


def report_capsule(theta):
    """QUIMOT's geometry: pads at azimuths -135, -45, 45, 135 deg, radius rho, H below the CG; the capsule
    leans by theta over the edge of legs 1-2 (y = -rho / sqrt 2), CG at the origin."""
    rho, H = 1.1, 0.9
    az = np.radians([-135.0, -45.0, 45.0, 135.0])
    xi = np.array([[rho * math.cos(t), rho * math.sin(t), -H] for t in az])
    R = rot_x(theta)
    return xi, R, np.array([R @ x for x in xi])


@pytest.mark.parametrize("theta", [0.0, 0.1, 0.25])
def test_report_eq93_is_exact_for_the_leaned_over_edge_and_conservative_elsewhere(theta):
    xi, R, pads = report_capsule(theta)
    m = at_rest(ZERO, pads, R=R)
    nut = st.nutation_angle(R, DOWN)
    assert nut == pytest.approx(theta, abs=1e-12)
    for k in range(4):
        h, tau = st.report_edge_geometry(xi[k], xi[(k + 1) % 4])
        w_cr = st.report_critical_rate(M, INERTIA[0], G, h, tau, nut)
        report = 0.5 * (M * h * h + INERTIA[0]) * w_cr ** 2     # = m g h (1 - sin(tau + Theta))
        if k == 0:
            assert m[k] == pytest.approx(report, rel=1e-12)
        else:   # the report assumes every edge is leaned over: it never overstates the margin
            assert m[k] >= report * (1 - 1e-12)


def test_report_edge_geometry_eq94_as_coded_not_as_printed():
    rng = np.random.default_rng(3)
    for _ in range(10):
        xi_i, xi_j = rng.normal(size=3), rng.normal(size=3)
        h, tau = st.report_edge_geometry(xi_i, xi_j)
        d = xi_j - xi_i
        dist = np.linalg.norm(np.cross(xi_i, d)) / np.linalg.norm(d)
        assert h == pytest.approx(dist, rel=1e-9)
        foot = xi_i - (xi_i @ d) / (d @ d) * d
        assert math.sin(tau) == pytest.approx(-foot[2] / dist, rel=1e-9, abs=1e-12)
        a, c = xi_i @ xi_i, xi_j @ xi_j
        printed = a + (a + d @ d - c) ** 2 / (-4.0 * c)        # eq. 94 as printed: -4 |zeta(i+1)|^2
        assert not math.isclose(printed, dist * dist, rel_tol=1e-6)


def test_report_critical_rate_skips_edges_past_vertical():
    assert st.report_critical_rate(M, 30.0, G, 1.0, 1.2, 0.4) == -1.0      # tau + Theta >= 90 deg
    assert st.report_critical_rate(M, 30.0, G, 1.0, 0.5, 0.2) > 0


def test_stable_and_tipped_flags():
    assert st.stable_by_energy(np.array([1.0, 2.0, 3.0]))
    assert not st.tipped_by_energy(np.array([1.0, 2.0, 3.0]))
    # Exactly on the edge at rest: QUIMOT's strict gamma_dot < gamma_dot_cr fails, but nothing tips.
    assert not st.stable_by_energy(np.array([1.0, 0.0, 2.0]))
    assert not st.tipped_by_energy(np.array([1.0, 0.0, 2.0]))
    assert st.tipped_by_energy(np.array([1.0, -1.0]))
    assert not st.stable_by_energy(np.array([1.0, -np.inf]))


def test_tipped_by_nutation_at_the_critical_angle():
    crit = math.radians(40.0)
    assert not st.tipped_by_nutation(rot_x(crit * (1 - 1e-9)), DOWN, crit)
    assert st.tipped_by_nutation(rot_x(crit * (1 + 1e-9)), DOWN, crit)
    assert st.nutation_angle(rot_x(-0.3), DOWN) == pytest.approx(0.3, abs=1e-12)


def test_leg_oscillation_period_is_the_listing_tau():
    m, k = 7.1, 3.0e5          # a few roundings apart: rel 1e-14
    assert st.leg_oscillation_period(m, k) == pytest.approx(math.pi * math.sqrt(m / k), rel=1e-14)
    assert st.leg_oscillation_period(m, k, 3) == pytest.approx(2 * math.pi * math.sqrt(m / (3 * k)), rel=1e-14)


def run(steps, dt, ref, period, taus):
    """Feed (momentum, in_contact) pairs; return the index of the step that ends the run, or None."""
    acc = 0.0
    for n, (p, contact) in enumerate(steps):
        acc, quiet = st.quiescence_update(dt, p, ref, acc, period, taus, contact)
        if quiet:
            return n, acc
    return None, acc


def test_quiescence_after_exactly_taus_periods_and_reset():
    dt, period, taus, ref = 1.0 / 64, 0.25, 2.0, 400.0     # taus * period = 32 dt, exact in binary
    loud, quiet = (50.0, True), (9.0, True)                # threshold 0.025 * 400 = 10
    n, acc = run([loud] + [quiet] * 40, dt, ref, period, taus)
    assert n == 32 and acc == 0.5                          # 32 dt after the last loud step
    # One step short: no verdict.
    assert run([loud] + [quiet] * 31, dt, ref, period, taus)[0] is None
    # Motion returns after 20 quiet steps: the count restarts from that step.
    n, _ = run([loud] + [quiet] * 20 + [loud] + [quiet] * 40, dt, ref, period, taus)
    assert n == 21 + 32
    # Free-flight steps neither advance nor reset the count (the listing skips the test in the air).
    n, _ = run([loud] + [quiet] * 10 + [(50.0, False)] * 5 + [quiet] * 40, dt, ref, period, taus)
    assert n == 1 + 10 + 5 + 21                            # the loud step's own dt counts (PERIOD=DLT)
    # The threshold itself counts as quiet (IF(QUIVEL-RRD)385,380,380).
    assert st.quiescence_update(dt, 0.025 * ref, ref, 0.5, period, taus)[1]


def test_quiescence_momenta_weigh_as_the_report_in_feet():
    slug, ft = 14.59390294, 0.3048
    m, inertia = 136.0, np.array([4.5, 4.5, 3.8])
    v0, w0 = np.array([2.0, 1.0, -7.6]), np.array([0.5, -0.2, 3.0])
    v1, w1 = np.array([0.1, 0.05, -0.3]), np.array([0.0, 0.0, 0.4])
    n0, t0 = st.quiescence_momenta(v0, w0, m, inertia)
    n1, t1 = st.quiescence_momenta(v1, w1, m, inertia)
    # The listing's RRD / QUIVEL, RRDX / QUIVEX in slugs and feet.
    ms, Is = m / slug, inertia / (slug * ft * ft)

    def rrd(v, w):
        return abs(ms * v[2] / ft) + math.hypot(Is[0] * w[0], Is[1] * w[1])

    def rrdx(v, w):
        return ms * math.hypot(v[0] / ft, v[1] / ft) + abs(Is[2] * w[2])

    assert n1 / n0 == pytest.approx(rrd(v1, w1) / rrd(v0, w0), rel=1e-12)
    assert t1 / t0 == pytest.approx(rrdx(v1, w1) / rrdx(v0, w0), rel=1e-12)
    # In metres the mixture weighs differently: the verdict depends on the length unit.
    n0m, _ = st.quiescence_momenta(v0, w0, m, inertia, 1.0)
    n1m, _ = st.quiescence_momenta(v1, w1, m, inertia, 1.0)
    assert not math.isclose(n1m / n0m, n1 / n0, rel_tol=1e-3)
    assert st.lateral_quiet(0.025 * t0, t0) and not st.lateral_quiet(0.03 * t0, t0)


def test_hanging_leg_margin_closed_form():
    """Edge along x through (0,0,0) and (1,0,0), CG at y = +1, z = 1, a footpad hanging h = 0.02 m up at
    y = -1: turning about the edge by h rad (foot 1 m from the edge) lands it and lifts the CG by h (1 m on
    the other side), so the margin is m g h less the kinetic energy (closed form, rel 1e-12). What counts is
    the height above the ground under the footpad: the same footpad 0.3 m higher over a 0.3 m rock, or 0.03 m
    lower over a hole 0.05 m deep, has the same margin. With the CG on the footpad's side the turn lowers it:
    not clear."""
    a, b, h = np.zeros(3), np.array([1.0, 0.0, 0.0]), 0.02
    foot, cg = np.array([0.5, -1.0, h]), np.array([0.5, 1.0, 1.0])
    at_rest = st.hanging_margin(cg, ZERO, ZERO, (M, INERTIA), DOWN, (a, b), foot, h)
    assert at_rest == pytest.approx(M * G * h, rel=1e-12)
    for lift in (0.3, -0.03):
        assert st.hanging_margin(cg, ZERO, ZERO, (M, INERTIA), DOWN, (a, b), foot + [0, 0, lift], h) == pytest.approx(
            at_rest, rel=1e-12)
    v, w = np.array([0.1, 0.0, 0.0]), np.array([0.0, 0.2, 0.0])
    kinetic = 0.5 * M * 0.01 + 0.5 * INERTIA[1] * 0.04
    assert st.hanging_margin(cg, v, w, (M, INERTIA), DOWN, (a, b), foot, h) == pytest.approx(M * G * h - kinetic,
                                                                                          rel=1e-12)
    assert st.hanging_margin(np.array([0.5, -0.5, 1.0]), ZERO, ZERO, (M, INERTIA), DOWN, (a, b), foot, h) < 0.0


def test_hanging_leg_margin_of_a_degenerate_edge_is_not_clear():
    """Two grounded footpads at one point give no edge to turn about: never judged clear (no NaN)."""
    a = np.array([0.3, 0.2, 0.0])
    assert st.hanging_margin(np.array([0.0, 0.0, 1.0]), ZERO, ZERO, (M, INERTIA), DOWN, (a, a.copy()),
                             np.array([1.0, 0.0, 0.05]), 0.05) == -1.0
