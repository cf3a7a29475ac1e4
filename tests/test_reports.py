"""Reference reports are current; user text is escaped in HTML/Markdown and never a spreadsheet formula."""

import importlib.metadata
import json

import pytest
from openpyxl import load_workbook

from alightsize.cli import main
from alightsize.design import run_design
from alightsize.design_config import read_design
from alightsize.report import render_html, render_markdown, write_workbook
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
        # XLSX files carry save times; compare the cell contents.
        assert _cells(tmp_path / name / "design.xlsx") == _cells(REPORTS / name / "design.xlsx")


def test_same_input_same_output(tmp_path):
    for k in (1, 2):
        main(["design", str(EXAMPLES / "telescoping.toml"), "--out", str(tmp_path / str(k))])
    assert (tmp_path / "1" / "summary.json").read_bytes() == (tmp_path / "2" / "summary.json").read_bytes()


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
