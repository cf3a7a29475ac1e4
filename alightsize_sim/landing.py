"""One landing of a rigid capsule on telescoping, articulated or tripod legs (AFFDL-TR-66-33 Sec. V).

`simulate(scene, controls)` places the capsule so that its lowest footpad touches the terrain at t = 0 and
runs the compiled step loop (`landing_kernel.run`; free flight of an axisymmetric capsule in closed form).
It returns the history at every accepted step, the outcome and the energy audit.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from . import crush_cell
from . import landing_kernel as lk
from .rigid_body import quat_matrices, quat_matrix
from .stability import quiescence_momenta
from .articulated_leg import ArticulatedLeg
from .footpad_mass import NB, PadModel, n_states, pad_model
from .soil import Soil
from .legs import TRIPOD, free_footpad, initial_shape, pack, with_terrain
from .terrain import Terrain, clearance
from .terrain import pack as pack_terrain
from .telescoping_leg import TelescopingLeg
from .tripod_leg import TripodLeg, strut_axial_forces

G0 = 9.80665


@dataclass(frozen=True)
class Scene:
    """Mass (kg), principal inertias (kg m^2), legs (principal axes), gravity in terrain axes (m/s^2),
    initial velocity (terrain), attitude quaternion (principal -> terrain) and body rates (principal axes),
    static and dynamic friction, the capsule's up axis and body points (principal axes, from the CG) that
    must stay clear of the terrain, the mass of each footpad (kg; 0: massless footpads that slide by a root
    search, the report's model), the Karnopp velocity band of footpads with mass (m/s; footpad_mass), the
    terrain's features on the plane (terrain axes, from the capsule's first-contact CG; alightsize_sim.terrain),
    the soil on it (None: rigid ground; needs footpads with mass) and the footpads' diameter (m; round
    footpads bearing on the soil)."""

    mass: float
    inertia: np.ndarray
    legs: tuple[TelescopingLeg | ArticulatedLeg | TripodLeg, ...]
    gravity: np.ndarray
    v0: np.ndarray
    q0: np.ndarray
    omega0: np.ndarray
    mu_static: float = 1.5e6
    mu_dynamic: float = 1.0e6
    up: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]))
    body_points: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    footpad_mass: float = 0.0
    footpad_band: float = 1e-2
    terrain: Terrain = field(default_factory=Terrain)
    soil: Soil | None = None
    footpad_diameter: float = 0.0

    def __post_init__(self):
        if self.soil is not None and not (self.footpad_mass > 0.0 and self.footpad_diameter > 0.0):
            raise ValueError("a scene on soil needs footpads with mass and a diameter (footpad_mass, "
                             "footpad_diameter > 0)")
        if any(isinstance(leg, TripodLeg) for leg in self.legs) and not self.footpad_mass > 0.0 and not holds(self):
            raise ValueError("tripod legs on ground they can slip on need footpads with mass (footpad_mass > 0): "
                             "their massless slide does not converge (docs/simulator.md)")


@dataclass(frozen=True)
class Controls:
    """Run controls: final time, error tolerances or a fixed step, largest step, event location tolerance,
    critical tip angle (nutation from the vertical), body clearance, quiescence (fraction of the
    first-contact momentum held for `taus` periods of `period` seconds; off when taus = 0), the time from
    which the energy criterion of eq. 89-95 may end the run as stable (None: never), whether bottoming ends
    the run, whether free flight is flown in closed form, the first step and the grazing band (m): a leg that has
    just touched down lifts off only once its main cell is this far short of its set, where it carries no force
    (landing_kernel._events; converged results do not depend on it)."""

    t_final: float = 1.0
    rtol: float = 1e-6
    atol: float = 1e-9
    fixed_step: float | None = None
    max_step: float = 2e-3
    event_tol: float = 1e-7
    tip_angle: float = np.radians(90.0)
    body_clearance: float = 0.0
    quiet_fraction: float = 0.025
    taus: float = 0.0
    period: float = 0.0
    energy_check_from: float | None = 0.05
    stop_on_bottoming: bool = True
    closed_form_flight: bool = True
    first_step: float = 1e-4
    contact_band: float = lk.BAND

    def __post_init__(self):
        least = max(10.0 * lk.ARM, lk.GRAZE_SPEED * self.event_tol)
        if not self.contact_band >= least:
            raise ValueError(f"the grazing band must be at least {least:g} m: ten times the distance that re-arms a "
                             f"leg's switch and what a footpad at {lk.GRAZE_SPEED:g} m/s crosses in event_tol, so that "
                             "a leg cannot touch and leave within one located event")


@dataclass
class Result:
    t: np.ndarray
    y: np.ndarray                      # (n, 14): r, v, q, omega, W
    dy: np.ndarray                     # (n, 14) derivatives at the accepted points
    deflections: np.ndarray            # (n, legs, cells); NaN off the ground
    forces: np.ndarray                 # (n, legs, cells)
    leg_force: np.ndarray              # (n, legs, 3) ground force on the capsule, principal axes
    footpad: np.ndarray                # (n, legs, 3) terrain axes
    footpad_velocity: np.ndarray       # (n, legs, 3) terrain axes (zero unless the footpads have mass)
    contact: np.ndarray                # (n, legs)
    status: str
    bottomed: tuple | None             # (time, leg, cell) of the first bottoming
    struck: int | None                 # the leg whose intermediate member struck the terrain (a tripod: folded flat)
    cell_energy: np.ndarray            # (legs, cells) J
    memory: np.ndarray                 # (legs, cells, 2) final dmax, fmax
    steps: int
    rejected: int
    rhs_evals: int
    events: int                        # located events (touchdown, lift-off, stick-to-slip, cell turns, corners)
    event_trials: int                  # trial steps spent locating them
    wall_s: float
    energy: dict

    gravity: np.ndarray
    struts: np.ndarray | None = None   # (n, legs, 3) tripod legs' strut axial forces (N, tension positive: primary,
                                       # secondary 1, 2; tripod_leg.strut_axial_forces), NaN for other kinds; None
                                       # without tripods

    @property
    def accel_g(self) -> np.ndarray:
        return accel_g(self.y, self.dy, self.gravity)


def accel_g(y: np.ndarray, dy: np.ndarray, gravity: np.ndarray) -> np.ndarray:
    """CG acceleration less gravity (what an accelerometer reads) in principal axes, multiples of g0, for
    states y and derivatives dy (rows)."""
    y, dy = np.atleast_2d(y), np.atleast_2d(dy)
    R = quat_matrices(np.ascontiguousarray(y[:, 6:10]))
    return np.einsum("nji,nj->ni", R, dy[:, 3:6] - gravity) / G0


HELD_FRICTION = 1e3   # a loaded footpad would slide only under an in-plane force 1,000 times the normal one
STATUS = {lk.END: "end", lk.BOTTOMED: "bottomed", lk.TIPPED: "tipped", lk.BODY: "body_contact",
          lk.QUIET: "quiet", lk.FAILED: "failed", lk.STABLE: "stable", lk.MEMBER: "member_strike",
          lk.FOLDED: "folded_flat"}


def holds(scene: Scene) -> bool:
    """Whether the scene's footpads cannot slip: static and dynamic friction of HELD_FRICTION or more (the
    report's non-slip 1.5e6). The simulator then holds each footpad where it touched, with no slip search."""
    return min(scene.mu_static, scene.mu_dynamic) >= HELD_FRICTION


