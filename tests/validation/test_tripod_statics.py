"""Tripod legs (inverted tripod, cantilever): strut forces against an independent space-truss solution, the
primary's bending moment against beam statics, virtual work and energy against the kinematics, symmetry."""

import numpy as np
import pytest

from alightsize_sim.crush_cell import CellModel
from alightsize_sim.crush_curve import CrushCurve
from alightsize_sim.tripod_leg import (
    MIN_DET,
    TripodLeg,
    bending_moment,
    cell_deflections,
    footpad_force,
    footpad_jacobian,
    footpad_position,
    length_jacobian,
    strut_forces,
    strut_lengths,
    tripod_from_params,
)

CELL = CellModel(CrushCurve((0.0, 0.005, 0.05), (0.0, 2e4, 2e4)), 1e7)
N_LEGS = 200


def _leg(rng, cantilever: bool) -> TripodLeg:
    """A random leg that passes validation: hardpoints in a 2 m box above z = 0, the footpad below z = -0.5."""
    while True:
        try:
            return TripodLeg(rng.uniform((-1, -1, 0), (1, 1, 1)), rng.uniform((-1, -1, 0), (1, 1, 1), (2, 3)),
                             rng.uniform((-3, -3, -2), (3, 3, -0.5)), rng.uniform(0.1, 0.8) if cantilever else 0.0,
                             CELL, (CELL, CELL), (CELL, CELL), 0.4)
        except ValueError:
            continue


def _triple(leg, P):
    """u . (e1 x e2) at the joint (footpad or knee) for the footpad at P."""
    u = _unit(P - leg.primary_hardpoint)
    J = leg.primary_hardpoint + leg.knee_offset * u if leg.is_cantilever else P
    return u @ np.cross(*(_unit(J - h) for h in leg.secondary_hardpoints))


def _cases(seed, cantilever):
    """(leg, footpad P, footpad force F): P moved up to 3 cm from rest in a random direction (the cantilever's
    overhang is >= 5 cm at rest: it stays below the knee), kept where the struts are as far from coplanar as
    validation asks and on the rest side of the hardpoints' plane; F of order 1e4 N."""
    rng = np.random.default_rng(seed)
    n = 0
    while n < N_LEGS:
        leg = _leg(rng, cantilever)
        P = leg.footpad + rng.uniform(0.0, 0.03) * _unit(rng.normal(size=3))
        if _triple(leg, P) * _triple(leg, leg.footpad) >= MIN_DET ** 2:
            n += 1
            yield leg, P, rng.normal(0.0, 1e4, 3)


def _unit(v):
    return v / np.linalg.norm(v)


def _truss(leg, P, F):
    """Method of joints with the hardpoints as supports (Hibbeler, Statics, sec. 6.5), written out node by node:
    unknowns (T_p, T_1, T_2, R_0, R_1, R_2), R_k the support's force on strut k; 12 equations, least squares."""
    H = leg.hardpoints
    A = np.zeros((12, 12))
    b = np.zeros(12)
    for k in range(3):                               # support node k: T_k pulls it toward the footpad, + R_k
        A[3 * k:3 * k + 3, k] = _unit(P - H[k])
        A[3 * k:3 * k + 3, 3 + 3 * k:6 + 3 * k] = np.eye(3)
        A[9:12, k] = _unit(H[k] - P)                 # footpad node: T_k pulls it toward hardpoint k
    b[9:12] = -F
    x = np.linalg.lstsq(A, b, rcond=None)[0]
    return x[:3], x[3:].reshape(3, 3), A @ x - b


