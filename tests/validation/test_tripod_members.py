"""Tripod members derived from the leg geometry: strut lengths and tube weights against hand calculation
(rho pi d t L), weight rising with the stance, the Johnson-Euler column over the derived pin-to-pin length
against Bruhn's 6061-T6 strut, the cantilever overhang's effective length against a finite-element buckling
solution, the crushable cores against their cells."""

from math import cos, pi, sin, sqrt

import numpy as np
import pytest
from member_cases import IN, LBF, MATERIALS, PSI

from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.pipeline.config import read_items
from alightsize.pipeline.tripod_members import TripodLoads, overhang_effective_length, tripod_items
from alightsize_sim.crush_cell import CellModel
from alightsize_sim.crush_curve import CrushCurve
from alightsize_sim.tripod_leg import strut_forces, tripod_from_params

PRIMARY = CellModel(CrushCurve((0.0, 0.01, 0.40, 0.41), (0.0, 2e4, 2e4, 8e4)), 1e7)
SEC_C = CellModel(CrushCurve((0.0, 0.01, 0.20, 0.21), (0.0, 1e4, 1e4, 4e4)), 1e7)
SEC_T = CellModel(CrushCurve((0.0, 0.01, 0.10, 0.11), (0.0, 6e3, 6e3, 2e4)), 1e7)
RH, H, ZF, SPREAD = 1.0, 0.5, -1.5, pi / 3
LOADS = TripodLoads(2e4, (1e4, 1e4), (6e3, 6e3), 2e4, 0.0, 0.0, 2e4, 2.5e4)
TUBE = {"shape": "tube", "outside_diameter": "60 mm", "wall": "1.5 mm"}
MEMBERS = {"primary_strut": {"material": "7178-t6", "section": TUBE},
           "secondary_strut": {"material": "7178-t6", "section": {**TUBE, "outside_diameter": "40 mm"}},
           "end_pin": {"material": "4130-steel", "section": {"shape": "rod", "diameter": "12 mm"},
                       "pin": {"lug_thickness": "10 mm", "lug_material": "7178-t6"},
                       "weight": {"method": "prism", "length": "60 mm"}},
           "footpad": {"material": "7178-t6", "section": {"shape": "plate", "thickness": "6 mm"},
                       "load_radius": "30 mm"},
           "primary_core": {"material": "al-honeycomb"},
           "secondary_core": {"material": "al-honeycomb"}}


def _leg(footpad_radius=2.0, secondary_attach=0.0, cells=(PRIMARY, SEC_C, SEC_T)):
    return tripod_from_params(footpad_radius, RH, H, footpad_height=ZF, secondary_spread=SPREAD, primary=cells[0],
                              secondary_compression=cells[1], secondary_tension=cells[2], footpad_diameter=0.4,
                              secondary_attach=secondary_attach)


def _items(leg, members=MEMBERS, loads=LOADS):
    root = Node("lander.toml", "", {"members": members})
    nodes = tripod_items(leg, loads, root.table("members"), "current", MATERIALS)
    return {i.name: i for i in read_items(tuple(nodes), MATERIALS, 1.25, root, "current")}


@pytest.mark.parametrize("rf", [1.5, 2.0, 3.0])
def test_strut_lengths_and_tube_weights_by_hand(rf):
    """Primary: hardpoint (RH, 0, H) to footpad (rf, 0, ZF); secondaries from (RH cos s, +-RH sin s, H). Each tube
    weighs rho pi (OD - t) t L over that length (App. V). Same arithmetic, other order: 1e-12."""
    items = _items(_leg(rf))
    lp = sqrt((rf - RH) ** 2 + (H - ZF) ** 2)
    ls = sqrt((rf - RH * cos(SPREAD)) ** 2 + (RH * sin(SPREAD)) ** 2 + (H - ZF) ** 2)
    rho = MATERIALS["7178-t6"].density
    for name, length, od in (("primary_strut", lp, 0.060), ("secondary_strut_1", ls, 0.040),
                             ("secondary_strut_2", ls, 0.040)):
        assert items[name].length == pytest.approx(length, rel=1e-12)
        assert items[name].weight_each()[0] == pytest.approx(rho * pi * (od - 0.0015) * 0.0015 * length, rel=1e-12)
    column = next(c for c in items["primary_strut"].checks if c.kind == "column_buckling")
    assert column.params["L"] == pytest.approx(lp, rel=1e-12)          # pinned over the pin-to-pin length


