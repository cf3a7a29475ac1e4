"""Member loads along simulated landing histories: dynamic load envelopes (AFFDL-TR-66-33 App. III on Sec. V.F).

The quasi-static envelopes (`load_envelopes`) put both cells of the articulated leg at the force their
loading curves give at the deflection each (alpha, psi) implies, i.e. on their crushing plateau (the
return spring added to AF2; positions past a cell's bottoming point left out), derive the ground force
from those cell forces (eq. 59-61) and sweep a grid of (alpha, beta, psi). Here the same member-load
functions (`articulated_statics.reactions`, eq. 53-61 and 98-100, then `member_loads`, eq. 101-106) are
evaluated at every accepted step of a simulated landing, for every articulated leg on the ground.

Taken from the history (`alightsize_sim.landing.Result`): the capsule state y, the contact flags, the footpad
positions, the upper cell force AF1 (`forces[..., 0]`: the loading curve while the cell crushes, the
unloading spring and damper below its maximum), the lower cell force (`forces[..., 1]`, likewise) and the
ground force (`leg_force`, turned into the leg's S axes as L^T X). Recomputed: the leg's shape
(alpha, beta, psi), which the Result does not keep, by the simulator's own `alightsize_sim.legs.leg_force` from the
stored footpad and state, the root seeded with the previous step's shape as the step loop seeds it (the
cells' memory enters only the forces, which are discarded); the recovered shape must reproduce the
history's cell deflections. The leg is massless, so wherever the peg leg is off its seat the history's
ground force is eq. 59-61 of the history's cell forces (AF2 = lower cell + return spring) to round-off.
On the seat (alpha < `alightsize_sim.articulated_leg.SEAT`) the simulator blends toward FORCE's vertical force from
the upper cell alone; there the lower-cell line force AF2 used is the one that, with the history's AF1,
gives exactly the simulated ground force (the ground force is linear in AF2), i.e. the seat's reaction is
lumped with the lower cell. Off the seat that AF2 equals the history's. The member loads therefore balance
the simulated ground force at every step.

Telescoping legs: the App. III free-body forces (AF1, P1-P4) at every step from the history's axial cell
force and ground force (`telescoping_member_histories`), beside the single quasi-static worst case of
alightsize.loads.telescoping. Tripod legs: the strut forces and the cantilever primary's bending moment at
every step from the footpad's position and force (`tripod_member_histories`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from math import degrees
from typing import Sequence

import numpy as np

from alightsize_sim.articulated_cells import return_spring_force
from alightsize_sim.articulated_leg import ArticulatedLeg
from alightsize_sim.articulated_statics import MEMBERS, Reactions, TrussAngles, ground_force, member_loads, reactions
from alightsize_sim.landing import Result, Scene
from alightsize_sim.legs import initial_shape, leg_force, lift_shape, pack, with_terrain
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.terrain import pack as pack_terrain
from alightsize_sim.telescoping_leg import TelescopingLeg as SimTelescopingLeg
from alightsize_sim.tripod_leg import TripodLeg, strut_forces

from alightsize.loads.quasi_static import TELESCOPING_FORCES
from alightsize.loads.telescoping import TelescopingLeg as TelescopingFreeBody, sliding_loads
from alightsize.model.scene_config import SceneConfig

SHAPE_TOL = 1e-9        # m: largest difference between the recovered and the recorded cell deflections


def leg_shapes(scene: Scene, res: Result) -> np.ndarray:
    """(n_steps, n_legs, 3) shape of every leg on the ground at every accepted step, NaN off it: articulated
    (alpha, beta, psi), telescoping (alpha, beta, 0), rad. ValueError if the recovered shape does not reproduce
    the recorded deflections (to SHAPE_TOL)."""
    geo, cells = pack(scene.legs)
    geo = with_terrain(geo, pack_terrain(scene.terrain))   # as the landing's: a free leg's shape looks at the terrain
    n_cell = cells[2].shape[1]
    mem = np.zeros((n_cell, 2))
    defl, frc, rte, X = np.zeros(n_cell), np.zeros(n_cell), np.zeros(n_cell), np.zeros(3)
    y = res.y
    R = [quat_matrix(q / np.linalg.norm(q)) for q in y[:, 6:10]]
    out = np.full(res.contact.shape + (3,), np.nan)
    for i, start in enumerate(initial_shape(scene.legs)):
        shape = start
        m = len(scene.legs[i].cells)
        for k in np.flatnonzero(res.contact[:, i] | np.r_[False, res.contact[:-1, i]]):
            if not res.contact[k, i]:                  # lifted off after step k - 1: FORCE's stored geometry (a
                # telescoping leg's held compression only places its free footpad, not needed here)
                alpha, beta, psi = out[k - 1, i]
                shape = np.array(lift_shape(geo, cells, i, mem, (alpha, beta, psi), 0.0, y[k - 1, 0:3], R[k - 1]))
                continue
            kin = (y[k, 0:3], R[k], y[k, 3:6] - res.footpad_velocity[k, i], y[k, 10:13])
            out[k, i] = leg_force(geo, cells, i, mem, shape, res.footpad[k, i], kin, (defl, frc, rte, X))[1:]
            shape = out[k, i].copy()
            miss = np.max(np.abs(defl[:m] - res.deflections[k, i, :m]))
            if not miss <= SHAPE_TOL:
                raise ValueError(f"leg {i + 1} at t = {res.t[k]:.9g} s: the recovered shape misses the recorded "
                                 f"deflections by {miss:.3g} m")
    return out


@dataclass(frozen=True)
class LegHistory:
    """One articulated leg's steps on the ground: shape (rad), the simulated ground force on the peg leg
    (N, S axes), the cell forces used (N) and the reactions (eq. 53-61, 98-100)."""

    leg: int                  # index into scene.legs
    steps: np.ndarray         # indices of the accepted steps with the leg on the ground
    alpha: np.ndarray
    beta: np.ndarray
    psi: np.ndarray
    ground: np.ndarray        # (m, 3) L^T X of the history
    af1: np.ndarray           # upper cell (history)
    af2: np.ndarray           # lower-cell line force balancing `ground` (seat lumped in)
    af2_cell: np.ndarray      # lower cell (history) + return spring
    reactions: Reactions


def leg_histories(scene: Scene, res: Result) -> tuple[LegHistory, ...]:
    """Shapes, forces and reactions of every articulated leg along the history (ValueError on telescoping
    legs)."""
    legs = [leg for leg in scene.legs if isinstance(leg, ArticulatedLeg)]
    if len(legs) != len(scene.legs):
        raise ValueError("dynamic member loads need articulated legs (telescoping: App. III free body only)")
    shapes = leg_shapes(scene, res)
    out = []
    for i, leg in enumerate(legs):
        g, k = leg.geometry, np.flatnonzero(res.contact[:, i])
        a, b, p = shapes[k, i].T
        ground = res.leg_force[k, i] @ leg.to_body        # S axes: the simulator writes X = L x (Sec. V.F, FORCE)
        af1 = res.forces[k, i, 0]
        base = np.stack(ground_force(g, a, b, p, af1, 0.0), -1)                         # eq. 59-61, linear in AF2:
        unit = np.stack(ground_force(g, a, b, p, 0.0, 1.0), -1)                         # the AF2 giving `ground`
        af2 = np.einsum("ij,ij->i", ground - base, unit) / np.einsum("ij,ij->i", unit, unit)
        af2_cell = res.forces[k, i, 1] + return_spring_force(g, res.deflections[k, i, 1])   # FORCE: + SPRG D2 + PLD
        out.append(LegHistory(i, k, a, b, p, ground, af1, af2, af2_cell, reactions(g, a, b, p, af1, af2)))
    return tuple(out)


def _members(hist: tuple[LegHistory, ...], shape: tuple[int, int], truss: TrussAngles) -> dict[str, np.ndarray]:
    out = {m: np.full(shape, np.nan) for m in MEMBERS}
    for h in hist:
        for m, v in member_loads(h.reactions, truss).items():                          # eq. 101-106
            out[m][h.steps, h.leg] = v
    return out


def member_histories(cfg: SceneConfig, res: Result, truss: TrussAngles) -> dict[str, np.ndarray]:
    """Member -> (n_steps, n_legs) load (N, tension positive), NaN where the leg is off the ground. `truss`:
    the Fig. 104-105 angles for PL1, PL2, PU1 (a loads config's [truss]; scenes carry none)."""
    return _members(leg_histories(cfg.scene, res), res.contact.shape, truss)


def _extremes(fields: dict[str, np.ndarray], where) -> list[dict]:
    """Per field the largest positive (tension) and negative (compression) value over (steps, legs) with
    `where(step, leg)`; None where a field never has that sign. Ties go to the earliest step, then leg."""
    rows = []
    for m, f in fields.items():
        row: dict[str, object] = {"member": m}
        for key, pick, sign in (("tension", np.nanargmax, 1.0), ("compression", np.nanargmin, -1.0)):
            if (np.isfinite(f) & (sign * f > 0)).any():
                k, i = np.unravel_index(int(pick(f)), f.shape)
                row[f"{key}_N"], row[f"{key}_at"] = float(f[k, i]), where(int(k), int(i))
            else:
                row[f"{key}_N"], row[f"{key}_at"] = None, None
        rows.append(row)
    return rows


def dynamic_envelope(cfg: SceneConfig, res: Result, truss: TrussAngles) -> list[dict]:
    """Per member the largest tension (> 0) and compression (< 0) over the history with where they occur:
    {member, tension_N, tension_at: {t_s, leg (1..), alpha_deg, beta_deg, psi_deg}, compression_N,
    compression_at}, None where the member never sees that sense. Ties go to the earliest step, then leg."""
    return articulated_envelope(leg_histories(cfg.scene, res), res, truss)


def articulated_envelope(hist: tuple[LegHistory, ...], res: Result, truss: TrussAngles) -> list[dict]:
    """`dynamic_envelope` of the leg histories `hist` of `res`."""
    by_leg = {h.leg: h for h in hist}

    def where(k: int, i: int) -> dict:
        h = by_leg[i]
        j = int(np.searchsorted(h.steps, k))
        return {"t_s": float(res.t[k]), "leg": i + 1, "alpha_deg": degrees(h.alpha[j]),
                "beta_deg": degrees(h.beta[j]), "psi_deg": degrees(h.psi[j])}
    return _extremes(_members(hist, res.contact.shape, truss), where)


def telescoping_member_histories(cfg: SceneConfig, res: Result, leg: TelescopingFreeBody) -> dict[str, np.ndarray]:
    """The App. III free-body forces along the history, (n_steps, n_legs) N, NaN off the ground: AF1 (the axial
    cell), P1 (the ground force across the leg axis at the footpad, |X - (X.u) u|: the pads' generalized forces
    over the current length al, eq. 25-27), P2 = P1 (al / a - 1) (the pads' resultant P1 al / a less P1, from
    the moments about the pivot; App. III with al = rho), and w1, w2, P4, P3 of `sliding_loads` with the step's
    AF1 and al. Bearing length and friction are the App. III leg's (`leg`)."""
    legs = [lg for lg in cfg.scene.legs if isinstance(lg, SimTelescopingLeg)]
    if len(legs) != len(cfg.scene.legs):
        raise ValueError("telescoping member loads need telescoping legs")
    shape = res.contact.shape
    out = {m: np.full(shape, np.nan) for m in TELESCOPING_FORCES}
    R = np.array([quat_matrix(q / np.linalg.norm(q)) for q in res.y[:, 6:10]])
    for i, lg in enumerate(legs):
        k = np.flatnonzero(res.contact[:, i])
        attach = res.y[k, 0:3] + np.einsum("kij,j->ki", R[k], lg.attach)
        d = np.einsum("kji,kj->ki", R[k], res.footpad[k, i] - attach)          # pivot to footpad, body axes
        al = np.linalg.norm(d, axis=1)
        u = d / al[:, None]
        X = res.leg_force[k, i]
        p1 = np.linalg.norm(X - np.einsum("ki,ki->k", X, u)[:, None] * u, axis=1)
        af1 = res.forces[k, i, 0]
        slide = sliding_loads(replace(leg, axial_crush=af1, length=al), p1)
        for m, v in (("AF1", af1), ("P1", p1), ("P2", p1 * (al / lg.pad_lever - 1.0)), ("P3", slide["P3"]),
                     ("P4", slide["P4"])):
            out[m][k, i] = v
    return out


def telescoping_dynamic_envelope(cfg: SceneConfig, res: Result, leg: TelescopingFreeBody) -> list[dict]:
    """Per App. III force its largest value over the history (`dynamic_envelope`'s format, `at` with psi 0)."""
    shapes = leg_shapes(cfg.scene, res)

    def where(k: int, i: int) -> dict:
        a, b, _ = shapes[k, i]
        return {"t_s": float(res.t[k]), "leg": i + 1, "alpha_deg": degrees(a), "beta_deg": degrees(b), "psi_deg": 0.0}
    return _extremes(telescoping_member_histories(cfg, res, leg), where)


TRIPOD_FORCES = ("primary", "secondary1", "secondary2", "primary_upper")     # N, tension positive


@dataclass(frozen=True)
class TripodHistory:
    """Strut loads of tripod legs along a history, NaN off the ground. `forces`: name -> (n_steps, n_legs) N,
    tension positive: the primary's cartridge (the primary below the knee), each secondary, the primary between
    its hardpoint and the knee; `knee_moment` (n_steps, n_legs) N m: the cantilever primary's bending moment at
    the knee, the largest along it (0 for an inverted tripod); `hardpoints` (n_steps, n_legs, 3, 3) N: the leg's
    force on the body at its primary, secondary 1 and secondary 2 hardpoints, body principal axes."""

    forces: dict[str, np.ndarray]
    knee_moment: np.ndarray
    hardpoints: np.ndarray


def tripod_member_histories(res: Result, legs: Sequence[TripodLeg]) -> TripodHistory:
    """Strut loads of the tripod legs `legs` (alightsize_sim.tripod_leg.TripodLeg, one per leg of the history) at
    every step on the ground, from the history's footpad positions (terrain axes, taken into body principal
    axes about the centre of gravity) and the force each leg carries (`leg_force`, principal axes): the struts
    are massless, so the leg is statically determinate (`strut_forces`: the method of joints for the inverted
    tripod, moments about the primary's pin for the cantilever; Hibbeler, Statics, sec. 6.5)."""
    if len(legs) != res.contact.shape[1]:
        raise ValueError(f"tripod member loads: {len(legs)} legs given for a history of {res.contact.shape[1]}")
    shape = res.contact.shape
    forces = {m: np.full(shape, np.nan) for m in TRIPOD_FORCES}
    moment, hard = np.full(shape, np.nan), np.full(shape + (3, 3), np.nan)
    for i, leg in enumerate(legs):
        k = np.flatnonzero(res.contact[:, i])
        R = np.array([quat_matrix(q / np.linalg.norm(q)) for q in res.y[k, 6:10]]).reshape(len(k), 3, 3)
        P = np.einsum("kji,kj->ki", R, res.footpad[k, i] - res.y[k, 0:3])
        for j, step in enumerate(k):
            s = strut_forces(leg, res.leg_force[step, i], P[j])
            for m, v in zip(TRIPOD_FORCES, (s.primary, *s.secondaries, s.primary_upper)):
                forces[m][step, i] = v
            moment[step, i], hard[step, i] = s.knee_moment, s.hardpoint_forces
    return TripodHistory(forces, moment, hard)


TRIPOD_MAGNITUDES = (("knee_moment", "N*m"), ("primary_pin", "N"), ("footpad", "N"))


def tripod_envelope(hist: TripodHistory, res: Result) -> list[dict]:
    """A tripod landing's load extremes: per strut force (TRIPOD_FORCES) its largest tension and compression
    (`dynamic_envelope`'s format, `at` = {t_s, leg (1..)}), then {member, largest, unit, at} for the knee moment,
    the resultant on the primary's hardpoint pin and the ground force on the footpad (the force the leg carries,
    `leg_force`); None where never loaded. Ties go to the earliest step, then leg."""
    def where(k: int, i: int) -> dict:
        return {"t_s": float(res.t[k]), "leg": i + 1}
    rows = _extremes(hist.forces, where)
    ground = np.where(res.contact[..., None], res.leg_force, np.nan)
    fields = {"knee_moment": hist.knee_moment, "primary_pin": np.linalg.norm(hist.hardpoints[:, :, 0], axis=-1),
              "footpad": np.linalg.norm(ground, axis=-1)}
    for m, unit in TRIPOD_MAGNITUDES:
        f = fields[m]
        if np.isfinite(f).any():
            k, i = np.unravel_index(int(np.nanargmax(f)), f.shape)
            rows.append({"member": m, "largest": float(f[k, i]), "unit": unit, "at": where(int(k), int(i))})
        else:
            rows.append({"member": m, "largest": None, "unit": unit, "at": None})
    return rows
