"""Member stress formulas of AFFDL-TR-66-33 App. IV and their successors: direct stresses, buckling, design factor
(section properties are in alightsize/model/section_properties.py).

All arguments and results in SI (m, N, Pa, N*m). One function per formula, each citing its source and stating
the range in which it holds; alightsize.checks.kinds keeps every check inside those ranges or refuses it.
"""

from __future__ import annotations

from math import exp, hypot, inf, pi, sqrt

# Thin-shell formulas (local buckling) hold for r/t >= 10, a wall under a tenth of the radius (Young & Budynas
# 2002 ch. 13); a thicker wall yields before it buckles locally.
THIN_WALL_MIN_R_OVER_T = 10.0
# NASA SP-8007 1968 states its knockdown for r/t < 1500.
SP8007_MAX_R_OVER_T = 1500.0
# Ring bending as a straight beam, M = P L / 4 with the span L = 2 R: 0.5 P R, 1.57 times Roark's closed ring
# under diametral loads (P R / pi, Young & Budynas 2002 Table 9.2 case 1). That margin covers the curved-beam
# (Winkler) inner-fibre factor of a rectangle, 1.52 at R/c = 2 (Young & Budynas 2002 Table 9.1), not below it.
RING_MIN_R_OVER_C = 2.0


def direct_stress(p: float, a: float) -> float:
    """Compression or tension sigma = P / A (AFFDL-TR-66-33 App. IV). Signed as P; uniform over a section of
    area A > 0 away from the load points (Saint-Venant)."""
    return p / a


def bending_stress(m: float, c: float, i: float) -> float:
    """Bending sigma = M c / I (AFFDL-TR-66-33 App. IV): a straight, linear-elastic beam (plane sections),
    I > 0; signed as M."""
    return m * c / i


def combined_stress(sigma_direct: float, sigma_bending: float) -> float:
    """Combined sigma_max = |sigma_B| + |sigma_C| at the worst fibre (App. IV adds them): superposition, valid
    while the axial load is far below the member's Euler load (no beam-column amplification, Timoshenko & Gere
    1961 ch. 1)."""
    return abs(sigma_direct) + abs(sigma_bending)


def ring_moment(p: float, span: float) -> float:
    """Ring bending moment M = P L / 4, the ring as a centrally loaded beam (App. IV, peg-leg ring); see
    RING_MIN_R_OVER_C for its range (R = L / 2)."""
    return p * span / 4


def euler_load(e: float, i: float, length: float) -> float:
    """Euler column load P_cr = pi^2 E I / L^2, pinned ends (App. IV, telescoping leg); valid at or above the
    transition slenderness (Bruhn 1973 C2.4), as euler_stress."""
    return pi ** 2 * e * i / length ** 2


def euler_stress(e: float, length: float, k: float) -> float:
    """Euler column stress sigma_cr = pi^2 E / (L/k)^2 (App. IV, trusses and struts). Valid for L/k at or above
    the transition slenderness pi sqrt(2 E / Fcy), where it is at most Fcy / 2; below it the column is
    inelastic and Johnson's parabola holds (Bruhn 1973 C2.4-C2.6)."""
    return pi ** 2 * e / (length / k) ** 2


def local_buckling_stress(e: float, t: float, d: float) -> float:
    """Thin tube local buckling sigma_LB = 0.4 E t / D, D the outside diameter (App. IV, telescoping leg). The
    report gives no source or range: it is used for 10 <= r/t while it does not exceed NASA SP-8007's design
    curve (r/t up to 474 for nu = 0.3; see app_iv_local_in_range)."""
    return 0.4 * e * t / d


def bearing_stress(p: float, d: float, t: float) -> float:
    """Bearing sigma_BR = P / (d t) on the projected area of a pin of diameter d > 0 in a hole of length t > 0
    (App. IV, cap lugs; Bruhn 1973 D1): a close-fitting pin; lug edge distance and net section not included."""
    return p / (d * t)


def cone_strip_area(t: float) -> float:
    """Cone in tension on a strip ten thicknesses wide: A = 10 t^2 (App. IV, peg-leg cone: the report's
    conservative estimate in place of a shell analysis; no stated range)."""
    return 10 * t * t


def resultant(*components: float) -> float:
    """Resultant of orthogonal load components, P = sqrt(sum P_i^2) (App. IV, swivel pins); any signs."""
    return hypot(*components)


def collinear_sum(*components: float) -> float:
    """Loads pressing the same bearing surface, P = sum |P_i| (App. IV, telescoping leg: w1 + w2)."""
    return sum(abs(c) for c in components)


