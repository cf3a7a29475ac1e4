"""What a reader sees: pictures fit the page, formulas read unambiguously, labels say each thing once,
figure text stays inside its figure."""

from __future__ import annotations

import re

from alightsize.report import template_env


def test_pictures_shrink_to_the_page():
    """A heat map wider than the text column is scaled down, not clipped."""
    style = template_env(True).get_template("style.html.j2").render()
    rule = re.search(r"img\s*\{([^}]*)\}", style)
    assert rule and re.search(r"max-width:\s*100%", rule.group(1))


def test_a_raised_length_is_substituted_in_parentheses():
    """t² with t = 4.98 in reads (4.980 in)², never 4.980 in² (an area); a bare number needs none."""
    from alightsize.checks import Step
    from alightsize.report import _step
    inch = 0.0254
    step = Step("Strip", "A", "{n} {t}² + {m}²", (("n", 10.0, "dimensionless"), ("t", 4.98 * inch, "length"),
                                                ("m", 3.0, "dimensionless")), 0.0, "area")
    assert _step(step, "US")["substituted"] == "10.00 (4.980 in)² + 3.000²"

