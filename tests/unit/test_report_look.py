"""What a reader sees: pictures fit the page, formulas read unambiguously, labels say each thing once,
figure text stays inside its figure."""

from __future__ import annotations

import re

from alightsize.reports.rendering import template_env


def test_pictures_shrink_to_the_page():
    """A heat map wider than the text column is scaled down, not clipped."""
    style = template_env(True).get_template("style.html.j2").render()
    rule = re.search(r"img\s*\{([^}]*)\}", style)
    assert rule and re.search(r"max-width:\s*100%", rule.group(1))


def test_a_raised_length_is_substituted_in_parentheses():
    """t² with t = 4.98 in reads (4.980 in)², never 4.980 in² (an area); a bare number needs none."""
    from alightsize.common.trace import Step
    from alightsize.reports.design_report import _step
    inch = 0.0254
    step = Step("Strip", "A", "{n} {t}² + {m}²", (("n", 10.0, "dimensionless"), ("t", 4.98 * inch, "length"),
                                                ("m", 3.0, "dimensionless")), 0.0, "area")
    assert _step(step, "US")["substituted"] == "10.00 (4.980 in)² + 3.000²"



def _disc(**p):
    from alightsize.weights.methods import WeightSpec
    params = {"rho": 2768.0, "length": None, "allowance": 0.0, "extra": 0.1, "diameter": 0.08, "thickness": 0.01,
              "inner_diameter": 0.0, "holes": 0, "hole_diameter": None, **p}
    return WeightSpec("disc", params, "item[0].weight").evaluate(None, None, None)


def test_a_plain_disc_weight_has_no_empty_cut_out_terms():
    from alightsize.reports.design_report import _step
    _, steps = _disc()
    line = _step(steps[0], "US")
    assert "dh" not in line["formula"] and "di" not in line["formula"]
    assert not re.search(r"(?<![\d.,])0(?![\d.,])", line["substituted"])
    _, steps = _disc(holes=6, hole_diameter=0.01, inner_diameter=0.02)
    line = _step(steps[0], "US")
    assert "6 dh²" in line["formula"] and "di²" in line["formula"] and line["substituted"].count("in)²") == 3


def test_a_given_value_is_not_stated_as_its_own_formula():
    """ΔW (extra) and Pallow are inputs: the sheet says so instead of "ΔW = ΔW"."""
    from alightsize.pipeline.design import run_design
    from alightsize.pipeline.config import read_design
    from alightsize.reports.design_report import render_html, render_markdown
    from conftest import EXAMPLES
    res = run_design(read_design(EXAMPLES / "telescoping.toml"))
    symbols = ({s.symbol for w in res.weights for s in w.steps}
               | {s.symbol for r in res.records for s in r.outcome.steps})
    for text in (render_html(res), render_markdown(res)):
        assert not [s for s in symbols if re.search(rf"(^|[ >|]){re.escape(s)} = {re.escape(s)}( |<|$)", text, re.M)]


def test_a_check_heading_names_its_failure_mode_once():
    """'compression (compression)' says one thing twice; a different failure mode still shows."""
    from alightsize.pipeline.design import run_design
    from alightsize.pipeline.config import read_design
    from alightsize.reports.design_report import render_html, render_markdown
    from conftest import EXAMPLES
    res = run_design(read_design(EXAMPLES / "articulated_3457.toml"))
    heads = re.findall(r'<th colspan="4">([^<]*)</th>', render_html(res))
    md_heads = [line.split(" | ")[0][2:] for line in render_markdown(res).splitlines()
                if line.endswith("| formula | substituted | value |")]
    assert len(heads) == len(md_heads) == len(res.records)
    for r, html_head, md_head in zip(res.records, heads, md_heads):
        kind, mode = r.item.checks[r.index].kind, r.outcome.mode
        for head in (html_head, md_head):
            assert not re.fullmatch(r"(.+) \((\1)\)", head)
            assert head.endswith(f"({mode.replace('_', ' ')})") == (kind != mode)


