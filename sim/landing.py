"""One landing of a rigid capsule on telescoping legs (AFFDL-TR-66-33 Sec. V).

State y = (r, v in terrain axes; q body->terrain; omega in principal axes; W the work the legs have done
on the cells). An embedded Runge-Kutta pair (Dormand-Prince 5(4)) with error control, or fixed steps,
advances it; leg touchdown and lift-off are located in time by bisection on the step size (to `event_tol`
seconds), and the cells' memory and contact points change only on accepted steps. Footpads hold where they
touched (no slip: friction enough); sliding is a later step of issue 4.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import crush_cell
from .rigid_body import euler_rates, quat_matrix, quat_rate
from .telescoping_leg import TelescopingLeg, axial_deflection, axial_set, free_footpad, leg_load

# Dormand-Prince 5(4) tableau.
_C = np.array([0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1, 1])
_A = [[], [1 / 5], [3 / 40, 9 / 40], [44 / 45, -56 / 15, 32 / 9],
      [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729],
      [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656],
      [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]]
_B5 = np.array([35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0])
_B4 = np.array([5179 / 57600, 0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40])


@dataclass(frozen=True)
class Scene:
    """Mass (kg), principal inertias (kg m^2), legs (principal axes), gravity in terrain axes (m/s^2),
    initial velocity (terrain), attitude quaternion and body rates (principal axes)."""

    mass: float
    inertia: np.ndarray
    legs: tuple[TelescopingLeg, ...]
    gravity: np.ndarray
    v0: np.ndarray
    q0: np.ndarray
    omega0: np.ndarray


@dataclass(frozen=True)
class Controls:
    t_final: float = 1.0
    rtol: float = 1e-6
    atol: float = 1e-9
    fixed_step: float | None = None
    max_step: float = 2e-3
    event_tol: float = 1e-10


@dataclass
class LegState:
    memory: np.ndarray                 # (n_cells, 2): dmax, fmax
    contact: bool = False
    P: np.ndarray = field(default_factory=lambda: np.zeros(3))
    tilt: tuple[float, float] = (0.0, 0.0)
    armed: bool = False                # the next switch needs a clear crossing (see _events)


@dataclass
class Result:
    t: np.ndarray
    y: np.ndarray                      # (n, 14)
    deflections: list                  # per leg: (n, n_cells)
    forces: list
    accel_g: np.ndarray                # CG acceleration in principal axes, multiples of g0
    legs: list[LegState]
    steps: int
    rejected: int
    rhs_evals: int
    energy: dict


G0 = 9.80665


def _loads(scene: Scene, states: list[LegState], y: np.ndarray):
    r, v, q, w = y[0:3], y[3:6], y[6:10], y[10:13]
    R = quat_matrix(q / np.linalg.norm(q))
    out = []
    for leg, st in zip(scene.legs, states):
        out.append(leg_load(leg, st.memory, st.P, r, R, v, w) if st.contact else None)
    return R, out


def rhs(scene: Scene, states: list[LegState], y: np.ndarray) -> np.ndarray:
    """dy/dt: eq. 3-5 in terrain axes, Euler's equations in principal axes, quaternion rate, cell power."""
    R, loads = _loads(scene, states, y)
    f_body, m_body, power = np.zeros(3), np.zeros(3), 0.0
    for ld in loads:
        if ld is not None:
            f_body += ld.force
            m_body += np.cross(ld.point, ld.force)
            power += ld.power
    dy = np.empty_like(y)
    dy[0:3] = y[3:6]
    dy[3:6] = scene.gravity + R @ f_body / scene.mass
    dy[6:10] = quat_rate(y[6:10], y[10:13])
    dy[10:13] = euler_rates(scene.inertia, y[10:13], m_body)
    dy[13] = power
    return dy


ARM = 1e-7          # m: a leg's next switch is armed once it is this far from its last one
BAND = 1e-4         # m: an unarmed leg switches only this far past zero (grazing contact never chatters)


