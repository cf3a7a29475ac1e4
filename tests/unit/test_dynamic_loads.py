"""Member loads along a simulated landing (alightsize.loads.histories): the recovered leg shapes against the
history, the dynamic loads against the quasi-static envelope functions where the cells crush, equilibrium
with the simulated ground force, and the envelope against the history's extremes."""

import numpy as np
import pytest

from alightsize.loads.histories import dynamic_envelope, leg_histories, member_histories
from alightsize.loads.envelopes import cell_forces
from alightsize.loads.config import read_loads
from alightsize.model.scene_config import read_scene
from alightsize_sim.articulated_cells import lower_deflection, lower_force_components, upper_deflection
from alightsize_sim.articulated_kinematics import footpad
from alightsize_sim.articulated_leg import SEAT
from alightsize_sim.articulated_statics import MEMBERS, member_loads, reactions, residuals
from alightsize_sim.landing import simulate
from alightsize_sim.rigid_body import quat_matrix

from conftest import EXAMPLES

CFG = read_scene(EXAMPLES / "scenes" / "articulated_config5.toml")
CASE = next(c for c in read_loads(EXAMPLES / "loads" / "articulated.toml").cases if c.name == "5")


@pytest.fixture(scope="module")
def landing():
    res = simulate(CFG.scene, CFG.controls)
    return res, leg_histories(CFG.scene, res), member_histories(CFG, res, CASE.truss)


def _scale(h):
    return np.max(np.abs(np.r_[h.af1, h.af2]))


def test_recovered_shapes_place_the_footpad_and_give_the_recorded_deflections(landing):
    # Eq. 38-40 and 45-48 evaluated at the recovered (alpha, beta, psi) against the stored footpad (terrain
    # axes, taken into the leg's S axes here) and the recorded deflections: 1e-9 m (round-off ~1e-14 m).
    res, hist, _ = landing
    for h in hist:
        leg, k = CFG.scene.legs[h.leg], h.steps
        R = np.array([quat_matrix(q) for q in res.y[k, 6:10]])
        b = np.einsum("nji,nj->ni", R, res.footpad[k, h.leg] - res.y[k, 0:3])          # principal axes
        s = (b - leg.attach) @ leg.to_body
        np.testing.assert_allclose(np.array(footpad(leg.geometry, h.alpha, h.beta, h.psi)).T, s, rtol=0, atol=1e-9)
        np.testing.assert_allclose(upper_deflection(leg.geometry, h.psi, leg.psi0), res.deflections[k, h.leg, 0],
                                   rtol=0, atol=1e-9)
        np.testing.assert_allclose(lower_deflection(leg.geometry, h.alpha), res.deflections[k, h.leg, 1],
                                   rtol=0, atol=1e-9)
    assert sum(len(h.steps) for h in hist) == res.contact.sum() > 0


def test_crushing_steps_give_the_quasi_static_member_loads(landing):
    # Where both cells load on their curves (deflection at a new maximum: no unloading spring, no damper),
    # the history's cell forces are those the envelopes assume, and the dynamic member loads must equal
    # the envelope functions' (cell_forces -> reactions -> member_loads of configuration 5 in the loads file)
    # at the same (alpha, beta, psi): 1e-9 of the largest load (found ~1e-13).
    res, hist, loads = landing
    leg0 = CFG.scene.legs[0]
    assert CASE.geometry == leg0.geometry and CASE.psi_initial == leg0.psi0
    n = 0
    for h in hist:
        d = res.deflections[:, h.leg]
        prior = np.fmax.accumulate(np.vstack([np.zeros((1, 2)), np.nan_to_num(d[:-1], nan=0.0)]))
        crush = np.all(d[h.steps] >= prior[h.steps], axis=1) & (h.alpha >= SEAT)
        a, b, p = h.alpha[crush], h.beta[crush], h.psi[crush]
        af1, af2 = cell_forces(CASE, a, p)
        np.testing.assert_allclose(h.af1[crush], af1, rtol=1e-12, atol=1e-6)
        np.testing.assert_allclose(h.af2[crush], af2, rtol=1e-9, atol=1e-6)
        quasi = member_loads(reactions(CASE.geometry, a, b, p, af1, af2), CASE.truss)
        for m in MEMBERS:
            dyn = loads[m][h.steps[crush], h.leg]
            assert np.max(np.abs(dyn - quasi[m])) <= 1e-9 * np.max(np.abs(quasi[m])), m
        n += int(crush.sum())
    assert n >= 100


def test_member_loads_balance_the_simulated_ground_force(landing):
    # The reactions behind the member loads reproduce the simulated ground force (L^T X), and the peg leg's
    # joint balances: F + AF2 (eq. 50-52) + ring reaction (R12, R13, -R11) = 0 (eq. 53, 54, 98); the whole
    # eq. 96 system holds. All to 1e-9 of the leg's largest cell force, seat steps included.
    res, hist, _ = landing
    seated = 0
    for h in hist:
        g, r, scale = CFG.scene.legs[h.leg].geometry, h.reactions, _scale(h)
        F = np.stack([r.F1, r.F2, r.F3], -1)
        assert np.max(np.abs(F - h.ground)) <= 1e-9 * scale
        ring = np.stack([r.R12, r.R13, -r.R11], -1)
        cell = np.stack(lower_force_components(g, h.alpha, h.beta, h.af2), -1)
        assert np.max(np.abs(h.ground + cell + ring)) <= 1e-9 * scale
        assert np.max(np.abs(residuals(g, h.alpha, h.beta, h.psi, h.af1, h.af2, r))) <= 1e-9 * scale
        off = h.alpha >= SEAT             # off its seat the lower-cell force is the history's (+ return spring)
        assert np.max(np.abs(h.af2[off] - h.af2_cell[off])) <= 1e-9 * scale
        seated += int((~off).sum())
    assert seated > 0                     # the seat blend is exercised (90 steps in this landing)


def test_envelope_is_the_extreme_of_the_history(landing):
    res, hist, loads = landing
    env = dynamic_envelope(CFG, res, CASE.truss)
    assert [e["member"] for e in env] == list(MEMBERS)
    for e in env:
        f = loads[e["member"]]
        assert np.isnan(f[res.contact == 0]).all() and np.isfinite(f[res.contact == 1]).all()
        for key, ext, sign in (("tension", np.nanmax, 1), ("compression", np.nanmin, -1)):
            if e[f"{key}_N"] is None:
                assert sign * ext(f) <= 0
                continue
            assert e[f"{key}_N"] == ext(f) and sign * e[f"{key}_N"] > 0
            at = e[f"{key}_at"]
            k = int(np.searchsorted(res.t, at["t_s"]))
            assert f[k, at["leg"] - 1] == e[f"{key}_N"]
            h = hist[at["leg"] - 1]
            j = int(np.searchsorted(h.steps, k))
            assert np.degrees([h.alpha[j], h.beta[j], h.psi[j]]) == pytest.approx(
                [at["alpha_deg"], at["beta_deg"], at["psi_deg"]], rel=1e-15)


def test_telescoping_legs_are_refused(landing):
    tele = read_scene(EXAMPLES / "scenes" / "telescoping_config0.toml")
    with pytest.raises(ValueError, match="articulated"):
        dynamic_envelope(tele, landing[0], CASE.truss)
