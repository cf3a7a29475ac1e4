"""Shock response spectrum (SRS) of a base acceleration history, e.g. a landing-impact record.

``srs`` gives the maximax absolute-acceleration SRS of a damped single-degree-of-freedom (SDOF)
oscillator on a moving base. The history (t, a) is taken as recorded: linear between its samples, at
their true times, however uneven (an adaptive integrator's accepted steps, whose located events put the
acceleration's corners on samples). Nothing is resampled.

* Steps. Over each piece the oscillator advances by the exact solution for a linearly varying input
  (the ramp invariance of Smallwood, "An improved recursive formula for calculating shock response
  spectra", Shock and Vibration Bulletin 51, 1981, there on uniform steps; here in state-transition form,
  one transition per piece and frequency), so the result does not depend on how the record is sampled,
  only on the record.
* Start. The oscillator is at rest before ``t[0]``; a non-zero ``a[0]`` is a step at ``t[0]``.
* Tail. The last value is held after ``t[-1]``; the residual (post-record) extremes of the free decay
  are found in closed form.
* Peaks. A piece longer than 1/16 of the natural period is split into equal sub-steps of at most that;
  inside each, the extreme of the cubic Hermite through the exact response and its rate at the sub-step's
  ends. Its under-estimate is at most (2 pi / 16)^4 / 384 = 6.2e-5 of the oscillation's amplitude (the
  Hermite error f''''(xi) (u - u0)^2 (u - u1)^2 / 4!, Burden & Faires, Numerical Analysis, Sec. 3.4);
  measured 1.9e-5 on a held step.
"""

from __future__ import annotations

from math import asin, atan2, ceil, cos, exp, expm1, pi, sin, sqrt

import numpy as np
from numba import njit

from alightsize_sim.cache import register

register(__file__)                                  # numba's cache in the user cache folder, not the package

SUBSTEPS_PER_PERIOD = 16
"""Sub-steps per natural period at least (a piece longer than 1/16 period is split)."""

MAX_SAMPLES = 100_000_000
"""Most oscillator steps (sub-steps summed over the frequencies) ``srs`` takes; beyond it ValueError."""


def default_frequencies(fmin: float = 1.0, fmax: float = 1000.0, per_octave: int = 12) -> np.ndarray:
    """Log-spaced natural frequencies [Hz] from fmin to fmax (both included), at most 1/per_octave octave apart."""
    if not (np.isfinite(fmin) and np.isfinite(fmax) and 0 < fmin < fmax):
        raise ValueError(f"need 0 < fmin < fmax (finite), got fmin={fmin}, fmax={fmax}")
    if int(per_octave) != per_octave or per_octave < 1:
        raise ValueError(f"per_octave must be a positive integer, got {per_octave}")
    n = int(np.ceil(per_octave * np.log2(fmax / fmin) - 1e-9)) + 1
    return np.geomspace(fmin, fmax, max(n, 2))


@njit(cache=True)
def _one_minus_sinc(x: float) -> float:
    """1 - sin(x)/x without cancellation for small x: sum_{n>=1} (-1)^(n+1) x^(2n) / (2n+1)! below x = 0.5 (six
    terms; the next is below 5e-17 relative there)."""
    if x >= 0.5:
        return 1.0 - sin(x) / x
    x2, term, acc = x * x, 1.0, 0.0
    for n in range(1, 7):
        term *= x2 / ((2 * n) * (2 * n + 1))
        acc += term if n % 2 else -term
    return acc


@njit(cache=True)
def _hermite_max(p0: float, p1: float, m0: float, m1: float) -> float:
    """Largest |H(u)| at the interior extremes (0 < u < 1) of the cubic Hermite with end values p0, p1 and end
    slopes m0, m1 (per unit u); 0 when it has none. H'(u) = qa u^2 + qb u + qc."""
    qa = 6.0 * (p0 - p1) + 3.0 * (m0 + m1)
    qb = -6.0 * (p0 - p1) - 4.0 * m0 - 2.0 * m1
    qc = m0
    if qa == 0.0:
        r0, r1 = (-qc / qb if qb != 0.0 else -1.0), -1.0
    else:
        disc = qb * qb - 4.0 * qa * qc
        if disc < 0.0:
            return 0.0
        q = -0.5 * (qb + (sqrt(disc) if qb >= 0.0 else -sqrt(disc)))  # roots without cancellation
        r0, r1 = q / qa, (qc / q if q != 0.0 else -1.0)
    best = 0.0
    for u in (r0, r1):
        if 0.0 < u < 1.0:
            v = 1.0 - u
            best = max(best, abs(v * v * (1.0 + 2.0 * u) * p0 + u * u * (3.0 - 2.0 * u) * p1
                                 + u * v * v * m0 - u * u * v * m1))
    return best