def variant(scene: Scene) -> str:
    """The compiled variant a scene runs on, in words: its leg kinds and footpad model (each compiles once per
    machine: numba specializes the kernel on them)."""
    kinds = sorted({"articulated" if isinstance(leg, ArticulatedLeg) else "tripod" if isinstance(leg, TripodLeg)
                    else "telescoping" for leg in scene.legs})
    pads = ("footpads with mass on soil" if scene.soil is not None else "footpads with mass" if scene.footpad_mass > 0
            else "footpads that hold" if holds(scene) else "sliding footpads")
    return f"{' and '.join(kinds)} legs, {pads}"


compiling_for = ""          # the variant of the last landing set up here (read by a compile notice, if any)


def axisymmetric(inertia: np.ndarray) -> bool:
    return abs(inertia[0] - inertia[1]) <= 1e-9 * max(inertia[0], inertia[1])


class _Run:
    """Arrays the compiled loop reads and updates in place."""

    def __init__(self, scene: Scene, ctl: Controls):
        self.scene, self.ctl = scene, ctl
        geo, self.cells = pack(scene.legs)
        self.geo = with_terrain(geo, pack_terrain(scene.terrain))     # geo[9]: the terrain (alightsize_sim.terrain)
        n, C = self.cells[2].shape
        self.n, self.C = n, C
        self.bottoming = np.full((n, C), np.inf)
        for i, leg in enumerate(scene.legs):
            for j, cell in enumerate(leg.cells):
                self.bottoming[i, j] = cell.curve.bottoming
        # The slide's tolerance follows the integration's: 1e-3 rtol, within 1e-13..1e-8 (docs/simulator.md).
        # Footpads on soil sink whatever the friction: they need the footpad-mass model.
        if holds(scene) and scene.soil is None:
            self.mu = None
        elif scene.footpad_mass > 0.0:
            self.mu = pad_model(scene.mu_static, scene.mu_dynamic, scene.footpad_mass, scene.footpad_band,
                                scene.soil, scene.footpad_diameter, holds(scene))
        else:
            self.mu = np.array([scene.mu_static, scene.mu_dynamic, min(max(1e-3 * ctl.rtol, 1e-13), 1e-8)])
        self.soil = scene.soil is not None
        self.ny = n_states(n, C, self.soil) if isinstance(self.mu, PadModel) else NB
        self.mem = np.zeros((n, C, 2))
        self.contact = np.zeros(n, np.int64)
        self.P = np.zeros((n, 3))
        self.sliding = np.zeros(n, np.int64)
        self.shape = initial_shape(scene.legs)
        self.armed = np.zeros(n, np.int64)
        self.energy = np.zeros((n, C))
        self.last = np.zeros((n, 2 * C + 1))
        self.scratch = lk.new_scratch(n, C, self.ny)
        self.work = self.scratch[lk.SCRATCH_WORK]    # the legs' state at the current point, the step loop's too
        self.cev = lk.cell_events(self.cells, self.mem)
        self.cnt = np.zeros(6, np.int64)
        self.run_state = np.array([ctl.first_step, 0.0, 0.0, -1.0, -1.0, -1.0, -1.0, -1.0, 0.0])
        self.ctl_arr = np.array([ctl.t_final, ctl.rtol, ctl.atol, ctl.fixed_step or 0.0, ctl.max_step, ctl.event_tol,
                                 float(ctl.stop_on_bottoming), np.cos(ctl.tip_angle), ctl.body_clearance,
                                 float(ctl.closed_form_flight and axisymmetric(scene.inertia)), ctl.quiet_fraction,
                                 ctl.taus, ctl.period,
                                 -1.0 if ctl.energy_check_from is None else ctl.energy_check_from,
                                 ctl.contact_band])
        attach = np.array([leg.attach for leg in scene.legs])
        self.order = np.argsort(np.arctan2(attach[:, 1], attach[:, 0])).astype(np.int64)
        # The compiled functions' view of the landing, in landing_kernel.LANDING's order.
        named = dict(geo=self.geo, cells=self.cells, mass=scene.mass, inertia=scene.inertia, gravity=scene.gravity,
                     mu=self.mu, bottoming=self.bottoming, up=scene.up, body=scene.body_points, order=self.order,
                     mem=self.mem, contact=self.contact, P=self.P, sliding=self.sliding, shape=self.shape,
                     armed=self.armed, cev=self.cev, energy=self.energy, last=self.last, ctl=self.ctl_arr,
                     cnt=self.cnt, run_state=self.run_state)
        self.arrays = tuple(named[name] for name in lk.LANDING.fields)
        self._grow(1024)

    def _grow(self, size: int):
        n, C = self.n, self.C
        new = dict(H_t=np.empty(size), H_y=np.empty((size, self.ny)), H_dy=np.empty((size, self.ny)),   # rows
                   H_d=np.empty((size, n, C)), H_f=np.empty((size, n, C)), H_X=np.empty((size, n, 3)),  # as
                   H_P=np.empty((size, n, 3)), H_c=np.empty((size, n), np.int64))   # recorded
        k = int(self.cnt[lk.K_HIST])
        for name, arr in new.items():
            if k:
                arr[:k] = getattr(self, name)[:k]
            setattr(self, name, arr)

    def heights(self, r: np.ndarray, R: np.ndarray) -> np.ndarray:
        feet = [free_footpad(self.geo, self.cells, i, self.mem[i], self.shape[i], r, R) for i in range(self.n)]
        return np.array([clearance(self.geo[9], *foot) for foot in feet])

    def loop(self, y: np.ndarray, t: float) -> tuple[int, float]:
        while True:
            history = tuple(getattr(self, "H_" + name) for name in lk.HISTORY.fields)
            status, t = lk.run(self.arrays, y, t, history, self.scratch)
            if status == lk.BUFFER:
                self._grow(2 * len(self.H_t))
            else:
                return status, t


