"""Articulated-leg footpad kinematics: forward/inverse round trip, alpha = 0 convention, root crossing."""

import numpy as np
import pytest

from alightsize.loads.config import read_loads
from conftest import EXAMPLES
from alightsize_sim.articulated_kinematics import (ArticulatedGeometry, Unreachable, footpad, inverse, nearest_root,
                                                   residual)

IN = 0.0254
# The reference geometry (AU 44 in, AL 25 in, AS 8 in printed; AO, AE fitted, docs/articulated-geometry.md)
# and a second one with larger offsets: the identities tested here hold for any geometry.
G = read_loads(EXAMPLES / "loads" / "articulated.toml").cases[0].geometry
G_OFFSET = ArticulatedGeometry(AU=44 * IN, AO=10 * IN, AS=8 * IN, AL=25 * IN, AE=4 * IN)
A_MAX = np.radians(45)


@pytest.mark.parametrize("G", [G, G_OFFSET], ids=["reference", "offset"])
def test_round_trip_over_the_reachable_range(G):
    rng = np.random.default_rng(1)
    n = 2000
    alpha = rng.uniform(1e-3, A_MAX, n)
    beta = rng.uniform(-np.pi, np.pi, n)
    psi = rng.uniform(np.radians(-30), np.radians(30), n)
    s = np.array(footpad(G, alpha, beta, psi))
    worst = 0.0
    for k in range(n):
        a, b, p = inverse(G, s[:, k], A_MAX, alpha_prev=alpha[k])
        db = (b - beta[k] + np.pi) % (2 * np.pi) - np.pi
        worst = max(worst, abs(a - alpha[k]), abs(db), abs(p - psi[k]))
    # Issue 3: within 1e-10 rad (brentq to 1e-15 in alpha; beta, psi from closed forms).
    assert worst < 1e-10


@pytest.mark.parametrize("psi_deg", [-30.0, 0.0, 30.0])
def test_alpha_zero_gives_defined_beta(psi_deg):
    psi = np.radians(psi_deg)
    s = footpad(G, 0.0, 1.234, psi)         # beta has no effect at alpha = 0
    a, b, p = inverse(G, s, A_MAX, beta_prev=0.7)
    assert a == pytest.approx(0.0, abs=1e-10) and p == pytest.approx(psi, abs=1e-10)
    assert b == 0.7 and not np.isnan(b)


def test_residual_vanishes_at_the_true_alpha():
    s = footpad(G, 0.3, 0.5, 0.1)
    assert abs(residual(G, s, 0.3)) < 1e-15


def test_unreachable_point_is_an_error_not_nan():
    with pytest.raises(Unreachable):
        inverse(G, (10.0, 0.0, -10.0), A_MAX)


def _crossing(g, alpha, beta, psi):
    """Signed gap between sin(alpha) and the nearest other root of the eq. 41 quartic in [0, 1] (NaN if
    none): a sign change along a path is a crossing of the true root by an extraneous one."""
    from alightsize_sim.articulated_kinematics import quartic
    r = np.roots(quartic(g, footpad(g, alpha, beta, psi)))
    r = r[np.abs(r.imag) < 1e-9].real
    true = np.argmin(np.abs(r - np.sin(alpha)))
    others = np.delete(r, true)
    others = others[(others >= 0) & (others <= 1)]
    if len(others) == 0:
        return np.nan
    return (others - np.sin(alpha))[np.argmin(np.abs(others - np.sin(alpha)))]


def test_inverse_follows_the_true_root_through_a_quartic_root_crossing():
    g = G
    rng = np.random.default_rng(7)
    alphas = np.radians(np.linspace(0.5, 45, 400))
    for _ in range(200):                       # find a straight path in alpha that crosses (seeded)
        beta, psi = rng.uniform(-np.pi, np.pi), rng.uniform(np.radians(-30), np.radians(30))
        gap = np.array([_crossing(g, a, beta, psi) for a in alphas])
        ok = np.isfinite(gap[:-1]) & np.isfinite(gap[1:]) & (gap[:-1] * gap[1:] < 0)
        if ok.any():
            break
    else:
        pytest.fail("no path with a quartic root crossing found")
    worst, prev, prev_sim = 0.0, None, 0.0
    for a in alphas:                           # drive the inverse along the path, through the crossing
        s = footpad(g, a, beta, psi)
        a2, b2, p2 = inverse(g, s, A_MAX, alpha_prev=prev)
        prev_sim = nearest_root(g, *s, prev_sim)   # the simulator's root tracking (no psi range, no scan)
        worst = max(worst, abs(a2 - a), abs((b2 - beta + np.pi) % (2 * np.pi) - np.pi), abs(p2 - psi),
                    abs(prev_sim - a))
        prev = a2
    assert worst < 1e-10