def test_a_wider_stance_weighs_more():
    """Fixed sections: the struts lengthen with the footpad radius, so the leg's weight rises strictly."""
    weights = [sum(i.count * i.weight_each()[0] for i in _items(_leg(rf)).values()) for rf in (1.5, 2.0, 2.5, 3.0)]
    assert all(b > a for a, b in zip(weights, weights[1:]))


def test_johnson_euler_over_the_derived_pin_length():
    """A secondary whose pin-to-pin length the geometry makes 34 in, a 2.0 x 0.058 in 6061-T6 tube at 9,000 lbf:
    L/k 49.5 below the transition 74.7, Johnson's parabola sigma_cr = Fcy - (Fcy/2 pi)^2 (L/k)^2 / E (Bruhn 1973
    eq. C2.6), f = 1.074 (Euler's would be 1.57). Hand arithmetic: 1e-9; the printed f to its 3 decimals."""
    rh = 0.5                                      # hardpoints and footpad on a 0.5 m radius
    h = sqrt((34 * IN) ** 2 - (rh - rh * cos(SPREAD)) ** 2 - (rh * sin(SPREAD)) ** 2)
    leg = tripod_from_params(rh, rh, H, footpad_height=H - h, secondary_spread=SPREAD, primary=PRIMARY,
                             secondary_compression=SEC_C, secondary_tension=SEC_T, footpad_diameter=0.4)
    assert leg.rest_lengths[1] == pytest.approx(34 * IN, rel=1e-9)
    members = {"secondary_strut": {"material": "6061-t6", "section": {"shape": "tube", "outside_diameter": "2.0 in",
                                                                      "wall": "0.058 in"}}}
    loads = TripodLoads(0.0, (9000 * LBF, 9000 * LBF), (0.0, 0.0), 0.0, 0.0, 0.0, 0.0, 0.0)
    strut = _items(leg, members, loads)["secondary_strut_1"]
    o = next(o for o in strut.evaluate() if o.mode == "column_buckling")
    e, fcy, d, t = 9.9e6, 35_000, 2.0 - 0.058, 0.058
    lk = 34 / (d / (2 * sqrt(2)))
    johnson = fcy - (fcy / (2 * pi)) ** 2 * lk ** 2 / e
    assert o.allowable / PSI == pytest.approx(johnson, rel=1e-9)
    assert o.factor == pytest.approx(johnson / (9000 / (pi * d * t)), rel=1e-9)
    assert o.factor == pytest.approx(1.074, abs=0.001)


def _fe_buckling(a: float, b: float, n: int = 60) -> float:
    """Least buckling load (units of E I = 1) of a uniform column pinned at x = 0, held laterally at x = a, free at
    x = a + b: Hermite beam elements, K phi = P Kg phi (Cook et al. 2002 sec. 18.2: the consistent geometric
    stiffness of a cubic beam element)."""
    x = np.sort(np.unique(np.concatenate([np.linspace(0, a, n + 1), np.linspace(a, a + b, n + 1)])))
    dof = 2 * len(x)
    K, G = np.zeros((dof, dof)), np.zeros((dof, dof))
    for i, L in enumerate(np.diff(x)):
        k = np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                      [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]]) / L ** 3
        g = np.array([[36, 3 * L, -36, 3 * L], [3 * L, 4 * L * L, -3 * L, -L * L],
                      [-36, -3 * L, 36, -3 * L], [3 * L, -L * L, -3 * L, 4 * L * L]]) / (30 * L)
        idx = slice(2 * i, 2 * i + 4)
        K[idx, idx] += k
        G[idx, idx] += g
    held = {0, 2 * int(np.argmin(abs(x - a)))}                  # lateral deflection at the pin and at the knee
    keep = [j for j in range(dof) if j not in held]
    w = np.linalg.eigvals(np.linalg.solve(G[np.ix_(keep, keep)], K[np.ix_(keep, keep)]))
    return float(min(w.real[w.real > 0]))


