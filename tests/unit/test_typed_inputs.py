"""Typed input models (alightsize.common.typed): the scene reference documents exactly the keys the models take,
and a validation error keeps the InputError contract (file, key path as written, expected, found)."""

import re
from pathlib import Path

import pytest

from alightsize.common.errors import InputError
from alightsize.model import scene_config as sc
from alightsize.model.legs import GeometryTable
from alightsize.model.scene_config import read_scene
from alightsize.pipeline.lander import read_lander
from conftest import ROOT

SCENES = ROOT / "examples" / "affdl-tr-66-33" / "scenes"
LEG_KEYS = set(sc.Legs.model_fields) | {"kind"}
SECTIONS = {"`[scene]`": set(sc.SceneHead.model_fields), "`[capsule]`": set(sc.Capsule.model_fields),
            "`[cells.NAME]`": set(sc.Cell.model_fields), "`[legs]`": LEG_KEYS,
            "Telescoping legs": set(sc.TelescopingLegs.model_fields) - LEG_KEYS,
            "Articulated legs": set(sc.ArticulatedLegs.model_fields) - LEG_KEYS,
            "`[legs.geometry]`": set(GeometryTable.model_fields), "`[terrain]`": set(sc.TerrainTable.model_fields),
            "`[initial]`": set(sc.Initial.model_fields), "`[controls]`": set(sc.ControlsTable.model_fields),
            "`[output]`": set(sc.OutputTable.model_fields)}


def documented(path: Path, sections) -> dict[str, set[str]]:
    """The keys each of `sections` of a reference page lists in the first column of its tables."""
    out: dict[str, set[str]] = {}
    section = None
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("#"):
            section = next((s for s in sections if s in line), None)
        elif section and line.startswith("| `"):
            out.setdefault(section, set()).update(re.findall(r"`\[*(\w+)\]*`", line.split("|")[1]))
    return out


def test_the_scene_reference_lists_every_key_the_models_take_and_no_other():
    assert documented(ROOT / "docs" / "reference" / "scene.md", SECTIONS) == SECTIONS


def test_the_loads_reference_lists_every_key_the_models_take_and_no_other():
    from alightsize.loads import config as lc
    sections = {"`[loads]`": set(lc.LoadsHead.model_fields), "`[report]`": set(lc.LoadsReport.model_fields),
                "`[truss]`": set(lc.TrussTable.model_fields), "`[grid]`": set(lc.GridTable.model_fields),
                "`[[configuration]]`": set(lc.Configuration.model_fields),
                "`[[combined]]`": set(lc.Combined.model_fields),
                "`[telescoping]`": set(lc.TelescopingTable.model_fields)}
    assert documented(ROOT / "docs" / "reference" / "loads.md", sections) == sections


@pytest.mark.parametrize("override, key, expected, found", [
    ({"cells.axial.force[1]": "3 lb"}, "cells.axial.force[1]", "a force like", "'3 lb'"),
    ({"legs.kind": "wheel"}, "legs.kind", "one of 'telescoping', 'articulated'", "'wheel'"),
    ({"capsule.inertia[1]": "-2 kg*m^2"}, "capsule.inertia[1]", "a positive inertia", "'-2 kg*m^2'"),
    ({"legs.count": 1.5}, "legs.count", "an integer from 2", "1.5"),
    ({"legs.lenght": "1 m"}, "legs.lenght", "one of the known keys", "did you mean 'length'?"),
    ({"terrain.rocks": [{"x": "0 m", "y": "0 m", "radius": "1 m"}]}, "terrain.rocks[0].shape",
     "this key to be present", "nothing"),
    ({"terrain.rocks": [{"hsape": "box", "x": "0 m", "y": "0 m", "radius": "1 m"}]}, "terrain.rocks[0].hsape",
     "the required key 'shape'", "did you mean 'shape'?"),
])
def test_an_error_names_the_key_as_written(override, key, expected, found):
    with pytest.raises(InputError) as err:
        read_scene(SCENES / "telescoping_config1.toml", override)
    assert (err.value.file, err.value.key) == (str(SCENES / "telescoping_config1.toml"), key)
    assert expected in err.value.expected and found in err.value.found


def test_a_misspelt_required_key_is_named_as_written_with_the_key_meant(tmp_path):
    text = (SCENES / "telescoping_config1.toml").read_text(encoding="utf-8")
    assert "\nunloading_rate =" in text
    p = tmp_path / "scene.toml"
    p.write_text(text.replace("\nunloading_rate =", "\nunloading_rat =", 1), encoding="utf-8")
    with pytest.raises(InputError) as err:
        read_scene(p)
    assert err.value.key.endswith(".unloading_rat")
    assert (err.value.expected, err.value.found) == ("the required key 'unloading_rate'",
                                                     "'unloading_rat' (did you mean 'unloading_rate'?)")


def test_the_materials_reference_lists_every_key_of_a_material_file():
    from alightsize.model.materials import MaterialFile
    sections = {"Material file": set(MaterialFile.model_fields)}
    assert documented(ROOT / "docs" / "reference" / "materials.md", sections) == sections


def test_the_design_reference_lists_every_key_of_the_design_tables():
    from alightsize.pipeline import config as dc
    from alightsize.pipeline.landings import LandingsTable
    sections = {"`[design]`": set(dc.DesignHead.model_fields), "`[report]`": set(dc.DesignReport.model_fields),
                "`[audit]`": set(dc.Audit.model_fields), "`[loads]`": set(dc.LoadsFileRef.model_fields),
                "`[landings]`": set(LandingsTable.model_fields)}
    assert documented(ROOT / "docs" / "reference" / "design.md", sections) == sections