def _events(scene: Scene, states: list[LegState], y: np.ndarray, raw: bool = False) -> np.ndarray:
    """Per leg: free footpad height (off the ground) or axial compression beyond the set (on the ground);
    an event is a crossing of zero from above. Right after a switch the leg is unarmed and the threshold
    sits BAND past zero, so a footpad that grazes the terrain (touches while the leg would extend) stays
    in contact at zero force until it clearly leaves, instead of switching at every step."""
    r, q = y[0:3], y[6:10]
    R = quat_matrix(q / np.linalg.norm(q))
    out = np.empty(len(scene.legs))
    for i, (leg, st) in enumerate(zip(scene.legs, states)):
        if st.contact:
            out[i] = axial_deflection(leg, st.P, r, R) - axial_set(leg, st.memory)
        else:
            out[i] = free_footpad(leg, st.memory, st.tilt, r, R)[2]
        if not (raw or st.armed):
            out[i] += BAND
    return out


def _step(scene, states, y, h, k1):
    k = [k1]
    for i in range(1, 7):
        yi = y + h * sum(a * kj for a, kj in zip(_A[i], k))
        k.append(rhs(scene, states, yi))
    y5 = y + h * sum(b * kj for b, kj in zip(_B5, k))
    err = h * sum((b5 - b4) * kj for b5, b4, kj in zip(_B5, _B4, k))
    return y5, err, k[6]


def initial_state(scene: Scene) -> tuple[np.ndarray, list[LegState]]:
    """y0 with the CG placed so the lowest footpad touches the terrain at t = 0 (first contact by
    construction, as FORCE shifts R(3) by XMIN)."""
    states = [LegState(np.zeros((len(leg.cells), 2))) for leg in scene.legs]
    R = quat_matrix(scene.q0)
    heights = [free_footpad(leg, st.memory, st.tilt, np.zeros(3), R)[2] for leg, st in zip(scene.legs, states)]
    r0 = np.array([0.0, 0.0, -min(heights)])
    y0 = np.concatenate([r0, scene.v0, scene.q0, scene.omega0, [0.0]])
    for leg, st, h in zip(scene.legs, states, heights):
        if abs(h - min(heights)) <= 1e-12:
            st.contact = True
            st.P = free_footpad(leg, st.memory, st.tilt, r0, R) * np.array([1, 1, 0])
    return y0, states


def _commit(scene: Scene, states: list[LegState], y: np.ndarray) -> list:
    """Arm legs clear of their last switch and update cell memory at an accepted state; the leg loads there."""
    for st, g in zip(states, _events(scene, states, y, raw=True)):
        st.armed = st.armed or g > ARM
    R, loads = _loads(scene, states, y)
    for leg, st, ld in zip(scene.legs, states, loads):
        if ld is None:
            continue
        for j, cell in enumerate(leg.cells):
            dd, ff, k, c, yf = cell.arrays
            st.memory[j] = crush_cell.commit(dd, ff, yf, st.memory[j, 0], st.memory[j, 1], ld.deflections[j])
    return loads


def _switch(scene: Scene, states: list[LegState], y: np.ndarray, which: int) -> None:
    st, leg = states[which], scene.legs[which]
    st.armed = False
    r, R = y[0:3], quat_matrix(y[6:10] / np.linalg.norm(y[6:10]))
    if st.contact:                                    # lift-off: remember the tilt for recontact (eq. 13)
        ld = leg_load(leg, st.memory, st.P, r, R, y[3:6], y[10:13])
        st.contact, st.tilt = False, (ld.alpha, ld.beta)
    else:                                             # touchdown: the footpad holds here
        st.contact, st.P = True, free_footpad(leg, st.memory, st.tilt, r, R) * np.array([1, 1, 0])


def energy(scene: Scene, y: np.ndarray) -> tuple[float, float]:
    """(kinetic, potential relative to r = 0) in J."""
    R = quat_matrix(y[6:10] / np.linalg.norm(y[6:10]))
    ke = 0.5 * scene.mass * y[3:6] @ y[3:6] + 0.5 * np.sum(scene.inertia * y[10:13] ** 2)
    return float(ke), float(-scene.mass * scene.gravity @ y[0:3])


