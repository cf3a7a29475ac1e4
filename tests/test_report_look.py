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
