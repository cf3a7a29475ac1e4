"""Input a new user gets wrong: printed section properties left from other dimensions, sizing a dimension a
check overrides. Warnings name file and key path; errors exit 2 with file, key, expected and found."""

import contextlib
import io
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

from alightsize.common.config import Node
from alightsize.pipeline.config import read_design
from alightsize.common.errors import InputWarning
from alightsize.model.sections import read_section
from conftest import CONFIGS, EXAMPLES, ROOT

SIZED = ROOT / "examples" / "sizing" / "articulated_3457_sized.toml"


def run(*args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "alightsize", *map(str, args)], capture_output=True, text=True,
                          cwd=ROOT)


def cli(*args) -> subprocess.CompletedProcess:
    """`run` in this process (the command line's main, without starting Python again): exit status and stderr."""
    from alightsize.cli import main
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = main([str(a) for a in args])
    return subprocess.CompletedProcess(args, code, "", err.getvalue())


def _stale_telescoping(tmp_path: Path) -> Path:
    """The telescoping leg with the Lower Leg Tube's wall edited from 0.050 to 0.065 in, its printed I kept."""
    text = (EXAMPLES / "telescoping.toml").read_text()
    old = 'wall = "0.050 in", inertia = "0.478 in^4"'
    assert text.count(old) == 1
    cfg = tmp_path / "stale.toml"
    cfg.write_text(text.replace(old, 'wall = "0.065 in", inertia = "0.478 in^4"'))
    return cfg


def test_printed_inertia_left_from_an_older_wall_warns_on_the_command_line(tmp_path):
    # I = pi r^3 t on the mean radius: pi (1.4675 in)^3 0.065 in = 0.6454 in^4; 0.478 is 25.9 % below it.
    cfg = _stale_telescoping(tmp_path)
    r = run("design", cfg, "--out", tmp_path / "out")
    assert r.returncode in (0, 1), r.stderr          # a warning, not an error: the printed value is used
    lines = [ln for ln in r.stderr.splitlines() if ln.startswith("alightsize: warning: ")]
    assert len(lines) == 1, r.stderr
    assert f'{cfg}: item["Lower Leg Tube"].section.inertia: ' in lines[0]
    assert "0.478 in^4" in lines[0] and "0.6454 in^4" in lines[0] and "-25.9 %" in lines[0]
    assert "Traceback" not in r.stderr and "InputWarning" not in r.stderr


def test_printed_inertia_left_from_an_older_wall_is_a_python_warning(tmp_path):
    cfg = _stale_telescoping(tmp_path)
    with pytest.warns(InputWarning) as caught:
        read_design(cfg)
    assert [(w.message.file, w.message.key) for w in caught] == [(str(cfg), 'item["Lower Leg Tube"].section.inertia')]


@pytest.mark.parametrize("printed, warns", [("0.72 in^4", False), ("0.75 in^4", True)])
def test_override_tolerance_is_ten_percent(printed, warns):
    # rectangle 1 x 2 in: I = b h^3 / 12 = 0.6667 in^4; 0.72 is +8.0 %, 0.75 is +12.5 %
    node = Node("f.toml", "item[0].section", {"shape": "rectangle", "width": "1 in", "height": "2 in",
                                              "inertia": printed})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        read_section(node)
    assert [str(w.message) for w in caught if w.category is InputWarning] == (
        [f"f.toml: item[0].section.inertia: printed {printed} but the section's dimensions give 0.6667 in^4 "
         "(+12.5 %, beyond the 10% tolerance); the printed value is used: is it left over from other dimensions?"]
        if warns else [])


@pytest.mark.parametrize("config", [EXAMPLES / f"{c}.toml" for c in CONFIGS] + [SIZED], ids=lambda p: p.stem)
def test_shipped_printed_properties_are_within_the_tolerance(config):
    # measured: telescoping I -5.17 % and c -1.61 %, configuration 9 post A +0.44 %, I -4.59 %, c -0.18 %
    with warnings.catch_warnings():
        warnings.simplefilter("error", InputWarning)
        read_design(config)


