"""Fit the unprinted dimensions of the articulated landing leg to AFFDL-TR-66-33 (configuration 3 only).

The report prints AU = 44 in, AD = 24 in, AL = 25 in and a 16 in fulcrum ring (AS = 8 in) but none of
the other dimensions of Fig. 22-25. They are reconstructed here from what the report does print about
configuration 3:

- Table 14 (l. 3657-3677): the maximum tension and compression of every member with the position
  (alpha, beta, psi) where it occurs, computed by the model of `alightsize.loads.envelopes` over the
  default grid (alpha by 1 deg, beta -175..180 by 5, psi -15..+30 by 1; alpha range below);
- Fig. 10 (l. 734-736): the parallelogram force ratio sin(eta - psi) / cos(psi) (vertical footpad force
  per upper cell force, peg leg locked) 0.55 at psi = -30 deg and 0.40 at +30 deg; the peg-leg ratio
  lower_lever(alpha) / (AS sin alpha + AL cos alpha) "0.35 -> slightly under 0.30 -> 0.35" over 0-45 deg;
- the psi at which the upper cell reaches its crushing force (0.16 ft, configuration 3 curve l. 924-933):
  between -6 and -5 deg, the psi of Table 14's RA, RB, Q1 maxima; the lower cell's 0.02 ft between alpha 1
  and 2 deg (Table 14's alpha 2).

Fitted: AA, AB, AG, AH, AE, AO, AP, AQ (in), PHI (deg), the truss angles theta, gamma, rho (deg) and the
return spring SPRG (lbf/ft), PLD (lbf). Configurations 4-9 (Tables 15-22) are held out
(`calibration/validation.py`).

Envelope sweep (a finding of this fit, see docs/articulated-geometry.md): by default alpha is swept only
while the lower cell is on its crushing plateau (deflection <= 0.40 ft, the third point of its curve;
`--alpha-limit none` sweeps the whole default grid, 0-45 deg). The tables never place an extreme beyond
alpha = 25 deg, yet Fig. 10's peg-leg curve (and "peg leg bottoming at 45 degrees deflection", l. 760) needs a lower
cell that reaches its 0.50 ft bottoming ramp near 45 deg, where every load would double.

Method (reproducible: seeded starts, deterministic solver):
1. Stage 1, cheap: each Table 14 row's envelope is taken over a coarse grid (alpha by 5 deg, beta by
   20 deg, psi by 5 deg) joined with the printed position itself. Residuals: the relative error of the
   envelope value; the position gap (envelope minus the load at the printed position, relative; zero when
   the printed position is where the model's extreme is) and a stencil hinge (no neighbour of the printed
   position, +-1 deg alpha / psi, +-5 deg beta, may exceed it), both times POSITION_WEIGHT; the Fig. 10
   ratios (relative, times the Fig. 10 weight); the crush brackets (one-sided, CRUSH_MARGIN inside, times
   the crush weight); AP + AQ >= 1 in. scipy.optimize.least_squares (trf, bounds) from N_STARTS uniform
   random starts (seed SEED), for each (Fig. 10 weight, crush weight) of TRADEOFF: the trade-off table.
2. Stage 2-3: the chosen variant's (FIG10_WEIGHT, CRUSH_WEIGHT) best distinct stage-1 solutions are
   refined with the same residuals on a finer grid (alpha 3, beta 10, psi 3 deg), then on the default
   grid (alpha 1, beta 5, psi 1 deg).

Bounds: offsets AA-AO in [0, 30] in (positive, under ~30 in); AP, AQ in [-30, 30] in with AP + AQ >= 1 in
(a penalty); PHI in [-60, 60] deg; truss angles in [5, 85] deg; the "light" return spring SPRG in
[0, 2,500] lbf/ft and PLD in [0, 500] lbf (at most ~1,000 lbf, 3 % of the 30,000 lbf cell, at the end of
its 0.40 ft plateau). Options: --signed-offsets (AA-AO in [-30, 30]), --no-spring, --fig10-weight,
--crush-weight, --alpha-limit none.

Output: calibration/fitted_geometry.json (inches, degrees, lbf/ft, lbf) and a printed residual table.
Run from the repository root:  .venv/bin/python calibration/fit_articulated_geometry.py  (~75 s, 2 cores)
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import dataclass, replace
from multiprocessing import Pool
from pathlib import Path

import numpy as np
from scipy.optimize import least_squares

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

import reference_tables_14_22 as ref  # noqa: E402
from alightsize.loads.envelopes import Grid, LegCase, cell_forces, default_grid, member_fields  # noqa: E402
from alightsize_sim.articulated_cells import lower_deflection, lower_lever, upper_deflection, upper_lever  # noqa: E402
from alightsize_sim.articulated_kinematics import ArticulatedGeometry  # noqa: E402
from alightsize_sim.articulated_statics import TrussAngles, member_loads, reactions  # noqa: E402
from alightsize_sim.crush_curve import CrushCurve  # noqa: E402

IN = 0.0254
FT = 0.3048
LBF = 4.4482216152605
SEED = 20240521
N_STARTS = 20
FIG10_WEIGHT = 0.3
# Stage-1 trade-off variants (Fig. 10 weight, crush-bracket weight); the chosen one is refined in stage 2-3.
TRADEOFF = ((0.0, 50.0), (0.3, 50.0), (1.0, 50.0), (3.0, 50.0), (0.3, 0.0), (1.0, 0.0), (3.0, 0.0))
POSITION_WEIGHT = 3.0
CRUSH_WEIGHT = 50.0          # the crush brackets are facts of the tables' psi / alpha columns
CRUSH_MARGIN = 0.0005        # ft: kept this far inside the brackets
OUT = ROOT / "calibration" / "fitted_geometry.json"

# Known dimensions (Sec. III, l. 700-702; GUIDE.md): parallelogram 44 x 24 in, peg leg 25 in, 16 in ring.
KNOWN_IN = {"AU": 44.0, "AD": 24.0, "AL": 25.0, "AS": 8.0}

# name, unit, lower, upper bound (signed-offset lower bound for the first six)
PARAMS = (
    ("AA", "in", 0.0, 30.0), ("AB", "in", 0.0, 30.0), ("AG", "in", 0.0, 30.0), ("AH", "in", 0.0, 30.0),
    ("AE", "in", 0.0, 30.0), ("AO", "in", 0.0, 30.0), ("AP", "in", -30.0, 30.0), ("AQ", "in", -30.0, 30.0),
    ("PHI", "deg", -60.0, 60.0), ("theta", "deg", 5.0, 85.0), ("gamma", "deg", 5.0, 85.0),
    ("rho", "deg", 5.0, 85.0), ("SPRG", "lbf/ft", 0.0, 2_500.0), ("PLD", "lbf", 0.0, 500.0),
)
NAMES = tuple(p[0] for p in PARAMS)
X_SCALE = np.array([5, 5, 5, 5, 5, 5, 5, 5, 10, 10, 10, 10, 500, 100], float)

# Fig. 10 targets (l. 734-736)
PAR_TARGETS = ((-30.0, 0.55), (30.0, 0.40))          # parallelogram ratio at psi = -30, +30 deg
PEG_MIN_TARGET = 0.295                               # "slightly under 0.30"
PEG_END_TARGET = 0.35                                # at alpha = 45 deg
PEG_START_PRINTED = 0.35                             # at alpha = 0: equals AS/AL = 0.32 whatever AP, AQ
# Crush brackets (configuration 3 curves l. 924-933; Table 14 positions)
UPPER_CRUSH_FT, UPPER_CRUSH_PSI = 0.16, (-6.0, -5.0)
LOWER_CRUSH_FT, LOWER_CRUSH_ALPHA = 0.02, (1.0, 2.0)


def bounds(signed_offsets: bool = False):
    lo = np.array([p[2] for p in PARAMS])
    hi = np.array([p[3] for p in PARAMS])
    if signed_offsets:
        lo[:6] = -30.0
    return lo, hi


def as_dict(x) -> dict[str, float]:
    return {n: float(v) for n, v in zip(NAMES, x)}


def geometry(x, scale: float = 1.0) -> ArticulatedGeometry:
    """SI geometry from the parameter vector (in, deg, lbf/ft, lbf); lengths times `scale` (config 9).

    The return spring of a scaled leg keeps its preload / lower-force ratio and its deflection scales with
    length: PLD times the lower-force ratio, SPRG times force ratio / scale (the caller passes them)."""
    d = as_dict(x)
    s = scale * IN
    return ArticulatedGeometry(
        AU=KNOWN_IN["AU"] * s, AO=d["AO"] * s, AS=KNOWN_IN["AS"] * s, AL=KNOWN_IN["AL"] * s, AE=d["AE"] * s,
        AD=KNOWN_IN["AD"] * s, AA=d["AA"] * s, AB=d["AB"] * s, AG=d["AG"] * s, AH=d["AH"] * s,
        AP=d["AP"] * s, AQ=d["AQ"] * s, PHI=np.radians(d["PHI"]),
        SPRG=d["SPRG"] * LBF / FT, PLD=d["PLD"] * LBF)


def leg_case(config: str, x) -> LegCase:
    """LegCase of a configuration 3-9 (printed cell curves, initial psi; psi swept to +30 deg)."""
    up, lo, psi0 = ref.CELL_CURVES[config]
    upper = CrushCurve(tuple(d * FT for d, _ in up), tuple(f * LBF for _, f in up))
    lower = CrushCurve(tuple(d * FT for d, _ in lo), tuple(f * LBF for _, f in lo))
    x = np.array(x, float)
    scale = 1.0
    if config == "9":
        scale = ref.CONFIG_9_LENGTH_SCALE
        force_ratio = lo[1][1] / ref.CELL_CURVES["3"][1][1][1]      # 5,852 / 30,000
        x[NAMES.index("PLD")] *= force_ratio
        x[NAMES.index("SPRG")] *= force_ratio / scale
    d = as_dict(x)
    truss = TrussAngles(*np.radians([d["theta"], d["gamma"], d["rho"]]))
    return LegCase(config, geometry(x, scale), truss, upper, lower, np.radians(psi0), np.radians(30.0))


def target_rows(config: str, corrected: bool = True):
    """Printed rows of a table; with `corrected`, suspected misprints replaced (reference module)."""
    out = []
    for row in ref.TABLES[config]:
        key = (config, row[0], 1 if row[1] > 0 else -1)
        if corrected and key in ref.SUSPECTED_MISPRINTS:
            row = ref.SUSPECTED_MISPRINTS[key][0]
        out.append(row)
    return tuple(out)


def coarse_grid(level: int = 2) -> Grid:
    """Level 1: alpha by 5, beta by 20, psi by 5 deg; level 2: alpha by 3, beta by 10, psi by 3 deg."""
    if level == 1:
        return Grid(tuple(np.radians(np.arange(0, 46, 5))), tuple(np.radians(np.arange(-160, 181, 20))), np.radians(5.0))
    return Grid(tuple(np.radians(np.arange(0, 46, 3))), tuple(np.radians(np.arange(-170, 181, 10))), np.radians(3.0))


def stencil(rows, psi0: float):
    """Neighbours of each printed position (alpha +-1, beta +-5, psi +-1 deg, inside the swept ranges):
    a printed extreme must not be exceeded next to itself, whatever grid the envelope is taken on."""
    out = []
    for i, r in enumerate(rows):
        for da, db, dp in ((1, 0, 0), (-1, 0, 0), (0, 5, 0), (0, -5, 0), (0, 0, 1), (0, 0, -1)):
            a, b, p = r[2] + da, r[3] + db, r[4] + dp
            if 0 <= a <= 45 and psi0 - 1e-9 <= p <= 30 + 1e-9:
                out.append((i, (r[0], r[1], a, b, p)))
    return out


@dataclass
class RowResult:
    member: str
    printed: float          # lbf, signed (magnitude for MAGNITUDE_ONLY rows)
    model: float            # lbf, the model's extreme of the same sign (or magnitude)
    at_printed: float       # lbf, the model load at the printed position (same sign convention)
    printed_at: tuple       # deg
    model_at: tuple         # deg, where the model's extreme lies
    magnitude_only: bool


def loads_at(case: LegCase, rows):
    """Model loads (lbf) of each row's member at the row's printed position."""
    a = np.radians([r[2] for r in rows])
    b = np.radians([r[3] for r in rows])
    p = np.radians([r[4] for r in rows])
    af1, af2 = cell_forces(case, a, p)
    loads = member_loads(reactions(case.geometry, a, b, p, af1, af2), case.truss)
    return np.array([loads[r[0]][i] for i, r in enumerate(rows)]) / LBF


def plateau_alpha(case: LegCase) -> float:
    """Largest alpha (deg, <= 45, by 0.25) at which the lower cell is still on its crushing plateau."""
    a = np.arange(0.0, 45.0001, 0.25)
    ok = lower_deflection(case.geometry, np.radians(a)) <= case.lower.bottoming * (1 + 1e-12)
    return float(a[ok].max()) if ok.any() else 0.0


def sweep_grid(case: LegCase, grid: Grid, alpha_limit: str | None) -> Grid:
    """`grid` leaving bottomed positions out (alpha_limit "plateau", the envelope's default) or keeping
    them (None)."""
    if alpha_limit not in (None, "plateau"):
        raise ValueError(f"alpha_limit must be None or 'plateau', not {alpha_limit!r}")
    return replace(grid, include_bottomed=alpha_limit is None)


def compare(case: LegCase, rows, grid: Grid, magnitude_only=frozenset(), alpha_limit: str | None = None) -> list[RowResult]:
    """Each printed row against the model envelope over `grid` joined with the printed positions."""
    axes, fields = member_fields(case, sweep_grid(case, grid, alpha_limit))
    at = loads_at(case, rows)
    out = []
    for r, v_at in zip(rows, at):
        f = fields[r[0]] / LBF
        mag = r[0] in magnitude_only
        if mag:
            i_hi, i_lo = np.unravel_index(np.nanargmax(f), f.shape), np.unravel_index(np.nanargmin(f), f.shape)
            i = i_hi if abs(f[i_hi]) >= abs(f[i_lo]) else i_lo
            model, v_at = abs(f[i]), abs(v_at)
            if v_at > model:
                model, i = v_at, None
        else:
            pick = np.nanargmax if r[1] > 0 else np.nanargmin      # NaN: positions the envelope leaves out
            i = np.unravel_index(pick(f), f.shape)
            model = f[i]
            if (r[1] > 0 and v_at > model) or (r[1] < 0 and v_at < model):   # printed point off the grid
                model, i = v_at, None
        if i is None:
            model_at = tuple(r[2:5])
        else:
            psi, alpha, beta = (np.degrees(ax[k]) for ax, k in zip(axes, i))
            model_at = (round(float(alpha), 3), round(float(beta), 3), round(float(psi), 3))
        out.append(RowResult(r[0], float(abs(r[1]) if mag else r[1]), float(model), float(v_at),
                             tuple(r[2:5]), model_at, mag))
    return out


def fig10(x) -> dict[str, float]:
    """Fig. 10 ratios and crush positions of a parameter vector (configuration 3 geometry)."""
    g = geometry(x)
    psi = np.radians([t for t, _ in PAR_TARGETS])
    par = upper_lever(g, psi) / np.cos(psi)
    a = np.radians(np.arange(0.0, 45.001, 0.25))
    peg = lower_lever(g, a) / (g.AS * np.sin(a) + g.AL * np.cos(a))
    p0 = np.radians(-15.0)
    fine = np.linspace(-15.0, 30.0, 4501)
    d = upper_deflection(g, np.radians(fine), p0) / FT
    k = np.nonzero(d >= UPPER_CRUSH_FT)[0]
    return {
        "upper_crush_psi": float(fine[k[0]]) if len(k) else float("nan"),
        "par_m30": float(par[0]), "par_p30": float(par[1]),
        "peg_0": float(peg[0]), "peg_min": float(peg.min()), "peg_min_at": float(np.degrees(a[peg.argmin()])),
        "peg_45": float(peg[-1]),
        "upper_defl_ft_psi_m6": float(upper_deflection(g, np.radians(UPPER_CRUSH_PSI[0]), p0) / FT),
        "upper_defl_ft_psi_m5": float(upper_deflection(g, np.radians(UPPER_CRUSH_PSI[1]), p0) / FT),
        "upper_defl_ft_psi_p30": float(upper_deflection(g, np.radians(30.0), p0) / FT),
        "lower_defl_ft_alpha_1": float(lower_deflection(g, np.radians(LOWER_CRUSH_ALPHA[0])) / FT),
        "lower_defl_ft_alpha_2": float(lower_deflection(g, np.radians(LOWER_CRUSH_ALPHA[1])) / FT),
        "lower_defl_ft_alpha_45": float(lower_deflection(g, np.radians(45.0)) / FT),
        "sin_eta_minus_psi_p30": float(upper_lever(g, np.radians(30.0))),
        "sin_eta_minus_psi_m30": float(upper_lever(g, np.radians(-30.0))),
    }


def residuals(x, grid: Grid, w_fig: float, w_pos: float = POSITION_WEIGHT, alpha_limit: str | None = None,
              w_crush: float = CRUSH_WEIGHT):
    """Residual vector: Table 14 values and position gaps, Fig. 10 ratios, crush brackets, AP + AQ."""
    rows = target_rows("3")
    case = leg_case("3", x)
    res = compare(case, rows, grid, alpha_limit=alpha_limit)
    r = []
    for rr in res:
        scale = abs(rr.printed)
        r.append((rr.model - rr.printed) / scale)
        r.append(w_pos * abs(rr.model - rr.at_printed) / scale)
    nb = stencil(rows, -15.0)
    v_nb = loads_at(case, [n for _, n in nb])
    hinge = np.zeros(len(rows))
    for (i, n), v in zip(nb, v_nb):
        sign = 1.0 if n[1] > 0 else -1.0
        hinge[i] = max(hinge[i], sign * (v - res[i].at_printed) / abs(n[1]))
    r += list(w_pos * np.maximum(hinge, 0.0))
    f = fig10(x)
    r += [w_fig * (f["par_m30"] - 0.55) / 0.55, w_fig * (f["par_p30"] - 0.40) / 0.40,
          w_fig * (f["peg_min"] - PEG_MIN_TARGET) / PEG_MIN_TARGET, w_fig * (f["peg_45"] - PEG_END_TARGET) / PEG_END_TARGET]
    k, m = w_crush, CRUSH_MARGIN   # one-sided brackets, kept a little inside
    r += [k * max(0.0, UPPER_CRUSH_FT + m - f["upper_defl_ft_psi_m5"]) / UPPER_CRUSH_FT,
          k * max(0.0, f["upper_defl_ft_psi_m6"] - UPPER_CRUSH_FT + m) / UPPER_CRUSH_FT,
          k * max(0.0, LOWER_CRUSH_FT + m - f["lower_defl_ft_alpha_2"]) / LOWER_CRUSH_FT,
          k * max(0.0, f["lower_defl_ft_alpha_1"] - LOWER_CRUSH_FT + m) / LOWER_CRUSH_FT]
    d = as_dict(x)
    r.append(10.0 * max(0.0, 1.0 - (d["AP"] + d["AQ"])))
    return np.asarray(r)


def _solve(args):
    x0, lo, hi, grid, w_fig, max_nfev, alpha_limit, w_crush = args
    x0 = np.clip(x0, lo, hi)
    try:
        sol = least_squares(residuals, x0, bounds=(lo, hi), args=(grid, w_fig, POSITION_WEIGHT, alpha_limit, w_crush),
                            x_scale=X_SCALE,
                            max_nfev=max_nfev, method="trf")
    except (ValueError, FloatingPointError, np.linalg.LinAlgError):
        return np.inf, x0
    return float(sol.cost), sol.x


def starts(n: int, lo, hi, seed: int):
    rng = np.random.default_rng(seed)
    xs = lo + rng.random((n, len(lo))) * (hi - lo)
    xs[:, NAMES.index("SPRG")] *= 0.1       # "light" spring: start low
    xs[:, NAMES.index("PLD")] *= 0.1
    xs[:, NAMES.index("AP")] = rng.uniform(-5, 15, n)
    xs[:, NAMES.index("AQ")] = rng.uniform(1, 20, n)
    return xs


def distinct(solutions, k: int, tol: float = 0.05):
    """The k best solutions that differ by more than `tol` (relative to the bounds) from better ones."""
    lo, hi = bounds(True)
    out = []
    for cost, x in sorted(solutions, key=lambda s: s[0]):
        if all(np.max(np.abs(x - y) / (hi - lo)) > tol for _, y in out):
            out.append((cost, x))
        if len(out) == k:
            break
    return out


def residual_table(x, grid: Grid, alpha_limit: str | None = None) -> list[dict]:
    rows = compare(leg_case("3", x), target_rows("3"), grid, alpha_limit=alpha_limit)
    printed = target_rows("3", corrected=False)
    out = []
    for rr, pr in zip(rows, printed):
        out.append({"member": rr.member, "printed_lbf": rr.printed, "model_lbf": round(rr.model, 1),
                    "rel_error": (rr.model - rr.printed) / abs(rr.printed),
                    "printed_at_deg": list(pr[2:5]), "target_at_deg": list(rr.printed_at),
                    "model_at_deg": list(rr.model_at), "model_at_printed_lbf": round(rr.at_printed, 1)})
    return out


def summary(x, grid: Grid, alpha_limit) -> dict:
    """Table 14 error and position statistics and the Fig. 10 / crush figures of a parameter vector."""
    tab = residual_table(x, grid, alpha_limit)
    err = np.array([t["rel_error"] for t in tab])
    near = [all(abs(a - b) <= tol for a, b, tol in zip(t["model_at_deg"], t["target_at_deg"], (2, 10, 1))) for t in tab]
    f = fig10(x)
    return {"table14_rms": float(np.sqrt(np.mean(err ** 2))), "table14_median_abs": float(np.median(np.abs(err))),
            "table14_max_abs": float(np.max(np.abs(err))),
            "positions_exact": int(sum(t["model_at_deg"] == t["target_at_deg"] for t in tab)),
            "positions_near": int(sum(near)),
            **{k: f[k] for k in ("par_m30", "par_p30", "peg_min", "peg_45", "upper_crush_psi",
                                 "sin_eta_minus_psi_p30")}}


def print_residuals(table, f):
    print(f"{'member':6s} {'printed':>9s} {'model':>9s} {'err %':>7s}  {'printed at (a,b,psi)':22s} model at")
    for t in table:
        pa = "(" + ", ".join(f"{v:g}" for v in t["printed_at_deg"]) + ")"
        ma = "(" + ", ".join(f"{v:g}" for v in t["model_at_deg"]) + ")"
        print(f"{t['member']:6s} {t['printed_lbf']:9.0f} {t['model_lbf']:9.0f} {100 * t['rel_error']:7.2f}  {pa:22s} {ma}")
    print(f"Fig. 10 parallelogram ratio: {f['par_m30']:.3f} at -30 deg (target 0.55), {f['par_p30']:.3f} at +30 (0.40)")
    print(f"Fig. 10 peg-leg ratio: {f['peg_0']:.3f} at 0 (printed 0.35; = AS/AL, unreachable), min {f['peg_min']:.3f} "
          f"at {f['peg_min_at']:.1f} deg (target ~{PEG_MIN_TARGET}), {f['peg_45']:.3f} at 45 (0.35)")
    print(f"upper deflection (ft): psi -6 {f['upper_defl_ft_psi_m6']:.4f}, -5 {f['upper_defl_ft_psi_m5']:.4f} "
          f"(0.16 between), +30 {f['upper_defl_ft_psi_p30']:.3f}; lower (ft): alpha 1 {f['lower_defl_ft_alpha_1']:.4f}, "
          f"2 {f['lower_defl_ft_alpha_2']:.4f} (0.02 between), 45 {f['lower_defl_ft_alpha_45']:.3f}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--signed-offsets", action="store_true", help="allow negative AA, AB, AG, AH, AE, AO")
    ap.add_argument("--starts", type=int, default=N_STARTS)
    ap.add_argument("--fig10-weight", type=float, default=FIG10_WEIGHT)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--crush-weight", type=float, default=CRUSH_WEIGHT)
    ap.add_argument("--no-spring", action="store_true", help="fix SPRG = PLD = 0")
    ap.add_argument("--alpha-limit", choices=("plateau", "none"), default="plateau",
                    help="plateau (default): sweep alpha only while the lower cell is on its crushing plateau "
                         "(<= 0.40 ft); none: the whole default grid, alpha 0-45 deg")
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args(argv)
    if args.alpha_limit == "none":
        args.alpha_limit = None
    t0 = time.perf_counter()
    lo, hi = bounds(args.signed_offsets)
    if args.no_spring:
        hi[NAMES.index("SPRG")] = hi[NAMES.index("PLD")] = 1e-9
    xs = starts(args.starts, lo, hi, SEED)
    coarse, full = coarse_grid(), default_grid()
    variants = list(TRADEOFF)
    chosen = (args.fig10_weight, args.crush_weight)
    if chosen not in variants:
        variants.append(chosen)

    # Stage 1: every (Fig. 10 weight, crush weight) variant from the same seeded starts, coarse grid.
    stage1 = {}
    g1 = coarse_grid(1)
    with Pool(args.workers) as pool:
        for w, c in variants:
            stage1[w, c] = pool.map(_solve, [(x0, lo, hi, g1, w, 50, args.alpha_limit, c) for x0 in xs])
        best = distinct(stage1[chosen], 4)
        # Stage 2: refine the chosen variant's best distinct solutions on a finer, then the full grid.
        stage2 = pool.map(_solve, [(x, lo, hi, coarse, chosen[0], 40, args.alpha_limit, chosen[1]) for _, x in best])
        best2 = distinct(stage2, 2)
        stage3 = pool.map(_solve, [(x, lo, hi, full, chosen[0], 20, args.alpha_limit, chosen[1]) for _, x in best2])
    cost, x = min(stage3, key=lambda s: s[0])
    print(f"stage costs: 1 {[round(c, 4) for c, _ in best]}, 2 {[round(c, 4) for c, _ in best2]}, "
          f"3 {[round(c, 4) for c, _ in stage3]}")

    print(f"\nstage-1 trade-off (best of {args.starts} starts each; Table 14 on the full grid):")
    tradeoff = []
    for w, c in variants:
        _, xw = min(stage1[w, c], key=lambda s: s[0])
        tradeoff.append({"fig10_weight": w, "crush_weight": c, **summary(xw, full, args.alpha_limit),
                         "x": [round(float(v), 4) for v in xw]})
        t = tradeoff[-1]
        print(f"  w_fig {w:3.1f} w_crush {c:4.1f}: Table 14 rms {100 * t['table14_rms']:4.2f} %, max "
              f"{100 * t['table14_max_abs']:4.2f} %, positions exact {t['positions_exact']}/17 near {t['positions_near']}/17;"
              f" Fig. 10 par {t['par_m30']:.3f}/{t['par_p30']:.3f}, peg min {t['peg_min']:.3f} 45 deg {t['peg_45']:.3f};"
              f" 0.16 ft at psi {t['upper_crush_psi']:.2f}")

    table = residual_table(x, full, args.alpha_limit)
    f = fig10(x)
    runtime = time.perf_counter() - t0
    print(f"\nfitted (stage 3, w_fig {args.fig10_weight}, w_crush {args.crush_weight}, cost {cost:.5f}, {runtime:.1f} s):")
    for (n, unit, *_), v in zip(PARAMS, x):
        print(f"  {n:6s} {v:10.3f} {unit}")
    print()
    print_residuals(table, f)
    out = {
        "source": "calibration/fit_articulated_geometry.py; AFFDL-TR-66-33 Table 14, Fig. 10, config 3 curves",
        "known": {k: {"value": v, "unit": "in"} for k, v in KNOWN_IN.items()},
        "fitted": {n: {"value": round(float(v), 4), "unit": unit} for (n, unit, *_), v in zip(PARAMS, x)},
        "config_9_length_scale": ref.CONFIG_9_LENGTH_SCALE,
        "settings": {"seed": SEED, "starts": args.starts, "fig10_weight": args.fig10_weight,
                     "position_weight": POSITION_WEIGHT, "signed_offsets": args.signed_offsets,
                     "alpha_limit": args.alpha_limit,
                     "crush_weight": args.crush_weight, "no_spring": args.no_spring,
                     "bounds": {n: [float(a), float(b)] for n, a, b in zip(NAMES, lo, hi)}},
        "cost": cost,
        "summary": summary(x, full, args.alpha_limit),
        "table14": table,
        "fig10_and_crush": f,
        "tradeoff": tradeoff,
        "runtime_s": round(runtime, 1),
    }
    args.out.write_text(json.dumps(out, indent=2) + "\n")
    print(f"\nwritten {args.out.relative_to(ROOT) if args.out.is_relative_to(ROOT) else args.out}")


def load_fitted(path: Path = OUT) -> np.ndarray:
    """Parameter vector (in NAMES order) from fitted_geometry.json."""
    d = json.loads(Path(path).read_text())["fitted"]
    return np.array([d[n]["value"] for n in NAMES], float)


if __name__ == "__main__":
    main()
