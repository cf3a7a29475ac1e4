"""Every non-plate check kind, on random finite inputs: either bad input (InputError) or a design factor that is
finite and positive whenever something is loaded, and infinite only when nothing is (a zero load)."""

from math import inf, isfinite

from hypothesis import given, settings
from hypothesis import strategies as st
from member_cases import item

from alightsize.common.errors import InputError

# Loads: zero, or of either sign from 1 mN to 10 MN. Lengths: 0.1 mm to 1 m, or any finite value from -1 m to
# 1 m (non-positive ones must be refused). Below 1 mN a factor allowable / stress can overflow a float (f ~
# 1e308), a limit of the number format, not of a formula.
FORCE = st.one_of(st.just(0.0), st.builds(lambda s, e: s * 10.0 ** e, st.sampled_from([-1.0, 1.0]),
                                          st.floats(-3, 7)))
LENGTH = st.one_of(st.floats(1e-4, 1.0), st.floats(-1.0, 1.0, allow_nan=False))
MATERIAL = st.sampled_from(["7178-t6", "be-31al", "4130-steel"])


def n(x: float) -> str:
    return f"{x!r} N"


def m(x: float) -> str:
    return f"{x!r} m"


@st.composite
def section(draw, shapes=("tube", "rod", "rectangle")):
    shape = draw(st.sampled_from(shapes))
    if shape == "tube":
        return {"shape": shape, "outside_diameter": m(draw(LENGTH)), "wall": m(draw(LENGTH))}
    if shape == "rod":
        return {"shape": shape, "diameter": m(draw(LENGTH))}
    return {"shape": shape, "width": m(draw(LENGTH)), "height": m(draw(LENGTH))}


@st.composite
def case(draw):
    """(check table, section table, the load values that decide whether anything is loaded)."""
    kind = draw(st.sampled_from(["compression", "tension", "bending", "combined", "column_buckling",
                                 "local_buckling", "bearing", "pin_shear", "pin_double_shear", "ring_bending",
                                 "cone_tension"]))
    p, mf = draw(FORCE), draw(FORCE)
    moment = {"moment_force": n(mf), "moment_arm": m(draw(LENGTH))}
    comps = draw(st.lists(FORCE, min_size=1, max_size=3))
    tables = {
        "compression": ({"load": n(p)}, [p]),
        "tension": ({"load": n(p)}, [p]),
        "bending": (moment, [mf]),
        "combined": ({"load": n(p), **moment}, [p, mf]),
        "column_buckling": ({"load": n(p), "length": m(draw(LENGTH)),
                             "formula": draw(st.sampled_from(["euler", "johnson_euler"]))}, [p]),
        "local_buckling": ({"load": n(p), "formula": draw(st.sampled_from(["app_iv", "sp8007"])),
                            **draw(st.sampled_from([{}, moment])),
                            **draw(st.sampled_from([{}, {"wall": m(draw(LENGTH))}]))},
                           [p, mf]),
        "bearing": ({"loads": [n(c) for c in comps], "bearing_length": m(draw(LENGTH)),
                     "combine": draw(st.sampled_from(["resultant", "sum"]))}, comps),
        "pin_shear": ({"loads": [n(c) for c in comps], "allowable_load": n(abs(draw(FORCE)))}, comps),
        "pin_double_shear": ({"loads": [n(c) for c in comps], "planes": draw(st.integers(1, 4))}, comps),
        "ring_bending": ({"load": n(p), "span": m(draw(LENGTH))}, [p]),
        "cone_tension": ({"load": n(p), "thickness": m(draw(LENGTH))}, [p]),
    }
    table, loads = tables[kind]
    if kind == "local_buckling" and "moment_force" not in table:
        loads = [p]
    shapes = ("tube",) if kind in ("column_buckling", "local_buckling") else (
        ("rod",) if kind in ("bearing", "pin_double_shear") else ("tube", "rod", "rectangle"))
    return {"kind": kind, **table}, draw(section(shapes)), loads


@settings(max_examples=400, deadline=None)
@given(case(), MATERIAL, st.sampled_from(["current", "app_iv"]))
def test_factor_is_finite_and_positive_when_loaded_or_the_input_is_refused(c, material, rules):
    check, sec, loads = c
    try:
        outcome = item(check, sec, material, rules).evaluate()[0]
    except InputError:
        return
    if any(x != 0 for x in loads):
        assert isfinite(outcome.factor) and outcome.factor > 0, (check, sec, outcome)
    else:
        assert outcome.factor == inf, (check, sec, outcome)