def _cantilever(leg, P, F):
    """The primary as a rigid body pinned at its hardpoint (moments about the origin, not the pin), the
    secondaries as two-force members between their supports and the knee J: unknowns (T_1, T_2, R_p, R_1, R_2);
    12 equations of rank 11 (the primary's spin about its axis is free), least squares."""
    Ap, S = leg.primary_hardpoint, leg.secondary_hardpoints
    J = Ap + leg.knee_offset * _unit(P - Ap)
    A = np.zeros((12, 11))
    b = np.zeros(12)
    for i in range(2):
        to_knee = _unit(J - S[i])
        A[3 * i:3 * i + 3, i] = to_knee               # support node i: T_i toward the knee + R_i = 0
        A[3 * i:3 * i + 3, 5 + 3 * i:8 + 3 * i] = np.eye(3)
        A[6:9, i] = -to_knee                         # on the primary at J
        A[9:12, i] = np.cross(J, -to_knee)
    A[6:9, 2:5] = np.eye(3)                          # R_p at the pin
    A[9:12, 2:5] = np.array([np.cross(Ap, e) for e in np.eye(3)]).T
    b[6:9] = -F
    b[9:12] = -np.cross(P, F)
    x = np.linalg.lstsq(A, b, rcond=None)[0]
    return x[:2], x[2:5], x[5:].reshape(2, 3), A @ x - b, J


@pytest.mark.parametrize("seed", [11, 12])
def test_inverted_tripod_strut_forces_are_the_space_truss_solution(seed):
    # Both are exact for the pin-jointed truss; double rounding of a 3x3 (tripod) and 12x12 (truss) solve on
    # legs with |u . (e1 x e2)| >= 0.02 stays near 1e-13 of the load, so 1e-9 of the largest force is generous
    # yet 1e4 below any error of geometry or sign.
    for leg, P, F in _cases(seed, cantilever=False):
        T, R, residual = _truss(leg, P, F)
        s = strut_forces(leg, F, P)
        scale = max(np.abs(T).max(), np.linalg.norm(F))
        assert np.abs(residual).max() < 1e-9 * scale
        assert np.abs([s.primary, *s.secondaries] - T).max() < 1e-9 * scale
        assert s.primary_upper == s.primary and s.knee_moment == 0.0
        assert np.abs(s.hardpoint_forces + R).max() < 1e-9 * scale        # the leg on the body: -R_k
        assert np.abs(footpad_force(leg, T, P) - F).max() < 1e-9 * scale


@pytest.mark.parametrize("seed", [21, 22])
def test_cantilever_strut_forces_are_the_rigid_primary_solution(seed):
    # Same tolerance argument as the tripod (exact solutions, rounding ~1e-13). The cartridge's force is the
    # section below the knee, F . u; the primary above the knee is -R_p . u from the pin's free body.
    for leg, P, F in _cases(seed, cantilever=True):
        T, Rp, Rs, residual, J = _cantilever(leg, P, F)
        s = strut_forces(leg, F, P)
        u = _unit(P - leg.primary_hardpoint)
        scale = max(np.abs(T).max(), np.linalg.norm(F), np.linalg.norm(Rp))
        assert np.abs(residual).max() < 1e-9 * scale
        assert np.abs(s.secondaries - T).max() < 1e-9 * scale
        assert s.primary == pytest.approx(F @ u, abs=1e-9 * scale)
        assert s.primary_upper == pytest.approx(-Rp @ u, abs=1e-9 * scale)
        assert np.abs(s.hardpoint_forces - np.vstack((-Rp, -Rs))).max() < 1e-9 * scale
        assert np.abs(footpad_force(leg, [s.primary, *T], P) - F).max() < 1e-9 * scale


