"""Member-load envelopes against Tables 14-22, the cell curves against Sec. IV, Fig. 10 force ratios.

The geometry of examples/affdl-tr-66-33/loads/articulated.toml is fitted to configuration 3 only
(docs/articulated-geometry.md); Tables 15-22 are held out. Tolerances: the issue's targets (5 % on the
calibration table, 10 % held out); positions are compared within one grid step.
"""

from functools import lru_cache

import numpy as np
import pytest

from alightsize.loads.envelopes import cell_forces
from alightsize.loads.quasi_static import run_loads
from alightsize.loads.config import read_loads
from alightsize_sim.articulated_cells import lower_lever, upper_lever
from alightsize_sim.articulated_statics import member_loads, reactions

from conftest import EXAMPLES
from reference_tables_14_22 import CELL_CURVES, MAGNITUDE_ONLY, SUSPECTED_MISPRINTS, TABLES

LBF, FT = 4.4482216152605, 0.3048
LOADS = EXAMPLES / "loads" / "articulated.toml"


@lru_cache(maxsize=1)
def _result():
    return run_loads(read_loads(LOADS))


def _rows(config: str):
    """(printed row, model extreme) per printed row; suspected misprints replaced by their correction."""
    env = {r.member: r for r in _result().envelopes[config]}
    out = []
    for row in TABLES[config]:
        member, value = row[0], row[1]
        row = SUSPECTED_MISPRINTS.get((config, member, int(np.sign(value))), (row,))[0]
        e = env[member]
        if (config, member) in MAGNITUDE_ONLY:
            model = max((x for x in (e.tension, e.compression) if x), key=lambda x: abs(x.value))
        else:
            model = e.tension if value > 0 else e.compression
        out.append((row, model))
    return out


def _rel(row, model) -> float:
    return abs(abs(model.value / LBF) - abs(row[1])) / abs(row[1])


def _near(row, model) -> bool:
    a, b, p = np.degrees(model.at)
    db = (b - row[3] + 180) % 360 - 180
    return abs(a - row[2]) <= 2 and abs(db) <= 10 and abs(p - row[4]) <= 1


def _flat(config: str, row, model) -> bool:
    """The model's load at the printed position is within 1 % of its extreme (the printed point is as
    good a place for the extreme as the model's own). Combined tables: the source configurations."""
    cases = _result().config.cases
    names = {"3457": ("3", "4", "5", "7"), "68": ("6", "8")}.get(config, (config,))
    a, b, p = np.radians(row[2:5])
    best = 0.0
    for case in (c for c in cases if c.name in names):
        af1, af2 = cell_forces(case, a, p)
        load = member_loads(reactions(case.geometry, a, b, p, af1, af2), case.truss)[row[0]]
        best = max(best, float(load) * np.sign(model.value))
    return best >= 0.99 * abs(model.value)


def test_table_14_calibration_within_5_percent():
    errs = [_rel(r, m) for r, m in _rows("3")]
    assert max(errs) < 0.05                                    # issue 3 target (measured: max 4.3 %, median 1.1 %)
    near = sum(_near(r, m) for r, m in _rows("3"))
    assert near > len(errs) / 2                                # positions match for most members (measured 12/17)


@pytest.mark.parametrize("config", ["4", "5", "6", "7", "8", "9", "3457", "68"])
def test_held_out_tables_within_10_percent(config):
    errs = [_rel(r, m) for r, m in _rows(config)]
    assert max(errs) < 0.10, [f"{r[0]} {100 * e:.1f} %" for (r, _), e in zip(_rows(config), errs) if e >= 0.10]


def test_held_out_summary():
    rows = [(c, r, m) for c in ("4", "5", "6", "7", "8", "9", "3457", "68") for r, m in _rows(c)]
    # Issue 3: "positions of occurrence matching for most members": within one grid step, or where the
    # printed position is within 1 % of the model's extreme (the load is flat there). Measured 77 of 130
    # (56 within a step); values: median 1.9 %, 91 % within 5 %, all within 10 % (test above).
    assert sum(_near(r, m) or _flat(c, r, m) for c, r, m in rows) > len(rows) / 2


def test_shipped_cell_curves_are_the_printed_ones():
    cfg = read_loads(LOADS)
    for case in cfg.cases:
        up, lo, psi0 = CELL_CURVES[case.name]
        for curve, printed in ((case.upper, up), (case.lower, lo)):
            np.testing.assert_allclose(np.array(curve.deflection) / FT, [d for d, _ in printed], rtol=1e-12, atol=1e-12)
            np.testing.assert_allclose(np.array(curve.force) / LBF, [f for _, f in printed], rtol=1e-12)
        assert np.degrees(case.psi_initial) == pytest.approx(psi0)


