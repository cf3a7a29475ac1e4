"""Sandwich plates (alightsize.checks.sandwich): a circular sandwich, edge simply supported, under a central load W
over a radius r0, read and evaluated as a design file's item. Closed forms: the moment is Roark's solid-plate
moment, the face stresses carry it as a couple, the core carries the shear force W / (2 pi r0) at the load circle,
and the weight is the faces' and the core's volumes."""

from dataclasses import replace
from math import log, pi

import pytest
from member_cases import IN, LBF, MATERIALS, PSI, item, step

from alightsize.checks import plates
from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.weights.methods import read_weight

CORE = "al-honeycomb-5052-3.1"


def _pad(d: float, face: float, core: float) -> dict:
    return {"shape": "sandwich", "diameter": f"{d!r} in", "face": f"{face!r} in", "core_depth": f"{core!r} in",
            "core_material": CORE}


def _check(kind: str, w: float = 10_000.0, r0: float = 4.0) -> dict:
    return {"kind": kind, "load": f"{w!r} lbf", "load_radius": f"{r0!r} in"}


# A 37 in pad (the LM's), faces 0.020 in on a 2 in core, 10,000 lbf over a 4 in radius; 7178-T6 faces, m = 3.33.
PAD = _pad(37.0, 0.020, 2.0)


def test_moment_is_roarks_solid_plate_moment():
    # M = W/(4 pi) [1 + (1 + nu) ln(a/r0) - (1 - nu) r0²/(4 a²)], by hand (nu = 1/3.33): 795.77 x 2.9832 = 2,374.0
    # lbf in/in;
    # the same as the solid plate's sigma t²/6 (Roark 1954 p. 194-195, plates.supported_center_load, validated in
    # test_plates.py) for any t: 1e-12, round-off of two arrangements of one formula.
    o = item(_check("sandwich_face_stress"), PAD).evaluate()[0]
    m = step(o, "M")
    nu = 1 / 3.33
    by_hand = 10_000 / (4 * pi) * (1 + (1 + nu) * log(18.5 / 4) - (1 - nu) * 16 / (4 * 18.5 ** 2))
    assert m / LBF == pytest.approx(by_hand, rel=1e-12)
    assert m / LBF == pytest.approx(2374.0, rel=5e-5)                     # the hand figure, to its 5 digits
    t = 0.3 * IN
    solid = plates.supported_center_load(10_000 * LBF, t, 18.5 * IN, 4 * IN, 3.33)[0] * t * t / 6
    assert m == pytest.approx(solid, rel=1e-12)


def test_face_stress_carries_the_moment_as_a_couple():
    # The outer-fibre stress sigma with the linear distribution sigma z / (d/2) over the faces (c/2 <= |z| <= d/2)
    # gives back M: integral of sigma(z) z dz = sigma (d³ - c³) / (6 d) = M (closed form, 1e-12). With thin faces
    # it is the couple M / (h tf), h = c + tf, times (1 + tf/h) / (1 + tf²/(3 h²)) exactly (here tf/h = 0.0099).
    o = item(_check("sandwich_face_stress"), PAD).evaluate()[0]
    m, sig = step(o, "M"), step(o, "σf")
    tf, c = 0.020 * IN, 2.0 * IN
    d, h = c + 2 * tf, c + tf
    assert sig * (d ** 3 - c ** 3) / (6 * d) == pytest.approx(m, rel=1e-12)
    assert sig / (m / (h * tf)) == pytest.approx((1 + tf / h) / (1 + tf * tf / (3 * h * h)), rel=1e-12)
    assert 1 < sig / (m / (h * tf)) < 1 + tf / h
    assert o.stress == pytest.approx(sig, rel=1e-15)                      # equal biaxial: Tresca = sigma
    assert o.allowable == pytest.approx(69_000 * PSI, rel=1e-12)


def test_core_shear_balances_the_load_at_the_load_circle():
    # tau (2 pi r0) h = W: the shear force per unit width W / (2 pi r0) on the core's depth between the face
    # centroids (Allen 1969 ch. 2); by hand 10,000 / (2 pi 4 x 2.02) = 196.97 psi against 130 psi (W direction).
    o = item(_check("sandwich_core_shear"), PAD).evaluate()[0]
    h = 2.02 * IN
    assert o.stress * 2 * pi * 4 * IN * h == pytest.approx(10_000 * LBF, rel=1e-12)
    assert o.stress / PSI == pytest.approx(196.97, rel=5e-5)
    assert o.allowable / PSI == pytest.approx(130, rel=1e-12)
    assert o.factor == pytest.approx(130 / (10_000 / (2 * pi * 4 * 2.02)), rel=1e-12)