@pytest.mark.parametrize("seed", [31])
def test_cantilever_bending_moment_is_the_free_body_moment(seed):
    # The moment at a cut x from the tip is |sum (r - c) x f| over the forces below the cut (the tip force,
    # and past the knee the secondaries' forces of the independent solution): below the knee it is the beam
    # closed form |F_perp| x, above it falls linearly to 0 at the pin. Same 1e-9 argument, on |F| Lp.
    for leg, P, F in _cases(seed, cantilever=True):
        T, _, _, _, J = _cantilever(leg, P, F)
        Ap = leg.primary_hardpoint
        u, Lp = _unit(P - Ap), np.linalg.norm(P - Ap)
        knee = np.linalg.norm(P - J)
        x = np.linspace(0.0, Lp, 41)
        expected = []
        for xi in x:
            c = P - xi * u
            m = np.cross(P - c, F)
            if xi > knee:
                m += sum(np.cross(J - c, -t * _unit(J - h)) for t, h in zip(T, leg.secondary_hardpoints))
            expected.append(np.linalg.norm(m))
        scale = np.linalg.norm(F) * Lp
        assert np.abs(bending_moment(leg, F, x, P) - expected).max() < 1e-9 * scale
        perp = np.linalg.norm(np.cross(u, F))
        below = x[x <= knee]
        assert np.abs(bending_moment(leg, F, below, P) - perp * below).max() < 1e-12 * scale
        assert strut_forces(leg, F, P).knee_moment == pytest.approx(perp * knee, rel=1e-12)


def test_cantilever_lever_rule():
    # Vertical primary of length L from the origin, knee a below the pin, horizontal secondaries to the knee from
    # (+-c, d, -a): a side load F_y at the tip needs T_1 = T_2 = -L F_y n / (2 a d) (n = sqrt(c^2 + d^2)) by
    # moments about the pin; the cartridge carries -F_z, the knee moment is |F_y| (L - a). Closed form, 1e-12.
    L, a, c, d = 2.0, 1.4, 0.6, 0.5
    leg = TripodLeg((0, 0, 0), ((c, d, -a), (-c, d, -a)), (0, 0, -L), 1 - a / L, CELL, (CELL, CELL), (CELL, CELL), 0.4)
    Fy, Fz = 3e3, 2e4
    s = strut_forces(leg, (0.0, Fy, Fz))
    T = -L * Fy * np.hypot(c, d) / (2 * a * d)
    assert s.secondaries == pytest.approx([T, T], rel=1e-12)
    assert s.primary == pytest.approx(-Fz, rel=1e-12)
    assert s.knee_moment == pytest.approx(Fy * (L - a), rel=1e-12)


@pytest.mark.parametrize("cantilever", [False, True])
def test_forward_and_inverse_kinematics_are_inverse(cantilever):
    # Trilateration is closed form: both round trips are exact but for rounding (~1e-15 m on metre legs).
    # 1e-12 m leaves room for the square roots' ill-conditioning near |u . (e1 x e2)| = 0.02.
    for leg, P, _ in _cases(41 + cantilever, cantilever):
        L = strut_lengths(leg, P)
        assert np.abs(footpad_position(leg, L) - P).max() < 1e-12
        assert np.abs(strut_lengths(leg, footpad_position(leg, L)) - L).max() < 1e-12


@pytest.mark.parametrize("cantilever", [False, True])
def test_virtual_work_of_the_footpad_force_is_the_struts_work(cantilever):
    # Independent of the statics: F . dP/dL_k (fourth-order central differences of the forward kinematics,
    # (8 (P(h) - P(-h)) - (P(2h) - P(-2h))) / 12h) equals the strut force T_k. The kinematics' derivatives grow
    # as |u . (e1 x e2)|^-k, so the legs here keep it >= 0.1 (validation allows 0.02). Step h = 1e-5 m on metre
    # legs: truncation h^4 |P^(5)| / 30 and rounding eps L / (h |u . (e1 x e2)|) both ~1e-11 of the largest
    # force (measured worst 5e-11); 1e-9 leaves 20 times that. The analytic Jacobian agrees to 1e-8.
    h, n = 1e-5, 0
    for leg, P, F in _cases(51 + cantilever, cantilever):
        if abs(_triple(leg, P)) < 0.1:
            continue
        n += 1
        L = strut_lengths(leg, P)
        s = strut_forces(leg, F, P)
        T = np.array([s.primary, *s.secondaries])
        dP = np.array([(8 * (footpad_position(leg, L + h * e) - footpad_position(leg, L - h * e))
                        - (footpad_position(leg, L + 2 * h * e) - footpad_position(leg, L - 2 * h * e))) / (12 * h)
                       for e in np.eye(3)])                                    # rows: dP/dL_k
        scale = max(np.abs(T).max(), np.linalg.norm(F))
        assert np.abs(dP @ F - T).max() < 1e-9 * scale
        assert np.abs(footpad_jacobian(leg, L) - dP.T).max() < 1e-8 * np.abs(dP).max()
    assert n >= N_LEGS // 4                  # the filter leaves enough legs (62 and more of 200 here)


