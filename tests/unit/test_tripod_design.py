"""`alightsize design` of a tripod lander (examples/lunar_tripod.toml, its envelope narrowed to a few landings):
the members derived from the geometry take the strut-load extremes of the stored landings, the legs' hardpoint
forces balance the footpad force along a real landing, weight follows the geometry, and a cantilever designs."""

import json
from dataclasses import replace
from math import pi

import numpy as np
import pytest
from conftest import ROOT

from alightsize.loads.histories import TRIPOD_FORCES, tripod_member_histories
from alightsize.model.scene_config import read_scene
from alightsize.pipeline.design import FOOTPAD_MASS_TOLERANCE, DesignResult, run_design
from alightsize.pipeline.lander import read_lander
from alightsize.pipeline.tripod_members import SANDWICH_CHECKS, TripodLoads, landing_extremes, tripod_references
from alightsize_sim.landing import simulate

EXAMPLE = ROOT / "examples" / "lunar_tripod.toml"
# the envelope's fastest, widest corner, level and at one friction: 2 corners (a leg leading, two straddling)
# and 2 Monte Carlo landings over that point
SMALL = {"requirements.envelope.vertical_speed": "3 m/s", "requirements.envelope.horizontal_speed": "1 m/s",
         "requirements.envelope.slope": "0 deg", "requirements.envelope.friction": [0.7, 0.7],
         "requirements.monte_carlo.samples": 2}
# a load's trip through its item table: repr -> unit parser, exact but for the parser's one multiplication
PARSE = 1e-12


def _design(tmp_path, overrides=None, path=EXAMPLE, size=True):
    spec = read_lander(path, {**SMALL, **(overrides or {})}).spec
    return run_design(spec, tmp_path / "landings", size=size)


def _stored(rows) -> dict[str, float]:
    """Each strut's largest compression and tension and each magnitude's largest value over the stored rows."""
    out: dict[str, float] = {}
    for r in rows:
        for d in json.loads(r["member_loads_json"]):
            m = d["member"]
            pairs = ([(m, d["largest"])] if "largest" in d else
                     [(f"{m} tension", d["tension_N"]), (f"{m} compression", -(d["compression_N"] or 0.0))])
            for k, v in pairs:
                out[k] = max(out.get(k, 0.0), v or 0.0)
    return out


def _check(res, item: str, kind: str) -> dict | None:
    """The SI parameters of an item's check (None: no such check): P (or W, a plate's) its load N, M its moment
    N m."""
    it = next(i for i in res.config.items if i.name == item)
    return next((c.params for c in it.checks if c.kind == kind), None)


def _load(params: dict) -> float:
    return params["P"] if "P" in params else params["W"]


@pytest.fixture(scope="module")
def inverted(tmp_path_factory):
    return _design(tmp_path_factory.mktemp("inverted"))


def test_member_loads_are_the_strut_extremes_of_the_stored_landings(inverted):
    # The checks' loads are the extremes over every stored landing's strut forces (recomputed here from the rows),
    # to the float's round trip through the item table (PARSE); a sense never loaded has no check.
    res = inverted
    s = _stored(res.config.landings.rows)
    assert s["primary compression"] > 0 and s["footpad"] > 0
    expected = {("primary_strut", "compression"): s["primary compression"],
                ("primary_strut", "column_buckling"): s["primary compression"],
                **{("footpad", kind): s["footpad"] for kind in SANDWICH_CHECKS}}
    for i in (1, 2):
        c, t = s[f"secondary{i} compression"], s[f"secondary{i} tension"]
        expected |= {(f"secondary_strut_{i}", "compression"): c, (f"secondary_strut_{i}", "column_buckling"): c,
                     (f"secondary_strut_{i}", "tension"): t}
    for (item, kind), value in expected.items():
        params = _check(res, item, kind)
        if value > 0:
            assert params is not None and _load(params) == pytest.approx(value, rel=PARSE), (item, kind)
        else:
            assert params is None, (item, kind)