def test_fig_10_peg_leg_ratio_and_the_recorded_conflicts():
    g = read_loads(LOADS).cases[0].geometry

    def ratio(a):                                              # Fig. 10, lower curve
        return lower_lever(g, a) / (g.AS * np.sin(a) + g.AL * np.cos(a))

    # RECORDED: Fig. 10 starts at 0.35, but at alpha = 0 the ratio is AS/AL = 8/25 = 0.32 for any cell
    # attachment (the lever about the ring edge is AS, the tip lever AL).
    assert ratio(0.0) == pytest.approx(8 / 25, rel=1e-12)
    a = np.radians(np.arange(0, 46))
    r = ratio(a)
    assert r.min() < r[0] and r.min() < r[-1]                  # dips and recovers, as Fig. 10 shows
    assert r[-1] < 0.35                                        # RECORDED: short of the printed 0.35 at 45 deg
    # RECORDED: the tables and Fig. 10's upper curve disagree. By eq. 59-61 at (2, 0, +30 deg),
    # dR11/dAF1 = C18 sin(eta - psi) / (sin psi C20 + cos psi C18). Fig. 10's 0.40 at +30 deg means
    # sin(eta - psi) = 0.40 cos 30; Tables 14 and 17 (upper cell 36,000 and 72,000 lbf) differ in R11 by
    # 61,909 - 48,759 = 13,150 lbf, i.e. dR11/dAF1 = 0.365.
    a, p = np.radians(2), np.radians(30)
    c18, c20 = g.AS * np.sin(a) + g.AL * np.cos(a), g.AL * np.sin(a) - g.AS * np.cos(a)

    def slope(s):
        return c18 * s / (np.sin(p) * c20 + np.cos(p) * c18)

    fig10, tables = slope(0.40 * np.cos(p)), 13_150 / 36_000
    assert abs(fig10 - tables) / tables > 0.2                  # the two printed sources conflict (0.48 vs 0.365)
    r1 = reactions(g, a, 0.0, p, 36_000 * LBF, 30_000 * LBF)
    r2 = reactions(g, a, 0.0, p, 72_000 * LBF, 30_000 * LBF)
    model = (r2.R11 - r1.R11) / (36_000 * LBF)
    assert model == pytest.approx(slope(upper_lever(g, p)), rel=1e-12)       # eq. 59-61 closed form
    assert abs(model - tables) < abs(model - fig10)            # the shipped geometry follows the tables...

    def par(d):
        return upper_lever(g, np.radians(d)) / np.cos(np.radians(d))

    assert abs(par(-30) - 0.55) > 0.02 and abs(par(30) - 0.40) > 0.02        # ...so Fig. 10 is missed


def test_fig_10_parallelogram_alone_is_reachable_but_contradicts_the_tables():
    # Fig. 10's upper curve by itself is reachable: refitting only the upper cell's attachments (AA, AB,
    # AG, AH, PHI) gives 0.55 at -30 deg and 0.40 at +30 deg within 0.02. But that cell strokes 1.22 ft
    # from psi -15 to +30, past configuration 3's 0.97 ft plateau, so its cell would bottom (72,000 lbf)
    # before +30 deg, while Tables 14 and 15 print the same +30 deg loads (R11 48,759) as for a cell still
    # crushing at 36,000 lbf. Hence the shipped geometry follows the tables (docs/articulated-geometry.md).
    from scipy.optimize import least_squares
    from alightsize_sim.articulated_cells import upper_deflection
    g0 = read_loads(LOADS).cases[0].geometry
    IN = 0.0254

    def geo(x):
        return g0._replace(AA=x[0] * IN, AB=x[1] * IN, AG=x[2] * IN, AH=x[3] * IN, PHI=np.radians(x[4]))

    def par(g, p):
        return upper_lever(g, np.radians(p)) / np.cos(np.radians(p))

    fit = least_squares(lambda x: [par(geo(x), -30) - 0.55, par(geo(x), 30) - 0.40], [1, 1, 1, 1, 0],
                        bounds=([0, 0, 0, 0, -60], [30, 30, 30, 30, 60]))
    g = geo(fit.x)
    assert abs(par(g, -30) - 0.55) < 0.02 and abs(par(g, 30) - 0.40) < 0.02
    assert upper_deflection(g, np.radians(30), np.radians(-15)) / FT > 0.97
    assert upper_deflection(g0, np.radians(30), np.radians(-15)) / FT < 0.97      # shipped: 0.75 ft
