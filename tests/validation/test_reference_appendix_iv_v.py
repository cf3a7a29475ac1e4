"""The example configs reproduce the printed results of AFFDL-TR-66-33 App. IV (design factors) and App. V
(weight Tables 23-26). Printed values are in reference_data.py; where a printed result does not follow from
the printed inputs, the discrepancy is recorded below with a hand recomputation (plain floats, lb / psi / in)
that our value must match and that the printed value must miss, so each record stays true."""

from functools import lru_cache
from math import log, pi, sqrt

import pytest

from alightsize.pipeline.audit import run_audit
from alightsize.pipeline.design import run_design
from alightsize.pipeline.config import prepare, read_design
from reference_data import CRITICAL, DESIGN_FACTORS, PRINTED_STRESSES, TABLES
from conftest import ROOT

LB = 0.45359237                 # kg
LBF = LB * 9.80665              # N
PSI = 6894.757293               # Pa
EXAMPLES = ROOT / "examples" / "affdl-tr-66-33"
FILES = {"012": "telescoping", "3457": "articulated_3457", "68": "articulated_68", "9": "articulated_9"}
# Table 23 names its rows differently from the config's items.
TABLE_23_LABELS = {"Lower Leg": "Lower Leg Tube", "Upper Leg": "Upper Leg Tube", "Lower Cap": "Lower Leg Cap",
                   "Upper Cap": "Upper Leg Cap", "Swivel": "Double Pin Swivel",
                   "Rotational Honeycomb (4)": "Rotational Honeycomb"}

# f is printed to two decimals (half a unit 0.005) from 3-figure intermediate values (each up to ~0.5 %,
# ~0.006 at f = 1.2), and sometimes truncated (180,000/81,600 = 2.206 printed 2.20): one unit of the last
# printed digit, 0.01, covers that.
FACTOR_TOL = 0.01
# Printed stresses are 3-figure results of 3-figure intermediates (lower leg tube: M printed 16,150 for
# 1045 x 15.5 = 16,197.5, -0.3 %; I = 0.478 for pi 1.45^3 0.05 = 0.479): 1 % covers them; f is the binding check.
STRESS_RTOL = 0.01
# A recorded factor must equal our hand recomputation from the printed inputs within half a unit of the
# printed digit, 0.005 (the configs may enter a size where the report used its rounded area or inertia),
# and the printed f must miss the hand value by more than FACTOR_TOL.
HAND_FACTOR_TOL = 0.005


@lru_cache(maxsize=None)
def config(cid):
    return prepare(read_design(EXAMPLES / f"{FILES[cid]}.toml"))


@lru_cache(maxsize=None)
def outcomes(cid):
    return {(r.item.name, r.item.checks[r.index].kind): r.outcome for r in run_audit(config(cid))}


def outcome(key):
    cid, item, kind = key
    return outcomes(cid)[(item, kind)]


def ids(key):
    return "/".join(key).replace(" ", "_")


# ------------------------------------------------------------------ hand arithmetic (psi, in, lb)

def eccentric_and_distributed_plate(w, w_dist, m, t, a, p, r0, a_t=None):
    """App. IV parallelogram absorber caps (Roark pp. 194-195 as printed): one rod load w over r0 at offset p,
    plus w_dist spread over the plate; tau_max = (sigma_r + sigma_t)/2, f = (69,000/2)/tau_max."""
    a_t = a_t or a
    ecc = -3 * w / (2 * pi * m * t**2) * (m + (m + 1) * log((a - p) / r0) - (m - 1) * r0**2 / (4 * (a - p)**2))
    dist = 3 * w_dist / (8 * pi * m * t**2)
    sigma_r = ecc + dist * (3 * m + 1) * (1 - p**2 / a**2)
    sigma_t = ecc + dist * ((3 * m + 1) - (m + 3) * p**2 / a_t**2)
    return 34_500 / ((sigma_r + sigma_t) / 2)


def _upper_cap_lugs_combined():
    # App. IV telescoping leg, Upper Cap Lugs: sigma = M c / I + P / A, M = 1075 (0.5), I = 0.4 (0.5)^3 / 12, c = 0.25,
    # A = 0.5 (0.4)
    sigma_b = 1075 * 0.5 * 0.25 / (0.4 * 0.5**3 / 12)     # 32,250 psi (printed 30,000)
    sigma_c = 3750 / (0.5 * 0.4)                         # 18,750 psi (printed 18,800)
    return 69_000 / (sigma_b + sigma_c)                  # 1.353