def test_sizing_a_wall_that_a_check_overrides_exits_2(tmp_path):
    # Parallelogram Post is sized by its wall; a local_buckling `wall` would stay 0.083 in whatever the size.
    text = SIZED.read_text()
    old = 'kind = "local_buckling"\n'
    assert text.count(old) == 1
    cfg = tmp_path / "sized.toml"
    cfg.write_text(text.replace(old, old + '  wall = "0.083 in"\n'))
    r = cli("design", cfg, "--out", tmp_path / "out")
    assert r.returncode == 2, r.stderr
    assert "Traceback" not in r.stderr
    assert f'{cfg}: item["Parallelogram Post"].size.dimension: expected a dimension no check gives its own ' \
           'value for (item["Parallelogram Post"].check["local_buckling"].wall would keep its value while the ' \
           'wall is sized' in r.stderr
    assert r.stderr.rstrip().endswith("found 'wall'")
    assert not (tmp_path / "out").exists()


_ITEM = '''[design]
configuration = "x"

[[item]]
name = "Strut"
material = "7178-t6"
section = {section}
{size}
  [[item.check]]
  kind = "{kind}"
  {params}
'''
_TUBE_CHECKS = dict(kind="column_buckling", params='load = "1000 lbf"\n  length = "10 in"', size="")


@pytest.mark.parametrize("fields, key, expected, found", [
    # wall past the radius: with a printed I, sqrt(I / A) of a negative A was "math domain error"
    (dict(_TUBE_CHECKS, section='{ shape = "tube", outside_diameter = "1 in", wall = "0.6 in", inertia = "0.1 in^4" }'),
     "section.wall", "a wall less than half the outside diameter", "outside_diameter 1 in, wall 0.6 in"),
    (dict(_TUBE_CHECKS, section='{ shape = "tube", outside_diameter = "1 in", wall = "0.5 in" }'),
     "section.wall", "a wall less than half the outside diameter", "outside_diameter 1 in, wall 0.5 in"),
    (dict(kind="plate_annular_inner_supported_uniform_pressure", params='pressure = "100 psi"', size="",
          section='{ shape = "plate", diameter = "3.14 in", inner_diameter = "3.14 in", thickness = "0.88 in" }'),
     "section.inner_diameter", "an inner diameter less than the diameter", "inner_diameter 3.14 in"),
    (dict(_TUBE_CHECKS, section='{ shape = "tube", outside_diameter = "1 in", wall = "0.1 in" }',
          size='size = { dimension = "wall", min = "0.01 in", max = "0.6 in" }'),
     "size.max", "sizes that keep a real section: a wall less than half the outside diameter",
     "wall 0.6 in with outside_diameter 1 in"),
    (dict(_TUBE_CHECKS, section='{ shape = "tube", outside_diameter = "1 in", wall = "0.1 in" }',
          size='size = { dimension = "outside_diameter", gauges = ["0.5 in", "0.2 in", "1 in"] }'),
     "size.gauges", "a wall less than half the outside diameter", "outside_diameter 0.2 in with wall 0.1 in"),
    # a check's own wall or plate radii past the section: ran silently (f = 153.9 for a 2 in wall on a 3 in tube)
    (dict(kind="local_buckling", params='load = "1000 lbf"\n  wall = "0.6 in"', size="",
          section='{ shape = "tube", outside_diameter = "1 in", wall = "0.1 in" }'),
     'check["local_buckling"].wall', "a wall below the tube's outside radius 0.5000 in", "0.6000 in"),
    (dict(kind="plate_fixed_center_load", params='load = "1000 lbf"\n  load_radius = "2 in"', size="",
          section='{ shape = "plate", diameter = "3 in", thickness = "0.4 in" }'),
     'check["plate_fixed_center_load"].load_radius', "a load radius at most the plate radius 1.500 in", "2.000 in"),
    (dict(kind="plate_annular_inner_supported_uniform_pressure",
          params='pressure = "100 psi"\n  inner_radius = "1.6 in"', size="",
          section='{ shape = "plate", diameter = "3 in", thickness = "0.4 in" }'),
     'check["plate_annular_inner_supported_uniform_pressure"].inner_radius', "an inner radius below the plate radius",
     "1.600 in"),
    (dict(kind="tension", params='load = "1000 lbf"', size="", section='{ shape = "rod", diameter = "0 in" }'),
     "section.diameter", "a positive length", "'0 in'"),
    (dict(kind="bending", params='moment = "100 lbf*in"', size="",
          section='{ shape = "rectangle", width = "1 in", height = "-2 in" }'),
     "section.height", "a positive length", "'-2 in'"),
])
def test_impossible_section_exits_2_naming_key_expected_found(tmp_path, fields, key, expected, found):
    cfg = tmp_path / "bad.toml"
    cfg.write_text(_ITEM.format(**fields))
    r = cli("design", cfg, "--out", tmp_path / "out")
    assert r.returncode == 2, r.stderr
    assert "Traceback" not in r.stderr and "math domain error" not in r.stderr
    message = r.stderr.strip()
    assert message.startswith(f'alightsize: error: {cfg}: item["Strut"].{key}: expected ') and "\n" not in message
    assert expected in message and found in message.split(", found ", 1)[1]