@pytest.mark.parametrize("cantilever", [False, True])
def test_cells_absorb_the_work_of_the_footpad_force_over_a_stroke(cantilever):
    # Cartridges on their plateaus (constant forces f >= 0): the footpad force G^T T they hold, integrated along
    # a straight 5 cm footpad path (composite Simpson, 200 intervals: error ~h^4, below 1e-12), equals the cells'
    # energy sum f_k * (change of deflection k), exactly for any path (energy conservation of the massless leg).
    rng = np.random.default_rng(61 + cantilever)
    for leg, P0, _ in list(_cases(61 + cantilever, cantilever))[:50]:
        f = rng.uniform(1e3, 3e4, 5)
        f[rng.integers(1, 3)] = 0.0                  # one cell of each secondary pushes
        f[rng.integers(3, 5)] = 0.0
        T = np.array([-f[0], f[2] - f[1], f[4] - f[3]])
        P1 = P0 + _unit(rng.normal(size=3)) * 0.05
        s = np.linspace(0.0, 1.0, 201)
        power = np.array([footpad_force(leg, T, P0 + si * (P1 - P0)) @ (P1 - P0) for si in s])
        work = (power[0] + power[-1] + 4 * power[1:-1:2].sum() + 2 * power[2:-1:2].sum()) / 600.0
        cells = f @ (cell_deflections(leg, strut_lengths(leg, P1)) - cell_deflections(leg, strut_lengths(leg, P0)))
        assert work == pytest.approx(cells, abs=1e-9 * np.abs(f).max() * 0.05)


@pytest.mark.parametrize("attach", [0.0, 0.35])
def test_symmetric_leg_symmetric_and_antisymmetric_loads(attach):
    # Mirror symmetry about the leg's plane (azimuth 30 deg): a load in that plane gives equal secondary forces;
    # a load across it gives opposite ones and no primary force. Exact by symmetry; rounding ~1e-16 of the load.
    az = np.radians(30.0)
    leg = tripod_from_params(2.2, 1.0, 0.4, primary_angle=np.radians(40), secondary_spread=np.radians(35),
                             secondary_attach=attach, secondary_height=-0.2, azimuth=az, primary=CELL,
                             secondary_compression=CELL, secondary_tension=CELL, footpad_diameter=0.5)
    radial, across = np.array([np.cos(az), np.sin(az), 0.0]), np.array([-np.sin(az), np.cos(az), 0.0])
    for F in (np.array([0.0, 0.0, 2e4]), 2e4 * np.array([0, 0, 1]) + 5e3 * radial):
        s = strut_forces(leg, F)
        assert s.secondaries[0] == pytest.approx(s.secondaries[1], rel=1e-12)
    s = strut_forces(leg, 5e3 * across)
    assert s.secondaries[0] == pytest.approx(-s.secondaries[1], rel=1e-12)
    assert abs(s.primary) < 1e-12 * 5e3


def test_cell_deflections_split_each_secondary_into_compression_and_tension():
    # Definition checks with hand numbers: shortening crushes the primary and a compression cell, lengthening
    # a tension cell (deflections exact to rounding of metre lengths, 1e-15).
    leg = tripod_from_params(2.0, 1.0, 0.5, footpad_height=-1.0, secondary_spread=0.6, primary=CELL,
                             secondary_compression=CELL, secondary_tension=CELL, footpad_diameter=0.5)
    d = cell_deflections(leg, leg.rest_lengths + (-0.01, 0.02, -0.03))
    assert d == pytest.approx([0.01, -0.02, 0.02, 0.03, -0.03], abs=1e-15)
    assert leg.cells == (CELL,) * 5


