"""Interface loads: the force each leg puts on the body at each of its hardpoints along a landing (body principal
axes), and each hardpoint's largest force (reported along the geometric body axes, as XDD): what the designer of
the deck the legs attach to needs.

Every leg is massless between the body and its footpad, so at every step its hardpoint forces sum to the force
the leg carries (the history's `leg_force`, the ground force on the body through that leg) and their moments
balance; each leg kind splits it by its own statics:

- telescoping (the App. III free body): the leg pivots on its swivel and the rotational pads, a distance a (the
  pad lever) down the leg, react only across its axis u. Moments about the pivot, al u x X + a u x B = 0, give
  the pads' force on the body (al / a) X_perp (magnitude P1 al / a), and the pivot the rest,
  X_par - (al / a - 1) X_perp (its part across the axis is App. III's P2 = P1 (al / a - 1));
- articulated (App. III eq. 53-61, 96-100 in the leg's S axes): the upper attachment carries the upper
  parallelogram links (PU1, PU2), -(Q2 d + RA e2), d = (cos psi, 0, sin psi) along the links, e2 across the
  leg's plane; the lower attachment the lower members (PL1-PL6) and the upper cell, whose inboard end shares
  the lower inboard pivots (AA, AB; GUIDE.md), -(Q1 d + RB e2) + AF1 (cos eta, 0, sin eta). Their sum is the
  ground force on the peg leg (eq. 56-57 with eq. 53-54 and 98-100);
- tripod: the three strut ends (`alightsize_sim.tripod_leg.StrutForces.hardpoint_forces`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial
from typing import Callable, Sequence

import numpy as np

from alightsize_sim.articulated_cells import upper_angle
from alightsize_sim.articulated_leg import ArticulatedLeg
from alightsize_sim.articulated_statics import TrussAngles
from alightsize_sim.landing import Result
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.telescoping_leg import TelescopingLeg as SimTelescopingLeg
from alightsize_sim.tripod_leg import TripodLeg

from alightsize.loads.histories import (LegHistory, articulated_envelope, leg_histories, telescoping_dynamic_envelope,
                                        tripod_member_histories)
from alightsize.loads.telescoping import TelescopingLeg as TelescopingFreeBody
from alightsize.model.scene_config import SceneConfig

TELESCOPING_HARDPOINTS = ("pivot", "pads")
ARTICULATED_HARDPOINTS = ("upper", "lower")
TRIPOD_HARDPOINTS = ("primary", "secondary 1", "secondary 2")


@dataclass(frozen=True)
class HardpointHistory:
    """The force of each leg on the body at each hardpoint along a history: `forces` (n_steps, n_legs,
    n_hardpoints, 3) N in body principal axes, NaN where the leg is off the ground."""

    names: tuple[str, ...]
    forces: np.ndarray


def _rotations(res: Result, k: np.ndarray) -> np.ndarray:
    """Body-to-terrain matrices of the steps k."""
    return np.array([quat_matrix(q / np.linalg.norm(q)) for q in res.y[k, 6:10]]).reshape(len(k), 3, 3)


def body_footpads(res: Result, i: int, k: np.ndarray) -> np.ndarray:
    """(len(k), 3) footpad of leg i at steps k in body principal axes, from the centre of gravity."""
    return np.einsum("kji,kj->ki", _rotations(res, k), res.footpad[k, i] - res.y[k, 0:3])


def telescoping_hardpoints(cfg: SceneConfig, res: Result) -> HardpointHistory:
    """Pivot and pads of every telescoping leg along the history (the module's statics). ValueError for other leg
    kinds, or pads at the pivot (a pad lever of 0 carries no moment)."""
    legs = [lg for lg in cfg.scene.legs if isinstance(lg, SimTelescopingLeg)]
    if len(legs) != len(cfg.scene.legs):
        raise ValueError("telescoping interface loads need telescoping legs")
    out = np.full(res.contact.shape + (2, 3), np.nan)
    for i, lg in enumerate(legs):
        if not lg.pad_lever > 0:
            raise ValueError(f"leg {i + 1}: pads at the pivot (pad lever 0) react no moment")
        k = np.flatnonzero(res.contact[:, i])
        d = body_footpads(res, i, k) - lg.attach                         # pivot to footpad
        al = np.linalg.norm(d, axis=1)
        u = d / al[:, None]
        X = res.leg_force[k, i]
        par = np.einsum("ki,ki->k", X, u)[:, None] * u
        pads = (al / lg.pad_lever)[:, None] * (X - par)
        out[k, i, 0], out[k, i, 1] = X - pads, pads
    return HardpointHistory(TELESCOPING_HARDPOINTS, out)


def _articulated(cfg: SceneConfig, res: Result, hist: Sequence[LegHistory]) -> HardpointHistory:
    out = np.full(res.contact.shape + (2, 3), np.nan)
    for h in hist:
        leg = cfg.scene.legs[h.leg]
        assert isinstance(leg, ArticulatedLeg)            # `leg_histories` refuses other kinds
        r = h.reactions
        eta = upper_angle(leg.geometry, h.psi)
        zero = np.zeros_like(h.psi)
        d = np.stack((np.cos(h.psi), zero, np.sin(h.psi)), -1)
        e2 = np.stack((zero, zero + 1.0, zero), -1)
        cell = np.stack((np.cos(eta), zero, np.sin(eta)), -1)
        upper = -(r.Q2[:, None] * d + r.RA[:, None] * e2)
        lower = -(r.Q1[:, None] * d + r.RB[:, None] * e2) + h.af1[:, None] * cell
        out[h.steps, h.leg, 0] = upper @ leg.to_body.T                  # S axes to principal: X = L s
        out[h.steps, h.leg, 1] = lower @ leg.to_body.T
    return HardpointHistory(ARTICULATED_HARDPOINTS, out)


def articulated_hardpoints(cfg: SceneConfig, res: Result) -> HardpointHistory:
    """Upper and lower attachments of every articulated leg along the history (the module's statics)."""
    return _articulated(cfg, res, leg_histories(cfg.scene, res))


def tripod_hardpoints(res: Result, legs: Sequence[TripodLeg]) -> HardpointHistory:
    """The three strut ends of every tripod leg along the history (`StrutForces.hardpoint_forces`)."""
    return HardpointHistory(TRIPOD_HARDPOINTS, tripod_member_histories(res, legs).hardpoints)


def interface_extremes(h: HardpointHistory, t: np.ndarray, to_geo: np.ndarray | None = None) -> list[dict]:
    """Per leg and hardpoint its largest force over the history: {leg (1..), hardpoint, force_N (magnitude),
    components_N (at that step, along the body's geometric axes with `to_geo`, the principal-to-geometric matrix
    of the scene, else its principal axes), t_s}; legs never on the ground are left out. Ties go to the earliest
    step."""
    rows = []
    forces = h.forces if to_geo is None else h.forces @ np.asarray(to_geo).T
    mag = np.linalg.norm(forces, axis=-1)
    for i in range(h.forces.shape[1]):
        for j, name in enumerate(h.names):
            m = mag[:, i, j]
            if not np.isfinite(m).any():
                continue
            k = int(np.nanargmax(m))
            rows.append({"leg": i + 1, "hardpoint": name, "force_N": float(m[k]),
                         "components_N": [float(x) for x in forces[k, i, j]], "t_s": float(t[k])})
    return rows


def articulated_landing_loads(cfg: SceneConfig, res: Result, truss: TrussAngles) -> dict[str, list[dict]]:
    """A landing's stored loads (alightsize.landings.sweep): `member_loads` (`dynamic_envelope`) and
    `interface_loads` (`interface_extremes`, along the body's geometric axes) of its articulated legs."""
    hist = leg_histories(cfg.scene, res)
    return {"member_loads": articulated_envelope(hist, res, truss),
            "interface_loads": interface_extremes(_articulated(cfg, res, hist), res.t, cfg.to_geometric)}


def telescoping_landing_loads(cfg: SceneConfig, res: Result, leg: TelescopingFreeBody) -> dict[str, list[dict]]:
    """A landing's stored loads: `member_loads` (`telescoping_dynamic_envelope`) and `interface_loads`."""
    return {"member_loads": telescoping_dynamic_envelope(cfg, res, leg),
            "interface_loads": interface_extremes(telescoping_hardpoints(cfg, res), res.t, cfg.to_geometric)}


def landing_loads(truss: TrussAngles | None = None,
                  telescoping: TelescopingFreeBody | None = None) -> Callable[[SceneConfig, Result], dict]:
    """The sweep's per-landing loads function of a telescoping leg's free body or an articulated leg's truss."""
    if telescoping is not None:
        return partial(telescoping_landing_loads, leg=telescoping)
    assert truss is not None                          # an articulated leg's loads config has its truss
    return partial(articulated_landing_loads, truss=truss)
