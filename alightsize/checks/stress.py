"""Member stress formulas of AFFDL-TR-66-33 App. IV: direct stresses, buckling, design factor (section
properties are in alightsize/model/section_properties.py).

All arguments and results in SI (m, N, Pa, N*m). One function per formula, each citing its source.
"""

from __future__ import annotations

from math import exp, hypot, inf, pi, sqrt


def direct_stress(p: float, a: float) -> float:
    """Compression or tension sigma = P / A (AFFDL-TR-66-33 App. IV)."""
    return p / a


def bending_stress(m: float, c: float, i: float) -> float:
    """Bending sigma = M c / I (AFFDL-TR-66-33 App. IV)."""
    return m * c / i


def combined_stress(sigma_direct: float, sigma_bending: float) -> float:
    """Combined sigma_max = sigma_B + sigma_C, the stresses at the extreme fibre added (App. IV)."""
    return sigma_direct + sigma_bending


def ring_moment(p: float, span: float) -> float:
    """Ring bending moment M = P L / 4, the ring as a centrally loaded beam (App. IV, peg-leg ring)."""
    return p * span / 4


def euler_load(e: float, i: float, length: float) -> float:
    """Euler column load P_cr = pi^2 E I / L^2, pinned ends (App. IV, telescoping leg)."""
    return pi ** 2 * e * i / length ** 2


def euler_stress(e: float, length: float, k: float) -> float:
    """Euler column stress sigma_cr = pi^2 E / (L/k)^2 (App. IV, trusses and struts)."""
    return pi ** 2 * e / (length / k) ** 2


def local_buckling_stress(e: float, t: float, d: float) -> float:
    """Thin tube local buckling sigma_LB = 0.4 E t / D (App. IV, telescoping leg)."""
    return 0.4 * e * t / d


def bearing_stress(p: float, d: float, t: float) -> float:
    """Bearing sigma_BR = P / (d t) (App. IV, cap lugs)."""
    return p / (d * t)


def cone_strip_area(t: float) -> float:
    """Cone in tension on a strip ten thicknesses wide: A = 10 t^2 (App. IV, peg-leg cone)."""
    return 10 * t * t


def resultant(*components: float) -> float:
    """Resultant of orthogonal load components, P = sqrt(sum P_i^2) (App. IV, swivel pins)."""
    return hypot(*components)


def shear_allowable(yield_strength: float) -> float:
    """Maximum-shear theory: shear allowable = yield / 2 (App. IV; Roark 1954 p. 79)."""
    return yield_strength / 2


def report_max_shear(sigma_r: float, sigma_t: float) -> float:
    """tau_max = (sigma_r + sigma_t) / 2 as App. IV applies it to plates (tau = sigma when sigma_r = sigma_t)."""
    return (sigma_r + sigma_t) / 2


def design_factor(allowable: float, stress: float) -> float:
    """Design factor f = allowable / stress (App. IV); infinite when nothing is stressed."""
    return inf if stress <= 0 else allowable / stress


def transition_slenderness(e: float, fcy: float) -> float:
    """(L/k)_T = pi sqrt(2 E / Fcy), where Johnson's parabola meets Euler's curve (Bruhn 1973 C2.4)."""
    return pi * sqrt(2 * e / fcy)


def johnson_stress(e: float, fcy: float, slenderness: float) -> float:
    """Johnson parabola sigma_cr = Fcy - (Fcy / (2 pi))^2 (L/k)^2 / E (Bruhn 1973 eq. C2.6)."""
    return fcy - (fcy / (2 * pi)) ** 2 * slenderness ** 2 / e


def column_stress(e: float, fcy: float, slenderness: float) -> tuple[float, str]:
    """Critical stress of a pinned column: Johnson below the transition slenderness, Euler at or above it
    (Bruhn 1973 C2.4-C2.6); returns (stress, "johnson" | "euler")."""
    if slenderness < transition_slenderness(e, fcy):
        return johnson_stress(e, fcy, slenderness), "johnson"
    return pi ** 2 * e / slenderness ** 2, "euler"


def thin_wall_knockdown(r_over_t: float) -> float:
    """gamma = 1 - 0.901 (1 - exp(-phi)), phi = sqrt(r/t) / 16 (NASA SP-8007 1968, eq. 4)."""
    return 1 - 0.901 * (1 - exp(-sqrt(r_over_t) / 16))


def classical_cylinder_stress(e: float, t: float, r: float, nu: float) -> float:
    """sigma_cl = E t / (r sqrt(3 (1 - nu^2))), axially compressed cylinder (Timoshenko & Gere 1961 eq. 11-13)."""
    return e * t / (r * sqrt(3 * (1 - nu * nu)))


def tresca_stress(s1: float, s2: float, s3: float = 0.0) -> float:
    """Tresca equivalent stress max(|s1 - s2|, |s2 - s3|, |s3 - s1|), against Fcy (Young & Budynas 2002 §3.7)."""
    return max(abs(s1 - s2), abs(s2 - s3), abs(s3 - s1))


def von_mises_stress(s1: float, s2: float, s3: float = 0.0) -> float:
    """von Mises equivalent stress sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2) (Young & Budynas 2002 §3.7)."""
    return sqrt(((s1 - s2) ** 2 + (s2 - s3) ** 2 + (s3 - s1) ** 2) / 2)


def pin_shear_stress(p: float, d: float, planes: int) -> float:
    """tau = P / (n pi d^2 / 4), a pin in n shear planes (Bruhn 1973 D1.4)."""
    return p / (planes * pi * d * d / 4)
