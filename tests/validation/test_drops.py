"""The drop tests of AFFDL-TR-66-33 Sec. VI simulated with the test model (drops 1-11 of Table 5, no drop 7)
against Tables 6-13: energy closure, the cells' energy against each drop's energy, strokes against the
analytical columns."""

from __future__ import annotations

import numpy as np
import pytest

from alightsize_sim import crush_cell

from alightsize.landings.drops import FT, FT_LB, compare, run_drop
from alightsize.landings.output import outcome
from alightsize.common import units
from alightsize.landings.drop_tables import (DROPS, LEGS, STROKES_ENERGIES, corrected_strokes_energies,
                                            implied_static_force, simulation_cell_force, simulation_fit_points)

LBF = units.parse("1 lbf", "force")                                     # N per lbf


@pytest.mark.parametrize("n", sorted(DROPS))
def test_drop_closes_energy(n):
    """Closure below 1e-4 of the impact energy on every drop (issue 5)."""
    res = run_drop(n).res
    assert res.status != "failed"
    assert res.energy["closure_rel"] < 1e-4


@pytest.mark.parametrize("n", sorted(STROKES_ENERGIES))
def test_cell_energy_matches_the_drop_energy(n):
    """Each drop's total cell energy within 5 % of the printed drop energy (issue 5; the 1966 program: mean
    0.5 %, worst 4.1 %). Measured: worst 3.2 % (drop 2), mean of |error| 1.5 %."""
    res = run_drop(n).res
    energy = res.cell_energy.sum() / FT_LB
    assert energy == pytest.approx(STROKES_ENERGIES[n]["drop_energy_ft_lb"], rel=0.05)


@pytest.mark.parametrize("n", sorted(STROKES_ENERGIES))
def test_total_stroke_against_the_analytical_tables(n):
    """Sum of the eight cells' permanent strokes (the report's analytical strokes are permanent positions, Sec. VI.D)
    within 10 % of the analytical columns of Tables 6-13 (the issue's target). Measured: -3.4 % to +2.8 %, mean
    |difference| 2.1 %."""
    drop = run_drop(n)
    rows = compare(drop)
    simulated = sum(r["simulated_stroke_m"] for r in rows)
    printed = sum(r["analytical_stroke_m"] for r in rows)
    assert simulated == pytest.approx(printed, rel=0.10)


@pytest.mark.parametrize("n", sorted(STROKES_ENERGIES))
def test_cells_turn_the_analytical_strokes_into_the_analytical_energies(n):
    """The drop's upper cells, crushed to each analytical stroke of Tables 6-13 plus their spring-back and
    unloaded, absorb the printed analytical energy (the report's loading/unloading slope correction, Sec. VI.D):
    within 3 % on every stroke of 0.05 ft or more (measured -1.8 % to +2.4 %, mean |error| 1.0 %), within 12 % on
    the shorter ones over 0.03 ft. E = F (s - d): the scenes take one spring-back d for all drops of a cell set
    (0.0187 ft), the report's fitted d spreads 0.0170-0.0210 ft, and that spread is 11 % of s - d = 0.018 ft for
    drop 3's 0.0366 ft (measured -10.9 %). The plateau force times the stroke (E = F s, what the curves before the
    fit gave) is 8 % to 88 % high."""
    drop = run_drop(n)
    d, f, k, _, y = drop.cfg.scene.legs[0].upper.arrays
    fmax = f[1]                                                         # every stroke here ends on the plateau
    printed = corrected_strokes_energies()[n]["analytical"]["upper"]     # Table 12's swapped rows swapped back
    for stroke_ft, energy_ft_lb in zip(printed["stroke_ft"], printed["energy_ft_lb"]):
        if stroke_ft > 0.03:
            dmax = stroke_ft * FT + fmax / k                            # its permanent set is the printed stroke
            absorbed = (crush_cell.static_work(d, f, k, y, 0.0, 0.0, 0.0, dmax)
                        - crush_cell.elastic_energy(k, dmax, fmax, dmax))
            assert absorbed / FT_LB == pytest.approx(energy_ft_lb, rel=0.03 if stroke_ft >= 0.05 else 0.12)


@pytest.mark.parametrize("n", sorted(STROKES_ENERGIES))
def test_drop_scenes_take_the_forces_of_the_reports_simulation(n):
    """Each tabled drop's scene crushes at the force the report's simulation of that drop used, recovered from
    Tables 6-13 (Sec. VI.A: one measured curve per cell type and drop): to the 1 lb the scene files round to.
    The recovery itself: the printed analytical energies follow the fitted E = F (s - d) within 3 ft-lb on every
    fitted cell (their 1 ft-lb rounding and the 4-digit strokes), and on drops 1 and 6 F lies within every
    cell's experimental rounding bound (energy +-0.5 ft-lb over the stroke, Sec. VI.D)."""
    cells = run_drop(n).cfg.scene.legs[0]
    for cell, model in (("upper", cells.upper), ("lower", cells.lower)):
        force_lb, how = simulation_cell_force(n, cell)
        assert model.arrays[1][1] / LBF == pytest.approx(force_lb, abs=0.5)
        if how == "analytical fit":
            pts = simulation_fit_points(n, cell)
            d = np.mean([s - e / force_lb for s, e in pts])
            assert max(abs(force_lb * (s - d) - e) for s, e in pts) <= 3.0
        else:
            for leg in LEGS:
                implied = implied_static_force(n, leg, cell)
                if implied:
                    assert abs(force_lb - implied[0]) <= implied[1] + 1e-9


def test_drop_5_ends_on_the_capsule_bottom_as_the_report_did():
    """Sec. VI.D: drop 5's simulation stopped when the capsule bottom interfered with the ground."""
    _, cfg, res = run_drop(5)
    assert outcome(cfg, res)[0] == "body_contact"
