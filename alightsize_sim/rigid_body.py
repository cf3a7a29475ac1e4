"""Rigid-body kinematics and dynamics of the capsule (AFFDL-TR-66-33 Sec. V.B-D, V.G).

Attitude is a unit quaternion q = (w, x, y, z) taking principal-axis (eta) components to terrain (epsilon)
components, so no attitude is singular (the report's roll-yaw-pitch rates, eq. 9-11, are singular at yaw
90 deg). Euler's equations (eq. 6-8) in principal axes; free flight of an axisymmetric body in closed form
(the symmetric top of eq. 62-88) as a rotation about the fixed angular-momentum axis composed with a
rotation about the symmetry axis.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def quat_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrix (body -> terrain) of the quaternion q, normalized here (any nonzero length)."""
    w, x, y, z = q[0], q[1], q[2], q[3]
    k = 2.0 / (w * w + x * x + y * y + z * z)
    m = np.empty((3, 3))
    m[0, 0], m[0, 1], m[0, 2] = 1 - k * (y * y + z * z), k * (x * y - w * z), k * (x * z + w * y)
    m[1, 0], m[1, 1], m[1, 2] = k * (x * y + w * z), 1 - k * (x * x + z * z), k * (y * z - w * x)
    m[2, 0], m[2, 1], m[2, 2] = k * (x * z - w * y), k * (y * z + w * x), 1 - k * (x * x + y * y)
    return m


@njit(cache=True)
def quat_matrices(Q: np.ndarray) -> np.ndarray:
    """quat_matrix of every row of Q (n, 4): (n, 3, 3)."""
    out = np.empty((Q.shape[0], 3, 3))
    for k in range(Q.shape[0]):
        out[k] = quat_matrix(Q[k])
    return out


def matrix_quat(m: np.ndarray) -> np.ndarray:
    """Unit quaternion (w >= 0) of a rotation matrix (Shepperd's method: well conditioned everywhere)."""
    tr = np.trace(m)
    cand = np.array([tr, m[0, 0], m[1, 1], m[2, 2]])
    i = int(np.argmax(cand))
    if i == 0:
        w = 0.5 * np.sqrt(1 + tr)
        q = np.array([w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w), (m[1, 0] - m[0, 1]) / (4 * w)])
    else:
        j, k = (i % 3) + 1, ((i + 1) % 3) + 1
        a, b, c = i - 1, j - 1, k - 1
        s = 0.5 * np.sqrt(1 + m[a, a] - m[b, b] - m[c, c])
        q = np.empty(4)
        q[i] = s
        q[0] = (m[c, b] - m[b, c]) / (4 * s)
        q[j] = (m[b, a] + m[a, b]) / (4 * s)
        q[k] = (m[c, a] + m[a, c]) / (4 * s)
    return q if q[0] >= 0 else -q


@njit(cache=True)
def quat_rate(q: np.ndarray, omega: np.ndarray, out: np.ndarray) -> np.ndarray:
    """dq/dt = q (x) (0, omega) / 2 of the unit quaternion along q, omega in body axes, written to out."""
    n = 0.5 / np.sqrt(q[0] ** 2 + q[1] ** 2 + q[2] ** 2 + q[3] ** 2)
    w, x, y, z = n * q[0], n * q[1], n * q[2], n * q[3]
    p, r, s = omega[0], omega[1], omega[2]
    out[0], out[1] = -x * p - y * r - z * s, w * p + y * s - z * r
    out[2], out[3] = w * r + z * p - x * s, w * s + x * r - y * p
    return out


@njit(cache=True)
def euler_rates(inertia: np.ndarray, omega: np.ndarray, moment: np.ndarray) -> np.ndarray:
    """Angular acceleration in principal axes: I w' = M - w x (I w) (eq. 6-8)."""
    return (moment - np.cross(omega, inertia * omega)) / inertia


def axis_rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    """Rotation matrix about a unit axis (Rodrigues)."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * (k @ k)


@njit(cache=True)
def quat_multiply(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Hamilton product p (x) q (the rotation q, then p)."""
    out = np.empty(4)
    out[0] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3]
    out[1] = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2]
    out[2] = p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1]
    out[3] = p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0]
    return out


@njit(cache=True)
def free_flight(r0, v0, q0, omega0, inertia, gravity, t):
    """Closed-form free flight of a body with inertia (A, A, C) after time t: (r, v, q, omega).

    Translation is a parabola; with H = R I omega fixed in space, R(t) = Rot(H/|H|, |H| t / A) R0
    Rot(e3, (A - C) omega3 t / A) (the symmetric top, AFFDL-TR-66-33 eq. 62-88), composed as quaternions;
    the body rates keep omega3 and turn (omega1, omega2) at (C - A) omega3 / A.
    """
    a, c = inertia[0], inertia[2]
    if abs(a - inertia[1]) > 1e-12 * max(a, inertia[1]):
        raise ValueError("closed-form free flight needs an axisymmetric body (A = B)")
    r = r0 + v0 * t + 0.5 * gravity * t * t
    v = v0 + gravity * t
    h = quat_matrix(q0) @ (inertia * omega0)
    hn = np.sqrt(h[0] ** 2 + h[1] ** 2 + h[2] ** 2)
    spin = (a - c) * omega0[2] / a
    qs = np.array([1.0, 0.0, 0.0, 0.0])
    if hn > 0.0:
        half = 0.5 * hn * t / a
        qs = np.array([np.cos(half), np.sin(half) * h[0] / hn, np.sin(half) * h[1] / hn, np.sin(half) * h[2] / hn])
    qb = np.array([np.cos(0.5 * spin * t), 0.0, 0.0, np.sin(0.5 * spin * t)])
    q = quat_multiply(quat_multiply(qs, q0), qb)
    lam = -spin * t                      # body rates turn opposite the relative spin
    cl, sl = np.cos(lam), np.sin(lam)
    omega = np.array([cl * omega0[0] - sl * omega0[1], sl * omega0[0] + cl * omega0[1], omega0[2]])
    return r, v, q / np.sqrt(q @ q), omega


def roll_yaw_pitch(m: np.ndarray) -> tuple[float, float, float]:
    """(roll, yaw, pitch) of a geometric-body -> vertical (kappa) matrix m = R3(roll) R2(yaw) R1(pitch): the
    3-2-1 sequence about chi-3, chi-2, chi-1 (eq. 2 as FUNEV writes LKX)."""
    yaw = float(np.arcsin(np.clip(-m[2, 0], -1.0, 1.0)))
    roll = float(np.arctan2(m[1, 0], m[0, 0]))
    pitch = float(np.arctan2(m[2, 1], m[2, 2]))
    return roll, yaw, pitch
