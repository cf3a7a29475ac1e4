"""`[requirements.envelope] vertical_speed_limit`: the sloped envelope (the largest descent speed a polyline in the
horizontal speed), its corners (the speed region's vertices), its Monte Carlo draws (uniform over the region) and
bad values, on variants of the shipped lunar example."""

import numpy as np
import pytest

import alightsize
from alightsize.common.errors import InputError
from alightsize.landings.dispersions import SpeedRegion

from conftest import ROOT

LUNAR = ROOT / "examples" / "lunar_lander.toml"
BOX = 'vertical_speed = ["1 m/s", "3 m/s"]\nhorizontal_speed = ["0 m/s", "1 m/s"]\n'
# The LM's shape on the lunar example's box: 3 m/s down at rest falling to 2 m/s down at 1 m/s across.
SLOPED = '[["0 m/s", "3 m/s"], ["1 m/s", "2 m/s"]]'


def variant(tmp_path, limit: str | None, extra: str = "", name: str = "lander.toml"):
    text = LUNAR.read_text()
    assert BOX in text
    line = "" if limit is None else f"vertical_speed_limit = {limit}\n"
    p = tmp_path / name
    p.write_text(text.replace(BOX, BOX + line + extra))
    return p


def _speeds(run) -> tuple[float, float]:
    """(horizontal, descent) speed of a run, m/s."""
    o = run.overrides
    return float(o["initial.velocity[1]"].split()[0]), -float(o["initial.velocity[2]"].split()[0])


def test_corners_are_the_polygons_vertices_times_the_other_corners(tmp_path):
    # The region 1 <= v <= 3 - h, 0 <= h <= 1 has 4 vertices; each is landed at every combination of the other
    # corner dimensions (2 rolls x 2 slopes x 2 frictions = 8), and a rock lands the two vertices on the limit
    # (3 m/s at rest, 2 m/s at 1 m/s) again. Exact: the vertices are the values written.
    rock = '\n[requirements.terrain]\nrock_height = "0.3 m"\n'
    text = variant(tmp_path, SLOPED).read_text().replace("[requirements.monte_carlo]",
                                                         rock + "\n[requirements.monte_carlo]")
    (tmp_path / "rock.toml").write_text(text)
    runs = alightsize.read_lander(tmp_path / "rock.toml").study.runs
    corners = [r for r in runs if r.run_id.startswith("corner-") and r.run_id.count("-") == 1]
    speeds = [_speeds(r) for r in corners]
    assert set(speeds) == {(0.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 3.0)}
    assert all(speeds.count(s) == 8 for s in set(speeds))
    others = {tuple(sorted((k, str(v)) for k, v in r.overrides.items() if "velocity" not in k)) for r in corners}
    assert len(others) == 8
    rocks = [r for r in runs if r.run_id.startswith("corner-rock-")]
    assert sorted(_speeds(r) for r in rocks) == sorted([(0.0, 3.0)] * 8 + [(1.0, 2.0)] * 8)


def test_every_monte_carlo_landing_lies_inside_the_polygon(tmp_path):
    # 100 draws of the lander file: 0 <= h <= 1, 1 <= v <= 3 - h (the limit's line), to the 1e-12 m/s of
    # round-off in the draw's arithmetic; none beyond the limit though the box reaches 3 m/s at 1 m/s.
    runs = alightsize.read_lander(variant(tmp_path, SLOPED)).study.runs
    mc = [_speeds(r) for r in runs if not r.run_id.startswith("corner-")]
    assert len(mc) == 100
    for h, v in mc:
        assert 0.0 <= h <= 1.0 and 1.0 <= v <= 3.0 - h + 1e-12


def test_draws_are_uniform_over_the_region():
    # Region 1 <= v <= 3 - h over 0 <= h <= 1 (a trapezoid, area 1.5): P(h < 0.5) = (2 + 1.5) / 2 * 0.5 / 1.5 =
    # 7/12, and below the limit the descent is uniform, so P(v - 1 < (2 - h) / 2) = 1/2. 20,000 seeded draws: the
    # tolerance is 4 binomial standard deviations (sqrt(p (1 - p) / n) <= 0.0036), so a wrong density fails.
    region = SpeedRegion("v", "h", ((0.0, 3.0), (1.0, 2.0)), 1.0)
    n = 20_000
    draws = [region.draws(np.random.default_rng([5, k])) for k in range(n)]
    h = np.array([float(d["h"].split()[0]) for d in draws])
    v = -np.array([float(d["v"].split()[0]) for d in draws])
    tol = 4 * np.sqrt(0.25 / n)
    assert abs(np.mean(h < 0.5) - 7 / 12) < tol
    assert abs(np.mean(v - 1 < (2 - h) / 2) - 0.5) < tol
    assert h.min() >= 0 and h.max() <= 1 and v.min() >= 1 and np.all(v <= 3 - h + 1e-12)