def test_stored_extremes_and_hardpoints_of_a_landing_balance(inverted):
    # One stored landing flown again: its stored extremes are those of the strut forces along its history, and at
    # every step each leg's three hardpoint forces sum to the force the leg carries (the massless leg's
    # equilibrium, Hibbeler, Statics, sec. 6.5): 1e-9 of the largest force, round-off of 3x3 solves.
    land = inverted.config.landings
    run, row = land.study.runs[0], land.rows[0]
    cfg = read_scene(run.scene, run.overrides)
    res = simulate(cfg.scene, cfg.controls)
    h = tripod_member_histories(res, cfg.scene.legs)
    scale = np.nanmax(np.abs(res.leg_force))
    on = res.contact
    np.testing.assert_allclose(h.hardpoints.sum(axis=2)[on], res.leg_force[on], rtol=0, atol=1e-9 * scale)
    stored = {d["member"]: d for d in json.loads(row["member_loads_json"])}
    for m in TRIPOD_FORCES:
        f = h.forces[m]
        lo, hi = np.nanmin(f), np.nanmax(f)
        assert (stored[m]["compression_N"] or 0.0) == pytest.approx(min(lo, 0.0), rel=1e-12, abs=1e-9)
        assert (stored[m]["tension_N"] or 0.0) == pytest.approx(max(hi, 0.0), rel=1e-12, abs=1e-9)
    assert stored["footpad"]["largest"] == pytest.approx(np.nanmax(np.linalg.norm(
        np.where(on[..., None], res.leg_force, np.nan), axis=-1)), rel=1e-12)


def test_weight_follows_the_footpad_radius(tmp_path):
    # At the sections as written (sizing off: the loads change with the stance too), each strut weighs rho A L
    # (a tube, App. V) over its length from the hardpoints to the footpad, so a wider stance weighs more and each
    # strut's weight scales as its length: 1e-12, round-off.
    def weights(radius):
        res = _design(tmp_path / radius, {"legs.footpad_radius": radius}, size=False)
        leg = res.config.landings.scenes[0].scene.legs[0]
        each = {w.label: w.each for w in res.weights}
        return res.per_leg, each, leg.rest_lengths
    w1, e1, l1 = weights("2.2 m")
    w2, e2, l2 = weights("2.8 m")
    assert w2 > w1
    for name, i in (("primary_strut", 0), ("secondary_strut_1", 1), ("secondary_strut_2", 2)):
        assert e2[name] / e1[name] == pytest.approx(l2[i] / l1[i], rel=1e-12)
        assert l2[i] > l1[i]


def test_a_cantilever_designs_with_combined_checks_on_its_primary(tmp_path):
    # The secondaries meet the primary 0.8 m up from the footpad (above the primary's 0.61 m of stroke): the
    # primary's two parts carry the largest stored knee moment with their axial force (combined), the
    # largest knee moment being > 0 (the knee carries bending) and the loads those of the stored landings.
    text = EXAMPLE.read_text().replace('secondary_attach = "0 m"', 'secondary_attach = "0.8 m"')
    text = text.replace("[members.primary_strut]", "[members.primary_lower]\nmaterial = \"7178-t6\"\n"
                        "section = { shape = \"tube\", outside_diameter = \"80 mm\", wall = \"1.5 mm\" }\n"
                        "size = { dimension = \"wall\", min = \"0.5 mm\", max = \"8 mm\" }\n\n[members.primary_upper]")
    path = tmp_path / "cantilever.toml"
    path.write_text(text)
    res = _design(tmp_path, path=path)
    s = _stored(res.config.landings.rows)
    assert s["knee_moment"] > 0
    upper, lower = _check(res, "primary_upper", "combined"), _check(res, "primary_lower", "combined")
    assert upper["M"] == pytest.approx(s["knee_moment"], rel=PARSE)
    assert lower["M"] == pytest.approx(s["knee_moment"], rel=PARSE)
    assert upper["P"] == pytest.approx(max(s["primary_upper compression"], s["primary_upper tension"]), rel=PARSE)
    assert lower["P"] == pytest.approx(s["primary compression"], rel=PARSE)
    assert {r.item.name for r in res.records} >= {"primary_upper", "primary_lower"}


def test_every_cell_a_leg_can_have_names_its_bottomed_class():
    # A landing that bottoms is classed by its cell's name (`outcome_class`): every cell name a scene builds
    # (telescoping, articulated, tripod) must map to a class with a symbol and a meaning in the sweep's tables.
    from alightsize.landings.outcomes import MEANING, SYMBOL
    from alightsize.landings.study import BOTTOMED_KIND
    from alightsize.model.scene_config import TRIPOD_CELLS
    for cell in (*TRIPOD_CELLS, "axial", "rot1", "upper", "lower"):
        kinds = [v for k, v in BOTTOMED_KIND.items() if cell.startswith(k)]
        assert len(kinds) == 1, cell
        assert f"bottomed_{kinds[0]}" in SYMBOL and f"bottomed_{kinds[0]}" in MEANING