def test_core_crushing_is_the_load_over_its_circle():
    # W / (pi r0²) = 10,000 / (16 pi) = 198.94 psi against the stabilised 300 psi (closed form, 1e-12).
    o = item(_check("sandwich_core_crushing"), PAD).evaluate()[0]
    assert o.stress / PSI == pytest.approx(10_000 / (16 * pi), rel=1e-12)
    assert o.factor == pytest.approx(300 / (10_000 / (16 * pi)), rel=1e-12)


def test_intracell_buckling_is_a_plate_of_the_cell_size():
    # 2 E/(1 - nu²) (tf/s)² is the plate buckling stress k pi² E/(12 (1 - nu²)) (t/s)² with k = 24/pi² = 2.43
    # (Timoshenko & Gere 1961 eq. 9-7 form; Hexcel TSB 124): 10e6 psi faces of 0.020 in on 1/8 in cells,
    # nu = 0.3003: 2 x 10e6 / 0.9098 x 0.0256 = 562,760 psi, far above the yield: the wrinkling line (0.5 (Ef Ec
    # Gc)^(1/3) = 0.5 (10e6 x 75e3 x 22e3)^(1/3) = 127,300 psi) is capped at Fcy and the loaded face judged there.
    o = item(_check("sandwich_face_buckling"), PAD).evaluate()[0]
    nu = 1 / 3.33
    assert step(o, "σic") / PSI == pytest.approx(2 * 10e6 / (1 - nu * nu) * (0.020 / 0.125) ** 2, rel=1e-12)
    assert step(o, "σwr") / PSI == pytest.approx(0.5 * (10e6 * 75e3 * 22e3) ** (1 / 3), rel=1e-12)
    assert step(o, "σwr") / PSI == pytest.approx(127_300, rel=1e-4)
    sig = step(o, "σf")
    # the governing of the two: intracell on sigma_r + sigma_t against min(sigma_ic, 2 Fcy) = 2 Fcy, wrinkling on
    # sigma against Fcy: the same factor Fcy / sigma, at which the face yields
    assert o.factor == pytest.approx(69_000 * PSI / sig, rel=1e-12)


def test_wrinkling_governs_on_a_soft_core():
    # A core 100 times softer (Ec 750 psi, Gc 220 psi): 0.5 (10e6 x 750 x 220)^(1/3) = 5,909 psi, below the yield,
    # is the allowable of the face's compressive stress (closed form, 1e-12).
    MATERIALS["soft"] = replace(MATERIALS[CORE], key="soft", elastic_modulus=750 * PSI, shear_modulus=220 * PSI)
    try:
        o = item(_check("sandwich_face_buckling"), {**PAD, "core_material": "soft"}).evaluate()[0]
    finally:
        del MATERIALS["soft"]
    wr = 0.5 * (10e6 * 750 * 220) ** (1 / 3)
    assert o.allowable / PSI == pytest.approx(wr, rel=1e-12)
    assert o.factor == pytest.approx(wr * PSI / step(o, "σf"), rel=1e-12)


def test_weight_is_two_faces_and_the_core():
    # pi/4 d² (2 rho_f tf + rho_c c): 37 in, 0.100 lb/in³ faces of 0.020 in, 3.1 lb/ft³ core 2 in deep:
    # 1075.2 in² x (0.004 + 0.003588) lb/in² = 8.159 lb (closed form, 1e-12).
    it = item(_check("sandwich_core_crushing"), PAD)
    w, _ = replace(it, weight=read_weight(Node("f.toml", "w", {"method": "sandwich"}), MATERIALS)).weight_each()
    lb = 0.45359237
    expected = pi / 4 * 37 ** 2 * (2 * 0.100 * 0.020 + 3.1 / 1728 * 2.0)
    assert w / lb == pytest.approx(expected, rel=1e-12)
    assert w / lb == pytest.approx(8.159, rel=1e-3)


@pytest.mark.parametrize("section, key", [(_pad(37.0, 0.5, 9.0), "section.core_depth"),
                                          (_pad(7.0, 0.02, 1.0), "load_radius")])
def test_outside_the_thin_plate_or_with_the_load_beyond_the_plate_is_refused(section, key):
    # depth 10 in > a/2 = 9.25 in; a load radius of 4 in on a 3.5 in plate.
    with pytest.raises(InputError) as e:
        item(_check("sandwich_face_stress"), section)
    assert e.value.key.endswith(key)


def test_a_core_without_the_property_a_check_needs_is_refused():
    # al-honeycomb (the crush core) has no shear strength: the check names the section's core_material.
    with pytest.raises(InputError) as e:
        item(_check("sandwich_core_shear"), {**PAD, "core_material": "al-honeycomb"})
    assert e.value.key.endswith("section.core_material")
