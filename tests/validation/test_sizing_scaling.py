"""Sizing meets the required factor tightly; Table 27 and Sec. II figures; config scaling by dimension."""

from math import pi

import pytest

from alightsize.pipeline.design import run_design
from alightsize.pipeline.config import prepare, read_design
from alightsize.weights.scaling import (cushioning_weight_fraction, impact_energy_per_weight, scale_tree, table27)
from alightsize.common.units import parse
from conftest import ROOT

SIZED = ROOT / "examples" / "sizing" / "articulated_3457_sized.toml"


def test_sized_members_sit_in_the_required_band():
    res = run_design(read_design(SIZED))
    assert res.ok and len(res.sizings) == 5
    items = {i.name: i for i in prepare(read_design(SIZED)).items}
    for s in res.sizings:
        assert s.feasible
        spec = items[s.item].size
        if spec.gauges:
            # Standard gauges: the chosen gauge passes and the next one down fails.
            j = spec.gauges.index(s.sized)
            assert s.factor_sized >= 1.2
            if j > 0:
                thinner = items[s.item].section.with_dim("wall", spec.gauges[j - 1])
                assert items[s.item].governing_factor(thinner) < 1.2
        else:
            # Continuous: bisection to 1e-9 relative leaves the governing factor in [1.20, 1.22] (issue 2).
            assert 1.2 <= s.factor_sized <= 1.22, s


def test_sized_rod_matches_closed_form():
    # Rod in tension: f = Fcy pi d^2 / (4 P) = 1.2 -> d = sqrt(4 (1.2) P / (pi Fcy)); 12,000 lbf, 69,000 psi.
    res = run_design(read_design(SIZED))
    rod = next(s for s in res.sizings if s.item == "Parallelogram Absorber Rods")
    d_exact = (4 * 1.2 * 12000 / (pi * 69000)) ** 0.5 * 0.0254
    assert rod.sized == pytest.approx(d_exact, rel=1e-8)  # bisection tolerance 1e-9


# Table 27 as printed (model -> full scale). Mass density of the 300 lb column is printed "2.5":
# a misprint for 0.25 = 1.52 / 1.825^3 (GUIDE.md), asserted below as the corrected value.
TABLE27_3000 = dict(acceleration=1, length=4, mass=15.2, angular_velocity=0.5, energy=60.8, force=15.2,
                    mass_density=0.238, moment_of_inertia=243, pressure_stress=0.95, spring_rate=3.8, time=2,
                    velocity=2)
TABLE27_300 = dict(acceleration=1, length=1.825, mass=1.52, angular_velocity=0.739, energy=2.78, force=1.52,
                   mass_density=0.25, moment_of_inertia=5.08, pressure_stress=0.455, spring_rate=0.833,
                   time=1.35, velocity=1.35)


@pytest.mark.parametrize("length, mass, printed", [(4, 15.2, TABLE27_3000), (1.825, 1.52, TABLE27_300)])
def test_table27(length, mass, printed):
    got = table27(length, mass)
    for k, v in printed.items():
        # 0.5 %: the report rounded its intermediates to three figures (largest: inertia 5.06 vs 5.08, 0.35 %).
        assert got[k] == pytest.approx(v, rel=0.005), k


def test_table27_300lb_mass_density_misprint():
    assert table27(1.825, 1.52)["mass_density"] == pytest.approx(1.52 / 1.825 ** 3)
    assert abs(table27(1.825, 1.52)["mass_density"] - 2.5) > 2  # printed "2.5" is not reachable


def test_section_ii_impact_energy_and_cushioning():
    ft = 0.3048
    e_per_w = impact_energy_per_weight(35 * ft, 15 * ft) / ft       # ft (= ft-lbf per lbf)
    assert e_per_w == pytest.approx(22.54, abs=0.01)                # printed E = 22.54 W
    frac = cushioning_weight_fraction(e_per_w, 10000.0)            # 10,000 ft-lbf per lb of absorber
    assert 100 * frac == pytest.approx(0.225, abs=0.0006)           # printed 0.225 percent


def test_scale_tree_scales_each_quantity_by_its_dimension():
    model = {"leg": {"AU": "11 in", "curve": [["0 in", "250 lbf"], ["2 in", "250 lbf"]]},
             "capsule": {"weight": "197.5 lb", "inertia": "3.326 slug*ft^2", "psi0": "-15 deg"},
             "v": "17.5 ft/s", "name": "Test model", "count": 4}
    full = scale_tree(model, 4.0, 15.2)
    # App. VI: 197.5 lb x 15.2 and 3.326 slug ft^2 x 243.2; lengths x 4, forces x 15.2, velocity x 2.
    assert parse(full["capsule"]["weight"], "mass") == pytest.approx(parse("3002 lb", "mass"), rel=1e-5)
    assert parse(full["capsule"]["inertia"], "inertia") == pytest.approx(parse("808.88 slug*ft^2", "inertia"), rel=1e-5)
    assert parse(full["leg"]["AU"], "length") == pytest.approx(parse("44 in", "length"))
    assert parse(full["leg"]["curve"][1][1], "force") == pytest.approx(parse("3800 lbf", "force"))
    assert parse(full["v"], "velocity") == pytest.approx(parse("35 ft/s", "velocity"))
    assert full["capsule"]["psi0"] == "-15 deg" and full["name"] == "Test model" and full["count"] == 4
    back = scale_tree(full, 1 / 4.0, 1 / 15.2)
    assert parse(back["capsule"]["inertia"], "inertia") == pytest.approx(parse("3.326 slug*ft^2", "inertia"), rel=1e-5)