def test_the_lander_reference_names_every_key_of_the_lander_tables():
    from alightsize.model.envelope import Envelope
    from alightsize.pipeline.lander import (ArticulatedStructure, LanderFile, LanderHead, MonteCarlo, ReportTable,
                                            Requirements, TelescopingStructure)
    text = (ROOT / "docs" / "reference" / "lander.md").read_text(encoding="utf-8")
    written = {part for key in re.findall(r"`\[*([\w.]+)", text) for part in key.split(".")}
    for model in (LanderFile, LanderHead, Requirements, Envelope, MonteCarlo, ReportTable, TelescopingStructure,
                  ArticulatedStructure):
        assert set(model.model_fields) - {"note"} <= written, model.__name__


def test_the_study_reference_lists_every_key_the_models_take_and_no_other():
    from alightsize.landings import criteria, dispersions, study
    spread = set().union(*(set(m.model_fields) for m in (dispersions.Normal, dispersions.Uniform,
                                                          dispersions.TruncatedNormal)))
    sections = {"`[study]`": set(study.StudyHead.model_fields), "`[compare]`": set(study.Compare.model_fields),
                "`[runs]`": set(study.RunsTable.model_fields), "`[dispersions]`": spread,
                "`[criteria]`": set(criteria.CriteriaTable.model_fields), "`[matrix]`": set(study.Matrix.model_fields)}
    # ("`[compare]`" first: its heading names `[runs]` too)
    assert documented(ROOT / "docs" / "reference" / "study.md", sections) == sections


SPARE = ('\n[cells.spare]\ndeflection = ["0 m", "0.002 m", "0.1 m", "0.11 m"]\nforce = ["0 kN", "1 kN", "1 kN", '
         '"5 kN"]\nunloading_rate = "5e5 N/m"\n')


def test_a_cell_table_no_leg_names_is_refused(tmp_path):
    """A [cells.NAME] table that no leg names would be read and ignored: refused, naming it and the legs' cells."""
    p = tmp_path / "scene.toml"
    p.write_text((SCENES / "telescoping_config1.toml").read_text(encoding="utf-8") + SPARE, encoding="utf-8")
    with pytest.raises(InputError) as err:
        read_scene(p)
    assert (err.value.key, err.value.found) == ("cells.spare", "a cell nothing uses")
    assert err.value.expected == "a cell a leg names (axial, rotational)"


def test_an_override_of_a_cell_the_file_lacks_is_refused():
    """An override that names a cell by a name its file does not use (the simulator's `rot1` for the file's
    `rotational`) made a table of its own that nothing read: refused, naming it."""
    over = {"cells.rot1.deflection": ["0 m", "0.1 m"], "cells.rot1.force": ["0 N", "1 N"],
            "cells.rot1.unloading_rate": "1e6 N/m"}
    with pytest.raises(InputError) as err:
        read_scene(SCENES / "telescoping_config1.toml", over)
    assert (err.value.key, err.value.found) == ("cells.rot1", "a cell nothing uses")


def test_a_lander_cell_that_only_a_crushable_item_weighs_is_used(tmp_path):
    """In a lander file a cell its [[item]] weighs as a crushable core is used, though no leg names it; without
    the item it is refused."""
    text = (ROOT / "examples" / "lunar_lander.toml").read_text(encoding="utf-8")
    text = text.replace("\n[legs]", SPARE + "\n[legs]", 1)
    item = ('\n[[item]]\nname = "Spare honeycomb"\nmaterial = "al-honeycomb"\n'
            'weight = { method = "crushable", cell = "spare" }\n')
    anchor = "\n# `alightsize synthesize"
    assert SPARE in text and anchor in text
    p = tmp_path / "lander.toml"
    p.write_text(text.replace(anchor, item + anchor, 1), encoding="utf-8")
    assert "spare" in read_lander(p).document.cells_used
    assert read_scene(p).name == "lunar_lander"                  # read as a scene: its nominal landing
    p.write_text(text, encoding="utf-8")
    with pytest.raises(InputError) as err:
        read_lander(p)
    assert (err.value.key, err.value.found) == ("cells.spare", "a cell nothing uses")


def test_a_tripod_core_weight_takes_only_its_own_keys(tmp_path):
    """A tripod's crushable core is weighed from its cells: its `weight` table takes an allowance, extra mass, label
    and note, read as typed values (the extra mass in kg); any other key, such as a method of its own, is refused
    naming it."""
    text = (ROOT / "examples" / "lunar_tripod.toml").read_text(encoding="utf-8")
    anchor = '[members.primary_core]                               # the cartridges, weighed from their cells\n' \
             'material = "al-honeycomb"\n'
    assert anchor in text
    p = tmp_path / "lander.toml"
    p.write_text(text.replace(anchor, anchor + 'weight = { extra = "0.2 kg", label = "cores" }\n', 1),
                 encoding="utf-8")
    core = next(i for i in read_lander(p).spec.items if i.name == "core_primary")
    assert core.weight is not None and core.weight.params["extra"] == pytest.approx(0.2, rel=1e-12)
    p.write_text(text.replace(anchor, anchor + 'weight = { method = "prism" }\n', 1), encoding="utf-8")
    with pytest.raises(InputError) as err:
        read_lander(p)
    assert err.value.key == "members.primary_core.weight.method"
