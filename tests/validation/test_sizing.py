"""Sizing finds the lightest passing value, against closed forms: an annular plate whose weight falls as its
inner diameter grows, a feasible band narrower than the scan spacing, standard gauges, and the fallbacks."""

from math import exp, log, pi, sqrt
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from alightsize.pipeline.sizing import size_item
from alightsize.pipeline.config import prepare, read_design
from alightsize.pipeline.design import run_design
from alightsize.reports.design_report import summary_json

IN, PSI, LBF, LB = 0.0254, 6894.757293168361, 4.4482216152605, 0.45359237
FCY, E, M = 69000 * PSI, 10e6 * PSI, 3.33          # 7178-T6 (materials/7178-t6.toml): Fcy, E, Roark's m = 1/nu
RHO = 0.100 * LB / IN ** 3
NEED = 1.2


def _item(tmp_path: Path, body: str):
    """The one item of a design config holding `body` (a [[item]] table), as prepared."""
    path = tmp_path / "design.toml"
    path.write_text(f'[design]\nconfiguration = "t"\n[audit]\nrequired_design_factor = {NEED}\n{body}')
    return path, prepare(read_design(path)).items[0]


# ---------------------------------------------------------------- annular plate: weight falls with the bore

A, T_PLATE, Q = 3.0 * IN, 0.2 * IN, 100 * PSI      # outer radius, thickness, uniform pressure


def _annular_factor(di: float) -> float:
    """Fcy / sigma_t at the inner edge, outer edge supported, inner edge free, uniform pressure (Roark 1954
    p. 199); sigma_t falls as the inner radius b grows (0 at b = a), so f rises with it."""
    a, b, m, t = A, di / 2, M, T_PLATE
    s = 3 * Q / (4 * m * t * t * (a * a - b * b)) * (
        4 * a ** 4 * (m + 1) * log(a / b) + 4 * a * a * b * b + b ** 4 * (m - 1) - a ** 4 * (m + 3))
    return FCY / s


def _disc(di: float) -> float:
    """W = rho pi/4 (d^2 - d_i^2) t (AFFDL-TR-66-33 App. V, plates and caps)."""
    return RHO * pi / 4 * ((2 * A) ** 2 - di * di) * T_PLATE


def _annular(tmp_path, size: str, weight: str = 'weight = { method = "disc" }\n'):
    return _item(tmp_path, f"""[[item]]
name = "Annular cap"
material = "7178-t6"
section = {{ shape = "plate", diameter = "6 in", thickness = "0.2 in", inner_diameter = "1 in" }}
{weight}size = {size}
  [[item.check]]
  kind = "plate_annular_inner_supported_uniform_pressure"
  pressure = "100 psi"
""")


# The smallest passing inner diameter, f = 1.2, solved in closed form: 2.548 in (brentq to 1e-15 relative).
DI_MIN = brentq(lambda di: _annular_factor(di) - NEED, 0.5 * IN, 5.9 * IN, xtol=1e-18, rtol=1e-15)


def test_annular_plate_is_sized_to_its_lightest_inner_diameter(tmp_path):
    path, item = _annular(tmp_path, '{ dimension = "inner_diameter", min = "0.5 in", max = "4 in" }')
    xs = np.linspace(DI_MIN, 4 * IN, 50)
    assert all(_annular_factor(x) >= NEED for x in xs[1:])      # feasible from DI_MIN to the range's max
    s = size_item(item)
    # The weight falls as the bore grows: the lightest passing value is the largest, the range's max (exactly).
    assert s.feasible and s.at_bound and s.sized == 4 * IN
    assert s.factor_sized == pytest.approx(_annular_factor(4 * IN), rel=1e-12)   # same formula, round-off
    assert s.weight_sized == pytest.approx(_disc(4 * IN), rel=1e-12)
    assert s.weight_sized < _disc(DI_MIN)            # 0.1425 against 0.2102 kg at the smallest passing bore
    js = summary_json(run_design(read_design(path)))["sizing"][0]
    assert js["at_bound"] is True and js["sized_m"] == 4 * IN and js["feasible"] is True