SCENES = EXAMPLES / "scenes"


@pytest.mark.parametrize("v3", ["2 m/s", "0.1 ft/s"])
def test_upward_initial_velocity_warns_and_is_kept(v3):
    from alightsize.model.scene_config import read_scene
    scene = SCENES / "flat_drop.toml"
    with pytest.warns(InputWarning) as caught:
        cfg = read_scene(scene, {"initial.velocity[2]": v3})
    assert [(w.message.file, w.message.key) for w in caught] == [(str(scene), "initial.velocity[2]")]
    assert f"an upward initial velocity, V3 = {v3} " in str(caught[0].message)
    assert cfg.scene.v0[2] > 0                        # simulated as given, not refused


def test_shipped_scenes_descend_without_warnings():
    from alightsize.model.scene_config import read_scene
    with warnings.catch_warnings():
        warnings.simplefilter("error", InputWarning)
        for scene in sorted(SCENES.glob("*.toml")):
            read_scene(scene)


def test_key_paths_name_items_and_checks(tmp_path):
    # checks by kind where it is unique in the item, by index where it is not (two bending checks here)
    cfg = tmp_path / "bad.toml"
    cfg.write_text(_ITEM.format(kind="bending", params='moment = "100 lbf*in"', size="",
                                section='{ shape = "rectangle", width = "1 in", height = "2 in" }')
                   + '  [[item.check]]\n  kind = "bending"\n  moment = "100 lbf"\n'
                   + '  [[item.check]]\n  kind = "tension"\n  load = "100 lb"\n')
    r = cli("design", cfg, "--out", tmp_path / "out")
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert r.stderr.startswith(f'alightsize: error: {cfg}: item["Strut"].check[1].moment: expected a moment')
    cfg.write_text(cfg.read_text().replace('moment = "100 lbf"', 'moment = "100 lbf*in"'))
    r = cli("design", cfg, "--out", tmp_path / "out")
    assert r.stderr.startswith(f'alightsize: error: {cfg}: item["Strut"].check["tension"].load: expected a force')


