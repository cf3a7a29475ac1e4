"""Circular flat plates: thin-plate (Kirchhoff) bending stresses, and the Roark (1954) formulas AFFDL-TR-66-33
App. IV prints.

SI throughout; m = 1/nu is Roark's reciprocal Poisson ratio; logarithms natural. Each function returns the
bending stresses (sigma_r, sigma_t) on a face of the plate, 6 M / t², at the point its docstring names, positive
in tension on the face away from the load (Roark's sign). Each states its range; the checks refuse inputs
outside it (alightsize.checks.kinds). Every plate formula assumes a thin plate: thickness at most a quarter of
its least transverse dimension, t <= (a - b)/2 with b = 0 for a solid plate (Young & Budynas 2002 §11.1).
"""

from __future__ import annotations

from math import log, pi, sqrt

import numpy as np
from scipy.special import spence

APP_IV_HUB_MAX = 0.3          # r0/a up to which the 1954 hub-couple formula is used (see fixed_center_moment)


def fixed_center_load(w: float, t: float, a: float, r0: float, m: float) -> tuple[float, float]:
    """Edge fixed, load W uniform over a central circle r0; at the centre (Roark 1954 p. 196).

    Exact thin-plate theory for 0 < r0 <= a; the centre governs up to r0 ~ 0.6 a, the edge beyond
    (fixed_edge_load)."""
    s = 3 * w * (m + 1) / (2 * pi * m * t * t) * (log(a / r0) + r0 * r0 / (4 * a * a))
    return s, s


def fixed_edge_load(w: float, t: float, a: float, r0: float, m: float) -> tuple[float, float]:
    """Edge fixed, load W uniform over a central circle r0; at the edge: sigma_r = -3 W/(2 pi t²) (1 - r0²/(2 a²)),
    sigma_t = sigma_r/m (thin-plate solution, Timoshenko & Woinowsky-Krieger 1959 ch. 3). 0 < r0 <= a."""
    s = -3 * w / (2 * pi * t * t) * (1 - r0 * r0 / (2 * a * a))
    return s, s / m


def supported_center_load(w: float, t: float, a: float, r0: float, m: float) -> tuple[float, float]:
    """Edge simply supported, load W uniform over a central circle r0; at the centre, where the stress is greatest
    (Roark 1954 p. 194-195). Exact thin-plate theory for 0 < r0 <= a."""
    s = 3 * w / (2 * pi * m * t * t) * (m + (m + 1) * log(a / r0) - (m - 1) * r0 * r0 / (4 * a * a))
    return s, s


def hub_couple(moment: float, t: float, a: float, b: float, m: float, edge: str) -> tuple[float, float]:
    """Couple M through a rigid central hub of radius b, outer edge "fixed" or "supported"; at the hub edge in the
    plane of the couple, where the stress is greatest: sigma_r = 3 M F / (pi b t²), sigma_t = sigma_r / m.

    F = (a² - b²)/(a² + b²) (fixed), [(3+nu) a⁴ - 2 (1+nu) a² b² - (1-nu) b⁴] / [(3+nu) a⁴ + (1-nu) b⁴] (supported):
    the cos(theta) term of the thin-plate solution, w = (A r + B r³ + C/r + E r ln r) cos(theta), with the plate
    clamped to the hub (Timoshenko & Woinowsky-Krieger 1959 ch. 9; the couple is 4 pi D E). 0 < b < a.
    """
    nu, a2, b2 = 1 / m, a * a, b * b
    if edge == "fixed":
        f = (a2 - b2) / (a2 + b2)
    else:
        f = (((3 + nu) * a2 * a2 - 2 * (1 + nu) * a2 * b2 - (1 - nu) * b2 * b2)
             / ((3 + nu) * a2 * a2 + (1 - nu) * b2 * b2))
    s = 3 * moment * f / (pi * b * t * t)
    return s, s / m


def fixed_center_moment(moment: float, t: float, a: float, r0: float, m: float,
                        pi_squared: bool = False) -> tuple[float, float]:
    """Edge fixed, couple M applied through a central hub (lugs) of radius r0 (Roark 1954 p. 197), as App. IV uses it.

    sigma = 3M / (4 pi t² r0) [1 + (m+1)/m ln(2 (0.45 a - r0) / (0.45 k a))], k = 0.1 a² / (r0 + 0.28 a)². Used for
    0 < r0 <= 0.3 a only (APP_IV_HUB_MAX): it changes sign at r0 = 0.43 a, and it is 1.6-2.4 times below
    thin-plate theory (hub_couple) over that range (tests/validation/test_plates.py). `pi_squared` reproduces App.
    IV's upper leg cap, whose substitution and printed 1,790 psi use 4 pi² in the denominator.
    """
    k = 0.1 * a * a / (r0 + 0.28 * a) ** 2
    s = 3 * moment / (4 * (pi * pi if pi_squared else pi) * t * t * r0) * (
        1 + (m + 1) / m * log(2 * (0.45 * a - r0) / (0.45 * k * a)))
    return s, s