def test_annular_plate_without_weight_falls_back_to_the_smallest_passing(tmp_path):
    _, item = _annular(tmp_path, '{ dimension = "inner_diameter", min = "0.5 in", max = "4 in" }', weight="")
    s = size_item(item)
    # Bisection to rtol 1e-9 keeps the feasible end: within 1e-9 above the closed-form root.
    assert s.feasible and not s.at_bound and s.weight_sized is None
    assert DI_MIN <= s.sized <= DI_MIN * (1 + 2e-9)
    assert s.factor_sized >= NEED


GAUGES = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 3.8]       # in; 3.0, 3.5 and 3.8 pass (DI_MIN = 2.548 in)


@pytest.mark.parametrize("weight, expected", [
    ('weight = { method = "disc" }\n', 3.8),                    # lightest passing: the largest bore
    ('weight = { method = "fixed", weight = "1 lb" }\n', 3.0),  # equal weights: the smaller dimension
    ("", 3.0),                                                  # no weight: the smallest passing
])
def test_gauges_pick_the_lightest_passing(tmp_path, weight, expected):
    gauges = ", ".join(f'"{g} in"' for g in GAUGES)
    _, item = _annular(tmp_path, f'{{ dimension = "inner_diameter", gauges = [{gauges}] }}', weight)
    passing = [g for g in GAUGES if _annular_factor(g * IN) >= NEED]
    assert passing == [3.0, 3.5, 3.8]
    assert min(passing, key=lambda g: _disc(g * IN)) == 3.8
    s = size_item(item)
    assert s.feasible and s.sized == pytest.approx(expected * IN, rel=1e-15)
    assert s.at_bound == (expected == GAUGES[-1])


def test_gauges_none_passing_is_infeasible_at_the_largest_factor(tmp_path):
    _, item = _annular(tmp_path, '{ dimension = "inner_diameter", gauges = ["0.5 in", "1.0 in", "2.0 in"] }')
    s = size_item(item)
    # f rises with the bore (Roark p. 199): 2.0 in has the largest factor, 0.919, below 1.2.
    assert not s.feasible and s.sized == pytest.approx(2.0 * IN, rel=1e-15)
    assert s.factor_sized == pytest.approx(_annular_factor(2.0 * IN), rel=1e-12) and s.factor_sized < NEED


# ---------------------------------------------------------------- a band narrower than the scan spacing

# A thin tube of fixed wall t sized on its outside diameter D, mean diameter d = D - t (App. IV: A = pi d t,
# I = pi (d/2)^3 t, so I/A = d^2/8), with two checks for the same load P:
#   Euler column, f_col = pi^2 E (d^2/8) / L^2 / (P / (pi d t)) = pi^3 E d^3 t / (8 L^2 P), rising with d;
#   local buckling, SP-8007 eq. 4 knockdown on Timoshenko & Gere eq. 11-13 at r = d/2:
#   f_loc = gamma(r/t) E t / (r sqrt(3 (1 - nu^2))) / (P / (2 pi r t)) = 2 pi gamma(r/t) E t^2 / (c P),
#   c = sqrt(3 (1 - nu^2)), falling with d through gamma = 1 - 0.901 (1 - exp(-sqrt(r/t) / 16)).
# Both are solved for f = 1.2 in closed form: d1 from f_col, d2 from gamma(r/t) = 1.2 c P / (2 pi E t^2).
T_TUBE, P_TUBE = 0.05 * IN, 40000 * LBF
C = sqrt(3 * (1 - (1 / M) ** 2))


def _f_col(d: float, length: float) -> float:
    return pi ** 3 * E * d ** 3 * T_TUBE / (8 * length ** 2 * P_TUBE)


