"""Section properties of AFFDL-TR-66-33 App. IV: areas, second moments and radii of gyration from a section's
dimensions. SI in and out."""

from __future__ import annotations

from math import pi, sqrt


def tube_area(d_mean: float, t: float) -> float:
    """Tube area A = pi d t, d the mean diameter (AFFDL-TR-66-33 App. IV): exact for any wall, since
    pi (r_o^2 - r_i^2) = 2 pi r t."""
    return pi * d_mean * t


def tube_inertia(d_mean: float, t: float) -> float:
    """Thin tube second moment I = pi r^3 t, r the mean radius (AFFDL-TR-66-33 App. IV): the exact
    pi (r_o^4 - r_i^4) / 4 is pi r^3 t (1 + t^2 / (4 r^2)), so it is low (conservative) by 0.25 % at t = r / 10."""
    return pi * (d_mean / 2) ** 3 * t


def rod_area(d: float) -> float:
    """Solid rod area A = pi d^2 / 4 (AFFDL-TR-66-33 App. IV, 0.785 d^2)."""
    return pi * d * d / 4


def rod_inertia(d: float) -> float:
    """Solid circle second moment I = pi d^4 / 64 about a diameter (Young & Budynas 2002 Table A.1, solid circle);
    its extreme fibre is at c = d / 2."""
    return pi * d ** 4 / 64


def rect_area(b: float, h: float) -> float:
    """Rectangle area A = b h."""
    return b * h


def rect_inertia(b: float, h: float) -> float:
    """Rectangle second moment I = b h^3 / 12 (AFFDL-TR-66-33 App. IV, swivel and lugs)."""
    return b * h ** 3 / 12


def radius_of_gyration_tube(d_mean: float) -> float:
    """Thin tube radius of gyration k = d / (2 sqrt 2) (App. IV; equals sqrt(I/A) of pi r^3 t / pi d t)."""
    return d_mean / (2 * sqrt(2))
