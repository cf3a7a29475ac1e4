"""Landing-system synthesis: the lightest legs meeting a lander file's requirements (spec: the free
parameters; evaluate: candidates landed and sized; search: the optimizer, the re-check, trade curves and the
Pareto set; charts in alightsize.common.figures)."""