def simulate(scene: Scene, ctl: Controls) -> Result:
    """Integrate from first contact to ctl.t_final."""
    y, states = initial_state(scene)
    t, h = 0.0, ctl.fixed_step or min(1e-4, ctl.max_step)
    ts, ys = [t], [y.copy()]
    k1 = rhs(scene, states, y)
    nrhs, steps, rejected = 1, 0, 0
    g_prev = _events(scene, states, y)
    defl = [[np.zeros(len(leg.cells))] for leg in scene.legs]
    frc = [[np.zeros(len(leg.cells))] for leg in scene.legs]
    acc = [k1[3:6]]
    while t < ctl.t_final - 1e-15:
        h = min(h, ctl.t_final - t)
        y1, err, k7 = _step(scene, states, y, h, k1)
        nrhs += 6
        if ctl.fixed_step is None:
            scale = ctl.atol + ctl.rtol * np.maximum(np.abs(y), np.abs(y1))
            e = float(np.sqrt(np.mean((err / scale) ** 2)))
            if e > 1.0:
                rejected += 1
                h *= max(0.2, 0.9 * e ** -0.2)
                continue
        g1 = _events(scene, states, y1)
        crossed = np.where((g_prev > 0) & (g1 <= 0))[0] if np.any(g1 <= 0) else []
        which = None
        if len(crossed):                              # locate the earliest event by bisection on the step
            lo, hi = 0.0, h
            while hi - lo > ctl.event_tol:
                mid = 0.5 * (lo + hi)
                ym = _step(scene, states, y, mid, k1)[0]
                nrhs += 6
                gm = _events(scene, states, ym)
                if np.any((g_prev > 0) & (gm <= 0)):
                    hi = mid
                else:
                    lo = mid
            h_acc = hi
            y1, _, k7 = _step(scene, states, y, h_acc, k1)
            gh = _events(scene, states, y1)
            which = int(crossed[np.argmin([abs(gh[i]) for i in crossed])]) if len(crossed) > 1 else int(crossed[0])
        else:
            h_acc = h
        t += h_acc
        y = y1
        y[6:10] /= np.linalg.norm(y[6:10])
        steps += 1
        loads = _commit(scene, states, y)
        if which is None:
            k1 = k7                                   # first same as last: memory updates keep the force
        else:
            _switch(scene, states, y, which)
            k1 = rhs(scene, states, y)
            nrhs += 1
        g_prev = _events(scene, states, y)
        for i, ld in enumerate(loads):              # as committed (a switching leg shows its pre-switch state)
            defl[i].append(ld.deflections if ld is not None else np.full(len(scene.legs[i].cells), np.nan))
            frc[i].append(ld.forces if ld is not None else np.zeros(len(scene.legs[i].cells)))
        ts.append(t)
        ys.append(y.copy())
        acc.append(k1[3:6])
        if ctl.fixed_step is None and which is None:
            h = min(ctl.max_step, h * min(5.0, 0.9 * max(e, 1e-10) ** -0.2))
        elif ctl.fixed_step is not None:
            h = ctl.fixed_step
    Y = np.array(ys)
    accel = np.array([quat_matrix(yy[6:10]).T @ (a - scene.gravity) for yy, a in zip(Y, acc)]) / G0
    ke0, pe0 = energy(scene, Y[0])
    ke1, pe1 = energy(scene, Y[-1])
    elastic = 0.0
    for leg, st, dl in zip(scene.legs, states, defl):
        for j, cell in enumerate(leg.cells):
            last = dl[-1][j]
            if np.isfinite(last):
                elastic += crush_cell.elastic_energy(cell.k, st.memory[j, 0], st.memory[j, 1], last)
    work = float(Y[-1, 13])
    released = pe0 - pe1
    closure = abs(ke0 + released - (work + ke1)) / (ke0 + max(released, 0.0))
    en = {"initial_J": ke0, "potential_change_J": released, "absorbed_J": work - elastic, "elastic_J": elastic,
          "friction_J": 0.0, "kinetic_end_J": ke1, "closure_rel": closure}
    return Result(np.array(ts), Y, [np.array(d) for d in defl], [np.array(f) for f in frc], accel, states,
                  steps, rejected, nrhs, en)