def annular_uniform_pressure(q: float, t: float, a: float, b: float, m: float, outer: str,
                             inner: str) -> tuple[tuple[float, float], tuple[float, float]]:
    """Annular plate a > b > 0 under uniform pressure q, each edge "free", "supported" or "fixed"; the stresses at the
    inner and the outer edge, ((sigma_r, sigma_t) at b, (sigma_r, sigma_t) at a).

    Thin-plate solution w = C1 + C2 r² + C3 ln r + C4 r² ln r + q r⁴/(64 D), constants from the edge conditions
    (Young & Budynas 2002 Table 11.2 case 2, r0 = b). With one edge free and the other held (cases 2a, 2e, 2i,
    2j) the greatest stress is at an edge for every b/a.
    """
    nu = 1 / m

    def terms(r: float) -> tuple[list[float], ...]:
        """Derivatives 0 to 3 of 1, r², ln r, r² ln r and of q r⁴/64 (per unit D) at r."""
        lr = log(r)
        return ([1.0, r * r, lr, r * r * lr, q * r ** 4 / 64], [0.0, 2 * r, 1 / r, 2 * r * lr + r, q * r ** 3 / 16],
                [0.0, 2.0, -1 / r ** 2, 2 * lr + 3, 3 * q * r * r / 16], [0.0, 0.0, 2 / r ** 3, 2 / r, 6 * q * r / 16])

    def conditions(r: float, edge: str) -> list[list[float]]:
        """The two conditions of an edge at r, each as 4 coefficients and the particular term (sum = 0)."""
        w, w1, w2, w3 = terms(r)
        moment = [w2[i] + nu * w1[i] / r for i in range(5)]                   # -M_r / D
        shear = [w3[i] + w2[i] / r - w1[i] / (r * r) for i in range(5)]      # -Q / D
        return {"free": [moment, shear], "supported": [w, moment], "fixed": [w, w1]}[edge]

    eqs = conditions(a, outer) + conditions(b, inner)
    c = np.append(np.linalg.solve(np.array([e[:4] for e in eqs]), -np.array([e[4] for e in eqs])), 1.0)

    def stresses(r: float, edge: str) -> tuple[float, float]:
        _, w1, w2, _ = terms(r)
        wp, wpp = float(np.dot(c, w1)), float(np.dot(c, w2))
        radial = -6 * (wpp + nu * wp / r) / (t * t) if edge == "fixed" else 0.0    # M_r = 0 at a free or supported edge
        return radial, -6 * (wp / r + nu * wpp) / (t * t)

    return stresses(b, inner), stresses(a, outer)


def supported_uniform_load(w_total: float, t: float, a: float, r: float, m: float,
                           a_t: float | None = None) -> tuple[float, float]:
    """Edge simply supported, W' uniform over the whole plate; at radius r:
    sigma_r = 3 W'/(8 pi m t²) (3m+1)(1 - r²/a²), sigma_t = 3 W'/(8 pi m t²) [(3m+1) - (m+3) r²/a_t²]
    (Roark 1954 p. 194). 0 <= r <= a; `a_t` (default a)
    reproduces App. IV's configurations 3-5, 7 (printed 1.75 in for the plate's 1.725 in)."""
    s = 3 * w_total / (8 * pi * m * t * t)
    a_t = a if a_t is None else a_t
    return s * (3 * m + 1) * (1 - r * r / (a * a)), s * ((3 * m + 1) - (m + 3) * r * r / (a_t * a_t))


def app_iv_eccentric_load(w: float, t: float, a: float, p: float, r0: float, m: float) -> float:
    """Edge simply supported, W uniform over a circle r0 centred at radius p, taken (App. IV, Roark 1954 p. 194-195)
    as a central load on a plate of radius a - p: sigma_r = sigma_t at the load, for p + r0 <= a.

    An approximation: against thin-plate theory (supported_eccentric_load) it is low by 2-4 % at p = 0.1 a,
    4-9 % at 0.2 a, 10-26 % at 0.5 a and 20-110 % at 0.8 a (r0 = 0.02-0.2 a; tests/validation/test_plates.py):
    within 5 % only for a load near the centre, p <= 0.1 a.
    """
    c = a - p
    return 3 * w / (2 * pi * m * t * t) * (m + (m + 1) * log(c / r0) - (m - 1) * r0 * r0 / (4 * c * c))


_RHO, _RHO_W = np.polynomial.legendre.leggauss(16)   # quadrature over the load circle: 16 radii x 32 angles,
_BETA = 2 * pi * np.arange(32) / 32                   # converged to 1e-11 for p + r0 <= a (test_plates.py)