def initial_state(scene: Scene, run: _Run) -> np.ndarray:
    """y0 with the CG placed so the lowest footpad touches the terrain at t = 0 (first contact by
    construction, as FORCE shifts R(3) by XMIN); the lowest legs are marked to touch down as the compiled loop
    starts (landing_kernel.TOUCH)."""
    R = quat_matrix(scene.q0)
    heights = run.heights(np.zeros(3), R)
    r0 = np.array([0.0, 0.0, -heights.min()])
    y0 = np.concatenate([r0, scene.v0, scene.q0, scene.omega0, np.zeros(run.ny - 13)])
    run.armed[heights - heights.min() <= 1e-12] = lk.TOUCH
    # the energy scale of the steps' energy test (landing_kernel._error_norm): the initial kinetic energy and the
    # weight over 0.1 m (a landing from rest still has one), and 1 nJ (at rest in zero gravity: no division by zero)
    run.run_state[lk.S_EREF] = kinetic(scene, y0) + 0.1 * scene.mass * float(np.linalg.norm(scene.gravity)) + 1e-9
    return y0


def kinetic(scene: Scene, y: np.ndarray) -> float:
    return float(0.5 * scene.mass * y[3:6] @ y[3:6] + 0.5 * np.sum(scene.inertia * y[10:13] ** 2))