def test_the_sized_footpad_is_the_simulated_footpad_mass_or_the_design_fails(inverted):
    # The sized sandwich footpad weighs pi/4 d² (2 rho_f t_f + rho_c c) (1 + allowance) (closed form, 1e-12), and
    # the design holds only while that is at most [legs] footpad_mass x (1 + 5 %): at the limit it passes, 1e-9
    # below it fails, the verdict naming the mass to write.
    res = inverted
    pad = next(i for i in res.items if i.name == "footpad")
    dims, core = pad.section.dims, pad.section.core
    expected = pi / 4 * dims["diameter"] ** 2 * (2 * pad.material.density * dims["face"]
                                                 + core.density * dims["core_depth"]) * 1.25
    assert res.footpad_sized == pytest.approx(expected, rel=1e-12)
    assert res.config.footpad_mass == pytest.approx(2.1, rel=1e-12)          # examples/lunar_tripod.toml
    limit = res.footpad_sized / (1 + FOOTPAD_MASS_TOLERANCE)

    def with_mass(mass):
        return DesignResult(replace(res.config, footpad_mass=mass), res.items, res.records, res.sizings, res.weights)

    assert with_mass(limit).footpad_ok
    light = with_mass(limit * (1 - 1e-9))
    assert not light.footpad_ok and not light.ok
    assert f'write footpad_mass = "{res.footpad_sized:.4g} kg"' in light.verdict()
    assert light.verdict().startswith("FAIL")


def test_a_lander_without_a_footpad_member_has_no_footpad_mass_to_match(tmp_path):
    # Without [members.footpad] nothing sized stands for the simulated footpad: no comparison, no verdict part.
    text = EXAMPLE.read_text()
    start = text.index("\n[members.footpad]")
    text = text[:start] + "\n" + text[text.index("[members.primary_core]"):]
    path = tmp_path / "no_pad.toml"
    path.write_text(text)
    spec = read_lander(path, SMALL).spec
    assert spec.footpad_mass is None



def test_massless_held_footpads_have_no_footpad_mass_to_match():
    # Footpads that cannot slip (friction 1,000) may be massless: nothing moves them, so no mass to match.
    spec = read_lander(EXAMPLE, {**SMALL, "requirements.envelope.friction": [1000, 1000], "legs.footpad_mass": "0 kg"}
                       ).spec
    assert spec.footpad_mass is None


def test_each_tripod_load_names_the_landing_that_set_it(inverted):
    # With no landing named anywhere, every tripod load is the largest over every landing (the envelope of all
    # of them, recomputed here from the rows); the load_references table gives each with the landing it came from,
    # whose own stored extreme is that value (exactly: the same float), and the check loads are those values.
    res = inverted
    rows = res.config.landings.rows
    s = _stored(rows)
    refs = res.to_pandas()["load_references"]
    tripod = refs[refs["envelope"] == "landings"]
    assert len(tripod) > 0 and set(tripod["governs"]) == {"landing"}
    for r in tripod.to_dict("records"):
        key = r["member"] if r["sense"] == "largest" else f"{r['member']} {r['sense']}"
        assert r["value_N"] == s[key]
        run = r["configuration"].removeprefix("landing ")
        own = _stored([x for x in rows if x["run_id"] == run])
        assert own[key] == r["value_N"]
    footpad = tripod[(tripod["member"] == "footpad")]["value_N"].item()
    assert _check(res, "footpad", "sandwich_core_shear")["W"] == pytest.approx(footpad, rel=PARSE)


def test_round_off_is_not_a_load_in_that_sense():
    # A strut that only ever compresses can read +1e-13 N of "tension" from the statics solve's round-off (about
    # 1e-16 of the 1e4 N forces here): no tension load, reference or check for it; a tension of 1e-6 of the largest
    # strut force (far above round-off) is kept. The floor is ROUNDOFF = 1e-9 of the largest strut force.
    def row(run, tension):
        loads = [{"member": "secondary1", "tension_N": tension, "compression_N": -2.0e4},
                 {"member": "primary", "tension_N": None, "compression_N": -3.0e4},
                 {"member": "footpad", "largest": 3.1e4, "unit": "N", "at": None}]
        return {"run_id": run, "member_loads_json": json.dumps(loads)}
    rows = [row("a", 1e-13), row("b", 2e-13)]
    assert ("secondary1", "tension") not in landing_extremes(rows)
    loads = TripodLoads.from_landings(rows)
    assert loads.secondary_tension == (0.0, 0.0) and loads.secondary_compression == (2.0e4, 0.0)
    assert {r.key for r in tripod_references(rows)} == {"secondary1 compression", "primary compression",
                                                        "footpad largest"}
    kept = landing_extremes([row("a", 1e-13), row("c", 0.03)])
    assert kept[("secondary1", "tension")] == (0.03, "c")