def _image_sums(z: np.ndarray, c: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """sum over n >= 1 of z^n n^k / (2n + c), k = 0, 1, 2, for |z| < 1. The k = 0 sum is -ln(1 - z)/2 - c Li2(z)/4
    plus c²/4 sum z^n / (n² (2n + c)), whose terms fall as n^-3 (summed to |z|^n < 1e-17 or 2,000 terms: within
    3e-8 as |z| -> 1); k = 1, 2 follow from n/(2n+c) = 1/2 - (c/2)/(2n+c), n²/(2n+c) = n/2 - c/4 + (c²/4)/(2n+c)."""
    last = min(2000, int(np.ceil(np.log(1e-17) / np.log(max(float(np.abs(z).max()), 1e-3)))))
    n = np.arange(1, last + 1).reshape((-1,) + (1,) * z.ndim)
    powers = np.cumprod(np.broadcast_to(z, n.shape[:1] + z.shape), axis=0)
    s = -np.log(1 - z) / 2 - c * spence(1 - z) / 4 + c * c / 4 * np.sum(powers / (n * n * (2 * n + c)), axis=0)
    geometric = z / (1 - z)
    return s, geometric / 2 - c * s / 2, z / (2 * (1 - z) ** 2) - c * geometric / 4 + c * c * s / 4


def supported_eccentric_load(w: float, t: float, a: float, p: float, r0: float, m: float) -> tuple[float, float]:
    """Edge simply supported, W uniform over a circle r0 centred at radius p; at the centre of the load circle
    (radial, tangential), for 0 <= p, p + r0 <= a. Exact thin-plate theory.

    The Green's function of the supported plate is the clamped plate's (Michell 1902; Timoshenko & Woinowsky-
    Krieger 1959 ch. 9) plus a series that frees the edge moment, with image terms (rs/a²)^n cos(n psi)/(2n + 1 + nu).
    Its singular part rho² ln rho is integrated over the circle in closed form, the smooth rest by Gauss
    quadrature (_image_sums for the series). At p = 0 this is supported_center_load.
    """
    if p == 0:
        return supported_center_load(w, t, a, r0, m)
    nu, q = 1 / m, w / (pi * r0 * r0)
    rho = 0.5 * r0 * (_RHO + 1)
    rr, bb = np.meshgrid(rho, _BETA, indexing="ij")
    weight = (0.5 * r0 * _RHO_W)[:, None] * rr * (2 * pi / _BETA.size) * q / (16 * pi)   # dA q / (16 pi), D = 1
    xi, eta = p + rr * np.cos(bb), rr * np.sin(bb)
    dx, s2 = p - xi, xi * xi + eta * eta
    # clamped plate: rho² ln(rho² a² / Q) + (a² - r²)(a² - s²)/a², Q = a⁴ - 2 a² x.xi + r² s²
    big_q = a ** 4 - 2 * a * a * p * xi + p * p * s2
    h = 2 * log(a) - np.log(big_q)
    qx, qy = -2 * a * a * xi + 2 * p * s2, -2 * a * a * eta
    hxx = -2 * s2 / big_q + qx * qx / big_q ** 2
    hyy = -2 * s2 / big_q + qy * qy / big_q ** 2
    rho2 = dx * dx + eta * eta
    edge = -2 * (a * a - s2) / (a * a)
    wxx = np.sum(weight * (2 * h - 4 * dx * qx / big_q + rho2 * hxx + edge))
    wyy = np.sum(weight * (2 * h + 4 * eta * qy / big_q + rho2 * hyy + edge))
    # supported edge: (a² - s²)(a² - r²)/a² [2/(1+nu) + 4 Re sum z^n/(2n + 1 + nu)], z = r s e^(i psi)/a²
    sums = _image_sums(p * (xi + 1j * eta) / (a * a), 1 + nu)
    s0, s1, snn = 2 / (1 + nu) + 4 * sums[0].real, 4 * sums[1].real, 4 * sums[2].real
    s2n = snn - s1
    k, pa = weight * (a * a - s2) / (a * a), a * a - p * p
    wxx += np.sum(k * (-2 * s0 - 4 * s1 + pa * s2n / (p * p)))
    wyy += np.sum(k * (-2 * s0 + pa * (s1 - snn) / (p * p)))
    # the singular part rho² ln rho² over the circle, at its centre: w_xx = w_yy = W (ln r0 + 1/2) / (4 pi D)
    wxx += w * (log(r0) + 0.5) / (4 * pi)
    wyy += w * (log(r0) + 0.5) / (4 * pi)
    return -6 * (wxx + nu * wyy) / (t * t), -6 * (wyy + nu * wxx) / (t * t)


def equivalent_radius(r0: float, t: float) -> float:
    """Roark's equivalent radius of a load on a small circle: r0' = sqrt(1.6 r0² + t²) - 0.675 t when
    r0 < 0.5 t, else r0 (Roark 1954 p. 194; Young & Budynas 2002 §11.2)."""
    return sqrt(1.6 * r0 * r0 + t * t) - 0.675 * t if r0 < 0.5 * t else r0