def _f_loc(d: float) -> float:
    gamma = 1 - 0.901 * (1 - exp(-sqrt(d / 2 / T_TUBE) / 16))
    return 2 * pi * gamma * E * T_TUBE ** 2 / (C * P_TUBE)


def _d2() -> float:
    """Mean diameter where f_loc = 1.2: gamma = 1.2 c P / (2 pi E t^2), r/t = (16 (-ln(1 - (1 - gamma)/0.901)))^2."""
    gamma = NEED * C * P_TUBE / (2 * pi * E * T_TUBE ** 2)
    return 2 * T_TUBE * (16 * -log(1 - (1 - gamma) / 0.901)) ** 2


def _length_for(d1: float) -> float:
    """Column length at which f_col = 1.2 at mean diameter d1."""
    return sqrt(pi ** 3 * E * d1 ** 3 * T_TUBE / (8 * NEED * P_TUBE))


def _tube(tmp_path, length: float):
    return _item(tmp_path, f"""[[item]]
name = "Thin post"
material = "7178-t6"
section = {{ shape = "tube", outside_diameter = "12 in", wall = "0.05 in" }}
weight = {{ method = "tube", length = "40 in" }}
size = {{ dimension = "outside_diameter", min = "8 in", max = "24 in" }}
  [[item.check]]
  kind = "column_buckling"
  load = "40000 lbf"
  length = "{length / IN!r} in"
  formula = "euler"
  [[item.check]]
  kind = "local_buckling"
  load = "40000 lbf"
  formula = "sp8007"
""")


def test_a_band_narrower_than_the_scan_is_found_at_its_lightest_edge(tmp_path):
    d2 = _d2()                                       # 16.283 in (r/t = 162.8)
    d1 = d2 * (1 - 0.002)                            # the band: D from d1 + t to d2 + t, 0.033 in wide
    _, item = _tube(tmp_path, _length_for(d1))
    scan = np.linspace(8 * IN, 24 * IN, 64)
    assert (d2 - d1) < (scan[1] - scan[0]) / 7       # the band is far narrower than the scan spacing, 0.254 in,
    assert not np.any((scan >= d1 + T_TUBE) & (scan <= d2 + T_TUBE))   # and no scan point falls in it
    assert _f_loc(d1) >= NEED and _f_col(d2, _length_for(d1)) >= NEED
    s = size_item(item)
    # Tube weight rho pi d t l rises with d: the lightest passing is the band's lower edge, d1 + t, where
    # f_col = 1.2; bisection to rtol 1e-9 keeps the feasible end (the formulas agree to round-off).
    assert s.feasible and not s.at_bound
    assert d1 + T_TUBE <= s.sized * (1 + 1e-12) and s.sized <= (d1 + T_TUBE) * (1 + 2e-9)
    assert s.factor_sized >= NEED
    assert s.weight_sized == pytest.approx(RHO * pi * (s.sized - T_TUBE) * T_TUBE * 40 * IN, rel=1e-12)


def test_a_band_out_of_reach_is_infeasible_at_its_peak(tmp_path):
    d2 = _d2()
    length = _length_for(d2 * 1.002)                 # f_col reaches 1.2 only above d2: no value passes
    _, item = _tube(tmp_path, length)
    d_peak = brentq(lambda d: _f_col(d, length) - _f_loc(d), 8 * IN, 24 * IN, xtol=1e-18, rtol=1e-15)
    f_peak = _f_loc(d_peak)                          # the largest factor, where f_col = f_loc: 1.1993
    assert f_peak < NEED
    s = size_item(item)
    # Bounded Brent stops within xatol (1e-9 of the bound) plus sqrt(eps)|x|, about 2e-8 relative: 1e-6.
    assert not s.feasible and s.sized == pytest.approx(d_peak + T_TUBE, rel=1e-6)
    assert s.factor_sized == pytest.approx(f_peak, rel=1e-6)