@pytest.mark.parametrize("a, b", [(1.0, 1.0), (1.5, 0.5), (0.5, 1.5), (2.0, 0.3)])
def test_overhang_effective_length_against_finite_elements(a, b):
    """pi^2 / L_e^2 (E I = 1) against the finite-element eigenvalue: 120 cubic elements converge as h^4, well
    inside 1e-6."""
    assert pi ** 2 / overhang_effective_length(a, b) ** 2 == pytest.approx(_fe_buckling(a, b), rel=1e-6)


def test_overhang_effective_length_limits():
    """a -> 0: the clamped cantilever, L_e = 2 b (K = 2); b -> 0: the pinned span, L_e = a (Timoshenko & Gere 1961
    sec. 2.1). At a/b = 1e-6 and 1e6 the limits hold to 1e-5 (first-order in the ratio)."""
    assert overhang_effective_length(1e-6, 1.0) == pytest.approx(2.0, rel=1e-5)
    assert overhang_effective_length(1.0, 1e-6) == pytest.approx(1.0, rel=1e-5)


def test_cantilever_members_carry_the_knee_moment():
    """The cantilever's primary: the part above the knee (a = (1 - s) L0) and the overhang (b = s L0) each weigh
    their own length, and both take the knee moment |F_perp| b of `strut_forces` in their combined check."""
    leg = _leg(2.0, 0.3)
    F = np.array([3e3, 1e3, 2e4])
    loads = TripodLoads.from_forces(leg, [F])
    assert loads.knee_moment == pytest.approx(strut_forces(leg, F).knee_moment, rel=1e-15)
    members = {k: v for k, v in MEMBERS.items() if k != "primary_strut"}
    members |= {"primary_upper": {"material": "7178-t6", "section": {**TUBE, "outside_diameter": "70 mm"}},
                "primary_lower": {"material": "7178-t6", "section": TUBE}}
    items = _items(leg, members, loads)
    l0 = leg.rest_primary_length
    assert items["primary_upper"].length == pytest.approx(0.7 * l0, rel=1e-12)
    assert items["primary_lower"].length == pytest.approx(0.3 * l0, rel=1e-12)
    for name in ("primary_upper", "primary_lower"):
        combined = next(c for c in items[name].checks if c.kind == "combined")
        assert combined.params["M"] == pytest.approx(loads.knee_moment, rel=1e-12)
    column = next(c for c in items["primary_lower"].checks if c.kind == "column_buckling")
    assert column.params["L"] == pytest.approx(overhang_effective_length(0.7 * l0, 0.3 * l0), rel=1e-12)
    assert column.params["P"] == pytest.approx(max(loads.primary, loads.primary_upper_compression), rel=1e-12)
    with pytest.raises(InputError, match="primary_strut"):
        _items(leg, MEMBERS, loads)                 # an inverted tripod's member on a cantilever


def test_cores_from_their_cells():
    """Each core is the prism of area = crushing force / crush strength and length = stroke / usable fraction
    (App. V): the primary's 20 kN over 0.40 m, each secondary's 10 kN over 0.20 m and 6 kN over 0.10 m. 1e-12."""
    items = _items(_leg())
    hc = MATERIALS["al-honeycomb"]
    for name, force, stroke in (("core_primary", 2e4, 0.40), ("core_secondary_1_compression", 1e4, 0.20),
                                ("core_secondary_2_tension", 6e3, 0.10)):
        expected = hc.density * force / hc.crush_strength * stroke / hc.stroke_fraction
        assert items[name].weight_each()[0] == pytest.approx(expected, rel=1e-12)


def test_footpad_plate_takes_the_legs_footpad_diameter():
    """The footpad plate's diameter is the leg's (0.4 m); the section must not give another."""
    pad = _items(_leg())["footpad"]
    assert pad.section.dims["diameter"] == pytest.approx(0.4, rel=1e-15)
    bad = {**MEMBERS, "footpad": {**MEMBERS["footpad"], "section": {"shape": "plate", "thickness": "6 mm",
                                                                    "diameter": "0.5 m"}}}
    with pytest.raises(InputError, match="footpad diameter"):
        _items(_leg(), bad)