def _post_3457_combined():
    # App. IV configs 3-5, 7, Parallelogram Post: d = 12 - 0.083 = 11.917, A = pi d t, I = pi r^3 t (r = d/2), c = 6.0,
    # M = 49,000 (7.2)
    area = pi * 11.917 * 0.083                           # 3.107 in^2 (printed 3.11)
    inertia = pi * 5.9585**3 * 0.083                     # 55.16 in^4 (printed 55.0)
    sigma = 49_000 / area + 49_000 * 7.2 * 6.0 / inertia  # 15,769 + 38,374 = 54,143 psi (printed 54,400)
    return 69_000 / sigma                                # 1.274; printed 1.26 (69,000/54,400 = 1.268)


def _strut_9_compression():
    # App. IV config 9, Peg Leg Strut: A = pi (0.785 - 0.070)(0.070), sigma = 9779 / A
    return 74_000 / (9779 / (pi * 0.715 * 0.070))        # 62,193 psi -> 1.190


RECORDED = {
    ("012", "Upper Cap Lugs", "combined"):
        (_upper_cap_lugs_combined(),
         "printed sigma_B = 538 (0.25)/0.00417 = 30,000 psi; it is 32,250 psi, so f = 1.35, printed 1.42"),
    ("3457", "Parallelogram Post", "combined"):
        (_post_3457_combined(),
         "printed 1.26 for 69,000/54,400 = 1.268; the inputs give 54,143 psi and f = 1.274"),
    ("68", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (eccentric_and_distributed_plate(24_000, 72_000, 3.33, 0.92, 2.45, 1.825, 0.625),
         "printed distributed terms 15,955 and 24,385 psi are 6.9 % above what the printed inputs give "
         "(14,917 and 22,801 psi): tau 7,689 psi and f = 4.49 instead of 8,999 psi and 3.84 "
         "(34,500/8,999 is itself 3.83)"),
    ("9", "Peg Leg Strut", "compression"):
        (_strut_9_compression(),
         "printed 1.20 = 74,000/62,000 (which is 1.194), with sigma rounded down from 9779/0.157 = 62,290 psi; "
         "the exact area gives 62,193 psi and f = 1.190"),
    ("9", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (eccentric_and_distributed_plate(2_230, 6_688, 3.33, 0.43, 0.72, 0.532, 0.188),
         "printed distributed terms 6,474 and 9,773 psi are 4-5 psi above the inputs' 6,470 and 9,768 psi "
         "(tau 3,372 vs 3,368 psi); at f = 10 that 0.12 % is 0.013: f = 10.244, printed 10.23"),
}


# ------------------------------------------------------------------ App. IV design factors

@pytest.mark.parametrize("key", [k for k in DESIGN_FACTORS if k not in RECORDED], ids=ids)
def test_printed_design_factor(key):
    f, allowable, stress = DESIGN_FACTORS[key]
    o = outcome(key)
    assert o.factor == pytest.approx(f, abs=FACTOR_TOL)
    if key[2] == "pin_shear":       # a check on loads (bolt capacity / resultant): no stress or allowable
        return
    assert o.allowable / PSI == pytest.approx(allowable, abs=1.0)   # the yield (or half): exact, 1 psi is float slack
    assert o.stress / PSI == pytest.approx(stress, rel=STRESS_RTOL)


@pytest.mark.parametrize("key", list(RECORDED), ids=ids)
def test_recorded_design_factor(key):
    hand, reason = RECORDED[key]
    printed = DESIGN_FACTORS[key][0]
    assert outcome(key).factor == pytest.approx(hand, abs=HAND_FACTOR_TOL), reason
    assert abs(printed - hand) > FACTOR_TOL, f"record no longer needed: {reason}"


@pytest.mark.parametrize("key", list(PRINTED_STRESSES), ids=ids)
def test_printed_stress_without_factor(key):
    # 3-figure printed results of 3-figure areas (0.841 for pi 1.856 0.144 = 0.8396, 0.17 %): 0.5 %.
    assert outcome(key).stress / PSI == pytest.approx(PRINTED_STRESSES[key], rel=0.005)


# Informational critical values. Several printed values miss their own substitutions by up to 3.2 %:
# pi^2 (34e6)(0.478)/30.5^2 = 172,400 lb (printed 167,000); pi^2 (34e6)/(16/0.658)^2 = 567,500 psi (585,000);
# pi^2 (34e6)/(22.6/0.433)^2 = 123,200 psi (126,000). Ours also uses k from the exact mean diameter (0.6562 for
# the printed 0.658, -0.6 %), so 4 % bounds the comparison. The report's conclusion, that buckling does not
# govern, is checked against the required design factor.
CRITICAL_RTOL = 0.04
CRITICAL_STEP = {("column_buckling", "lb"): ("Pcr", LBF), ("column_buckling", "psi"): ("σcB", PSI),
                 ("local_buckling", "psi"): ("σLB", PSI)}




def _johnson_factor(p, od, t, length, e=34e6, fcy=74_000):
    """Johnson's parabola (Bruhn 1973 eq. C2.6) for a Be(31)Al thin tube, psi / in / lb: k = d / (2 sqrt 2) on
    the mean diameter d (App. IV), f = sigma_cr / (P / (pi d t)); the slenderness must be below the transition."""
    d = od - t
    slenderness = length / (d / (2 * sqrt(2)))
    assert slenderness < pi * sqrt(2 * e / fcy)             # 95.2 for Be(31)Al: Euler does not hold here
    return (fcy - (fcy / (2 * pi)) ** 2 * slenderness ** 2 / e) / (p / (pi * d * t))


# The report took Euler's stress where the slenderness is below the transition pi sqrt(2E/Fcy) = 95.2, so Euler's
# formula does not hold (its stress there exceeds Fcy/2, and here even Fcy). The check judges on Johnson's parabola
# instead, and the report's conclusion that buckling does not govern is false for these three: f is below 1.2.
BELOW_TRANSITION = {
    ("3457", "Lower Truss", "column_buckling"):
        (_johnson_factor(19_532, 2.50, 0.0426, 46.1),
         "L/k 53.1: Euler 119,200 psi > Fcy; Johnson 62,510 psi, f = 1.05"),
    ("3457", "Peg Leg Strut", "column_buckling"):
        (_johnson_factor(50_800, 2.0, 0.144, 16), "L/k 24.4: Euler 564,400 psi > Fcy; Johnson 71,570 psi, f = 1.18"),
    ("9", "Upper Truss", "column_buckling"):
        (_johnson_factor(6_340, 1.255, 0.0268, 22.6),
         "L/k 52.0: Euler 123,900 psi > Fcy; Johnson 62,950 psi, f = 1.03"),
}


@pytest.mark.parametrize("key", list(CRITICAL), ids=ids)
def test_critical_buckling_value(key):
    printed, unit, conclusion = CRITICAL[key]
    symbol, scale = CRITICAL_STEP[(key[2], unit)]
    o = outcome(key)
    ours = next(s.value for s in o.steps if s.symbol == symbol) / scale
    assert ours == pytest.approx(printed, rel=CRITICAL_RTOL)
    if key in BELOW_TRANSITION:
        hand, reason = BELOW_TRANSITION[key]
        assert o.factor == pytest.approx(hand, rel=1e-6), reason       # same formulas: unit round trips only
        assert hand < config(key[0]).required, f"record no longer needed: {reason}"
    else:
        assert o.factor >= config(key[0]).required, conclusion


# ------------------------------------------------------------------ App. V weights, Tables 23-26

RHO_BE_STEEL = 0.074 / 0.283    # eq. 107 density ratio of Be(31)Al members to the steel test model, 0.2615
RECORDED_WEIGHTS = {
    ("012", "Rotational Honeycomb (4)"):
        (4 * 0.0133 * 0.602**2 * 5.0, "4 x 0.0241 = 0.0964 lb, printed 0.097"),
    ("3457", "Upper Truss"):
        (RHO_BE_STEEL * 4 * (0.566 / 0.0984) * 0.82,
         "printed 4.80 is 2.7 % below its own substitution (4.93): as if rho/rho_TM were 0.2544, not 0.2615"),
    ("3457", "Lower Truss"):
        (RHO_BE_STEEL * 4 * (0.329 / 0.065) * 1.27,
         "printed 6.55 is 2.6 % below its own substitution (6.72): as if rho/rho_TM were 0.2547, not 0.2615"),
    ("3457", "Peg Leg Strut"):
        (0.4 * RHO_BE_STEEL * 4 * (0.841 / 0.078) * 1.10,
         "printed 4.83 is 2.7 % below its own substitution (4.96): as if rho/rho_TM were 0.2545, not 0.2615"),
    ("3457", "Remainder of Post"):
        (0.10 * 1 * 4 * 16 * 2.07, "0.10 (4)(16)(2.07) = 13.25, printed 13.5"),
    ("3457", "Peg Leg Absorber Cap"):
        (0.10 * pi / 4 * (3.14**2 - 0.818**2) * 0.88,
         "text 0.634 (pi/4 taken as 0.785) tabled as 0.63; with pi/4 the inputs give 0.6352, 0.0052 from 0.63, "
         "just over half a unit of the table's last digit"),
    ("68", "Upper Truss"):
        (RHO_BE_STEEL * 4 * (0.840 / 0.0984) * 0.82,
         "printed 7.20 is 1.7 % below its own substitution (7.32): as if rho/rho_TM were 0.2571, not 0.2615"),
    ("68", "Lower Truss"):
        (RHO_BE_STEEL * 4 * (0.406 / 0.065) * 1.27,
         "printed 8.10 is 2.4 % below its own substitution (8.30): as if rho/rho_TM were 0.2553, not 0.2615"),
    ("68", "Peg Leg Strut"):
        (0.4 * RHO_BE_STEEL * 4 * (1.04 / 0.078) * 1.10,
         "printed 6.09 is 0.75 % below its own substitution (6.14): as if rho/rho_TM were 0.2595, not 0.2615"),
    ("68", "Parallelogram Post"):
        (0.75 * 1 * (0.100 / 0.083) * 16 * 2.07, "0.75 (0.100/0.083)(16)(2.07) = 29.93, printed 31.20 (+4.25 %)"),
    ("68", "Peg Leg Absorber Cap"):
        (0.10 * pi / 4 * (3.14**2 - 0.818**2) * 0.88, "as configurations 3, 4, 5 and 7: 0.634 tabled 0.63; 0.6352"),
    ("9", "Upper Truss"):
        (RHO_BE_STEEL * 1.825 * (0.1035 / 0.0984) * 0.82,
         "printed 0.399 is 3.1 % below its own substitution (0.412): as if rho/rho_TM were 0.2535, not 0.2615"),
    ("9", "Lower Truss"):
        (RHO_BE_STEEL * 1.825 * (0.0627 / 0.065) * 1.27,
         "printed 0.568 is 2.8 % below its own substitution (0.585): as if rho/rho_TM were 0.2541, not 0.2615"),
    ("9", "Peg Leg Strut"):
        (0.4 * RHO_BE_STEEL * 1.825 * (0.157 / 0.078) * 1.1,
         "printed 0.413 is 2.3 % below its own substitution (0.423): as if rho/rho_TM were 0.2555, not 0.2615"),
    ("9", "Peg Leg Cone"):
        (0.1 * 1 * 0.81 * 1.825**2 * 1.1, "0.1 (0.81)(1.825)^2 (1.1) = 0.2968: text 0.30, table 0.300"),
    ("9", "Remainder of Post"):
        (0.10 * 1 * 1.825 * 1.825**2 * 2.07, "0.10 (1.825)^3 (2.07) = 1.258, printed 1.27"),
    ("9", "Parallelogram Absorber Caps"):
        (2 * 0.1 * 0.785 * (1.48**2 - 6 * 0.23**2) * 0.43, "2 x 0.0632 = 0.126, printed 2 x 0.072 = 0.144"),
    ("9", "Parallelogram Absorber Honeycomb"):
        (23 / 1728 * 1.61 * 6.65, "(23/1728)(1.61)(6.65) = 0.1425: text 0.14, table 0.140"),
    ("9", "Peg Leg Absorber Honeycomb"):
        (23 / 1728 * 1.41 * 2.74, "(23/1728)(1.41)(2.74) = 0.0514: text 0.05, table 0.050"),
}
# Our weight vs a recorded row's hand value: the printed substitutions use 3-figure areas, which ours computes
# from the printed sizes (0.566 for pi 2.6825 0.0675 = 0.5688, -0.47 %; 1.04 for pi 1.819 0.181 = 1.0344,
# +0.54 %), and pi/4 = 0.785 (-0.05 %): 0.6 %.
HAND_WEIGHT_RTOL = 0.006
# Floating-point slack for exact half-unit ties: (23/1728)(7.2)(6) = 0.575 printed 0.58.
TIE = 1e-9


def printed_tol(printed: str) -> float:
    """Row tolerance: 0.5 % of the printed value or half a unit of its last printed digit, whichever is larger."""
    decimals = len(printed.partition(".")[2])
    return max(0.005 * float(printed), 0.5 * 10.0 ** -decimals)


def our_row(cid, label):
    """count x weight each, lb, of the config item the table row names."""
    name = TABLE_23_LABELS.get(label, label) if cid == "012" else label
    item = next(i for i in config(cid).items if i.weight is not None and (i.weight.label or i.name) == name)
    return item.count * item.weight_each()[0] / LB


ROWS = [(cid, label) for cid, t in TABLES.items() for label in t["rows"]]


@pytest.mark.parametrize("key", [k for k in ROWS if k not in RECORDED_WEIGHTS], ids=ids)
def test_weight_row(key):
    cid, label = key
    printed = TABLES[cid]["rows"][label]
    assert abs(our_row(cid, label) - float(printed)) <= printed_tol(printed) + TIE


@pytest.mark.parametrize("key", list(RECORDED_WEIGHTS), ids=ids)
def test_recorded_weight_row(key):
    cid, label = key
    hand, reason = RECORDED_WEIGHTS[key]
    printed = TABLES[cid]["rows"][label]
    assert our_row(cid, label) == pytest.approx(hand, rel=HAND_WEIGHT_RTOL), reason
    assert abs(float(printed) - hand) > printed_tol(printed), f"record no longer needed: {reason}"


def half_unit(printed: str) -> float:
    return 0.5 * 10.0 ** -len(printed.partition(".")[2])


@pytest.mark.parametrize("cid", list(TABLES))
def test_printed_total_each_is_sum_of_printed_rows(cid):
    # The report's own addition of its printed rows: exact up to half a unit of the total's last digit.
    t = TABLES[cid]
    assert abs(sum(float(v) for v in t["rows"].values()) - float(t["total_each"])) <= half_unit(t["total_each"])


# Printed "Total 4" / "percent" figures that do not follow from legs x Total Each (GUIDE.md).
MISPRINTED_TOTALS = {
    ("3457", "total_4"): "Table 24 Total 4 = 340.03, but 4 x 85.08 = 340.32",
    ("68", "total_4"): "Table 25 Total 4 = 437.4, but 4 x 109.85 = 439.4",
    ("68", "percent"): "Table 25 14.8 percent, but 439.4 / 3000 = 14.6 % (437.4 would also give 14.6)",
}


@pytest.mark.parametrize("key", [(cid, what) for cid in TABLES for what in ("total_4", "percent")], ids=ids)
def test_total_4_and_percent(key):
    # Total 4 = legs x Total Each, percent = 100 Total 4 / capsule weight, legs and capsule from the config;
    # a figure follows when it is within half a unit of its last printed digit of that arithmetic.
    cid, what = key
    t, cfg = TABLES[cid], config(cid)
    assert cfg.capsule_mass / LB == pytest.approx(t["capsule_lb"], rel=1e-12)
    total_4 = cfg.legs * float(t["total_each"])
    correct = total_4 if what == "total_4" else 100 * total_4 / t["capsule_lb"]
    off = abs(float(t[what]) - correct)
    if key in MISPRINTED_TOTALS:
        assert off > half_unit(t[what]), f"record no longer needed: {MISPRINTED_TOTALS[key]}"
    else:
        assert off <= half_unit(t[what])


# Our per-leg total (the design pipeline's sum of count x weight) against the printed Total Each: within the
# rows' 0.5 % when no recorded row is off by more than that; otherwise the printed total corrected by the
# recorded rows (printed value replaced by the hand value) must be met within the same 0.5 %, and the
# uncorrected total must fail it (the correction is needed).
TOTAL_RTOL = 0.005


@pytest.mark.parametrize("cid", list(TABLES))
def test_our_total_each(cid):
    t = TABLES[cid]
    printed = float(t["total_each"])
    ours = run_design(config(cid)).per_leg / LB
    corrections = [hand - float(t["rows"][label]) for (c, label), (hand, _) in RECORDED_WEIGHTS.items() if c == cid]
    if all(abs(d) <= TOTAL_RTOL * printed for d in corrections):
        assert ours == pytest.approx(printed, rel=TOTAL_RTOL)
    else:
        corrected = printed + sum(corrections)
        assert ours == pytest.approx(corrected, rel=TOTAL_RTOL)
        assert ours != pytest.approx(printed, rel=TOTAL_RTOL)
