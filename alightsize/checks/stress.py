"""Member stress formulas of AFFDL-TR-66-33 App. IV: direct stresses, buckling, design factor (section
properties are in alightsize/model/section_properties.py).

All arguments and results in SI (m, N, Pa, N*m). One function per formula, each citing its source.
"""

from __future__ import annotations

from math import hypot, inf, pi


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
