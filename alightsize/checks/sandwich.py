"""Circular sandwich plates (two isotropic faces of thickness tf on a core of depth c, radius a), edge simply
supported, the load W over a central circle of radius r0: the moment, the face stress, the core's shear and
crushing and the faces' local buckling.

SI throughout; m = 1/nu of the faces. Each function states its range; alightsize.checks.kinds keeps the checks
inside it. The moment is the solid plate's (Roark 1954 p. 194-195): it does not depend on the plate's bending
stiffness, only on the faces' Poisson ratio (isotropic faces, the core without in-plane stiffness), and in
axisymmetric bending not on the transverse shear stiffness either: with Q_r = W / (2 pi r) fixed by equilibrium, the
Reissner-Mindlin rotation obeys Kirchhoff's equation and edge conditions (simply supported or clamped), so the
moments are Kirchhoff's whatever the core's shear modulus (Wang, Reddy & Lee 2000, axisymmetric bending of
circular plates).
"""

from __future__ import annotations

from math import log, pi


def centre_moment(w: float, a: float, r0: float, m: float) -> float:
    """Radial (= tangential) bending moment per unit width at the centre, N m / m:
    M = W / (4 pi) [1 + (1 + nu) ln(a / r0) - (1 - nu) r0² / (4 a²)], nu = 1/m (Roark 1954 p. 194-195: its
    sigma = 6 M / t²). Thin plate, 0 < r0 <= a."""
    nu = 1 / m
    return w / (4 * pi) * (1 + (1 + nu) * log(a / r0) - (1 - nu) * r0 * r0 / (4 * a * a))


def face_stress(moment: float, tf: float, c: float) -> float:
    """Outer-fibre face stress of a sandwich under a bending moment per unit width M, the core carrying no bending
    stress: sigma = 6 M d / (d³ - c³), d = c + 2 tf (Allen 1969 ch. 2, plane sections, the faces' own bending
    included). It exceeds the couple M / (h tf), h = c + tf, by the factor (1 + tf/h) / (1 + tf²/(3 h²)), at most
    tf/h. tf, c > 0."""
    d = c + 2 * tf
    return 6 * moment * d / (d ** 3 - c ** 3)


def core_shear(w: float, r0: float, tf: float, c: float) -> float:
    """Core shear stress at the load circle's edge, where the shear force per unit width is greatest:
    Q = W / (2 pi r0) (equilibrium), tau = Q / h, h = c + tf the distance between the faces' centroids (Allen 1969
    ch. 2: the core carries the whole shear, uniform through its depth; exact in the limit of thin faces, tf << c).
    r0 > 0."""
    return w / (2 * pi * r0) / (c + tf)


def core_bearing(w: float, r0: float) -> float:
    """Core compression under the load circle, the face spreading none of it: sigma = W / (pi r0²) (conservative:
    the loaded face spreads the load over a larger circle). r0 > 0."""
    return w / (pi * r0 * r0)


def intracell_buckling(e: float, nu: float, tf: float, s: float) -> float:
    """Face dimpling into the honeycomb's cells: sigma_cr = 2 E / (1 - nu²) (tf / s)², s the cell size (the
    inscribed circle's diameter), uniaxial compression (Hexcel 2000 TSB 124 'HexWeb Honeycomb Sandwich Design
    Technology' p. 5; NASA CR-1457 1969). Elastic: it holds below the face's proportional limit."""
    return 2 * e / (1 - nu * nu) * (tf / s) ** 2


def wrinkling(e_face: float, e_core: float, g_core: float) -> float:
    """Face wrinkling on the core: sigma_cr = 0.5 (Ef Ec Gc)^(1/3), Ec the core's flatwise compressive modulus, Gc
    its (weaker) transverse shear modulus, uniaxial compression (Hexcel 2000 TSB 124 p. 5; Allen 1969 ch. 8, the
    thick-core formula with the empirical 0.5 for initial waviness). A core deep against the wrinkle's half-wave
    (antisymmetric and symmetric modes alike); elastic, below the face's proportional limit."""
    return 0.5 * (e_face * e_core * g_core) ** (1 / 3)