def test_length_jacobian_of_a_tripod_holds_the_unit_strut_vectors():
    # Tripod with orthogonal struts (primary along -z, secondaries along +x and +y to the footpad at the origin):
    # G = rows (0, 0, -1), (1, 0, 0), (0, 1, 0), and the strut forces are (-F_z, F_x, F_y) (method of joints).
    leg = TripodLeg((0, 0, 1), ((-1, 0, 0), (0, -1, 0)), (0, 0, 0), 0.0, CELL, (CELL, CELL), (CELL, CELL), 0.4)
    assert np.abs(length_jacobian(leg, leg.footpad) - [[0, 0, -1], [1, 0, 0], [0, 1, 0]]).max() < 1e-15
    s = strut_forces(leg, (1.0, 2.0, 3.0))
    assert [s.primary, *s.secondaries] == pytest.approx([-3.0, 1.0, 2.0], abs=1e-15)


@pytest.mark.parametrize("change, name", [
    ({"secondary_attach": 1.0}, "secondary_attach"),
    ({"secondary_attach": -0.1}, "secondary_attach"),
    ({"footpad": (0, 0, 1)}, "footpad"),
    ({"secondary_hardpoints": ((0, 0, 0), (0, -1, 0))}, r"secondary_hardpoints\[0\]"),
    ({"secondary_hardpoints": ((-1, 0, 0), (1, 0, 0))}, "secondary_hardpoints: the struts meet"),
    ({"secondary_hardpoints": ((-1, 0, 0), (1, 0.01, 0.5))}, "nearly coplanar"),
    ({"secondary_attach": 0.02}, "primary: its curve runs"),
    ({"footpad_diameter": 0.0}, "footpad_diameter"),
    ({"footpad_mass": -1.0}, "footpad_mass"),
    ({"footpad": (0, 0)}, "footpad"),
    ({"secondary_tension": (CELL,)}, "secondary_tension"),
])
def test_invalid_geometry_is_refused_naming_the_parameter(change, name):
    kw = dict(primary_hardpoint=(0, 0, 1), secondary_hardpoints=((-1, 0, 0), (0, -1, 0)), footpad=(0, 0, 0),
              secondary_attach=0.0, primary=CELL, secondary_compression=(CELL, CELL),
              secondary_tension=(CELL, CELL), footpad_diameter=0.4)
    with pytest.raises(ValueError, match=name):
        TripodLeg(**{**kw, **change})


@pytest.mark.parametrize("change, name", [
    ({"primary_angle": 0.5, "footpad_height": -1.0}, "primary_angle, footpad_height"),
    ({"primary_angle": None}, "primary_angle, footpad_height"),
    ({"primary_angle": 2.0}, "primary_angle"),
    ({"footpad_radius": 0.8}, "primary_angle"),
    ({"secondary_spread": 0.0}, "secondary_spread"),
    ({"hardpoint_radius": 0.0}, "hardpoint_radius"),
    ({"primary_angle": None, "footpad_height": 0.6}, "footpad_height"),
])
def test_invalid_parameters_are_refused_naming_the_parameter(change, name):
    kw = dict(footpad_radius=2.0, hardpoint_radius=1.0, hardpoint_height=0.5, primary_angle=0.6,
              secondary_spread=0.6, primary=CELL, secondary_compression=CELL, secondary_tension=CELL,
              footpad_diameter=0.4)
    with pytest.raises(ValueError, match=name):
        tripod_from_params(**{**kw, **change})


def test_primary_angle_places_the_footpad():
    # tan(angle) = (footpad radius - hardpoint radius) / (hardpoint height - footpad height): 45 deg, 1 m out,
    # 1 m down (closed form, 1e-15).
    leg = tripod_from_params(2.0, 1.0, 0.5, primary_angle=np.pi / 4, secondary_spread=0.6, primary=CELL,
                             secondary_compression=CELL, secondary_tension=CELL, footpad_diameter=0.4)
    assert leg.footpad == pytest.approx([2.0, 0.0, -0.5], abs=1e-15)
