"""Roark (1954) circular flat plates as AFFDL-TR-66-33 App. IV uses them.

m is Roark's reciprocal Poisson ratio (3.33), logarithms natural, SI units. Each returns the
maximum radial and tangential stresses (sigma_r, sigma_t) in Pa at the point the report evaluates.
"""

from __future__ import annotations

from math import log, pi, sqrt


def fixed_center_load(w: float, t: float, a: float, r0: float, m: float) -> tuple[float, float]:
    """Edge fixed, load W uniform over a central circle of radius r0; at the centre (Roark 1954 p. 196)."""
    s = 3 * w * (m + 1) / (2 * pi * m * t * t) * (log(a / r0) + r0 * r0 / (4 * a * a))
    return s, s


def supported_center_load(w: float, t: float, a: float, r0: float, m: float) -> tuple[float, float]:
    """Edge simply supported, load W over a central circle of radius r0; at the centre (Roark 1954 p. 194-195)."""
    s = 3 * w / (2 * pi * m * t * t) * (m + (m + 1) * log(a / r0) - (m - 1) * r0 * r0 / (4 * a * a))
    return s, s


def fixed_center_moment(moment: float, t: float, a: float, r0: float, m: float,
                        pi_squared: bool = False) -> tuple[float, float]:
    """Edge fixed, couple M applied through a central hub (lugs) of radius r0 (Roark 1954 p. 197).

    sigma = 3M / (4 pi t^2 r0) [1 + (m+1)/m ln(2 (0.45 a - r0) / (0.45 k a))], k = 0.1 a^2 / (r0 + 0.28 a)^2.
    `pi_squared` reproduces AFFDL-TR-66-33 App. IV (upper leg cap), whose substitution and printed
    1,790 psi use 4 pi^2 in the denominator.
    """
    k = 0.1 * a * a / (r0 + 0.28 * a) ** 2
    s = 3 * moment / (4 * (pi * pi if pi_squared else pi) * t * t * r0) * (
        1 + (m + 1) / m * log(2 * (0.45 * a - r0) / (0.45 * k * a)))
    return s, s


def annular_uniform_pressure(q: float, t: float, a: float, b: float, m: float) -> tuple[float, float]:
    """Annular plate, outer edge a supported, inner edge b free, uniform pressure q; sigma_t at the inner
    edge (Roark 1954 p. 199; AFFDL-TR-66-33 App. IV peg-leg absorber cap, its "W" = 4,150 psi). sigma_r = 0."""
    s = 3 * q / (4 * m * t * t * (a * a - b * b)) * (
        4 * a ** 4 * (m + 1) * log(a / b) + 4 * a * a * b * b + b ** 4 * (m - 1) - a ** 4 * (m + 3))
    return 0.0, s


def supported_eccentric_and_distributed(w: float, w_total: float, t: float, a: float, p: float,
                                        r0: float, m: float, a_t: float | None = None) -> tuple[float, float]:
    """Simply supported plate: one load W over a small circle r0 at radius p, plus W' uniform over the
    whole plate; stresses at the loaded point (Roark 1954 p. 194-195, superposed as App. IV does).

    The eccentric load is taken as a central load on a plate of radius a - p (App. IV); `a_t`
    is the radius in the tangential distributed term, default `a` (App. IV config. 3-5, 7 prints 1.75).
    """
    ecc = -3 * w / (2 * pi * m * t * t) * (
        m + (m + 1) * log((a - p) / r0) - (m - 1) * r0 * r0 / (4 * (a - p) ** 2))
    dist = 3 * w_total / (8 * pi * m * t * t)
    a_t = a if a_t is None else a_t
    sigma_r = ecc + dist * (3 * m + 1) * (1 - p * p / (a * a))
    sigma_t = ecc + dist * ((3 * m + 1) - (m + 3) * p * p / (a_t * a_t))
    return sigma_r, sigma_t


def equivalent_radius(r0: float, t: float) -> float:
    """Roark's equivalent radius of a load on a small circle: r0' = sqrt(1.6 r0^2 + t^2) - 0.675 t when
    r0 < 0.5 t, else r0 (Roark 1954 p. 194; Young & Budynas 2002 §11.2)."""
    return sqrt(1.6 * r0 * r0 + t * t) - 0.675 * t if r0 < 0.5 * t else r0
