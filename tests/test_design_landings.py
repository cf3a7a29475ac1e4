"""Landing cases in `alightsize design` (issues 5 and 6): the study runs through the sweep runner, each
member takes the larger of the App. III envelope and the landings, and the report says which governed."""

from __future__ import annotations

import json
import shutil

import pytest

from alightsize.design_config import read_design
from alightsize.errors import InputError
from alightsize.landing_loads import LANDING, quasi_static_load

from conftest import EXAMPLES

CONFIG = EXAMPLES / "articulated_3457_envelopes.toml"


@pytest.fixture(scope="module")
def design(tmp_path_factory):
    return read_design(CONFIG, tmp_path_factory.mktemp("landings"))


def test_every_landing_case_runs_and_closes_energy(design):
    """24 cases (configurations 3, 4, 5, 7 x three slopes x two inclinations), all done, closure < 1e-4."""
    rows = design.landings.rows
    assert len(rows) == 24 and {r["status"] for r in rows} == {"done"}
    assert max(r["closure_rel"] for r in rows) < 1e-4
    assert all(json.loads(r["member_loads_json"]) for r in rows)


def test_each_check_takes_the_larger_of_sweep_and_landings(design):
    """The load a check uses is exactly max(quasi-static extreme, every landing's extreme) times its factor
    (same numbers, so equality to round-off), and it is attributed to a landing exactly when a landing's is
    the larger."""
    sense_key = {"tension": ("tension_N",), "compression": ("compression_N",),
                 "magnitude": ("tension_N", "compression_N")}
    governed_by_landing = 0
    for ref in design.load_refs:
        qs = quasi_static_load(design.landings, ref.envelope, ref.member, ref.sense) or 0.0
        landing = max(abs(d[k]) for r in design.landings.rows for d in json.loads(r["member_loads_json"])
                      if d["member"] == ref.member for k in sense_key[ref.sense] if d[k] is not None)
        assert ref.value == pytest.approx(max(qs, landing) * ref.factor, rel=1e-12)
        assert ref.extreme.configuration.startswith(LANDING) == (landing > qs)
        governed_by_landing += landing > qs
    assert governed_by_landing >= 1                  # PU1 compression (measured 33,088 vs 32,745 lbf)


def test_unknown_envelope_is_bad_input(tmp_path):
    """[landings] envelopes naming no envelope of the loads file is an InputError naming the key."""
    shutil.copytree(EXAMPLES, tmp_path / "ex")
    bad = tmp_path / "ex" / CONFIG.name
    bad.write_text(CONFIG.read_text().replace('envelopes = ["3457"]', 'envelopes = ["3458"]'))
    with pytest.raises(InputError) as e:
        read_design(bad, tmp_path / "o")
    assert "landings.envelopes" in str(e.value) and "3458" in str(e.value)
