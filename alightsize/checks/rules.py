"""Rule sets: the formulas a check uses when its table does not name one.

"current" (the default) takes Johnson's parabola below the Euler transition (Bruhn 1973 C2.4), the SP-8007
thin-wall knockdown for local buckling (NASA SP-8007 1968 eq. 4), Roark's equivalent load radius on plates
(Roark 1954 p. 194), the Tresca criterion on plates (the more conservative of the two classical yield
criteria for ductile metals, Young & Budynas 2002 §3.7) and thin-plate solutions for the hub couple and the
eccentric load. "app_iv" is AFFDL-TR-66-33 App. IV as printed: Euler only, 0.4 E t / D, the nominal load
radius, (sigma_r + sigma_t) / 2 against Fcy / 2 and Roark's 1954 hub-couple and eccentric-load formulas. A
check's own `formula`, `theory` or `equivalent_radius` key overrides its rule set.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal


@dataclass(frozen=True)
class Rules:
    column: str               # column_buckling `formula`: "johnson_euler" | "euler"
    local: str                # local_buckling `formula`: "sp8007" | "app_iv"
    plate: str                # plate `theory`: "tresca" | "von_mises" | "app_iv"
    equivalent_radius: bool   # plate `equivalent_radius`
    plate_formula: str        # hub-couple and eccentric plate `formula`: "thin_plate" | "app_iv"


RULES = {"current": Rules("johnson_euler", "sp8007", "tresca", True, "thin_plate"),
         "app_iv": Rules("euler", "app_iv", "app_iv", False, "app_iv")}
RuleSet = Literal["current", "app_iv"]          # the names of RULES, the type of a table's `rules` key
DEFAULT_RULES: RuleSet = "current"
