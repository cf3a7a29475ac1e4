"""Telescoping leg footpad position and spherical coordinates (AFFDL-TR-66-33 Sec. V.E.1-2, eq. 12-21).

A leg of axial length al tilted by alpha from -S3 in the direction beta (from S1). alpha = 0 leaves beta
undefined; as the report does for this leg, beta is then 0. SI units, radians, numpy-vectorized.
"""

from __future__ import annotations

import numpy as np


def footpad(al, alpha, beta):
    """(S1, S2, S3) of the footpad from the attachment point (eq. 12-13)."""
    return (al * np.sin(alpha) * np.cos(beta), al * np.sin(alpha) * np.sin(beta), -al * np.cos(alpha))


def spherical(s1, s2, s3):
    """(al, alpha, beta) of a deflection vector (eq. 17-19); beta = 0 where alpha = 0."""
    s1, s2, s3 = (np.asarray(x, float) for x in (s1, s2, s3))
    horizontal = np.hypot(s1, s2)
    al = np.sqrt(horizontal ** 2 + s3 ** 2)
    alpha = np.arctan2(horizontal, -s3)          # = arccos(-S3/al), well conditioned near 0
    beta = np.where(horizontal > 0, np.arctan2(s2, s1), 0.0)
    return al, alpha, beta


def axial_deflection(rho, al):
    """Delta_1 = rho - al (eq. 20)."""
    return rho - al


def pad_deflection(lever, alpha, beta, pad_angle, small_angle: bool = False):
    """Deflection of the rotational pad at angle gamma_j, lever arm `lever` from the pivot (eq. 21).

    Exact: the leg axis at the pad moves lever * sin(alpha) toward beta; the pad takes its component
    lever sin(alpha) cos(gamma_j - beta). The report's small-angle form uses alpha for sin(alpha) (1.2 %
    apart at 15 deg). A pad is never pulled: negative values are 0.
    """
    tilt = alpha if small_angle else np.sin(alpha)
    return np.maximum(lever * tilt * np.cos(pad_angle - beta), 0.0)
