"""Telescoping leg: App. III free body against the printed numbers, kinematics eq. 12-21."""

import numpy as np
import pytest

from alightsize.loads.config import read_loads
from alightsize.loads.telescoping import free_body, side_loads, sliding_loads
from alightsize_sim.telescoping_kinematics import footpad, pad_deflection, spherical

from conftest import EXAMPLES

LBF, IN = 4.4482216152605, 0.0254
LEG = read_loads(EXAMPLES / "loads" / "telescoping.toml").telescoping


def test_side_loads_from_the_printed_inputs_and_the_recorded_discrepancy():
    p1, p2 = (x / LBF for x in side_loads(LEG))
    # sqrt(2) 1500 (15 / 30.5) = 1043.3 and sqrt(2) 1500 (1 - 15 / 30.5) = 1078.0 (exact arithmetic).
    assert p1 == pytest.approx(1043.3, abs=0.05) and p2 == pytest.approx(1078.0, abs=0.05)
    # RECORDED: the report prints P1 = 1045 and P2 = 1075 (0.16 % and 0.28 % off); both follow from
    # sqrt(2) AF2 taken as 2120 lb and a / rho as 0.493 (docs/report-notes.md).
    assert round(p1) != 1045 and round(p2) != 1075
    assert p1 + p2 == pytest.approx(np.sqrt(2) * 1500, rel=1e-12)      # statics: P1 + P2 = sqrt(2) AF2


def test_sliding_loads_from_the_printed_p1_reach_the_printed_digits():
    out = sliding_loads(LEG, 1045 * LBF)
    assert round(out["w2"] / (LBF / IN), -1) == 6070       # 6 (1045)(15.5) / 16 = 6074
    assert round(out["w1"] / (LBF / IN)) == 261             # 1045 / 4 = 261.25
    assert round(out["P4"] / LBF, -1) == 660                # 0.05 [261 (4) + 0.5 (6070)(4)] = 659.6
    assert round(out["P3"] / LBF, -1) == 3090               # 3750 - 660


def test_free_body_balances():
    fb = free_body(LEG)
    assert fb["P3"] + fb["P4"] == pytest.approx(LEG.axial_crush, rel=1e-12)
    # The bearing distributions carry P1 (w1 chi) and the moment P1 (rho - a) (w2 chi^2 / 6).
    chi = LEG.bearing_length
    assert fb["w1"] * chi == pytest.approx(fb["P1"], rel=1e-12)
    assert fb["w2"] * chi ** 2 / 6 == pytest.approx(fb["P1"] * (LEG.length - LEG.pad_lever), rel=1e-12)


def test_spherical_coordinates_round_trip_and_alpha_zero():
    rng = np.random.default_rng(2)
    al, a, b = rng.uniform(0.5, 1.0, 1000), rng.uniform(1e-6, np.radians(80), 1000), rng.uniform(-np.pi, np.pi, 1000)
    al2, a2, b2 = spherical(*footpad(al, a, b))
    assert np.max(np.abs(al2 - al)) < 1e-14 and np.max(np.abs(a2 - a)) < 1e-12 and np.max(np.abs(b2 - b)) < 1e-9
    al0, a0, b0 = spherical(0.0, 0.0, -0.7)          # alpha = 0: beta is set to 0 (Sec. V.E.1)
    assert (al0, a0, b0) == (0.7, 0.0, 0.0)


def test_small_angle_pad_deflection_differs_by_the_printed_1_2_percent_at_15_deg():
    a = np.radians(15)
    exact, small = pad_deflection(15 * IN, a, 0.0, 0.0), pad_deflection(15 * IN, a, 0.0, 0.0, small_angle=True)
    assert round(100 * (small - exact) / exact, 1) == 1.2        # Sec. V.E.2: "1.2 percent ... at 15 degrees"
    assert pad_deflection(15 * IN, a, 0.0, np.pi) == 0.0         # the pad opposite is never pulled


def test_a_landing_side_load_carries_its_own_bearing_reactions():
    """When a landing's P1 replaces the free body's, the free-body table's w1, w2 and P4 follow from the P1
    printed beside them by App. III's relations (w1 = P1 / chi, w2 = 6 P1 (rho - a) / chi^2, P4 = mu (w1 chi +
    0.5 w2 chi)), and the App. III column keeps the quasi-static set, which satisfies them too. A synthetic
    landing row (P1 twice the free body's, AF1 below its 3,750 lb) stands for a landing. Tolerance 1e-12: the
    same arithmetic in another order."""
    import json

    from alightsize.common.units import parse
    from alightsize.loads.quasi_static import run_loads
    from alightsize.pipeline.landings import merge
    from alightsize.reports.loads_report import telescoping_rows
    qs = run_loads(read_loads(EXAMPLES / "loads" / "telescoping.toml"))
    at = {"t_s": 0.1, "leg": 1, "alpha_deg": 5.0, "beta_deg": 45.0, "psi_deg": 0.0}
    loads = [{"member": "P1", "tension_N": 2 * qs.telescoping["P1"], "tension_at": at, "compression_N": None,
              "compression_at": None},
             {"member": "AF1", "tension_N": 0.5 * qs.telescoping["AF1"], "tension_at": at, "compression_N": None,
              "compression_at": None}]
    res = merge(qs, ({"run_id": "L1", "member_loads_json": json.dumps(loads)},), ("telescoping",))
    rows = {r["name"]: r for r in telescoping_rows(res, "SI", qs.telescoping)}
    dims = {"w1": "spring_rate", "w2": "spring_rate"}
    t = {k: parse(f"{r['number']!r} {r['unit']}", dims.get(k, "force")) for k, r in rows.items()}  # as printed, to SI
    chi, rho, a, mu = LEG.bearing_length, LEG.length, LEG.pad_lever, LEG.friction
    assert t["P1"] == pytest.approx(2 * qs.telescoping["P1"], rel=1e-12) and rows["P1"]["source"] == "landing L1"
    for fb in (t, qs.telescoping):                                    # the design set, the App. III set
        assert fb["w1"] == pytest.approx(fb["P1"] / chi, rel=1e-12)
        assert fb["w2"] == pytest.approx(6 * fb["P1"] * (rho - a) / chi ** 2, rel=1e-12)
        assert fb["P4"] == pytest.approx(mu * (fb["w1"] * chi + 0.5 * fb["w2"] * chi), rel=1e-12)
    assert t["AF1"] == pytest.approx(LEG.axial_crush, rel=1e-12) and rows["AF1"]["source"] == "App. III free body"