def shear_allowable(yield_strength: float) -> float:
    """Maximum-shear theory: shear allowable = yield / 2 (App. IV; Roark 1954 p. 79)."""
    return yield_strength / 2


def report_max_shear(sigma_r: float, sigma_t: float) -> float:
    """tau_max = (sigma_r + sigma_t) / 2 as App. IV applies it to plates (tau = sigma when sigma_r = sigma_t)."""
    return (sigma_r + sigma_t) / 2


def design_factor(allowable: float, stress: float) -> float:
    """Design factor f = allowable / |stress| (App. IV): tension and compression alike, so a sign never makes
    it infinite; infinite only when nothing is stressed (a zero load)."""
    magnitude = abs(stress)
    return inf if magnitude == 0 else allowable / magnitude


def transition_slenderness(e: float, fcy: float) -> float:
    """(L/k)_T = pi sqrt(2 E / Fcy), where Johnson's parabola meets Euler's curve (Bruhn 1973 C2.4)."""
    return pi * sqrt(2 * e / fcy)


def johnson_stress(e: float, fcy: float, slenderness: float) -> float:
    """Johnson parabola sigma_cr = Fcy - (Fcy / (2 pi))^2 (L/k)^2 / E (Bruhn 1973 eq. C2.6), valid for
    0 <= L/k below the transition slenderness, where it falls from Fcy to Fcy / 2."""
    return fcy - (fcy / (2 * pi)) ** 2 * slenderness ** 2 / e


def column_stress(e: float, fcy: float, slenderness: float) -> tuple[float, str]:
    """Critical stress of a pinned column: Johnson below the transition slenderness, Euler at or above it
    (Bruhn 1973 C2.4-C2.6); returns (stress, "johnson" | "euler")."""
    if slenderness < transition_slenderness(e, fcy):
        return johnson_stress(e, fcy, slenderness), "johnson"
    return pi ** 2 * e / slenderness ** 2, "euler"


def thin_wall_knockdown(r_over_t: float) -> float:
    """gamma = 1 - 0.901 (1 - exp(-phi)), phi = sqrt(r/t) / 16 (NASA SP-8007 1968, eq. 4), stated there for
    r/t < 1500 (SP8007_MAX_R_OVER_T)."""
    return 1 - 0.901 * (1 - exp(-sqrt(r_over_t) / 16))


def classical_cylinder_stress(e: float, t: float, r: float, nu: float) -> float:
    """sigma_cl = E t / (r sqrt(3 (1 - nu^2))), axially compressed cylinder (Timoshenko & Gere 1961 eq. 11-13):
    an elastic thin shell, r/t >= 10 (THIN_WALL_MIN_R_OVER_T), r the mean radius."""
    return e * t / (r * sqrt(3 * (1 - nu * nu)))


def sp8007_stress(e: float, t: float, r: float, nu: float) -> float:
    """NASA SP-8007 1968 design stress gamma sigma_cl for 10 <= r/t < 1500 (elastic; see local_critical)."""
    return thin_wall_knockdown(r / t) * classical_cylinder_stress(e, t, r, nu)


def app_iv_local_in_range(e: float, t: float, r: float, nu: float) -> bool:
    """App. IV's 0.4 E t / D holds where it does not exceed NASA SP-8007's lower-bound design curve (r/t up to
    474 for nu = 0.3): beyond, the 1966 formula would credit a thin tube with more than tests support."""
    return local_buckling_stress(e, t, 2 * r + t) <= sp8007_stress(e, t, r, nu)


def local_critical(elastic: float, fcy: float) -> float:
    """Local-buckling allowable min(sigma_elastic, Fcy): the elastic shell formulas hold below the compressive
    yield only (NASA SP-8007 1968 applies them to elastic walls), and a wall at Fcy yields whatever its
    buckling stress."""
    return min(elastic, fcy)


def tresca_stress(s1: float, s2: float, s3: float = 0.0) -> float:
    """Tresca equivalent stress max(|s1 - s2|, |s2 - s3|, |s3 - s1|), against Fcy (Young & Budynas 2002 §3.7)."""
    return max(abs(s1 - s2), abs(s2 - s3), abs(s3 - s1))


def von_mises_stress(s1: float, s2: float, s3: float = 0.0) -> float:
    """von Mises equivalent stress sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2) (Young & Budynas 2002 §3.7)."""
    return sqrt(((s1 - s2) ** 2 + (s2 - s3) ** 2 + (s3 - s1) ** 2) / 2)


def pin_shear_stress(p: float, d: float, planes: int) -> float:
    """tau = P / (n pi d^2 / 4), the average shear of a pin of diameter d > 0 in n shear planes (Bruhn 1973
    D1.4); pin bending not included."""
    return p / (planes * pi * d * d / 4)