def simulate(scene: Scene, ctl: Controls) -> Result:
    """Integrate from first contact to ctl.t_final or an outcome the loop detects."""
    global compiling_for
    compiling_for = variant(scene)
    wall = time.perf_counter()
    run = _Run(scene, ctl)
    y = initial_state(scene, run)
    run.run_state[lk.S_MOMENTUM] = quiescence_momenta(scene.v0, scene.omega0, scene.mass, scene.inertia)[0]
    status, t = run.loop(y, 0.0)
    wall = time.perf_counter() - wall
    k = int(run.cnt[lk.K_HIST])
    Y = run.H_y[:k].copy()
    # The audit reads the final state y, not the record's last row: a leg that switched in the last step (a
    # lift-off's released strut energy goes to the friction work) is recorded as it was before the switch.
    ke0, ke1 = kinetic(scene, Y[0]), kinetic(scene, y)
    released = float(scene.mass * scene.gravity @ (y[0:3] - Y[0, 0:3]))
    stored = np.zeros_like(run.energy)                 # each cell's elastic energy (zero in the air: given up)
    for i in range(run.n):
        if run.contact[i]:
            for j in range(1 + int(run.geo[5][i])):
                stored[i, j] = crush_cell.elastic_energy(run.cells[3][i, j], run.mem[i, j, 0], run.mem[i, j, 1],
                                                         run.last[i, j])
    elastic = float(stored.sum())
    cell = run.energy.copy()
    n = run.n
    velocity = np.zeros((k, n, 3))
    pad_kinetic = other = soil = 0.0
    if run.ny > NB:
        # Footpads with mass: the dampers' work, the footpads' friction work and the legs' work beyond their
        # cells (return springs, seat) are integrated with the state, and on soil the soil's work; the
        # footpads keep their kinetic energy.
        base = NB + 4 * n + 2
        cell += y[base:base + n * run.C].reshape(n, run.C)
        velocity[:, :, :2] = Y[:, NB:NB + 4 * n].reshape(k, n, 4)[:, :, 2:]
        end = np.zeros((n, 3))
        end[:, :2] = y[NB:NB + 4 * n].reshape(n, 4)[:, 2:]
        if run.soil:
            velocity[:, :, 2] = -Y[:, base + n * run.C:-1].reshape(k, n, 4)[:, :, 1]
            end[:, 2] = -y[base + n * run.C:-1].reshape(n, 4)[:, 1]
            soil = float(y[-1])
        pad_kinetic = 0.5 * scene.footpad_mass * float(np.sum(end ** 2))
        friction, other = float(y[NB + 4 * n]), float(y[NB + 4 * n + 1])
    else:
        # The massless legs pass on all the work they take from the capsule (integrated with the state): what
        # the cells did not take went into the footpad-terrain interface (slip, and pads unloading at lift-off).
        friction = float(y[13]) - float(cell.sum())
    absorbed = float(cell.sum()) - elastic
    denom = ke0 + max(released, 0.0)
    out = absorbed + elastic + friction + pad_kinetic + other + soil + ke1
    closure = abs(ke0 + released - out) / denom if denom > 0 else 0.0
    en = {"initial_J": ke0, "potential_change_J": released, "absorbed_J": absorbed, "elastic_J": elastic,
          "friction_J": friction, "kinetic_end_J": ke1, "closure_rel": float(closure), "leg_work_J": float(y[13]),
          "footpad_kinetic_J": pad_kinetic, "leg_other_J": other, "soil_J": soil,
          # a passive cell gives back at most what it stored: its work less its elastic energy is >= 0 up to the
          # integration error (an energy the closure does not see: a stroke given to a cell by a jump, not work)
          "cell_absorbed_min_J": float((cell - stored).min())}
    rs = run.run_state
    bottomed = (float(rs[lk.S_BOT_T]), int(rs[lk.S_BOT_LEG]), int(rs[lk.S_BOT_CELL])) if rs[lk.S_BOT_T] >= 0 else None
    res = Result(run.H_t[:k].copy(), Y[:, :NB], run.H_dy[:k, :NB].copy(), run.H_d[:k].copy(), run.H_f[:k].copy(),
                 run.H_X[:k].copy(), run.H_P[:k].copy(), velocity, run.H_c[:k].copy(), STATUS[status], bottomed,
                 int(rs[lk.S_STRUCK]) if status in (lk.MEMBER, lk.FOLDED) else None, cell,
                 run.mem.copy(), int(run.cnt[lk.K_STEPS]), int(run.cnt[lk.K_REJECTED]),
                 int(run.cnt[lk.K_RHS]), int(run.cnt[lk.K_EVENTS]), int(run.cnt[lk.K_TRIALS]), wall, en,
                 scene.gravity)
    tripods = run.geo[7] == TRIPOD
    if np.any(tripods):
        res.struts = np.full((k, n, 3), np.nan)
        res.struts[:, tripods] = strut_axial_forces(res.forces[:, tripods, :5])
    return res
