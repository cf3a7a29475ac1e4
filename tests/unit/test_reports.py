"""Reference reports are current; user text is escaped in HTML/Markdown and never a spreadsheet formula."""

import importlib.metadata
import json
import re

import pytest
from openpyxl import load_workbook

from alightsize.cli import main
from alightsize.pipeline.design import run_design
from alightsize.pipeline.config import read_design
from alightsize.reports.design_report import render_html, render_markdown, write_workbook
from conftest import CONFIGS, EXAMPLES, ROOT

REPORTS = ROOT / "reports" / "affdl-tr-66-33"


def _cells(path):
    return {ws.title: [[c.value for c in row] for row in ws.iter_rows()] for ws in load_workbook(path)}


def test_reference_reports_are_not_stale(tmp_path):
    """Regenerate with `alightsize reports` and compare; rerun that command when this fails."""
    assert main(["reports", "--examples", str(EXAMPLES), "--out", str(tmp_path)]) == 0
    for name in CONFIGS:
        for f in ("summary.json", "report.md", "report.html"):
            assert (tmp_path / name / f).read_text() == (REPORTS / name / f).read_text(), f"{name}/{f} is stale"
        # Workbook and PNG bytes depend on the openpyxl and matplotlib builds: compare the cells.
        assert _cells(tmp_path / name / "design.xlsx") == _cells(REPORTS / name / "design.xlsx")
        for png in ("design_factors.png", "weights.png"):
            assert (REPORTS / name / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_same_input_same_output(tmp_path):
    """Two runs of one config give the same bytes in every text and spreadsheet output (openpyxl stamps the
    save time into each workbook unless told otherwise)."""
    for k in (1, 2):
        main(["design", str(EXAMPLES / "telescoping.toml"), "--out", str(tmp_path / str(k))])
    for f in ("summary.json", "report.html", "report.md", "design.xlsx"):
        assert (tmp_path / "1" / f).read_bytes() == (tmp_path / "2" / f).read_bytes(), f


@pytest.fixture
def hostile(tmp_path):
    text = (EXAMPLES / "articulated_9.toml").read_text()
    text = text.replace('name = "Upper Truss"', 'name = "=HYPERLINK(\\"http://x\\")<script>alert(1)</script>|*"')
    cfg = tmp_path / "hostile.toml"
    cfg.write_text(text)
    return run_design(read_design(cfg))


def test_html_and_markdown_escape_user_text(hostile):
    html = render_html(hostile)
    assert "<script>" not in html and "&lt;script&gt;" in html
    md = render_markdown(hostile)
    assert "<script>" not in md and "\\<script\\>" in md and "\\|" in md


def test_spreadsheet_never_turns_user_text_into_a_formula(hostile, tmp_path):
    path = tmp_path / "h.xlsx"
    write_workbook(hostile, path)
    wb = load_workbook(path)
    cell = wb["Stress"]["A2"]
    assert cell.value.startswith("=HYPERLINK") and cell.data_type == "s"
    assert all(c.data_type != "f" for ws in wb for row in ws.iter_rows() for c in row)


def test_summary_has_no_nan(tmp_path):
    main(["design", str(EXAMPLES / "telescoping.toml"), "--out", str(tmp_path)])
    json.loads((tmp_path / "summary.json").read_text(), parse_constant=lambda c: pytest.fail(f"{c} in JSON"))


def test_installed_distribution_carries_materials_and_templates():
    files = importlib.metadata.files("alightsize") or []
    names = {str(f) for f in files}
    if not any(n.startswith("alightsize/") and n.endswith(".py") for n in names):
        pytest.skip("editable install: data folders are read from the checkout")
    assert "alightsize/_data/materials/7178-t6.toml" in names
    assert "alightsize/_data/templates/design_report.html.j2" in names


def test_si_display_and_user_material(tmp_path):
    # A user material by path, and [report] units = "SI": the same stress shown in MPa.
    (tmp_path / "mats").mkdir()
    (tmp_path / "mats" / "my-al.toml").write_text(
        'name = "My Al"\nyield_strength = "475.7 MPa"\ndensity = "2768 kg/m^3"\nelastic_modulus = "68.9 GPa"\n'
        'poisson_m = 3.33\n')
    text = (EXAMPLES / "articulated_9.toml").read_text().replace('units = "US"', 'units = "SI"')
    text = text.replace('legs = 4', 'legs = 4\nmaterials = ["mats"]').replace('"7178-t6"', '"my-al"')
    cfg = tmp_path / "si.toml"
    cfg.write_text(text)
    res = run_design(read_design(cfg))
    md = render_markdown(res)
    # 475.7 MPa = 69,000 psi to 4 figures, so the Peg Leg Cone factor is unchanged: 69,000/57,370 = 1.20.
    cone = next(r for r in res.records if r.item.name == "Peg Leg Cone")
    sigma = 5852 * 4.4482216 / (10 * 0.101 ** 2 * 0.0254 ** 2)
    assert cone.outcome.factor == pytest.approx(475.7e6 / sigma, rel=1e-6)
    tables = [line for line in md.splitlines() if line.startswith("|")]
    assert any("475.7 MPa" in line for line in tables) and not any("psi" in line for line in tables)
    assert "My Al" in md


def test_every_check_states_its_margin_of_safety():
    """Each stress sheet's design-factor line gives MS = f / f_required - 1 beside f (to the two decimals
    shown), in HTML and Markdown."""
    res = run_design(read_design(EXAMPLES / "articulated_9.toml"))
    for text in (render_html(res), render_markdown(res)):
        shown = re.findall(r"\(required (\d\.\d\d); MS ([+-]\d\.\d\d)\)", text)
        assert len(shown) == len(res.records)
        for r, (req, ms) in zip(res.records, shown):
            assert float(req) == pytest.approx(r.required) and float(ms) == pytest.approx(r.margin, abs=0.005)
            assert ms.startswith("-") is (not r.ok)


def test_names_with_mathtext_are_drawn_literally(tmp_path):
    """An item or configuration named with unbalanced mathtext is drawn as written, not parsed (it would raise)."""
    import io
    text = (EXAMPLES / "articulated_9.toml").read_text()
    text = text.replace('configuration = "9"', 'configuration = "$\\\\foo{$"', 1).replace(
        'name = "Peg Leg Cone"', 'name = "Cone $\\\\alpha{$ and $x$"', 1)
    cfg = tmp_path / "m.toml"
    cfg.write_text(text)
    res = run_design(read_design(cfg))
    for kind in ("factors", "weights"):
        fig = res.plot(kind)
        fig.savefig(io.BytesIO(), format="png")
        shown = [t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text"))]
        assert any("$\\foo{$" in t.replace("\\$", "$") for t in shown)


def test_a_file_name_with_backticks_stays_inside_its_code_span(tmp_path):
    """A config named x`y.toml: the Markdown code span takes a longer fence, so the name cannot close it."""
    cfg = tmp_path / "x`y.toml"
    cfg.write_text((EXAMPLES / "articulated_9.toml").read_text())
    md = render_markdown(run_design(read_design(cfg)))
    head = md.splitlines()[2]
    assert "from ``x`y.toml`` ·" in head and head.count("`") == 5