def test_a_region_clipped_by_the_high_draws_uniformly():
    # A limit above vertical_speed's high over part of the range is cut there: region 0 <= v <= min(4 - 2 h, 3)
    # over 0 <= h <= 1.5, upper edge (0, 3), (0.5, 3), (1.5, 1); area 0.5 * 3 + (3 + 1) / 2 * 1 = 3.5, so
    # P(h < 0.5) = 1.5 / 3.5 = 3/7. Tolerance as above (4 binomial standard deviations of 20,000 draws).
    region = SpeedRegion("v", "h", ((0.0, 3.0), (0.5, 3.0), (1.5, 1.0)), 0.0)
    n = 20_000
    h = np.array([float(region.draws(np.random.default_rng([9, k]))["h"].split()[0]) for k in range(n)])
    assert abs(np.mean(h < 0.5) - 3 / 7) < 4 * np.sqrt(0.25 / n)


def test_a_flat_limit_is_the_box_and_the_box_draws_as_uniform_speeds(tmp_path):
    # A limit at vertical_speed's high over the whole range is the box: the same runs, to the character. The box's
    # draws are numpy's uniform descent (-3 to -1 m/s) then uniform horizontal speed (0 to 1 m/s) from
    # default_rng([seed, k]), exactly, then the other dispersions from the same generator.
    box = alightsize.read_lander(variant(tmp_path, None, name="box.toml")).study.runs
    flat = alightsize.read_lander(variant(tmp_path, '[["0 m/s", "3 m/s"], ["2 m/s", "3 m/s"]]')).study.runs
    assert [(r.run_id, r.overrides) for r in flat] == [(r.run_id, r.overrides) for r in box]
    mc = [r for r in box if not r.run_id.startswith("corner-")]
    for k, r in enumerate(mc):
        rng = np.random.default_rng([20261124, k])
        assert r.overrides["initial.velocity[2]"] == f"{float(rng.uniform(-3.0, -1.0))!r} m/s"
        assert r.overrides["initial.velocity[1]"] == f"{float(rng.uniform(0.0, 1.0))!r} m/s"
        assert r.overrides["initial.heading"] == f"{float(rng.uniform(-180.0, 180.0))!r} deg"


def test_the_nominal_landing_is_the_regions_fastest_vertex(tmp_path):
    # The nominal scene lands the largest descent speed at its largest horizontal speed: (0, 3) m/s in the sloped
    # region, not the box's (1, 3) outside it.
    lander = alightsize.read_lander(variant(tmp_path, SLOPED))
    assert tuple(lander.scene.scene.v0) == (0.0, 0.0, -3.0)


@pytest.mark.parametrize("limit, key", [
    ('[["0 m/s", "3 m/s"]]', "vertical_speed_limit"),                               # one point
    ('[["0 m/s", "3 m/s"], ["0 m/s", "2 m/s"]]', "vertical_speed_limit[1]"),         # not ascending
    ('[["0.5 m/s", "3 m/s"], ["1 m/s", "2 m/s"]]', "vertical_speed_limit"),          # starts inside the range
    ('[["0 m/s", "3 m/s"], ["0.8 m/s", "2 m/s"]]', "vertical_speed_limit"),          # ends inside the range
    ('[["0 m/s", "3 m/s"], ["1 m/s", "-2 m/s"]]', "vertical_speed_limit[1]"),        # a negative speed
    ('[["0 m/s", "3 m/s"], ["1 m/s", "0.5 m/s"]]', "vertical_speed_limit"),          # below the low (1 m/s)
    ('[["0 m/s", "3 m/s"], ["1 m/s", "2 m"]]', "vertical_speed_limit[1][1]"),        # not a speed
    ('[["0 m/s", "3 m/s"], ["1 m/s"]]', "vertical_speed_limit[1]"),                  # not a pair
    ('"3 m/s"', "vertical_speed_limit"),                                             # not a polyline
])
def test_a_bad_limit_is_refused_at_its_key(tmp_path, limit, key):
    with pytest.raises(InputError) as e:
        alightsize.read_lander(variant(tmp_path, limit))
    assert f"requirements.envelope.{key}:" in str(e.value)


def test_a_trade_point_beyond_the_limits_span_is_refused_not_infeasible(tmp_path):
    # The lunar example trades horizontal speeds up to 4 kn (2.06 m/s): a limit spanning 0 to 1 m/s cannot
    # have that point, which must exit 2 naming the limit rather than search candidates that are all invalid;
    # 1 kn (0.51 m/s) is within the span and gives the range [0, 0.514...] m/s.
    from alightsize.synthesis.evaluate import Evaluator
    from alightsize.synthesis.search import _trade_context
    from alightsize.synthesis.spec import read_synthesis
    spec = read_synthesis(variant(tmp_path, SLOPED))
    ev = Evaluator(spec.path, spec.free, tmp_path / "out")
    assert _trade_context(ev, "horizontal_speed", 0.5144) == {
        "requirements.envelope.horizontal_speed": ["0.0 m/s", "0.5144 m/s"]}
    with pytest.raises(InputError) as e:
        _trade_context(ev, "horizontal_speed", 2.0578)
    assert "requirements.envelope.vertical_speed_limit:" in str(e.value)
    ev.close()