def test_report_labels_a_checks_load_key_by_item_and_kind(tmp_path):
    """A check's envelope load is a row of the design's "load_references" table, labelled in the report by item
    and check kind; its value is the envelope's extreme (the same number: nothing is recomputed on the way)."""
    from alightsize.loads.quasi_static import pick
    from alightsize.pipeline.design import run_design
    from alightsize.reports.design_report import context
    text = (EXAMPLES / "articulated_3457_envelopes.toml").read_text()
    head = '[landings]\nstudy = "studies/design_landings_3457.toml"\nenvelopes = ["3457"]\n'
    assert head in text and 'file = "loads/articulated.toml"' in text
    loads = (EXAMPLES / "loads" / "articulated.toml").as_posix()
    cfg = tmp_path / "quasi_static.toml"           # the quasi-static envelopes alone: no landing cases
    cfg.write_text(text.replace(head, "").replace('file = "loads/articulated.toml"', f'file = "{loads}"'))
    res = run_design(read_design(cfg))
    refs = res.to_pandas()["load_references"]
    row = refs[(refs["item"] == "Upper Truss") & (refs["kind"] == "column_buckling")].iloc[0]
    assert row["load_key"] == 'item["Upper Truss"].check["column_buckling"].load' and row["key"] == "load"
    assert row["value_N"] == abs(pick(res.config.loads, "3457", "PU1", "compression").value)
    shown = context(res)["references"][int(row.name)]
    assert shown["key"] == "Upper Truss / column buckling (load)" and shown["governs"] == ""


@pytest.mark.parametrize("text, dim", [
    ("9**9**9 in", "length"),        # arithmetic is never evaluated (it would not return)
    ("2**2000 in", "length"),        # nor overflow
    ("-1e400 deg", "angle"),         # a number beyond double range is not finite
    ("inf deg", "angle"),
    ("nan m", "length"),
    ("1e308 km", "length"),          # finite as written, infinite in SI
    ("3 in^99", "second_moment"),    # unit powers are one digit
    ("__import__('os') m", "length"),
])
def test_quantities_are_a_number_and_a_unit_never_evaluated(text, dim):
    from alightsize.common.units import parse
    with pytest.raises(ValueError):
        parse(text, dim)


@pytest.mark.parametrize("text, dim, si", [
    ("16150 lbf*in", "moment", 16150 * 4.4482216152605 * 0.0254),   # exact definitions of lbf and in
    ("0.478 in^4", "second_moment", 0.478 * 0.0254 ** 4),
    ("3 m*s**-1", "velocity", 3.0),
    ("1.5e-3 m", "length", 1.5e-3),
    ("-2.4 m/s", "velocity", -2.4),
])
def test_quantities_in_the_forms_the_docs_use_parse_to_si(text, dim, si):
    from alightsize.common.units import parse
    assert parse(text, dim) == pytest.approx(si, rel=1e-12)      # conversion factors are exact to the last digit


@pytest.mark.parametrize("value", ["[" * 5000 + "]" * 5000, "{b=" * 3000 + "1" + "}" * 3000])
def test_toml_nested_past_the_recursion_limit_exits_2(tmp_path, value):
    path = tmp_path / "deep.toml"
    path.write_text(f"a = {value}\n")
    proc = subprocess.run([sys.executable, "-m", "alightsize", "design", str(path), "--out", str(tmp_path / "o")],
                          capture_output=True, text=True)
    assert proc.returncode == 2 and "nested" in proc.stderr and "Traceback" not in proc.stderr


@pytest.mark.parametrize("entry", ['""', '"  "', '"nosuch"', '"telescoping.toml/x"'])
def test_a_material_path_that_is_empty_or_missing_exits_2_naming_the_key(tmp_path, entry):
    """An empty path would name the config's own folder (and report another file's keys): refused by key."""
    text = (EXAMPLES / "telescoping.toml").read_text().replace("legs = 4\n", f"legs = 4\nmaterials = [{entry}]\n", 1)
    cfg = tmp_path / "t.toml"
    cfg.write_text(text)
    with pytest.raises(Exception) as err:
        read_design(cfg)
    assert type(err.value).__name__ == "InputError" and err.value.key == "design.materials"