@njit(cache=True)
def _maximax(t: np.ndarray, a: np.ndarray, w: float, zeta: float) -> float:
    """Max |x''| of the SDOF (natural frequency w rad/s, damping zeta) from rest, base acceleration a linear
    between the samples at t, held after t[-1].

    Relative displacement z: z'' + 2 s z' + w^2 z = -a (s = zeta w), x'' = -(2 s z' + w^2 z); with a = a0 + k tau
    over a sub-step of length d: z = -(a0 + k tau) / w^2 + 2 s k / w^4 plus the homogeneous solution, advanced by
    its transition matrix P(d) (standard SDOF result). The particular part enters through 1 - P11, d - P12 and
    1 - P22, evaluated without cancellation (expm1, 1 - cos = 2 sin^2, series 1 - sinc): a near-instant rise
    (large k over a tiny d) then adds only its own small change. x''' = -2 s (x'' - a) - w^2 z'.
    """
    w2 = w * w
    s = zeta * w
    wd = w * sqrt(1.0 - zeta * zeta)
    d_max = 2.0 * pi / (w * SUBSTEPS_PER_PERIOD)
    z = zd = x2 = 0.0
    x3 = 2.0 * s * a[0]
    peak = abs(a[-1])                      # the held last value, which the response tends to
    for i in range(t.size - 1):
        h = t[i + 1] - t[i]
        k = (a[i + 1] - a[i]) / h
        m = ceil(h / d_max)
        d = h / m
        em1 = expm1(-s * d)                                    # e - 1
        e, x = 1.0 + em1, wd * d
        sinc = sin(x) / x
        omc = 2.0 * sin(0.5 * x) ** 2                          # 1 - cos x
        q11 = -em1 + e * omc - e * s * d * sinc                # 1 - P11
        q22 = -em1 + e * omc + e * s * d * sinc                # 1 - P22
        q12 = d * (_one_minus_sinc(x) - em1 * sinc)            # d - P12
        p11, p12, p22 = 1.0 - q11, e * d * sinc, 1.0 - q22
        p21 = -w2 * p12
        lift = 2.0 * s * k / (w2 * w2)
        for j in range(m):
            a0 = a[i] + k * (j * d)
            a1 = a[i + 1] if j == m - 1 else a[i] + k * ((j + 1) * d)
            z, zd = (p11 * z + p12 * zd + (lift - a0 / w2) * q11 - k / w2 * q12,
                     p21 * z + p22 * zd + p21 * (a0 / w2 - lift) - k / w2 * q22)
            y2 = -(2.0 * s * zd + w2 * z)
            y3 = -2.0 * s * (y2 - a1) - w2 * zd
            peak = max(peak, abs(y2))
            if max(abs(x2), abs(y2)) + 4.0 / 27.0 * d * (abs(x3) + abs(y3)) > peak:  # bound on |Hermite|
                peak = max(peak, _hermite_max(x2, y2, x3 * d, y3 * d))
            x2, x3 = y2, y3
    # Held tail: g = x'' - a[-1] = exp(-s tau) (g0 cos wd tau + (g0' + s g0) / wd sin wd tau)
    # = r exp(-s tau) cos(wd tau - phi), extreme where wd tau - phi + asin(zeta) = n pi; the first two at
    # tau >= 0 are its largest of either sign.
    g0 = x2 - a[-1]
    gb = (x3 + s * g0) / wd
    r = sqrt(g0 * g0 + gb * gb)
    if r > 0.0:
        phi, beta = atan2(gb, g0), asin(zeta)
        n0 = ceil((beta - phi) / pi)
        for n in (n0, n0 + 1):
            tau = (n * pi - beta + phi) / wd
            peak = max(peak, abs(a[-1] + r * exp(-s * tau) * cos(n * pi - beta)))
    return peak


def _validate(t: np.ndarray, accel: np.ndarray, freqs: np.ndarray, damping: float) -> None:
    """Raise ValueError on inputs srs cannot process."""
    if t.ndim != 1 or accel.ndim != 1:
        raise ValueError(f"t and accel must be 1-D arrays, got shapes {t.shape} and {accel.shape}")
    if t.size != accel.size:
        raise ValueError(f"t and accel must have the same length, got {t.size} and {accel.size}")
    if t.size < 2:
        raise ValueError("need at least two samples")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(accel))):
        raise ValueError("t and accel must be finite (no NaN or inf)")
    if not np.all(np.diff(t) > 0):
        raise ValueError("t must be strictly increasing")
    if freqs.ndim != 1 or freqs.size == 0:
        raise ValueError(f"freqs_hz must be a non-empty 1-D array, got shape {freqs.shape}")
    if not (np.all(np.isfinite(freqs)) and np.all(freqs > 0)):
        raise ValueError("freqs_hz must be finite and > 0")
    if not (np.isfinite(damping) and 0.0 < damping < 1.0):
        raise ValueError(f"damping must be in (0, 1) (fraction of critical), got {damping}")
    need = SUBSTEPS_PER_PERIOD * (t[-1] - t[0]) * freqs.sum() + t.size * freqs.size  # bounds the sub-steps
    if need > MAX_SAMPLES:
        raise ValueError(f"record and frequencies need up to {need:.3g} oscillator steps, above MAX_SAMPLES = "
                         f"{MAX_SAMPLES}; shorten the record or lower the frequencies")


def srs(t: np.ndarray, accel: np.ndarray, freqs_hz: np.ndarray, damping: float = 0.05) -> np.ndarray:
    """Maximax absolute-acceleration SRS of the base acceleration history (t [s], accel [any unit]).

    Returns, for each natural frequency in ``freqs_hz`` [Hz], max over time of |x''| of a damped SDOF
    (damping = fraction of critical) on the base, in the unit of ``accel``: exact for the history linear
    between its samples, peaks as in the module docstring.
    """
    t = np.ascontiguousarray(t, dtype=float)
    accel = np.ascontiguousarray(accel, dtype=float)
    freqs = np.atleast_1d(np.asarray(freqs_hz, dtype=float))
    damping = float(damping)
    _validate(t, accel, freqs, damping)
    return np.array([_maximax(t, accel, 2.0 * pi * f, damping) for f in freqs])