def _inside_and_apart(fig) -> None:
    """Every axes (with its labels, ticks and title) lies inside the saved figure and overlaps no other."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    renderer = FigureCanvasAgg(fig).get_renderer()
    boxes = [ax.get_tightbbox(renderer) for ax in fig.axes]
    page = fig.bbox
    for box in boxes:
        assert page.x0 - 0.5 <= box.x0 and box.x1 <= page.x1 + 0.5
        assert page.y0 - 0.5 <= box.y0 and box.y1 <= page.y1 + 0.5
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not (a.x0 < b.x1 - 1 and b.x0 < a.x1 - 1 and a.y0 < b.y1 - 1 and b.y0 < a.y1 - 1)


def _kept(monkeypatch) -> list:
    """The figures saved, in order, kept for inspection."""
    from matplotlib.figure import Figure
    figs: list = []
    save = Figure.savefig

    def keep(fig, *args, **kwargs):
        figs.append(fig)
        return save(fig, *args, **kwargs)
    monkeypatch.setattr(Figure, "savefig", keep)
    return figs


def test_heat_map_colorbars_stay_off_the_next_panel(tmp_path, monkeypatch):
    from alightsize.reports import loads_report as loads_output
    from alightsize.loads.quasi_static import run_loads
    from alightsize.loads.config import read_loads
    from conftest import EXAMPLES
    res = run_loads(read_loads(EXAMPLES / "loads" / "articulated.toml"))
    figs = _kept(monkeypatch)
    loads_output.heatmap(res, "9", tmp_path / "h.png", "US")
    _inside_and_apart(figs[0])


def test_landing_plots_keep_their_labels_and_a_short_legend(tmp_path, monkeypatch):
    """The shock spectrum's axis labels are inside the picture; the stroke plot's legend names legs and cell
    kinds (not every cell of every leg) and sits beside the plot, not over it."""
    from alightsize.landings.output import LandingResult
    from alightsize.reports.landing_report import plots
    from alightsize.model.scene_config import read_scene
    from alightsize_sim.landing import simulate
    from conftest import EXAMPLES
    cfg = read_scene(EXAMPLES / "scenes" / "telescoping_config2.toml")
    res = simulate(cfg.scene, cfg.controls)
    figs = _kept(monkeypatch)
    names = [p.name for p in plots(LandingResult(cfg, res), tmp_path)]
    for fig in figs:
        _inside_and_apart(fig)
    strokes = figs[names.index("strokes.png")]
    kinds = {n.rstrip("0123456789") for cells in cfg.cell_names for n in cells}
    legend = strokes.legends[0] if strokes.legends else strokes.axes[0].get_legend()
    assert len(legend.get_texts()) <= len(cfg.scene.legs) + len(kinds)
    box, plot = legend.get_window_extent(strokes.canvas.get_renderer()), strokes.axes[0].bbox
    assert box.x0 >= plot.x1 or box.y0 >= plot.y1 or box.x1 <= plot.x0


def test_sweep_axes_are_the_parameters_as_written():
    """A grid written in ft/s and deg is plotted in ft/s and deg, labelled with the scene key."""
    import json
    from alightsize.common.figures import boundary_figure
    from alightsize.landings.outcomes import boundary_points
    rows = [{"params_json": json.dumps({"initial.velocity[1]": f"{v} ft/s", "terrain.slope": f"{a} deg"}),
             "outcome": "stable" if v < 10 else "tipped"} for v in (5, 10, 15) for a in (-10, 10)]
    fig = boundary_figure(*boundary_points(rows, ("initial.velocity[1]", "terrain.slope")))
    ax = fig.axes[0]
    assert ax.get_xlabel() == "initial.velocity[1] (ft/s)" and ax.get_ylabel() == "terrain.slope (deg)"
    xy = ax.collections[0].get_offsets()
    assert sorted(set(xy[:, 0])) == [5, 10, 15] and sorted(set(xy[:, 1])) == [-10, 10]


def test_matrix_legend_names_only_this_studys_outcomes():
    """A telescoping study's matrix legend does not explain the articulated legs' α and ψ cells."""
    from alightsize.reports.sweep_report import SYMBOL, matrix_legend
    doc = {"run_list": [{"outcome_class": "stable", "reference_class": "tipped"},
                        {"outcome_class": "bottomed_rotational_pad", "reference_class": None}]}
    legend = " · ".join(matrix_legend(doc))
    assert "α" not in legend and "ψ" not in legend
    for cls in ("stable", "tipped", "bottomed_rotational_pad"):
        assert SYMBOL[cls] in legend
    assert SYMBOL["bottomed_psi"] not in legend and SYMBOL["body_contact"] not in legend
