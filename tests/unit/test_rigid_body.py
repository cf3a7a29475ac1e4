"""Rigid body: quaternion algebra, Euler's equations against the closed-form free flight."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from alightsize_sim.rigid_body import (axis_rotation, euler_rates, free_flight, matrix_quat, quat_matrices, quat_matrix,
                                      quat_rate, roll_yaw_pitch)

INERTIA = np.array([3.326, 3.326, 2.77])     # slug ft^2 numbers of the test model (App. VI), units immaterial


def test_quaternion_matrix_round_trip():
    rng = np.random.default_rng(0)
    for _ in range(200):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        q = q if q[0] >= 0 else -q
        m = quat_matrix(q)
        assert np.allclose(m @ m.T, np.eye(3), atol=1e-14) and np.linalg.det(m) == pytest.approx(1.0)
        assert np.allclose(matrix_quat(m), q, atol=1e-14)


def test_quaternion_matrices_of_rows_are_the_rows_matrices():
    """The batch form used on histories gives each row's matrix bit for bit (the same compiled formula)."""
    Q = np.random.default_rng(1).normal(size=(50, 4))
    assert np.array_equal(quat_matrices(Q), np.array([quat_matrix(q) for q in Q]))


def test_roll_yaw_pitch_321():
    roll, yaw, pitch = 0.3, -0.2, 1.1
    m = axis_rotation(np.array([0, 0, 1.0]), roll) @ axis_rotation(np.array([0, 1.0, 0]), yaw) \
        @ axis_rotation(np.array([1.0, 0, 0]), pitch)          # LKX = R3(roll) R2(yaw) R1(pitch), eq. 2
    assert np.allclose(roll_yaw_pitch(m), (roll, yaw, pitch), atol=1e-14)


def _integrate(q0, w0, t):
    def rhs(_, y):
        return np.concatenate([quat_rate(y[:4], y[4:], np.empty(4)), euler_rates(INERTIA, y[4:], np.zeros(3))])
    sol = solve_ivp(rhs, (0, t), np.concatenate([q0, w0]), method="DOP853", rtol=1e-13, atol=1e-14)
    return sol.y[:4, -1], sol.y[4:, -1]


def test_free_flight_closed_form_matches_integration_with_3_rad_s_roll():
    # Issue 4: closed form and integration agree to 1e-9 over 1 s with a 3 rad/s roll; momentum to 1e-12.
    q0 = matrix_quat(axis_rotation(np.array([0.6, 0.0, 0.8]), 0.4))
    w0 = np.array([0.4, -0.7, 3.0])
    g = np.array([0.0, -1.2, -9.7])
    r, v, q, w = free_flight(np.zeros(3), np.array([1.0, 2.0, -10.0]), q0, w0, INERTIA, g, 1.0)
    qi, wi = _integrate(q0, w0, 1.0)
    qi = qi / np.linalg.norm(qi) * np.sign(qi[0])
    assert np.max(np.abs(quat_matrix(q) - quat_matrix(qi))) < 1e-9 and np.max(np.abs(w - wi)) < 1e-9
    assert np.allclose(r, [1.0, 2.0 - 0.6, -10.0 - 4.85], atol=1e-15)
    h0 = quat_matrix(q0) @ (INERTIA * w0)
    for t in np.linspace(0, 1, 11):
        _, _, qt, wt = free_flight(np.zeros(3), np.zeros(3), q0, w0, INERTIA, g, t)
        assert np.max(np.abs(quat_matrix(qt) @ (INERTIA * wt) - h0)) < 1e-12 * np.linalg.norm(h0)
